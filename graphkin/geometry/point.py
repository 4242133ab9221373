"""Points (finite or at infinity) and free vectors: the small frozen values of the API.

A :class:`Point` keeps homogeneous coordinates ``(x, y, w)`` as three floats.
A finite point is normalised to ``w = 1``; a point at infinity (an *ideal*
point) has ``w = 0`` and a unit direction with a canonical sign (its first
nonzero component positive), so that ``==`` and ``hash`` work: the ideal point
of a direction and of its opposite are the same point, as in projective
geometry.  A :class:`Vector` is a free vector ``(x, y)``.

These values are views onto :mod:`graphkin.geometry.ops`: ``numpy.asarray(P)``
is the array the engine works on, and :meth:`Point.from_array` reads one back.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.2 (position of a point), Sec. 2.10 (polar notation ``R∠θ``) and
Sec. 3.14 (instant centers at infinity).
"""

from __future__ import annotations

import math
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from graphkin.errors import DegenerateError, IdealPointError
from graphkin.geometry import ops
from graphkin.tolerance import Tolerance

__all__ = ["Point", "Vector", "midpoint"]


def _num(v: float) -> str:
    """A float as the shortest text that reads back to it (``3`` rather than ``3.0``)."""
    if math.isfinite(v) and v.is_integer() and abs(v) < 1e16:
        return str(int(v))
    return repr(float(v))


def _clean(v: float) -> float:
    """``v`` with a negative zero made positive (so reprs and signs stay tidy)."""
    return v + 0.0


@dataclass(frozen=True, slots=True)
class Vector:
    """A free vector ``(x, y)``: a magnitude and a direction, with no position.

    Parameters
    ----------
    x, y : float
        Components.

    See Also
    --------
    Point : a position (finite or at infinity).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.10, Eqs. (2.34)-(2.36)
    (rectangular and polar forms ``R = R∠θ``).

    Examples
    --------
    Example 2.3 of the book: ``A = 10∠30°`` plus ``B = 8∠-15°``.

    >>> import math
    >>> C = Vector.polar(10, math.radians(30)) + Vector.polar(8, math.radians(-15))
    >>> round(C.magnitude, 2), round(math.degrees(C.angle), 1)
    (16.65, 10.1)
    >>> Vector(3, 4)
    Vector(3, 4)
    """

    x: float
    y: float

    def __post_init__(self) -> None:
        x, y = float(self.x), float(self.y)
        if not (math.isfinite(x) and math.isfinite(y)):
            raise DegenerateError(f"a vector needs finite components, not ({x!r}, {y!r})",
                                  components=(x, y))
        object.__setattr__(self, "x", _clean(x))
        object.__setattr__(self, "y", _clean(y))

    @classmethod
    def polar(cls, magnitude: float, angle: float) -> Vector:
        """The vector ``R∠θ`` (Eq. 2.35): ``(R cos θ, R sin θ)``, ``θ`` in radians.

        A negative magnitude gives the vector pointing the other way.
        """
        v = ops.rotate(ops.vector(magnitude, 0.0), angle)
        return cls(float(v[0]), float(v[1]))

    @classmethod
    def from_array(cls, a: ArrayLike) -> Vector:
        """The vector stored in a length-2 array (as made by :mod:`graphkin.geometry.ops`)."""
        arr = np.asarray(a, dtype=float)
        if arr.shape != (2,):
            raise DegenerateError(f"a vector is an array of shape (2,), not {arr.shape}",
                                  shape=arr.shape)
        return cls(float(arr[0]), float(arr[1]))

    @property
    def magnitude(self) -> float:
        """Length ``R`` (Eq. 2.36), never negative."""
        return math.hypot(self.x, self.y)

    @property
    def angle(self) -> float:
        """Direction angle ``θ`` in radians, counterclockwise from +x, in (-π, π]."""
        return float(ops.angle_of(np.asarray(self)))

    def unit(self) -> Vector:
        """The unit vector of the same direction; the zero vector raises ``DegenerateError``."""
        n = self.magnitude
        if n == 0.0:
            raise DegenerateError("the zero vector has no direction", vector=self)
        return Vector(self.x / n, self.y / n)

    def rotated(self, angle: float) -> Vector:
        """The vector turned counterclockwise by ``angle`` (rad)."""
        return Vector.from_array(ops.rotate(np.asarray(self), angle))

    def dot(self, other: Vector) -> float:
        """Dot product."""
        return float(ops.dot2(np.asarray(self), np.asarray(other)))

    def cross(self, other: Vector) -> float:
        """The z component of ``self × other`` (positive when ``other`` is to the left)."""
        return float(ops.cross2(np.asarray(self), np.asarray(other)))

    def __add__(self, other: object) -> Vector:
        if not isinstance(other, Vector):
            return NotImplemented
        return Vector(self.x + other.x, self.y + other.y)

    def __sub__(self, other: object) -> Vector:
        if not isinstance(other, Vector):
            return NotImplemented
        return Vector(self.x - other.x, self.y - other.y)

    def __neg__(self) -> Vector:
        return Vector(-self.x, -self.y)

    def __mul__(self, k: object) -> Vector:
        if isinstance(k, bool) or not isinstance(k, (int, float)):
            return NotImplemented
        return Vector(self.x * k, self.y * k)

    __rmul__ = __mul__

    def __truediv__(self, k: object) -> Vector:
        if isinstance(k, bool) or not isinstance(k, (int, float)):
            return NotImplemented
        return Vector(self.x / k, self.y / k)

    def __abs__(self) -> float:
        return self.magnitude

    def __iter__(self) -> Iterator[float]:
        return iter((self.x, self.y))

    def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
        return np.array([self.x, self.y], dtype=dtype or float)

    def __repr__(self) -> str:
        return f"Vector({_num(self.x)}, {_num(self.y)})"


@dataclass(frozen=True, slots=True)
class Point:
    """A point of the plane in homogeneous coordinates: finite, or at infinity.

    Parameters
    ----------
    x, y : float
        Coordinates (of a finite point), or a direction (with ``w = 0``).
    w : float, default 1
        Homogeneous weight.  Any nonzero ``w`` is divided out; ``w = 0`` makes
        a point at infinity whose direction ``(x, y)`` is scaled to unit length
        with its first nonzero component positive.

    Raises
    ------
    DegenerateError
        Non-finite coordinates, or ``(0, 0, 0)`` (which is no point at all).

    See Also
    --------
    Point.at_infinity : the ideal point of a direction.
    graphkin.geometry.meet : the meet of parallel lines is an ideal point.

    Notes
    -----
    Geometry never raises for a point at infinity (a slider's instant center
    ``I14``, the meet of parallel lines); only asking for its finite
    coordinates with :attr:`xy` does, with :class:`~graphkin.errors.IdealPointError`.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.14 (instant centers at
    infinity, for example ``I14`` of a slider and ``I13`` of the Scotch yoke).

    Examples
    --------
    >>> Point(3, 4)
    Point(3, 4)
    >>> Point(6, 8, 2) == Point(3, 4)
    True
    >>> P = Point.at_infinity((0, -2))
    >>> P
    Point(0, 1) at infinity
    >>> P == Point.at_infinity((0, 5)), P.is_ideal, P.direction
    (True, True, Vector(0, 1))
    """

    x: float
    y: float
    w: float = 1.0

    def __post_init__(self) -> None:
        x, y, w = float(self.x), float(self.y), float(self.w)
        if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(w)):
            raise DegenerateError(f"a point needs finite homogeneous coordinates, "
                                  f"not ({x!r}, {y!r}, {w!r})", coordinates=(x, y, w))
        if w != 0.0:
            x, y, w = x / w, y / w, 1.0
            if not (math.isfinite(x) and math.isfinite(y)):
                raise DegenerateError(f"the point ({x!r}, {y!r}) overflows", coordinates=(x, y))
        else:
            n = math.hypot(x, y)
            if n == 0.0:
                raise DegenerateError("(0, 0, 0) is not a point: a point at infinity "
                                      "needs a nonzero direction", coordinates=(x, y, w))
            x, y = x / n, y / n
            if x < 0.0 or (x == 0.0 and y < 0.0):
                x, y = -x, -y
        object.__setattr__(self, "x", _clean(x))
        object.__setattr__(self, "y", _clean(y))
        object.__setattr__(self, "w", _clean(w))

    @classmethod
    def at_infinity(cls, direction: Vector | Sequence[float]) -> Point:
        """The point at infinity in ``direction`` (a :class:`Vector` or ``(dx, dy)``).

        Opposite directions give the same point.

        Examples
        --------
        >>> Point.at_infinity((-1, 0))
        Point(1, 0) at infinity
        """
        dx, dy = direction
        return cls(float(dx), float(dy), 0.0)

    @classmethod
    def from_array(cls, a: ArrayLike, tol: Tolerance | None = None) -> Point:
        """The point stored in a length-3 homogeneous array (as made by the ops).

        The array is normalised with :func:`graphkin.geometry.ops.normalize_point`,
        so a ``w`` that is negligible for ``tol`` makes an ideal point.

        Raises
        ------
        DegenerateError
            NaN entries (the engine's "no answer") or an all-zero array.

        Examples
        --------
        >>> from graphkin.geometry import ops
        >>> Point.from_array(ops.point(1, 2))
        Point(1, 2)
        """
        arr = np.asarray(a, dtype=float)
        if arr.shape != (3,):
            raise DegenerateError(f"a point is an array of shape (3,), not {arr.shape}",
                                  shape=arr.shape)
        if not np.all(np.isfinite(arr)):
            raise DegenerateError(f"no point: {arr.tolist()}", coordinates=arr.tolist())
        p = ops.normalize_point(arr, tol)
        if not np.all(np.isfinite(p)):
            raise DegenerateError(f"no point: {arr.tolist()}", coordinates=arr.tolist())
        return cls(float(p[0]), float(p[1]), float(p[2]))

    @property
    def is_finite(self) -> bool:
        """True for an ordinary point (``w = 1``)."""
        return self.w != 0.0

    @property
    def is_ideal(self) -> bool:
        """True for a point at infinity (``w = 0``)."""
        return self.w == 0.0

    @property
    def xy(self) -> tuple[float, float]:
        """Cartesian coordinates ``(x, y)`` of a finite point.

        Raises
        ------
        IdealPointError
            For a point at infinity (it has a direction, not coordinates).
        """
        if self.is_ideal:
            raise IdealPointError(f"{self!r} has no finite coordinates; use .direction",
                                  point=self)
        return (self.x, self.y)

    @property
    def direction(self) -> Vector:
        """The unit direction of a point at infinity (canonical sign).

        Raises
        ------
        DegenerateError
            For a finite point, which is not a direction.
        """
        if self.is_finite:
            raise DegenerateError(f"{self!r} is a finite point, not a direction at infinity",
                                  point=self)
        return Vector(self.x, self.y)

    def __add__(self, v: object) -> Point:
        if not isinstance(v, Vector):
            return NotImplemented
        if self.is_ideal:
            return self
        return Point.from_array(ops.translate(np.asarray(self), np.asarray(v)))

    def __sub__(self, other: object) -> Any:
        if isinstance(other, Vector):
            return self + (-other)
        if not isinstance(other, Point):
            return NotImplemented
        (x1, y1), (x0, y0) = self.xy, other.xy
        return Vector(x1 - x0, y1 - y0)

    def __array__(self, dtype: Any = None, copy: bool | None = None) -> np.ndarray:
        return np.array([self.x, self.y, self.w], dtype=dtype or float)

    def __repr__(self) -> str:
        text = f"Point({_num(self.x)}, {_num(self.y)})"
        return f"{text} at infinity" if self.w == 0.0 else text


def midpoint(P: Point, Q: Point) -> Point:
    """The midpoint of two finite points.

    Raises
    ------
    IdealPointError
        When either point is at infinity.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (graphic constructions).

    Examples
    --------
    >>> midpoint(Point(0, 0), Point(4, 2))
    Point(2, 1)
    """
    for name, p in (("P", P), ("Q", Q)):
        if p.is_ideal:
            raise IdealPointError(f"midpoint: {name} = {p!r} is at infinity", point=p)
    return Point.from_array(ops.midpoint(np.asarray(P), np.asarray(Q)))
