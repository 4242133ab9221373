"""Explicit, scale-aware tolerances.

Parallelism is decided by an angle (dimensionless); coincidence by a length
relative to the size of the figure plus an absolute floor.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TypeVar

import numpy as np
from numpy.typing import NDArray

_S = TypeVar("_S", float, NDArray[np.float64])

__all__ = ["Tolerance", "DEFAULT_TOL"]


@dataclass(frozen=True, slots=True)
class Tolerance:
    """Tolerances of the geometric decisions.

    Parameters
    ----------
    length_rel : float
        Two lengths are equal when they differ by less than ``length_rel``
        times the size of the figure (plus ``length_abs``).
    length_abs : float
        Absolute floor of the length tolerance, in the drawing's length unit.
    angle : float
        Two lines are parallel when the sine of their angle is below this (rad).

    Examples
    --------
    >>> tol = Tolerance()
    >>> tol.length(1000.0) > tol.length(1.0)
    True
    """

    length_rel: float = 1e-9
    length_abs: float = 1e-12
    angle: float = 1e-9

    def length(self, scale: _S) -> _S:
        """Length tolerance for a figure whose size is ``scale`` (a number or an array)."""
        return self.length_abs + self.length_rel * abs(scale)


DEFAULT_TOL = Tolerance()


# --- verdicts on computed values -------------------------------------------------------
#
# A sign, a sense, a branch or a verdict (self-locking, a toggle, cw/ccw) taken on a value
# that is round-off of its scale differs between machines: the last digits of sin, hypot
# or a linear solve are not the same on every CPU.  Such decisions go through these
# helpers, with the scale of the quantity (the largest value of its kind in the problem).

VERDICT_REL = 1e-9
"""A computed value within this fraction of its scale is zero for every verdict."""


def is_zero(x: float, scale: float, rel: float = VERDICT_REL) -> bool:
    """True when ``x`` is round-off of ``scale``: no verdict may be taken on its sign.

    Parameters
    ----------
    x : float
        The computed value (a component, a rate, a moment).
    scale : float
        The size of its kind in the problem: the largest force of a force analysis,
        the largest velocity of a posture, the size of the mechanism.
    rel : float
        Relative threshold (default :data:`VERDICT_REL`).

    Examples
    --------
    >>> is_zero(1e-17, 1.0), is_zero(1e-3, 1.0), is_zero(0.0, 0.0)
    (True, False, True)
    """
    return bool(abs(x) <= rel * abs(scale)) or x == 0.0


def sign(x: float, scale: float, rel: float = VERDICT_REL) -> int:
    """The sign of ``x`` (-1, 0 or 1), 0 when ``x`` is round-off of ``scale``.

    Examples
    --------
    >>> sign(-2.0, 1.0), sign(3e-18, 1.0), sign(1e-6, 1.0)
    (-1, 0, 1)
    """
    if is_zero(x, scale, rel):
        return 0
    return 1 if x > 0 else -1


def first_largest(values: NDArray[np.float64] | list[float], rel: float = VERDICT_REL,
                  periodic: bool = False) -> int:
    """The index of the first value within round-off of the largest (non-finite ones skipped).

    Two equal maxima (a symmetric cam program's |y''| at Θ = 0° and 180°)
    differ only by round-off, which differs between machines: ``np.argmax``
    would pick either.  The first of those within ``rel`` of the largest value's
    magnitude is the one reported, on every machine.

    Examples
    --------
    >>> first_largest([1.0, 3.0 - 1e-15, 2.0, 3.0]), first_largest([1.0, 2.0, 3.0])
    (1, 2)
    >>> first_largest([float("nan"), -2.0, -1.0])
    2

    ``periodic`` (values over one turn): a stretch of equal largest values that
    runs on past the end into the start is reported at its own start.

    >>> first_largest([3.0, 1.0, 2.0, 3.0, 3.0], periodic=True)
    3
    """
    v = np.asarray(values, dtype=float).reshape(-1)
    ok = np.isfinite(v)
    if not np.any(ok):
        return 0
    top = float(np.max(v[ok]))
    at = ok & (v >= top - rel * abs(top))
    i = int(np.flatnonzero(at)[0])
    if periodic and i == 0 and at[-1] and not np.all(at):
        i = int(np.flatnonzero(~at)[-1]) + 1   # the wrapped stretch starts after the last gap
    return i


__all__ += ["VERDICT_REL", "first_largest", "is_zero", "sign"]
