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
from typing import Any

import numpy as np

from graphkin.construction import Step
from graphkin.text import fmt

__all__ = ["assembly_words"]

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
