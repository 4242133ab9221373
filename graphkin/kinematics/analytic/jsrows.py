"""The analytic solver's constraint rows written out as code: one table, two writers.

Newton-Raphson on the loop-closure equations (Sec. 2.7) needs, at a posture
``q``, the residual ``Φ(q)``, its Jacobian ``Φ_q`` and, for the
accelerations, ``γ`` (Secs. 3.9 and 4.9).  The solver computes them with
its row records (:mod:`~graphkin.kinematics.analytic.constraints`,
:mod:`~graphkin.kinematics.analytic.rolling`).  This module writes the same
rows out as straight-line code of one posture, for a page that solves a
mechanism while the user drags it (``graphkin live``): :data:`ROWS` is the
one table, one entry per kind of row, each writing its arithmetic through a
:class:`RowWriter` in expressions Python and JavaScript read alike
(``+ - * /``, ``_cos``, ``_sin``, ``_atan2``, ``_wrap``, indexing).
:class:`PyRowWriter` and :class:`JSRowWriter` differ only in how a line is
written (``t = e`` against ``const t = e;``), so the JavaScript is never a
hand-written copy of the Python: the Python written from the table is
tested against the solver's own rows (tests/kinematics/test_jsrows.py), and
the JavaScript against the Python.

The written functions, of the state ``q`` (``[x, y, θ]`` of every moving
link), the rates ``qd``, the numbers ``K`` (the frame points' coordinates
and the rolling constants, so a frame pivot can be dragged), the drive
values ``V`` and the anchors ``A`` of the rolling contacts on circles:

* ``phi(q, K, V, A)`` -> ``[r, J]``: the rows of the constraints, the drives
  and the known rates, in that order (angle rows wrapped);
* ``gam(q, qd, K, A)`` -> ``γ`` of the constraint and rate rows;
* ``anchors(q, K, A)`` -> the ``φ`` of every rolling contact on a circle,
  counted on from ``A`` (:meth:`_System.follow`).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.7 (loop-closure equations), Sec. 2.19 (the rolling constraint),
Secs. 3.9 and 4.9 (algebraic velocity and acceleration analysis).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.kinematics.analytic.constraints import (
    _F,
    _Angle,
    _OnCircle,
    _OnLine,
    _Pin,
    _wrap,
)
from graphkin.kinematics.analytic.rolling import _Rolling, _RollingCircle
from graphkin.kinematics.analytic.system import _System

__all__ = ["JS_RUNTIME", "ROWS", "RowWriter", "PyRowWriter", "JSRowWriter", "WrittenRows",
           "compile_python", "write_rows"]

_Pt = tuple[str, str]


def _lit(v: float) -> str:
    """A float literal both languages read exactly (``repr`` round-trips)."""
    s = repr(float(v))
    return s if s[0] != "-" else f"({s})"


class RowWriter:
    """Writes the rows of one function: names, folded arithmetic, J and γ entries.

    Subclasses say how a line is written; the table's entries call only the
    methods here.
    """

    def __init__(self, frame_slot: Callable[[tuple[float, float]], _Pt | None]) -> None:
        self.lines: list[str] = []
        self.memo: dict[str, str] = {}
        self.n = 0
        #: the K slots of a frame point at these coordinates (None: a literal)
        self.frame_slot = frame_slot
        self.row = 0
        #: Jacobian entries of the current row are multiplied by this (a rolling row)
        self.factor = "1.0"

    # -- the language ----------------------------------------------------
    def assign(self, name: str, expr: str) -> str:
        """The line binding ``name`` to ``expr``."""
        raise NotImplementedError

    def jline(self, row: int, col: int, expr: str) -> str:
        """The line adding ``expr`` to the Jacobian's entry ``(row, col)``."""
        raise NotImplementedError

    # -- names and folded arithmetic ------------------------------------
    def let(self, expr: str, hint: str = "t") -> str:
        """``expr`` bound to a name once (a name or literal is returned as it is)."""
        if expr.replace("_", "a").isalnum() or _is_num(expr) or expr.startswith(("q[", "K[")):
            return expr
        name = self.memo.get(expr)
        if name is None:
            name = self.memo[expr] = f"{hint}{self.n}"
            self.n += 1
            self.lines.append(self.assign(name, expr))
        return name

    @staticmethod
    def add(a: str, b: str) -> str:
        """``a + b`` (a zero drops out)."""
        if a == "0.0":
            return b
        if b == "0.0":
            return a
        return f"({a} + {b})"

    @staticmethod
    def sub(a: str, b: str) -> str:
        """``a - b`` (a zero drops out)."""
        if b == "0.0":
            return a
        if a == "0.0":
            return f"(-{b})"
        return f"({a} - {b})"

    @staticmethod
    def mul(a: str, b: str) -> str:
        """``a b`` (a zero or a one folded)."""
        if a == "0.0" or b == "0.0":
            return "0.0"
        if a == "1.0":
            return b
        if b == "1.0":
            return a
        return f"({a} * {b})"

    def dot(self, u: _Pt, v: _Pt) -> str:
        """``u · v``."""
        return self.add(self.mul(u[0], v[0]), self.mul(u[1], v[1]))

    def cross(self, u: _Pt, v: _Pt) -> str:
        """``u × v = u_x v_y - u_y v_x``."""
        return self.sub(self.mul(u[0], v[1]), self.mul(u[1], v[0]))

    # -- the state ----------------------------------------------------------
    def th(self, k: int) -> str:
        """``θ_k`` (zero for the frame)."""
        return "0.0" if k == _F else f"q[{3 * k + 2}]"

    def cs(self, k: int) -> _Pt:
        """``cos θ_k``, ``sin θ_k``, each computed once."""
        if k == _F:
            return "1.0", "0.0"
        return (self.let(f"_cos(q[{3 * k + 2}])", "c"), self.let(f"_sin(q[{3 * k + 2}])", "s"))

    def origin(self, k: int) -> _Pt:
        """The origin of link ``k``'s axes."""
        return ("0.0", "0.0") if k == _F else (f"q[{3 * k}]", f"q[{3 * k + 1}]")

    def rate(self, k: int) -> tuple[str, str, str]:
        """``(ȯx, ȯy, ω)`` of link ``k`` from ``qd``."""
        if k == _F:
            return "0.0", "0.0", "0.0"
        return f"qd[{3 * k}]", f"qd[{3 * k + 1}]", f"qd[{3 * k + 2}]"

    def local(self, k: int, p: tuple[float, float], named: bool = False) -> _Pt:
        """A point's local coordinates: a pinned frame point's K slots (``named``), else literals.

        Only a pin reads a frame point from ``K`` (a pivot the page drags);
        a path's points (a slider's line, a slot's or rolling circle's
        center) are literals, as the page does not drag them.
        """
        if k == _F and named:
            got = self.frame_slot((float(p[0]), float(p[1])))
            if got is not None:
                return got
        return _lit(p[0]), _lit(p[1])

    def rot(self, k: int, p: _Pt) -> _Pt:
        """``R_k p``."""
        c, s = self.cs(k)
        return (self.let(self.sub(self.mul(c, p[0]), self.mul(s, p[1])), "rx"),
                self.let(self.add(self.mul(s, p[0]), self.mul(c, p[1])), "ry"))

    def world(self, k: int, p: _Pt) -> _Pt:
        """``o_k + R_k p``."""
        ox, oy = self.origin(k)
        rx, ry = self.rot(k, p)
        return self.let(self.add(ox, rx), "wx"), self.let(self.add(oy, ry), "wy")

    # -- the rows -----------------------------------------------------------
    def jac(self, off: int, k: int, j: int, expr: str) -> None:
        """``J[row + off, 3k + j] += factor · expr`` (nothing for the frame)."""
        if k == _F:
            return
        e = self.mul(self.factor, expr)
        if e != "0.0":
            self.lines.append(self.jline(self.row + off, 3 * k + j, e))


def _is_num(s: str) -> bool:
    try:
        float(s.strip("()"))
    except ValueError:
        return False
    return True

# ---------------------------------------------------------------------------
# The table: one entry per kind of row (eval with its Jacobian, and γ)
# ---------------------------------------------------------------------------


def _pin(w: RowWriter, c: _Pin) -> list[str]:
    pa, pb = w.local(c.a, c.pa, True), w.local(c.b, c.pb, True)
    for k, sign, p in ((c.a, "1.0", pa), (c.b, "(-1.0)", pb)):
        rx, ry = w.rot(k, p)
        w.jac(0, k, 0, sign)
        w.jac(1, k, 1, sign)
        w.jac(0, k, 2, w.mul(sign, f"(-{ry})"))
        w.jac(1, k, 2, w.mul(sign, rx))
    a, b = w.world(c.a, pa), w.world(c.b, pb)
    return [w.sub(a[0], b[0]), w.sub(a[1], b[1])]


def _pin_gamma(w: RowWriter, c: _Pin) -> list[str]:
    # γ = -ω_a² R_a p_a + ω_b² R_b p_b
    pa, pb = w.local(c.a, c.pa, True), w.local(c.b, c.pb, True)
    wa, wb = w.rate(c.a)[2], w.rate(c.b)[2]
    ra, rb = w.rot(c.a, pa), w.rot(c.b, pb)
    wa2, wb2 = w.mul(wa, wa), w.mul(wb, wb)
    return [w.add(w.mul(f"(-{wa2})", ra[0]), w.mul(wb2, rb[0])) if wa2 != "0.0"
            else w.mul(wb2, rb[0]),
            w.add(w.mul(f"(-{wa2})", ra[1]), w.mul(wb2, rb[1])) if wa2 != "0.0"
            else w.mul(wb2, rb[1])]


def _line_parts(w: RowWriter, c: _OnLine) -> tuple[_Pt, _Pt, _Pt, _Pt, _Pt]:
    p, l0 = w.local(c.s, c.p), w.local(c.o, c.l0)
    P, L0 = w.world(c.s, p), w.world(c.o, l0)
    v = w.rot(c.o, (_lit(c.v_loc[0]), _lit(c.v_loc[1])))
    r = (w.let(w.sub(P[0], L0[0]), "dx"), w.let(w.sub(P[1], L0[1]), "dy"))
    return p, l0, v, r, (w.rot(c.s, p) if c.s != _F else ("0.0", "0.0"))


def _on_line(w: RowWriter, c: _OnLine) -> list[str]:
    p, l0, (vx, vy), (rx, ry), (qx, qy) = _line_parts(w, c)
    if c.s != _F:
        w.jac(0, c.s, 0, vx)
        w.jac(0, c.s, 1, vy)
        w.jac(0, c.s, 2, w.add(w.mul(vx, f"(-{qy})"), w.mul(vy, qx)))
    if c.o != _F:
        lx, ly = w.rot(c.o, l0)
        w.jac(0, c.o, 0, f"(-{vx})")
        w.jac(0, c.o, 1, f"(-{vy})")
        # ∂f/∂θ_o = perp(v)·r - v·perp(R_o l0)
        w.jac(0, c.o, 2, w.sub(w.add(w.mul(f"(-{vy})", rx), w.mul(vx, ry)),
                               w.add(w.mul(vx, f"(-{ly})"), w.mul(vy, lx))))
    return [w.dot((vx, vy), (rx, ry))]


def _on_line_gamma(w: RowWriter, c: _OnLine) -> list[str]:
    # γ = -ω_o² v·r + 2 ω_o perp(v)·ṙ + v·(-ω_s² R_s p + ω_o² R_o l0)
    p, l0, (vx, vy), (rx, ry), (px, py) = _line_parts(w, c)
    vsx, vsy, ws = w.rate(c.s)
    vox, voy, wo = w.rate(c.o)
    lx, ly = w.rot(c.o, l0) if c.o != _F else ("0.0", "0.0")
    rdx = w.let(w.sub(w.sub(vsx, w.mul(ws, py)), w.sub(vox, w.mul(wo, ly))), "rd")
    rdy = w.let(w.sub(w.add(vsy, w.mul(ws, px)), w.add(voy, w.mul(wo, lx))), "rd")
    ws2, wo2 = w.mul(ws, ws), w.mul(wo, wo)
    g = w.mul(f"(-{wo2})", w.dot((vx, vy), (rx, ry))) if wo2 != "0.0" else "0.0"
    g = w.add(g, w.mul(w.mul("2.0", wo), w.add(w.mul(f"(-{vy})", rdx), w.mul(vx, rdy))))
    ax = w.sub(w.mul(wo2, lx), w.mul(ws2, px))
    ay = w.sub(w.mul(wo2, ly), w.mul(ws2, py))
    return [w.add(g, w.dot((vx, vy), (ax, ay)))]


def _angle(w: RowWriter, c: _Angle) -> list[str]:
    w.jac(0, c.a, 2, "1.0")
    w.jac(0, c.b, 2, "(-1.0)")
    return [w.sub(w.sub(w.th(c.a), w.th(c.b)), _lit(c.c))]


def _angle_gamma(w: RowWriter, c: _Angle) -> list[str]:
    return ["0.0"]


def _circle_parts(w: RowWriter, c: _OnCircle) -> tuple[_Pt, _Pt, _Pt]:
    p, cc = w.local(c.s, c.p), w.local(c.o, c.center)
    P, C = w.world(c.s, p), w.world(c.o, cc)
    return p, cc, (w.let(w.sub(P[0], C[0]), "dx"), w.let(w.sub(P[1], C[1]), "dy"))


def _on_circle(w: RowWriter, c: _OnCircle) -> list[str]:
    p, cc, (rx, ry) = _circle_parts(w, c)
    rho = _lit(c.radius)
    gx, gy = w.let(f"({rx} / {rho})", "g"), w.let(f"({ry} / {rho})", "g")
    if c.s != _F:
        qx, qy = w.rot(c.s, p)
        w.jac(0, c.s, 0, gx)
        w.jac(0, c.s, 1, gy)
        w.jac(0, c.s, 2, w.add(w.mul(gx, f"(-{qy})"), w.mul(gy, qx)))
    if c.o != _F:
        cx, cy = w.rot(c.o, cc)
        w.jac(0, c.o, 0, f"(-{gx})")
        w.jac(0, c.o, 1, f"(-{gy})")
        w.jac(0, c.o, 2, f"(-{w.add(w.mul(gx, f'(-{cy})'), w.mul(gy, cx))})")
    return [f"(({rx} * {rx} + {ry} * {ry} - {rho} * {rho}) / (2.0 * {rho}))"]


def _on_circle_gamma(w: RowWriter, c: _OnCircle) -> list[str]:
    # γ = (ṙ·ṙ + r·(-ω_s² R_s p + ω_o² R_o c)) / ρ
    p, cc, (rx, ry) = _circle_parts(w, c)
    px, py = w.rot(c.s, p) if c.s != _F else ("0.0", "0.0")
    cx, cy = w.rot(c.o, cc) if c.o != _F else ("0.0", "0.0")
    vsx, vsy, ws = w.rate(c.s)
    vox, voy, wo = w.rate(c.o)
    rdx = w.let(w.sub(w.sub(vsx, w.mul(ws, py)), w.sub(vox, w.mul(wo, cy))), "rd")
    rdy = w.let(w.sub(w.add(vsy, w.mul(ws, px)), w.add(voy, w.mul(wo, cx))), "rd")
    ws2, wo2 = w.mul(ws, ws), w.mul(wo, wo)
    g = w.add(w.dot((rdx, rdy), (rdx, rdy)),
              w.dot((rx, ry), (w.sub(w.mul(wo2, cx), w.mul(ws2, px)),
                               w.sub(w.mul(wo2, cy), w.mul(ws2, py)))))
    return [f"({g} / {_lit(c.radius)})"]


def _rolling(w: RowWriter, c: _Rolling) -> list[str]:
    # g = (θ_l - θ_o) + σ s/ρ - c (the integrated no-slip row, Sec. 2.19), c read from K
    assert c.ref is not None
    k = w.rolling_slot(c)  # type: ignore[attr-defined]
    w.jac(0, c.link, 2, "1.0")
    w.jac(0, c.on, 2, "(-1.0)")
    w.factor = _lit(c.sigma / c.radius)
    s = _on_line(w, c.travel)[0]
    w.factor = "1.0"
    return [w.sub(w.add(w.sub(w.th(c.link), w.th(c.on)),
                        w.mul(_lit(c.sigma / c.radius), s)), k)]


def _rolling_gamma(w: RowWriter, c: _Rolling) -> list[str]:
    return [w.mul(_lit(c.sigma / c.radius), _on_line_gamma(w, c.travel)[0])]


def _circle_d(w: RowWriter, c: _RollingCircle) -> tuple[_Pt, _Pt, _Pt]:
    p, oc = w.local(c.link, c.p), w.local(c.on, c.oc)
    P, Oc = w.world(c.link, p), w.world(c.on, oc)
    return p, oc, (w.let(w.sub(P[0], Oc[0]), "dx"), w.let(w.sub(P[1], Oc[1]), "dy"))


def _phi(w: RowWriter, c: _RollingCircle) -> str:
    """``φ = A + wrap(atan2(d) - θ_o - A)``: the angle of P - O in o's axes, counted on."""
    _, _, (dx, dy) = _circle_d(w, c)
    a = w.anchor_slot(c)  # type: ignore[attr-defined]
    raw = w.sub(f"_atan2({dy}, {dx})", w.th(c.on))
    return w.let(f"({a} + _wrap({w.sub(raw, a)}))", "phi")


def _rolling_circle(w: RowWriter, c: _RollingCircle) -> list[str]:
    # g = (θ_l - θ_o) - k φ - c; its row: the angle row minus k (∂ψ/∂q - ∂θ_o/∂q)
    assert c.ref is not None
    k = _lit(c.ratio)
    p, oc, (dx, dy) = _circle_d(w, c)
    d2 = w.let(w.add(w.mul(dx, dx), w.mul(dy, dy)), "d2")
    gx, gy = w.let(f"((-{dy}) / {d2})", "g"), w.let(f"({dx} / {d2})", "g")
    if c.link != _F:
        px, py = w.rot(c.link, p)
        w.jac(0, c.link, 0, w.mul(f"(-{k})", gx))
        w.jac(0, c.link, 1, w.mul(f"(-{k})", gy))
        w.jac(0, c.link, 2, w.sub("1.0", w.mul(k, w.add(w.mul(gx, f"(-{py})"),
                                                          w.mul(gy, px)))))
    if c.on != _F:
        cx, cy = w.rot(c.on, oc)
        w.jac(0, c.on, 0, w.mul(k, gx))
        w.jac(0, c.on, 1, w.mul(k, gy))
        w.jac(0, c.on, 2, w.add(w.add("(-1.0)", w.mul(k, w.add(w.mul(gx, f"(-{cy})"),
                                                                w.mul(gy, cx)))), k))
    ref = w.rolling_slot(c)  # type: ignore[attr-defined]
    return [w.sub(w.sub(w.sub(w.th(c.link), w.th(c.on)), w.mul(k, _phi(w, c))), ref)]


def _rolling_circle_gamma(w: RowWriter, c: _RollingCircle) -> list[str]:
    # γ = -k γ_ψ, γ_ψ = (d × d̈_γ)/|d|² - 2 (d × ḋ)(d·ḋ)/|d|⁴
    p, oc, (dx, dy) = _circle_d(w, c)
    vlx, vly, wl = w.rate(c.link)
    vox, voy, wo = w.rate(c.on)
    px, py = w.rot(c.link, p) if c.link != _F else ("0.0", "0.0")
    cx, cy = w.rot(c.on, oc) if c.on != _F else ("0.0", "0.0")
    ddx = w.let(w.sub(w.sub(vlx, w.mul(wl, py)), w.sub(vox, w.mul(wo, cy))), "dd")
    ddy = w.let(w.sub(w.add(vly, w.mul(wl, px)), w.add(voy, w.mul(wo, cx))), "dd")
    wl2, wo2 = w.mul(wl, wl), w.mul(wo, wo)
    ax = w.let(w.sub(w.mul(wo2, cx), w.mul(wl2, px)), "ax")
    ay = w.let(w.sub(w.mul(wo2, cy), w.mul(wl2, py)), "ay")
    d2 = w.let(w.add(w.mul(dx, dx), w.mul(dy, dy)), "d2")
    g = (f"({w.cross((dx, dy), (ax, ay))} / {d2} - 2.0 * {w.cross((dx, dy), (ddx, ddy))} * "
         f"{w.dot((dx, dy), (ddx, ddy))} / ({d2} * {d2}))")
    return [w.mul(f"(-{_lit(c.ratio)})", g)]


Entry = tuple[Callable[[RowWriter, Any], list[str]], Callable[[RowWriter, Any], list[str]]]

#: The one table: kind of row -> (its rows with their Jacobian, its γ).
ROWS: dict[type, Entry] = {
    _Pin: (_pin, _pin_gamma),
    _OnLine: (_on_line, _on_line_gamma),
    _Angle: (_angle, _angle_gamma),
    _OnCircle: (_on_circle, _on_circle_gamma),
    _Rolling: (_rolling, _rolling_gamma),
    _RollingCircle: (_rolling_circle, _rolling_circle_gamma),
}

# ---------------------------------------------------------------------------
# The two languages
# ---------------------------------------------------------------------------


class PyRowWriter(RowWriter):
    """Python: ``t = e`` and ``J[i, j] += e``."""

    def assign(self, name: str, expr: str) -> str:
        """``name = expr``."""
        return f"    {name} = {expr}"

    def jline(self, row: int, col: int, expr: str) -> str:
        """``J[row, col] += expr``."""
        return f"    J[{row}, {col}] += {expr}"


class JSRowWriter(RowWriter):
    """JavaScript: ``const t = e;`` and ``J[i][j] += e;``."""

    def assign(self, name: str, expr: str) -> str:
        """``const name = expr;``."""
        return f"  const {name} = {expr};"

    def jline(self, row: int, col: int, expr: str) -> str:
        """``J[row][col] += expr;``."""
        return f"  J[{row}][{col}] += {expr};"


@dataclass
class WrittenRows:
    """The rows of one mechanism written out.

    Attributes
    ----------
    source : str
        The three functions ``phi``, ``gam``, ``anchors`` (named with ``prefix``).
    slots : list of (str, float)
        ``K``'s entries: ``"O2.0"``/``"O2.1"`` (a frame point's x, y), ``"rolling[i].c"``
        (a contact's constant), and their values.
    m, n, ncons, ndrives : int
        Rows of the posture system, unknowns, constraint rows, drive rows.
    rate_rows : int
        Rows of the known rates (after the drive rows).
    angle_rows : list of int
        The rows wrapped to (-π, π].
    """

    source: str
    slots: list[tuple[str, float]]
    m: int
    n: int
    ncons: int
    ndrives: int
    rate_rows: int
    angle_rows: list[int]
    circles: int


def write_rows(eqs: _System, lang: str, frame_points: dict[str, tuple[float, float]],
               prefix: str = "gkRows") -> WrittenRows:
    """Write the rows of ``eqs`` (its integrated form: no-slip rows with their constants).

    Parameters
    ----------
    eqs : _System
        The system through a posture (:meth:`_System.integrated`).
    lang : {"python", "js"}
    frame_points : dict
        Frame point name -> coordinates: a frame point of a row at these
        coordinates is read from ``K`` (the first name at those coordinates).
    prefix : str
        The functions are ``<prefix>Phi``, ``<prefix>Gam``, ``<prefix>Anchors``.
    """
    slots: list[tuple[str, float]] = []
    index: dict[str, int] = {}

    def slot(name: str, value: float) -> str:
        if name not in index:
            index[name] = len(slots)
            slots.append((name, float(value)))
        return f"K[{index[name]}]"

    by_xy: dict[tuple[float, float], str] = {}
    for name, xy in frame_points.items():
        by_xy.setdefault((float(xy[0]), float(xy[1])), name)

    def frame_slot(xy: tuple[float, float]) -> _Pt | None:
        name = by_xy.get(xy)
        if name is None:
            return None
        return slot(f"{name}.0", xy[0]), slot(f"{name}.1", xy[1])

    rolls = [c for c in eqs.cons if isinstance(c, (_Rolling, _RollingCircle))]
    circles = [c for c in rolls if isinstance(c, _RollingCircle)]

    def make() -> RowWriter:
        w: RowWriter = (PyRowWriter if lang == "python" else JSRowWriter)(frame_slot)
        w.rolling_slot = lambda c: slot(f"rolling[{rolls.index(c)}].c",  # type: ignore
                                        float(c.ref))
        w.anchor_slot = lambda c: f"A[{circles.index(c)}]"  # type: ignore[attr-defined]
        return w

    rate_fns = list(eqs.rate_functions or [])
    # phi: constraints, drives (minus V), rate rows
    w = make()
    res: list[str] = []
    angle_rows: list[int] = []
    for i, c in enumerate([*eqs.cons, *eqs.drives, *rate_fns]):
        w.row = len(res)
        got = ROWS[type(c)][0](w, c)
        if i >= len(eqs.cons) and i < len(eqs.cons) + len(eqs.drives):
            got = [w.sub(got[0], f"V[{i - len(eqs.cons)}]")]
        for e, kind in zip(got, c.kinds):
            if kind == "A":
                angle_rows.append(len(res))
                e = f"_wrap({e})"
            res.append(w.let(e, "r"))
    m_all = len(res)
    phi_body, phi_res = w.lines, res
    # gam: constraints and rate rows
    g = make()
    gres: list[str] = []
    for c in [*eqs.cons, *rate_fns]:
        gres.extend(g.let(e, "y") for e in ROWS[type(c)][1](g, c))
    # anchors
    a = make()
    anc = [_phi(a, c) for c in circles]
    n = eqs.n

    def lines(xs: list[str]) -> str:
        return "".join(x + "\n" for x in xs)

    if lang == "python":
        src = (f"def {prefix}Phi(q, K, V, A):\n    J = _zeros(({m_all}, {n}))\n"
               + lines(phi_body) + f"    return [{', '.join(phi_res)}], J\n\n")
        src += (f"def {prefix}Gam(q, qd, K, A):\n" + lines(g.lines)
                + f"    return [{', '.join(gres)}]\n\n")
        src += (f"def {prefix}Anchors(q, K, A):\n" + lines(a.lines)
                + f"    return [{', '.join(anc)}]\n")
    else:
        src = (f"function {prefix}Phi(q, K, V, A) {{\n  const J = [];\n"
               f"  for (let i = 0; i < {m_all}; i++) J.push(new Array({n}).fill(0));\n"
               + lines(phi_body) + f"  return [[{', '.join(phi_res)}], J];\n}}\n")
        src += (f"function {prefix}Gam(q, qd, K, A) {{\n" + lines(g.lines)
                + f"  return [{', '.join(gres)}];\n}}\n")
        src += (f"function {prefix}Anchors(q, K, A) {{\n" + lines(a.lines)
                + f"  return [{', '.join(anc)}];\n}}\n")
    return WrittenRows(src, slots, eqs.ncons + len(eqs.drives), n, eqs.ncons,
                       len(eqs.drives), len(rate_fns), angle_rows, len(circles))


#: The name the JavaScript rows call beside ``_cos``, ``_sin`` and ``_atan2`` (those are in
#: :data:`graphkin.construction.jsgen.RUNTIME`; :func:`compile_python` gives the Python all
#: four): ``_wrap``, ``constraints._wrap``, an angle in (-π, π].
JS_RUNTIME = """\
const _wrap = (x) => { const w = x - 2 * Math.PI * Math.round(x / (2 * Math.PI));
                       return w <= -Math.PI ? w + 2 * Math.PI : w; };
"""


def compile_python(rows: WrittenRows) -> dict[str, Any]:
    """The Python functions of :func:`write_rows` (``lang="python"``), compiled."""
    ns: dict[str, Any] = {"_cos": math.cos, "_sin": math.sin, "_atan2": math.atan2,
                          "_wrap": _wrap, "_zeros": np.zeros}
    exec(compile(rows.source, "<graphkin rows>", "exec"), ns)  # noqa: S102
    return ns
