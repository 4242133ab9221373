"""Reading the student's image points off a rectified worksheet.

Each image point of the polygon can only be in a few places: where it truly
is, or where one of the usual mistakes puts it (the polygon turned 180° for
a reversed sense, and each single mistake of
:meth:`graphkin.check.diagnose.Diagnoser.candidates`: an image flipped over,
a relative velocity drawn from the pole, a normal component drawn outward,
the Coriolis component's mistakes, the other branch, the whole polygon redrawn
from a slip in the input's rate ...), or where the construction puts it when
done right from the student's own images read wrong before it
(follow-through, :class:`graphkin.check.carry.Carry`).  The names are given
to the pencil segments' ends near those places (within 4 mm, or 12 % of the
vector's length on the sheet if that is more) all at once, the assignment of
least total distance, two names never on one vertex; where two or more
segments end there, the image is where their lines meet.  A polygon drawn
for the wrong sense of the input's ω is turned 180° as a whole, one
decision for the drawing: the names are also given for the places turned
(each image's reversed place first, then its usual mistakes' turned), and
the reading of less total distance is taken.  The points, in mm
on the sheet, with the printed scale and pole, are then marked as
``check --drawing`` marks a drawing with a stated scale
(:func:`graphkin.check.drawing.check_polygons`: not turned, within the
drawing tolerance in mm on the sheet, follow-through included; that
marking is :mod:`graphkin.scan.mark`).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (image points measured from the
pole to the scale), Sec. 3.5 (images flipped over), Secs. 4.3-4.5 (normal and
Coriolis components).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphkin.check.answers import Given, Key
from graphkin.check.carry import carry_for
from graphkin.check.diagnose import Diagnoser, Mistake
from graphkin.errors import GraphkinError, InputError
from graphkin.scan.arrows import arrow_tips, broken_by_tips, head_at
from graphkin.scan.crossings import other_ray, past_crossings
from graphkin.scan.inkfit import Sheet, refine_read
from graphkin.scan.poleray import pole_ray_cuts, printed_sheet
from graphkin.scan.sheet import PX_PER_MM, Page, Rectified, rectify, template_ink
from graphkin.scan.strokes import apart, ends, pencil, segments, vertex_at
from graphkin.scan.tipweight import tip_behind
from graphkin.tolerance import sign

__all__ = ["SheetRead", "read_sheet", "places", "NOT_FOUND", "too_short"]

NOT_FOUND = Mistake("missing", "no pencil line ends near where this image point can be: "
                               "not drawn, or too faint to read", "not-found")
_NEAR_MM = 4.0
_NEAR_FRACTION = 0.12
_POLE_MM = 2.5
_SHORT_MM = 7.0
"""A vector shorter than this on the sheet is not read: the printed pole hides its
first 1.1 mm and a stroke under 5 mm cannot be told from an arrowhead or a letter."""
_SAME_MM = 2.5
_UNTOLD_MM = 2.0
"""A usual mistake is not named for an image read this close to its right place: the
reading is off by up to about 2 mm (docs/checking.md), so a mistake that moves the
image less than that cannot be told from a misread."""
_CLEAR_MM = 6.0
_ALTERNATIVE_MM = 1.5
"""A mistaken place counts as this much farther than it is (the exact one wins a tie)."""
_CARRIED_MM = 0.5
"""A place constructed right from the student's own wrong images counts this much farther:
nearer than a usual mistake's (one mistake carried through is likelier than two), farther
than the exact one."""
_OWN_MM = 1.0
"""An image read farther than this from its exact place is carried on as the student drew it
(follow-through from the student's own images); nearer, it is the reading's own error."""
_CARRY_ROUNDS = 3
_CHOICES = 4
"""The nearest vertices (within reach) each name may take in the joint assignment."""
_TELL_MM = 1.0
_GAP_MM = 2.0
_STRONG_MM = 0.5
_GAP_SIN = math.sin(math.radians(8.0))
_PAST_MM = 1.0
"""A vertex read farther than this beyond every stroke's end there, on bare paper, is the
crossing of a line passing by (the hand stops short by up to 0.3 mm)."""
_HALF_END_MM = 0.5
"""The rounded end of a stroke and of a line it meets: left out of the stretch between."""
_OWN_RUN_MM = 1.2
"""Ink past a gap in a stroke is its own when it runs on this far along it (:func:`_own_end`)."""
_HEAD_HOLD_MM = 1.0
"""An image read at an arrowhead's tip found at its place is not moved farther than this by
its lines' ink (a tip is found to 0.1-0.3 mm, at most 0.9 mm off; see :func:`_held_at_heads`)."""
_AGREE_MM = 0.5
"""A vertex read and an arrowhead's tip found this near (mm) agree: the hand's 0.5 mm."""
_RAY_LINE_MM = 1.5
_RAY_START_MM = 10.0
"""A segment end under this far from the pole, on a line through the pole within 1.5 mm,
is the start of a vector drawn from the pole, not an image point."""


@dataclass
class SheetRead:
    """What was read from one page.

    Attributes
    ----------
    rect : Rectified
    layout : Layout
    segments : ndarray (n, 2, 2)
        Pencil segments, sheet mm.
    points : dict
        Name -> the image point read (sheet mm).
    places : dict
        Name -> the places it can be (sheet mm; the exact one first).
    missing : list of str
    notes : list of str
        What the reading could not decide (two images that cannot be told apart).
    carried : dict
        Name -> where it is when constructed right from the images read before
        it that are wrong (sheet mm; follow-through from the student's own images).
    arrows : ndarray (k, 2)
        The tips of arrowheads in the middle of a line from the pole, where
        no segment ends (sheet mm; :func:`graphkin.scan.strokes.arrow_tips`).
    turned : dict
        Name -> the places it can be when the whole polygon is drawn turned
        180° (the reversed one first; see :func:`_places`); empty: the
        turned polygon is not looked for.
    is_turned : bool
        Whether the names were given for the turned polygon (its total
        distance was the less).
    sheet : Sheet or None
        The pencil's darkness on the sheet (:class:`graphkin.scan.inkfit.Sheet`),
        to tell whether a stroke runs on to a vertex read past its end.
    moved : dict
        Name -> how far the ink's lines moved the image from where the pencil
        segments' ends put it (mm; :func:`graphkin.scan.inkfit.refine_read`).
    heads : ndarray (k, 2)
        The tips of arrowheads found at the places the images can be, along
        the pole → place direction (sheet mm; :func:`_with_heads`); each
        not in ``arrows`` a vertex the names may take, none breaking a stroke
        (:func:`graphkin.scan.arrows.broken_by_tips` takes ``arrows`` alone).
    """

    rect: Rectified
    layout: Any
    segments: np.ndarray
    points: dict[str, np.ndarray] = field(default_factory=dict)
    places: dict[str, list[np.ndarray]] = field(default_factory=dict)
    missing: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    carried: dict[str, list[np.ndarray]] = field(default_factory=dict)
    arrows: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))
    turned: dict[str, list[np.ndarray]] = field(default_factory=dict)
    is_turned: bool = False
    sheet: Sheet | None = None
    moved: dict[str, float] = field(default_factory=dict)
    heads: np.ndarray = field(default_factory=lambda: np.zeros((0, 2)))


def _names(sol: Any) -> list[str]:
    mech = sol.mechanism
    return [n for n in mech.point_names if n not in mech.helper_points]


def places(sol: Any, layout: Any, diag: Diagnoser) -> dict[str, list[np.ndarray]]:
    """Where each image point can be on the sheet (mm): exact, reversed, each variant.

    Image points less than 7 mm from the pole are left out: at the pole
    (fixed points) nothing can be drawn, and a shorter vector cannot be read
    (see :func:`too_short`).  A mistaken place is kept only
    inside the polygon area, clear of the pole (where every vector starts)
    and of every other image's exact place (a right neighbour is not read
    as this image's mistake).
    """
    return _places(sol, layout, diag)[0]


def _places(sol: Any, layout: Any, diag: Diagnoser
            ) -> tuple[dict[str, list[np.ndarray]], dict[str, list[np.ndarray]]]:
    """:func:`places`, and the places of the polygon turned 180° about the pole.

    The turned polygon (the input's ω taken the wrong way, Sec. 3.4) is one
    decision for the whole drawing, not one per image: its places are those
    of :func:`places` turned about the pole (each image's reversed place
    first, then its exact one and each usual mistake's, turned: that mistake
    and the reversed sense), kept by the same rules turned, so clear of
    every other image's *reversed* place, where the turned polygon's
    neighbours are.
    """
    letter = "V" if layout.diagram == "velocity" else "A"
    pole = np.array(layout.pole)
    f = sol.velocity if layout.diagram == "velocity" else sol.acceleration
    exact: dict[str, np.ndarray] = {}
    for name in _names(sol):
        v = np.asarray(f(name), dtype=float) / layout.per_mm
        if float(np.hypot(*v)) >= _SHORT_MM:
            exact[name] = pole + v
    out: dict[str, list[np.ndarray]] = {}
    turned: dict[str, list[np.ndarray]] = {}
    rights = list(exact.values())
    for name, e in exact.items():
        at = [e, 2 * pole - e]
        key = Key(f"{letter}_{name}", letter, (name,))
        vec = (e - pole) * layout.per_mm
        given = Given(key, "", value=float(np.hypot(*vec)),
                      direction=math.degrees(math.atan2(vec[1], vec[0])), vector=vec)
        try:
            exact_value = diag.ev.value(key)
            found = [c for m, c in diag.candidates(given, exact_value) if m.kind != "combined"]
        except GraphkinError:
            found = []
        for c in found:
            xy = c.xy
            if xy is not None and not c.ideal and np.all(np.isfinite(xy)):
                at.append(pole + np.asarray(xy, dtype=float) / layout.per_mm)
        out[name] = _kept(at, rights, layout)
        turned[name] = _kept([2 * pole - c for c in at], [2 * pole - q for q in rights], layout)
    return out, turned


def _kept(at: list[np.ndarray], exact: list[np.ndarray], layout: Any) -> list[np.ndarray]:
    """``at[0]``, and those of ``at[1:]`` clear of the rest (one of each place).

    Kept: inside the polygon area, clear of the pole and of every place in
    ``exact`` (the images' right places).
    """
    pole = np.array(layout.pole)
    x0, y0, x1, y1 = layout.polygon_box
    keep = [at[0]]
    for c in at[1:]:
        if not (x0 < c[0] < x1 and y0 < c[1] < y1):
            continue
        if float(np.hypot(*(c - pole))) < _CLEAR_MM:
            continue
        if any(float(np.hypot(*(c - q))) < _CLEAR_MM for q in exact):
            continue
        if any(float(np.hypot(*(c - q))) < 0.3 for q in keep):
            continue
        keep.append(c)
    return keep


def too_short(sol: Any, layout: Any) -> list[str]:
    """The images away from the pole whose vectors are too short to read (not marked)."""
    f = sol.velocity if layout.diagram == "velocity" else sol.acceleration
    return [n for n in _names(sol)
            if _POLE_MM <= float(np.hypot(*np.asarray(f(n), dtype=float))) / layout.per_mm
            < _SHORT_MM]


def read_sheet(sol: Any, page: Page, diag: Diagnoser, digest: str, title: str = "",
               upto: int | None = None) -> SheetRead:
    """Rectify one page, find its pencil segments and the image points they end at."""
    from graphkin.render.worksheet_layout import worksheet_layout

    if page.identity is not None and page.identity.get("digest") != digest:
        raise InputError(f"this worksheet was printed for another mechanism file (its hash "
                         f"{page.identity.get('digest')}, this file's {digest})",
                         file=page.name, key="--scan")
    rect = rectify(page)
    layout = worksheet_layout(sol, rect.diagram, rect.paper, digest,
                              rect.upto if rect.upto is not None else upto)
    ink = template_ink(sol, layout, title)
    w, h = layout.size
    x0, y0, x1, y1 = layout.polygon_box
    box = (int(x0 * PX_PER_MM), int((h - y1) * PX_PER_MM), int(np.ceil(x1 * PX_PER_MM)),
           int(np.ceil((h - y0) * PX_PER_MM)))
    ratio = pencil(rect.gray, ink, box)
    segs = apart(segments(ratio, (box[0], box[1]), h), ratio, (box[0], box[1]), h)
    sheet = Sheet(ratio, (box[0], box[1]), h)
    at, turned = _places(sol, layout, diag)
    segs = pole_ray_cuts(segs, sheet, np.array(layout.pole),    # tips run on past a short
                         [q for ps in (*at.values(), *turned.values()) for q in ps],
                         printed_sheet(ink, box, h))           # vector's end, over a barb
    segs = past_crossings(segs, sheet)                      # tips run on to letters
    read = SheetRead(rect, layout, segs, places=at, turned=turned,
                     arrows=arrow_tips(segs, ratio, (box[0], box[1]), h,
                                       np.array(layout.pole)),
                     sheet=sheet)
    read.heads = _with_heads(read)
    _match(read)
    for _ in range(_CARRY_ROUNDS):
        if not _carried(read, sol, diag):
            break
        _match(read)
    at_head = {n: p.copy() for n, p in read.points.items()
               if _at_head(read, p) or _by_head(read, p)}
    refine_read(read, sol, ratio, (box[0], box[1]), h)      # the images from their lines' ink
    _held_at_heads(read, at_head)
    return read


def _at_head(read: SheetRead, p: np.ndarray) -> bool:
    """Whether ``p`` is an arrowhead's tip that one found at a place confirms (within 1 mm)."""
    tips = _head_points(read)
    if not len(read.heads) or not len(tips):
        return False
    return bool(float(np.min(np.hypot(*(tips - p).T))) < 1e-9
                and float(np.min(np.hypot(*(read.heads - p).T))) < 1.0)


def _by_head(read: SheetRead, p: np.ndarray) -> bool:
    """Whether an arrowhead found at a place lies within :data:`_AGREE_MM` of ``p``.

    The vertex read from the segments' ends and the tip of the arrowhead
    looked for along pole -> place (:func:`_with_heads`) are two readings of
    where the vector ends (Sec. 3.4: the arrowhead at the image); where they
    agree to the hand's 0.5 mm, the lines fitted to the ink may not carry
    the image over 1 mm away (:func:`_held_at_heads`): a vector crossing a
    band of merged link lines (a coupler point on its link's line, Sec. 3.5)
    has its ink walked on through the band, past the image.
    """
    if not len(read.heads):
        return False
    return float(np.min(np.hypot(*(read.heads - p).T))) <= _AGREE_MM


def _held_at_heads(read: SheetRead, at_head: dict[str, np.ndarray]) -> None:
    """Put back at its arrowhead's tip an image the ink's lines moved far from it.

    An image read at an arrowhead found at its place (:func:`_with_heads`) is
    where the student's vector ends, to 0.1-0.3 mm (Sec. 3.4: each vector's
    arrowhead at its image).  Its lines, fitted to the ink
    (:func:`graphkin.scan.inkfit.refine_read`), are least sure where the
    image has no segment end of its own: in a band of merged strokes they
    cross 0.6-3 mm along the band.  A move of more than :data:`_HEAD_HOLD_MM`
    from the tip is not taken.  So too for an image read where the segments'
    ends and such a tip agree (:func:`_by_head`): it is put back where read.
    """
    for name, tip in at_head.items():
        if read.moved.get(name, 0.0) <= _HEAD_HOLD_MM:
            continue
        moved = read.moved.pop(name)
        read.points[name] = tip
        read.notes = [n for n in read.notes
                      if not n.startswith(f"{name.lower()} is read {moved:.1f} mm from")]


def _with_heads(read: SheetRead) -> np.ndarray:
    """The arrowheads found at the places the images can be (mm, (k, 2)).

    Every absolute vector starts at the printed pole and has its arrowhead at
    its image (Uicker, Pennock & Shigley, 5th ed., Sec. 3.4), and every place
    an image can be is known (``read.places``, ``read.turned``): at each, an
    arrowhead is looked for with its axis along pole → place, its tip within
    the image's reach of the place (:func:`graphkin.scan.arrows.head_at`: one
    barb may lie in another stroke's ink).  A short vector whose ink is one
    band with a link line near the pole, or an image in the middle of a band
    of merged strokes, has no segment end of its own there; its tip is then
    one more vertex the names may take (:func:`_head_points`).
    """
    heads: list[np.ndarray] = []
    if read.sheet is None:
        return np.zeros((0, 2))
    pole = np.array(read.layout.pole)
    seen: list[np.ndarray] = []
    for name, at in read.places.items():
        reach = max(_NEAR_MM, _NEAR_FRACTION * float(np.hypot(*(at[0] - pole))))
        for c in at + read.turned.get(name, []):
            if any(float(np.hypot(*(c - q))) < 0.3 for q in seen):
                continue
            seen.append(c)
            tip = head_at(read.sheet, c, pole, reach)
            if tip is not None:
                heads.append(tip)
    return np.array(heads).reshape(-1, 2)


def _head_points(read: SheetRead) -> np.ndarray:
    """The arrowheads' tips the names may take (mm, (k, 2)).

    ``read.arrows``, then each of ``read.heads`` over 1 mm from those before
    it (one arrowhead found twice is one vertex).
    """
    tips = [p for p in read.arrows.reshape(-1, 2)]
    for h in read.heads.reshape(-1, 2):
        if all(float(np.hypot(*(h - q))) >= 1.0 for q in tips):
            tips.append(h)
    return np.array(tips).reshape(-1, 2)


def _carried(read: SheetRead, sol: Any, diag: Diagnoser) -> bool:
    """Add, for each image, where it is when constructed right from the images read wrong.

    Follow-through from the student's own images (:class:`graphkin.check.carry.Carry`):
    every image read away from its exact place is put in the construction as
    read, and each later image's place in the construction replayed from
    those before it is one more place it can be (kept as the usual
    mistakes' places are: inside the polygon area, clear of the pole and of
    every other image's exact place).  Returns whether any place was added.
    """
    layout = read.layout
    pole = np.array(layout.pole)
    carry = carry_for(diag)
    drawn = {n: (p - pole) * layout.per_mm for n, p in read.points.items()
             if float(np.hypot(*(p - read.places[n][0]))) > _OWN_MM}
    if not drawn:
        return False
    x0, y0, x1, y1 = layout.polygon_box
    added = False
    order = carry.order(layout.diagram)
    for i, name in enumerate(order):
        before = {n: drawn[n] for n in order[:i] if n in drawn}
        at = read.places.get(name)
        if at is None or not before:
            continue
        v = carry.images(layout.diagram, before).get(name)
        if v is None:
            continue
        c = pole + v / layout.per_mm
        if not (x0 < c[0] < x1 and y0 < c[1] < y1) or float(np.hypot(*(c - pole))) < _CLEAR_MM:
            continue
        if any(float(np.hypot(*(c - q[0]))) < _CLEAR_MM for n, q in read.places.items()
               if n != name):
            continue
        mine = read.carried.setdefault(name, [])
        if any(float(np.hypot(*(c - q))) < 0.3 for q in at + mine):
            continue
        mine.append(c)
        added = True
    return added


def _match(read: SheetRead) -> None:
    """Name the vertices: the best joint assignment of vertices to names (see the module).

    Each name may take any segment end within its reach of one of its places
    (cost: the distance; plus 1.5 mm to a usual mistake's place, plus 0.5 mm
    to a place carried from the student's own wrong images, plus 2 mm for an
    end that may be a gap in one straight line, less 0.5 mm for each other
    segment ending with it, at most 1 mm) or none (cost: more than any
    within reach), two names never one vertex (ends within 2.5 mm) unless
    their exact images coincide; of all such assignments the one of least
    total cost is taken, so an image nearest to a vertex another image needs
    more does not take it.  The start of a vector drawn from the pole (the
    end near the pole of a segment whose line runs through it: the printed
    pole and its label hide the first millimetres of every vector) is no
    vertex.  Where another assignment costs hardly more (1 mm) and
    swaps two names' vertices, a note says the two cannot be told apart.

    With ``read.turned`` (the places of the polygon turned 180°, Sec. 3.4:
    the input's ω taken the wrong way), the names are given for those places
    too, and the turned reading is taken when its total cost is the less
    (beyond round-off; ``read.is_turned``).  Per image, a turned image near
    another image's right place would take that name (its own reversed place
    was dropped as a right neighbour's), and one near one of its unturned
    mistakes' places a stray end there.
    """
    read.points = {}
    read.notes = []
    segs = read.segments
    pole = np.array(read.layout.pole)
    ends_at, seg_of = ends(segs)
    # the segments' ends, then the arrowheads' tips where none ends (an image in the middle
    # of a straight line from the pole)
    pts = np.concatenate([ends_at, _head_points(read)])
    extra = len(pts) - len(ends_at)
    # a stroke broken beside an arrowhead's tip: the tip is the vertex, not the break
    ok = np.concatenate([_vertex_ends(segs, ends_at, pole)
                         & ~broken_by_tips(segs, read.arrows, _SAME_MM), np.ones(extra, bool)])
    gap = np.concatenate([_gap_ends(segs, ends_at), np.zeros(extra, bool)])
    strong = np.concatenate([_strength(ends_at), np.zeros(extra)])
    names = list(read.places)
    reach = {n: max(_NEAR_MM, _NEAR_FRACTION * float(np.hypot(*(at[0] - pole))))
             for n, at in read.places.items()}

    def candidates(where: dict[str, list[np.ndarray]]) -> dict[str, list[tuple[float, int]]]:
        cands: dict[str, list[tuple[float, int]]] = {}
        for name in names:
            at = where[name]
            if not len(pts):
                cands[name] = []
                continue
            d = np.min([np.hypot(*(pts - c).T) + (_ALTERNATIVE_MM if i else 0.0)
                        for i, c in enumerate(at)]
                       + [np.hypot(*(pts - c).T) + _CARRIED_MM
                          for c in read.carried.get(name, ())],
                       axis=0) + np.where(gap, _GAP_MM, 0.0)
            best: list[tuple[float, int]] = []
            for j in np.argsort(d - strong, kind="stable").tolist():
                if not ok[j] or d[j] > reach[name]:
                    continue
                if any(float(np.hypot(*(pts[j] - pts[k]))) < _SAME_MM for _, k in best):
                    continue                       # another end of a vertex already listed
                best.append((float(d[j] - strong[j]), int(j)))
                if len(best) == _CHOICES:
                    break
            cands[name] = best
        return cands

    cands = candidates(read.places)
    chosen, cost = _best_assignment(read, names, cands, reach, pts)
    read.is_turned = False
    if read.turned:
        # the polygon turned 180° as a whole (Sec. 3.4: ω2 taken the wrong way): its places
        # are the reversed ones, and its usual mistakes' turned; taken when it costs less
        t_cands = candidates({n: read.turned.get(n) or read.places[n] for n in names})
        t_chosen, t_cost = _best_assignment(read, names, t_cands, reach, pts)
        if sign(cost - t_cost, max(cost, t_cost)) > 0:
            cands, chosen, read.is_turned = t_cands, t_chosen, True
    for name, j in chosen.items():
        p = pts[j]
        near = [int(seg_of[k]) for k in np.flatnonzero(np.hypot(*(ends_at - p).T) < _SAME_MM)
                if j < len(ends_at)]           # an arrowhead's tip: on its own line
        # an arrowhead found at a place, along pole -> place: the tip is the vertex, not a
        # crossing of lines passing near it (in a band of merged strokes they cross anywhere)
        held = j >= len(ends_at) and _at_head(read, p)
        v = p.copy() if held else _vertex(read, sorted(set(near)), p, pole)
        # the ends' vertex carried on along its own vector past the arrowhead found there
        read.points[name] = v if held else tip_behind(read.segments, read.heads, v, pole,
                                                      _SAME_MM, _RAY_LINE_MM, _PAST_MM,
                                                      _GAP_SIN)
    read.missing = [n for n in read.places if n not in read.points]
    read.notes += _untellable(read, chosen, cands, pts)


def _vertex(read: SheetRead, near: list[int], p: np.ndarray, pole: np.ndarray) -> np.ndarray:
    """The vertex where segments ``near`` end at ``p`` (:func:`vertex_at`), on their ink.

    :func:`vertex_at` also crosses the strokes ending there with long lines
    passing within 3 mm (a stroke run on over a line's ink ends past it).
    A line passing by that the strokes never reach puts the vertex on bare
    paper beyond every stroke's end: the lines' crossing is then no vertex
    drawn (a four-bar's link `a b` passing 3 mm beyond `f` when `b` is drawn
    short), and the vertex is read from the strokes ending there alone.  A
    stroke's end is past its vertex, or short of it by the hand's 0.3 mm
    (Sec. 3.4: each vector drawn to its image point); a vertex more than
    :data:`_PAST_MM` beyond every end, with no pencil line running on to it
    (under half the stretch as dark as half the stroke), is such a crossing.
    Each end is where the stroke's own ink ends (:func:`_own_end`), not
    where a segment's tip walked over a gap onto the passing line's ink.
    Another image's vector from the pole passing 1 mm or more from ``p``
    is none of the vertex's lines (:func:`graphkin.scan.crossings.other_ray`).
    """
    keep = [i for i, g in enumerate(read.segments)
            if i in near or not other_ray(g, p, pole, _RAY_LINE_MM, _RAY_START_MM)]
    if near and len(keep) < len(read.segments):      # another image's vector: not this vertex's
        read = dataclasses.replace(read, segments=read.segments[keep])
        near = [keep.index(k) for k in near]
    v = vertex_at(read.segments, near, p, pole)
    if not near or read.sheet is None:
        return v
    segs = read.segments.copy()
    for k in near:
        t = int(np.argmin(np.hypot(*(segs[k] - p).T)))
        tip, far = segs[k, t], segs[k, 1 - t]
        u = (tip - far) / max(float(np.hypot(*(tip - far))), 1e-12)
        segs[k, t] = tip = _own_end(read.sheet, far, tip)
        past = float((v - tip) @ u)
        if past <= _PAST_MM or _inked(read.sheet, far, tip, v):
            return v
    return vertex_at(segs[near], list(range(len(near))), p, pole)


def _own_end(sheet: Sheet, far: np.ndarray, tip: np.ndarray) -> np.ndarray:
    """Where segment ``far``-``tip``'s own ink ends, walking its line to its tip (mm).

    Its tip (:func:`graphkin.scan.strokes.segments`) is walked over gaps
    under 3 mm, also onto another stroke's ink beyond one; ink past a gap is
    the stroke's own only when it runs on :data:`_OWN_RUN_MM` along the line
    (a line crossing it at over 40° is narrower along it): the end is then
    the last sample before that gap (a gap: under a quarter of the stroke's
    darkness).
    """
    length = float(np.hypot(*(tip - far)))
    u = (tip - far) / max(length, 1e-12)
    t = np.arange(max(length - 4.0, 0.0), length + 0.05, 0.1)
    if len(t) < 2:
        return tip
    dark = sheet.darkness(far + np.outer(t, u))
    # a gap is paper: under a quarter of the stroke's darkness (a blurred, noisy stroke dips
    # under half of it along its own ink)
    inked = dark >= 0.25 * float(np.median(dark[: max(len(t) // 4, 1)]))
    last, run = 0, 0
    for k in range(1, len(t)):
        if not inked[k]:
            continue
        run = k if not inked[k - 1] else run
        if run <= last + 1 or t[k] - t[run] >= _OWN_RUN_MM:
            last = k
    if t[-1] - t[last] < _HALF_END_MM:
        return tip
    return np.asarray(far + t[last] * u)


def _inked(sheet: Sheet, far: np.ndarray, tip: np.ndarray, v: np.ndarray) -> bool:
    """Whether a pencil line runs on from segment ``far``-``tip``'s end to ``v`` (mm)."""
    length = float(np.hypot(*(tip - far)))
    u = (tip - far) / max(length, 1e-12)
    n = np.array([-u[1], u[0]])
    # the stroke's own darkness over its last 5 mm, the best of three samples across
    t_own = np.arange(max(length - 5.0, 0.0), length - 0.5, 0.1)
    across = np.array([-0.1, 0.0, 0.1])
    own = sheet.darkness(far + np.outer(t_own, u)[:, None, :]
                         + across[None, :, None] * n[None, None, :]).max(axis=1)
    if not len(own):
        return True
    stroke = float(np.median(own))
    # the stretch from the end (and the stroke's rounded end) to the vertex, on the line to v
    w = v - tip
    reach = float(np.hypot(*w))
    wu = w / max(reach, 1e-12)
    wn = np.array([-wu[1], wu[0]])
    t = np.arange(_HALF_END_MM, reach - _HALF_END_MM, 0.1)
    if not len(t):
        return True
    dark = sheet.darkness(tip + np.outer(t, wu)[:, None, :]
                          + across[None, :, None] * wn[None, None, :]).max(axis=1)
    return bool(np.mean(dark >= 0.5 * stroke) >= 0.5)


def _vertex_ends(segs: np.ndarray, pts: np.ndarray, pole: np.ndarray) -> np.ndarray:
    """Which segment ends may be an image: away from the pole, no vector's start."""
    if not len(pts):
        return np.zeros(0, bool)
    ok = np.hypot(*(pts - pole).T) > _POLE_MM
    for i, (p, q) in enumerate(segs):
        d = q - p
        length = float(np.hypot(*d))
        if length == 0.0:
            continue
        off = abs(float(d[0] * (pole - p)[1] - d[1] * (pole - p)[0])) / length
        if off > _RAY_LINE_MM:
            continue
        k = 2 * i if float(np.hypot(*(p - pole))) < float(np.hypot(*(q - pole))) else 2 * i + 1
        if float(np.hypot(*(pts[k] - pole))) < _RAY_START_MM:
            ok[k] = False
    return ok


def _strength(pts: np.ndarray) -> np.ndarray:
    """How much nearer an end counts for the other segments that end with it (mm).

    An image point of a drawn polygon is where its vector from the pole and
    the lines of its link's image end together; a lone end is more often a
    stroke run on by a letter or a barb.  0.5 mm for each other segment
    ending within 2.5 mm, at most 1 mm.
    """
    if not len(pts):
        return np.zeros(0)
    seg = np.arange(len(pts)) // 2
    close = np.hypot(*(pts[:, None, :] - pts[None, :, :]).transpose(2, 0, 1)) < _SAME_MM
    close &= seg[:, None] != seg[None, :]
    return _STRONG_MM * np.minimum(close.sum(axis=1), 2)


def _gap_ends(segs: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """Which segment ends are a gap in one straight line rather than a vertex.

    Exactly two ends there, of two segments within 8° of one line that run
    on from it to opposite sides, and no other line passing through: the
    pencil lifted (or a printed line crossed) in the middle of a stroke.
    An image in the middle of a straight line looks the same, so such an
    end is not refused, only counted 2 mm farther than it is.
    """
    out = np.zeros(len(pts), bool)
    n = len(segs)
    if n < 2:
        return out
    d = segs[:, 1] - segs[:, 0]
    u = d / np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-12)[:, None]
    for k in range(len(pts)):
        near = np.flatnonzero(np.hypot(*(pts - pts[k]).T) < _SAME_MM)
        if len(near) != 2 or near[0] // 2 == near[1] // 2:
            continue
        i, j = int(near[0] // 2), int(near[1] // 2)
        if abs(float(u[i, 0] * u[j, 1] - u[i, 1] * u[j, 0])) > _GAP_SIN:
            continue
        # each segment runs on from the gap: away from it along its own direction
        out_i = segs[i, 1 - near[0] % 2] - pts[near[0]]
        out_j = segs[j, 1 - near[1] % 2] - pts[near[1]]
        if float(out_i @ out_j) >= 0.0:
            continue
        through = False
        for m in range(n):
            if m in (i, j):
                continue
            p, q = segs[m]
            length = float(np.hypot(*(q - p)))
            t = float((pts[k] - p) @ (q - p)) / max(length, 1e-12)
            off = abs(float((pts[k] - p) @ np.array([-(q - p)[1], (q - p)[0]]))) / max(
                length, 1e-12)
            if -1.0 < t < length + 1.0 and off < 1.0:
                through = True
                break
        out[k] = not through
    return out


def _best_assignment(read: SheetRead, names: list[str], cands: dict[str, list[tuple[float, int]]],
                     reach: dict[str, float], pts: np.ndarray) -> tuple[dict[str, int], float]:
    """The assignment of segment ends to names of least total cost, and that cost.

    Branch and bound over each name's candidates (or none, at a cost above its reach).
    """
    order = sorted(names, key=lambda n: (len(cands[n]), names.index(n)))
    miss = {n: reach[n] + _ALTERNATIVE_MM + 1.0 for n in names}
    best: list[Any] = [math.inf, {}]
    rest = [sum(min([c for c, _ in cands[n]] + [miss[n]]) for n in order[i:])
            for i in range(len(order) + 1)]

    def clash(name: str, j: int, got: dict[str, int]) -> bool:
        return any(float(np.hypot(*(pts[j] - pts[k]))) < _SAME_MM
                   and not _same_image(read, name, other) for other, k in got.items())

    def walk(i: int, cost: float, got: dict[str, int]) -> None:
        if cost + rest[i] >= best[0] - 1e-12:
            return
        if i == len(order):
            best[0], best[1] = cost, dict(got)
            return
        name = order[i]
        for c, j in cands[name]:
            if not clash(name, j, got):
                got[name] = j
                walk(i + 1, cost + c, got)
                del got[name]
        walk(i + 1, cost + miss[name], got)

    walk(0, 0.0, {})
    return best[1], float(best[0])


def _untellable(read: SheetRead, chosen: dict[str, int],
                cands: dict[str, list[tuple[float, int]]], pts: np.ndarray) -> list[str]:
    """Notes on pairs of images whose vertices could be swapped at hardly more cost."""
    notes = []
    cost = {n: {j: c for c, j in cands[n]} for n in cands}
    got = sorted(chosen)
    for i, a in enumerate(got):
        for b in got[i + 1:]:
            ja, jb = chosen[a], chosen[b]
            if _same_image(read, a, b) or jb not in cost[a] or ja not in cost[b]:
                continue
            if cost[a][jb] + cost[b][ja] <= cost[a][ja] + cost[b][jb] + _TELL_MM:
                notes.append(f"{a.lower()} and {b.lower()} cannot be told apart: the vertices "
                             f"read as {a.lower()} and {b.lower()} are each as near the other's "
                             "places (within 1 mm); each was taken as the nearer")
    return notes


def _same_image(read: SheetRead, a: str, b: str) -> bool:
    """Two names whose exact images coincide on the sheet may share a vertex."""
    return float(np.hypot(*(read.places[a][0] - read.places[b][0]))) < _SAME_MM
