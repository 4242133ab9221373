"""Coupler-curve synthesis through four precision points by point reduction (Sec. 9.9).

Hain's construction as the book draws it (Figs. 9.30-9.32): O4 on the
bisector c13 of C1C3, so that the turn about O4 taking C1 to C3 takes A1 to
A3 (triangles C1A1O4 and C3A3O4 congruent, points 1 and 3 of the inversion
coincide with O4); A1 where the circle of radius R about O4 meets the circle
of radius r about C1, A3 its turn about O4 (two mirrors: in O4C1, then in
c13); O2 on the bisector a13 of A1A3; A2 and A4 on the crank circle at r from
C2 and C4; the inversion on the O4B1 posture: point 2 makes C1A1(2)
congruent to C2A2O4, point 4 makes C1A1(4) congruent to C4A4O4; B1 is the
center of the circle through O4, 2 and 4 (the meet of the bisectors of O4-2
and O4-4).  Four choices are free (O4 on c13, R, r, O2 on a13): the
``∞⁴`` solutions of the book.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 9.9, Figs. 9.30-9.32; Hain,
*Applied Kinematics*, Ch. 17.
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import product

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Role, Side
from graphkin.errors import GraphkinError, InputError
from graphkin.synthesis.linkage import Linkage
from graphkin.synthesis.postures import DIAGRAM, Postures

__all__ = ["CouplerCurve", "coupler_construction", "coupler_curve"]


@dataclass(frozen=True)
class CouplerCurve:
    """The result: the construction, its branch choices and the four-bar it gives."""

    construction: Construction
    sides: tuple[Side, Side, Side]
    linkage: Linkage


def coupler_construction(c: np.ndarray, o4_near: complex, o2_near: complex, big_r: float,
                         r: float, sides: tuple[Side, Side, Side]) -> Construction:
    """The recorded construction of Sec. 9.9 for precision points ``c`` (4 complex).

    ``sides``: the intersections kept for A1, A2 and A4 (left or right of the line
    from the first circle's center to the second's).
    """
    cx = Construction(title="coupler-curve synthesis (four precision points)")

    def pt(name: str, z: complex, note: str) -> None:
        cx.add("point", (), (name,), xy=(float(z.real), float(z.imag)), role=Role.GIVEN,
               diagram=DIAGRAM, note=note)

    for j in range(4):
        pt(f"C{j + 1}", complex(c[j]), f"C{j + 1}: precision point {j + 1} of the path.")
    cx.add("bisector", ("C1", "C3"), ("c13",), diagram=DIAGRAM,
           note="c13: the bisector of C1C3; O4 is chosen on it (Fig. 9.31).")
    pt("O4*", o4_near, "the point chosen near c13 for O4.")
    cx.add("perpendicular", ("c13", "O4*"), ("n4",), diagram=DIAGRAM,
           note="the perpendicular to c13 from the chosen point.")
    cx.add("meet", ("c13", "n4"), ("O4",), role=Role.RESULT, diagram=DIAGRAM,
           note="O4: the output link's fixed pivot, on c13.")
    cx.add("circle", ("O4",), ("k_R",), radius=float(big_r), diagram=DIAGRAM,
           note=f"the arc of radius R = {big_r:.6g} about O4.")
    for j in (1, 2, 3, 4):
        cx.add("circle", (f"C{j}",), (f"k_C{j}",), radius=float(r), diagram=DIAGRAM,
               note=f"the arc of radius r = {r:.6g} about C{j} (the coupler's AC).")
    cx.add("intersect_circles", ("k_R", "k_C1"), ("A1",), branch=sides[0], role=Role.RESULT,
           diagram=DIAGRAM, note=f"A1: where the arcs about O4 and C1 meet ({sides[0]}).")
    cx.add("join", ("O4", "C1"), ("m_1",), diagram=DIAGRAM, note="the line O4C1.")
    cx.add("reflect", ("A1", "m_1"), ("A'",), diagram=DIAGRAM, note="A1 mirrored in O4C1.")
    cx.add("reflect", ("A'", "c13"), ("A3",), role=Role.RESULT, diagram=DIAGRAM,
           note="A3: A1 turned about O4 as C1 turns to C3 (mirrored again, in c13): the "
                "triangles C1A1O4 and C3A3O4 are congruent (Fig. 9.30).")
    cx.add("bisector", ("A1", "A3"), ("a13",), diagram=DIAGRAM,
           note="a13: the bisector of A1A3 (it passes through O4); O2 is chosen on it.")
    pt("O2*", o2_near, "the point chosen near a13 for O2.")
    cx.add("perpendicular", ("a13", "O2*"), ("n2",), diagram=DIAGRAM,
           note="the perpendicular to a13 from the chosen point.")
    cx.add("meet", ("a13", "n2"), ("O2",), role=Role.RESULT, diagram=DIAGRAM,
           note="O2: the input link's fixed pivot, on a13.")
    cx.add("circle_through", ("O2", "A1"), ("k_2",), diagram=DIAGRAM,
           note="the crank circle about O2 through A1 and A3.")
    for j, side in ((2, sides[1]), (4, sides[2])):
        cx.add("intersect_circles", ("k_2", f"k_C{j}"), (f"A{j}",), branch=side,
               role=Role.RESULT, diagram=DIAGRAM,
               note=f"A{j}: on the crank circle, r from C{j} ({side}).")
    for j in (2, 4):
        cx.add("image", (f"C{j}", f"A{j}", "C1", "A1", "O4"), (f"Q{j}",), diagram=DIAGRAM,
               note=f"point {j}: C1A1({j}) congruent to C{j}A{j}O4 (inversion on the "
                    "first posture, Fig. 9.32).")
        cx.add("bisector", ("O4", f"Q{j}"), (f"b_{j}",), diagram=DIAGRAM,
               note=f"the bisector of O4 and point {j}.")
    cx.add("meet", ("b_2", "b_4"), ("B1",), role=Role.RESULT, diagram=DIAGRAM,
           note="B1: the center of the circle through O4, 2 and 4 (points 1 and 3 are O4).")
    cx.add("circle_through", ("B1", "O4"), ("k_B",), diagram=DIAGRAM,
           note="the circle of B's inverted positions about B1.")
    return cx


def _z(v: np.ndarray) -> complex:
    return complex(v[0] / v[2], v[1] / v[2])


def coupler_curve(c: np.ndarray, o4_near: complex, o2_near: complex, big_r: float, r: float,
                  source: str = "<synthesis>") -> CouplerCurve:
    """The four-bar whose coupler point passes through the four precision points ``c``.

    The intersections (A1, A2, A4) are tried both ways; the first linkage that
    passes every check (branch, order, toggle, transmission) is kept, else the
    first that can be built.

    Raises
    ------
    InputError
        The arcs miss each other for every choice (R, r too small or too large).
    """
    found: list[CouplerCurve] = []
    for s1, s2, s4 in product((Side.LEFT, Side.RIGHT), repeat=3):
        sides = (s1, s2, s4)
        cx = coupler_construction(c, o4_near, o2_near, big_r, r, sides)
        try:
            ev = cx.evaluate()
        except GraphkinError:
            continue
        pts = {k: _z(np.asarray(ev[k], dtype=float))
               for k in ("O2", "O4", "A1", "A2", "A3", "A4", "B1")}
        if not all(np.isfinite(v) for v in pts.values()):
            continue
        a = np.array([pts[f"A{j}"] for j in (1, 2, 3, 4)])
        ang = np.angle(a - c)
        post = Postures(np.stack([c.real, c.imag], axis=-1), ang, ("C", "E"),
                        (0.5 * r, 0.0), source, "coupler_curve", second_given=False)
        link = Linkage(post, pts["O2"], pts["O4"], pts["A1"], pts["B1"], ("A", "B"))
        link.check()
        found.append(CouplerCurve(cx, sides, link))
        if link.ok:
            break
    if not found:
        raise InputError(f"the arcs of R = {big_r:g} about O4 and r = {r:g} about the "
                         "precision points do not meet for any choice: choose other radii",
                         key="coupler_curve", file=source)
    return next((f for f in found if f.linkage.ok), found[0])
