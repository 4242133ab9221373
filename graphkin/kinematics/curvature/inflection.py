"""The inflection pole J, the pole velocity and the center of acceleration (Secs. 4.12-4.15)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from graphkin.kinematics.curvature._vec import _xy
from graphkin.kinematics.solution import perp

__all__ = ["inflection_pole", "pole_velocity", "acceleration_center"]

Array = np.ndarray


def inflection_pole(pole: ArrayLike, pole_acceleration: ArrayLike, omega: ArrayLike) -> Array:
    """``J = I + A_I/ω²``: the point of the link at ``I`` accelerates toward ``J`` (Eqs. 4.46-4.47).

    Examples
    --------
    >>> inflection_pole([1.0, 0.0], [0.0, 8.0], 2.0)
    array([1., 2.])

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.15, Eqs. 4.46-4.47.
    """
    w = np.asarray(omega, dtype=float)
    return _xy(pole) + np.asarray(pole_acceleration, dtype=float) / (w**2)[..., None]


def pole_velocity(pole: ArrayLike, inflection_pole: ArrayLike, omega: ArrayLike) -> Array:
    """The pole velocity ``v = ω k × R_JI``: ``|v| = ω R_JI`` (Eq. 4.47), along the tangent T.

    Examples
    --------
    A wheel of radius 1 rolling to the right turns clockwise (``ω = -2``); its
    contact point moves with the wheel's center, at 2 to the right.

    >>> pole_velocity([0, 0], [0, 1], -2.0)
    array([2., 0.])

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.15, Eq. 4.47.
    """
    w = np.asarray(omega, dtype=float)
    return w[..., None] * perp(_xy(inflection_pole) - _xy(pole)) + 0.0


def acceleration_center(point: ArrayLike, acceleration: ArrayLike, omega: ArrayLike,
                        alpha: ArrayLike) -> Array:
    """The instantaneous center of acceleration Γ from one point's acceleration.

    ``A_A = ω² R_ΓA R̂_ΓA - α R_ΓA (k × R̂_ΓA)`` (Sec. 4.14, Eq. b) solved for
    ``Γ``: ``Γ = A + (ω² A_A + α k × A_A)/(ω⁴ + α²)``; ``|R_ΓA| = A_A/√(ω⁴ + α²)``
    (Eq. 4.45) and the angle of Eq. 4.44, ``γ = tan⁻¹(α/ω²)``.

    Examples
    --------
    A wheel turning about the origin at ω = 1: the point (2, 0) accelerates
    toward the origin, which is Γ.

    >>> acceleration_center([2.0, 0.0], [-2.0, 0.0], 1.0, 0.0)
    array([0., 0.])

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.14, Eqs. 4.44-4.45.
    """
    a = np.asarray(acceleration, dtype=float)
    w, al = np.asarray(omega, dtype=float), np.asarray(alpha, dtype=float)
    w2 = w * w
    den = (w2 * w2 + al * al)[..., None]
    return _xy(point) + (w2[..., None] * a + al[..., None] * perp(a)) / den
