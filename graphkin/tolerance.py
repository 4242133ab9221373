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
