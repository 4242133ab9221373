"""Hypothesis invariants of the geometry (STYLE.md R4, layer 1).

* a meet lies on both lines, and a join contains both points;
* circle intersections lie on both circles, ``left`` to the left of the
  directed line of centers (positive cross product), ``right`` to its right;
  line-circle intersections come ``behind`` then ``ahead`` along the line;
* a batch evaluation of shape ``(N, 3)`` equals a loop of single evaluations (to the
  last bits: numpy's vectorised loops may round differently);
* the meet of parallel lines is a point at infinity in their direction.

References: Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (cases 2-4).
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from graphkin.errors import DegenerateError
from graphkin.geometry import (
    Circle,
    Line,
    Point,
    Vector,
    intersect,
    is_on,
    is_parallel,
    join,
    meet,
    ops,
    parallel,
)

# a drawing a few hundred units across; the relative tolerances scale with it
# (no subnormal-sized coordinates or angles: ops.normalize_point would overflow dividing by them)
coord = st.one_of(st.just(0.0), st.floats(1e-6, 100), st.floats(-100, -1e-6))
radius = st.floats(0.1, 100, allow_nan=False, allow_infinity=False)
angle = st.one_of(st.just(0.0), st.floats(1e-9, math.pi), st.floats(-math.pi, -1e-9))

points = st.builds(Point, coord, coord)
directions = st.builds(lambda t: Vector(math.cos(t), math.sin(t)), angle)
lines = st.builds(Line.from_point_direction, points, directions)
circles = st.builds(Circle, points, radius)


def _same(batch: np.ndarray, loop: np.ndarray) -> None:
    """Equal, NaN where NaN, to a few units in the last place of the drawing's size (100)."""
    assert batch.shape == loop.shape
    assert_allclose(batch, loop, rtol=1e-13, atol=1e-13 * 100)


def _far_apart(P: Point, Q: Point, d: float = 1e-3) -> bool:
    return math.hypot(P.x - Q.x, P.y - Q.y) > d


@given(lines, lines)
def test_meet_lies_on_both_lines(l, m):  # noqa: E741
    # nearly parallel lines meet very far away; beyond 1e-6 rad the meet stays finite
    assume(abs(l.direction.cross(m.direction)) > 1e-6)
    P = meet(l, m)
    assert P.is_finite
    assert is_on(P, l) and is_on(P, m)


@given(points, points)
def test_join_contains_both_points_directed_from_first(P, Q):
    assume(_far_apart(P, Q))
    line = join(P, Q)
    assert is_on(P, line) and is_on(Q, line)
    assert (Q - P).dot(line.direction) > 0


@given(points, directions)
def test_join_with_a_point_at_infinity(P, d):
    line = join(P, Point.at_infinity(d))
    assert is_on(P, line) and is_parallel(line, d)


@given(lines, points)
def test_meet_of_parallel_lines_is_ideal(l, Q):  # noqa: E741
    # lines nearly coincident lose the direction of their meet to cancellation in l × m
    assume(abs(l.signed_distance(Q)) > 1e-3)
    m = parallel(l, through=Q)
    P = meet(l, m)
    assert P.is_ideal
    # the same direction as the line's own point at infinity (== is exact, so compare by angle)
    assert is_parallel(P.direction, l) and is_on(P, l) and is_on(P, m)


@given(circles, circles)
def test_circle_intersections_lie_on_both_and_follow_left_right(k1, k2):
    try:
        found = intersect(k1, k2)
    except DegenerateError:  # the same circle twice: every point is common
        assume(False)
    if len(found) < 2:
        return
    left, right = found
    # a clear crossing, so that the side of each point is well defined
    assume(_far_apart(left, right, 1e-6 * max(k1.radius, k2.radius)))
    for P in found:
        assert is_on(P, k1) and is_on(P, k2)
    d = k2.center - k1.center
    assert d.cross(left - k1.center) > 0 > d.cross(right - k1.center)


@given(lines, circles)
def test_line_circle_intersections_behind_then_ahead(l, k):  # noqa: E741
    found = intersect(l, k)
    for P in found:
        assert is_on(P, l) and is_on(P, k)
    if len(found) == 2:
        behind, ahead = found
        assert (ahead - behind).dot(l.direction) > 0


@given(st.lists(st.tuples(lines, lines), min_size=1, max_size=8))
def test_batch_meet_and_join_equal_a_loop(pairs):
    L1 = np.array([np.asarray(a) for a, _ in pairs])
    L2 = np.array([np.asarray(b) for _, b in pairs])
    batch = ops.meet(L1, L2)
    loop = np.array([ops.meet(a, b) for a, b in zip(L1, L2)])
    assert batch.shape == (len(pairs), 3)
    _same(batch, loop)
    P, Q = ops.point(L1[:, 0] * 7, L1[:, 1]), ops.point(L2[:, 2], L2[:, 0])
    _same(ops.join(P, Q), np.array([ops.join(p, q) for p, q in zip(P, Q)]))


@given(st.lists(st.tuples(circles, circles, lines), min_size=1, max_size=8))
def test_batch_intersections_equal_a_loop(triples):
    K1 = np.array([np.asarray(a) for a, _, _ in triples])
    K2 = np.array([np.asarray(b) for _, b, _ in triples])
    L = np.array([np.asarray(c) for _, _, c in triples])
    for batch, loop in (
            (ops.intersect_circles(K1, K2),
             [ops.intersect_circles(a, b) for a, b in zip(K1, K2)]),
            (ops.intersect_line_circle(L, K1),
             [ops.intersect_line_circle(c, a) for c, a in zip(L, K1)])):
        for branch in range(2):
            _same(batch[branch], np.array([pair[branch] for pair in loop]))


@settings(max_examples=50)
@given(st.lists(st.tuples(lines, lines), min_size=1, max_size=8))
def test_value_meet_equals_array_meet(pairs):
    batch = ops.meet(np.array([np.asarray(a) for a, _ in pairs]),
                     np.array([np.asarray(b) for _, b in pairs]))
    for (l, m), row in zip(pairs, batch):  # noqa: E741
        if np.all(np.isfinite(row)):
            assert meet(l, m) == Point.from_array(row)
