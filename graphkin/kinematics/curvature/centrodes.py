"""The curvatures of the fixed and moving centrodes (Sec. 4.17, Eqs. 4.40 and 4.56)."""

from __future__ import annotations

import math

__all__ = ["centrode_radii"]


def centrode_radii(inflection_diameter: float, M: float) -> tuple[float, float]:
    """Signed radii ``R_IO_M``, ``R_IO_F`` of the moving and fixed centrodes (Eqs. 4.56, 4.40).

    ``1/R_IO_M = 1/R_JI - 3/M`` (Eq. 4.56) and ``1/R_IO_F = 1/R_JI + 1/R_IO_M``
    (Eq. 4.40 for the point ``J``, whose conjugate is at infinity).  Both are
    ``I - O`` measured along the positive centrode normal: positive when the
    center lies on the side of ``I`` away from ``J``.  ``inf`` for a straight
    centrode.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12 and 4.17, Eqs. 4.40, 4.56.

    Examples
    --------
    Example 4.16 with the sign of ``R_JI`` put right (see the module notes):

    >>> import numpy as np
    >>> [round(r, 6) for r in centrode_radii(2 * np.sqrt(2.0), -2 * np.sqrt(2.0))]
    [0.707107, 0.565685]
    """
    d = float(inflection_diameter)
    km = 1.0 / d - (0.0 if math.isinf(M) else 3.0 / M)
    rm = math.inf if km == 0.0 else 1.0 / km
    kf = 1.0 / d + km
    rf = math.inf if kf == 0.0 else 1.0 / kf
    return float(rm), float(rf)
