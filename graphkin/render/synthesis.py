"""Drawings of a synthesis in the house style, after Figs. 9.5-9.26 and 9.38-9.42.

A synthesis is laid out on a :class:`~graphkin.render.sheet.Sheet` like
every other drawing of graphkin: one panel per figure, each to a stated
round scale with its scale bar, the letters placed by
:mod:`graphkin.render.labels` clear of every line and letter, the styles of
:mod:`graphkin.render.style`.  Every recorded step of the construction is a
group whose gid is its step id (``step-07-P12``: the pole P12;
``step-12-b_A12``: a bisector), drawn the way the book draws it: points as
dots with the book's letters (P₁₂, P₁₃, ..., A₁ A₂ A₃, O_A / O_B), the sides
of the pole triangle and of the opposite-pole quadrilateral between their
poles, bisectors and the lines turned about a pole from the point they start
at to the points found on them, circles clipped to the panel.  The curves
and the linkage have named groups (``center-point-curve-1``,
``circle-point-curve-1``, ``burmester-1``, ``linkage-1``, ``coupler-curve``).
The function generator, the cognates and the dwell linkage are drawn by
:mod:`graphkin.render.synthesis_more`.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 9.3-9.7, 9.10, 9.13; Figs. 9.5-9.26.
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.construction import Construction
from graphkin.render.labels import place_labels
from graphkin.render.scene import (
    Group,
    Item,
    LabelRequest,
    Panel,
    clip_segment,
    construction_text,
    inside_spans,
    point_text,
)
from graphkin.render.sheet import Sheet, _frame, _layout, box_panel
from graphkin.synthesis.run import Result

__all__ = ["synthesis_sheet", "draw_synthesis", "synthesis_figure", "save_synthesis",
           "letter", "Pen"]

_POLE = re.compile(r"P\d\d$")
_CIRCLE_OPS = {"circle_through", "circle_on_diameter", "circle_on_chord"}
REACH = 4.0
"""Construction points farther than this many figure sizes from the postures are left off."""


def letter(label: str) -> str:
    """How a point's name is printed: ``P12`` -> P₁₂, ``O_A`` -> O with subscript A."""
    return construction_text(label) if "_" in label else point_text(label)


def _xy(v: Any) -> np.ndarray | None:
    a = np.asarray(v, dtype=float)
    if a.shape != (3,) or not np.all(np.isfinite(a)) or abs(a[2]) <= 1e-12 * max(
            abs(a[0]), abs(a[1]), 1e-300):
        return None
    return a[:2] / a[2]


def _c(z: complex) -> np.ndarray:
    return np.array([z.real, z.imag])


class Pen:
    """Draws into one panel: points with letters, segments, circles, curves; each a group.

    ``labelled`` collects the names already lettered (a point drawn twice is
    lettered once); ``optional`` the gids of labels that may be left out of a
    crowded figure (see :func:`draw_synthesis`).
    """

    def __init__(self, p: Panel, skip: frozenset[str] = frozenset()) -> None:
        self.p = p
        self.skip = skip
        self.labelled: set[str] = set()
        self.optional: set[str] = set()
        self.points: dict[str, np.ndarray] = {}
        self.off: dict[str, np.ndarray] = {}
        """Points asked for beyond the panel (a far Burmester point, a far pivot): each gets
        an arrow at the edge with its name and distance (:func:`far_points`)."""
        self.stage: tuple[Construction, int] | None = None
        """A teaching frame: this construction up to this step (the newest highlighted);
        the constructions in :attr:`before` whole, nothing else of the result."""
        self.before: list[Construction] = []

    @property
    def box(self) -> tuple[float, float, float, float]:
        """Where lines may run: the panel less its title and scale strips."""
        assert self.p.inner is not None
        return self.p.inner

    def inside(self, xy: np.ndarray) -> bool:
        """Whether a point is within the panel's drawing area."""
        x0, y0, x1, y1 = self.box
        return bool(x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1)

    def found(self, xy: np.ndarray, name: str) -> bool:
        """Whether a linkage's fixed pivot ``O_...`` is a point lettered under another name."""
        return name.startswith("O_") and name not in self.points and any(
            float(np.hypot(*(q - xy))) <= 1e-9 * self.p.diag() for q in self.points.values())

    def group(self, gid: str, z: float, **kw: Any) -> Group:
        """A new group of the panel (its gid prefixed with the panel's)."""
        return self.p.group(self.p.prefix + gid, z, **kw)

    def point(self, g: Group, name: str, xy: np.ndarray, style: str = "point",
              optional: bool = False, text: str | None = None) -> None:
        """A dot and its letter (once per name); off the panel: kept for :func:`far_points`."""
        if not self.inside(xy):
            if np.all(np.isfinite(xy)):
                self.off.setdefault(name, np.asarray(xy, dtype=float))
            return
        if self.found(xy, name):
            # a pivot the construction found already, under the book's name for it (O4)
            g.items.append(Item("marker", np.array([xy]), style))
            return
        g.items.append(Item("marker", np.array([xy]), style, key=name))
        self.points.setdefault(name, xy)
        if name in self.labelled:
            return
        gid = f"label-{g.gid}-{name}"
        if gid in self.skip:
            return
        self.labelled.add(name)
        self.p.labels.append(LabelRequest(text if text is not None else letter(name),
                                          np.asarray(xy, dtype=float),
                                          "label-aux" if optional else "label", gid, g,
                                          key=name))
        if optional:
            self.optional.add(gid)

    def words(self, g: Group, text: str, xy: np.ndarray, key: str) -> None:
        """Words naming a curve or a line (left out of a crowded figure)."""
        gid = f"label-{g.gid}-{key}"
        if gid in self.skip or not self.inside(xy):
            return
        self.p.labels.append(LabelRequest(text, np.asarray(xy, dtype=float), "label-aux",
                                          gid, g, key=key))
        self.optional.add(gid)

    def segment(self, g: Group, a: np.ndarray, b: np.ndarray, style: str,
                key: str | None = None) -> bool:
        """The part of the segment ab inside the panel."""
        seg = clip_segment(np.asarray(a, float), np.asarray(b, float), self.box)
        if seg is None:
            return False
        g.items.append(Item("path", np.array(seg), style, key=key))
        return True

    def polyline(self, g: Group, z: np.ndarray, style: str, key: str | None = None,
                 jump: float = math.inf) -> None:
        """A sampled curve (complex), broken where it leaves the panel, is NaN or jumps."""
        z = np.asarray(z, dtype=complex)
        x0, y0, x1, y1 = self.box
        ok = np.isfinite(z) & (z.real >= x0) & (z.real <= x1) & (z.imag >= y0) & (z.imag <= y1)
        cut = np.zeros(z.shape, bool)
        cut[1:] = np.abs(np.diff(z)) > jump
        run: list[np.ndarray] = []
        for k in range(len(z) + 1):
            if k < len(z) and ok[k] and not (cut[k] and run):
                run.append(_c(z[k]))
                continue
            if len(run) >= 2:
                g.items.append(Item("path", np.array(run), style, key=key))
                key = None
            run = [_c(z[k])] if k < len(z) and ok[k] else []

    def circle(self, g: Group, c: np.ndarray, r: float, style: str,
               key: str | None = None) -> None:
        """A circle, or the arcs of it inside the panel."""
        if not (np.all(np.isfinite(c)) and math.isfinite(r) and r > 0):
            return
        spans = inside_spans(np.asarray(c, float), float(r), self.box)
        if spans is None:
            g.items.append(Item("circle", np.array([c]), style, radius=float(r), key=key))
            return
        for t1, t2 in spans:
            g.items.append(Item("arc", np.array([c]), style, radius=float(r), theta1=t1,
                                theta2=t2, key=key))


def panel(name: str, title: str, unit: str, lo: np.ndarray, hi: np.ndarray,
          max_inches: float = 6.0) -> Panel:
    """A panel showing the box ``lo``-``hi`` to a round scale (as the gear drawings' panels)."""
    return box_panel(name, "synthesis", title, unit, lo, hi, max_inches)


def _after_t(cx: Construction) -> set[str]:
    """The labels that depend on the input t (the curves' steps, drawn as curves instead)."""
    out = {"t"}
    for s in cx:
        if any(i in out for i in s.inputs):
            out.update(s.outputs)
    return out


def paint_construction(pen: Pen, cx: Construction, skip: set[str], near: np.ndarray,
                       reach: float, optional: frozenset[str] | set[str] = frozenset(),
                       suffix: str = "") -> None:
    """Every step of ``cx`` not in ``skip``, as the book draws it (the gid: the step id).

    Points farther than ``reach`` from ``near`` are left off; lines run between
    the points found on them (a bisector from its chord's midpoint to the
    center it finds, a line turned about a pole from the pole to the point it
    meets); labels named in ``optional`` may be left out of a crowded figure.
    ``suffix`` ends the gids of a second construction drawn in the same panel
    (the selection after the poles, whose steps are numbered from 1 again).
    """
    last, newest = len(cx.steps), -1
    if pen.stage is not None:
        if pen.stage[0] is cx:
            last = newest = pen.stage[1]
        elif not any(c is cx for c in pen.before):
            return
    ev = cx.evaluate({"t": np.array(0.0)} if "t" in cx.labels else None, strict=False)
    pts: dict[str, np.ndarray] = {}
    for s in cx:
        if s.kind == "point" and s.outputs[0] in ev:
            xy = _xy(ev[s.outputs[0]])
            if xy is not None and float(np.hypot(*(xy - near))) <= reach and s.index <= last:
                pts[s.outputs[0]] = xy
    users: dict[str, list[str]] = {}
    for s in cx:
        for i in s.inputs:
            users.setdefault(i, []).extend(o for o in s.outputs if o in pts)
    for s in cx:
        lab = s.outputs[0]
        if lab in skip or s.label in skip or lab not in ev or s.index > last:
            continue
        result = str(s.role) == "result"
        hl = s.index == newest
        if s.kind == "point" and lab in pts:
            g = pen.group(s.step_id + suffix, 5.0, step=s, key=lab, highlight=hl)
            style = "pole" if _POLE.match(lab) else (
                "pin" if lab.startswith("O_") else
                "aux-point" if str(s.role) == "auxiliary" else "point")
            pen.point(g, lab, pts[lab], style, optional=lab in optional
                      or (style == "aux-point" and not lab.startswith("O")))
        elif s.kind == "line":
            on = [pts[i] for i in s.inputs if i in pts] + [pts[o] for o in users.get(lab, [])]
            if s.op == "bisector" and len(s.inputs) == 2 and all(i in pts for i in s.inputs):
                on = [(pts[s.inputs[0]] + pts[s.inputs[1]]) / 2] + [
                    pts[o] for o in users.get(lab, [])]
            line = np.asarray(ev[lab], dtype=float)
            if not on or line.shape != (3,) or not np.all(np.isfinite(line)):
                continue
            d = np.array([line[1], -line[0]])
            d /= max(float(np.hypot(*d)), 1e-300)
            t = [float(np.dot(q - on[0], d)) for q in on]
            if len(on) == 1:   # nothing found on it yet (a teaching frame): a stretch of it
                t = [-0.15 * pen.p.diag(), 0.15 * pen.p.diag()]
            lo, hi = min(t), max(t)
            if hi - lo <= 1e-9 * reach:
                continue
            pad = 0.0 if s.op == "join" else 0.12 * (hi - lo)
            g = pen.group(s.step_id + suffix, 3.0, step=s, key=lab, highlight=hl)
            side = s.op == "join" and all(_POLE.match(i) for i in s.inputs)
            pen.segment(g, on[0] + (lo - pad) * d, on[0] + (hi + pad) * d,
                        "given-line" if side else "aux-line", key=lab)
        elif s.kind == "circle" and s.op in _CIRCLE_OPS:
            v = np.asarray(ev[lab], dtype=float)
            if v.shape != (3,) or not np.all(np.isfinite(v)) or v[2] > 3 * reach:
                continue
            g = pen.group(s.step_id + suffix, 2.0, step=s, key=lab, highlight=hl)
            style = "result-arc" if result else "arc"
            span = _span(v, list(pts.values()))
            if span is None or s.op != "circle_through":
                pen.circle(g, v[:2], float(v[2]), style, key=lab)
            else:   # the arc through the positions it carries, as the book draws it
                arc = np.radians(np.linspace(span[0], span[1], 91))
                pen.polyline(g, complex(v[0], v[1]) + v[2] * np.exp(1j * arc), style, key=lab)


def _span(circle: np.ndarray, points: list[np.ndarray]) -> tuple[float, float] | None:
    """The shortest arc (degrees) of a circle holding every drawn point on it, 12° longer.

    None when fewer than two drawn points lie on the circle.
    """
    c, r = circle[:2], float(circle[2])
    on = [q for q in points if abs(float(np.hypot(*(q - c))) - r) <= 1e-9 * max(r, 1e-300)]
    if len(on) < 2:
        return None
    ang = np.sort(np.degrees(np.arctan2([q[1] - c[1] for q in on], [q[0] - c[0] for q in on])))
    gaps = np.diff(np.append(ang, ang[0] + 360.0))
    k = int(np.argmax(gaps))   # the arc runs from the end of the largest gap round to its start
    start = float(ang[(k + 1) % len(ang)])
    return start - 12.0, start + 360.0 - float(gaps[k]) + 12.0


def _postures_extent(res: Result) -> tuple[np.ndarray, float]:
    post = res.postures
    assert post is not None
    pts = np.vstack([post.positions((0.0, 0.0)), post.positions(post.second)])
    return pts.mean(axis=0), max(float(np.max(np.ptp(pts, axis=0))), post.scale)


def hidden(cx: Construction, post: Any) -> set[str]:
    """The steps of a body-guidance construction not drawn one by one.

    The curves' own steps (drawn as the curves), the marked points of the
    postures (drawn as the body's bars) and the bisectors that found the poles
    (the pole construction of Fig. 9.7, left out where the postures are bars).
    """
    marked = {f"{n}{j + 1}" for n in post.names for j in range(post.n)}
    helpers = {lab for s in cx if s.op == "rigid" and s.inputs and s.inputs[0] in marked
               for lab in s.outputs}
    pole_bisectors = {s.label for s in cx if s.op == "bisector"
                      and set(s.inputs) <= marked | helpers}
    return _after_t(cx) | marked | pole_bisectors


def _body_panel(res: Result, max_inches: float, skip: frozenset[str],
                stage: tuple[Construction, int] | None = None) -> tuple[Panel, Pen]:
    """The postures, poles, constructions, curves and linkage of body guidance (Figs. 9.7-9.24).

    ``stage``: a teaching frame (see :attr:`Pen.stage`): the postures and the
    construction up to that step, no curves and no linkage.
    """
    post = res.postures
    assert post is not None
    mid, size = _postures_extent(res)
    reach = REACH * size
    keep = [*post.positions((0.0, 0.0)), *post.positions(post.second)]
    for cx in (res.construction, res.selection):
        if cx is None:
            continue
        ev = cx.evaluate({"t": np.array(0.0)} if "t" in cx.labels else None, strict=False)
        after = _after_t(cx)
        for s in cx:
            if s.kind == "point" and s.outputs[0] not in after and s.outputs[0] in ev:
                xy = _xy(ev[s.outputs[0]])
                if xy is not None and float(np.hypot(*(xy - mid))) <= reach:
                    keep.append(xy)
    link = res.chosen
    if link is not None:
        a, b = link.pivots
        for z in (link.o_a, link.o_b, *a, *b):
            if np.isfinite(z) and abs(z - complex(*mid)) <= reach:
                keep.append(_c(z))
    for bp in res.burmester:
        for z in (bp.center, bp.circle):
            if abs(z - complex(*mid)) <= reach:
                keep.append(_c(z))
    arr = np.array(keep)
    lo, hi = arr.min(axis=0), arr.max(axis=0)
    pad = 0.06 * float(max(hi - lo))
    lo, hi = lo - pad, hi + pad
    title = {"2 postures": "(a) two postures: the pole P₁₂ (Fig. 9.6)",
             "3 postures": "(a) three postures: the pole triangle (Figs. 9.8-9.18)",
             "4 postures": "(a) four postures: the center-point curve (Figs. 9.20-9.24)",
             "5 postures": "(a) five postures: the Burmester points (Sec. 9.6)",
             "coupler curve (Sec. 9.9)": "(a) a coupler curve through four precision points "
                                         "(Figs. 9.30-9.32)"}.get(
        res.kind, "(a) path generation with prescribed timing (Sec. 9.12, Fig. 9.41)")
    p = panel("synthesis", title, res.spec.units, lo, hi, max_inches)
    pen = Pen(p, skip)
    d, e = post.names
    # the postures first: the body as a bar between its two marked points (Fig. 9.7)
    pos_d, pos_e = post.positions((0.0, 0.0)), post.positions(post.second)
    given = res.spec.postures is not None   # else the body is the coupler, its point the path's
    for j in range(post.n):
        g = pen.group(f"posture-{j + 1}", 4.0, key=f"posture {j + 1}")
        if given:
            pen.segment(g, pos_d[j], pos_e[j], "vector-abs", key=f"posture-{j + 1}")
            pen.point(g, f"{e}{j + 1}", pos_e[j], "point", optional=True)
        pen.point(g, f"{d}{j + 1}", pos_d[j], "point")
    if stage is not None:
        pen.stage = stage
        order = [c for c in (res.construction, res.selection) if c is not None]
        pen.before = order[:next(i for i, c in enumerate(order) if c is stage[0])]
    for cx in (res.construction, res.selection):
        if cx is None:
            continue
        locus = "k_O" in cx.labels    # the straight-line circles of Example 9.4
        optional = {s.outputs[0] for s in cx if (locus and s.outputs[0] in (
            "O", "O1", "O2", "O3", "H")) or s.outputs[0].endswith(("_I", "*"))}
        paint_construction(pen, cx, hidden(cx, post), mid, reach, optional,
                           "-selection" if cx is res.selection else "")
    for cx in (res.construction, res.selection):
        if cx is not None:
            far_poles(pen, cx, post.positions((0.0, 0.0))[0], f"{d}1")
    if stage is not None:
        return p, pen
    if res.curves is not None:
        jump = 0.25 * float(max(hi - lo))
        for br in range(2):
            g = pen.group(f"center-point-curve-{br + 1}", 1.0,
                          key=f"center-point curve {br + 1}")
            pen.polyline(g, res.curves.center[br], "cubic",
                         key=f"center-point-curve-{br + 1}", jump=jump)
            g2 = pen.group(f"circle-point-curve-{br + 1}", 1.0,
                           key=f"circle-point curve {br + 1}")
            pen.polyline(g2, res.curves.circle[br], "ref-line",
                         key=f"circle-point-curve-{br + 1}", jump=jump)
    used = set() if link is None else {link.o_a, link.o_b}
    for k, bp in enumerate(res.burmester, 1):
        g = pen.group(f"burmester-{k}", 5.0, key=f"Burmester point {k}")
        if bp.center in used:
            g.items.append(Item("marker", np.array([_c(bp.center)]), "ball"))  # lettered O_A
        else:
            pen.point(g, f"M{k}", _c(bp.center), "ball")
            pen.point(g, f"m{k}", _c(bp.circle), "aux-point", optional=True)
    if link is not None:
        paint_linkage(pen, link)
    far_points(pen, post.positions((0.0, 0.0))[0], f"{d}1")
    return p, pen


def _far_arrow(pen: Pen, gid: str, names: list[str], xy: np.ndarray, ref: np.ndarray,
               ref_name: str, step: Any = None) -> None:
    """An arrow at the panel's edge toward the far point ``xy``, named, with its distance.

    Lettered with its names and its distance from ``ref`` (``M₂, O_B, 12.3 in
    from D₁``), as graphkin letters far instant centers.
    """
    from graphkin.render.scene import far_distance

    box = pen.box
    mid = np.array([(box[0] + box[2]) / 2, (box[1] + box[3]) / 2])
    k = pen.p.k
    seg = clip_segment(mid, xy, box)
    if seg is None:
        return
    u = (xy - mid) / float(np.hypot(*(xy - mid)))
    tip = np.asarray(seg[1], dtype=float) - 0.08 * k * u
    tail = tip - 0.45 * k * u
    lab = names[0]
    g = pen.group(gid, 5.0, step=step, key=lab)
    arrow = Item("arrow", np.array([tail, tip]), "vector-aux", key=f"{lab}-arrow",
                 head=0.08 * k, width=0.028 * k)
    g.items.append(arrow)
    for n in names:
        pen.points[n] = tail
        pen.labelled.add(n)
    who = ", ".join(letter(n) for n in names)
    far = f"{far_distance(float(np.hypot(*(xy - ref))))} {pen.p.unit}"
    text = f"{who}, {far} from {letter(ref_name)}"
    # where the edge has no room: the distance on a second line, then the name alone
    pen.p.labels.append(LabelRequest(text, tail, "label", f"label-{g.gid}-{lab}", g,
                                     key=lab, arrow=arrow,
                                     fallback=(f"{who}\n{far} from {letter(ref_name)}",
                                               f"{who}, {far}", f"{who}\n{far}", who)))


def far_points(pen: Pen, ref: np.ndarray, ref_name: str) -> None:
    """An arrow at the panel's edge toward each point asked for beyond it (Sec. 9.6).

    A Burmester point or a pivot of the chosen linkage far from the postures
    is not left off with nothing said: it is drawn as graphkin draws every far
    point, an arrow at the edge lettered with its name and its distance from the
    first posture's point; points at one place share one arrow (``M₂, O_B``).
    """
    groups: list[tuple[list[str], np.ndarray]] = []
    tol = 1e-9 * pen.p.diag()
    for name, xy in pen.off.items():
        if name in pen.points or name in pen.labelled:
            continue
        for names, q in groups:
            if float(np.hypot(*(q - xy))) <= tol:
                names.append(name)
                break
        else:
            groups.append(([name], xy))
    for names, xy in groups:
        _far_arrow(pen, f"far-{names[0]}", names, xy, ref, ref_name)


def far_poles(pen: Pen, cx: Construction, ref: np.ndarray, ref_name: str) -> None:
    """An arrow at the panel's edge toward each finite pole left off the figure.

    Lettered with the pole's distance from the first posture's point
    (``P₃₄, 11.2 in from D₁``).
    """
    ev = cx.evaluate({"t": np.array(0.0)} if "t" in cx.labels else None, strict=False)
    for s in cx:
        lab = s.outputs[0]
        if not _POLE.match(lab) or lab in pen.points or lab not in ev:
            continue
        xy = _xy(ev[lab])
        if xy is None or pen.inside(xy):
            continue
        _far_arrow(pen, f"{s.step_id}-far", [lab], xy, ref, ref_name, step=s)


def paint_linkage(pen: Pen, link: Any, postures: bool = True) -> None:
    """The four-bar O_A A B O_B in every design posture (the first bold), pins lettered."""
    a, b = link.pivots
    na, nb = link.names
    dpos = link.post.positions((0.0, 0.0))
    for j in range(a.shape[0]):
        if not postures and j:
            break
        g = pen.group(f"linkage-{j + 1}", 4.5, key=f"linkage {j + 1}")
        chain = [link.o_a, a[j], b[j], link.o_b]
        style = "result-line" if j == 0 else "aux-line"
        for p, q in zip(chain[:-1], chain[1:]):
            pen.segment(g, _c(p), _c(q), style)
        for p in (a[j], b[j]):
            pen.segment(g, _c(p), dpos[j], "aux-line" if j else "given-line")
        pen.point(g, f"{na}{j + 1}", _c(a[j]), "pin")
        pen.point(g, f"{nb}{j + 1}", _c(b[j]), "pin")
    g = pen.group("fixed-pivots", 5.5, key="fixed pivots")
    pen.point(g, f"O_{na}", _c(link.o_a), "pin")
    pen.point(g, f"O_{nb}", _c(link.o_b), "pin")
    path = link.coupler_path()
    g = pen.group("coupler-curve", 0.5, key="coupler curve")
    pen.polyline(g, path, "datum", key="coupler-curve",
                 jump=0.25 * max(link.post.scale, 1e-300))


def synthesis_sheet(res: Result, *, max_inches: float = 6.0,
                    skip: frozenset[str] = frozenset(),
                    stage: tuple[Construction, int] | None = None) -> tuple[Sheet, list[Pen]]:
    """Lay out the drawing of a synthesis on a sheet (pure data, no matplotlib).

    ``stage``: one frame of the teaching page (a construction and the step it
    is drawn up to).  Returns the sheet and the pens of its panels (their
    optional labels).
    """
    from graphkin.render import synthesis_more as more

    if res.function is not None:
        pairs = more.function_panels(res, max_inches, skip, stage)
    elif res.cognates is not None:
        pairs = [more.cognates_panel(res, max_inches, skip, stage)]
    elif res.dwell is not None:
        pairs = [more.dwell_panel(res, max_inches, skip, stage)]
    elif res.overlay is not None:
        pairs = [more.overlay_panel(res, max_inches, skip, stage)]
    elif res.crank_rocker is not None:
        pairs = [more.crank_rocker_panel(res, max_inches, skip, stage)]
    else:
        pairs = [_body_panel(res, max_inches, skip, stage)]
    panels = [p for p, _ in pairs]
    for p in panels:
        _frame(p)
        place_labels(p)
    sheet = Sheet(panels, (0.0, 0.0), res.spec.title or f"Synthesis: {res.kind}", "synthesis")
    sheet.width_cap = 2 * max_inches + 1.5
    _layout(sheet, legend=False)
    return sheet, [pen for _, pen in pairs]


BIG = {"4 postures": 8.5, "5 postures": 8.5}
"""Room (inches) for the crowded figures: the curves, six or ten poles, two dyads in every
posture (at 6 in the letters of a figure like Example 9.5's stood away from their points)."""


def draw_synthesis(res: Result, *, max_inches: float | None = None) -> Any:
    """The drawing (:class:`~graphkin.render.mpl.Drawing`) of a synthesis.

    Words naming a curve and the letters of auxiliary points (the image point,
    the straight-line circles' centers, the body's second point) that find no
    place clear of every line and letter are left out, as the gear drawings
    leave out the names of crowded circles; the letters of poles, pivots and
    postures always stay, and where one still finds no clean place the figure
    is drawn larger (1.3, 1.7 and 2.2 times).
    """
    from graphkin.render.labels import collisions
    from graphkin.render.mpl import render_sheet

    if max_inches is None:
        max_inches = BIG.get(res.kind, 6.0)
    for grow in (1.0, 1.3, 1.7, 2.2):   # a crowded figure is drawn larger: more room for letters
        skip: frozenset[str] = frozenset()
        for _ in range(4):
            sheet, pens = synthesis_sheet(res, max_inches=grow * max_inches, skip=skip)
            drawing = render_sheet(sheet)
            optional = set().union(*(pen.optional for pen in pens))
            hits = collisions(drawing)
            bad = {gid for _, gid, _ in hits if gid in optional}
            if not bad:
                break
            skip = skip | bad
        if not hits:
            break
    return drawing


def synthesis_figure(res: Result) -> Any:
    """The matplotlib Figure of a synthesis (no pyplot state)."""
    return draw_synthesis(res).figure


def save_synthesis(res: Result, path: str | os.PathLike[str]) -> Path:
    """Draw the result and write it (SVG, PDF or PNG by the suffix)."""
    from graphkin.render.svg import save

    return save(synthesis_figure(res), path)
