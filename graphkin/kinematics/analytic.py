"""The independent analytic solver: the oracle every graphic construction is checked against.

Each moving link ``k`` gets three generalized coordinates ``q = (x_k, y_k, θ_k)``:
where its local origin is and the direction of its own x axis.  A point with
local coordinates ``p`` is then at ``P = o_k + R(θ_k) p``.  Every joint of the
mechanism file becomes scalar constraint equations ``Φ(q) = 0`` (the
loop-closure equations of Sec. 2.7 written link by link, as in the
"relative coordinates" form of Sec. 2.9), the drives add one equation each,
and the posture is found by damped Newton-Raphson (Levenberg-Marquardt, then
plain Newton to polish).  Velocities and accelerations follow by one linear
solve each (Secs. 3.9 and 4.9, the algebraic velocity and acceleration
analyses)::

    Φ_q q̇ = -Φ_t,        Φ_q q̈ = -(Φ_q q̇)_q q̇ - Φ_tt.

Nothing here uses the graphic constructions (``graphkin.construction``,
``graphkin.geometry``): it is a second, independent route to the same numbers.

The constraint rows
-------------------
With ``perp(v) = k × v`` (``(-v_y, v_x)``), for a body point
``P = o + R(θ) p`` we have ``∂P/∂o = I``, ``∂P/∂θ = perp(R p)`` and

    ``dP/dt = ȯ + ω perp(R p)``,
    ``d²P/dt² = ö + α perp(R p) - ω² R p``          (Eqs. 3.4 and 4.5).

The last term, ``-ω² R p``, is the only part of a point's acceleration that
is *not* linear in ``q̈``: it is the point's contribution to the quadratic
velocity terms ``γ = (Φ_q q̇)_q q̇`` that go to the right-hand side.

* **Pin** (a point name shared by links ``a`` and ``b``):
  ``P_a - P_b = 0`` (two rows).  ``γ = -ω_a² R_a p_a + ω_b² R_b p_b``.
* **Point on a line of link** ``o`` (slider, straight slot, slider drive):
  ``f = v·(P - L0)`` with ``v = R_o v_loc`` a unit vector fixed in ``o``
  (the line's normal ``n`` for "on the line", its direction ``u`` for the
  travel of a slider drive) and ``L0 = o_o + R_o l0`` its first point.
  Writing ``r = P - L0``, ``v̇ = ω_o perp(v)`` and
  ``v̈ = α_o perp(v) - ω_o² v``, so

      ``f̈ = v̈·r + 2 v̇·ṙ + v·r̈``

  whose part free of second derivatives is
  ``γ = -ω_o² v·r + 2 ω_o perp(v)·ṙ + v·(-ω_s² R_s p_s + ω_o² R_o l0)``
  (the middle term is the Coriolis term of Sec. 4.5).
* **Slider angle** (the slider cannot turn relative to ``on``):
  ``θ_s - θ_o - φ = 0`` with ``φ`` the line's angle in ``on``'s coordinates;
  linear, ``γ = 0``.  A revolute drive ``θ_k - value = 0`` likewise.
* **Circular slot** (centre ``c`` fixed in ``o``, radius ``ρ``):
  ``f = (|r|² - ρ²) / (2ρ)`` with ``r = P - C``; ``ḟ = r·ṙ/ρ``,
  ``f̈ = (ṙ·ṙ + r·r̈)/ρ`` so ``γ = (ṙ·ṙ + r·(-ω_s² R_s p_s + ω_o² R_o c))/ρ``.
* **Rolling contact without slip** (``[[rolling]]``: a circle of radius
  ``ρ`` of link ``l`` on a line of link ``o``).  The contact is the
  equivalent slot of the center (among the slots, as the parser gives it);
  no slip adds ``g = (θ_l - θ_o) + σ s/ρ - c`` with ``s = u·(P - L0)`` the
  travel of the center along the line in ``o``'s coordinates (``σ = +1``
  when the circle lies on the left of the line, -1 on the right): an angle
  row plus ``σ/ρ`` times a travel row, so ``γ = σ/ρ γ_travel``.  At the
  file's drive the posture row is ``θ_l - angle = 0`` instead (the rolling
  link stands at the file's angle); over a sweep it is ``g`` with ``c``
  taken from the file's posture.  See :class:`_Rolling` for the derivation.
* **Rolling contact on a circle** (a circle of radius ``r`` of link ``l``
  on a circle of radius ``R`` of link ``o``, center ``O`` fixed in ``o``:
  gears).  The center distance is the equivalent circular slot of radius
  ``R + r`` (outside) or ``R - r`` (inside), unless one link already holds
  both centers (a planet on its arm: then no slot).  No slip adds
  ``g = (θ_l - θ_o) - k φ - c`` with ``φ`` the angle of ``P - O`` in
  ``o``'s axes and ``k = (R + r)/r`` (outside) or ``-(R - r)/r`` (inside),
  so ``γ = -k γ_φ``; the posture rows are as for a line.  See
  :class:`_RollingCircle`.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 2.7 (loop-closure equations), Secs. 2.9-2.11 (algebraic posture
analysis), Sec. 2.19 (apparent angular displacement: the rolling
constraint), Sec. 3.7 (rolling contact, Eq. 3.13), Sec. 3.9 (algebraic
velocity analysis), Sec. 3.11 and Sec. 4.11 (kinematic coefficients; Example
3.9, a wheel rolling on the ground), Sec. 4.5 (Coriolis), Sec. 4.7 (Eq.
4.19), Sec. 4.9 (algebraic acceleration analysis).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from graphkin.errors import AssemblyError, ConstructionError
from graphkin.kinematics.solution import LinkState, Solution
from graphkin.mechanisms.model import FRAME, Drive, Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["solve_analytic", "solve_analytic_many"]

Guess = Mapping[str, tuple[float, float, float]]

_TWO_PI = 2.0 * math.pi

#: Scaled residual below which Levenberg-Marquardt hands over to plain Newton.
_LM_DONE = 1e-8
#: Iteration limits of the two stages.
_LM_ITER = 200
_NEWTON_ITER = 12
#: Every this many iterations, a residual that fell by less than _STALL_RATIO while
#: still above _STALL_FAR (scaled) means a local minimum of |Φ|: that start fails.
_STALL_EVERY = 10
_STALL_RATIO = 0.9
_STALL_FAR = 1e-3
#: Iteration limit when continuing from the previous posture of a sweep.
_SWEEP_ITER = 60
#: Number of deterministic pseudo-random restarts when no guess is given.
_RESTARTS = 40
#: Restarts at the later postures of a sweep whose first postures do not assemble.
_SWEEP_RESTARTS = 6
#: Largest drive step (rad, and fraction of the size) when a sweep of a mechanism
#: with rolling contact is continued from the file's posture to its first value.
_MARCH_ANGLE = math.radians(2.0)
_MARCH_LENGTH = 0.02
#: Seed of those restarts: the search is deterministic.
_SEED = 20240611
#: Two converged postures are the same when every scaled coordinate agrees to this.
_SAME_POSTURE = 1e-6
#: A hint score within this fraction of the size² of the best is a tie (and a
#: score this small means the hints are met exactly).
_TIE = 1e-12


def _wrap(a: float) -> float:
    """An angle in (-π, π]."""
    w = math.remainder(a, _TWO_PI)
    return math.pi if w == -math.pi else w


def _wrap_array(a: np.ndarray) -> np.ndarray:
    w = np.remainder(a + math.pi, _TWO_PI) - math.pi
    return np.where(w <= -math.pi, w + _TWO_PI, w)


# ---------------------------------------------------------------------------
# Poses: the state of every link at one q (plain floats: the systems are small)
# ---------------------------------------------------------------------------


class _Poses:
    """Origins and rotations of every link at one ``q`` (the frame at rest)."""

    __slots__ = ("x", "y", "c", "s", "th")

    def __init__(self, q: np.ndarray, nlinks: int) -> None:
        qq = q.tolist()
        self.x = [qq[3 * k] for k in range(nlinks)] + [0.0]
        self.y = [qq[3 * k + 1] for k in range(nlinks)] + [0.0]
        self.th = [qq[3 * k + 2] for k in range(nlinks)] + [0.0]
        self.c = [math.cos(t) for t in self.th]
        self.s = [math.sin(t) for t in self.th]

    def rot(self, k: int, p: tuple[float, float]) -> tuple[float, float]:
        """``R_k p``: a local vector turned into world axes."""
        c, s = self.c[k], self.s[k]
        return (c * p[0] - s * p[1], s * p[0] + c * p[1])

    def world(self, k: int, p: tuple[float, float]) -> tuple[float, float]:
        """``o_k + R_k p``."""
        rx, ry = self.rot(k, p)
        return (self.x[k] + rx, self.y[k] + ry)


# A link index of -1 is the frame (its entries sit at the end of the _Poses lists).
_F = -1


@dataclass(frozen=True)
class _Pin:
    """Point ``p_a`` of link ``a`` and ``p_b`` of link ``b`` coincide (two length rows)."""

    a: int
    pa: tuple[float, float]
    b: int
    pb: tuple[float, float]
    label: str
    kinds: tuple[str, ...] = ("L", "L")

    def eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        pa, pb = st.world(self.a, self.pa), st.world(self.b, self.pb)
        if J is not None:
            for k, sign, p in ((self.a, 1.0, self.pa), (self.b, -1.0, self.pb)):
                if k == _F:
                    continue
                rx, ry = st.rot(k, p)
                J[row, 3 * k] += sign
                J[row + 1, 3 * k + 1] += sign
                J[row, 3 * k + 2] += -sign * ry
                J[row + 1, 3 * k + 2] += sign * rx
        return [pa[0] - pb[0], pa[1] - pb[1]]

    def gamma(self, st: _Poses, qd: Sequence[float]) -> list[float]:
        # γ = -ω_a² R_a p_a + ω_b² R_b p_b
        wa = qd[3 * self.a + 2] if self.a != _F else 0.0
        wb = qd[3 * self.b + 2] if self.b != _F else 0.0
        ra, rb = st.rot(self.a, self.pa), st.rot(self.b, self.pb)
        return [-wa * wa * ra[0] + wb * wb * rb[0], -wa * wa * ra[1] + wb * wb * rb[1]]


@dataclass(frozen=True)
class _OnLine:
    """``f = v·(P - L0)``: point ``p`` of link ``s`` against a line fixed in link ``o``.

    ``v_loc`` is the unit normal of the line (point on the line) or its unit
    direction (travel along the line, for a slider drive), in ``o``'s axes.
    """

    s: int
    p: tuple[float, float]
    o: int
    l0: tuple[float, float]
    v_loc: tuple[float, float]
    label: str
    kinds: tuple[str, ...] = ("L",)

    def eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        P = st.world(self.s, self.p)
        L0 = st.world(self.o, self.l0)
        vx, vy = st.rot(self.o, self.v_loc)
        rx, ry = P[0] - L0[0], P[1] - L0[1]
        if J is not None:
            if self.s != _F:
                qx, qy = st.rot(self.s, self.p)
                J[row, 3 * self.s] += vx
                J[row, 3 * self.s + 1] += vy
                J[row, 3 * self.s + 2] += vx * -qy + vy * qx
            if self.o != _F:
                lx, ly = st.rot(self.o, self.l0)
                J[row, 3 * self.o] -= vx
                J[row, 3 * self.o + 1] -= vy
                # ∂f/∂θ_o = perp(v)·r - v·perp(R_o l0)
                J[row, 3 * self.o + 2] += (-vy * rx + vx * ry) - (vx * -ly + vy * lx)
        return [vx * rx + vy * ry]

    def gamma(self, st: _Poses, qd: Sequence[float]) -> list[float]:
        # γ = -ω_o² v·r + 2 ω_o perp(v)·ṙ + v·(-ω_s² R_s p + ω_o² R_o l0)
        ws = qd[3 * self.s + 2] if self.s != _F else 0.0
        wo = qd[3 * self.o + 2] if self.o != _F else 0.0
        P = st.world(self.s, self.p)
        L0 = st.world(self.o, self.l0)
        vx, vy = st.rot(self.o, self.v_loc)
        rx, ry = P[0] - L0[0], P[1] - L0[1]
        px, py = st.rot(self.s, self.p)
        lx, ly = st.rot(self.o, self.l0)
        vs = (qd[3 * self.s] if self.s != _F else 0.0, qd[3 * self.s + 1] if self.s != _F else 0.0)
        vo = (qd[3 * self.o] if self.o != _F else 0.0, qd[3 * self.o + 1] if self.o != _F else 0.0)
        # ṙ = (ȯ_s + ω_s perp(R_s p)) - (ȯ_o + ω_o perp(R_o l0))
        rdx = vs[0] - ws * py - (vo[0] - wo * ly)
        rdy = vs[1] + ws * px - (vo[1] + wo * lx)
        g = -wo * wo * (vx * rx + vy * ry)
        g += 2.0 * wo * (-vy * rdx + vx * rdy)
        g += vx * (-ws * ws * px + wo * wo * lx) + vy * (-ws * ws * py + wo * wo * ly)
        return [g]


@dataclass(frozen=True)
class _Angle:
    """``θ_a - θ_b - c = 0`` (an angle row, residual wrapped to (-π, π])."""

    a: int
    b: int
    c: float
    label: str
    kinds: tuple[str, ...] = ("A",)

    def eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        if J is not None:
            if self.a != _F:
                J[row, 3 * self.a + 2] += 1.0
            if self.b != _F:
                J[row, 3 * self.b + 2] -= 1.0
        return [st.th[self.a] - st.th[self.b] - self.c]

    def gamma(self, st: _Poses, qd: Sequence[float]) -> list[float]:
        return [0.0]


@dataclass(frozen=True)
class _OnCircle:
    """``f = (|P - C|² - ρ²) / (2ρ)``: point ``p`` of ``s`` on a circle fixed in ``o``."""

    s: int
    p: tuple[float, float]
    o: int
    center: tuple[float, float]
    radius: float
    label: str
    kinds: tuple[str, ...] = ("L",)

    def eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        P = st.world(self.s, self.p)
        C = st.world(self.o, self.center)
        rx, ry = P[0] - C[0], P[1] - C[1]
        rho = self.radius
        if J is not None:
            gx, gy = rx / rho, ry / rho
            if self.s != _F:
                qx, qy = st.rot(self.s, self.p)
                J[row, 3 * self.s] += gx
                J[row, 3 * self.s + 1] += gy
                J[row, 3 * self.s + 2] += gx * -qy + gy * qx
            if self.o != _F:
                cx, cy = st.rot(self.o, self.center)
                J[row, 3 * self.o] -= gx
                J[row, 3 * self.o + 1] -= gy
                J[row, 3 * self.o + 2] -= gx * -cy + gy * cx
        return [(rx * rx + ry * ry - rho * rho) / (2.0 * rho)]

    def gamma(self, st: _Poses, qd: Sequence[float]) -> list[float]:
        # γ = (ṙ·ṙ + r·(-ω_s² R_s p + ω_o² R_o c)) / ρ
        ws = qd[3 * self.s + 2] if self.s != _F else 0.0
        wo = qd[3 * self.o + 2] if self.o != _F else 0.0
        P = st.world(self.s, self.p)
        C = st.world(self.o, self.center)
        rx, ry = P[0] - C[0], P[1] - C[1]
        px, py = st.rot(self.s, self.p)
        cx, cy = st.rot(self.o, self.center)
        vs = (qd[3 * self.s] if self.s != _F else 0.0, qd[3 * self.s + 1] if self.s != _F else 0.0)
        vo = (qd[3 * self.o] if self.o != _F else 0.0, qd[3 * self.o + 1] if self.o != _F else 0.0)
        rdx = vs[0] - ws * py - (vo[0] - wo * cy)
        rdy = vs[1] + ws * px - (vo[1] + wo * cx)
        g = rdx * rdx + rdy * rdy
        g += rx * (-ws * ws * px + wo * wo * cx) + ry * (-ws * ws * py + wo * wo * cy)
        return [g / self.radius]


@dataclass(frozen=True)
class _Rolling:
    """No slip between a circle of link ``l`` and a line of link ``o`` (one angle row).

    Derivation.  Let ``u = R_o u_loc`` be the line's unit direction, ``n =
    σ perp(u)`` its unit normal toward the center ``P`` (``σ = +1`` for a
    circle on the left of the directed line, -1 on the right), ``ρ`` the
    radius, and ``C = P - ρ n`` the contact point.  No slip (Eq. 3.13) says
    ``V_C(l) = V_C(o)``.  With ``V_C(k) = V_P(k) + ω_k perp(C - P)`` and
    ``C - P = -ρ n``::

        V_P - V_{P∈o} = ρ (ω_l - ω_o) perp(n) = -σ ρ (ω_l - ω_o) u,

    since ``perp(n) = σ perp(perp(u)) = -σ u``.  The left side is the
    apparent velocity of the center seen from ``o``; along ``u`` it is
    ``ṡ``, the rate of ``s = u·(P - L0)`` (``L0`` the line's first point
    fixed in ``o``): indeed ``ṡ = u̇·(P - L0) + u·(V_P - V_L0)`` with
    ``u̇ = ω_o perp(u)``, and ``V_{P∈o} = V_L0 + ω_o perp(P - L0)`` gives
    ``u·V_{P∈o} = u·V_L0 - u̇·(P - L0)``.  Hence

        ``ω_l - ω_o = -σ ṡ / ρ``,

    the derivative of the holonomic condition (Sec. 2.19, Eq. b; Example
    3.9, Eq. 5)

        ``g(q) = (θ_l - θ_o) + σ s/ρ - c = 0``

    (``c`` a constant).  Its Jacobian row is that of the angle row
    ``θ_l - θ_o`` plus ``σ/ρ`` times that of the travel row ``s`` (an
    :class:`_OnLine` with ``v = u``); its acceleration row is
    ``α_l - α_o + σ s̈/ρ = 0``, so ``γ = (σ/ρ) γ_s``.  Written out,
    ``s̈ = ü·(P - L0) + 2 u̇·(V_P - V_L0) + u·(A_P - A_L0)`` with
    ``ü = α_o perp(u) - ω_o² u``; collecting terms with
    ``A_{P∈o} = A_L0 + α_o perp(P - L0) - ω_o² (P - L0)`` and
    ``V_rel = V_P - V_{P∈o}``,

        ``s̈ = u·(A_P - A_{P∈o} - 2 ω_o perp(V_rel))``,

    the apparent tangential acceleration, Coriolis term included (it
    vanishes along ``u`` here, since ``V_rel`` is along ``u``).

    Posture rows.  With ``ref`` None (one posture at the file's drive) the
    posture row is ``θ_l - angle = 0``: at its own drive the file gives the
    rolling link's angle.  With ``ref = c`` (a sweep) it is ``g`` itself,
    the integrated no-slip condition through the file's posture.  The rate
    rows are ``g``'s in both cases (:meth:`rate_eval`).
    """

    link: int
    on: int
    travel: _OnLine
    sigma: float
    radius: float
    angle: float
    ref: float | None
    label: str
    kinds: tuple[str, ...] = ("A",)

    def value(self, st: _Poses) -> float:
        """``(θ_l - θ_o) + σ s/ρ`` at a posture (not wrapped)."""
        s = self.travel.eval(st, None, 0)[0]
        return st.th[self.link] - st.th[self.on] + self.sigma * s / self.radius

    def rate_eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        """``g + c`` and its Jacobian row (the no-slip row of the rates)."""
        if J is not None:
            if self.link != _F:
                J[row, 3 * self.link + 2] += 1.0
            if self.on != _F:
                J[row, 3 * self.on + 2] -= 1.0
            tmp = np.zeros((1, J.shape[1]))
            self.travel.eval(st, tmp, 0)
            J[row] += (self.sigma / self.radius) * tmp[0]
        return [self.value(st)]

    def eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        if self.ref is None:
            if J is not None and self.link != _F:
                J[row, 3 * self.link + 2] += 1.0
            return [st.th[self.link] - self.angle]
        return [self.rate_eval(st, J, row)[0] - self.ref]

    def gamma(self, st: _Poses, qd: Sequence[float]) -> list[float]:
        return [self.sigma / self.radius * self.travel.gamma(st, qd)[0]]


@dataclass
class _RollingCircle:
    """No slip between a circle of link ``l`` and a circle of link ``o`` (one angle row).

    Derivation.  Let ``P`` be the rolling circle's center (radius ``r``),
    ``O`` the center of ``o``'s circle (radius ``R``, fixed in ``o``),
    ``d = P - O`` and ``d̂ = d/|d|``.  The circles touch at ``C = O + R d̂``
    with ``|d| = R + κ r`` (``κ = +1`` outside, external gears; ``κ = -1``
    inside, a planet in a ring), so ``C - P = (R - |d|) d̂ = -κ r d̂``.  No
    slip (Eq. 3.13) says ``V_C(l) = V_C(o)``, with
    ``V_C(k) = V_P(k) + ω_k perp(C - P)``::

        V_P - V_{P∈o} = κ r (ω_l - ω_o) perp(d̂).

    The left side is the apparent velocity of the center seen from ``o``.
    Write ``d = |d| (cos(φ + θ_o), sin(φ + θ_o))``, ``φ`` the angle of ``d``
    in ``o``'s axes; ``|d|`` is constant (the slot, or the link that holds
    both centers), ``V_P = V_O + ḋ`` with ``ḋ = |d| (φ̇ + ω_o) perp(d̂)``, and
    ``V_{P∈o} = V_O + ω_o perp(d)``, so ``V_P - V_{P∈o} = |d| φ̇ perp(d̂)``.
    Hence

        ``ω_l - ω_o = κ |d| φ̇ / r = k φ̇``,  ``k = κ (R + κ r)/r``:

    ``(R + r)/r · φ̇`` outside, ``-(R - r)/r · φ̇`` inside (a planet carried
    round a fixed sun turns ``(R + r)/r`` times as fast as its arm; round
    inside a fixed ring, ``(R - r)/r`` times as fast the other way).  It is
    the derivative of the holonomic condition (Sec. 2.19)

        ``g(q) = (θ_l - θ_o) - k φ - c = 0``

    (``c`` a constant; ``φ = atan2(d) - θ_o`` taken continuously, see
    below).  With ``ψ = atan2(d_y, d_x)``, ``∂ψ/∂d = perp(d)/|d|²``, and
    ``∂d/∂q`` that of two body points (``P`` of ``l`` minus ``O`` of ``o``),
    its Jacobian row is the angle row ``θ_l - θ_o`` minus ``k`` times
    ``∂ψ/∂q - ∂θ_o/∂q``.  Its acceleration row: ``ψ̇ = (d × ḋ)/|d|²``, so

        ``ψ̈ = (d × d̈)/|d|² - 2 (d × ḋ)(d · ḋ)/|d|⁴``

    and with ``d̈ = (linear in q̈) - ω_l² R_l p + ω_o² R_o c_o`` (``p``,
    ``c_o`` the local coordinates of ``P`` and ``O``)
    ``γ_ψ = (d × (-ω_l² R_l p + ω_o² R_o c_o))/|d|² - 2 (d × ḋ)(d · ḋ)/|d|⁴``
    and ``γ = -k γ_ψ``.  The contact point of ``l`` then has no apparent
    tangential acceleration and the normal one ``ω_rel² r R/(R + κ r)``
    toward ``P`` (Eq. 4.19 for two circles).

    Posture rows as for :class:`_Rolling`: with ``ref`` None (the file's
    drive) ``θ_l - angle = 0``; with ``ref = c`` (a sweep) ``g``.  ``φ`` is
    an angle on a covering: ``k φ`` with ``k`` not an integer is not a
    function of ``φ`` modulo 2π, so ``φ`` is counted on from ``anchor``
    (``anchor + wrap(atan2(d) - θ_o - anchor)``), and a sweep moves the
    anchor to each posture it accepts (:meth:`_System.follow`): the steps
    between postures turn ``φ`` by far less than π.
    """

    link: int
    on: int
    p: tuple[float, float]
    oc: tuple[float, float]
    ratio: float
    angle: float
    ref: float | None
    label: str
    kinds: tuple[str, ...] = ("A",)
    anchor: float | None = None

    def _d(self, st: _Poses) -> tuple[float, float]:
        px, py = st.world(self.link, self.p)
        ox, oy = st.world(self.on, self.oc)
        return px - ox, py - oy

    def phi(self, st: _Poses) -> float:
        """``φ``, the angle of ``P - O`` in ``o``'s axes, counted on from the anchor."""
        dx, dy = self._d(st)
        raw = math.atan2(dy, dx) - st.th[self.on]
        if self.anchor is None:
            return _wrap(raw)
        return self.anchor + _wrap(raw - self.anchor)

    def value(self, st: _Poses) -> float:
        """``(θ_l - θ_o) - k φ`` at a posture (not wrapped)."""
        return st.th[self.link] - st.th[self.on] - self.ratio * self.phi(st)

    def rate_eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        """``g + c`` and its Jacobian row (the no-slip row of the rates)."""
        if J is not None:
            k = self.ratio
            dx, dy = self._d(st)
            d2 = dx * dx + dy * dy
            gx, gy = -dy / d2, dx / d2  # ∂ψ/∂d = perp(d)/|d|²
            if self.link != _F:
                px, py = st.rot(self.link, self.p)
                J[row, 3 * self.link] -= k * gx
                J[row, 3 * self.link + 1] -= k * gy
                J[row, 3 * self.link + 2] += 1.0 - k * (gx * -py + gy * px)
            if self.on != _F:
                cx, cy = st.rot(self.on, self.oc)
                J[row, 3 * self.on] += k * gx
                J[row, 3 * self.on + 1] += k * gy
                # -1 - k ∂φ/∂θ_o, with ∂φ/∂θ_o = -∂ψ/∂d·perp(R_o c_o) - 1
                J[row, 3 * self.on + 2] += -1.0 + k * (gx * -cy + gy * cx) + k
        return [self.value(st)]

    def eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        if self.ref is None:
            if J is not None and self.link != _F:
                J[row, 3 * self.link + 2] += 1.0
            return [st.th[self.link] - self.angle]
        return [self.rate_eval(st, J, row)[0] - self.ref]

    def gamma(self, st: _Poses, qd: Sequence[float]) -> list[float]:
        # γ = -k γ_ψ, γ_ψ = (d × d̈_γ)/|d|² - 2 (d × ḋ)(d·ḋ)/|d|⁴
        lk, o = self.link, self.on
        wl = qd[3 * lk + 2] if lk != _F else 0.0
        wo = qd[3 * o + 2] if o != _F else 0.0
        vl = (qd[3 * lk] if lk != _F else 0.0, qd[3 * lk + 1] if lk != _F else 0.0)
        vo = (qd[3 * o] if o != _F else 0.0, qd[3 * o + 1] if o != _F else 0.0)
        dx, dy = self._d(st)
        px, py = st.rot(lk, self.p)
        cx, cy = st.rot(o, self.oc)
        ddx = vl[0] - wl * py - (vo[0] - wo * cy)
        ddy = vl[1] + wl * px - (vo[1] + wo * cx)
        ax = -wl * wl * px + wo * wo * cx
        ay = -wl * wl * py + wo * wo * cy
        d2 = dx * dx + dy * dy
        g_psi = (dx * ay - dy * ax) / d2 \
            - 2.0 * (dx * ddy - dy * ddx) * (dx * ddx + dy * ddy) / (d2 * d2)
        return [-self.ratio * g_psi]


_Constraint = _Pin | _OnLine | _Angle | _OnCircle | _Rolling | _RollingCircle


# ---------------------------------------------------------------------------
# The system of equations of one mechanism
# ---------------------------------------------------------------------------


class _System:
    """Constraint, drive and rate equations of a mechanism in ``q``."""

    def __init__(self, mech: Mechanism, tol: Tolerance,
                 rolling_ref: Sequence[float] | None = None) -> None:
        self.mech = mech
        self.tol = tol
        self.ids = list(mech.moving)
        self.index = {lid: k for k, lid in enumerate(self.ids)}
        self.index[FRAME] = _F
        self.nlinks = len(self.ids)
        self.n = 3 * self.nlinks
        self.size = float(mech.scale)
        self.cons: list[_Constraint] = []
        for pin in mech.pins:
            first = pin.links[0]
            for other in pin.links[1:]:
                self.cons.append(_Pin(self.index[first], mech.links[first].points[pin.name],
                                      self.index[other], mech.links[other].points[pin.name],
                                      f"pin {pin.name} (links {first} and {other})"))
        for sl in mech.sliders:
            u, n = _unit(sl.p0, sl.p1)
            s, o = self.index[sl.link], self.index[sl.on]
            p = mech.links[sl.link].points[sl.point]
            self.cons.append(_OnLine(s, p, o, sl.p0, n,
                                     f"{sl.key} (point {sl.point} of link {sl.link} on link "
                                     f"{sl.on})"))
            self.cons.append(_Angle(s, o, sl.direction_angle,
                                    f"{sl.key} (link {sl.link} parallel to its line)"))
        for sk in mech.slots:
            s, o = self.index[sk.link], self.index[sk.on]
            p = mech.links[sk.link].points[sk.point]
            lab = f"{sk.key} (point {sk.point} of link {sk.link} in the slot of link {sk.on})"
            if sk.is_line:
                assert sk.p0 is not None and sk.p1 is not None
                _, n = _unit(sk.p0, sk.p1)
                self.cons.append(_OnLine(s, p, o, sk.p0, n, lab))
            else:
                assert sk.center is not None and sk.radius is not None
                self.cons.append(_OnCircle(s, p, o, sk.center, float(sk.radius), lab))
        # rolling: the contact is the equivalent slot above; no slip is one more row
        self.rolling_fixed = rolling_ref is None
        for i, ro in enumerate(mech.rolling):
            s, o = self.index[ro.link], self.index[ro.on]
            p = mech.links[ro.link].points[ro.center]
            lab = f"{ro.key} (link {ro.link} rolls on link {ro.on} without slip)"
            ref = None if rolling_ref is None else float(rolling_ref[i])
            if ro.p0 is None or ro.p1 is None:
                assert ro.on_center is not None and ro.on_radius is not None
                rad, big = float(ro.radius), float(ro.on_radius)
                ratio = (big + rad) / rad if ro.contact == "outside" else -(big - rad) / rad
                self.cons.append(_RollingCircle(s, o, p, ro.on_center, ratio, float(ro.angle),
                                                ref, lab))
                continue
            u, _ = _unit(ro.p0, ro.p1)
            travel = _OnLine(s, p, o, ro.p0, u, lab)
            sigma = 1.0 if ro.side == "left" else -1.0
            self.cons.append(_Rolling(s, o, travel, sigma, float(ro.radius), float(ro.angle),
                                      ref, lab))
        self.drives: list[_Constraint] = [self._drive_function(d) for d in mech.drives]
        self.values = np.array([d.value for d in mech.drives], dtype=float)
        kinds: list[str] = []
        for c in [*self.cons, *self.drives]:
            kinds.extend(c.kinds)
        self.kinds = kinds
        self.m = len(kinds)
        self.ncons = self.m - len(self.drives)
        # scaling: length rows and x, y columns in units of the mechanism's size
        self.row_scale = np.array([1.0 / self.size if k == "L" else 1.0 for k in kinds])
        self.col_scale = np.tile([self.size, self.size, 1.0], self.nlinks)
        self.angle_rows = np.array([k == "A" for k in kinds])
        rates = self._rates()
        self.rate_functions: list[_Constraint] | None = rates[0]
        self.rate_values: list[tuple[float, float]] | None = rates[1]

    # -- the functions that drives and rates prescribe --------------------
    def _drive_function(self, d: Drive) -> _Constraint:
        k = self.index[d.link]
        if d.kind == "angle":
            return _Angle(k, _F, 0.0, f"{d.key} (angle of link {d.link})")
        sl = d.slider
        assert sl is not None
        u, _ = _unit(sl.p0, sl.p1)
        p = self.mech.links[sl.link].points[sl.point]
        return _OnLine(self.index[sl.link], p, self.index[sl.on], sl.p0, u,
                       f"{d.key} (travel of point {sl.point} of link {sl.link})")

    def _rates(self) -> tuple[list[_Constraint], list[tuple[float, float]]] | tuple[None, None]:
        """The functions ``g(q)`` whose rates are known, and (ġ, g̈)."""
        mech = self.mech
        if not mech.has_rates:
            return None, None
        r = mech.rates
        if r is None:
            funcs = list(self.drives)
            vals = [(float(d.rate), float(d.rate2 or 0.0)) for d in mech.drives
                    if d.rate is not None]
            return funcs, vals
        k = self.index[r.link]
        if r.kind == "angle":
            g: _Constraint = _Angle(k, _F, 0.0, f"rates (ω of link {r.link})")
        else:
            sl = next(s for s in mech.sliders if s.link == r.link)
            u, _ = _unit(sl.p0, sl.p1)
            g = _OnLine(k, mech.links[sl.link].points[sl.point], self.index[sl.on], sl.p0, u,
                        f"rates (travel of point {sl.point} of link {sl.link})")
        assert r.rate is not None
        return [g], [(float(r.rate), float(r.rate2 or 0.0))]

    # -- evaluation --------------------------------------------------------
    def residual(self, q: np.ndarray, values: np.ndarray,
                 jac: bool = True) -> tuple[np.ndarray, np.ndarray | None]:
        """Φ(q) (angle rows wrapped) and, when asked, Φ_q."""
        st = _Poses(q, self.nlinks)
        J = np.zeros((self.m, self.n)) if jac else None
        res: list[float] = []
        row = 0
        for c in self.cons:
            res.extend(c.eval(st, J, row))
            row += len(c.kinds)
        for i, c in enumerate(self.drives):
            res.append(c.eval(st, J, row)[0] - values[i])
            row += 1
        r = np.array(res)
        r[self.angle_rows] = _wrap_array(r[self.angle_rows])
        return r, J

    def scaled(self, q: np.ndarray, values: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Residual and Jacobian in dimensionless form (lengths over the size)."""
        r, J = self.residual(q, values)
        assert J is not None
        return r * self.row_scale, J * self.row_scale[:, None] * self.col_scale[None, :]

    # -- the rates --------------------------------------------------------
    def velocity_system(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``A q̇ = b``: the constraint rows of Φ_q and the rows of the known rates."""
        assert self.rate_functions is not None and self.rate_values is not None
        st = _Poses(q, self.nlinks)
        rows = self.ncons + len(self.rate_functions)
        A = np.zeros((rows, self.n))
        row = 0
        for c in self.cons:
            (c.rate_eval if isinstance(c, (_Rolling, _RollingCircle)) else c.eval)(st, A, row)
            row += len(c.kinds)
        for g in self.rate_functions:
            g.eval(st, A, row)
            row += 1
        b = np.zeros(rows)
        b[self.ncons:] = [v for v, _ in self.rate_values]
        return A, b

    def acceleration_rhs(self, q: np.ndarray, qd: np.ndarray) -> np.ndarray:
        """``-γ`` for the constraint rows, ``g̈ - γ_g`` for the rate rows."""
        assert self.rate_functions is not None and self.rate_values is not None
        st = _Poses(q, self.nlinks)
        qdl = qd.tolist()
        out: list[float] = []
        for c in self.cons:
            out.extend(-g for g in c.gamma(st, qdl))
        for g, (_, acc) in zip(self.rate_functions, self.rate_values):
            out.append(acc - g.gamma(st, qdl)[0])
        return np.array(out)

    # -- rolling contact ----------------------------------------------------
    def rolling_constants(self, q: np.ndarray) -> list[float]:
        """``c`` of every rolling contact at posture ``q``.

        ``(θ_l - θ_o) + σ s/ρ`` on a line, ``(θ_l - θ_o) - k φ`` on a circle.
        """
        st = _Poses(q, self.nlinks)
        return [c.value(st) for c in self.cons if isinstance(c, (_Rolling, _RollingCircle))]

    def follow(self, q: np.ndarray) -> None:
        """Count the ``φ`` of every rolling contact on a circle on from posture ``q``."""
        st = _Poses(q, self.nlinks)
        for c in self.cons:
            if isinstance(c, _RollingCircle):
                c.anchor = c.phi(st)

    def integrated(self, q: np.ndarray) -> _System:
        """The same system with the integrated no-slip rows through posture ``q``.

        Its Jacobian is the true constraint Jacobian of the mechanism (the
        one of the rates); without rolling contact it is ``self``.  The ``φ``
        of a contact on a circle is counted on from ``q`` (as ``self`` counts it).
        """
        if not self.mech.rolling:
            return self
        out = _System(self.mech, self.tol, self.rolling_constants(q))
        st = _Poses(q, self.nlinks)
        for mine, new in zip(self.cons, out.cons):
            if isinstance(mine, _RollingCircle) and isinstance(new, _RollingCircle):
                new.anchor = mine.phi(st)
        return out

    # -- output -------------------------------------------------------------
    def pose_of(self, q: np.ndarray, lid: str) -> tuple[float, float, float]:
        k = self.index[lid]
        if k == _F:
            return (0.0, 0.0, 0.0)
        return (float(q[3 * k]), float(q[3 * k + 1]), float(q[3 * k + 2]))


def _unit(p0: tuple[float, float], p1: tuple[float, float]) -> tuple[tuple[float, float],
                                                                     tuple[float, float]]:
    """Unit direction ``u`` from ``p0`` to ``p1`` and its normal ``n = perp(u)``."""
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    d = math.hypot(dx, dy)
    u = (dx / d, dy / d)
    return u, (-u[1], u[0])


# ---------------------------------------------------------------------------
# Newton-Raphson with damping
# ---------------------------------------------------------------------------


def _converge(eqs: _System, q0: np.ndarray, values: np.ndarray,
              max_iter: int = _LM_ITER) -> np.ndarray | None:
    """Solve Φ(q) = 0 from ``q0``: Levenberg-Marquardt, then Newton polishing.

    Returns the converged ``q`` (angles wrapped to (-π, π]) or None.
    """
    accept = eqs.tol.length_rel * 1e-2
    with np.errstate(all="ignore"):
        q = np.array(q0, dtype=float)
        cs = eqs.col_scale
        try:
            r, J = eqs.scaled(q, values)
        except (ValueError, OverflowError):
            return None
        f = float(r @ r)
        A = J.T @ J
        mu = 1e-3 * max(float(np.max(np.diag(A))), 1e-12)
        nu = 2.0
        f_before = f
        for it in range(max_iter):
            if not math.isfinite(f):
                return None
            if math.sqrt(f) < _LM_DONE:
                break
            if it and it % _STALL_EVERY == 0:
                # stalled far from any solution: a local minimum of |Φ|, give up
                if f > _STALL_RATIO * f_before and f > _STALL_FAR**2:
                    return None
                f_before = f
            g = J.T @ r
            try:
                step = np.linalg.solve(A + mu * np.eye(eqs.n), -g)
            except np.linalg.LinAlgError:
                mu *= nu
                nu *= 2.0
                continue
            big = float(np.max(np.abs(step)))
            if big > 1.0:  # a trust region of one size (or one radian) per step
                step /= big
            q_new = q + step * cs
            try:
                r_new, J_new = eqs.scaled(q_new, values)
            except (ValueError, OverflowError):
                return None
            f_new = float(r_new @ r_new)
            predicted = float(step @ (mu * step - g))
            rho = (f - f_new) / predicted if predicted > 0 else -1.0
            if math.isfinite(f_new) and rho > 0:
                q, r, J, f = q_new, r_new, J_new, f_new
                A = J.T @ J
                mu *= max(1.0 / 3.0, 1.0 - (2.0 * rho - 1.0) ** 3)
                nu = 2.0
            else:
                mu *= nu
                nu *= 2.0
                if mu > 1e16:
                    return None
        else:
            if math.sqrt(f) >= _LM_DONE:
                return None
        # Newton polishing (quadratic convergence at a regular solution)
        for _ in range(_NEWTON_ITER):
            try:
                step = np.linalg.lstsq(J, -r, rcond=None)[0]
            except np.linalg.LinAlgError:
                break
            q_new = q + step * cs
            try:
                r_new, J_new = eqs.scaled(q_new, values)
            except (ValueError, OverflowError):
                break
            f_new = float(r_new @ r_new)
            if not (math.isfinite(f_new) and f_new < f):
                break
            q, r, J, f = q_new, r_new, J_new, f_new
            if f == 0.0:
                break
        if not math.isfinite(f) or float(np.max(np.abs(r), initial=0.0)) > accept:
            return None
    out = q.copy()
    out[2::3] = _wrap_array(out[2::3])
    return out


# ---------------------------------------------------------------------------
# Starting guesses and the choice among branches
# ---------------------------------------------------------------------------


def _fit_pose(pairs: list[tuple[tuple[float, float], tuple[float, float]]],
              angle: float | None) -> tuple[float, float, float]:
    """Rigid pose taking local points onto world points (least squares, Procrustes)."""
    n = len(pairs)
    lx = sum(p[0][0] for p in pairs) / n
    ly = sum(p[0][1] for p in pairs) / n
    wx = sum(p[1][0] for p in pairs) / n
    wy = sum(p[1][1] for p in pairs) / n
    if angle is None:
        sc = sum((p[0][0] - lx) * (p[1][1] - wy) - (p[0][1] - ly) * (p[1][0] - wx)
                 for p in pairs)
        cc = sum((p[0][0] - lx) * (p[1][0] - wx) + (p[0][1] - ly) * (p[1][1] - wy)
                 for p in pairs)
        angle = math.atan2(sc, cc) if (sc or cc) else 0.0
    c, s = math.cos(angle), math.sin(angle)
    return (wx - (c * lx - s * ly), wy - (s * lx + c * ly), angle)


class _Search:
    """Starting guesses (from the assembly hints and the frame), restarts, and the choice."""

    def __init__(self, eqs: _System) -> None:
        self.eqs = eqs
        mech = eqs.mech
        self.frame_pts = dict(mech.links[FRAME].points)
        self.hints = dict(mech.assembly)
        pts = list(self.frame_pts.values()) + list(self.hints.values())
        if pts:
            self.center = (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))
        else:
            self.center = (0.0, 0.0)

    def heuristic(self, values: np.ndarray, rng: np.random.Generator | None,
                  fixed: Guess | None = None) -> np.ndarray:
        """Place links one by one from what is known: frame points, hints, drive angles.

        With ``rng`` the links that nothing places get random angles and the
        hinted positions are jittered; without, they get angle 0.
        """
        eqs, mech = self.eqs, self.eqs.mech
        size = eqs.size
        known: dict[str, tuple[float, float]] = {}
        for name, xy in self.hints.items():
            if rng is not None:
                xy = (xy[0] + 0.05 * size * rng.standard_normal(),
                      xy[1] + 0.05 * size * rng.standard_normal())
            known[name] = xy
        known.update(self.frame_pts)
        poses: dict[str, tuple[float, float, float]] = {FRAME: (0.0, 0.0, 0.0)}
        if fixed:
            for lid, pose in fixed.items():
                if lid in eqs.index and lid != FRAME:
                    poses[lid] = tuple(float(v) for v in pose)  # type: ignore[assignment]
        angles: dict[str, float] = {}
        for d, v in zip(mech.drives, values):
            if d.kind == "angle":
                angles[d.link] = float(v)
        if eqs.rolling_fixed:  # at the file's drive a rolling link stands at its angle
            for ro in mech.rolling:
                angles.setdefault(ro.link, float(ro.angle))

        def learn(lid: str) -> None:
            x, y, t = poses[lid]
            c, s = math.cos(t), math.sin(t)
            for name, p in mech.links[lid].points.items():
                if name not in known:
                    known[name] = (x + c * p[0] - s * p[1], y + s * p[0] + c * p[1])

        for lid in list(poses):
            learn(lid)
        todo = [lid for lid in eqs.ids if lid not in poses]
        while todo:
            progress = False
            for lid in list(todo):
                angle = angles.get(lid)
                if angle is None:
                    for sl in mech.sliders:
                        if sl.link == lid and sl.on in poses:
                            angle = poses[sl.on][2] + sl.direction_angle
                        elif sl.on == lid and sl.link in poses:
                            angle = poses[sl.link][2] - sl.direction_angle
                pairs = [(p, known[name]) for name, p in mech.links[lid].points.items()
                         if name in known]
                if len(pairs) >= 2 or (pairs and angle is not None):
                    poses[lid] = _fit_pose(pairs, angle)
                    learn(lid)
                    todo.remove(lid)
                    progress = True
            if progress:
                continue
            # nothing can be placed for sure: place the best-known link with a guessed angle
            lid = max(todo, key=lambda k: sum(n in known for n in mech.links[k].points))
            pairs = [(p, known[name]) for name, p in mech.links[lid].points.items()
                     if name in known]
            angle = angles.get(lid)
            if angle is None:
                angle = float(rng.uniform(-math.pi, math.pi)) if rng is not None else 0.0
            if pairs:
                poses[lid] = _fit_pose(pairs[:1], angle)
            else:
                poses[lid] = (self.center[0], self.center[1], angle)
            learn(lid)
            todo.remove(lid)
        q = np.zeros(eqs.n)
        for lid in eqs.ids:
            k = eqs.index[lid]
            q[3 * k:3 * k + 3] = poses[lid]
        return q

    def random(self, values: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """Every link anywhere near the frame, at any angle (drive angles kept)."""
        eqs = self.eqs
        q = np.zeros(eqs.n)
        for k in range(eqs.nlinks):
            q[3 * k] = self.center[0] + eqs.size * rng.uniform(-1.0, 1.0)
            q[3 * k + 1] = self.center[1] + eqs.size * rng.uniform(-1.0, 1.0)
            q[3 * k + 2] = rng.uniform(-math.pi, math.pi)
        for d, v in zip(eqs.mech.drives, values):
            if d.kind == "angle":
                q[3 * eqs.index[d.link] + 2] = v
        if eqs.rolling_fixed:
            for ro in eqs.mech.rolling:
                q[3 * eqs.index[ro.link] + 2] = ro.angle
        return q

    def score(self, q: np.ndarray) -> tuple[float, float]:
        """(distance² to the hints, distance² to the file's own layout)."""
        eqs, mech = self.eqs, self.eqs.mech
        st = _Poses(q, eqs.nlinks)
        hint = 0.0
        for name, (hx, hy) in self.hints.items():
            owners = mech.point_links[name]
            lid = next((o for o in owners if o != FRAME), owners[0])
            px, py = st.world(eqs.index[lid], mech.links[lid].points[name])
            hint += (px - hx) ** 2 + (py - hy) ** 2
        layout = 0.0
        for lid in eqs.ids:
            k = eqs.index[lid]
            for p in mech.links[lid].points.values():
                px, py = st.world(k, p)
                layout += (px - p[0]) ** 2 + (py - p[1]) ** 2
        return hint, layout

    def same(self, q1: np.ndarray, q2: np.ndarray) -> bool:
        d = (q1 - q2) / self.eqs.col_scale
        d[2::3] = _wrap_array(d[2::3])
        return bool(np.max(np.abs(d), initial=0.0) < _SAME_POSTURE)

    def solve(self, values: np.ndarray, restarts: int = _RESTARTS,
              explain: bool = True) -> np.ndarray:
        """Every start, every converged posture; return the one nearest the hints.

        Raises AssemblyError when nothing converges; with ``explain`` its
        message names the constraint that stays open at the best compromise.
        """
        eqs = self.eqs
        rng = np.random.default_rng(_SEED)
        found: list[np.ndarray] = []
        starts: list[Callable[[], np.ndarray]] = [lambda: self.heuristic(values, None)]
        for i in range(restarts):
            if i % 2 == 0:
                starts.append(lambda: self.heuristic(values, rng))
            else:
                starts.append(lambda: self.random(values, rng))
        exact = _TIE * eqs.size**2
        for make in starts:
            q = _converge(eqs, make(), values)
            if q is None or any(self.same(q, f) for f in found):
                continue
            found.append(q)
            if self.hints and self.score(q)[0] <= exact:
                break  # the hints are met exactly: no posture can be nearer
        if not found:
            if not explain:
                raise AssemblyError("cannot assemble the mechanism", key="drive",
                                    file=eqs.mech.source)
            raise _assembly_error(eqs, values, self.best_attempt(values))
        scores = [self.score(q) for q in found]
        best_hint = min(s[0] for s in scores)
        tie = best_hint + _TIE * eqs.size**2 * max(1, len(self.hints))
        candidates = [(s[1], i) for i, s in enumerate(scores) if s[0] <= tie]
        return found[min(candidates)[1]]

    def best_attempt(self, values: np.ndarray) -> np.ndarray:
        """The least-squares compromise of the unsolvable equations (for the message)."""
        q = self.heuristic(values, None)
        with np.errstate(all="ignore"):
            for _ in range(_LM_ITER):
                r, J = self.eqs.scaled(q, values)
                try:
                    step = np.linalg.lstsq(J, -r, rcond=None)[0]
                except np.linalg.LinAlgError:
                    break
                big = float(np.max(np.abs(step), initial=0.0))
                if not math.isfinite(big):
                    break
                q = q + step * self.eqs.col_scale * min(1.0, 0.5 / max(big, 1e-300))
        return q


def _assembly_error(eqs: _System, values: np.ndarray, q: np.ndarray) -> AssemblyError:
    """Name the constraint that stays open at the best compromise."""
    mech = eqs.mech
    what = ", ".join(_drive_text(d, v) for d, v in zip(mech.drives, values))
    reason = "the loop-closure equations have no real solution"
    with np.errstate(all="ignore"):
        r, _ = eqs.residual(q, values, jac=False)
    if np.all(np.isfinite(r)) and r.size:
        row = 0
        worst, worst_label = 0.0, ""
        for c in [*eqs.cons, *eqs.drives]:
            for j, kind in enumerate(c.kinds):
                v = abs(float(r[row + j])) * (1.0 / eqs.size if kind == "L" else 1.0)
                if v > worst:
                    worst, worst_label = v, c.label
            row += len(c.kinds)
        if worst_label:
            reason += f" ({worst_label} cannot be closed)"
    return AssemblyError(f"cannot assemble the mechanism at {what}: {reason}",
                         key="drive", file=mech.source)


def _drive_text(d: Drive, v: float) -> str:
    if d.kind == "angle":
        return f"link {d.link} angle {math.degrees(v):.6g}°"
    return f"link {d.link} position {v:.6g}"


def _check_regular(eqs: _System, q: np.ndarray, values: np.ndarray) -> None:
    """Raise ConstructionError at a singular (toggle, dead-center) posture."""
    _, J = eqs.scaled(q, values)
    if not eqs.n:
        return
    sv = np.linalg.svd(J, compute_uv=False)
    if sv.size < eqs.n or sv[-1] <= _singular_threshold(eqs.tol) * sv[0]:
        what = ", ".join(_drive_text(d, v) for d, v in zip(eqs.mech.drives, values))
        raise ConstructionError(
            f"the posture at {what} is singular (a toggle or dead-center posture: the "
            "Jacobian of the loop-closure equations is rank deficient)",
            key="drive", file=eqs.mech.source)


def _singular_threshold(tol: Tolerance) -> float:
    # a double root found to machine precision leaves σ_min ~ √ε ~ 1e-8; a
    # regular posture this close to a toggle is a singular one for a drawing
    return 100.0 * tol.angle


# ---------------------------------------------------------------------------
# Rates
# ---------------------------------------------------------------------------


def _rates(eqs: _System, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """q̇ and q̈ at a posture (Secs. 3.9 and 4.9)."""
    A, b = eqs.velocity_system(q)
    # dimensionless rows and columns, as for the posture, to judge the rank
    rows = np.concatenate([eqs.row_scale[:eqs.ncons],
                           [1.0 if g.kinds[0] == "A" else 1.0 / eqs.size
                            for g in eqs.rate_functions or []]])
    sv = np.linalg.svd(A * rows[:, None] * eqs.col_scale[None, :], compute_uv=False)
    if A.shape[0] != eqs.n or sv[-1] <= _singular_threshold(eqs.tol) * sv[0]:
        r = eqs.mech.rates
        who = f"the given rate of link {r.link}" if r is not None else "the drive rates"
        raise ConstructionError(f"{who} cannot fix the velocities at this posture (the "
                                "velocity equations are singular)", key="rates",
                                file=eqs.mech.source)
    qd = np.linalg.solve(A, b)
    qdd = np.linalg.solve(A, eqs.acceleration_rhs(q, qd))
    return qd, qdd


# ---------------------------------------------------------------------------
# Building the Solution
# ---------------------------------------------------------------------------


def _solution(eqs: _System, q: np.ndarray, qd: np.ndarray | None, qdd: np.ndarray | None,
              valid: np.ndarray, notes: list[str]) -> Solution:
    """A Solution from stacked coordinates of shape (n,) or (N, n)."""
    lead = q.shape[:-1]
    links: dict[str, LinkState] = {}
    for lid in eqs.mech.links:
        k = eqs.index[lid]
        if k == _F:
            zero = np.zeros(lead)
            zero2 = np.zeros((*lead, 2))
            rated = qd is not None
            links[lid] = LinkState(zero.copy(), zero2.copy(),
                                   zero.copy() if rated else None,
                                   zero.copy() if rated else None,
                                   zero2.copy() if rated else None,
                                   zero2.copy() if rated else None)
            continue
        sl = slice(3 * k, 3 * k + 2)
        th = 3 * k + 2
        links[lid] = LinkState(
            np.array(q[..., th]), np.array(q[..., sl]),
            None if qd is None else np.array(qd[..., th]),
            None if qdd is None else np.array(qdd[..., th]),
            None if qd is None else np.array(qd[..., sl]),
            None if qdd is None else np.array(qdd[..., sl]))
    return Solution(mechanism=eqs.mech, links=links, method="analytic", valid=valid,
                    notes=notes)


def _guess_vector(eqs: _System, guess: Guess | Solution, values: np.ndarray) -> np.ndarray:
    if isinstance(guess, Solution):
        g: dict[str, tuple[float, float, float]] = {}
        for lid in eqs.ids:
            s = guess.links[lid]
            ang = np.asarray(s.angle, dtype=float).reshape(-1)
            org = np.asarray(s.origin, dtype=float).reshape(-1, 2)
            i = 0
            if ang.size > 1:
                ok = np.flatnonzero(np.asarray(guess.valid).reshape(-1))
                i = int(ok[-1]) if ok.size else 0
            g[lid] = (float(org[i, 0]), float(org[i, 1]), float(ang[i]))
        guess = g
    return _Search(eqs).heuristic(values, None, fixed=guess)


def _drive_values(mech: Mechanism) -> np.ndarray:
    return np.array([d.value for d in mech.drives], dtype=float)


def solve_analytic(mech: Mechanism, *, guess: Guess | Solution | None = None,
                   tol: Tolerance | None = None) -> Solution:
    """Solve a mechanism at its posture by Newton-Raphson on the loop-closure equations.

    Parameters
    ----------
    mech : Mechanism
        The mechanism, as read from a mechanism file.
    guess : dict or Solution, optional
        Link id -> ``(x, y, θ)``: the start of the iteration (origin of the
        link's local frame and its angle, rad), or a solved posture of the
        same mechanism.  Newton's method then stays on
        the branch of the guess.  Without a guess the solver starts from the
        assembly hints (``[assembly]``), the frame and the drives, plus
        deterministic pseudo-random restarts, and returns the converged posture
        whose points are nearest the hints (without hints: nearest the file's
        own layout, every link as written).
    tol : Tolerance, optional
        Convergence and singularity tolerances (default
        :data:`~graphkin.tolerance.DEFAULT_TOL`).

    Returns
    -------
    Solution
        ``method="analytic"``; a :class:`LinkState` for every link, the frame
        included.  Rates are present when the file gives them (a missing
        second rate means zero).

    Raises
    ------
    AssemblyError
        No posture satisfies the constraints at the given drive.
    ConstructionError
        The posture is singular (a toggle posture: the Jacobian is rank
        deficient), or the given rates cannot fix the velocities there.

    See Also
    --------
    solve_analytic_many : the same over many drive values, with branch continuity.

    Notes
    -----
    Rolling contact (``[[rolling]]``): the circle's center runs on the line
    offset by the radius, or on the circle of radius ``R + r`` (outside) or
    ``R - r`` (inside) about the center of ``on``'s circle (the equivalent
    slot; none when one link already holds both centers), and at the file's
    drive the rolling link stands at the file's ``angle`` (absolute).  The
    rates obey no slip and its derivative (Eq. 3.13 and 4.19): on a line
    ``ω_l - ω_o = -σ ṡ/ρ`` (``ṡ`` the center's apparent speed along the line
    seen from ``on``, ``σ = +1`` for a circle on the left of the line); on a
    circle ``ω_l - ω_o = (R + r)/r · φ̇`` (outside) or ``-(R - r)/r · φ̇``
    (inside), ``φ`` the angle of the line of centers in ``on``'s axes.  The
    singularity check uses these rows.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.7 (loop-closure equations),
    Secs. 2.9-2.11 (algebraic posture analysis), Sec. 2.19 (rolling
    constraint), Sec. 3.7 (rolling contact), Sec. 3.9 (algebraic velocity
    analysis), Sec. 4.9 (algebraic acceleration analysis), Sec. 4.5
    (Coriolis), Sec. 4.7 (rolling contact acceleration).

    Examples
    --------
    Example 3.1 of the textbook: crank 4 in at 120°, 900 rev/min.

    >>> from graphkin.mechanisms import loads
    >>> mech = loads('''
    ... units = { length = "in" }
    ... [links.1]
    ... A = [0, 0]
    ... D = [10, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [4, 0]
    ... [links.3]
    ... B = [0, 0]
    ... C = [18, 0]
    ... [links.4]
    ... D = [0, 0]
    ... C = [11, 0]
    ... [drive]
    ... link = 2
    ... angle = 120
    ... omega = "900 rev/min"
    ... [assembly]
    ... C = [15, 10]
    ... ''')
    >>> sol = solve_analytic(mech)
    >>> import math
    >>> round(math.degrees(float(sol.angle_rad("3"))), 4), round(float(sol.omega("4")), 3)
    (20.9187, 49.501)
    """
    tol = tol or DEFAULT_TOL
    eqs = _System(mech, tol)
    values = _drive_values(mech)
    if guess is not None:
        q = _converge(eqs, _guess_vector(eqs, guess, values), values)
        if q is None:
            raise AssemblyError(
                "cannot assemble the mechanism at "
                + ", ".join(_drive_text(d, v) for d, v in zip(mech.drives, values))
                + ": Newton's method does not converge from the given guess",
                key="drive", file=mech.source)
        notes = ["analytic: Newton-Raphson from the given guess"]
    else:
        q = _Search(eqs).solve(values)
        notes = ["analytic: Newton-Raphson from the assembly hints, nearest posture chosen"]
    # rolling contact: from here on the no-slip rows (the true constraint Jacobian)
    eqs = eqs.integrated(q)
    _check_regular(eqs, q, values)
    qd = qdd = None
    if eqs.rate_functions is not None:
        qd, qdd = _rates(eqs, q)
    return _solution(eqs, q, qd, qdd, np.array(True), notes)


def solve_analytic_many(mech: Mechanism, drive_values: np.ndarray,
                        start: Solution | Guess | None = None, *,
                        tol: Tolerance | None = None) -> Solution:
    """Solve a mechanism at many drive values, each posture continuing the one before.

    Parameters
    ----------
    mech : Mechanism
        The mechanism; its drives' rates (or ``[rates]``) apply at every posture.
    drive_values : ndarray, shape (N, n_drives) or (N,)
        Drive values in file order: angles in radians, slider travels in the
        file's length unit.
    start : Solution or dict, optional
        Where the first posture starts (a solved posture, or link id ->
        ``(x, y, θ)``).  Default: the posture :func:`solve_analytic` chooses
        at the first drive value (nearest the assembly hints).  With rolling
        contact: a posture at the file's own drive values (the reference of
        the no-slip condition, see Notes); default the one
        :func:`solve_analytic` chooses there.
    tol : Tolerance, optional
        As for :func:`solve_analytic`.

    Returns
    -------
    Solution
        Arrays of leading shape ``(N,)``.  Postures that cannot be assembled
        (or are singular) are NaN, and False in ``valid``.

    Raises
    ------
    AssemblyError
        With rolling contact only: the file's own posture, the reference of
        the no-slip condition, cannot be assembled.

    See Also
    --------
    solve_analytic : one posture.

    Notes
    -----
    Branch continuity: each posture starts from the previous valid one,
    advanced by the first-order kinematic coefficients ``dq/dd = -Φ_q⁻¹ Φ_d``
    (Sec. 3.11) times the change of the drive.  A Python loop over postures:
    this is the oracle, not the fast path.

    Rolling contact (``[[rolling]]``): the file gives the rolling link's
    angle only at the file's own drive values, so over a sweep the posture
    row of each contact is the integrated no-slip condition (Sec. 2.19)

        ``(θ_l - θ_o) - (θ_l - θ_o)_ref = -σ (s - s_ref) / ρ``,

    ``s`` the travel of the circle's center along the line in ``on``'s
    coordinates, ``σ = +1`` for a circle on the left of the line, and
    ``ref`` the posture at the file's drive values (rolling links at their
    file angles, as :func:`solve_analytic` finds it).  On a circle it is

        ``(θ_l - θ_o) - (θ_l - θ_o)_ref = ±(R ± r)/r · (φ - φ_ref)``

    (``+(R + r)/r`` outside, ``-(R - r)/r`` inside), ``φ`` the angle of the
    line of centers in ``on``'s axes, counted continuously from posture to
    posture (the ratio need not be an integer, so ``φ`` is not taken modulo
    2π).  The sweep continues
    that posture to the first drive value in steps of at most 2° (or 2 % of
    the mechanism's size), then on as above; the rates are the same as
    :func:`solve_analytic`'s.  After a gap that cannot be assembled the
    search picks the posture nearest the hints among those that satisfy the
    integrated condition.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 2.9, 2.19, 3.9, 3.11, 4.9.
    """
    tol = tol or DEFAULT_TOL
    eqs = _System(mech, tol)
    dv = np.asarray(drive_values, dtype=float)
    if dv.ndim == 1:
        dv = dv[:, None]
    if dv.ndim != 2 or dv.shape[1] != len(mech.drives):
        raise ValueError(f"drive_values must have shape (N, {len(mech.drives)}), "
                         f"not {np.shape(drive_values)}")
    N = dv.shape[0]
    Q = np.full((N, eqs.n), np.nan)
    rated = eqs.rate_functions is not None
    QD = np.full((N, eqs.n), np.nan) if rated else None
    QDD = np.full((N, eqs.n), np.nan) if rated else None
    valid = np.zeros(N, dtype=bool)
    prev: np.ndarray | None = None
    prev_values: np.ndarray | None = None
    prev_index = -2
    if mech.rolling and N:
        # the integrated no-slip condition through the file's posture, reached from
        # there by continuation (a search could find the circle rolled elsewhere)
        ref = _reference_posture(eqs, start)
        eqs = eqs.integrated(ref)
        prev = _march(eqs, ref, eqs.values, dv[0])
    elif start is not None:
        prev = _guess_vector(eqs, start, dv[0] if N else eqs.values)
    search = _Search(eqs)
    for i in range(N):
        values = dv[i]
        if prev is None:
            # the first posture gets the full search; while none assembles, fewer restarts
            try:
                q0 = search.solve(values, _RESTARTS if i == 0 else _SWEEP_RESTARTS,
                                  explain=False)
            except AssemblyError:
                continue
        else:
            q0 = prev
            if prev_values is not None and prev_index == i - 1:  # a step, not a gap
                q0 = prev + _sensitivity(eqs, prev, prev_values) @ _delta(eqs, values,
                                                                          prev_values)
        q = _converge(eqs, q0, values, _SWEEP_ITER)
        if q is None and prev is not None and q0 is not prev:
            q = _converge(eqs, prev, values, _SWEEP_ITER)
        if q is None:
            continue
        try:
            _check_regular(eqs, q, values)
            if rated:
                qd, qdd = _rates(eqs, q)
                assert QD is not None and QDD is not None
                QD[i], QDD[i] = qd, qdd
        except ConstructionError:
            continue
        Q[i] = q
        valid[i] = True
        prev, prev_values, prev_index = q, values, i
        eqs.follow(q)
    notes = ["analytic: Newton-Raphson, each posture from the one before"]
    return _solution(eqs, Q, QD, QDD, valid, notes)


def _reference_posture(eqs: _System, start: Solution | Guess | None) -> np.ndarray:
    """The posture at the file's drive values (rolling links at their file angles).

    From ``start`` when given and Newton converges from it, else the posture
    :func:`solve_analytic` chooses.  ``eqs`` has the file-angle rolling rows.
    """
    values = eqs.values
    if start is not None:
        q = _converge(eqs, _guess_vector(eqs, start, values), values)
        if q is not None:
            return q
    return _Search(eqs).solve(values)


def _march(eqs: _System, q: np.ndarray, v_from: np.ndarray,
           v_to: np.ndarray) -> np.ndarray | None:
    """Continue posture ``q`` at drive ``v_from`` to ``v_to`` in small steps (None: lost)."""
    d = _delta(eqs, v_to, v_from)
    steps = 1
    for i, drv in enumerate(eqs.mech.drives):
        unit = _MARCH_ANGLE if drv.kind == "angle" else _MARCH_LENGTH * eqs.size
        steps = max(steps, math.ceil(abs(float(d[i])) / unit))
    here = np.array(v_from, dtype=float)
    for k in range(1, steps + 1):
        there = v_from + d * (k / steps)
        q_new = _converge(eqs, q + _sensitivity(eqs, q, here) @ (there - here), there,
                          _SWEEP_ITER)
        if q_new is None:
            return None
        q, here = q_new, there
        eqs.follow(q)
    return q


def _delta(eqs: _System, values: np.ndarray, before: np.ndarray) -> np.ndarray:
    d = values - before
    for i, drv in enumerate(eqs.mech.drives):
        if drv.kind == "angle":
            d[i] = _wrap(float(d[i]))
    return d


def _sensitivity(eqs: _System, q: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``dq/dd``: the first-order kinematic coefficients (Sec. 3.11), shape (n, n_drives)."""
    _, J = eqs.residual(q, values)
    assert J is not None
    rhs = np.zeros((eqs.m, len(eqs.drives)))
    rhs[eqs.ncons:, :] = np.eye(len(eqs.drives))
    try:
        return np.linalg.solve(J, rhs)
    except np.linalg.LinAlgError:
        return np.zeros((eqs.n, len(eqs.drives)))
