"""Array helpers shared by the curvature modules (any leading shape)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from graphkin.geometry import ops as g

Array = np.ndarray

# ---------------------------------------------------------------------------
# closed forms (any leading shape)
# ---------------------------------------------------------------------------

def _xy(p: ArrayLike) -> Array:
    p = np.asarray(p, dtype=float)
    return g.xy(p) if p.shape[-1] == 3 else p


def _dot(u: Array, v: Array) -> Array:
    return u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1]


def _cross(u: Array, v: Array) -> Array:
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def _unit(v: Array) -> Array:
    return v / float(np.hypot(*v))


def _sin_angle(u: Array, v: Array) -> float:
    nu, nv = float(np.hypot(*u)), float(np.hypot(*v))
    if nu == 0.0 or nv == 0.0:
        return 0.0
    return abs(float(_cross(u, v))) / (nu * nv)
