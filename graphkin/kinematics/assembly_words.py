"""Why a posture cannot be assembled, in the user's words: which link is too short, by how much.

The construction says "step 13 (B): the line and the arc do not meet
(l_B(sliders[0]), k_B(A))"; the user wants "link 3 (AB = 15 mm) cannot reach
the slider line of B: it needs at least 30 mm".  The arc ``k_B(A)`` is drawn
about A with the length AB of the link that carries both points (Sec. 2.8:
the construction of a position by arcs and lines), so its radius is that
link's length, and the missing length is read off the geometry of the failed
step: the distance from the arc's center to the line, or between the two
arcs' centers.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Cases 1-4: when arcs and lines
do not meet, the mechanism cannot be assembled in that position), Sec. 1.10
(Grashof's criterion and the limits of a linkage).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from typing import Any

import numpy as np

from graphkin.construction import Step
from graphkin.text import fmt

__all__ = ["assembly_words", "parallel_meet", "placement_words", "point_words", "toggle_words"]

_ARC = re.compile(r"^k_(?P<to>[^()]+)\((?P<about>[^()]+)\)$")


def _link_of(mech: Any, a: str, b: str) -> tuple[str, float] | None:
    """The link carrying both named points ``a`` and ``b``, and its length |ab|."""
    for lid, link in mech.links.items():
        pts = link.points
        if a in pts and b in pts:
            pa, pb = np.asarray(pts[a], dtype=float), np.asarray(pts[b], dtype=float)
            return lid, float(math.hypot(*(pa - pb)))
    return None


def _arc(mech: Any, label: str, value: Any) -> tuple[str, str, str, float, np.ndarray] | None:
    """``(link, about, to, radius, center)`` of an arc ``k_TO(ABOUT)`` of a link's length."""
    m = _ARC.match(label)
    if m is None:
        return None
    to, about = m.group("to"), m.group("about")
    found = _link_of(mech, about, to)
    k = np.asarray(value, dtype=float).reshape(-1)
    if found is None or k.shape != (3,) or not np.all(np.isfinite(k)):
        return None
    lid, length = found
    if not math.isclose(length, float(k[2]), rel_tol=1e-9, abs_tol=1e-12 * max(1.0, length)):
        return None  # an arc of another length (an offset, a rolling contact): not a link's
    return lid, about, to, length, k[:2]


def _line_words(label: str, point: str) -> str:
    if "sliders[" in label:
        return f"the slider line of {point}"
    if "slots[" in label:
        return f"the slot that guides {point}"
    return f"the line {label}"


def _unlike(a: float, b: float) -> tuple[str, str]:
    """Two lengths compared in a message, with digits enough to tell them apart.

    Four significant digits, more (up to ten) while they read the same: a posture
    a hair past its limit is "5.4998 in apart, less than 5.5 in", never "5.5 in
    apart, less than 5.5 in".

    >>> _unlike(5.4996, 5.5), _unlike(40.0, 29.0)
    (('5.4996', '5.5'), ('40', '29'))
    """
    for digits in range(4, 11):
        sa, sb = fmt(a, digits), fmt(b, digits)
        if sa != sb:
            return sa, sb
    return sa, sb


def assembly_words(mech: Any, step: Step, args: list[Any]) -> str | None:
    """One sentence on why ``step`` has no answer, in the mechanism's terms; None if unknown.

    Parameters
    ----------
    mech : Mechanism
    step : Step
        The failed step: ``intersect_line_circle`` or ``intersect_circles``.
    args : list
        The values of its inputs (a line ``(a, b, c)``, an arc ``(x, y, r)``).

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.examples.fourbar()          # AB = 4 in, BC = 18 in, DC = 11 in
    >>> from graphkin.construction import Construction
    >>> cx = Construction()
    >>> s = cx.add("intersect_circles", ("k_C(B)", "k_C(D)"), ("C",), branch="left")
    >>> print(assembly_words(mech, s, [(0.0, 0.0, 18.0), (40.0, 0.0, 11.0)]))
    ... # doctest: +NORMALIZE_WHITESPACE
    link 3 (BC = 18 in) and link 4 (DC = 11 in) cannot reach each other:
    B and D are 40 in apart, more than 18 + 11 = 29 in
    """
    unit = mech.length_unit
    vals = dict(zip(step.inputs, args))
    if step.op == "intersect_line_circle" and len(step.inputs) == 2:
        line_label, arc_label = step.inputs
        arc = _arc(mech, arc_label, vals[arc_label])
        line = np.asarray(vals[line_label], dtype=float).reshape(-1)
        if arc is None or line.shape != (3,) or not np.all(np.isfinite(line)):
            return None
        lid, about, to, r, c = arc
        n = math.hypot(line[0], line[1])
        if n == 0:
            return None
        d = abs(line[0] * c[0] + line[1] * c[1] + line[2]) / n
        rs, ds = _unlike(r, d)
        return (f"link {lid} ({about}{to} = {rs} {unit}) cannot reach "
                f"{_line_words(line_label, to)}: it needs at least {ds} {unit} "
                f"(the distance from {about} to that line)")
    if step.op == "intersect_circles" and len(step.inputs) == 2:
        a1 = _arc(mech, step.inputs[0], vals[step.inputs[0]])
        a2 = _arc(mech, step.inputs[1], vals[step.inputs[1]])
        if a1 is None or a2 is None:
            return None
        (l1, p1, t1, r1, c1), (l2, p2, t2, r2, c2) = a1, a2
        d = float(math.hypot(*(c1 - c2)))
        both = (f"link {l1} ({p1}{t1} = {fmt(r1, 4)} {unit}) and link {l2} "
                f"({p2}{t2} = {fmt(r2, 4)} {unit})")
        if d > r1 + r2:
            ds, ss = _unlike(d, r1 + r2)
            return (f"{both} cannot reach each other: {p1} and {p2} are {ds} {unit} "
                    f"apart, more than {fmt(r1, 4)} + {fmt(r2, 4)} = {ss} {unit}")
        ds, ss = _unlike(d, abs(r1 - r2))
        return (f"{both} cannot meet: {p1} and {p2} are only {ds} {unit} apart, less "
                f"than the difference of their lengths, {ss} {unit}")
    return None


# ---------------------------------------------------------------------------
# Toggle and dead-center postures: why the polygons have no answer (Sec. 3.5)
# ---------------------------------------------------------------------------

_OUT = re.compile(r"^(?P<what>[va])\((?P<point>[^()]+)\)$")
_DIRECTION = re.compile(r"the direction of (?P<q>[^\s:,.]+)")
_RELATIVE = re.compile(r"^R_([^:]+):")


def point_words(label: str) -> str:
    """A point's label as the user wrote or reads it: ``rolling[0]:C@4`` -> ``the contact C``.

    Examples
    --------
    >>> point_words("B"), point_words("rolling[0]:C"), point_words("rolling[1]:P@4")
    ('B', 'the contact C', 'the contact P')
    """
    base = label.split("@", 1)[0]
    if base.startswith("rolling[") and ":" in base:
        return f"the contact {base.split(':', 1)[1]}"
    return base


def _quantity(label: str) -> str:
    """What a polygon step finds, in the book's words: ``v(B)`` -> ``the velocity of B``."""
    m = _OUT.match(label)
    if m is not None:
        what = "velocity" if m.group("what") == "v" else "acceleration"
        return f"the {what} of {point_words(m.group('point'))}"
    for sym, what in (("ω", "the angular velocity"), ("α", "the angular acceleration")):
        if label.startswith(sym) and label[1:].isdigit():
            return f"{label}, {what} of link {label[1:]}"
    return point_words(label)


def _joined(cx: Any, label: str) -> tuple[str, str] | None:
    """The two points a ``join`` step draws its line through, else None."""
    try:
        st = cx.step_of(label)
    except (KeyError, LookupError, ValueError):
        return None
    if st.op == "join" and len(st.inputs) == 2:
        return st.inputs[0], st.inputs[1]
    return None


def _letter(label: str) -> str:
    """A point's letter in a line's name: ``rolling[0]:C`` -> ``C``, ``B`` -> ``B``."""
    return label.split("@", 1)[0].rsplit(":", 1)[-1]


def _line_of(cx: Any, label: str, what: str) -> tuple[str, tuple[str, str] | None]:
    """A polygon's line in words (``the direction of V_CB (⊥ BC)``) and the posture's line.

    ``what`` is ``"v"`` or ``"a"``: the polygon the line is drawn in.
    """
    try:
        st = cx.step_of(label)
    except (KeyError, LookupError, ValueError):
        return "a line of the polygon", None
    m = _DIRECTION.search(st.note or "")
    head = f"the direction of {m.group('q')}" if m else "a line of the polygon"
    if st.op in ("perpendicular", "parallel") and st.inputs:
        ends = _joined(cx, st.inputs[0])
        if ends is not None:
            r = _RELATIVE.match(st.inputs[0])
            if m is None and r is not None:  # the join R_BC of the posture: V_BC ⊥ BC
                head = ("the direction of " + (f"V_{r.group(1)}" if what == "v" else
                                               f"A_{r.group(1)}^t"))
            sign = "⊥" if st.op == "perpendicular" else "∥"
            return f"{head} ({sign} {_letter(ends[0])}{_letter(ends[1])})", ends
    return head, None


def _in_line(p: tuple[str, str], q: tuple[str, str]) -> str:
    """Why the posture's lines ``p`` and ``q`` are parallel: three points in line, or not."""
    pts: list[str] = []
    for e in (*p, *q):
        if e not in pts:
            pts.append(e)
    words = [point_words(e) for e in pts]
    if len(pts) == 3:
        return f"{words[0]}, {words[1]} and {words[2]} lie on one line"
    a, b, c, d = words
    return f"the line {a}{b} is parallel to the line {c}{d}"


def parallel_meet(cx: Any, values: Mapping[str, Any], below: float) -> Step | None:
    """The first ``meet`` of a polygon whose two lines are parallel (sine under ``below``).

    The lines are kept with unit normals, so ``|a1 b2 - a2 b1|`` is the sine
    of their angle, dimensionless and independent of the mechanism's size.
    """
    for st in cx.steps:
        if st.op != "meet" or len(st.inputs) != 2 or any(i not in values for i in st.inputs):
            continue
        l1, l2 = (np.asarray(values[i], dtype=float) for i in st.inputs)
        sine = np.abs(l1[..., 0] * l2[..., 1] - l1[..., 1] * l2[..., 0])
        if np.any(~np.isfinite(sine) | (sine < below)):
            return st  # type: ignore[no-any-return]
    return None


def toggle_words(cx: Any, values: Mapping[str, Any], below: float,
                 failed: str | None = None) -> str:
    """Why a velocity or acceleration polygon has no answer at this posture, in the book's words.

    At a toggle or dead-center posture (Sec. 3.5) the two lines that fix an
    image in a polygon are parallel, because the posture has three points in
    line: the words name them and the quantity the polygon cannot find,
    never a step of the construction.

    Parameters
    ----------
    cx : Construction
        The velocity (or acceleration) polygon.
    values : mapping
        Its values as far as they were found (a replay that went on past the failure).
    below : float
        The sine under which two lines are parallel (``solve.SINGULAR_SINE``).
    failed : str, optional
        The label of the step that had no answer, when no meet of parallel lines explains it.

    Examples
    --------
    >>> import graphkin
    >>> from graphkin.kinematics.posture import build_posture
    >>> from graphkin.kinematics.polygons import build_polygons
    >>> mech = graphkin.examples.fourbar()
    >>> pol = build_polygons(mech, build_posture(mech))
    >>> cx = pol.velocity
    >>> vals = {"⊥CB:v": np.array([0.0, 1.0, 0.0]), "⊥CD:v": np.array([0.0, 1.0, 2.0])}
    >>> print(toggle_words(cx, vals, 1e-7))  # doctest: +NORMALIZE_WHITESPACE
    B, C and D lie on one line: the direction of V_CB (⊥ BC) and the direction of V_CD
    (⊥ DC) are parallel, so the velocity of C is undetermined
    """
    st = parallel_meet(cx, values, below)
    if st is not None:
        what = "a" if st.outputs[0].startswith("a(") else "v"
        (w1, e1), (w2, e2) = (_line_of(cx, i, what) for i in st.inputs)
        why = f"{_in_line(e1, e2)}: " if e1 is not None and e2 is not None else ""
        return f"{why}{w1} and {w2} are parallel, so {_quantity(st.outputs[0])} is undetermined"
    if failed is not None:
        return f"{_quantity(failed)} is undetermined"
    return "the polygon has no answer"


def placement_words(step: Step) -> str:
    """Why the posture step ``step`` placed nothing, when :func:`assembly_words` cannot say more.

    Examples
    --------
    >>> from graphkin.construction import Construction
    >>> s = Construction().add("intersect_line_circle", ("l_B", "k_B(A)"), ("B",))
    >>> placement_words(s)
    'B cannot be placed: the line and the arc that locate it do not meet'
    """
    what = {
        "intersect_circles": "the two arcs that locate it do not meet",
        "intersect_line_circle": "the line and the arc that locate it do not meet",
        "join": "the two points that fix its line coincide",
        "meet": "the two lines that locate it are parallel",
    }.get(step.op, "no construction locates it here")
    return f"{point_words(step.outputs[0])} cannot be placed: {what}"
