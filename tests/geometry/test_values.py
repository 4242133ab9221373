"""The frozen value types of the public geometry API (STYLE.md R3, R5).

Expected values are worked out by hand in the comments; textbook references
are to Uicker, Pennock & Shigley, 5th ed.
"""

from __future__ import annotations

import dataclasses
import math
import pickle

import numpy as np
import pytest

from graphkin.errors import DegenerateError, GraphkinError, IdealPointError
from graphkin.geometry import (
    Circle,
    Line,
    Point,
    Vector,
    angle_between,
    are_collinear,
    are_concurrent,
    intersect,
    is_on,
    is_parallel,
    join,
    meet,
    midpoint,
    ops,
    parallel,
    perpendicular,
    project,
    reflect,
)

# ---- immutability (as shapely's test_point_immutable) ----------------------------------


@pytest.mark.parametrize("value, field", [
    (Point(1, 2), "x"),
    (Point.at_infinity((0, 1)), "w"),
    (Vector(1, 2), "y"),
    (Line(0, 1, 0), "c"),
    (Circle(Point(0, 0), 1), "radius"),
])
def test_values_are_immutable(value, field):
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(value, field, 5.0)
    # slots: no new attributes either
    with pytest.raises((AttributeError, TypeError)):
        value.extra = 1  # type: ignore[attr-defined]


def test_change_by_replace_renormalises():
    P = dataclasses.replace(Point(1, 2), x=5)
    assert P == Point(5, 2)
    # replace goes through __post_init__: w = 2 is divided out
    assert dataclasses.replace(Point(1, 2), w=2) == Point(0.5, 1)
    assert dataclasses.replace(Line(0, 1, 0), c=-3).point == Point(0, 3)


# ---- points: normalisation, ==, hash --------------------------------------------------


def test_finite_points_are_normalised_to_w_1():
    P = Point(6, 8, 2)
    assert (P.x, P.y, P.w) == (3.0, 4.0, 1.0)
    assert P == Point(3, 4) and hash(P) == hash(Point(3, 4))
    assert isinstance(P.x, float)
    assert P.is_finite and not P.is_ideal
    assert P.xy == (3.0, 4.0)


def test_ideal_points_have_unit_direction_and_canonical_sign():
    # (0, -2) and (0, 5) are the same direction up to sign: one point at infinity
    P, Q = Point.at_infinity((0, -2)), Point.at_infinity((0, 5))
    assert P == Q and hash(P) == hash(Q)
    assert (P.x, P.y, P.w) == (0.0, 1.0, 0.0)
    # first nonzero component positive: (-3, 4) becomes (3, -4)/5
    R = Point.at_infinity((-3, 4))
    assert (R.x, R.y) == (0.6, -0.8)
    assert R == Point(3, -4, 0) == Point.at_infinity(Vector(-6, 8))
    assert len({P, Q, R, Point(3, -4, 0)}) == 2
    assert P.is_ideal and not P.is_finite
    assert P.direction == Vector(0, 1)


def test_negative_zero_is_cleaned():
    assert repr(Point(-0.0, 1)) == "Point(0, 1)"
    assert repr(Point.at_infinity((-0.0, -1))) == "Point(0, 1) at infinity"
    assert math.copysign(1.0, Vector(-0.0, 0).x) == 1.0


def test_finite_and_ideal_points_differ():
    assert Point(1, 0) != Point.at_infinity((1, 0))


def test_xy_of_an_ideal_point_raises():
    P = Point.at_infinity((1, 1))
    with pytest.raises(IdealPointError) as info:
        _ = P.xy
    # it is both a graphkin error and a ValueError, and names the point
    assert isinstance(info.value, GraphkinError) and isinstance(info.value, ValueError)
    assert info.value.point == P
    with pytest.raises(DegenerateError):
        _ = Point(1, 1).direction


@pytest.mark.parametrize("args", [(math.nan, 0), (0, math.inf), (0, 0, 0), (1e308, 0, 1e-308)])
def test_no_point_raises_degenerate(args):
    with pytest.raises(DegenerateError):
        Point(*args)


def test_reprs():
    assert repr(Point(3, 4)) == "Point(3, 4)"
    assert repr(Point(0.5, -1.25)) == "Point(0.5, -1.25)"
    assert repr(Point.at_infinity((0, 3))) == "Point(0, 1) at infinity"
    assert repr(Vector(3, 4)) == "Vector(3, 4)"
    assert repr(Line(0, 2, -2)) == "Line(0, 1, -1)"
    assert repr(Circle(Point(1, 2), 2.5)) == "Circle(Point(1, 2), 2.5)"
    # a repr that reads back
    assert eval(repr(Point(0.1, 1 / 3))) == Point(0.1, 1 / 3)


def test_array_views_round_trip():
    P = Point(3, 4)
    assert np.asarray(P).tolist() == [3.0, 4.0, 1.0]
    assert np.asarray(Point.at_infinity((0, 2))).tolist() == [0.0, 1.0, 0.0]
    assert Point.from_array(np.asarray(P)) == P
    assert np.asarray(Vector(1, 2)).tolist() == [1.0, 2.0]
    assert np.asarray(Line(0, 1, -1)).tolist() == [0.0, 1.0, -1.0]
    assert np.asarray(Circle(Point(1, 2), 3)).tolist() == [1.0, 2.0, 3.0]
    # a w that is negligible for the tolerance reads back as a point at infinity
    assert Point.from_array([3.0, 4.0, 1e-12]) == Point.at_infinity((3, 4))
    with pytest.raises(DegenerateError):
        Point.from_array([np.nan, 0.0, 1.0])
    with pytest.raises(DegenerateError):
        Point.from_array([1.0, 2.0])


def test_values_pickle():
    for v in (Point(1, 2), Point.at_infinity((1, 1)), Vector(1, 2), Line(1, 1, 0),
              Circle(Point(0, 0), 2)):
        assert pickle.loads(pickle.dumps(v)) == v


def test_errors_pickle_with_their_objects():
    with pytest.raises(DegenerateError) as info:
        join(Point(1, 1), Point(1, 1))
    err = pickle.loads(pickle.dumps(info.value))
    assert type(err) is DegenerateError and err.points == (Point(1, 1), Point(1, 1))
    assert str(err) == str(info.value)


# ---- vectors --------------------------------------------------------------------------


def test_vector_polar_example_2_3():
    # Example 2.3: 10∠30° + 8∠-15° = (8.66 + 7.73, 5.00 - 2.07) = 16.65∠10.1°
    C = Vector.polar(10, math.radians(30)) + Vector.polar(8, math.radians(-15))
    assert C.magnitude == pytest.approx(16.647, abs=5e-4)
    assert math.degrees(C.angle) == pytest.approx(10.14, abs=5e-3)


def test_vector_arithmetic():
    u, v = Vector(1, 2), Vector(3, -1)
    assert u + v == Vector(4, 1) and u - v == Vector(-2, 3) and -u == Vector(-1, -2)
    assert 2 * u == u * 2 == Vector(2, 4) and u / 2 == Vector(0.5, 1)
    assert u.dot(v) == 1.0 and u.cross(v) == -7.0 and abs(Vector(3, 4)) == 5.0
    assert Vector(0, 2).unit() == Vector(0, 1)
    # a negative magnitude points the other way
    assert Vector.polar(-2, 0.0) == Vector(-2, 0)
    with pytest.raises(DegenerateError):
        Vector(0, 0).unit()
    x, y = Vector(5, 6)
    assert (x, y) == (5.0, 6.0)


def test_point_and_vector_arithmetic():
    assert Point(1, 1) + Vector(2, 3) == Point(3, 4)
    assert Point(3, 4) - Point(1, 1) == Vector(2, 3)
    assert Point(3, 4) - Vector(2, 3) == Point(1, 1)
    # a point at infinity stays where it is
    assert Point.at_infinity((1, 0)) + Vector(5, 5) == Point.at_infinity((1, 0))
    with pytest.raises(IdealPointError):
        Point.at_infinity((1, 0)) - Point(0, 0)


# ---- lines ----------------------------------------------------------------------------


def test_line_is_normalised_and_directed():
    line = Line(0, 2, -2)
    assert (line.a, line.b, line.c) == (0.0, 1.0, -1.0)
    assert line.direction == Vector(1, 0) and line.normal == Vector(0, 1)
    assert line.reversed() == Line(0, -1, 1) and line.reversed() != line
    assert line.point == Point(0, 1)
    assert line.ideal_point == Point.at_infinity((1, 0))
    # through (0, 0) toward (0, 5): directed +y
    assert Line.through(Point(0, 0), Point(0, 5)).direction == Vector(0, 1)
    assert Line.from_point_direction(Point(0, 1), Vector(-3, 0)).direction == Vector(-1, 0)
    # (0, 1) is to the left of the x axis directed +x
    assert Line(0, 1, 0).signed_distance(Point(0, 1)) == 1.0


@pytest.mark.parametrize("args", [(0, 0, 1), (math.nan, 1, 0)])
def test_no_line_raises_degenerate(args):
    with pytest.raises(DegenerateError):
        Line(*args)


def test_join_and_its_degenerate_cases():
    assert join(Point(0, 0), Point(2, 0)) == Line(0, 1, 0)
    # a finite point and a direction: the line through it in that direction (Kennedy)
    line = join(Point(1, 1), Point.at_infinity((0, 1)))
    assert is_on(Point(1, 50), line)
    with pytest.raises(DegenerateError, match="coincide"):
        join(Point(1, 1), Point(1, 1))
    with pytest.raises(DegenerateError, match="infinity"):
        join(Point.at_infinity((1, 0)), Point.at_infinity((0, 1)))


def test_meet_crossing_parallel_coincident():
    # x = 2 and y = 3
    assert meet(Line(1, 0, -2), Line(0, 1, -3)) == Point(2, 3)
    # y = 0 and y = 1: the point at infinity of the x direction, not an error
    P = meet(Line(0, 1, 0), Line(0, 1, -1))
    assert P == Point.at_infinity((1, 0))
    with pytest.raises(DegenerateError, match="coincide"):
        meet(Line(0, 1, -1), Line(0, -1, 1))


def test_parallel_perpendicular_project_reflect_midpoint():
    assert parallel(Line(0, 1, 0), through=Point(5, 2)) == Line(0, 1, -2)
    perp = perpendicular(Line(0, 1, 0), through=Point(3, 3))
    assert perp.direction == Vector(0, 1) and is_on(Point(3, -1), perp)
    assert project(Point(3, 4), Line(0, 1, 0)) == Point(3, 0)
    assert reflect(Point(4, 3), Line(0, 1, 0)) == Point(4, -3)
    # the direction (1, 2) mirrored in the x axis is (1, -2)
    assert reflect(Point.at_infinity((1, 2)), Line(0, 1, 0)) == Point.at_infinity((1, -2))
    assert midpoint(Point(0, 0), Point(4, 2)) == Point(2, 1)
    for f in (lambda: parallel(Line(0, 1, 0), through=Point.at_infinity((1, 0))),
              lambda: perpendicular(Line(0, 1, 0), through=Point.at_infinity((1, 0))),
              lambda: project(Point.at_infinity((1, 0)), Line(0, 1, 0)),
              lambda: midpoint(Point(0, 0), Point.at_infinity((1, 0)))):
        with pytest.raises(IdealPointError):
            f()


def test_angle_between():
    # from the x axis (directed +x) to the direction (-1, 1): +135 degrees
    assert math.degrees(angle_between(Line(0, 1, 0), Vector(-1, 1))) == pytest.approx(135)
    assert math.degrees(angle_between(Vector(-1, 1), Line(0, 1, 0))) == pytest.approx(-135)
    assert angle_between(Line(0, 1, 0), Line(0, -1, 0)) == pytest.approx(math.pi)


# ---- circles and intersect ------------------------------------------------------------


def test_circle_validation():
    assert Circle.through(Point(1, 1), Point(4, 5)).radius == 5.0
    for r in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(DegenerateError):
            Circle(Point(0, 0), r)
    with pytest.raises(IdealPointError):
        Circle(Point.at_infinity((1, 0)), 1)


def test_intersect_two_circles_left_then_right():
    # Fig. 2.13, C = 8∠0°, A = B = 5: (4, 3) is left of the directed line of centers
    assert intersect(Circle(Point(0, 0), 5), Circle(Point(8, 0), 5)) == (Point(4, 3),
                                                                          Point(4, -3))
    assert intersect(Circle(Point(8, 0), 5), Circle(Point(0, 0), 5)) == (Point(4, -3),
                                                                          Point(4, 3))


def test_intersect_tangent_missing_coincident_circles():
    # 3 + 5 = 8: tangent at (3, 0), one point
    assert intersect(Circle(Point(0, 0), 3), Circle(Point(8, 0), 5)) == (Point(3, 0),)
    assert intersect(Circle(Point(0, 0), 1), Circle(Point(8, 0), 2)) == ()
    # concentric: nothing in common
    assert intersect(Circle(Point(0, 0), 1), Circle(Point(0, 0), 2)) == ()
    with pytest.raises(DegenerateError, match="coincide"):
        intersect(Circle(Point(1, 1), 2), Circle(Point(1, 1), 2))


def test_intersect_line_and_circle_behind_then_ahead():
    k = Circle(Point(0, 0), 5)
    assert intersect(Line(0, 1, 0), k) == (Point(-5, 0), Point(5, 0))
    # either order of the arguments; the order follows the line's direction
    assert intersect(k, Line(0, -1, 0)) == (Point(5, 0), Point(-5, 0))
    assert intersect(Line(0, 1, -5), k) == (Point(0, 5),)
    assert intersect(Line(0, 1, -6), k) == ()


def test_intersect_two_lines():
    assert intersect(Line(1, 0, -2), Line(0, 1, -3)) == (Point(2, 3),)
    assert intersect(Line(0, 1, 0), Line(0, 1, -1)) == (Point.at_infinity((1, 0)),)
    with pytest.raises(TypeError):
        intersect(Point(0, 0), Line(0, 1, 0))  # type: ignore[arg-type]


# ---- predicates -----------------------------------------------------------------------


def test_is_parallel_uses_an_angle():
    assert is_parallel(Line(0, 1, 0), Line(0, -1, 7))
    # lines 1e-10 rad apart are parallel; 1e-6 rad apart are not (Tolerance.angle = 1e-9)
    assert is_parallel(Vector(1, 0), Vector(1, 1e-10))
    assert not is_parallel(Vector(1, 0), Vector(1, 1e-6))
    # far from the origin changes nothing: the test is dimensionless
    assert is_parallel(Line(0, 1, -1e6), Line.from_point_direction(Point(0, 0),
                                                                   Vector(1, 1e-10)))


def test_is_on():
    assert is_on(Point(4, 3), Circle(Point(0, 0), 5))
    assert not is_on(Point(4, 3.001), Circle(Point(0, 0), 5))
    assert is_on(Point.at_infinity((1, 0)), Line(0, 1, -3))
    assert not is_on(Point.at_infinity((1, 1)), Line(0, 1, -3))
    assert not is_on(Point.at_infinity((1, 0)), Circle(Point(0, 0), 5))


def test_are_collinear():
    assert are_collinear(Point(0, 0), Point(1, 1), Point(3, 3))
    assert not are_collinear(Point(0, 0), Point(1, 0), Point(0, 1))
    # Kennedy's theorem with an instant center at infinity: I12, I23 and I13 at infinity
    assert are_collinear(Point(0, 0), Point(1, 1), Point.at_infinity((-2, -2)))
    assert not are_collinear(Point(0, 0), Point(1, 1), Point.at_infinity((1, 0)))
    # all at infinity: on the line at infinity
    assert are_collinear(Point.at_infinity((1, 0)), Point.at_infinity((0, 1)),
                         Point.at_infinity((1, 1)))
    assert are_collinear(Point(1, 1), Point(1, 1), Point(1, 1))
    assert are_collinear(Point(0, 0), Point(5, 0))


def test_are_concurrent():
    assert are_concurrent(Line(1, 0, 0), Line(0, 1, 0), Line(1, 1, 0))
    assert not are_concurrent(Line(1, 0, 0), Line(0, 1, 0), Line(1, 1, -1))
    # parallel lines are concurrent at infinity
    assert are_concurrent(Line(0, 1, 0), Line(0, 1, -1), Line(0, -1, 5))
    assert are_concurrent(Line(0, 1, 0), Line(0, 1, 0), Line(0, 1, 0))


def test_value_functions_are_views_onto_ops():
    # the same numbers as the array engine
    l1, l2 = Line(1, 2, -3), Line(-2, 1, 4)
    assert meet(l1, l2) == Point.from_array(ops.meet(np.asarray(l1), np.asarray(l2)))
    left, right = ops.intersect_circles([0, 0, 5], [6, 1, 4])
    assert intersect(Circle(Point(0, 0), 5), Circle(Point(6, 1), 4)) == (
        Point.from_array(left), Point.from_array(right))
