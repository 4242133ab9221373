"""The operations a construction step may perform, by name.

Each operation takes the arrays named by the step's ``inputs`` (any common
leading shape), the step's ``params`` and a tolerance, and returns a tuple of
arrays, one per output.  They are thin wrappers over :mod:`graphkin.geometry.ops`;
none of them loops over postures.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (cases 1-4), 3.4-3.5 and 4.2-4.3
(velocity and acceleration polygons and images).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

__all__ = ["OPS", "op", "OUTPUT_KIND"]

Array = np.ndarray
OPS: dict[str, Callable[..., tuple[Array, ...]]] = {}
OUTPUT_KIND: dict[str, str] = {}


def op(name: str, kind: str = "point") -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Register an operation under ``name``; ``kind`` is the kind of its outputs."""

    def deco(f: Callable[..., Any]) -> Callable[..., Any]:
        OPS[name] = f
        OUTPUT_KIND[name] = kind
        return f

    return deco


@op("point")
def _point(*, tol: Tolerance, xy: tuple[float, float]) -> tuple[Array]:
    """A fixed point given by its coordinates (a frame pivot)."""
    return (g.point(*xy),)


@op("ideal_point")
def _ideal(*, tol: Tolerance, direction: tuple[float, float]) -> tuple[Array]:
    """A fixed point at infinity."""
    return (g.ideal_point(*direction),)


@op("rigid")
def _rigid(p: Array, theta: Array, *, tol: Tolerance, local_p: tuple[float, float],
           local_q: tuple[float, float], offset: float = 0.0) -> tuple[Array]:
    """Lay off a link: ``Q = P + R(θ + offset)(q - p)`` (case 1: magnitude and direction known)."""
    d = np.subtract(local_q, local_p)
    v = g.rotate(d, np.asarray(theta) + offset)
    return (g.translate(p, v),)


@op("similar")
def _similar(a: Array, b: Array, *, tol: Tolerance, local_a: tuple[float, float],
             local_b: tuple[float, float], local_p: tuple[float, float]) -> tuple[Array]:
    """The image of a point similar to its link (placement, velocity and acceleration images)."""
    return (g.similar_point(a, b, local_a, local_b, local_p),)


@op("link_angle", kind="scalar")
def _link_angle(a: Array, b: Array, *, tol: Tolerance, local_a: tuple[float, float],
                local_b: tuple[float, float]) -> tuple[Array]:
    """Angle of a link's x axis from two of its placed points."""
    d = g.xy(b) - g.xy(a)
    dl = np.subtract(local_b, local_a)
    return (np.arctan2(d[..., 1], d[..., 0]) - np.arctan2(dl[1], dl[0]),)


@op("add_angle", kind="scalar")
def _add_angle(theta: Array, *, tol: Tolerance, offset: float) -> tuple[Array]:
    """An angle that differs from a known one by a constant (a slider keeps its angle)."""
    return (np.asarray(theta) + offset,)


@op("circle", kind="circle")
def _circle(center: Array, *, tol: Tolerance, radius: float) -> tuple[Array]:
    """Draw a circle of known radius about a point."""
    return (g.circle(center, radius),)


@op("circle_on_diameter", kind="circle")
def _thales(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """The circle on the diameter PQ (Thales: every point sees PQ at a right angle)."""
    return (g.circle(g.midpoint(p, q), g.distance(p, q) / 2),)


@op("intersect_circles")
def _cc(c1: Array, c2: Array, *, tol: Tolerance, branch: str) -> tuple[Array]:
    """Intersect two arcs (case 4) and keep the named branch."""
    left, right = g.intersect_circles(c1, c2, tol)
    return (left if branch == "left" else right,)


@op("intersect_line_circle")
def _lc(line: Array, c: Array, *, tol: Tolerance, branch: str) -> tuple[Array]:
    """Intersect a line and an arc (case 2) and keep the named branch."""
    behind, ahead = g.intersect_line_circle(line, c, tol)
    return (behind if branch == "behind" else ahead,)


@op("join", kind="line")
def _join(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """Draw the line through two points."""
    return (g.join(p, q, tol),)


@op("meet")
def _meet(l1: Array, l2: Array, *, tol: Tolerance) -> tuple[Array]:
    """Intersect two lines (case 3); the result may be a point at infinity."""
    return (g.meet(l1, l2, tol),)


@op("line_at_angle", kind="line")
def _line_at_angle(p: Array, theta: Array, *, tol: Tolerance, offset: float = 0.0) -> tuple[Array]:
    """The line through P at the angle θ + offset."""
    t = np.asarray(theta) + offset
    return (g.line_through(p, g.vector(np.cos(t), np.sin(t))),)


@op("parallel", kind="line")
def _parallel(line: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """Through P draw a line parallel to a given line."""
    return (g.parallel(line, p),)


@op("perpendicular", kind="line")
def _perpendicular(line: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """Through P draw a line perpendicular to a given line."""
    return (g.perpendicular(line, p),)


@op("translate")
def _translate(p: Array, v: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off a known vector from a point (case 1)."""
    return (g.translate(p, v),)


@op("vector", kind="vector")
def _vector(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """The vector from P to Q."""
    return (g.xy(q) - g.xy(p),)


@op("scale_vector", kind="vector")
def _scale_vector(v: Array, s: Array, *, tol: Tolerance, factor: float = 1.0) -> tuple[Array]:
    """A vector times a scalar (and a constant factor)."""
    return (np.asarray(v) * (np.asarray(s) * factor)[..., None],)


@op("input", kind="scalar")
def _input(*, tol: Tolerance, name: str) -> tuple[Array]:  # pragma: no cover - never called
    """A given input (a drive angle or travel): its value is supplied at evaluation."""
    raise KeyError(name)


@op("scalar", kind="scalar")
def _scalar(*, tol: Tolerance, value: float) -> tuple[Array]:
    """A constant (the frame's angle)."""
    return (np.asarray(float(value)),)


@op("along_line")
def _along_line(p0: Array, p1: Array, s: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off the travel ``s`` from P0 toward P1 (a slider's given position)."""
    a, b = g.xy(p0), g.xy(p1)
    d = b - a
    n = np.hypot(d[..., 0], d[..., 1])
    q = a + d * (np.asarray(s) / n)[..., None]
    return (g.point(q[..., 0], q[..., 1]),)


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
    r = g.xy(c) - g.xy(p)
    v = g.xy(img_c) - g.xy(img_p)
    return (-(g.dot2(v, v) / g.dot2(r, r))[..., None] * r,)


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
    r = g.xy(center) - g.xy(s)
    v = g.xy(img_s) - g.xy(img_sk)
    return ((g.dot2(v, v) / g.dot2(r, r))[..., None] * r,)


@op("add_along")
def _add_along(p: Array, p0: Array, p1: Array, s: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off a known amount ``s`` along the direction P0 → P1 from a point."""
    d = g.xy(p1) - g.xy(p0)
    n = np.hypot(d[..., 0], d[..., 1])
    return (g.translate(p, d * (np.asarray(s) / n)[..., None]),)


@op("subtract")
def _subtract(p: Array, v: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off a known vector backward from a point (vector subtraction)."""
    return (g.translate(p, -np.asarray(v)),)


@op("rolling_normal", kind="vector")
def _rolling_normal(c: Array, center: Array, omega_i: Array, omega_j: Array, *,
                    tol: Tolerance) -> tuple[Array]:
    """Rolling-contact component ``A^r`` of a circle rolling on a line (Eq. 4.19).

    The contact point of the circle, seen from the link it rolls on, has the
    acceleration ``ρ ω_rel²`` toward the circle's center, normal to the surfaces.
    """
    r = g.xy(center) - g.xy(c)
    w = (np.asarray(omega_i) - np.asarray(omega_j))[..., None]
    return (w**2 * r,)


@op("tangent_foot")
def _tangent_foot(p: Array, s: Array, *, tol: Tolerance, offset: float,
                  branch: str) -> tuple[Array]:
    """The foot T of the perpendicular from P to a tangent from S to the circle (P, d).

    T is where the circle of radius ``d = offset`` about P meets Thales' circle
    on the diameter PS.  Evaluated in closed form, ``T = P + (d²/D) ŝ ± (d t/D) k × ŝ``
    with ``D = |PS|``, ``ŝ`` the unit vector P → S and ``t = √(D² − d²)`` (the
    tangent's length), which stays accurate when the path passes close to P.
    ``left``/``right`` follow :class:`~graphkin.construction.Side` for the
    directed line P → S.
    """
    a, b = g.xy(p), g.xy(s)
    v = b - a
    dist = np.hypot(v[..., 0], v[..., 1])
    d = float(offset)
    with np.errstate(invalid="ignore", divide="ignore"):
        t = np.sqrt(np.where(dist >= d, (dist - d) * (dist + d), np.nan))
        u = v / dist[..., None]
    nrm = np.stack([-u[..., 1], u[..., 0]], axis=-1)
    sign = 1.0 if branch == "left" else -1.0
    q = a + (d * d / dist)[..., None] * u + sign * (d * t / dist)[..., None] * nrm
    return (g.point(q[..., 0], q[..., 1]),)


@op("angle_along", kind="scalar")
def _angle_along(t: Array, s: Array, *, tol: Tolerance, local_angle: float,
                 sign: float) -> tuple[Array]:
    """Angle of a link whose line runs from T through S (``sign`` −1: from S through T).

    ``θ = ∠(sign · (S − T)) − local_angle``, the line's direction in the link.
    """
    v = (g.xy(s) - g.xy(t)) * sign
    return (np.arctan2(v[..., 1], v[..., 0]) - local_angle,)
