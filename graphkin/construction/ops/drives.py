"""Operations for the inputs that are not a link's own angle or travel (Sec. 5.4, P5.7, P5.13).

* ``add_angles``: the angle of a link laid off from another link's angle by
  a joint angle, ``θ3 = θ2 + θ3/2`` (a robot's joint motor, Problems
  5.7-5.11); the same sum holds for the rates, ``ω3 = ω2 + ω3/2`` and
  ``α3 = α2 + α3/2``, in plane motion.
* ``point_xy``: a point at given coordinates (the pantograph's tracing
  point, Problem 5.13), or its velocity or acceleration image from the
  given components, laid off from the pole.
* ``roll_circle_angle``: the angle of a gear rolling on a circle, both
  centers on one link (a planet on its arm, gears on fixed centers): the
  no-slip condition integrated on the covering (Sec. 2.19, Sec. 7.15).
* ``planetary_arm``: the arm of a planet between a first and a last gear
  (a driven sun, a fixed ring), the train formula integrated (Eq. 7.25).
* ``coordinate_line``: the line ``x = s`` (or ``y = s``) on which a point
  with one given coordinate lies; in a polygon, the line on which the
  image of that point lies when one component of its velocity or
  acceleration is given.
"""

from __future__ import annotations

import numpy as np

from graphkin.construction.ops.registry import op
from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

Array = np.ndarray


@op("add_angles", kind="scalar")
def _add_angles(a: Array, b: Array, *, tol: Tolerance, sign: float = 1.0) -> tuple[Array]:
    """``a + sign·b``: an angle (or angular rate) laid off from another by a joint's own."""
    return (np.asarray(a, dtype=float) + sign * np.asarray(b, dtype=float),)


@op("point_xy")
def _point_xy(x: Array, y: Array, *, tol: Tolerance) -> tuple[Array]:
    """The point (x, y): a point at given coordinates, or an image from given components."""
    return (g.point(x, y),)


@op("coordinate_line", kind="line")
def _coordinate_line(s: Array, *, tol: Tolerance, axis: str) -> tuple[Array]:
    """The line ``x = s`` (directed +y) or ``y = s`` (directed +x)."""
    s = np.asarray(s, dtype=float)
    zero = np.zeros_like(s)
    if axis == "x":
        return (g.line_through(g.point(s, zero), np.array([0.0, 1.0])),)
    return (g.line_through(g.point(zero, s), np.array([1.0, 0.0])),)


@op("roll_angle", kind="scalar")
def _roll_angle(theta_on: Array, center: Array, l0: Array, l1: Array, *, tol: Tolerance,
                c: float, k: float) -> tuple[Array]:
    """The angle of a circle rolling on a line without slip: ``θ_l = θ_o + c - k s``.

    ``s = u·(P - L0)`` is the travel of the circle's center ``P`` along the
    line ``L0 L1`` (``u`` its unit direction), ``k = σ/ρ`` (``σ = +1`` for a
    circle on the left of the directed line, ``ρ`` its radius) and ``c`` the
    constant of the file's posture: no slip, ``ω_l - ω_o = -σ ṡ/ρ`` (Eq.
    3.13), integrated (Sec. 2.19, Eq. b; Example 3.9).
    """
    p, a, b = g.xy(center), g.xy(l0), g.xy(l1)
    u = b - a
    n = np.hypot(u[..., 0], u[..., 1])
    s = ((p[..., 0] - a[..., 0]) * u[..., 0] + (p[..., 1] - a[..., 1]) * u[..., 1]) / n
    return (np.asarray(theta_on, dtype=float) + c - k * s,)


@op("roll_circle_angle", kind="scalar")
def _roll_circle_angle(theta: Array, theta_m: Array, *, tol: Tolerance, k: float, beta: float,
                       c: float, solve: str) -> tuple[Array]:
    """The angle of a gear rolling on a circle without slip, both centers on one link ``m``.

    A circle of link ``l`` (radius ``r``) rolls on a circle of link ``o``
    (radius ``R``); both centers are points of a link ``m`` (the arm of a
    planetary train, or the frame for gears on fixed centers), so the line
    of centers stands at ``ψ = θ_m + β``.  No slip, ``ω_l - ω_o = k (ω_m -
    ω_o)`` with ``k = (R + r)/r`` outside and ``-(R - r)/r`` inside (Eq.
    3.13; Sec. 7.15, Eq. 7.25 for the arm), integrated on the covering
    (Sec. 2.19)::

        θ_l = θ_o + k (θ_m + β - θ_o) + c.

    The angles are those of the covering (not taken modulo 2π): with the
    input counted on continuously, ``θ_l`` turns on continuously past 2π.
    ``solve = "rolling"`` gives ``θ_l`` from ``theta = θ_o``;
    ``solve = "on"`` gives ``θ_o`` from ``theta = θ_l`` (``k ≠ 1`` since
    ``R > 0``).
    """
    t = np.asarray(theta, dtype=float)
    m = np.asarray(theta_m, dtype=float) + beta
    if solve == "rolling":
        return (t + k * (m - t) + c,)
    return ((t - k * m - c) / (1.0 - k),)


@op("planetary_arm", kind="scalar")
def _planetary_arm(theta_f: Array, theta_l: Array, *, tol: Tolerance, u: float, v: float,
                   w: float) -> tuple[Array]:
    """The arm of a planet meshing with a first and a last gear: ``θ_A = u θ_F + v θ_L + w``.

    The two contacts' no-slip conditions on the covering, ``θ_p`` eliminated:
    the train formula ``(ω_L - ω_A)/(ω_F - ω_A) = e`` (Sec. 7.15, Eq. 7.25)
    integrated, with the constants of the file's posture in ``w``.
    """
    return (u * np.asarray(theta_f, dtype=float) + v * np.asarray(theta_l, dtype=float) + w,)
