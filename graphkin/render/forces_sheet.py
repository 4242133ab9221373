"""The forces drawing as a sheet of scene panels: Fig. 11.5's layout with placed labels.

(a) the mechanism with its loads, to a length scale; (b, c, ...) the free
body of each moving link to the same scale, every force drawn on its line of
action (dashed) with the concurrency point of a three-force member
(Fig. 11.5e), the offset h of an inertia force (Fig. 12.8c) and the drive's
torque; then the force polygon of each link to one stated force scale, each
closing (Σ F = 0, Fig. 11.5f).  With several loaded links the polygons of each
partial analysis (Sec. 12.5) come first, then those of the totals.

The panels are ordinary :class:`~graphkin.render.scene.Panel` objects, so the
labels are placed by :func:`~graphkin.render.labels.place_labels` (candidate
positions scored against every drawn line and label) and the sheet is laid
out, framed and rendered like every other figure (handout pages, title block,
results table).

References
----------
Uicker, Pennock & Shigley, 5th ed., Figs. 11.5, 11.8, 11.12, 12.8, 12.10.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
import shapely
import shapely.geometry

from graphkin.render.labels import place_labels
from graphkin.render.results import Row
from graphkin.render.scale import NICE, SERIES_125, Scale, choose_scale, fmt, paper_unit
from graphkin.render.scene import Group, Item, LabelRequest, Panel, clip_segment
from graphkin.render.sheet import (
    FOOT_H,
    TITLE_H,
    Sheet,
    _frame,
    _layout,
)
from graphkin.render.text import math_escape
from graphkin.tolerance import is_zero

if TYPE_CHECKING:
    from graphkin.forces.solve import ForceSolution
    from graphkin.render.legend import LegendEntry

__all__ = ["ForceSheet", "build_forces_sheet", "LOAD", "INERTIA", "DRIVE", "JOINT",
           "GREY_INK"]

LOAD = "#1f4e9c"
"""Colour of a given load (and a weight)."""
INERTIA = "#9c2f1f"
"""Colour of an inertia force -m A_G."""
DRIVE = "#2e7d32"
"""Colour of the drive's torque or force."""
JOINT = "#000000"
"""Colour of a joint force."""
GREY_INK = "#5a5a5a"
"""Colour of a rough joint force's normal and friction components."""
ARROW_IN = 0.55
"""Length of a force's arrow on a free body, in inches of paper."""
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


@dataclass
class Force:
    """One force on a free body: its gid label, printed text, vector, point, colour, sources."""

    name: str
    text: str
    vector: np.ndarray
    at: np.ndarray
    color: str
    raw: tuple[str, ...] = ()
    along: np.ndarray | None = None
    """A rough joint's sliding direction: the force is drawn with its normal and friction
    components (Sec. 11.9, Fig. 11.11b)."""
    parts: tuple[str, str] = ("", "")
    """The components' labels (``F₁₄ⁿ``, ``F₁₄ᵗ`` as mathtext)."""


@dataclass
class ForceSheet:
    """A laid-out forces sheet and what the tests read off it."""

    sheet: Sheet
    vectors: dict[str, list[tuple[str, np.ndarray, np.ndarray]]] = field(default_factory=dict)
    scales: str = ""
    colors: dict[str, str] = field(default_factory=dict)
    """Text gid -> colour (labels take their force's colour)."""
    table: Any = None
    """A handout page's compact table (the forces in the force scale's unit), else None."""
    legend: list[LegendEntry] = field(default_factory=list)
    """A handout page's legend entries (the forces' colours and line styles)."""


def label_text(name: str) -> str:
    """How a force's label is printed (mathtext for the inertia force's A_G₃).

    Examples
    --------
    >>> label_text("F₃₄"), label_text("−m₃A_G₃"), label_text("F_A")
    ('F₃₄', '$-m_{3}A_{G_{3}}$', '$F_{A}$')
    """
    if name.startswith("−m") and "A_" in name:
        back = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")
        body = name[2:].translate(back)
        k = body.index("A_")
        link, g = body[:k], body[k + 2:]
        head = g.rstrip("0123456789")
        tail = g[len(head):]
        gtxt = f"{head}_{{{tail}}}" if tail else head
        return f"$-m_{{{link}}}A_{{{gtxt}}}$"
    if name.startswith("F_") and not any(ch.isdigit() for ch in name[2:]):
        esc = math_escape(name[2:])  # the input force at a named point: F_A
        if esc:
            return f"$F_{{{esc}}}$"
    return name


def _unit(v: np.ndarray) -> np.ndarray:
    n = float(np.hypot(*v))
    return v / n if n > 0 else np.array([1.0, 0.0])


def _extent(points: list[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    a = np.array(points, dtype=float)
    return a.min(axis=0), a.max(axis=0)


def _panel(name: str, title: str, unit: str, lo: np.ndarray, hi: np.ndarray, scale: Scale,
           paper: bool) -> Panel:
    """A panel showing ``lo``-``hi`` at ``scale`` with the title and scale-bar strips."""
    p = Panel(name, "posture", title, unit, mechanism=name == "forces-mechanism")
    p.bbox = (float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1]))
    p.scale = scale
    k = p.k
    margin = 0.22 if paper else 0.32
    ex, ey = hi - lo
    from graphkin.render.labels import text_size

    tw = text_size(title, 10.0, "title")[0] + 0.2
    w, h = max(float(ex), 1.0 * k, tw * k - 2 * margin * k), max(float(ey), 0.6 * k)
    cx, cy = (lo + hi) / 2
    p.view = (cx - w / 2 - margin * k, cy - h / 2 - margin * k - FOOT_H * k,
              cx + w / 2 + margin * k, cy + h / 2 + margin * k + TITLE_H * k)
    p.inner = (p.view[0], p.view[1] + FOOT_H * k, p.view[2], p.view[3] - TITLE_H * k)
    return p


def _arrow(g: Group, tail: np.ndarray, tip: np.ndarray, k: float, color: str, key: str,
           gid: str, lw: float = 1.3) -> None:
    g.items.append(Item("arrow", np.array([tail, tip], dtype=float), "vector-abs", gid=gid,
                        key=key, head=0.09 * k, width=0.032 * k,
                        overrides={"color": color, "lw": lw}))


def _request(p: Panel, g: Group, text: str, anchor: np.ndarray, gid: str, color: str,
             colors: dict[str, str], prefer: np.ndarray | None = None,
             style: str = "label-vector") -> None:
    pr = None if prefer is None else (float(prefer[0]), float(prefer[1]))
    p.labels.append(LabelRequest(label_text(text), np.asarray(anchor, dtype=float), style, gid,
                                 g, key=gid, gap=0.05, prefer=pr))
    colors[gid] = color


def forces_on(fs: ForceSolution, lid: str) -> list[Force]:
    """Every force on a link, loads first (the book's labels)."""
    from graphkin.render.forces import force_name, load_name

    sol, mech = fs.solution, fs.mechanism
    out: list[Force] = []
    for ld in mech.loads:
        if ld.link == lid and ld.force is not None and ld.point is not None:
            n = load_name(fs, ld)
            out.append(Force(n, n, np.asarray(ld.force, float),
                             np.asarray(sol.position(ld.point, lid)), LOAD))
    if lid in fs.inertia:
        f = fs.inertia[lid]
        n = f"−m{lid}A_{mech.inertia[lid].center}".translate(_SUB)
        out.append(Force(n, n, f.force, f.point, INERTIA))
    if mech.gravity is not None and lid in mech.inertia:
        inr = mech.inertia[lid]
        n = f"W{lid}".translate(_SUB)
        out.append(Force(n, n, inr.mass * np.asarray(mech.gravity),
                         np.asarray(sol.position(inr.center, lid)), LOAD))
    for j in fs.joints:
        if lid in (j.lo, j.hi):
            w = fs.forces[j.key][:2]
            n = force_name(j.label(lid))
            jf = Force(n, n, w if lid == j.hi else -w, fs.point(j.key), JOINT,
                       (j.label(lid), j.label(j.other(lid))))
            src = j.source
            if src is not None and getattr(src, "key", None) in mech.friction \
                    and j.key in fs.geometry.along:
                by, at = j.other(lid), j.key.partition("@")[2]
                tail = f" at {at}" if at else ""
                jf.along = fs.geometry.along[j.key]
                jf.parts = (f"$F^{{n}}_{{{by}{lid}}}${tail}", f"$F^{{t}}_{{{by}{lid}}}${tail}")
            out.append(jf)
    for d in mech.drives:
        if d.link == lid and d.kind == "position" and d.slider is not None:
            key = next(j.key for j in fs.joints if j.source is d.slider)
            u = fs.geometry.along[key]
            n = f"F_{d.slider.point}"
            esc = math_escape(d.slider.point)
            out.append(Force(n, f"$F_{{{esc}}}$" if esc is not None else n,
                             fs.drives[lid][1] * u,
                             fs.geometry.points[d.slider.point], DRIVE,
                             (f"F_{d.slider.point}·u",)))
    return out


def _link_items(fs: ForceSolution, p: Panel, lid: str, prefix: str,
                colors: dict[str, str]) -> None:
    """A moving link cut free: a bar or a plate, its pins and their letters."""
    from graphkin.render.scene import point_text

    sol, mech = fs.solution, fs.mechanism
    names = [n for n in mech.links[lid].points if n not in mech.helper_points]
    pts = np.array([sol.position(n, lid) for n in names]) if names else np.zeros((0, 2))
    g = p.group(f"{prefix}-link", 1.0, key=f"{prefix}-link")
    outline = _outline(pts)
    if len(outline) >= 3:
        g.items.append(Item("polygon", outline, "plate"))
    elif len(outline) == 2:
        g.items.append(Item("path", outline, "link", overrides={"color": "#000000", "lw": 2.0}))
    for j in fs.joints:
        if lid in (j.lo, j.hi) and j.kind != "pin" and not j.point.startswith("P_"):
            q = fs.geometry.points[j.point]
            g.items.append(Item("marker", np.array([q]), "pin",
                                overrides={"marker": "s", "ms": 9.0}))
    for n, q in zip(names, pts):
        g.items.append(Item("marker", np.array([q]), "pin"))
        p.labels.append(LabelRequest(point_text(n), q, "label-small", f"{prefix}-label-{n}", g,
                                     key=f"{prefix}-label-{n}"))


def _outline(pts: np.ndarray) -> np.ndarray:
    """A cut-free link's outline: the convex hull of its points, or a bar between its extremes.

    A point inside (a mass center ``G4`` at the middle of its pins) is not a
    corner of the plate: ordering the points by their angle about the centroid
    would make one at the centroid a corner placed by round-off.  Points in a
    line (to round-off of the link's size) give a bar.

    Examples
    --------
    >>> _outline(np.array([[0.0, 0.0], [2.0, 0.0], [1.0, 0.5], [1.0, 2.0]])).tolist()
    [[0.0, 0.0], [2.0, 0.0], [1.0, 2.0]]
    >>> _outline(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]])).tolist()
    [[0.0, 0.0], [2.0, 2.0]]
    """
    if len(pts) < 2:
        return pts
    hull = shapely.MultiPoint([tuple(q) for q in pts]).convex_hull
    size = float(np.max(np.ptp(pts, axis=0)))
    if hull.geom_type == "Polygon" and not is_zero(hull.area, size * size):
        # a corner on a side but for round-off is no corner; the ring from its lowest-left
        # corner (to a millionth of the size: two corners level but for round-off are level)
        hull = shapely.geometry.polygon.orient(hull.simplify(1e-9 * size), 1.0)
        ring = np.asarray(hull.exterior.coords)[:-1]
        key = np.round((ring - ring.min(axis=0)) / size * 1e6)
        start = int(np.lexsort((key[:, 1], key[:, 0]))[0])
        return np.roll(ring, -start, axis=0)
    # a bar: its two farthest points
    d = np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1))
    i, j = np.unravel_index(int(np.argmax(d)), d.shape)
    return pts[[min(i, j), max(i, j)]]


def _line_of_action(p: Panel, g: Group, at: np.ndarray, u: np.ndarray) -> None:
    assert p.inner is not None
    far = p.diag()
    seg = clip_segment(at - u * far, at + u * far, p.inner)
    if seg is not None:
        g.items.append(Item("path", np.array(seg), "datum",
                            overrides={"color": "#7a7a7a", "lw": 0.5, "ls": (0, (4, 3))}))


def _results(fs: ForceSolution) -> list[Row]:
    """The table: each joint force and drive, drawn (graphic) beside the matrix method."""
    from graphkin.forces.solve import solve_forces
    from graphkin.render.forces import force_name

    mech = fs.mechanism
    try:
        ref = solve_forces(fs.solution, method="analytic")
    except Exception:  # the analytic check is a bonus; the drawing stands without it
        ref = None
    fu, lu = mech.force_unit, mech.length_unit
    rows: list[Row] = []

    def polar(v: np.ndarray) -> str:
        ang = round(math.degrees(math.atan2(v[1], v[0])), 2) + 0.0  # no "-0.00°"
        return f"{fmt(float(np.hypot(*v)), 4)} ∠ {180.0 if ang == -180.0 else ang:.2f}°"

    for j in fs.joints:
        v = fs.forces[j.key][:2]
        e = ref.forces[j.key][:2] if ref is not None else None
        diff = None if e is None else float(np.hypot(*(v - e))) / max(float(np.hypot(*e)),
                                                                       1e-300)
        name = force_name(j.label(j.hi))
        rows.append(Row(f"F_{j.key}", name, fu, polar(v), "—" if e is None else polar(e), diff))
    for lid, (what, val) in fs.drives.items():
        e2 = ref.drives[lid][1] if ref is not None else None
        diff = None if e2 is None else abs(val - e2) / max(abs(e2), 1e-300)
        if what == "torque":
            rows.append(Row(f"T_1{lid}", f"T1{lid}".translate(_SUB), f"{fu}·{lu}",
                            fmt(val, 5), "—" if e2 is None else fmt(e2, 5), diff))
        else:
            d = next(d for d in mech.drives if d.link == lid)
            what_ = f"F_{d.slider.point} (input, on {lid})" if d.slider is not None else \
                f"input force on {lid}"
            rows.append(Row(f"F_drive_{lid}", what_, fu, fmt(val, 5),
                            "—" if e2 is None else fmt(e2, 5), diff))
    return rows


_Vec = tuple[str, np.ndarray, str, tuple[str, ...]]


def _polygons(fs: ForceSolution) -> list[tuple[str, str, list[_Vec]]]:
    """(link, partial tag, [(label, vector, colour, sources)]) of every polygon to draw."""
    from graphkin.forces.graphic import applied_labels
    from graphkin.render.forces import force_name

    out: list[tuple[str, str, list[_Vec]]] = []
    if len(fs.partials) > 1:
        env = fs.built.values if fs.built is not None else {}
        for part in fs.partials:
            for lid in fs.mechanism.moving:
                items: list[_Vec] = []
                if lid == part.link:
                    for label, kind, _src in applied_labels(fs.mechanism, fs.dynamic).get(lid,
                                                                                          []):
                        if kind != "couple":
                            items.append((force_name(label), env[label][:2],
                                          INERTIA if kind == "inertia" else LOAD, ()))
                for j in fs.joints:
                    if lid in (j.lo, j.hi):
                        w = env[part.forces[j.key]][:2]
                        items.append((force_name(j.label(lid, part.suffix)),
                                      w if lid == j.hi else -w, JOINT, (part.forces[j.key],)))
                if _is_polygon(items):
                    out.append((lid, f"{part.suffix} loads of link {part.link}", items))
    for lid in fs.mechanism.moving:
        items = [(f.name, f.vector, f.color, f.raw) for f in forces_on(fs, lid)]
        if _is_polygon(items):
            out.append((lid, "", items))
    return out


def _is_polygon(items: list[_Vec]) -> bool:
    """Three or more forces: a polygon worth drawing (two are just equal and opposite)."""
    return sum(1 for _, v, _, _ in items if float(np.hypot(*v)) > 0) >= 3


def concurrency(fs: ForceSolution, lid: str) -> np.ndarray | None:
    """The concurrency point of a link that was solved as a three-force member."""
    if fs.built is None or len(fs.partials) != 1:
        return None
    x = fs.built.values.get(f"X_{lid}")
    if x is None or abs(float(x[2])) < 1e-12:
        return None
    return np.asarray(x[:2] / x[2])


def build_forces_sheet(fs: ForceSolution, *, upto: int | None = None, table: bool = True,
                       paper: str | None = None, big: float = 3.4,
                       width_cap: float = 11.5, force_grow: float = 1.0) -> ForceSheet:
    """Lay out and paint the forces drawing (no matplotlib).

    Parameters
    ----------
    fs : ForceSolution
    upto : int, optional
        Draw only what the force construction has found up to this step.
    table : bool
        Add the results table: on a free sheet the graphic values beside the
        matrix method's; on paper the compact table of
        :func:`graphkin.render.forces_page.page_table`.
    paper : str, optional
        ``a4`` or ``letter``: the panels for a handout page (1-2-5 scales, no
        key panel: :func:`graphkin.render.forces_page.paper_forces_sheet`
        places them above the page's band).
    big : float
        The largest side of the mechanism panel, in inches.
    width_cap : float
        The widest a row of panels may be, in inches.
    force_grow : float
        A factor on the room of the force polygons (a handout page draws them
        one 1-2-5 step larger where the page has room).
    """
    from graphkin.render.mechanism import mechanism_extent, paint_mechanism
    from graphkin.render.sources import as_source

    mech, sol = fs.mechanism, fs.solution
    moving = list(mech.moving)
    known: set[str] | None = None
    newest: set[str] = set()
    if upto is not None and fs.construction is not None:
        steps = fs.construction.steps[: upto + 1]
        known = {o for st in steps for o in st.outputs}
        newest = set(steps[-1].outputs) if steps else set()

    def seen(raw: tuple[str, ...]) -> bool:
        return known is None or not raw or any(r in known for r in raw)

    def hot(raw: tuple[str, ...]) -> bool:
        return any(r in newest for r in raw)

    out = ForceSheet(Sheet([], (0.0, 0.0), "", "forces"))
    colors = out.colors
    src = as_source(sol)
    pu = paper_unit(mech.length_unit)
    series = SERIES_125 if paper is not None else NICE  # a handout's 1-2-5 scales
    on = {lid: forces_on(fs, lid) for lid in moving}
    loads = [f for lid in moving for f in on[lid] if f.color != JOINT]
    # ---- the length scale: the mechanism, and its loads' arrows (fixed on paper)
    pts = mechanism_extent(src) or [np.zeros(2)]
    for r in mech.rolling:
        pts += _circle_extent(fs, r, r.on)
    lo, hi = _extent(pts)
    lscale = choose_scale(float(max(hi - lo)) or 1.0, big, pu, mech.length_unit, series)
    for _ in range(2):
        k = lscale.per_inch
        tails = [f.at - _unit(f.vector) * ARROW_IN * k for f in loads]
        lo, hi = _extent(pts + tails)
        lscale = choose_scale(float(max(hi - lo)) or 1.0, big, pu, mech.length_unit, series)
    k = lscale.per_inch
    tails = [f.at - _unit(f.vector) * ARROW_IN * k for f in loads]
    lo, hi = _extent(pts + tails)
    panels: list[Panel] = []
    letters = iter("abcdefghijklmnopqrstuvwxyz" * 4)
    pm = _panel("forces-mechanism", f"({next(letters)}) mechanism and loads",
                mech.length_unit, lo, hi, lscale, paper is not None)
    panels.append(pm)
    paint_mechanism(src, pm, None, set())
    for r in mech.rolling:  # the other gear's pitch circle (the painter draws the rolling one)
        if r.on_center is not None and r.on_radius is not None:
            c = np.asarray(sol.links[r.on].position(r.on_center), dtype=float)
            pm.group(f"forces-mechanism-pitch-{r.on}", 0.95).items.append(
                Item("circle", np.array([c]), "result-arc", radius=r.on_radius))
    for f in loads:
        g = pm.group(f"forces-mechanism-{f.name}", 3.0, key=f"load-{f.name}")
        u = _unit(f.vector)
        _arrow(g, f.at - u * ARROW_IN * k, f.at, k, f.color, f"load-{f.name}",
               f"forces-mechanism-{f.name}-arrow")
        _request(pm, g, f.text, f.at - u * ARROW_IN * k * 0.6,
                 f"forces-mechanism-label-{f.name}", f.color, colors, np.array([-u[1], u[0]]))
    for lid in moving:
        for name, text, tq, at in couples_on(fs, lid):
            _couple(pm, f"forces-mechanism-{name}", at, tq, text, LOAD, k, colors)
    # ---- (b...) the free bodies, to the same length scale
    for lid in moving:
        names = [n for n in mech.links[lid].points if n not in mech.helper_points]
        lpts = [np.asarray(sol.position(n, lid)) for n in names] or [np.zeros(2)]
        llo, lhi = _extent(lpts)
        size = max(float(max(lhi - llo)), ARROW_IN * k)
        content = list(lpts)
        for f in on[lid]:
            if float(np.hypot(*f.vector)) > 0:
                content += [f.at, f.at - _unit(f.vector) * ARROW_IN * k]
        x = concurrency(fs, lid)
        near = x is not None and float(np.hypot(*(x - (llo + lhi) / 2))) <= 2.5 * size
        if x is not None and near:
            content.append(x)
        if lid in fs.inertia:
            content.append(np.asarray(sol.position(mech.inertia[lid].center, lid)))
        for r in mech.rolling:
            if lid in (r.link, r.on):
                content += [fs.geometry.points[j.point] for j in fs.joints
                            if j.point.startswith("P_") and j.point in fs.geometry.points
                            and lid in (j.lo, j.hi)]
                content += _circle_extent(fs, r, lid)
        clo, chi = _extent(content)
        p = _panel(f"fbd-{lid}", f"({next(letters)}) free body of link {lid}",
                   mech.length_unit, clo, chi, lscale, paper is not None)
        panels.append(p)
        _link_items(fs, p, lid, f"fbd-{lid}", colors)
        _pitch_circles(fs, p, lid, p.group(f"fbd-{lid}-circles", 0.95))
        for name, text, tq, at in couples_on(fs, lid):
            _couple(p, f"fbd-{lid}-{name}", at, tq, text, LOAD, k, colors)
        if known is not None and f"l_{lid}" in known and fs.built is not None:
            ln = fs.built.values[f"l_{lid}"]  # a two-force member's line (Sec. 11.6)
            g = p.group(f"fbd-{lid}-two-force-line", 0.9, highlight=hot((f"l_{lid}",)))
            d = np.array([ln[1], -ln[0]])
            q = -ln[2] * np.array([ln[0], ln[1]]) / float(ln[0] ** 2 + ln[1] ** 2)
            _line_of_action(p, g, q, _unit(d))
        for f in on[lid]:
            if float(np.hypot(*f.vector)) == 0 or not seen(f.raw):
                continue
            u = _unit(f.vector)
            gl = p.group(f"fbd-{lid}-{f.name}-line", 2.0, highlight=hot(f.raw))
            _line_of_action(p, gl, f.at, u)  # under every arrow
            g = p.group(f"fbd-{lid}-{f.name}", 3.0, highlight=hot(f.raw))
            tail = f.at - u * ARROW_IN * k
            if f.along is not None:  # a rough joint: normal and friction components
                size = float(np.hypot(*f.vector))
                ft = float(f.vector @ f.along) * f.along
                for comp, text, tag in ((f.vector - ft, f.parts[0], "n"),
                                        (ft, f.parts[1], "t")):
                    if float(np.hypot(*comp)) < 1e-9 * size:
                        continue
                    gc = p.group(f"fbd-{lid}-{f.name}-{tag}", 2.9, highlight=hot(f.raw))
                    t0 = f.at - comp / size * ARROW_IN * k
                    gc.items.append(Item("arrow", np.array([t0, f.at]), "vector-n",
                                         gid=f"fbd-{lid}-{f.name}-{tag}-arrow",
                                         key=f"fbd-{lid}-{f.name}-{tag}", head=0.07 * k,
                                         width=0.025 * k,
                                         overrides={"color": GREY_INK, "lw": 0.9}))
                    cu = _unit(comp)
                    _request(p, gc, text, (t0 + f.at) / 2, f"fbd-{lid}-label-{f.name}-{tag}",
                             GREY_INK, colors, np.array([-cu[1], cu[0]]))
            _arrow(g, tail, f.at, k, f.color, f"fbd-{lid}-{f.name}",
                   f"fbd-{lid}-{f.name}-arrow")
            _request(p, g, f.text, (tail + f.at) / 2, f"fbd-{lid}-label-{f.name}", f.color,
                     colors, np.array([-u[1], u[0]]))
        if lid in fs.inertia and fs.inertia[lid].offset > 0:
            gpt = np.asarray(sol.position(mech.inertia[lid].center, lid))
            foot = fs.inertia[lid].point
            g = p.group(f"fbd-{lid}-h", 3.1, key=f"fbd-{lid}-h")
            g.items.append(Item("marker", np.array([gpt]), "point"))
            g.items.append(Item("path", np.array([gpt, foot]), "aux-line",
                                overrides={"color": INERTIA, "lw": 0.8}))
            _request(p, g, "h", (gpt + foot) / 2, f"fbd-{lid}-label-h", INERTIA, colors,
                     style="label-small")
        if x is not None and near and seen((f"X_{lid}",)):
            g = p.group(f"concurrency-{lid}", 3.2, highlight=hot((f"X_{lid}",)))
            g.items.append(Item("marker", np.array([x]), "point", key=f"concurrency-{lid}"))
            _request(p, g, "X", x, f"concurrency-{lid}-label", JOINT, colors,
                     style="label-small")
        for d in mech.drives:
            if d.link == lid and d.kind == "angle" and d.pivot is not None \
                    and seen((f"T_1{lid}",)):
                _torque(fs, p, lid, np.asarray(sol.position(d.pivot)), k, colors,
                        hot((f"T_1{lid}",)))
    # ---- the force polygons, to one force scale
    polys = _polygons(fs)
    fmax = 0.0
    for _, _, items in polys:
        run = np.cumsum([np.zeros(2)] + [v for _, v, _, _ in items], axis=0)
        fmax = max(fmax, float(max(run.max(axis=0) - run.min(axis=0))))
    fscale = choose_scale(max(fmax, 1e-300), big * 0.8 * force_grow, pu, mech.force_unit,
                          series)
    fk = fscale.per_inch
    for lid, tag, items in polys:
        if not all(seen(raw) for *_, raw in items):
            continue
        path = [np.zeros(2)]
        for _, v, _, _ in items:
            path.append(path[-1] + v)
        name = f"polygon-{lid}" + (f"-{tag.split()[0]}" if tag else "")
        title = (f"({next(letters)}) force polygon of link {lid}" if not tag else
                 f"({next(letters)}) link {lid}, loads of link {tag.split()[-1]} "
                 f"({tag.split()[0]})")
        plo, phi = _extent(path)
        p = _panel(name, title, mech.force_unit, plo, phi, fscale, paper is not None)
        panels.append(p)
        out.vectors[name] = [(lab, t, t + v) for (lab, v, _, _), t in zip(items, path)]
        turn = sum(float(a[0] * b[1] - a[1] * b[0]) for a, b in zip(path, path[1:]))
        for (lab, v, color, raw), t in zip(items, path):
            if float(np.hypot(*v)) == 0:
                continue
            g = p.group(f"{name}-{lab}", 3.0, highlight=hot(raw))
            _arrow(g, t, t + v, fk, color, f"{name}-{lab}", f"{name}-{lab}-arrow", lw=1.2)
            u = _unit(v) * (1.0 if turn > 0 else -1.0)  # outside: right of a ccw polygon
            _request(p, g, lab, t + v / 2, f"{name}-label-{lab}", color, colors,
                     np.array([u[1], -u[0]]))
        g = p.group(f"{name}-start", 3.5)
        g.items.append(Item("marker", np.array([path[0]]), "point", key=f"{name}-start"))
    if paper is None:  # the free sheet's key; a handout page has its legend in the band
        panels.append(_legend(fs, on))
    # ---- frame, labels, table, layout
    for p in panels:
        _frame(p)
        place_labels(p)
        for g in p.groups:
            for it in g.items:
                if it.kind == "text" and it.gid in colors:
                    it.overrides["color"] = colors[it.gid]
    rows = _results(fs) if table and upto is None and paper is None else []
    kind = "Dynamic" if fs.dynamic else "Static"
    title = f"{kind} force analysis: {mech.title or mech.source}"
    sheet = Sheet(panels, (0.0, 0.0), title, "forces", rows)
    sheet.paper, sheet.width_cap = paper, width_cap
    _layout(sheet)
    if paper is None:  # room under the title for the line that states both scales
        sheet.size = (sheet.size[0], sheet.size[1] + SCALES_H)
    else:
        from graphkin.render.forces_page import page_legend, page_table

        out.table = page_table(fs, lscale, fscale, known) if table else None
        out.legend = page_legend(fs, on)
    out.sheet = sheet
    out.scales = f"lengths {lscale.text}" + (f";  forces {fscale.text}" if polys else "")
    return out


def _legend(fs: ForceSolution, on: dict[str, list[Force]]) -> Panel:
    """The key to the drawing's colours and line styles (only what the drawing uses)."""
    colours = {f.color for fl in on.values() for f in fl}
    rows: list[tuple[str, str, str]] = [("joint force $F_{ij}$, by i on j", JOINT, "vector-abs")]
    if LOAD in colours or fs.mechanism.loads:
        rows.append(("given load", LOAD, "vector-abs"))
    if INERTIA in colours:
        rows.append(("inertia force $-mA_{G}$, offset h", INERTIA, "vector-abs"))
    rows.append(("drive (torque or force)", DRIVE, "vector-abs"))
    if any(f.along is not None for fl in on.values() for f in fl):
        rows.append(("normal and friction components", GREY_INK, "vector-n"))
    rows.append(("line of action", "#7a7a7a", "datum"))
    h = 0.22 * len(rows) + 0.45
    p = Panel("legend", "posture", "Key", "in")
    p.view = (0.0, 0.0, 2.45, h)
    p.bbox = p.view
    g = p.group("legend", 3.0, key="legend")
    for i, (text, color, style) in enumerate(rows):
        y = h - 0.45 - 0.22 * i
        if style == "datum":
            g.items.append(Item("path", np.array([[0.12, y], [0.52, y]]), "datum",
                                overrides={"color": color, "lw": 0.5, "ls": (0, (4, 3))}))
        else:
            g.items.append(Item("arrow", np.array([[0.12, y], [0.52, y]]), style,
                                head=0.08, width=0.03,
                                overrides={"color": color, "lw": 1.2 if style == "vector-abs"
                                           else 0.9}))
        g.items.append(Item("text", np.array([[0.62, y]]), "label-small",
                            gid=f"legend-{i}", text=text, ha="left",
                            overrides={"color": color}))
    return p


def _torque(fs: ForceSolution, p: Panel, lid: str, o: np.ndarray, k: float,
            colors: dict[str, str], hot: bool) -> None:
    """The drive's torque T₁₂ as an arc with an arrowhead about the pivot (Ex 11.1 step 7)."""
    _couple(p, f"fbd-{lid}-torque", o, fs.drives[lid][1], f"T1{lid}".translate(_SUB), DRIVE,
            k, colors, hot)


def _couple(p: Panel, gid: str, o: np.ndarray, tq: float, text: str, color: str, k: float,
            colors: dict[str, str], hot: bool = False) -> None:
    """A couple as an arc with an arrowhead about ``o``, labelled with its name and sense."""
    r = 0.22 * k
    g = p.group(gid, 3.3, highlight=hot, key=gid)
    g.items.append(Item("arc", np.array([o]), "rate", radius=r, theta1=30.0, theta2=300.0,
                        gid=f"{gid}-arc", overrides={"color": color, "lw": 1.2}))
    tip = 300.0 if tq >= 0 else 30.0
    a = math.radians(tip)
    e = o + r * np.array([math.cos(a), math.sin(a)])
    tang = np.array([-math.sin(a), math.cos(a)]) * (1.0 if tq >= 0 else -1.0)
    _arrow(g, e - tang * 0.09 * k, e, k, color, f"{gid}-head", f"{gid}-head")
    sense = "ccw" if tq > 0 else "cw" if tq < 0 else ""
    at = o + r * np.array([math.cos(math.radians(165)), math.sin(math.radians(165))])
    _request(p, g, f"{text} {sense}", at, f"{gid}-label", color, colors,
             np.array([-1.0, 0.5]))


def couples_on(fs: ForceSolution, lid: str) -> list[tuple[str, str, float, np.ndarray]]:
    """The applied couples of a link: (gid name, printed name, torque, where to draw it)."""
    from graphkin.forces.graphic import applied_labels
    from graphkin.render.forces import force_name

    sol, mech = fs.solution, fs.mechanism
    names = [n for n in mech.links[lid].points if n not in mech.helper_points]
    pts = [np.asarray(sol.position(n, lid)) for n in names]
    out = []
    for label, kind, src in applied_labels(mech, fs.dynamic).get(lid, []):
        if kind == "couple" and src.torque:
            at = np.mean(pts, axis=0) if len(pts) > 2 else (pts[0] if pts else np.zeros(2))
            for r in mech.rolling:  # a gear: about its center
                if r.link == lid:
                    at = np.asarray(sol.position(r.center, lid))
            out.append((label, force_name(label), float(src.torque), at))
    return out


def _circle_extent(fs: ForceSolution, r: Any, lid: str) -> list[np.ndarray]:
    """The corners of the box around a rolling pair's circle on link ``lid`` (if any)."""
    sol = fs.solution
    if r.link == lid:
        c, rad = np.asarray(sol.position(r.center, lid)), float(r.radius)
    elif r.on == lid and r.on_center is not None and r.on_radius is not None:
        c = np.asarray(sol.links[lid].position(r.on_center), dtype=float)
        rad = float(r.on_radius)
    else:
        return []
    return [c - rad, c + rad]


def _pitch_circles(fs: ForceSolution, p: Panel, lid: str, g: Group) -> list[np.ndarray]:
    """A rolling link's circle (a gear's pitch circle, a wheel) and each point of contact."""
    sol, mech = fs.solution, fs.mechanism
    out: list[np.ndarray] = []
    for r in mech.rolling:
        if r.link == lid:
            c = np.asarray(sol.position(r.center, lid))
            g.items.append(Item("circle", np.array([c]), "result-arc", radius=r.radius))
            out += [c - r.radius, c + r.radius]
        elif r.on == lid and r.on_center is not None and r.on_radius is not None:
            c = np.asarray(sol.links[lid].position(r.on_center), dtype=float)
            g.items.append(Item("circle", np.array([c]), "result-arc", radius=r.on_radius))
            out += [c - r.on_radius, c + r.on_radius]
    n = 0
    for j in fs.joints:
        if lid in (j.lo, j.hi) and j.point.startswith("P_") and j.point in fs.geometry.points:
            q = fs.geometry.points[j.point]
            g.items.append(Item("marker", np.array([q]), "point"))
            # a compound gear has two points of contact, both P (Fig. 11.17): the second's
            # label is ...-label-P-2, so that no two elements share a gid
            n += 1
            gid = f"{g.gid}-label-P" + ("" if n == 1 else f"-{n}")
            p.labels.append(LabelRequest("P", q, "label-small", gid, g, key=gid))
            out.append(q)
    return out


SCALES_H = 0.22
"""Height of the line under the sheet's title that states both scales, in inches."""
