"""Directed lines and the ruler verbs: join, meet, parallel, perpendicular, project, reflect.

A :class:`Line` keeps ``(a, b, c)``, meaning ``a x + b y + c w = 0``, with a
unit normal ``a² + b² = 1``.  A line is *directed*: its direction is
``(b, -a)``, so ``join(P, Q)`` runs from ``P`` toward ``Q``, and the
line-circle branches (``behind``, ``ahead``) are read along it.  ``Line(a, b, c)``
and ``Line(-a, -b, -c)`` are the same set of points with opposite directions,
and compare unequal; :func:`graphkin.geometry.predicates.is_on` and
:func:`~graphkin.geometry.predicates.is_parallel` compare the point sets.

Every function here is a thin view onto :mod:`graphkin.geometry.ops`.  As
there, a point at infinity is an ordinary input and output (the meet of
parallel lines); only true degeneracy raises :class:`~graphkin.errors.DegenerateError`.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (the lines of the case-2 and case-3 constructions) and Sec. 3.13
(the line of centers).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from graphkin.errors import DegenerateError, IdealPointError
from graphkin.geometry import ops
from graphkin.geometry.point import Point, Vector, _clean, _num
from graphkin.tolerance import Tolerance

__all__ = ["Line", "join", "meet", "parallel", "perpendicular", "project", "reflect",
           "angle_between"]


@dataclass(frozen=True, slots=True)
class Line:
    """A directed line ``a x + b y + c = 0`` with a unit normal ``(a, b)``.

    Parameters
    ----------
    a, b, c : float
        Coefficients; they are scaled so that ``a² + b² = 1`` (the sign is kept:
        it fixes the direction ``(b, -a)``).

    Raises
    ------
    DegenerateError
        Non-finite coefficients, or ``a = b = 0`` (the line at infinity, or no
        line at all, has no unit normal).

    See Also
    --------
    join : the line through two points.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8.

    Examples
    --------
    >>> l = Line(0, 2, -2)
    >>> l
    Line(0, 1, -1)
    >>> l.direction, l.normal
    (Vector(1, 0), Vector(0, 1))
    >>> Line.through(Point(0, 0), Point(0, 5)).direction
    Vector(0, 1)
    """

    a: float
    b: float
    c: float

    def __post_init__(self) -> None:
        a, b, c = float(self.a), float(self.b), float(self.c)
        if not (math.isfinite(a) and math.isfinite(b) and math.isfinite(c)):
            raise DegenerateError(f"a line needs finite coefficients, not ({a!r}, {b!r}, {c!r})",
                                  coefficients=(a, b, c))
        n = math.hypot(a, b)
        if n == 0.0:
            raise DegenerateError(f"({a!r}, {b!r}, {c!r}) has no normal: it is the line at "
                                  "infinity or no line at all", coefficients=(a, b, c))
        object.__setattr__(self, "a", _clean(a / n))
        object.__setattr__(self, "b", _clean(b / n))
        object.__setattr__(self, "c", _clean(c / n))

    @classmethod
    def through(cls, P: Point, Q: Point, tol: Tolerance | None = None) -> Line:
        """The line through ``P`` and ``Q``, directed from ``P`` toward ``Q`` (:func:`join`)."""
        return join(P, Q, tol)

    @classmethod
    def from_point_direction(cls, P: Point, direction: Vector) -> Line:
        """The line through finite ``P`` running in ``direction`` (its sense is kept).

        Examples
        --------
        >>> Line.from_point_direction(Point(0, 1), Vector(-3, 0))
        Line(0, -1, 1)
        """
        _need_finite(P, "P")
        line = ops.line_through(np.asarray(P), np.asarray(direction.unit()))
        return cls.from_array(line)

    @classmethod
    def from_array(cls, a: ArrayLike) -> Line:
        """The line stored in a length-3 array (as made by :mod:`graphkin.geometry.ops`).

        Raises
        ------
        DegenerateError
            NaN entries (the engine's "no answer") or a zero normal.
        """
        arr = np.asarray(a, dtype=float)
        if arr.shape != (3,):
            raise DegenerateError(f"a line is an array of shape (3,), not {arr.shape}",
                                  shape=arr.shape)
        if not np.all(np.isfinite(arr)):
            raise DegenerateError(f"no line: {arr.tolist()}", coefficients=arr.tolist())
        return cls(float(arr[0]), float(arr[1]), float(arr[2]))

    @property
    def direction(self) -> Vector:
        """The unit direction ``(b, -a)``."""
        return Vector(self.b, -self.a)

    @property
    def normal(self) -> Vector:
        """The unit normal ``(a, b)``: the direction turned 90° counterclockwise."""
        return Vector(self.a, self.b)

    @property
    def point(self) -> Point:
        """The point of the line nearest the origin (the foot of the perpendicular)."""
        return Point(-self.a * self.c, -self.b * self.c)

    @property
    def ideal_point(self) -> Point:
        """The line's point at infinity (shared by every parallel line)."""
        return Point.at_infinity(self.direction)

    def reversed(self) -> Line:
        """The same points, directed the other way."""
        return Line(-self.a, -self.b, -self.c)

    def signed_distance(self, P: Point) -> float:
        """Signed distance of finite ``P``: positive on the normal's side (to the left).

        Raises
        ------
        IdealPointError
            When ``P`` is at infinity.
        """
        _need_finite(P, "P")
        return float(ops.signed_distance(np.asarray(self), np.asarray(P)))

    def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
        return np.array([self.a, self.b, self.c], dtype=dtype or float)

    def __repr__(self) -> str:
        return f"Line({_num(self.a)}, {_num(self.b)}, {_num(self.c)})"


def _need_finite(P: Point, name: str) -> None:
    if P.is_ideal:
        raise IdealPointError(f"{name} = {P!r} is at infinity; a finite point is needed",
                              point=P)


def join(P: Point, Q: Point, tol: Tolerance | None = None) -> Line:
    """The line through two points, directed from ``P`` toward ``Q``.

    Either point may be at infinity: the line through the other point in
    that direction (so Kennedy's theorem needs no special case).

    Parameters
    ----------
    P, Q : Point
    tol : Tolerance, optional
        Decides when two finite points coincide (a length relative to their size).

    Returns
    -------
    Line

    Raises
    ------
    DegenerateError
        When ``P`` and ``Q`` coincide, or when both are at infinity (the line at
        infinity has no unit normal).

    See Also
    --------
    meet : the dual operation.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.13 (the line of centers through
    two instant centers).

    Examples
    --------
    >>> l = join(Point(0, 0), Point(2, 0))
    >>> l, l.direction
    (Line(0, 1, 0), Vector(1, 0))
    >>> join(Point(1, 1), Point.at_infinity((0, 1)))
    Line(-1, 0, 1)
    """
    line = ops.join(np.asarray(P), np.asarray(Q), tol)
    if not np.all(np.isfinite(line)):
        if P.is_ideal and Q.is_ideal:
            why = "both points are at infinity: they lie on the line at infinity"
        else:
            why = "the two points coincide, so no line joins them"
        raise DegenerateError(f"join({P!r}, {Q!r}): {why}", points=(P, Q))
    return Line.from_array(line)


def meet(l: Line, m: Line, tol: Tolerance | None = None) -> Point:  # noqa: E741
    """The point common to two lines; a point at infinity when they are parallel.

    Parameters
    ----------
    l, m : Line
    tol : Tolerance, optional
        Decides when the meet is far enough to count as a point at infinity.

    Returns
    -------
    Point

    Raises
    ------
    DegenerateError
        When the lines coincide (every point is common).

    See Also
    --------
    join : the dual operation.
    intersect : all intersections of lines and circles.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, case 3 (two lines of known
    direction meet at the solution; parallel lines meet at infinity).

    Examples
    --------
    >>> meet(Line(1, 0, -2), Line(0, 1, -3))
    Point(2, 3)
    >>> meet(Line(0, 1, 0), Line(0, 1, -1))
    Point(1, 0) at infinity
    """
    p = ops.meet(np.asarray(l), np.asarray(m), tol)
    if not np.all(np.isfinite(p)):
        raise DegenerateError(f"meet({l!r}, {m!r}): the two lines coincide", lines=(l, m))
    return Point.from_array(p, tol)


def parallel(line: Line, through: Point) -> Line:
    """The line through ``through`` parallel to ``line``, in the same direction.

    Raises
    ------
    IdealPointError
        When ``through`` is at infinity.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, case 2 step 2 ("construct a
    line through the origin of C parallel to Â").

    Examples
    --------
    >>> parallel(Line(0, 1, 0), through=Point(5, 2))
    Line(0, 1, -2)
    """
    _need_finite(through, "through")
    return Line.from_array(ops.parallel(np.asarray(line), np.asarray(through)))


def perpendicular(line: Line, through: Point) -> Line:
    """The line through ``through`` perpendicular to ``line``.

    Its direction is ``line``'s normal: ``line``'s direction turned 90°
    counterclockwise.

    Raises
    ------
    IdealPointError
        When ``through`` is at infinity.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (velocity differences are
    drawn perpendicular to the link).

    Examples
    --------
    >>> perpendicular(Line(0, 1, 0), through=Point(3, 3)).direction
    Vector(0, 1)
    """
    _need_finite(through, "through")
    return Line.from_array(ops.perpendicular(np.asarray(line), np.asarray(through)))


def project(P: Point, line: Line) -> Point:
    """The foot of the perpendicular from finite ``P`` to ``line``.

    Raises
    ------
    IdealPointError
        When ``P`` is at infinity.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8.

    Examples
    --------
    >>> project(Point(3, 4), Line(0, 1, 0))
    Point(3, 0)
    """
    _need_finite(P, "P")
    return Point.from_array(ops.project(np.asarray(P), np.asarray(line)))


def reflect(P: Point, line: Line) -> Point:
    """The mirror image of ``P`` in ``line``.

    A point at infinity reflects to the point at infinity of the mirrored
    direction.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (the two branches of case 4
    are mirror images in the line of vector C).

    Examples
    --------
    >>> reflect(Point(4, 3), Line(0, 1, 0))
    Point(4, -3)
    >>> reflect(Point.at_infinity((1, 2)), Line(0, 1, 0)) == Point.at_infinity((1, -2))
    True
    """
    if P.is_ideal:
        d, n = np.asarray(P.direction), np.asarray(line.normal)
        mirrored = d - 2.0 * ops.dot2(d, n) * n
        return Point.at_infinity((float(mirrored[0]), float(mirrored[1])))
    return Point.from_array(ops.reflect(np.asarray(P), np.asarray(line)))


def angle_between(first: Line | Vector, second: Line | Vector) -> float:
    """The angle (rad) from the direction of ``first`` to that of ``second``, in (-π, π].

    Counterclockwise is positive.  Lines and vectors may be mixed.

    Raises
    ------
    DegenerateError
        When a vector is zero (it has no direction).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.10 (angles measured
    counterclockwise, Eq. 2.36).

    Examples
    --------
    >>> import math
    >>> round(math.degrees(angle_between(Line(0, 1, 0), Vector(-1, 1))), 6)
    135.0
    """
    u = first.direction if isinstance(first, Line) else first.unit()
    v = second.direction if isinstance(second, Line) else second.unit()
    uu, vv = np.asarray(u), np.asarray(v)
    return float(np.arctan2(ops.cross2(uu, vv), ops.dot2(uu, vv)))
