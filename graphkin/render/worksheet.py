"""A worksheet to draw a velocity or acceleration polygon on by hand, and mark from a photo.

One page of A4 or Letter, in millimetres: the mechanism to a round scale
(top), the polygon area with the pole O_V (or O_A) placed and the polygon's
scale printed (bottom), four ArUco markers at the corners and a fifth top
centre (what the sheet is, for ``graphkin check --scan``), and one printed
identity line (the mechanism file's hash, the diagram, the scale, the pole)
that is also the PDF's ``Subject`` metadata as JSON.  ``upto=K`` prints the
construction's first K steps in the polygon area (``draw --upto``).

The layout's numbers are in :mod:`graphkin.render.worksheet_layout`, shared
with the scan reader.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity polygon), Sec. 4.3
(the acceleration polygon).
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.render.worksheet_layout import MARKER_MM, Layout, marker_bits, next_round

__all__ = ["worksheet_figure", "save_worksheet", "fit_mechanism"]

_INK = "black"
_LIGHT = "0.55"


def _markers(ax: Any, layout: Layout) -> None:
    from matplotlib.patches import Rectangle

    c = MARKER_MM / 6
    for mid, x0, y0 in layout.markers:
        cells = marker_bits(mid)
        for r in range(6):
            for col in range(6):
                if cells[r, col]:
                    ax.add_patch(Rectangle((x0 + col * c, y0 + (5 - r) * c), c, c,
                                           facecolor=_INK, edgecolor="none", lw=0,
                                           gid=f"marker-{mid}"))


def _mechanism(fig: Any, sol: Any, layout: Layout) -> Any:
    """The posture, drawn into an axes over the mechanism box, 1 mm = mech_per_mm.

    Nothing is clipped at the box: :func:`fit_mechanism` chose the scale and
    centre at which everything drawn (links, slider blocks, ground hatching,
    labels) lies inside it.  Returns the axes.
    """
    from graphkin.render.mpl import draw

    w, h = layout.size
    x0, y0, x1, y1 = layout.mechanism_box
    ax = fig.add_axes((x0 / w, y0 / h, (x1 - x0) / w, (y1 - y0) / h))
    d = draw(sol, "posture", ax=ax)
    for gid, group in d.groups.items():   # the panel's title and scale bar: the sheet has its own
        if gid.startswith(("title", "scale")):
            group.set_visible(False)
    cx, cy = layout.mech_center
    k = layout.mech_per_mm
    ax.set_aspect("auto")
    ax.set_xlim(cx - (x1 - x0) / 2 * k, cx + (x1 - x0) / 2 * k)
    ax.set_ylim(cy - (y1 - y0) / 2 * k, cy + (y1 - y0) / 2 * k)
    ax.set_axis_off()
    for a in ax.findobj():
        if a is not ax:
            a.set_clip_on(False)
    return ax


def _drawn_box_mm(sol: Any, layout: Layout) -> tuple[float, float, float, float]:
    """The box (mm on the sheet) of everything the posture draws at ``layout``'s scale."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from graphkin.render.style import rc_context

    w, h = layout.size
    with rc_context():
        fig = Figure(figsize=(w / 25.4, h / 25.4), dpi=72.0)
        ax = _mechanism(fig, sol, layout)
        r = FigureCanvasAgg(fig).get_renderer()
        boxes = [a.get_window_extent(r) for a in _inked(ax)]
    px = 25.4 / fig.dpi
    good = [b for b in boxes if np.all(np.isfinite(b.extents)) and b.width + b.height > 0]
    if not good:
        return layout.mechanism_box
    e = np.array([b.extents for b in good])
    return (float(e[:, 0].min() * px), float(e[:, 1].min() * px),
            float(e[:, 2].max() * px), float(e[:, 3].max() * px))


def _inked(ax: Any) -> list[Any]:
    """The artists of ``ax`` that put ink on the page: visible, under visible parents.

    The axes' own background, axis and spines are left out (the axes is off).
    """
    from matplotlib.axis import Axis
    from matplotlib.spines import Spine
    from matplotlib.text import Text

    out: list[Any] = []

    def walk(a: Any) -> None:
        if not a.get_visible() or isinstance(a, (Axis, Spine)) or a is ax.patch:
            return
        kids = a.get_children()
        if a is ax or kids:
            for c in kids:
                walk(c)
            if a is ax or not hasattr(a, "get_path") and not isinstance(a, Text):
                return
        if isinstance(a, Text) and not a.get_text().strip():
            return
        out.append(a)

    walk(ax)
    return out


def fit_mechanism(sol: Any, layout: Layout) -> Layout:
    """``layout`` with the mechanism's scale and centre at which all it draws fits its box.

    The layout's scale fits the mechanism's points; what the posture draws
    around them (a slider's block and its line, ground hatching, the link
    numbers and point labels, the drive's angle) takes more, part of it a
    fixed size on the paper.  The drawing is measured and the scale taken one
    round step larger (1 mm stands for more) until it fits, then the drawing
    is centred in the box (Sec. 3.4: the figure to a stated scale).
    """
    x0, y0, x1, y1 = layout.mechanism_box
    for _ in range(12):
        b = _drawn_box_mm(sol, layout)
        if b[2] - b[0] <= x1 - x0 and b[3] - b[1] <= y1 - y0:
            k = layout.mech_per_mm
            dx = ((b[0] + b[2]) - (x0 + x1)) / 2 * k   # file units: the drawing's centre
            dy = ((b[1] + b[3]) - (y0 + y1)) / 2 * k   # minus the box's
            cx, cy = layout.mech_center
            return replace(layout, mech_center=(cx + dx, cy + dy))
        layout = replace(layout, mech_per_mm=next_round(layout.mech_per_mm))
    return layout


def _given_steps(fig: Any, sol: Any, layout: Layout) -> None:
    """The construction's first ``upto`` steps, to the polygon's scale about the pole."""
    from graphkin.render.mpl import draw

    w, h = layout.size
    x0, y0, x1, y1 = layout.polygon_box
    ax = fig.add_axes((x0 / w, y0 / h, (x1 - x0) / w, (y1 - y0) / h))
    d = draw(sol, layout.diagram, ax=ax, upto=layout.upto - 1)
    for gid, group in d.groups.items():          # the panel's own scale bar: ours is printed
        if "scale" in gid:
            group.set_visible(False)
    for key in [k for k in d if k.startswith("scale")]:
        d[key].set_visible(False)
    for t in ax.texts:                            # the panel's title: the sheet has its own
        if "polygon" in t.get_text().lower():
            t.set_visible(False)
    k = layout.per_mm
    px, py = layout.pole
    ax.set_aspect("auto")
    ax.set_xlim((x0 - px) * k, (x1 - px) * k)
    ax.set_ylim((y0 - py) * k, (y1 - py) * k)
    ax.set_axis_off()


def _givens(sol: Any, diagram: str) -> str:
    """The inputs' rates the student starts from, as the book states a problem.

    ``ω2 = 10 rad/s ccw`` (and ``α2`` for the acceleration polygon), or a
    slider's point velocity as the book writes it, ``V_C = 10000 mm/s ∠180.00°``
    (Example 3.2: "driven by slider 4 at V_C = -10 î m/s"), and on a moving link
    the velocity relative to it, ``V_A3/2`` (Sec. 3.5; Example 4.4); rates the
    file gives for another link (``[rates]``) likewise.  Without them no polygon
    can be drawn.
    """
    from graphkin.text import g6, sense

    mech = sol.mechanism
    length = mech.length_unit
    parts = []
    wanted = (0,) if diagram == "velocity" else (0, 1)
    for d in mech.drives:
        if d.kind == "position" and d.slider is not None:
            parts += [_slide(sol, d.slider, i, v) for i, v in enumerate((d.rate, d.rate2))
                      if i in wanted and v is not None]
            continue
        angle = d.kind in ("angle", "relative")
        units = ("rad/s", "rad/s²") if angle else (f"{length}/s", f"{length}/s²")
        for i in wanted:
            v = d.rate if i == 0 else d.rate2
            if v is None:
                continue
            text = f"{d.rate_labels[i]} = {g6(abs(v) if angle else v)} {units[i]}"
            parts.append(f"{text} {sense(v)}".rstrip() if angle else text)
    r = mech.rates
    slid = [sl for sl in mech.sliders if r is not None and sl.link == r.link]
    if r is not None and r.kind == "position" and slid:
        parts += [_slide(sol, slid[0], i, v) for i, v in enumerate((r.rate, r.rate2))
                  if i in wanted and v is not None]
    elif r is not None:
        for i, v in enumerate((r.rate, r.rate2)[:len(wanted)]):
            if v is not None:
                name = ("ω", "α")[i] + r.link if r.kind != "position" else ("v", "a")[i] + r.link
                unit = ("rad/s", "rad/s²")[i] if r.kind != "position" \
                    else (f"{length}/s", f"{length}/s²")[i]
                sign = sense(v) if r.kind != "position" else ""
                parts.append(f"{name} = {g6(abs(v) if sign else v)} {unit} {sign}".rstrip())
    import re

    from graphkin.render.scene import sub_digits

    # the book's ω₂, α₃/₂: the link numbers after ω and α as subscripts
    text = re.sub(r"([ωα])(\d+)(/\d+)?",
                  lambda m: sub_digits(m[1] + m[2]) + (sub_digits("/" + m[3][1:]) if m[3] else ""),
                  "Given " + ", ".join(parts) + ".")
    return text if parts else ""


def _slide(sol: Any, sl: Any, i: int, v: float) -> str:
    """A slider's given rate as the book gives it: its point's velocity or acceleration.

    ``i = 0`` the velocity along the slide, ``V_C = 10000 mm/s ∠180.00°`` (Example
    3.2), ``i = 1`` the acceleration; relative to the link it slides on when that link
    moves (``V_A3/2``, Sec. 3.5).
    """
    from graphkin.text import polar

    # the slide's direction in the frame at this posture: θ_on + φ (Sec. 2.8)
    t = float(np.asarray(sol.angle_rad(sl.on), dtype=float)) + sl.direction_angle
    rel = "" if sl.on == "1" else f"{sl.link}/{sl.on}"
    unit = f"{sol.mechanism.length_unit}/s" + ("" if i == 0 else "²")
    return f"{'VA'[i]}_{sl.point}{rel} = {polar((v * math.cos(t), v * math.sin(t)), unit)}"


def worksheet_figure(sol: Any, layout: Layout, title: str = "") -> Any:
    """The worksheet as a matplotlib Figure of the paper's size (axes in mm).

    Parameters
    ----------
    sol : Solution
    layout : Layout
        From :func:`graphkin.render.worksheet_layout.worksheet_layout`.
    title : str
        The mechanism's title, printed under the markers.
    """
    from matplotlib.figure import Figure
    from matplotlib.patches import Circle, Rectangle

    layout = fit_mechanism(sol, layout)
    w, h = layout.size
    fig = Figure(figsize=(w / 25.4, h / 25.4))
    ax = fig.add_axes((0, 0, 1, 1))
    ax.set_xlim(0, w)
    ax.set_ylim(0, h)
    ax.set_axis_off()
    _markers(ax, layout)
    top = layout.mechanism_box[3]
    letter = "V" if layout.diagram == "velocity" else "A"
    ax.text(layout.mechanism_box[0], top + 8.0, (title or "Mechanism")[:90], fontsize=9,
            va="bottom", gid="worksheet-title")
    ax.text(layout.mechanism_box[0], top + 3.0,
            f"Mechanism drawn to 1 mm = {layout.mech_per_mm:.6g} {layout.length_unit}.  "
            f"{_givens(sol, layout.diagram)}", fontsize=6.5, va="bottom",
            gid="worksheet-task")
    _mechanism(fig, sol, layout)
    x0, y0, x1, y1 = layout.polygon_box
    ax.add_patch(Rectangle((x0, y0), x1 - x0, y1 - y0, fill=False, edgecolor=_LIGHT, lw=0.5,
                           gid="polygon-area"))
    ax.text(x0, y1 + 2.0, f"{layout.diagram.capitalize()} polygon:  {layout.scale_text}."
            f"  Draw it from O$_{letter}$ below to this scale; label the image points.",
            fontsize=8, va="bottom", gid=f"scale-text-{layout.diagram}")
    px, py = layout.pole
    if layout.upto:
        _given_steps(fig, sol, layout)
    ax.add_patch(Circle((px, py), 0.7, color=_INK, gid="pole"))
    if not layout.upto:                           # else the given steps label it
            ax.text(px - 1.5, py - 1.5, f"O$_{letter}$", fontsize=8, ha="right", va="top",
                gid="pole-label")
    ax.text(w / 2, layout.markers[3][2] + MARKER_MM / 2, layout.identity_line(), fontsize=5,
            ha="center", va="center", color="0.3", gid="worksheet-identity")
    return fig


def save_worksheet(fig: Any, layout: Layout, path: str | Path, dpi: float = 200.0) -> None:
    """Write the worksheet (PDF, PNG or SVG by the suffix); a PDF carries the identity."""
    p = Path(path)
    meta: dict[str, Any] = {}
    if p.suffix.lower() == ".pdf":
        meta = {"Title": "graphkin worksheet", "Subject": layout.identity_json(),
                "Creator": "graphkin", "CreationDate": None}
    elif p.suffix.lower() == ".svg":
        meta = {"Date": None, "Description": layout.identity_json()}
    from graphkin.render.style import rc_context

    with rc_context():                  # text stays text in an SVG, as every graphkin drawing
        fig.savefig(p, dpi=dpi, metadata=meta or None)


def worksheet_pixels(sol: Any, layout: Layout, px_per_mm: float, title: str = "") -> Any:
    """The worksheet as :func:`worksheet_figure` draws it, rasterized: RGB, ``px_per_mm``.

    ``check --scan`` subtracts this printed ink from a photo so that nothing
    printed is read as pencil (:func:`graphkin.scan.sheet.template_ink`).
    """
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = worksheet_figure(sol, layout, title=title)
    fig.set_dpi(px_per_mm * 25.4)
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    return np.asarray(canvas.buffer_rgba())[..., :3]
