"""Geometric predicates with explicit, scale-aware tolerances.

Parallelism is decided by an *angle* (dimensionless, the right measure for
drawings); incidence by a *length* relative to the size of the figure
(:class:`~graphkin.tolerance.Tolerance`).  A point at infinity lies on a line
when it is the line's direction.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (case 3: parallel or collinear lines) and Sec. 3.13 (Kennedy's
theorem: three instant centers are collinear).
"""

from __future__ import annotations

import math
from itertools import combinations

import numpy as np

from graphkin.errors import DegenerateError
from graphkin.geometry import ops
from graphkin.geometry.circle import Circle
from graphkin.geometry.line import Line, join, meet
from graphkin.geometry.point import Point, Vector
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["is_parallel", "are_collinear", "are_concurrent", "is_on"]


def _direction(x: Line | Vector) -> np.ndarray:
    return np.asarray(x.direction if isinstance(x, Line) else x.unit())


def is_parallel(first: Line | Vector, second: Line | Vector,
                tol: Tolerance | None = None) -> bool:
    """True when two lines (or vectors) are parallel: the sine of their angle ≤ ``tol.angle``.

    Opposite directions count as parallel.

    Raises
    ------
    DegenerateError
        When a vector is zero.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8: case 3 has no unique
    solution when its two lines are parallel or collinear.

    Examples
    --------
    >>> is_parallel(Line(0, 1, 0), Line(0, -1, 7))
    True
    >>> is_parallel(Vector(1, 0), Vector(1, 1e-6))
    False
    """
    tol = tol or DEFAULT_TOL
    return bool(abs(ops.cross2(_direction(first), _direction(second))) <= tol.angle)


def is_on(P: Point, obj: Line | Circle, tol: Tolerance | None = None) -> bool:
    """True when the point ``P`` lies on the line or circle ``obj``.

    A finite point is on a line when its distance is within the length
    tolerance of the figure's size; a point at infinity is on a line when it is
    the line's direction (by angle).  No point at infinity lies on a circle.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.13 (an instant center at
    infinity lies on every line of its direction).

    Examples
    --------
    >>> is_on(Point(4, 3), Circle(Point(0, 0), 5))
    True
    >>> is_on(Point.at_infinity((1, 0)), Line(0, 1, -3))
    True
    >>> is_on(Point(0, 1), Line(0, 1, 0))
    False
    """
    tol = tol or DEFAULT_TOL
    if isinstance(obj, Line):
        if P.is_ideal:
            return is_parallel(P.direction, obj, tol)
        scale = max(abs(P.x), abs(P.y), abs(obj.c))
        return bool(abs(obj.signed_distance(P)) <= tol.length(scale))
    if isinstance(obj, Circle):
        if P.is_ideal:
            return False
        d = float(ops.distance(np.asarray(obj.center), np.asarray(P)))
        scale = max(obj.radius, abs(obj.center.x), abs(obj.center.y), abs(P.x), abs(P.y))
        return bool(abs(d - obj.radius) <= tol.length(scale))
    raise TypeError(f"is_on() tests a Line or a Circle, not {type(obj).__name__}")


def are_collinear(*points: Point, tol: Tolerance | None = None) -> bool:
    """True when all the points lie on one line (points at infinity included).

    Points at infinity all lie on the line at infinity; a finite line holds
    exactly one of them (its direction).  Fewer than three points, or points
    that all coincide, are collinear.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.13: the Aronhold-Kennedy
    theorem, three instant centers shared by three bodies lie on one line.

    Examples
    --------
    >>> are_collinear(Point(0, 0), Point(1, 1), Point(3, 3))
    True
    >>> are_collinear(Point(0, 0), Point(1, 1), Point.at_infinity((1, 1)))
    True
    >>> are_collinear(Point(0, 0), Point(1, 0), Point(0, 1))
    False
    """
    tol = tol or DEFAULT_TOL
    if len(points) < 3:
        return True
    finite = [p for p in points if p.is_finite]
    ideal = [p for p in points if p.is_ideal]
    if not finite:
        return True
    if ideal:
        line = join(finite[0], ideal[0], tol)
    else:
        P, Q = max(combinations(finite, 2),
                   key=lambda pq: math.hypot(pq[1].x - pq[0].x, pq[1].y - pq[0].y))
        try:
            line = join(P, Q, tol)
        except DegenerateError:  # every point coincides
            return True
    return all(is_on(p, line, tol) for p in points)


def are_concurrent(*lines: Line, tol: Tolerance | None = None) -> bool:
    """True when all the lines pass through one point (parallel lines meet at infinity).

    Fewer than three lines, or lines that all coincide, are concurrent.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.13-3.14 (instant centers as the
    meet of lines of centers).

    Examples
    --------
    >>> are_concurrent(Line(1, 0, 0), Line(0, 1, 0), Line(1, 1, 0))
    True
    >>> are_concurrent(Line(0, 1, 0), Line(0, 1, -1), Line(0, 1, -2))
    True
    >>> are_concurrent(Line(1, 0, 0), Line(0, 1, 0), Line(1, 1, -1))
    False
    """
    tol = tol or DEFAULT_TOL
    if len(lines) < 3:
        return True
    common = None
    for other in lines[1:]:
        try:
            common = meet(lines[0], other, tol)
            break
        except DegenerateError:  # coincident with the first line
            continue
    if common is None:
        return True
    return all(is_on(common, line, tol) for line in lines)
