"""The line-style legend of a drawing: a sample of each style drawn and what it means.

A handout page (:mod:`graphkin.render.handout`) sets it in its band; a
curvature sheet (``draw -d curvature``, ``inflection``, ``bobillier``,
``hartmann``, ``cubic``) under its panels, where construction lines, centre
lines, result circles and the cubic are told apart by their dashes alone.

References
----------
Uicker, Pennock & Shigley, 5th ed., Figs. 4.26-4.39 (the curvature
constructions), Sec. 1.6 (conventions of a kinematic diagram).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from graphkin.render.scene import Panel
from graphkin.render.style import STYLES
from graphkin.render.table import measure

__all__ = ["LEGEND", "LEGEND_PT", "LINE_H", "HANDLE_W", "LegendEntry", "legend_entries",
           "legend_size", "legend_cols", "draw_legend", "box_axes", "CURVATURE_SHEETS"]

CURVATURE_SHEETS = ("curvature", "inflection", "bobillier", "hartmann", "cubic")
"""The diagrams whose sheets carry a legend under their panels (issue 11, item 1)."""

LEGEND_PT = 6.5
"""Size of the legend's text (points)."""
LINE_H = 0.14
"""Height of one legend (or title-block) line, in inches."""
HANDLE_W = 0.38
"""Length of a legend's sample line, in inches."""

LEGEND: tuple[tuple[tuple[str, ...], str, str], ...] = (
    (("link", "plate", "pin"), "link", "link, pin joint"),
    (("given-line",), "given-line", "given line"),
    (("aux-line", "arc", "right-angle"), "aux-line", "construction line or arc"),
    (("ref-line",), "ref-line", "centre line, line of centres"),
    (("datum",), "datum", "datum or direction"),
    (("result-line",), "result-line", "result line"),
    (("result-arc",), "result-arc", "result circle"),
    (("vector-abs",), "vector-abs", "absolute velocity or acceleration"),
    (("vector-rel",), "vector-rel", "relative velocity or acceleration"),
    (("vector-t",), "vector-t", "tangential component Aᵗ"),
    (("vector-n",), "vector-n", "normal component Aⁿ"),
    (("vector-c",), "vector-c", "Coriolis component Aᶜ"),
    (("cubic",), "cubic", "cubic of stationary curvature"),
    (("kennedy-known",), "kennedy-known", "Kennedy circle: center found"),
    (("kennedy-unknown",), "kennedy-unknown", "Kennedy circle: center not yet found"),
)
"""Legend entries: the styles an entry stands for, the style of its sample, its words."""


@dataclass
class LegendEntry:
    """One line of the legend: a sample (line or fill) and what it means."""

    gid: str
    style: str
    text: str
    fill: str | None = None
    color: str | None = None
    """The sample's colour when it is not the style's (the forces drawing's colours)."""


def legend_entries(panels: Iterable[Panel]) -> list[LegendEntry]:
    """The legend of the styles drawn in ``panels``, in a fixed order, then the image fills.

    Examples
    --------
    >>> from graphkin.render.scene import Item
    >>> import numpy as np
    >>> p = Panel("posture", "posture", "Posture", "in")
    >>> p.group("g", 1.0).items.append(Item("path", np.zeros((2, 2)), "aux-line"))
    >>> [e.text for e in legend_entries([p])]
    ['construction line or arc']
    """
    used: set[str] = set()
    fills: dict[str, str] = {}
    for p in panels:
        for g in p.groups:
            for it in g.items:
                used.add(it.style)
                if it.style == "image" and it.key:
                    fills.setdefault(it.overrides.get("fc", "#dddddd"), it.key.split(" ", 1)[-1])
    out = [LegendEntry(f"legend-{style}", style, text) for styles, style, text in LEGEND
           if used & set(styles)]
    for k, (fc, lid) in enumerate(fills.items()):
        out.append(LegendEntry(f"legend-image-{k}", "image", f"image of link {lid}", fc))
    return out


def _widths(entries: list[LegendEntry]) -> list[float]:
    return [HANDLE_W + 0.08 + measure(e.text, LEGEND_PT, "caption")[0] for e in entries]


def legend_size(entries: list[LegendEntry], cols: int) -> tuple[float, float]:
    """Width and height (inches) of the legend's box set in ``cols`` columns."""
    if not entries:
        return 0.0, 0.0
    per = -(-len(entries) // cols)
    widths = _widths(entries)
    colw = [max(widths[c * per:(c + 1) * per], default=0.0) for c in range(cols)]
    return sum(colw) + 0.12 * (cols - 1) + 0.16, per * LINE_H + 0.12


def legend_cols(entries: list[LegendEntry], width: float) -> int:
    """The most columns (up to 4) whose legend fits ``width`` inches (at least 1)."""
    best = 1
    for c in range(1, 5):
        if legend_size(entries, c)[0] <= width:
            best = c
    return best


def draw_legend(ax: Any, entries: list[LegendEntry], cols: int, height: float) -> None:
    """Draw the legend into ``ax`` (axes in inches, ``height`` tall, origin lower left)."""
    from matplotlib import patches
    from matplotlib.lines import Line2D

    per = -(-len(entries) // cols)
    widths = _widths(entries)
    colw = [max(widths[c * per:(c + 1) * per], default=0.0) for c in range(cols)]
    for k, e in enumerate(entries):
        c, r = divmod(k, per)
        x = 0.08 + sum(colw[:c]) + 0.12 * c
        y = height - 0.06 - LINE_H * (r + 0.5)
        st = STYLES.get(e.style, {})
        if e.style == "image":
            art: Any = patches.Rectangle((x, y - 0.04), HANDLE_W, 0.08, fc=e.fill, ec="none")
        elif e.style == "link":
            art = patches.Rectangle((x, y - 0.03), HANDLE_W, 0.06, fc="#ffffff", ec="k",
                                    lw=STYLES["link"]["lw"])
        else:
            art = Line2D([x, x + HANDLE_W], [y, y], color=e.color or st.get("color", "k"),
                         lw=st.get("lw", 1.0), ls=st.get("ls", "-"))
        art.set_gid(f"{e.gid}-sample")
        ax.add_artist(art)
        t = ax.text(x + HANDLE_W + 0.08, y, e.text, fontsize=LEGEND_PT, ha="left", va="center")
        t.set_gid(e.gid)


def box_axes(fig: Any, size: tuple[float, float], box: tuple[float, float, float, float],
             gid: str) -> Any:
    """Framed axes in inches for ``box`` = ``(x, y, w, h)`` on a figure of ``size`` inches."""
    from matplotlib import patches

    W, H = size
    x, y, w, h = box
    ax = fig.add_axes((x / W, y / H, w / W, h / H))
    ax.set_axis_off()
    ax.set_xlim(0, w)
    ax.set_ylim(0, h)
    ax.set_gid(gid)
    frame = patches.Rectangle((0.0, 0.0), w, h, fill=False, lw=0.8, ec="k", clip_on=False)
    frame.set_gid(f"{gid}-frame")
    ax.add_patch(frame)
    return ax
