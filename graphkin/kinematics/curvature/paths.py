"""Path curvature of a point from its velocity and acceleration (Sec. 4.12)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from graphkin.kinematics.curvature._vec import _cross, _dot
from graphkin.kinematics.solution import perp
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["path_curvature", "PathCurvature"]

Array = np.ndarray


def path_curvature(position: ArrayLike, velocity: ArrayLike, acceleration: ArrayLike,
                   tol: Tolerance | None = None) -> tuple[Array, Array]:
    """Radius and center of curvature of a path from a point's velocity and acceleration.

    ``ρ = V²/A^n`` (Eq. 4.49), the center on the side the normal acceleration
    points to.  Radius ``inf`` and center NaN where the path is straight here
    (``V × A = 0``); both NaN where the point is at rest.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.16, Eq. 4.49.

    Examples
    --------
    >>> path_curvature([2.0, 0.0], [0.0, 2.0], [-2.0, 0.0])
    (array(2.), array([0., 0.]))
    """
    tol = tol or DEFAULT_TOL
    p = np.asarray(position, dtype=float)
    v, a = np.asarray(velocity, dtype=float), np.asarray(acceleration, dtype=float)
    v2 = _dot(v, v)
    c = _cross(v, a)
    va = np.sqrt(v2) * np.hypot(a[..., 0], a[..., 1])
    straight = np.abs(c) <= tol.angle * va
    rest = v2 == 0.0
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        k = np.where(straight, np.nan, v2 / np.where(straight, 1.0, c))
        # a normal acceleration so small that V²/A^n overflows: straight here
        straight = straight | ~np.isfinite(np.where(straight, 0.0, k))
        k = np.where(straight, np.nan, k)
        center = p + k[..., None] * perp(v)
        rho = np.where(straight, np.inf, np.abs(k) * np.sqrt(v2))
    rho = np.where(rest, np.nan, rho)
    center = np.where((rest | straight)[..., None], np.nan, center)
    return rho, center


@dataclass
class PathCurvature:
    """Radius and center of curvature of a named point's absolute path.

    Attributes
    ----------
    name : str
    link : str or None
        The link whose curvature theory gave it (``None``: from its velocity
        and acceleration, Eq. 4.49, because no link carrying it turns).
    radius : float or None
        ``None`` where the path is straight here or the point is at rest.
    center : ndarray or None
    how : str
        How the center was found: ``"inspection"``, ``"bobillier"``,
        ``"hartmann"``, ``"euler-savary"``, ``"pivot"``, ``"velocity-acceleration"``
        (Eq. 4.49); or ``"straight"``, ``"at rest"``.
    """

    name: str
    link: str | None
    radius: float | None
    center: Array | None
    how: str
