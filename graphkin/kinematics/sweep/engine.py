"""The posture and polygon constructions of one mechanism, built once and replayed on arrays.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 2.8 (posture), Secs. 3.4-3.6 and 4.2-4.6 (polygons), Sec. 5.4 (several inputs).
"""

from __future__ import annotations

import dataclasses
import math
import weakref
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.construction import Construction, Evaluation
from graphkin.errors import AssemblyError, GraphkinError, InputError
from graphkin.kinematics.polygons import Polygons, build_polygons
from graphkin.kinematics.posture import NotDecomposable, PostureConstruction, build_posture
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import Drive, Mechanism
from graphkin.tolerance import VERDICT_REL, Tolerance

Array = np.ndarray


class _Engine:
    """The posture and polygon constructions of a mechanism and how to evaluate them."""

    def __init__(self, mech: Mechanism, tol: Tolerance) -> None:
        if not mech.drives:
            raise InputError("the mechanism has no drive to sweep", key="drive", file=mech.source)
        self.mech = mech
        self.tol = tol
        self.drive: Drive = mech.drives[0]
        self.method = "construction"
        self.reason = ""
        self.built_at: float | None = None
        self.pc: PostureConstruction | None = None
        self.pol: Polygons | None = None
        self.combined: Construction | None = None
        self.recipe: Any = False
        self.const_rows: dict[tuple[str, int], float] = {}
        #: what later sweeps reuse (the resolved Kennedy search, ...), keyed by what it depends on
        self.extras: dict[Any, Any] = {}
        #: the constructions written out as one function (:mod:`.fast`): False until built,
        #: None when they cannot be
        self.fast: Any = False
        if mech.has_rates and any(x.law is not None and not x.law.linear
                                  for x in mech.drives) and (mech.rolling or mech.rates):
            # the analytic solver takes each drive's rates as constants over a sweep
            bad = next(x for x in mech.drives if x.law is not None and not x.law.linear)
            raise InputError("a drive that follows by a table is swept with its rates by the "
                             "constructions only; this mechanism has rolling contact or "
                             "[rates]: leave out the rates, or give a ratio and an offset",
                             key=f"{bad.key}.follows.table", file=mech.source)
        travel = None
        if mech.rolling:
            # away from the file's drive a roller's angle follows its travel (the no-slip
            # condition integrated): a step when its center and line are drawn before it
            # (roll_angle), or, for a gear on a circle whose centers one link holds, from
            # that link's and the other gear's angle (roll_circle_angle); otherwise no
            # ruler-and-compass step gives it
            from graphkin.kinematics.posture_drives import rolling_travel

            travel = rolling_travel(mech, tol)
            if travel is None:
                self.method = "analytic"
                self.reason = ("rolling contact: the roller's angle follows its travel over "
                               "the sweep, so the analytic solver sweeps it")
                return
        try:
            self.pc = (self._build(mech, tol) if travel is None else
                       build_posture(mech, tol, travel=travel))
        except NotDecomposable as exc:
            if travel is not None:
                self.method = "analytic"
                self.reason = ("rolling contact: the roller's angle follows its travel over "
                               "the sweep, so the analytic solver sweeps it")
                return
            self.method = "analytic"
            self.reason = str(exc)
            if mech.has_rates and any(x.law is not None and not x.law.linear
                                      for x in mech.drives):
                raise InputError("a drive that follows by a table is swept with its rates by "
                                 "the constructions only, and this mechanism has none "
                                 f"({exc}): leave out the rates, or give a ratio and an offset",
                                 key="drive", file=mech.source) from None
            return
        d = self.drive
        self.label = d.label
        if self.label not in self.pc.inputs:  # pragma: no cover - the builder names them so
            raise GraphkinError(f"the posture construction has no input {self.label!r}")
        #: the inputs coupled to the swept one by a law (``follows``): label -> law
        self.coupled = {dd.label: dd.law for dd in mech.drives if dd.law is not None}
        #: a table law's follower has rates that change with the posture: rate labels -> drive
        self.coupled_rates: dict[tuple[str, str], Drive] = {}
        self.held = {k: v for k, v in self.pc.inputs.items()
                     if k != self.label and k not in self.coupled}
        if mech.has_rates:
            self.pol = build_polygons(mech, self.pc)
            if mech.rates is None:
                # posture, velocity and acceleration as one construction: one replay per block
                cx = Construction(title=self.pc.construction.title)
                cx.extend(self.pc.construction)
                self.n_posture = len(cx)
                cx.extend(self.pol.velocity)
                cx.extend(self.pol.acceleration)
                self.combined = cx
                self.keep = self._keep()
                self.rate_given: dict[str, float] = {}
                for d in mech.drives:
                    w, a = self.pol.rate_inputs[d.index]
                    self.rate_given[w] = 0.0 if d.rate is None else d.rate
                    self.rate_given[a] = 0.0 if d.rate2 is None else d.rate2
            for d in mech.drives:
                if d.law is not None and not d.law.linear:
                    self.coupled_rates[self.pol.rate_inputs[d.index]] = d
                    if self.combined is not None:
                        for lab in self.pol.rate_inputs[d.index]:
                            self.rate_given.pop(lab, None)

    def _build(self, mech: Mechanism, tol: Tolerance) -> PostureConstruction:
        """The posture construction, laid out at the file's drive if it assembles there.

        Otherwise it is laid out at the first drive angle of the turn where it
        can (its branches then follow the assembly hints at that posture).
        """
        try:
            return build_posture(mech, tol)
        except AssemblyError:
            d = self.drive
            if not d.is_angle:
                raise
            for k in range(1, 360):
                moved = dataclasses.replace(d, value=d.value + math.radians(k))
                drives = tuple(moved if x is d else x if x.law is None else
                               dataclasses.replace(x, value=x.law.value(moved.value))
                               for x in mech.drives)
                try:
                    pc = build_posture(dataclasses.replace(mech, drives=drives), tol)
                except AssemblyError:
                    continue
                self.built_at = moved.value
                return pc
            raise

    def _keep(self) -> frozenset[str]:
        """The labels a sweep reads: named points, anchors, angles, rates and their images."""
        assert self.pc is not None
        mech, pc, pol = self.mech, self.pc, self.pol
        keep = set(mech.point_names) | set(pc.angles.values()) | set(pc.inputs)
        keep |= {a for a, _ in pc.anchors.values()}
        for pin, c1, c2 in _dyads(pc):
            keep |= {pin, c1, c2}
        if pol is not None:
            for lab in list(keep):
                for images in (pol.velocity_images, pol.acceleration_images):
                    if lab in images:
                        keep.add(images[lab])
            keep |= {f"ω{lid}" for lid in mech.links} | {f"α{lid}" for lid in mech.links}
            for w, a in pol.rate_inputs.values():
                keep |= {w, a}
        return frozenset(keep)

    # ---- evaluation -------------------------------------------------
    def posture(self, dv: Array) -> Evaluation:
        """The posture construction at the drive values ``dv`` (internal units)."""
        assert self.pc is not None
        given: dict[str, Any] = dict(self.held)
        given.update(self.inputs_at(dv))
        return self.pc.construction.evaluate(given, tol=self.tol, strict=False)

    def inputs_at(self, dv: Array) -> dict[str, Array]:
        """The swept input and the inputs coupled to it by a law, at drive values ``dv``."""
        out = {self.label: dv}
        for lab, law in self.coupled.items():
            out[lab] = law.value(np.asarray(dv, dtype=float))
        if self.combined is not None:
            out.update(self.rates_at(dv))
        return out

    def rates_at(self, dv: Array) -> dict[str, Array]:
        """The rates of the inputs that follow by a table, at drive values ``dv``.

        ``ω_f = f'(x) ω`` and ``α_f = f''(x) ω² + f'(x) α``, ``x`` the swept input
        (the chain rule, as a cam's follower, Sec. 6.3).
        """
        d0 = self.drive
        out: dict[str, Array] = {}
        for (w, a), d in self.coupled_rates.items():
            assert d.law is not None
            out[w], out[a] = d.law.rates(np.asarray(dv, dtype=float), d0.rate or 0.0,
                                         d0.rate2 or 0.0)
        return out

    @property
    def varying(self) -> list[str]:
        """The inputs that change over a sweep: the swept one, its followers and their rates."""
        extra = [lab for pair in self.coupled_rates for lab in pair] \
            if self.combined is not None else []
        return [self.label, *self.coupled, *extra]

    def rates(self, ev: Evaluation, unit: bool = False) -> tuple[Evaluation, Evaluation]:
        """The velocity and acceleration constructions on an evaluated posture.

        With ``unit``, the swept drive turns at unit speed and every other
        input is at rest: the velocities are the first-order kinematic
        coefficients (Sec. 3.11).
        """
        assert self.pol is not None and self.pc is not None
        pol, mech = self.pol, self.mech
        vin: dict[str, Any] = {}
        ain: dict[str, Any] = {}
        for d in mech.drives:
            w, a = pol.rate_inputs[d.index]
            if unit:  # the first-order coefficients with respect to the swept input
                vin[w] = 1.0 if d is self.drive else (
                    0.0 if d.law is None else d.law.slope(self._swept(ev)))
                ain[a] = 0.0
            elif (w, a) in self.coupled_rates:
                assert d.law is not None
                vin[w], ain[a] = d.law.rates(self._swept(ev), self.drive.rate or 0.0,
                                             self.drive.rate2 or 0.0)
            else:
                vin[w] = 0.0 if d.rate is None else d.rate
                ain[a] = 0.0 if d.rate2 is None else d.rate2
        if mech.rates is not None and not unit:
            return self._scaled_rates(ev, vin, ain)
        evv = pol.velocity.evaluate(vin, values=ev.values, tol=self.tol, strict=False)
        eva = pol.acceleration.evaluate(ain, values=evv.values, tol=self.tol, strict=False)
        return evv, eva

    def _swept(self, ev: Evaluation) -> Array:
        """The swept input's values of an evaluated posture."""
        return np.asarray(ev.values[self.label], dtype=float)

    def _scaled_rates(self, ev: Evaluation, vin: dict[str, Any],
                      ain: dict[str, Any]) -> tuple[Evaluation, Evaluation]:
        """``[rates]`` of another link: the input's rates found posture by posture.

        The polygons are linear in the input speed and affine in the input
        acceleration (superposition, Sec. 5.4), as in
        :func:`graphkin.kinematics.solve.rate_inputs`, but with the ratio of
        every posture.
        """
        assert self.pol is not None
        pol, mech, tol = self.pol, self.mech, self.tol
        target = mech.rates
        assert target is not None
        if target.kind != "angle":
            raise InputError("[rates] of a slider are not supported yet; give the drive's rate",
                             key="rates", file=mech.source)
        (d,) = mech.drives
        w, a = pol.rate_inputs[d.index]
        k = np.asarray(pol.velocity.evaluate({w: 1.0}, values=ev.values, tol=tol,
                                             strict=False)[f"ω{target.link}"])
        with np.errstate(divide="ignore", invalid="ignore"):
            vin[w] = np.where(k == 0.0, np.nan, (target.rate or 0.0) / np.where(k == 0.0, 1.0, k))
        evv = pol.velocity.evaluate(vin, values=ev.values, tol=tol, strict=False)
        a0 = np.asarray(pol.acceleration.evaluate({a: 0.0}, values=evv.values, tol=tol,
                                                  strict=False)[f"α{target.link}"])
        a1 = np.asarray(pol.acceleration.evaluate({a: 1.0}, values=evv.values, tol=tol,
                                                  strict=False)[f"α{target.link}"])
        want = 0.0 if target.rate2 is None else target.rate2
        with np.errstate(divide="ignore", invalid="ignore"):
            ain[a] = (want - a0) / (a1 - a0)
        eva = pol.acceleration.evaluate(ain, values=evv.values, tol=tol, strict=False)
        return evv, eva

    def solve(self, dv: Array) -> _Block:
        """Everything at the drive values ``dv``: one block of a sweep."""
        if self.method == "analytic":
            return self._analytic(dv)
        if self.combined is not None:
            given: dict[str, Any] = dict(self.held)
            given.update(self.rate_given)
            given.update(self.inputs_at(dv))
            ev = self.combined.evaluate_for(self.keep, given, tol=self.tol, strict=False)
            fa = ev.failed_at
            assembled = None
            if fa is not None:
                assembled = ~((fa >= 0) & (fa < self.n_posture))
            return _Block(dv, ev, ev, ev, assembled=assembled)
        ev = self.posture(dv)
        if self.pol is None:
            return _Block(dv, ev, None, None)
        evv, eva = self.rates(ev)
        return _Block(dv, ev, evv, eva)

    def _analytic(self, dv: Array) -> _Block:
        from graphkin.kinematics.analytic import solve_analytic_many

        mech = self.mech
        full = np.empty((len(dv), len(mech.drives)))
        for i, d in enumerate(mech.drives):
            full[:, i] = dv if i == 0 else d.value if d.law is None else d.law.value(dv)
        sol = solve_analytic_many(mech, full, tol=self.tol)
        near = self.at_limit(dv)
        if near.any():
            _blank_rates(sol, near)
        return _Block(dv, None, None, None, sol)

    def at_limit(self, dv: Array) -> Array:
        """Drive values within round-off of a limit position found by :func:`_travel`.

        At a dead center at the end of a slider drive's travel (Sec. 1.10) the
        velocity equations are singular: the rates at a drive value within
        ``VERDICT_REL`` of the size of the mechanism from it are set by the
        round-off of that value (the end found by bisection lies within ~1e-12
        of the size of it), not by the mechanism.  The constructions leave such
        rates empty at their tangency; so does the analytic solver here.
        """
        dv = np.asarray(dv, dtype=float)
        limits = self.extras.get(("limits", self.drive.value), ())
        near = np.zeros(dv.shape, dtype=bool)
        if self.drive.is_angle:  # a travel: a slider's, or a point's coordinate
            return near
        for x in limits:
            near |= np.abs(dv - x) <= VERDICT_REL * self.mech.scale
        return near


@dataclass
class _Block:
    dv: Array
    ev: Evaluation | None
    evv: Evaluation | None
    eva: Evaluation | None
    analytic: Solution | None = None
    assembled: Array | None = None
    user: Array | None = None


_ENGINES: dict[int, tuple[weakref.ref[Mechanism], Tolerance, _Engine]] = {}


def _engine(mech: Mechanism, tol: Tolerance) -> _Engine:
    """The engine of ``mech``, built once per mechanism object and tolerance."""
    key = id(mech)
    hit = _ENGINES.get(key)
    if hit is not None and hit[0]() is mech and hit[1] == tol:
        return hit[2]
    eng = _Engine(mech, tol)
    if len(_ENGINES) > 64:
        for k in [k for k, v in _ENGINES.items() if v[0]() is None]:
            del _ENGINES[k]
    _ENGINES[key] = (weakref.ref(mech), tol, eng)
    return eng


def _dyads(pc: PostureConstruction) -> list[tuple[str, str, str]]:
    """(pin, first center, second center) of every case-4 group of two arcs."""
    cx = pc.construction
    out = []
    for s in cx.steps:
        if s.op != "intersect_circles" or s.label not in pc.branches:
            continue
        centers = []
        for k in s.inputs:
            src = cx.step_of(k)
            if src.op != "circle":
                break
            centers.append(src.inputs[0])
        else:
            if not s.label.count(":"):
                out.append((s.outputs[0], centers[0], centers[1]))
    return out


def _blank_rates(sol: Solution, rows: Array) -> None:
    """NaN rates (velocities and accelerations) at ``rows``; the postures are kept."""
    for st in sol.links.values():
        for name in ("omega", "alpha", "origin_velocity", "origin_acceleration"):
            a = getattr(st, name)
            if a is not None:
                a = np.array(a, dtype=float)
                a[rows] = np.nan
                setattr(st, name, a)
