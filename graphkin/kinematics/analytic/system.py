"""The loop-closure system Φ(q) = 0 of a mechanism, its Jacobian and rate equations."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from graphkin.kinematics.analytic.constraints import (
    _F,
    _Angle,
    _OnCircle,
    _OnLine,
    _Pin,
    _Poses,
    _wrap_array,
)
from graphkin.kinematics.analytic.phase import Phase, rolling_phases
from graphkin.kinematics.analytic.rolling import _Rolling, _RollingCircle
from graphkin.mechanisms.model import FRAME, Drive, Mechanism
from graphkin.tolerance import Tolerance

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
        # at the file's drive each contact places one link (its phase), as a drive would
        self.phases: tuple[Phase, ...] = rolling_phases(mech) if rolling_ref is None else ()
        for i, ro in enumerate(mech.rolling):
            s, o = self.index[ro.link], self.index[ro.on]
            p = mech.links[ro.link].points[ro.center]
            lab = f"{ro.key} (link {ro.link} rolls on link {ro.on} without slip)"
            ref = None if rolling_ref is None else float(rolling_ref[i])
            row = self._phase_row(self.phases[i]) if self.phases else None
            rk = ("L",) if row is not None and row[1] == "travel" else ("A",)
            if ro.p0 is None or ro.p1 is None:
                assert ro.on_center is not None and ro.on_radius is not None
                rad, big = float(ro.radius), float(ro.on_radius)
                ratio = (big + rad) / rad if ro.contact == "outside" else -(big - rad) / rad
                self.cons.append(_RollingCircle(s, o, p, ro.on_center, ratio, float(ro.angle),
                                                ref, lab, rk, phase=row))
                continue
            u, _ = _unit(ro.p0, ro.p1)
            travel = _OnLine(s, p, o, ro.p0, u, lab)
            sigma = 1.0 if ro.side == "left" else -1.0
            self.cons.append(_Rolling(s, o, travel, sigma, float(ro.radius), float(ro.angle),
                                      ref, lab, rk, phase=row))
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

    def _phase_row(self, ph: Phase) -> tuple[int, str, float, _OnLine | None]:
        """The posture row of a rolling contact's phase (an angle or a slider's travel)."""
        if ph.kind == "angle" or ph.slider is None:
            return self.index[ph.link], "angle", ph.value, None
        sl = ph.slider
        u, _ = _unit(sl.p0, sl.p1)
        row = _OnLine(self.index[sl.link], self.mech.links[sl.link].points[sl.point],
                      self.index[sl.on], sl.p0, u, f"{ph.key} (travel of link {sl.link})")
        return self.index[sl.link], "travel", ph.value, row

    # -- the functions that drives and rates prescribe --------------------
    def _drive_function(self, d: Drive) -> _Constraint:
        k = self.index[d.link]
        if d.kind == "angle":
            return _Angle(k, _F, 0.0, f"{d.key} (angle of link {d.link})")
        if d.kind == "relative":
            assert d.relative_to is not None
            return _Angle(k, self.index[d.relative_to], 0.0,
                          f"{d.key} (angle of link {d.link} relative to link {d.relative_to})")
        if d.kind in ("x", "y"):
            # f = v·(P − O): the coordinate of the point, with v the frame's x or y axis
            assert d.point is not None
            p = self.mech.links[d.link].points[d.point]
            axis = (1.0, 0.0) if d.kind == "x" else (0.0, 1.0)
            return _OnLine(k, p, _F, (0.0, 0.0), axis,
                           f"{d.key} ({d.kind} of point {d.point})")
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
