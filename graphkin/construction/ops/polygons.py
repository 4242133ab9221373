"""Operations of the velocity and acceleration polygons and images (Secs. 3.4-3.5, 4.2-4.3)."""

from __future__ import annotations

import numpy as np

from graphkin.construction.ops.registry import op
from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

Array = np.ndarray


@op("image")
def _image(a: Array, b: Array, img_a: Array, img_b: Array, p: Array, *,
           tol: Tolerance) -> tuple[Array]:
    """Image of a point of a link from its position: the triangle abp is similar to ABP.

    Mehmke's theorem (Sec. 3.5, 4.3): ``p' = a' + (b' - a') (P - A) / (B - A)``.
    """
    za, zb, zp = g.xy(a), g.xy(b), g.xy(p)
    return (g.similar_point(img_a, img_b, za, zb, zp),)

# ---- velocity and acceleration polygons (images are points of the polygon's plane) ----

@op("velocity_difference")
def _velocity_difference(img_a: Array, omega: Array, a: Array, x: Array, *,
                         tol: Tolerance) -> tuple[Array]:
    """Case 1: ``V_X = V_A + ω × R_XA`` (Eq. 3.4); the image of X from the image of A."""
    r = g.xy(x) - g.xy(a)
    w = np.asarray(omega)[..., None]
    return (g.translate(img_a, w * np.stack([-r[..., 1], r[..., 0]], axis=-1)),)


@op("acceleration_difference")
def _acceleration_difference(img_a: Array, omega: Array, alpha: Array, a: Array, x: Array, *,
                             tol: Tolerance) -> tuple[Array]:
    """Case 1: ``A_X = A_A + α × R_XA − ω² R_XA`` (Eq. 4.5)."""
    r = g.xy(x) - g.xy(a)
    w = np.asarray(omega)[..., None]
    al = np.asarray(alpha)[..., None]
    return (g.translate(img_a, al * np.stack([-r[..., 1], r[..., 0]], axis=-1) - w**2 * r),)


@op("angular_rate", kind="scalar")
def _angular_rate(a: Array, b: Array, img_a: Array, img_b: Array, *,
                  tol: Tolerance) -> tuple[Array]:
    """ω (or α) of a link from two of its points and their images.

    ``ω = (R_BA × V_BA)/R_BA²``: the length of the image line over the link
    line, with the sense from the image's turn (Sec. 3.4).  For accelerations
    the normal component is along R_BA and drops out, leaving α (Sec. 4.3).
    """
    r = g.xy(b) - g.xy(a)
    v = g.xy(img_b) - g.xy(img_a)
    return (g.cross2(r, v) / g.dot2(r, r),)


@op("normal_component", kind="vector")
def _normal_component(p: Array, c: Array, img_p: Array, img_c: Array, *,
                      tol: Tolerance) -> tuple[Array]:
    """``A_CP^n = −(V_CP²/R_CP) R̂_CP``: toward P, of length V²/R (Eq. 4.7)."""
    r, k = _squared_ratio(p, c, img_p, img_c)
    return (-k[..., None] * r,)


def _squared_ratio(p: Array, c: Array, img_p: Array, img_c: Array) -> tuple[Array, Array]:
    """``R = C - P`` and ``|V|² / |R|²`` with ``V`` the image difference ``c − p``."""
    r = g.xy(c) - g.xy(p)
    v = g.xy(img_c) - g.xy(img_p)
    return r, g.dot2(v, v) / g.dot2(r, r)


@op("coriolis", kind="vector")
def _coriolis(omega: Array, img_p: Array, img_pk: Array, *, tol: Tolerance) -> tuple[Array]:
    """Coriolis component ``2 ω × V_rel`` (Eq. 4.15), with ω of the link that carries the path."""
    v = g.xy(img_p) - g.xy(img_pk)
    w = np.asarray(omega)[..., None]
    return (2 * w * np.stack([-v[..., 1], v[..., 0]], axis=-1),)


@op("apparent_normal", kind="vector")
def _apparent_normal(s: Array, center: Array, img_s: Array, img_sk: Array, *,
                     tol: Tolerance) -> tuple[Array]:
    """Apparent normal component ``V_rel²/ρ`` toward the path's center of curvature (Eq. 4.15)."""
    r, k = _squared_ratio(s, center, img_sk, img_s)
    return (k[..., None] * r,)


@op("rolling_normal", kind="vector")
def _rolling_normal(c: Array, center: Array, omega_i: Array, omega_j: Array, *,
                    tol: Tolerance, factor: float = 1.0) -> tuple[Array]:
    """Rolling-contact component ``A^r`` (Eq. 4.19), normal to the surfaces.

    The contact point of a circle of radius ρ, seen from the link it rolls on,
    has the acceleration ``factor · ρ ω_rel²`` toward the circle's center:
    ``factor`` is 1 on a line and ``R/(R ± ρ)`` on a circle of radius R
    (outside / inside).
    """
    r = g.xy(center) - g.xy(c)
    w = (np.asarray(omega_i) - np.asarray(omega_j))[..., None]
    return (factor * w**2 * r,)


@op("equal_velocity_point")
def _equal_velocity_point(p_i: Array, img_i: Array, omega_i: Array, p_j: Array, img_j: Array,
                          omega_j: Array, *, tol: Tolerance, scale: float = 1.0) -> tuple[Array]:
    """The instant center ``Iij`` from the velocities: where links i and j move alike.

    Each link is given by one of its points ``P``, that point's image in the
    velocity polygon and the link's ω (the frame: any point, the pole ``o_v``
    and ω = 0).  The velocity of link k's point at ``X`` is
    ``V_k(X) = V_Pk + ω_k k × (X - P_k)`` (Eq. 3.4); with ``u_k = V_Pk - ω_k k ×
    P_k`` both are equal where ``(ω_i - ω_j) k × X = u_j - u_i``, so ``Iij`` is
    the homogeneous point ``(k × (u_i - u_j), ω_i - ω_j)``: at infinity,
    perpendicular to the relative velocity, when ``ω_i = ω_j`` (Sec. 3.12;
    Sec. 5.4 for the speed-dependent centers of two inputs).  The pole cancels
    from ``u_i - u_j``.  ``scale`` (the mechanism's size) makes the decision
    "at infinity" an angle, as for the meet of two lines; no relative motion
    at all gives NaN.
    """
    wi = np.asarray(omega_i, dtype=float)
    wj = np.asarray(omega_j, dtype=float)
    pi, pj = g.xy(p_i), g.xy(p_j)
    du = (g.xy(img_i) - g.xy(img_j)
          - wi[..., None] * np.stack([-pi[..., 1], pi[..., 0]], axis=-1)
          + wj[..., None] * np.stack([-pj[..., 1], pj[..., 0]], axis=-1))
    h = np.concatenate([np.stack([-du[..., 1], du[..., 0]], axis=-1) / scale,
                        (wi - wj)[..., None]], axis=-1)
    p = g.normalize_point(h, tol)
    return (np.where(g.is_ideal(p)[..., None], p, p * np.array([scale, scale, 1.0])),)
