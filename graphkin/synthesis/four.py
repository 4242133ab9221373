"""Four postures: six poles, the opposite-pole quadrilateral and the Burmester curves (Sec. 9.5).

The center point of a circle through four positions of a body point sees
opposite sides of an opposite-pole quadrilateral under angles that are equal
or differ by 180° (the theorem of Sec. 9.5).  The book draws it with circles
on two opposite sides as chords (Fig. 9.20): a circle on P12P24 with its
center t half-chords to the right of P12 → P24, and a circle on P13P34 drawn
the same way with the same t (radii in the ratio of the sides, Eq. 9.19);
their two intersections E_C1, E_C2 are center points.  Recorded once with
``t`` as the construction's input, the construction is evaluated on an
array of t: every point of the center-point curve is an exact circle-circle
intersection, not a search.  Each center point's circle point A1 is where
the lines through P12 and P13, turned by −φ12 and −φ13 from the lines to
the center point, meet; A2, A3, A4 are A1 mirrored in the lines from P12,
P13, P14 to the center point (Eq. 9.18).  The circle points make the
circle-point curve.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 9.5, Eqs. 9.19-9.21, Figs. 9.19-9.23,
Examples 9.5-9.6.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Role, Side
from graphkin.errors import InputError
from graphkin.synthesis import analytic as an
from graphkin.synthesis.postures import DIAGRAM, Postures, add_poles, add_postures

__all__ = ["QUADRILATERALS", "Curves", "burmester_construction", "curves", "sample_t",
           "circle_point_steps"]

QUADRILATERALS = {
    "a": (("P13", "P12"), ("P12", "P24"), ("P24", "P34"), ("P34", "P13")),
    "b": (("P14", "P12"), ("P12", "P23"), ("P23", "P34"), ("P34", "P14")),
    "c": (("P14", "P13"), ("P13", "P23"), ("P23", "P24"), ("P24", "P14")),
}
"""The three opposite-pole quadrilaterals of Fig. 9.19, side by side."""

CHORDS = {"a": (("P12", "P24"), ("P13", "P34")),
          "b": (("P12", "P14"), ("P23", "P34")),
          "c": (("P13", "P14"), ("P23", "P24"))}
"""The pair of opposite sides each is drawn on, directed from i to k ignoring the common
subscript (Sec. 9.5: standing at P12 looking toward P24 we look from 1 to 4)."""


def _phi(post: Postures, i: int, j: int) -> float:
    return math.remainder(float(post.angles[j - 1] - post.angles[i - 1]), math.tau) / 2


def circle_point_steps(cx: Construction, post: Postures, center: str, name: str,
                       n: int) -> str:
    """From a center point: the circle point ``name``1 and its positions 2..n (Eq. 9.18).

    The bisector of A1A_j passes through P1j and the center point, and
    ∠A1 P1j O = φ1j: so A1 is on the line through P1j turned −φ1j from P1jO,
    and A_j is A1 mirrored in P1jO.
    """
    first = f"{name}1"
    for j in (2, 3):
        pole, ang, line = f"P1{j}", f"∠P1{j}{center}", f"l_{name}1{j}"
        cx.add("angle_along", (pole, center), (ang,), local_angle=0.0, sign=1.0,
               diagram=DIAGRAM, note=f"the direction of {pole}{center}.")
        phi = _phi(post, 1, j)
        cx.add("line_at_angle", (pole, ang), (line,), offset=-phi, diagram=DIAGRAM,
               note=f"through {pole} the line turned −φ1{j} = {math.degrees(-phi):.6g}° from "
                    f"{pole}{center}.")
    cx.add("meet", (f"l_{name}12", f"l_{name}13"), (first,), role=Role.RESULT, diagram=DIAGRAM,
           note=f"{first}: the circle point of {center}, where the two lines meet.")
    for j in range(2, n + 1):
        mirror = f"m_{name}1{j}"
        cx.add("join", (f"P1{j}", center), (mirror,), diagram=DIAGRAM,
               note=f"P1{j}{center}: the bisector of {name}1{name}{j}.")
        cx.add("reflect", (first, mirror), (f"{name}{j}",), role=Role.RESULT, diagram=DIAGRAM,
               note=f"{name}{j}: {first} mirrored in P1{j}{center}.")
    cx.add("circle_through", (center, first), (f"k_{name}",), diagram=DIAGRAM,
           note=f"the circle about {center} through the positions of {name}.")
    return first


def check_quadrilateral(post: Postures, quadrilateral: str = "a") -> None:
    """Refuse postures two of whose six poles coincide.

    A side of the opposite-pole quadrilateral of no length, or P12 = P13 (the
    two lines that find a circle point through one point), leaves the
    center-point curve undefined; two poles that coincide elsewhere make it
    degenerate into lines and circles through them.

    Raises
    ------
    InputError
        Naming the file's postures and the two poles.
    """
    def pole(i: int, j: int) -> complex:
        return an.pole(complex(*post.points[i - 1]), float(post.angles[i - 1]),
                       complex(*post.points[j - 1]), float(post.angles[j - 1]))

    names = ["P12", "P13", "P14", "P23", "P24", "P34"]
    poles = {n: pole(int(n[1]), int(n[2])) for n in names}
    for k, p in enumerate(names):
        for q in names[k + 1:]:
            if abs(poles[p] - poles[q]) <= post.tol.length(post.scale) * 1e3:
                raise InputError(f"the poles {p} and {q} coincide (three postures turn about "
                                 "one point, or the body turns about a pole): the center-point "
                                 "curve degenerates (Sec. 9.5)", key=post.key, file=post.source)


def burmester_construction(post: Postures, quadrilateral: str = "a") -> Construction:
    """Record the center-point and circle-point curves of four postures as one construction.

    Its input is ``t`` (the cotangent of the angle under which a center point
    sees the two chords); evaluate it on an array of t for the whole curve.
    Results: ``E_C``, ``F_C`` (center points, the left and right
    intersections) and ``E1``, ``F1`` (their circle points in posture 1;
    other letters when the body's points are named E or F, :func:`letters`).
    """
    check_quadrilateral(post, quadrilateral)
    cx = Construction(title="center-point curve (four postures)")
    labels = add_postures(cx, post)
    add_poles(cx, post, labels, [(1, 2), (1, 3), (1, 4), (2, 3), (2, 4), (3, 4)])
    for p, q in QUADRILATERALS[quadrilateral]:
        cx.add("join", (p, q), (f"q_{p}{q}",), diagram=DIAGRAM,
               note=f"side {p}{q} of the opposite-pole quadrilateral (Fig. 9.19{quadrilateral}).")
    (p1, q1), (p2, q2) = CHORDS[quadrilateral]
    cx.add("input", (), ("t",), name="t", diagram=DIAGRAM,
           note="t: the center of the first circle stands t half-chords right of the chord.")
    cx.add("circle_on_chord", (p1, q1, "t"), ("k_R",), diagram=DIAGRAM,
           note=f"a circle of radius R with {p1}{q1} as a chord, its center on the bisector, "
                f"to the right standing at {p1} looking toward {q1} (Fig. 9.20).")
    cx.add("circle_on_chord", (p2, q2, "t"), ("k_r",), diagram=DIAGRAM,
           note=f"a circle of radius r = R·{p2}{q2}/{p1}{q1} with {p2}{q2} as a chord, its "
                f"center on the same side (Eq. 9.19).")
    e, f = letters(post)
    for side, name in ((Side.LEFT, f"{e}_C"), (Side.RIGHT, f"{f}_C")):
        cx.add("intersect_circles", ("k_R", "k_r"), (name,), branch=side, role=Role.RESULT,
               diagram=DIAGRAM, note=f"{name}: a center point, where the two circles meet; it "
                                     f"sees {p1}{q1} and {p2}{q2} under equal angles (Eq. 9.20).")
    circle_point_steps(cx, post, f"{e}_C", e, post.n)
    circle_point_steps(cx, post, f"{f}_C", f, post.n)
    return cx


def letters(post: Postures) -> tuple[str, str]:
    """The two letters of the curve's circle points (E and F unless the body's points use them)."""
    free = [c for c in "EFGHKLMN" if c not in post.names]
    return free[0], free[1]


def sample_t(count: int) -> np.ndarray:
    """``count`` values of t = tan β, β evenly spread over (−90°, 90°)."""
    beta = (np.arange(count) + 0.5) / count * np.pi - np.pi / 2
    return np.tan(beta)


@dataclass(frozen=True)
class Curves:
    """The sampled Burmester curves of four postures.

    Attributes
    ----------
    t : ndarray (M,)
        The construction's input.
    center : ndarray complex (2, M)
        Center points (left and right intersections); NaN where the circles miss.
    circle : ndarray complex (2, M)
        The circle points (posture 1) of the center points.
    construction : Construction
    cubic, circle_cubic : ndarray
        The algebraic cubics (:func:`graphkin.synthesis.analytic.cubic`).
    """

    t: np.ndarray
    center: np.ndarray
    circle: np.ndarray
    construction: Construction
    cubic: np.ndarray
    circle_cubic: np.ndarray


def _cplx(v: np.ndarray) -> np.ndarray:
    v = np.asarray(v, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        return v[..., 0] / v[..., 2] + 1j * (v[..., 1] / v[..., 2])


def curves(post: Postures, count: int = 2001, quadrilateral: str = "a",
           cx: Construction | None = None) -> Curves:
    """The center-point and circle-point curves of postures 1-4, sampled at ``count`` t's.

    The construction is evaluated once on the whole array (no loop over points).
    """
    cx = cx if cx is not None else burmester_construction(post, quadrilateral)
    t = sample_t(count)
    ev = cx.evaluate({"t": t}, strict=False)
    e, f = letters(post)
    center = np.stack([_cplx(ev[f"{e}_C"]), _cplx(ev[f"{f}_C"])])
    circle = np.stack([_cplx(ev[f"{e}1"]), _cplx(ev[f"{f}1"])])
    mo = post.motion()
    return Curves(t, center, circle, cx, an.cubic(mo), an.circle_cubic(mo))
