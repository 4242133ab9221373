"""The construction operations the cam layout adds: I24 on a line of centers, the normal through it.

Registered in the operations' table (:data:`graphkin.construction.ops.OPS`)
when :mod:`graphkin.cams` is imported.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.17 (the angular-velocity-ratio
theorem), Sec. 6.10 (I24 of Fig. 6.27).
"""

from __future__ import annotations

import numpy as np

from graphkin.construction.ops.registry import op
from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

Array = np.ndarray


@op("ratio_point")
def _ratio_point(p: Array, q: Array, k: Array, *, tol: Tolerance,
                 factor: float = 1.0) -> tuple[Array]:
    """The instant center I24 on the line of centers O2 O4 of two turning links.

    With ``k = factor·k_in = ω4/ω2``, the point X of both links with one
    velocity satisfies ``ω2 (X − P) = ω4 (X − Q)``, so ``X = (P − kQ)/(1 − k)``
    (the angular-velocity-ratio theorem).  It is kept as the homogeneous point
    ``(P − kQ, 1 − k)`` *as written* (not scaled to ``w = 1``): at infinity
    when ``ω4 = ω2``, and its sign tells :func:`_along_normal` which way the cam lies.
    """
    kk = factor * np.asarray(k, dtype=float)
    a, b = g.xy(p), g.xy(q)
    num = a - kk[..., None] * b
    return (np.concatenate([num, (1.0 - kk)[..., None]], axis=-1),)


@op("along_normal")
def _along_normal(t: Array, x: Array, *, tol: Tolerance, distance: float) -> tuple[Array]:
    """The point at ``distance`` from T on the line from T toward the point X = (x, y, w).

    The direction is ``(x, y) − w·T``: toward X when X is finite with ``w > 0``,
    along X's direction when X is at infinity, so that the common normal
    through an instant center I24 of :func:`_ratio_point` keeps pointing into
    the cam as I24 passes through infinity (the follower turning with the cam).
    """
    tt = g.xy(t)
    x = np.asarray(x, dtype=float)
    d = x[..., :2] - x[..., 2:3] * tt
    n = np.hypot(d[..., 0], d[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        q = tt + d * (distance / n)[..., None]
    return (g.point(q[..., 0], q[..., 1]),)
