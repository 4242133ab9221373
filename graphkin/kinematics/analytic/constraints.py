"""The constraint rows of the analytic solver: pins, points on lines and circles, angles."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

_TWO_PI = 2.0 * math.pi


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
