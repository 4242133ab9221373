"""Circles and :func:`intersect`: the compass verbs, with their branches in a fixed order.

:func:`intersect` returns a tuple of 0, 1 or 2 points in a documented order,
never raising for "no intersection" (the construction layer names the missing
branch and raises :class:`~graphkin.errors.NoIntersectionError`):

* circle and circle: ``(left, right)`` of the directed line from the first
  center to the second, ``left`` where the cross product
  ``(c2 - c1) × (P - c1)`` is positive (:class:`graphkin.construction.Side`);
* line and circle (either order): ``(behind, ahead)`` along the line's
  direction (:class:`graphkin.construction.Along`);
* line and line: ``(meet,)``, a point at infinity for parallel lines.

Tangency gives one point.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 and Table 2.2: case 2 intersects a line and an arc (Fig. 2.11),
case 4 two arcs (Fig. 2.13).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.errors import DegenerateError, IdealPointError
from graphkin.geometry import ops
from graphkin.geometry.line import Line, meet
from graphkin.geometry.point import Point, _num
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["Circle", "intersect"]


@dataclass(frozen=True, slots=True)
class Circle:
    """A circle (a compass arc) about a finite center with a radius > 0.

    Parameters
    ----------
    center : Point
        A finite point.
    radius : float
        Finite and > 0.

    Raises
    ------
    IdealPointError
        When ``center`` is at infinity.
    DegenerateError
        When ``radius`` is not a finite number > 0.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, case 4 ("construct a circular
    arc of radius A centered at the origin of C").

    Examples
    --------
    >>> k = Circle(Point(0, 0), 5)
    >>> k
    Circle(Point(0, 0), 5)
    >>> Circle.through(Point(1, 1), Point(4, 5)).radius
    5.0
    """

    center: Point
    radius: float

    def __post_init__(self) -> None:
        if not isinstance(self.center, Point):
            raise DegenerateError(f"a circle's center must be a Point, not {self.center!r}",
                                  center=self.center)
        if self.center.is_ideal:
            raise IdealPointError(f"a circle's center must be finite, not {self.center!r}",
                                  point=self.center)
        r = float(self.radius)
        if not (math.isfinite(r) and r > 0.0):
            raise DegenerateError(f"a circle needs a finite radius > 0, not {r!r}", radius=r)
        object.__setattr__(self, "radius", r)

    @classmethod
    def through(cls, center: Point, P: Point) -> Circle:
        """The circle about ``center`` through the finite point ``P``."""
        return cls(center, float(ops.distance(np.asarray(center), np.asarray(P))))

    def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
        return np.array([self.center.x, self.center.y, self.radius], dtype=dtype or float)

    def __repr__(self) -> str:
        return f"Circle({self.center!r}, {_num(self.radius)})"


def _points(*arrays: np.ndarray) -> tuple[Point, ...]:
    """The finite answers among ``arrays``, with a repeated (tangent) point kept once."""
    if not all(np.all(np.isfinite(a)) for a in arrays):
        return ()
    if len(arrays) == 2 and np.array_equal(arrays[0], arrays[1]):
        arrays = arrays[:1]
    return tuple(Point.from_array(a) for a in arrays)


def intersect(first: Line | Circle, second: Line | Circle,
              tol: Tolerance | None = None) -> tuple[Point, ...]:
    """The points common to two lines or circles, in the documented branch order.

    Parameters
    ----------
    first, second : Line or Circle
    tol : Tolerance, optional
        Decides tangency (a length relative to the figure) and parallelism.

    Returns
    -------
    tuple of Point
        * two circles: ``(left, right)`` of the directed line from
          ``first.center`` to ``second.center`` (left: positive cross product
          ``(c2 - c1) × (P - c1)``); ``()`` when they miss; one point when tangent;
        * a line and a circle, in either order: ``(behind, ahead)`` along the
          line's direction; ``()`` when the line misses; one point when tangent;
        * two lines: ``(meet,)``, at infinity when they are parallel.

    Raises
    ------
    DegenerateError
        Coincident lines or coincident circles (every point is common).

    See Also
    --------
    graphkin.geometry.ops.intersect_circles, graphkin.geometry.ops.intersect_line_circle :
        the array forms, which return NaN rather than fewer points.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, Table 2.2: case 2 (a line and
    an arc, Fig. 2.11), case 3 (two lines, Fig. 2.12), case 4 (two arcs,
    Fig. 2.13).

    Examples
    --------
    Case 4 with C = 8∠0°, A = B = 5: the arcs meet above and below C.

    >>> intersect(Circle(Point(0, 0), 5), Circle(Point(8, 0), 5))
    (Point(4, 3), Point(4, -3))
    >>> intersect(Line(0, 1, 0), Circle(Point(0, 0), 5))
    (Point(-5, 0), Point(5, 0))
    >>> intersect(Circle(Point(0, 0), 1), Circle(Point(5, 0), 1))
    ()
    """
    tol = tol or DEFAULT_TOL
    if isinstance(first, Circle) and isinstance(second, Circle):
        c1, c2 = np.asarray(first), np.asarray(second)
        if first.center == second.center or (
                float(ops.distance(np.asarray(first.center), np.asarray(second.center)))
                <= tol.length(max(first.radius, second.radius))):
            if abs(first.radius - second.radius) <= tol.length(max(first.radius,
                                                                   second.radius)):
                raise DegenerateError(f"intersect({first!r}, {second!r}): the circles "
                                      "coincide", circles=(first, second))
            return ()
        left, right = ops.intersect_circles(c1, c2, tol)
        return _points(left, right)
    if isinstance(first, Circle) and isinstance(second, Line):
        first, second = second, first
    if isinstance(first, Line) and isinstance(second, Circle):
        behind, ahead = ops.intersect_line_circle(np.asarray(first), np.asarray(second), tol)
        return _points(behind, ahead)
    if isinstance(first, Line) and isinstance(second, Line):
        return (meet(first, second, tol),)
    raise TypeError(f"intersect() takes Line or Circle objects, not "
                    f"{type(first).__name__} and {type(second).__name__}")
