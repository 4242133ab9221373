"""The constraint rows of rolling contact without slip (Sec. 4.6)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from graphkin.kinematics.analytic.constraints import _F, _OnLine, _Poses, _wrap


class _RollingRow:
    """The row of a rolling contact: the roller's angle at the posture, its rate otherwise.

    With ``ref`` None the row fixes the roller's angle (a posture); else its
    rate equation (:meth:`rate_eval`) equals ``ref``.
    """

    link: int
    angle: float
    ref: float | None
    #: the posture row at the file's drive: (link index, "angle" or "travel", value, the
    #: travel row of a slider or None); see :mod:`graphkin.kinematics.analytic.phase`
    phase: tuple[int, str, float, _OnLine | None] | None

    def rate_eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        raise NotImplementedError

    def eval(self, st: _Poses, J: np.ndarray | None, row: int) -> list[float]:
        if self.ref is None:
            k, kind, value, travel = self.phase or (self.link, "angle", self.angle, None)
            if kind == "angle" or travel is None:
                if J is not None and k != _F:
                    J[row, 3 * k + 2] += 1.0
                return [st.th[k] - value]
            return [travel.eval(st, J, row)[0] - value]
        return [self.rate_eval(st, J, row)[0] - self.ref]


@dataclass(frozen=True)
class _Rolling(_RollingRow):
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
    posture row places the link that the contact places at the file's drive
    (``phase``: the rolling link at its ``angle``, or another link, see
    :mod:`graphkin.kinematics.analytic.phase`).  With ``ref = c`` (a sweep) it is ``g`` itself,
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
    phase: tuple[int, str, float, _OnLine | None] | None = None

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

    def gamma(self, st: _Poses, qd: Sequence[float]) -> list[float]:
        return [self.sigma / self.radius * self.travel.gamma(st, qd)[0]]


@dataclass
class _RollingCircle(_RollingRow):
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
    drive) the row of ``phase``; with ``ref = c`` (a sweep) ``g``.  ``φ`` is
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
    phase: tuple[int, str, float, _OnLine | None] | None = None

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
