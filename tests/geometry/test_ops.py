"""The array engine, graphkin.geometry.ops: homogeneous points and lines, broadcasting.

Every expected value is worked out by hand in a comment (Uicker et al., 5th ed.,
Sec. 2.8 for the constructions the functions serve).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from numpy.testing import assert_allclose, assert_array_equal

from graphkin.geometry import ops
from graphkin.tolerance import Tolerance


def _none(p) -> bool:
    """The engine's "no answer": a NaN in the coordinates (a missing point is (nan, nan, 1))."""
    return bool(np.any(np.isnan(p)))


def test_point_and_ideal_point():
    assert_array_equal(ops.point(3, 4), [3.0, 4.0, 1.0])
    # the direction (3, 4) has length 5
    assert_allclose(ops.ideal_point(3, 4), [0.6, 0.8, 0.0])
    # broadcasting: three x values and one y
    assert ops.point([0, 1, 2], 5).shape == (3, 3)


def test_xy_of_finite_and_ideal_points():
    assert_array_equal(ops.xy([2.0, 4.0, 2.0]), [1.0, 2.0])
    # a point at infinity has no finite coordinates: NaN, and no RuntimeWarning
    assert _none(ops.xy(ops.ideal_point(1, 0)))
    assert_array_equal(ops.is_ideal([[1, 0, 0], [1, 0, 1]]), [True, False])


def test_normalize_point():
    assert_array_equal(ops.normalize_point([2.0, 4.0, 2.0]), [1.0, 2.0, 1.0])
    # |w| below tol.angle times |(x, y)|: taken as a point at infinity, unit direction
    assert_allclose(ops.normalize_point([3.0, 4.0, 1e-12]), [0.6, 0.8, 0.0])
    assert _none(ops.normalize_point([0.0, 0.0, 0.0]))


def test_join_is_directed_from_p_to_q():
    # through (0, 0) and (2, 0): the x axis, a x + b y + c = 0 with (a, b, c) = (0, 1, 0)
    line = ops.join(ops.point(0, 0), ops.point(2, 0))
    assert_array_equal(line, [0.0, 1.0, 0.0])
    assert_array_equal(ops.direction(line), [1.0, 0.0])
    assert_array_equal(ops.direction(ops.join(ops.point(2, 0), ops.point(0, 0))), [-1.0, 0.0])


def test_join_with_an_ideal_point_and_of_coincident_points():
    # the line through (1, 1) toward the point at infinity upward is x = 1
    line = ops.join(ops.point(1, 1), ops.ideal_point(0, 1))
    assert_allclose(ops.direction(line), [0.0, 1.0])
    assert abs(ops.signed_distance(line, ops.point(1, 7))) < 1e-15
    # coincident points: no line (NaN), the domain raises
    assert _none(ops.join(ops.point(1, 1), ops.point(1, 1)))


def test_meet_of_crossing_parallel_and_coincident_lines():
    # y = x and y = 2 - x cross at (1, 1)
    l1 = ops.join(ops.point(0, 0), ops.point(1, 1))
    l2 = ops.join(ops.point(0, 2), ops.point(1, 1))
    assert_allclose(ops.meet(l1, l2), [1.0, 1.0, 1.0])
    # y = 0 and y = 1 are parallel: they meet at the point at infinity of +-x
    p = ops.meet([0.0, 1.0, 0.0], [0.0, 1.0, -1.0])
    assert p[2] == 0.0 and abs(abs(p[0]) - 1.0) < 1e-15
    # the same line twice: NaN
    assert _none(ops.meet([0.0, 1.0, -1.0], [0.0, 1.0, -1.0]))
    # the same line with the opposite direction is still the same line
    assert _none(ops.meet([0.0, 1.0, -1.0], [0.0, -1.0, 1.0]))


def test_w_of_a_meet_is_the_sine_of_the_angle():
    # two unit-normal lines through the origin at 0 and t: (l1 x l2)_w = sin t (R3)
    for t in (0.3, 1e-4, 1e-10):
        l1 = ops.line_through(ops.point(0, 0), ops.vector(1, 0))
        l2 = ops.line_through(ops.point(0, 0), ops.vector(math.cos(t), math.sin(t)))
        assert abs(np.cross(l1, l2)[2] - math.sin(t)) <= 1e-15


def test_parallel_and_perpendicular():
    x_axis = ops.join(ops.point(0, 0), ops.point(1, 0))
    par = ops.parallel(x_axis, ops.point(5, 2))
    # y = 2, the same direction
    assert_array_equal(par, [0.0, 1.0, -2.0])
    perp = ops.perpendicular(x_axis, ops.point(3, 3))
    # x = 3, directed along the x axis's normal: +y (90 degrees counterclockwise)
    assert_allclose(ops.direction(perp), [0.0, 1.0])
    assert abs(ops.signed_distance(perp, ops.point(3, -10))) < 1e-15


def test_project_reflect_midpoint_distance():
    x_axis = [0.0, 1.0, 0.0]
    assert_allclose(ops.project(ops.point(3, 4), x_axis), [3.0, 0.0, 1.0])
    assert_allclose(ops.reflect(ops.point(3, 4), x_axis), [3.0, -4.0, 1.0])
    assert_allclose(ops.midpoint(ops.point(0, 0), ops.point(4, 2)), [2.0, 1.0, 1.0])
    # a 3-4-5 triangle
    assert ops.distance(ops.point(0, 0), ops.point(3, 4)) == 5.0


def test_signed_distance_is_positive_to_the_left():
    # the x axis directed +x: (0, 1) is to its left, on the normal's side
    line = ops.join(ops.point(0, 0), ops.point(1, 0))
    assert ops.signed_distance(line, ops.point(0, 1)) == 1.0
    assert ops.signed_distance(line, ops.point(0, -2)) == -2.0


def test_angles_rotation_translation():
    assert ops.angle_of(ops.vector(0, 1)) == pytest.approx(math.pi / 2)
    # from the x axis to the line y = x: +45 degrees
    l1 = ops.join(ops.point(0, 0), ops.point(1, 0))
    l2 = ops.join(ops.point(0, 0), ops.point(1, 1))
    assert ops.angle_between(l1, l2) == pytest.approx(math.pi / 4)
    assert ops.angle_between(l2, l1) == pytest.approx(-math.pi / 4)
    assert_allclose(ops.rotate(ops.vector(1, 0), math.pi / 2), [0.0, 1.0], atol=1e-16)
    assert_array_equal(ops.translate(ops.point(1, 1), ops.vector(2, 3)), [3.0, 4.0, 1.0])
    assert ops.cross2([1, 0], [0, 1]) == 1.0 and ops.dot2([1, 2], [3, 4]) == 11.0


def test_intersect_circles_left_then_right():
    # Fig. 2.13 with C = 8 along +x, A = B = 5: the arcs meet at (4, +-3);
    # (4, 3) is to the left of the directed line from (0, 0) to (8, 0)
    left, right = ops.intersect_circles([0, 0, 5], [8, 0, 5])
    assert_allclose(left, [4.0, 3.0, 1.0])
    assert_allclose(right, [4.0, -3.0, 1.0])
    # swapping the circles reverses the directed line, so the branches swap
    left2, right2 = ops.intersect_circles([8, 0, 5], [0, 0, 5])
    assert_allclose(left2, right)
    assert_allclose(right2, left)


def test_intersect_circles_tangent_missing_concentric():
    # externally tangent: 3 + 5 = 8, one point (3, 0) given twice
    left, right = ops.intersect_circles([0, 0, 3], [8, 0, 5])
    assert_array_equal(left, right)
    assert_allclose(left, [3.0, 0.0, 1.0])
    # 1 + 2 < 8: no point
    left, right = ops.intersect_circles([0, 0, 1], [8, 0, 2])
    assert _none(left) and _none(right)
    # concentric: no point
    left, _ = ops.intersect_circles([0, 0, 1], [0, 0, 2])
    assert _none(left)


def test_intersect_line_circle_behind_then_ahead():
    # the x axis directed +x cuts the circle r = 5 at x = -5 (first) and x = +5
    line = ops.join(ops.point(-9, 0), ops.point(9, 0))
    behind, ahead = ops.intersect_line_circle(line, [0, 0, 5])
    assert_allclose(behind, [-5.0, 0.0, 1.0])
    assert_allclose(ahead, [5.0, 0.0, 1.0])
    # directed the other way, the order turns round
    behind, ahead = ops.intersect_line_circle(-np.asarray(line), [0, 0, 5])
    assert_allclose(behind, [5.0, 0.0, 1.0])


def test_intersect_line_circle_tangent_and_missing():
    # y = 5 touches the circle r = 5 at (0, 5)
    behind, ahead = ops.intersect_line_circle([0.0, 1.0, -5.0], [0, 0, 5])
    assert_array_equal(behind, ahead)
    assert_allclose(behind, [0.0, 5.0, 1.0])
    behind, ahead = ops.intersect_line_circle([0.0, 1.0, -6.0], [0, 0, 5])
    assert _none(behind) and _none(ahead)


def test_similar_point_builds_a_directly_similar_triangle():
    # local triangle A=(0,0), B=(1,0), P=(1,1); the image of AB is (0,0)->(0,2):
    # turned 90 degrees and doubled, so P maps to (0,0) + 2 * (-1, 1) = (-2, 2)
    p = ops.similar_point(ops.point(0, 0), ops.point(0, 2), [0, 0], [1, 0], [1, 1])
    assert_allclose(p, [-2.0, 2.0, 1.0])


def test_tolerance_decides_tangency():
    # the arcs miss by 1e-6: tangent for a loose tolerance, missing for the default
    loose = Tolerance(length_rel=1e-3)
    left, right = ops.intersect_circles([0, 0, 3], [8 + 1e-6, 0, 5], loose)
    assert np.all(np.isfinite(left)) and np.array_equal(left, right)
    left, _ = ops.intersect_circles([0, 0, 3], [8 + 1e-6, 0, 5])
    assert _none(left)


def test_broadcasting_one_against_many():
    # one line against four points: four signed distances
    pts = ops.point([0, 1, 2, 3], [1, -1, 2, 0])
    assert_array_equal(ops.signed_distance([0.0, 1.0, 0.0], pts), [1.0, -1.0, 2.0, 0.0])
    # one circle against a fan of lines through its center: every line cuts it
    t = np.linspace(0, math.pi, 7)
    lines = ops.line_through(ops.point(0, 0), ops.vector(np.cos(t), np.sin(t)))
    behind, ahead = ops.intersect_line_circle(lines, [0, 0, 2])
    assert behind.shape == (7, 3)
    assert_allclose(ops.distance(behind, ahead), 4.0)


def test_meet_decides_parallel_by_angle_not_by_distance():
    # Two lines 1e-6 rad apart meet about 1e6 length units away: a finite point in any
    # unit (it was taken as at infinity only past 1/tol.angle = 1e9 units before).
    g = ops
    l1 = g.join(g.point(0, 0), g.point(1, 0))
    l2 = g.line_through(g.point(0, 1), g.vector(np.cos(1e-6), -np.sin(1e-6)))
    p = g.meet(l1, l2)
    assert p[2] == 1.0
    # x = 1/tan(1e-6)
    assert p[0] == pytest.approx(1.0 / np.tan(1e-6), rel=1e-9)
    # 1e-10 rad apart: parallel within the default angle tolerance 1e-9 -> at infinity
    l3 = g.line_through(g.point(0, 1), g.vector(np.cos(1e-10), -np.sin(1e-10)))
    q = g.meet(l1, l3)
    assert q[2] == 0.0 and abs(q[0]) == pytest.approx(1.0)


def test_parallel_and_perpendicular_broadcast_one_line_against_many_points():
    # found by the batch property test: a design axis on the points only (a slider's line
    # fixed in the frame, its point varied per design) -- the lines through (0, 2) and
    # (5, -1) parallel to y = 0 are y = 2 and y = -1; the perpendiculars are x = 0 and x = 5
    from graphkin.geometry.ops import parallel, perpendicular

    pts = np.array([[0.0, 2.0, 1.0], [5.0, -1.0, 1.0]])
    par = parallel([0.0, 1.0, 0.0], pts)
    assert par.shape == (2, 3)
    np.testing.assert_allclose(-par[:, 2] / par[:, 1], [2.0, -1.0])
    per = perpendicular([0.0, 1.0, 0.0], pts)
    assert per.shape == (2, 3)
    np.testing.assert_allclose(per[:, 0] * pts[:, 0] + per[:, 1] * pts[:, 1] + per[:, 2], 0.0)
    np.testing.assert_allclose(per[:, 1], 0.0)
