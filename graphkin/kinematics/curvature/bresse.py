"""The Bresse circle and the center of acceleration Γ (Secs. 4.14-4.15, Eq. 4.48)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from graphkin.kinematics.curvature._vec import _xy
from graphkin.kinematics.solution import perp

__all__ = ["bresse_pole"]

Array = np.ndarray


def bresse_pole(pole: ArrayLike, inflection_pole: ArrayLike, omega: ArrayLike,
                alpha: ArrayLike) -> Array:
    """The far end ``E`` of the Bresse circle's diameter through ``I``.

    The Bresse circle (the points with no tangential acceleration) has the
    diameter ``b = R_JI ω²/α`` (Eq. 4.48) along the centrode tangent:
    ``E = I + (ω²/α) k × R_JI``, on the negative side of ``T`` when ``α > 0``.
    NaN (no circle: it becomes the centrode normal) when ``α = 0``.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.15, Eq. 4.48, Fig. 4.34.

    Examples
    --------
    >>> bresse_pole([0, 0], [0, 2], 1.0, 0.5)
    array([-4.,  0.])
    """
    w, al = np.asarray(omega, dtype=float), np.asarray(alpha, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        k = np.where(al == 0.0, np.nan, w**2 / np.where(al == 0.0, 1.0, al))
        out = _xy(pole) + k[..., None] * perp(_xy(inflection_pole) - _xy(pole))
    return np.where(np.isfinite(out), out, np.nan)
