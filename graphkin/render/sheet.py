"""A drawing sheet: the panels of one or all diagrams, each to scale, and the results table.

:func:`build_sheet` turns a :class:`~graphkin.render.sources.Source` into a
:class:`Sheet` of panels (pure data: no matplotlib); :mod:`graphkin.render.mpl`
then turns the sheet into a matplotlib figure.

* ``posture``: the mechanism with its posture construction (arcs, lines,
  intersections);
* ``velocity`` / ``acceleration``: the mechanism (with its angular rates) beside
  the polygon, each to its own round scale;
* ``centers`` / ``curvature``: the mechanism with that construction;
* ``all``: every diagram that can be drawn.

Each sheet ends with the results table (values read off the construction
and the analytic ones).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, 3.4, 4.3 (Figs. 2.14, 3.5, 4.4).
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from shapely.geometry import MultiPoint

from graphkin.construction import Role
from graphkin.mechanisms.model import FRAME
from graphkin.render.curvature_notes import link_title, missing_reasons, sheet_note
from graphkin.render.labels import place_labels, text_size
from graphkin.render.legend import CURVATURE_SHEETS, legend_cols, legend_entries, legend_size
from graphkin.render.measurable import (
    component_magnitudes,
    room_for,
    short_components,
    short_note,
)
from graphkin.render.mechanism import mechanism_extent, paint_mechanism
from graphkin.render.paint import POLES, StepPainter
from graphkin.render.results import Row, result_rows
from graphkin.render.scale import NICE, SERIES_125, choose_scale, paper_unit, quantity_unit
from graphkin.render.scene import Item, LabelRequest, Panel, finite_xy, safe_id
from graphkin.render.sources import (
    CURVATURE_PANELS,
    DIAGRAMS,
    DiagramUnavailable,
    Source,
    plane_of,
    split_curvature,
    title_of,
)
from graphkin.render.style import IMAGE_FILLS, STYLES
from graphkin.render.text import plain
from graphkin.tolerance import VERDICT_REL

__all__ = ["Sheet", "build_sheet", "MARGIN", "TITLE_H", "FOOT_H", "GAP"]

MARGIN = 0.45
"""Clearance around a panel's content, in inches."""
TITLE_H = 0.3
"""Height of a panel's title strip, in inches."""
FOOT_H = 0.4
"""Height of a panel's scale-bar strip, in inches."""
GAP = 0.12
"""Space between panels, in inches."""
SHEET_TITLE_H = 0.4
"""Height of the sheet's title, in inches."""
FAR = 1.0
"""Construction points farther than this many mechanism sizes from the mechanism are
left off the sheet."""
FAR_RESULT = 4.0
"""Results and given points are kept on the sheet up to this many mechanism sizes away
(beyond, an arrow at the edge points to them)."""
FAR_RESULT_PAPER = 1.5
"""On an instant-center panel (a handout page's and a sheet's alike): a center farther than this
is an arrow at the edge, so that one far center does not shrink the mechanism to a corner of its
panel (the Stephenson III six-bar's I26, 3.4 mechanism sizes away, once left it 1.2 in wide and
its letters in a crowd)."""


@dataclass
class Sheet:
    """Panels laid out on a sheet.

    Attributes
    ----------
    panels : list of Panel
    size : tuple
        Width and height in inches.
    title : str
    diagram : str
    rows : list of Row
        The results table (empty when not asked for).
    """

    panels: list[Panel]
    size: tuple[float, float]
    title: str
    diagram: str
    rows: list[Row] = field(default_factory=list)
    prefix: dict[str, str] = field(default_factory=dict)
    painters: dict[str, StepPainter] = field(default_factory=dict)
    table_origin: tuple[float, float] = (0.0, 0.0)
    table_size: tuple[float, float] = (0.0, 0.0)
    paper: str | None = None
    """``a4`` or ``letter`` for a handout page (``--sheet``), else None."""
    last_row: tuple[float, float] = (0.0, 0.0)
    """Width used by the last row of panels and its height, in inches."""
    legend: list[Any] = field(default_factory=list)
    """The line-style legend under the panels of a curvature sheet (LegendEntry's)."""
    legend_cols: int = 1
    legend_box: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    """Where the legend goes: ``(x, y, width, height)`` in inches."""
    title_offset: tuple[float, float] | None = None
    """Where the sheet's title starts (left, top), in inches (None: the top left)."""
    width_cap: float = 11.5
    """The widest a row of panels may be, in inches."""
    page: Any = None
    """A handout page's band (:class:`graphkin.render.handout.Page`), else None."""

    def panel(self, name: str) -> Panel:
        """The panel called ``name``."""
        for p in self.panels:
            if p.name == name:
                return p
        raise KeyError(name)


def sheet_diagrams(src: Source, diagram: str) -> list[str]:
    """The diagrams a sheet shows (``all`` expands to those available)."""
    if diagram == "all":
        return src.available()
    if diagram in CURVATURE_PANELS:
        src.construction("curvature")  # raises DiagramUnavailable when it cannot be drawn
        return ["curvature"]
    if "+" in diagram:
        parts = [d.strip() for d in diagram.split("+")]
        for d in parts:
            sheet_diagrams(src, d)
        return [d for d in DIAGRAMS if d in parts]
    if diagram not in DIAGRAMS:
        raise DiagramUnavailable(src.why_not(diagram), diagram=diagram)
    src.construction(diagram)  # raises DiagramUnavailable when it cannot be drawn
    return [diagram]


def build_sheet(src: Source, diagram: str, *, upto: int | None = None,
                highlight: int | Collection[int] | None = None, table: bool = True,
                max_inches: float | None = None, title: str | None = None,
                paper: str | None = None, width_cap: float = 11.5, dry: bool = False,
                drop: Collection[str] = (), grow: dict[str, float] | None = None,
                legend: bool = True) -> Sheet:
    """Lay out the panels of a sheet and paint them.

    Parameters
    ----------
    src : Source
    diagram : str
        One of :data:`~graphkin.render.sources.DIAGRAMS`, several joined by
        ``+`` (``"posture+velocity"``), or ``"all"``.
    upto : int, optional
        Draw the diagram's construction only up to this step (inclusive).
    highlight : int or collection of int, optional
        The step (or steps) drawn in the highlight colour (a teaching page's newest act).
    table : bool
        Add the results table.
    max_inches : float, optional
        The largest side of a panel.
    title : str, optional
        The sheet's title (default: the mechanism's title).
    paper : str, optional
        ``a4`` or ``letter``: a handout page (:mod:`graphkin.render.handout`):
        scales from the 1-2-5 series, tighter clearances, and ``all`` shows
        only the first curvature figure, (a) the inflection circle.
    dry : bool
        Lay the panels out and paint them but place no labels (the handout
        page tries many scales; only the one it keeps gets its labels).
    drop : collection of str
        Panels left off: ``curvature`` on a handout page that does not fit
        otherwise; ``kennedy`` for a caller that wants no Kennedy circle.
    legend : bool
        A curvature sheet's line-style legend under its panels (the step page,
        which explains every line in words, leaves it off).
    grow : dict, optional
        Panel name -> a factor on its room (a handout page draws a panel a
        scale larger where the page has room).

    Raises
    ------
    DiagramUnavailable
        The diagram cannot be drawn for this source.
    """
    diagrams = sheet_diagrams(src, diagram)
    if "curvature" in drop and diagram == "all" and "curvature" in diagrams \
            and len(diagrams) > 1:
        diagrams.remove("curvature")
    if "curvature" in diagrams:
        # one idea per figure, as the book draws it (Figs. 4.25-4.39)
        subs = split_curvature(src)
        if diagram in CURVATURE_PANELS:
            if diagram not in subs:
                lc0 = src.extras.get("curvature")
                why = (missing_reasons(lc0, subs).get(diagram, "") if subs and lc0 is not None
                       else "the link turns about a frame pivot")
                raise DiagramUnavailable(
                    f"no {diagram} figure for this link's curvature: {why}" + (
                        f"; draw --diagram curvature for {', '.join(subs)}" if subs else ""),
                    diagram=diagram)
            subs = [diagram]
        if paper and diagram == "all":
            subs = subs[:1]  # a handout's `all` page: (a) only; -d curvature has them all
        if subs:
            i = diagrams.index("curvature")
            diagrams[i:i + 1] = subs
    many = len(diagrams) > 1
    mech = src.mechanism
    unit = src.length_unit
    paper_u = paper_unit(unit)
    panels: list[Panel] = []
    length_of: dict[str, Panel | None] = {}
    polygon_of: dict[str, Panel | None] = {}

    def new_panel(name: str, plane: str, with_mech: bool, prefix: str) -> Panel:
        p = Panel(name, plane, title_of(name), quantity_unit(unit, plane), prefix=prefix,
                  mechanism=with_mech, pole=POLES.get(plane, (None, ""))[0])
        panels.append(p)
        return p

    if mech is not None:
        main = new_panel("posture", "posture", True, "")
        if not many and diagram in ("velocity", "acceleration"):
            main.title = "Mechanism"
        for d in diagrams:
            if d in ("posture", "velocity", "acceleration"):
                length_of[d] = main
            if d in ("velocity", "acceleration"):
                polygon_of[d] = new_panel(d, d, False, f"{d}-" if many else "")
        for d in diagrams:
            if d not in ("posture", "velocity", "acceleration"):
                if not many:
                    panels.remove(main)
                    main.name = d
                    main.title = title_of(d)
                    panels.append(main)
                    length_of[d] = main
                else:
                    length_of[d] = new_panel(d, "posture", True, f"{d}-")
    else:
        d = diagrams[0]
        p = new_panel(d, plane_of(d), False, "")
        (length_of if p.plane == "posture" else polygon_of)[d] = p

    lc_ = src.extras.get("curvature")
    if mech is not None and len(panels) > 1 and main not in length_of.values():
        panels.remove(main)  # a sheet of curvature panels has no separate posture panel

    kinds: dict[str, str] = {}
    planes: dict[str, str] = {}
    for cx in src.constructions.values():
        for s in cx.steps:
            for o in s.outputs:
                kinds.setdefault(o, s.kind)
                planes.setdefault(o, plane_of(s.diagram))
    painters: dict[str, StepPainter] = {}
    for d in diagrams:
        if src.constructions.get(d) is None:
            continue
        prefix = f"{d}-" if many and d != "posture" else ""
        painters[d] = StepPainter(src, d, {"length": length_of.get(d),
                                           "polygon": polygon_of.get(d)}, prefix, kinds, planes)
        painters[d].quiet_rates = many

    # ---- extents and scales -------------------------------------------
    big = max_inches or (4.2 if many else 5.0)
    for p in panels:
        pts = _content(src, p, painters,
                       FAR_RESULT_PAPER if p.name == "centers" else FAR_RESULT)
        if not pts:
            pts = [np.zeros(2)]
        arr = np.array(pts)
        lo, hi = arr.min(axis=0), arr.max(axis=0)
        p.bbox = (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))
        ex, ey = hi - lo
        room = big if p.plane == "posture" else big * 0.85
        if not many and p.name in ("centers", "curvature") and max_inches is None:
            room = 6.5
        room *= (grow or {}).get(p.name, 1.0)
        extent = max(float(ex), float(ey), 1e-12)
        if p.plane in ("velocity", "acceleration") and p.name in painters and not paper:
            # room enough for the shortest component to be measured (3 mm), up to twice it
            room = room_for(extent, component_magnitudes(painters[p.name], p.plane), room,
                            2.0 * room)
        p.scale = choose_scale(extent, room, paper_u, p.unit,
                               SERIES_125 if paper else NICE)
        k = p.k
        # a handout page packs its panels closer (smaller clearances, no minimum width)
        margin = 0.25 if paper else MARGIN
        minw, minh = (1.0 * k, 0.6 * k) if paper else (1.6 * k, 0.9 * k)
        # the panel is at least as wide as its whole title
        minw = max(minw, (text_size(p.title, STYLES["title"]["size"], "title")[0] + 0.25
                          - 2 * margin) * k)
        cx_, cy_ = (lo + hi) / 2
        w, h = max(float(ex), minw), max(float(ey), minh)
        p.view = (cx_ - w / 2 - margin * k, cy_ - h / 2 - margin * k - FOOT_H * k,
                  cx_ + w / 2 + margin * k, cy_ + h / 2 + margin * k + TITLE_H * k)
        p.inner = (p.view[0], p.view[1] + FOOT_H * k, p.view[2], p.view[3] - TITLE_H * k)

    # ---- the Kennedy circle beside the instant centers (Fig. 3.22b) ------
    ic = src.extras.get("centers")
    if "centers" in diagrams and ic is not None and hasattr(ic, "kennedy_circle") \
            and "kennedy" not in drop \
            and length_of.get("centers") is not None:
        from graphkin.render.kennedy import kennedy_panel

        kp = kennedy_panel(ic, "centers-" if many else "")
        panels.insert(panels.index(length_of["centers"]) + 1, kp)  # type: ignore[arg-type]

    # ---- paint ----------------------------------------------------------
    for d, painter in painters.items():
        own = d == diagram or (diagram == "curvature" and d in CURVATURE_PANELS)
        painter.paint(upto if own else None, highlight if own else None)
    for p in panels:
        if not p.mechanism:
            continue
        known: set[str] | None = None
        drawn: set[str] = set()
        for d, painter in painters.items():
            if length_of.get(d) is p:
                drawn |= painter.drawn_points
        post = painters.get("posture")
        if post is not None and length_of.get("posture") is p and diagram in ("posture",) \
                and upto is not None:
            known = {o for s in post.cx.steps[: upto + 1] for o in s.outputs}
        paint_mechanism(src, p, known, drawn)
    for d in ("velocity", "acceleration"):
        poly = polygon_of.get(d)
        if poly is not None and d in painters:
            _images(src, poly, painters[d], upto if d == diagram else None)
    for d in diagrams:
        if d in ("cubic", "curvature") and length_of.get(d) is not None:
            own = d == diagram or (diagram == "curvature" and d in CURVATURE_PANELS)
            _curvature_extras(src, length_of[d], d,  # type: ignore[arg-type]
                              upto if own else None)
    firsts = [d for d in diagrams if d in CURVATURE_PANELS and length_of.get(d) is not None]
    if firsts and lc_ is not None:
        note = sheet_note(lc_, [d for d in diagrams if d in CURVATURE_PANELS],
                          mechanism_extent(src), unit, diagram == "curvature",
                          src.extras.get("conjugates_omitted", []))
        if note:
            _caption(length_of[firsts[0]], note)  # type: ignore[arg-type]
    for p in panels:
        if p.plane in ("velocity", "acceleration"):
            note = short_note(p, short_components(p))
            if note:
                _caption(p, note, "short-components")
    for p in panels:
        if p.mechanism:
            _hold_anchors(p)
        _frame(p)
        if not dry:
            place_labels(p)

    rows: list[Row] = []
    if table and mech is not None:
        rows = result_rows(src, list(dict.fromkeys(
            "curvature" if d in CURVATURE_PANELS else d for d in diagrams)))
        if upto is not None:
            rows = _reached(src, diagram, upto, rows)
        rows = _few_points(mech, rows)
    name = title if title is not None else (
        mech.title if mech is not None and mech.title else
        (next(iter(src.constructions.values())).title if src.constructions else ""))
    if name and lc_ is not None and any(p.name in CURVATURE_PANELS or p.name == "curvature"
                                        for p in panels):
        name = link_title(name, str(lc_.link))  # the sheet says whose motion it shows
    sheet = Sheet(panels, (0.0, 0.0), name,
                  diagram, rows, {d: pp.prefix for d, pp in painters.items()}, painters)
    sheet.paper, sheet.width_cap = paper, width_cap
    _layout(sheet, legend)
    return sheet


POINT_ROWS = 8
"""The results table of a sheet lists at most this many coupler points (a coupler with 300
lettered points would make a table of a thousand rows; the report has them all)."""


def _few_points(mech: Any, rows: list[Row]) -> list[Row]:
    """The rows of the first :data:`POINT_ROWS` coupler points, and one row saying how many more.

    Joints (pins, slider and slot points) always keep their rows.
    """
    joints = {s.point for s in (*mech.sliders, *mech.slots)}
    coupler = [n for n in mech.point_names
               if len(mech.point_links[n]) == 1 and n not in joints
               and FRAME not in mech.point_links[n] and n not in mech.helper_points]
    if len(coupler) <= POINT_ROWS:
        return rows
    left = set(coupler[POINT_ROWS:])

    def point_of(key: str) -> str:
        for pre in ("R_", "V_", "A_"):
            if key.startswith(pre):
                return key[len(pre):]
        if key.startswith("curvature-") and key.endswith("_"):
            return key[len("curvature-"):-1]
        return ""

    kept = [r for r in rows if point_of(r.key) not in left]
    kept.append(Row("more-points", f"… {len(left)} more points: graphkin solve", "", "", "",
                    None))
    return kept


def _content(src: Source, p: Panel, painters: dict[str, StepPainter],
             far_result: float = 4.0) -> list[np.ndarray]:
    """Every point a panel must show, in data units (the full construction, not ``upto``)."""
    pts: list[np.ndarray] = []
    allowed: tuple[float, float, float, float] | None = None
    allowed_result: tuple[float, float, float, float] | None = None
    if p.mechanism:
        mext = mechanism_extent(src)
        pts.extend(mext)
        if mext:
            lo, hi = np.min(mext, axis=0), np.max(mext, axis=0)
            size = max(float(np.max(hi - lo)), 1e-12)
            reach = FAR * size
            allowed = (lo[0] - reach, lo[1] - reach, hi[0] + reach, hi[1] + reach)
            reach = far_result * size
            allowed_result = (lo[0] - reach, lo[1] - reach, hi[0] + reach, hi[1] + reach)
    if p.pole is not None:
        for painter in painters.values():
            q = painter.xy(p.pole)
            if q is not None:
                pts.append(q)
                break
    for painter in painters.values():
        for s in painter.cx.steps:
            if painter.panel_for(s) is not p or plane_of(s.diagram) != p.plane:
                continue
            rect = allowed if s.role == Role.AUXILIARY else allowed_result
            for o in s.outputs:
                v = painter.raw(o)
                if v is None:
                    continue
                if s.kind == "point":
                    q = finite_xy(v)
                    if q is not None and _inside(q, rect):
                        pts.append(q)
                elif s.kind == "circle" and v.shape == (3,) and np.all(np.isfinite(v)):
                    cut = any(c.op in ("intersect_circles", "intersect_line_circle")
                              for c in painter.consumers.get(o, []))
                    if not cut:
                        r = float(v[2])
                        for q in (v[:2] + [r, 0], v[:2] - [r, 0], v[:2] + [0, r],
                                  v[:2] - [0, r]):
                            if _inside(q, rect):
                                pts.append(q)
    return pts


def _reached(src: Source, diagram: str, upto: int, rows: list[Row]) -> list[Row]:
    """The rows of a started drawing: only the answers its steps ``0..upto`` have reached.

    A construction handed out half done must not print the rest of the answers
    in its table.
    """
    base = "curvature" if diagram in CURVATURE_PANELS else diagram
    cx = src.constructions.get(base)
    if cx is None:
        return rows
    made = {o for s in cx.steps if s.index <= upto for o in s.outputs}
    later = {o for s in cx.steps if s.index > upto for o in s.outputs}

    def label_of(key: str) -> str:
        for prefix, fmt in (("theta", "θ{}"), ("omega", "ω{}"), ("alpha", "α{}")):
            if key.startswith(prefix):
                return fmt.format(key[len(prefix):])
        if key.startswith(("V_", "A_")):
            return f"{'v' if key[0] == 'V' else 'a'}({key[2:]})"
        if key.startswith("R_"):
            return key[2:]
        if key.startswith("center-"):
            return key[len("center-"):]
        return key

    # a row of this diagram is kept once its value is made; rows of other diagrams stay
    return [r for r in rows if label_of(r.key) in made or label_of(r.key) not in later]


def _curvature_extras(src: Source, p: Panel, d: str, upto: int | None = None) -> None:
    """The cubic of stationary curvature as a curve and Ball's point (Figs. 4.37-4.39).

    For a link turning about a frame pivot: the sentence that says why there is
    nothing more to draw.  A started drawing (``upto``) shows the cubic only
    once its panel's last step is drawn, and Ball's point once the step that
    finds it (U) is: the curve and the point are answers.
    """
    lc = src.extras.get("curvature")
    if lc is None:
        return
    x0, y0, x1, y1 = p.inner or p.view
    if d == "curvature" and set(getattr(lc, "sections", {}).values()) <= {"pivot"}:
        cx = src.constructions.get("curvature")
        note = cx.steps[0].note if cx is not None and len(cx.steps) else ""
        if note:
            _caption(p, note)
        return
    cubic = getattr(lc, "cubic", None)
    if d != "cubic" or cubic is None:
        return
    steps = list(getattr(src.constructions.get(d), "steps", []))
    last = max((s.index for s in steps), default=-1)
    found_u = min((s.index for s in steps if "U" in s.outputs), default=last)
    if upto is not None and upto < last:
        cubic = None  # not yet: the curve is drawn with the panel's last step
    g = p.group(f"{p.prefix}cubic-curve", 1.8, key="cubic of stationary curvature")
    if cubic is None:
        _ball(lc, g, p, upto is None or upto >= found_u)
        return
    psi = np.linspace(0.0, np.pi, 2001)[1:-1]
    with np.errstate(all="ignore"):
        pts = np.asarray(cubic.point(psi), dtype=float)
    ok = np.all(np.isfinite(pts), axis=1) & (pts[:, 0] >= x0) & (pts[:, 0] <= x1) \
        & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)
    # a run of points inside the panel is one piece of the curve
    start = None
    pieces = 0
    for i in range(len(pts) + 1):
        if i < len(pts) and ok[i]:
            start = i if start is None else start
            continue
        if start is not None and i - start >= 2:
            g.items.append(Item("path", pts[start:i], "cubic",
                                gid=f"{p.prefix}cubic" + (f"-{pieces}" if pieces else ""),
                                key="cubic" if not pieces else f"cubic:{pieces}"))
            pieces += 1
        start = None
    _ball(lc, g, p, upto is None or upto >= found_u)


def _caption(p: Panel, note: str, name: str = "curvature-note") -> None:
    """A sentence below a panel's drawing, where the scale bar was (it moves down under it).

    Wrapped to the panel's width (at least 3 in: a narrow panel grows).
    """
    vx0, vy0, vx1, vy1 = p.view
    room = max(p.size[0] - 0.3, 3.0)
    text = _wrap_to(note, room, STYLES["caption"]["size"])
    depth = text_size(text, STYLES["caption"]["size"], "caption")[1]
    grow = max(room + 0.3 - p.size[0], 0.0) * p.k
    p.view = (vx0, vy0 - (depth + 0.2) * p.k, vx1 + grow, vy1)
    key = name.replace("-", " ")
    g = p.group(f"{p.prefix}{name}", 6.0, key=key)
    g.items.append(Item("text", np.array([[vx0 + 0.15 * p.k, vy0 + 0.3 * p.k]]),
                        "caption", gid=f"{p.prefix}{name}-text",
                        text=text, ha="left", va="top", key=key))


def _ball(lc: Any, g: Any, p: Panel, reached: bool) -> None:
    """Ball's point U as a ring (Fig. 4.39), once the construction has found it."""
    ball = getattr(lc, "ball_point", None)
    if reached and ball is not None and np.all(np.isfinite(ball)):
        at = np.asarray(ball, dtype=float)[:2]
        g.items.append(Item("marker", np.array([at]), "ball",
                            gid=f"{p.prefix}ball-point", key="Ball's point"))
        x0, y0, x1, y1 = p.inner or p.view
        if x0 <= at[0] <= x1 and y0 <= at[1] <= y1:  # named in words beside its ring
            p.labels.append(LabelRequest("Ball's point", at, "label-small",
                                         f"{p.prefix}label-ball-point", g,
                                         key="Ball's point:label", gap=0.08))


def _hold_anchors(p: Panel, reach: float = 1.0, clear: float = 0.3) -> None:
    """Widen a panel's view to hold every label's anchor up to ``reach`` inches beyond it.

    A link's number sits beside the link (a slider's beside its block, past
    the end of the guide the extent counted); an anchor outside the view would
    push its label onto another link.
    """
    x0, y0, x1, y1 = p.view
    k = p.k
    lo = np.array([x0, y0 + FOOT_H * k])
    hi = np.array([x1, y1 - TITLE_H * k])
    for r in p.labels:
        a = finite_xy(np.array([*np.asarray(r.anchor, dtype=float)[:2], 1.0]))
        if a is None:
            continue
        # outside by a clear margin (a millionth of an inch of paper): an anchor on the view's
        # edge (the extent was taken from its point) is inside on every machine
        eps = 1e-6 * k
        out = np.maximum(lo - a - eps, 0.0) + np.maximum(a - hi - eps, 0.0)
        if np.all(out <= reach * k):
            lo = np.minimum(lo, a - np.where(a < lo - eps, clear * k, 0.0))
            hi = np.maximum(hi, a + np.where(a > hi + eps, clear * k, 0.0))
    if (lo[0], lo[1] - FOOT_H * k, hi[0], hi[1] + TITLE_H * k) != (x0, y0, x1, y1):
        p.view = (float(lo[0]), float(lo[1] - FOOT_H * k), float(hi[0]),
                  float(hi[1] + TITLE_H * k))
        p.inner = (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))


def _wrap_to(text: str, inches: float, size: float) -> str:
    """``text`` in lines no wider than ``inches`` at ``size`` points (font metrics)."""
    import textwrap

    chars = 100
    lines = textwrap.wrap(text, chars)
    while chars > 10 and any(text_size(ln, size, "caption")[0] > inches for ln in lines):
        chars -= 3
        lines = textwrap.wrap(text, chars)
    return "\n".join(lines)


def _inside(q: np.ndarray, rect: tuple[float, float, float, float] | None) -> bool:
    """True when ``q`` is in ``rect``, or on its edge to round-off of its size.

    The rectangle is the mechanism's extent grown by whole sizes: a point of a
    textbook's round numbers (Example 4.16's A_G at y = 3 in, the extent's top
    1 in plus its size 2 in) stands on its edge, inside on every machine.
    """
    if rect is None:
        return True
    e = VERDICT_REL * max(rect[2] - rect[0], rect[3] - rect[1])
    return bool(rect[0] - e <= q[0] <= rect[2] + e and rect[1] - e <= q[1] <= rect[3] + e)


def _images(src: Source, p: Panel, painter: StepPainter, upto: int | None) -> None:
    """Shade the image of every link with three or more points (Mehmke's theorem)."""
    mech, sol = src.mechanism, src.solution
    if mech is None or sol is None:
        return
    steps = painter.cx.steps if upto is None else painter.cx.steps[: upto + 1]
    made = {o for s in steps for o in s.outputs}
    pref = "v" if p.plane == "velocity" else "a"
    pole = p.pole
    shaded = 0  # fills go by image, not by link: the first images differ most in grey
    for lid in mech.moving:
        names = [n for n in mech.links[lid].points if n not in mech.helper_points]
        world = {}
        for n in names:
            world[n] = np.asarray(sol.position(n, lid), dtype=float)
        hull = MultiPoint([tuple(v) for v in world.values()]).convex_hull
        # points in a line (or two on one) but for round-off have no image to shade
        size = float(np.ptp(np.array(list(world.values())), axis=0).max()) if world else 0.0
        if hull.geom_type != "Polygon" or hull.area <= VERDICT_REL * size * size:
            continue
        ring = list(hull.exterior.coords)[:-1]
        order = []
        for c in ring:
            for n, v in world.items():
                if n not in order and abs(v[0] - c[0]) + abs(v[1] - c[1]) <= 1e-9 * (
                        1 + abs(c[0]) + abs(c[1])):
                    order.append(n)
                    break
        pts: list[np.ndarray] = []
        for n in order:
            lab = f"{pref}({n})"
            if lab not in made:
                if FRAME in mech.point_links[n] and pole is not None and pole in made:
                    lab = pole
                else:
                    pts = []
                    break
            q = painter.xy(lab)
            if q is None:
                pts = []
                break
            pts.append(q)
        if len(pts) < 3:
            continue
        g = p.group(f"{p.prefix}image-{safe_id(lid)}", 1.5, key=f"image {lid}")
        g.items.append(Item("polygon", np.array(pts), "image", key=f"image {lid}",
                            overrides={"fc": IMAGE_FILLS[shaded % len(IMAGE_FILLS)]}))
        shaded += 1


def _frame(p: Panel) -> None:
    """The panel's title and scale bar."""
    x0, y0, x1, y1 = p.view
    k = p.k
    g = p.group(f"{p.prefix}title-{p.name}", 6.0, key=f"title {p.name}")
    g.items.append(Item("text", np.array([[x0 + 0.08 * k, y1 - 0.16 * k]]), "title",
                        gid=f"{p.prefix}title-text-{p.name}", text=p.title, ha="left"))
    if p.scale is None:
        return
    s = p.scale
    length = s.paper_inches * k
    bx, by = x0 + 0.15 * k, y0 + 0.16 * k
    g = p.group(f"{p.prefix}scale-{p.name}", 6.0, key=f"scale {p.name}")
    t = 0.04 * k
    g.items.append(Item("path", np.array([[bx, by], [bx + length, by]]), "scale-bar",
                        key=f"scale {p.name}"))
    for f in (0.0, 0.5, 1.0):
        h = t if f != 0.5 else t * 0.6
        g.items.append(Item("path", np.array([[bx + f * length, by - h],
                                              [bx + f * length, by + h]]), "scale-bar"))
    beside = p.size[0] >= 0.15 + s.paper_inches + 0.1 + text_size(s.text, 7.5, "caption")[0]
    at = [bx + length + 0.08 * k, by] if beside else [bx, by - 0.1 * k]  # under a narrow bar
    g.items.append(Item("text", np.array([at]), "caption",
                        gid=f"{p.prefix}scale-text-{p.name}", text=s.text, ha="left"))


def _layout(sheet: Sheet, legend: bool = True) -> None:
    """Place the panels in rows (shelves) and the table under them; set the sheet size."""
    sizes = [p.size for p in sheet.panels]
    boxes: list[tuple[float, float]] = list(sizes)
    if sheet.rows:
        from graphkin.render.results import full_table
        from graphkin.render.table import table_size

        boxes.append(table_size(full_table(sheet.rows)))
    if legend and sheet.paper is None and sheet.diagram in CURVATURE_SHEETS:
        # line styles tell the constructions apart: say what each means (issue 11, item 1)
        sheet.legend = legend_entries(sheet.panels)
        if sheet.legend:
            sheet.legend_cols = legend_cols(sheet.legend, 6.5)
            boxes.append(legend_size(sheet.legend, sheet.legend_cols))
    width_cap = max(sheet.width_cap, max(w for w, _ in boxes))
    rows: list[list[int]] = [[]]
    used = 0.0
    for i, (w, _) in enumerate(boxes):
        if rows[-1] and used + GAP + w > width_cap:
            rows.append([])
            used = 0.0
        used += (GAP if rows[-1] else 0.0) + w
        rows[-1].append(i)
    heights = [max(boxes[i][1] for i in r) for r in rows]
    W = max(sum(boxes[i][0] for i in r) + GAP * (len(r) - 1) for r in rows) + 2 * GAP
    if sheet.title:
        # as drawn: bold, a point larger than a panel's title, 0.12 in from the left edge
        tw = text_size(plain(sheet.title), STYLES["title"]["size"] + 1, "title")[0]
        W = max(W, tw * 1.06 + 0.12 + 2 * GAP)
    H = sum(heights) + GAP * (len(rows) + 1) + (SHEET_TITLE_H if sheet.title else 0.0)
    y = H - (SHEET_TITLE_H if sheet.title else 0.0) - GAP
    positions: list[tuple[float, float]] = [(0.0, 0.0)] * len(boxes)
    for r, h in zip(rows, heights):
        x = GAP
        for i in r:
            positions[i] = (x, y - boxes[i][1])
            x += boxes[i][0] + GAP
        y -= h + GAP
        sheet.last_row = (x, h + GAP)
    for p, pos in zip(sheet.panels, positions):
        p.origin = pos
    if sheet.legend:
        sheet.legend_box = (*positions[-1], *boxes[-1])
    if sheet.rows:
        k = len(sheet.panels)
        sheet.table_origin = positions[k]
        sheet.table_size = boxes[k]
    sheet.size = (float(W), float(H))


def box_panel(name: str, kind: str, title: str, unit: str, lo: np.ndarray, hi: np.ndarray,
              max_inches: float = 6.0) -> Panel:
    """A panel showing the box ``lo``-``hi`` to a round scale, wide enough for its title.

    The design chapters' drawings (gears, synthesis) lay their panels out so.
    """
    size = np.maximum(hi - lo, 1e-9 * max(float(np.max(np.abs(hi))), 1.0))
    scale = choose_scale(float(max(size)), max_inches, paper_unit(unit), unit, NICE)
    p = Panel(name, kind, title, unit, scale=scale, prefix=f"{name}-")
    k = p.k
    w = max(float(size[0]), (text_size(title, STYLES["title"]["size"], "title")[0] + 0.25
                             - 2 * MARGIN) * k)
    h = float(size[1])
    cx, cy = (lo + hi) / 2
    p.view = (cx - w / 2 - MARGIN * k, cy - h / 2 - MARGIN * k - FOOT_H * k,
              cx + w / 2 + MARGIN * k, cy + h / 2 + MARGIN * k + TITLE_H * k)
    p.inner = (p.view[0], p.view[1] + FOOT_H * k, p.view[2], p.view[3] - TITLE_H * k)
    return p
