"""Three postures: the pole triangle, center points from circle points and the reverse (Sec. 9.4).

A point D of the body in its three positions D1, D2, D3 lies on a circle
about the center point D_C.  The book finds D2 and D3 from D1 by the *image
point* D_I (Example 9.1): D1 mirrored in side 1 of the pole triangle is D_I,
and D_I mirrored in sides 2 and 3 gives D2 and D3.  The reverse (Example
9.2): from a center point E_C, the lines through P12 and P31 turned by
−φ12 and +φ31 from P12E_C and P31E_C meet at the circle point E1.  The points
that move on straight lines through the three postures lie on the circles of
the pole triangle's circumradius about the reflections O1, O2, O3 of its
circumcenter O (Example 9.4).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 9.4, Eqs. 9.14-9.18, Examples
9.1-9.4, Figs. 9.7-9.18.
"""

from __future__ import annotations

import math

from graphkin.construction import Construction
from graphkin.construction.step import Role
from graphkin.synthesis.postures import DIAGRAM, Postures, add_poles, add_postures

__all__ = ["pole_triangle", "half_angles", "center_from_circle_point",
           "circle_point_from_center", "straight_line_locus"]

SIDES = {"s1": ("P31", "P12"), "s2": ("P12", "P23"), "s3": ("P23", "P31")}
"""The sides of the pole triangle: side i joins the two poles with the common subscript i."""


def half_angles(post: Postures, i: int, j: int) -> float:
    """φ_ij = θ_ij / 2 (Eq. 9.14), θ_ij in (−180°, 180°]: the interior angle at pole P_ij."""
    return math.remainder(float(post.angles[j - 1] - post.angles[i - 1]), math.tau) / 2


def pole_triangle(post: Postures, cx: Construction | None = None) -> Construction:
    """Record the three poles P12, P23, P31 and the pole triangle's sides (Fig. 9.7).

    Parameters
    ----------
    post : Postures
        Three postures.
    cx : Construction, optional
        Append to this construction (a new one otherwise).
    """
    cx = cx if cx is not None else Construction(title="pole triangle")
    labels = add_postures(cx, post)
    add_poles(cx, post, labels, [(1, 2), (2, 3), (3, 1)])
    for side, (p, q) in SIDES.items():
        k = side[1]
        cx.add("join", (p, q), (side,), diagram=DIAGRAM,
               note=f"side {k} of the pole triangle: {p}{q}, the poles with the common "
                    f"subscript {k}.")
    return cx


def _images(cx: Construction, name: str, first: str) -> None:
    """From the circle point's first position: the image point and positions 2 and 3."""
    image = f"{name}_I"
    cx.add("reflect", (first, "s1"), (image,), diagram=DIAGRAM,
           note=f"{image}: the image point, {first} mirrored in side 1 (Example 9.1).")
    for k in (2, 3):
        cx.add("reflect", (image, f"s{k}"), (f"{name}{k}",), role=Role.RESULT, diagram=DIAGRAM,
               note=f"{name}{k}: the image point {image} mirrored in side {k}.")


def center_from_circle_point(cx: Construction, post: Postures, name: str,
                             xy: tuple[float, float]) -> str:
    """The center point of the body point at ``xy`` in posture 1 (Example 9.1).

    Records ``name``1 (given), the image point, ``name``2, ``name``3, the
    bisectors of ``name``1``name``2 and ``name``2``name``3 and their meet
    ``O_name`` (the center point), and the circle through the three positions.
    Returns the center point's label.
    """
    first, center = f"{name}1", f"O_{name}"
    cx.add("point", (), (first,), xy=tuple(map(float, xy)), role=Role.GIVEN, diagram=DIAGRAM,
           note=f"{first}: the chosen circle point in posture 1.")
    _images(cx, name, first)
    cx.add("bisector", (first, f"{name}2"), (f"b_{name}12",), diagram=DIAGRAM,
           note=f"the bisector of {name}1{name}2 (it passes through P12).")
    cx.add("bisector", (f"{name}2", f"{name}3"), (f"b_{name}23",), diagram=DIAGRAM,
           note=f"the bisector of {name}2{name}3 (it passes through P23).")
    cx.add("meet", (f"b_{name}12", f"b_{name}23"), (center,), role=Role.RESULT,
           diagram=DIAGRAM, note=f"{center}: the center point, where the bisectors meet "
                                 f"(Sec. 9.4).")
    cx.add("circle_through", (center, first), (f"k_{name}",), diagram=DIAGRAM,
           note=f"the circle about {center} through {name}1, {name}2, {name}3.")
    return center


def circle_point_from_center(cx: Construction, post: Postures, name: str,
                             xy: tuple[float, float]) -> str:
    """The circle point (posture 1) of the center point at ``xy`` (Example 9.2).

    ∠O P12 A1 = −φ12 and ∠O P31 A1 = +φ31 (Eq. 3 of Example 9.2): two lines
    turned from P12O and P31O meet at A1; A2 and A3 follow by the image point.
    Returns the label of the circle point's first position.
    """
    first, center = f"{name}1", f"O_{name}"
    cx.add("point", (), (center,), xy=tuple(map(float, xy)), role=Role.GIVEN, diagram=DIAGRAM,
           note=f"{center}: the chosen center point.")
    for pole, turn, sign in (("P12", half_angles(post, 1, 2), -1.0),
                             ("P31", half_angles(post, 3, 1), 1.0)):
        ang, line = f"∠{pole}{center}", f"l_{name}{pole}"
        cx.add("angle_along", (pole, center), (ang,), local_angle=0.0, sign=1.0,
               diagram=DIAGRAM, note=f"the direction of {pole}{center}.")
        word = "−φ12" if sign < 0 else "+φ31"
        cx.add("line_at_angle", (pole, ang), (line,), offset=sign * turn, diagram=DIAGRAM,
               note=f"through {pole} the line turned {word} = {math.degrees(sign * turn):.6g}° "
                    f"from {pole}{center}.")
    cx.add("meet", (f"l_{name}P12", f"l_{name}P31"), (first,), role=Role.RESULT,
           diagram=DIAGRAM, note=f"{first}: the circle point, where the two lines meet "
                                 f"(Example 9.2).")
    _images(cx, name, first)
    cx.add("circle_through", (center, first), (f"k_{name}",), diagram=DIAGRAM,
           note=f"the circle about {center} through {name}1, {name}2, {name}3.")
    return first


def straight_line_locus(cx: Construction) -> list[str]:
    """The circumcenter O, its mirrors O1, O2, O3 and their circles (Example 9.4, Fig. 9.18).

    The points of the body whose three positions lie on a straight line are,
    in posture i, on the circle about O_i of the pole triangle's circumradius.
    """
    cx.add("bisector", ("P12", "P23"), ("b_s2",), diagram=DIAGRAM,
           note="the bisector of side 2.")
    cx.add("bisector", ("P23", "P31"), ("b_s3",), diagram=DIAGRAM,
           note="the bisector of side 3.")
    cx.add("meet", ("b_s2", "b_s3"), ("O",), role=Role.RESULT, diagram=DIAGRAM,
           note="O: the center of the pole triangle's circumscribing circle (Fig. 9.15).")
    cx.add("circle_through", ("O", "P12"), ("k_O",), diagram=DIAGRAM,
           note="the circumscribing circle of the pole triangle.")
    out = []
    for k in (1, 2, 3):
        ok = f"O{k}"
        cx.add("reflect", ("O", f"s{k}"), (ok,), diagram=DIAGRAM,
               note=f"{ok}: O mirrored in side {k}.")
        cx.add("circle_through", (ok, SIDES[f"s{k}"][0]), (f"k_{ok}",), role=Role.RESULT,
               diagram=DIAGRAM, note=f"the circle about {ok} of the circumradius: the points "
                                     f"of posture {k} that move on straight lines.")
        out.append(f"k_{ok}")
    return out
