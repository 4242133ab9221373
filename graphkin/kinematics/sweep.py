"""Whole cycles at once: the recorded constructions evaluated on arrays of drive values.

A sweep runs the *same* constructions as :func:`graphkin.solve` -- the posture
groups of Sec. 2.8 and the velocity and acceleration polygons of Secs. 3.4-4.6
-- once, on whole arrays of drive values (shape ``(N,)``), with no Python
loop over postures.  The constructions are built once at the file's posture,
where every two-way choice is named (``left``/``right`` of the directed line
of centers, ``behind``/``ahead`` along a line); the sweep keeps those names.

Branch continuity
-----------------
Each posture continues the assembly of the one before because the *named*
branch is kept: the side of C relative to the directed line from the first
circle's center to the second's can only change where the two intersections
coincide (the arcs are tangent: the linkage is at a dead center, its
transmission angle 0° or 180°) or where the two centers coincide.  Away from
those postures, keeping the name is keeping continuity.  Where the branches
meet the sweep reports it (:attr:`Sweep.singular`): at the ends of a range
where the linkage cannot be assembled, and at a change point, where the
branches touch without a gap and the sweep goes on with the same name.

Several drives
--------------
The first drive is swept; every other drive is held at its value in the
file (and its rates, if any, apply at every posture).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 1.9 (Grashof's law, Eq. 1.6), Sec. 1.10 (transmission angle, toggle and
dead-center postures), Sec. 2.8 (posture), Secs. 3.4-3.6 and 4.2-4.6
(polygons), Sec. 5.4 (several inputs).
"""

from __future__ import annotations

import csv
import dataclasses
import io
import math
import weakref
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import IO, Any

import numpy as np

from graphkin.construction import Construction, Evaluation
from graphkin.errors import AssemblyError, GraphkinError, InputError
from graphkin.geometry import ops as g
from graphkin.kinematics.polygons import Polygons, build_polygons
from graphkin.kinematics.posture import NotDecomposable, PostureConstruction, build_posture
from graphkin.kinematics.solution import Solution
from graphkin.kinematics.solve import link_states
from graphkin.mechanisms.model import FRAME, Drive, Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = [
    "Sweep",
    "SingularPosture",
    "sweep",
    "wrap_degrees",
    "FourBar",
    "fourbar",
    "Grashof",
    "grashof",
    "transmission_angle",
]

Array = np.ndarray

#: Sweeps longer than this are evaluated in blocks (so a progress callback can be told).
BLOCK = 100_000


def wrap_degrees(rad: Any) -> Array:
    """Angles (rad) as degrees in (-180, 180], element by element, as ``solve`` prints them.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.2 (angles measured counterclockwise from +x).

    Examples
    --------
    >>> wrap_degrees(np.array([np.pi, -np.pi, 3 * np.pi / 2, 0.25]))
    array([180.        , 180.        , -90.        ,  14.32394488])
    """
    d = np.degrees(np.asarray(rad, dtype=float))
    # d - 360 k with k = ceil((d - 180) / 360): the turn that brings d into (-180, 180]
    k = np.ceil((d - 180.0) * (1.0 / 360.0))
    d -= 360.0 * k
    return d


# ---------------------------------------------------------------------------
# the constructions of one mechanism, built once
# ---------------------------------------------------------------------------

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
        if mech.rolling:
            # away from the file's drive a roller's angle follows its travel (the no-slip
            # condition integrated), which no ruler-and-compass step gives
            self.method = "analytic"
            self.reason = ("rolling contact: the roller's angle follows its travel over the "
                           "sweep, so the analytic solver sweeps it")
            return
        try:
            self.pc = self._build(mech, tol)
        except NotDecomposable as exc:
            self.method = "analytic"
            self.reason = str(exc)
            return
        d = self.drive
        self.label = f"θ{d.link}" if d.kind == "angle" else f"s{d.link}"
        if self.label not in self.pc.inputs:  # pragma: no cover - the builder names them so
            raise GraphkinError(f"the posture construction has no input {self.label!r}")
        self.held = {k: v for k, v in self.pc.inputs.items() if k != self.label}
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

    def _build(self, mech: Mechanism, tol: Tolerance) -> PostureConstruction:
        """The posture construction, laid out at the file's drive if it assembles there.

        Otherwise it is laid out at the first drive angle of the turn where it
        can (its branches then follow the assembly hints at that posture).
        """
        try:
            return build_posture(mech, tol)
        except AssemblyError:
            d = self.drive
            if d.kind != "angle":
                raise
            for k in range(1, 360):
                moved = dataclasses.replace(d, value=d.value + math.radians(k))
                drives = tuple(moved if x is d else x for x in mech.drives)
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
        given[self.label] = dv
        return self.pc.construction.evaluate(given, tol=self.tol, strict=False)

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
            if unit:
                vin[w] = 1.0 if d is self.drive else 0.0
                ain[a] = 0.0
            else:
                vin[w] = 0.0 if d.rate is None else d.rate
                ain[a] = 0.0 if d.rate2 is None else d.rate2
        if mech.rates is not None and not unit:
            return self._scaled_rates(ev, vin, ain)
        evv = pol.velocity.evaluate(vin, values=ev.values, tol=self.tol, strict=False)
        eva = pol.acceleration.evaluate(ain, values=evv.values, tol=self.tol, strict=False)
        return evv, eva

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
            given[self.label] = dv
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
            full[:, i] = dv if i == 0 else d.value
        sol = solve_analytic_many(mech, full, tol=self.tol)
        return _Block(dv, None, None, None, sol)


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


# ---------------------------------------------------------------------------
# columns
# ---------------------------------------------------------------------------

def _xy_rows(a: Any, n: int, unit: bool) -> tuple[Array, Array]:
    """The x and y rows (length ``n``) of a point array of shape (3,) or (n, 3)."""
    a = np.asarray(a, dtype=float)
    if a.ndim == 1:
        x, y = g.xy(a)
        return np.full(n, x), np.full(n, y)
    if unit or bool(np.all(a[:, 2] == 1.0)):
        return a[:, 0], a[:, 1]
    q = g.xy(a)
    return q[:, 0], q[:, 1]


def _full(v: Any, n: int) -> Array:
    v = np.asarray(v, dtype=float)
    if v.shape == (n,):
        return v
    if v.ndim == 0:
        return np.full(n, float(v))
    return np.broadcast_to(v, (n,)).copy()


def _recipe(eng: _Engine) -> list[tuple[str, str, int, str, int]] | None:
    """Where every column comes from: (name, kind, phase, label, component), or None.

    ``kind`` is ``zero``, ``angle`` (θ in rad), ``scalar`` (ω, α) or ``row`` (a
    component of a point); ``phase`` 0, 1, 2 for the posture, velocity and
    acceleration constructions.  None when some point is not constructed by name.
    """
    mech, pc, pol = eng.mech, eng.pc, eng.pol
    assert pc is not None
    rated = mech.has_rates
    out: list[tuple[str, str, int, str, int]] = []
    for lid in mech.links:
        if lid == FRAME:
            out.append((f"angle_{lid}", "zero", 0, "", 0))
            if rated:
                out += [(f"omega_{lid}", "zero", 0, "", 0), (f"alpha_{lid}", "zero", 0, "", 0)]
            continue
        out.append((f"angle_{lid}", "angle", 0, pc.angles[lid], 0))
        if rated:
            out += [(f"omega_{lid}", "scalar", 1, f"ω{lid}", 0),
                    (f"alpha_{lid}", "scalar", 2, f"α{lid}", 0)]
    labels = set(pc.construction.labels)
    for name in mech.point_names:
        if name not in labels:
            return None
        out += [(f"x_{name}", "row", 0, name, 0), (f"y_{name}", "row", 0, name, 1)]
        if rated:
            assert pol is not None
            vi, ai = pol.velocity_images.get(name), pol.acceleration_images.get(name)
            if vi is None or ai is None:
                return None
            out += [(f"vx_{name}", "row", 1, vi, 0), (f"vy_{name}", "row", 1, vi, 1),
                    (f"ax_{name}", "row", 2, ai, 0), (f"ay_{name}", "row", 2, ai, 1)]
    return out


def _columns(eng: _Engine, blk: _Block) -> dict[str, Array]:
    """The columns of ``spec/sweep.md`` for one block."""
    mech = eng.mech
    dv = blk.dv
    n = len(dv)
    cols: dict[str, Array] = {}
    cols["drive"] = blk.user if blk.user is not None else (
        np.degrees(dv) if eng.drive.kind == "angle" else np.array(dv, dtype=float))
    if blk.analytic is not None:
        return _columns_of_solution(mech, blk.analytic, cols, n, mech.has_rates)
    if eng.recipe is False:
        eng.recipe = _recipe(eng)
    evals = [e for e in (blk.ev, blk.evv, blk.eva)]
    recipe = eng.recipe
    if recipe is None or any(e is not None and any(
            r[3] not in e.values for r in recipe if r[2] == k and r[1] != "zero")
            for k, e in enumerate(evals)):
        return _columns_slow(eng, blk, cols)
    zero = np.zeros(n)
    consts = eng.const_rows
    xys: dict[tuple[int, str], Any] = {}
    for name, kind, phase, lab, comp in recipe:
        if kind == "zero":
            cols[name] = zero
            continue
        e = evals[phase]
        assert e is not None
        a = e.values[lab]
        if kind == "row":
            if type(a) is not np.ndarray or a.ndim != 2:
                v = consts.get((lab, comp))
                if v is None:
                    v = consts[(lab, comp)] = float(g.xy(np.asarray(a, dtype=float))[comp])
                cols[name] = zero if v == 0.0 else np.full(n, v)
            elif lab in e.unit:
                cols[name] = a[:, comp]
            else:
                q = xys.get((phase, lab))
                if q is None:
                    q = xys[(phase, lab)] = g.xy(a)
                cols[name] = q[:, comp]
        elif kind == "angle":
            cols[name] = wrap_degrees(a if type(a) is np.ndarray and a.shape == (n,)
                                      else _full(a, n))
        else:
            cols[name] = a if type(a) is np.ndarray and a.shape == (n,) else _full(a, n)
    return cols


def _columns_slow(eng: _Engine, blk: _Block, cols: dict[str, Array]) -> dict[str, Array]:
    """The columns read one by one (a point not constructed by name comes from its link)."""
    mech = eng.mech
    n = len(blk.dv)
    rated = mech.has_rates
    pc, pol, ev = eng.pc, eng.pol, blk.ev
    assert pc is not None and ev is not None
    pv = ev.values
    vv = blk.evv.values if blk.evv is not None else {}
    av = blk.eva.values if blk.eva is not None else {}
    vunit = blk.evv.unit if blk.evv is not None else frozenset()
    aunit = blk.eva.unit if blk.eva is not None else frozenset()
    zero = np.zeros(n)
    for lid in mech.links:
        if lid == FRAME:
            cols[f"angle_{lid}"] = zero
            if rated:
                cols[f"omega_{lid}"] = zero
                cols[f"alpha_{lid}"] = zero
            continue
        cols[f"angle_{lid}"] = wrap_degrees(_full(pv[pc.angles[lid]], n))
        if rated:
            cols[f"omega_{lid}"] = _full(vv[f"ω{lid}"], n)
            cols[f"alpha_{lid}"] = _full(av[f"α{lid}"], n)
    missing: list[str] = []
    for name in mech.point_names:
        if name not in pv:
            missing.append(name)
            continue
        images: tuple[str, str] | None = None
        if rated:
            assert pol is not None
            vi, ai = pol.velocity_images.get(name), pol.acceleration_images.get(name)
            if vi is None or ai is None or vi not in vv or ai not in av:
                missing.append(name)
                continue
            images = (vi, ai)
        x, y = _xy_rows(pv[name], n, name in ev.unit)
        cols[f"x_{name}"], cols[f"y_{name}"] = x, y
        if images is not None:
            vi, ai = images
            vx, vy = _xy_rows(vv[vi], n, vi in vunit)
            ax, ay = _xy_rows(av[ai], n, ai in aunit)
            cols[f"vx_{name}"], cols[f"vy_{name}"] = vx, vy
            cols[f"ax_{name}"], cols[f"ay_{name}"] = ax, ay
    if missing:
        sol = _solution_of_block(eng, blk)
        for name in missing:
            _point_columns(sol, name, cols, rated)
        order = _column_order(mech, rated)
        known = set(order)
        cols = {k: cols[k] for k in order if k in cols} | \
            {k: v for k, v in cols.items() if k not in known}
    return cols


def _column_order(mech: Mechanism, rated: bool) -> list[str]:
    names = ["drive"]
    for lid in mech.links:
        names.append(f"angle_{lid}")
        if rated:
            names += [f"omega_{lid}", f"alpha_{lid}"]
    for p in mech.point_names:
        names += [f"x_{p}", f"y_{p}"]
        if rated:
            names += [f"vx_{p}", f"vy_{p}", f"ax_{p}", f"ay_{p}"]
    return names


def _point_columns(sol: Solution, name: str, cols: dict[str, Array], rated: bool) -> None:
    p = sol.position(name)
    cols[f"x_{name}"], cols[f"y_{name}"] = p[..., 0], p[..., 1]
    if rated:
        v, a = sol.velocity(name), sol.acceleration(name)
        cols[f"vx_{name}"], cols[f"vy_{name}"] = v[..., 0], v[..., 1]
        cols[f"ax_{name}"], cols[f"ay_{name}"] = a[..., 0], a[..., 1]


def _columns_of_solution(mech: Mechanism, sol: Solution, cols: dict[str, Array], n: int,
                         rated: bool) -> dict[str, Array]:
    for lid in mech.links:
        cols[f"angle_{lid}"] = wrap_degrees(_full(sol.angle_rad(lid), n))
        if rated:
            cols[f"omega_{lid}"] = _full(sol.omega(lid), n)
            cols[f"alpha_{lid}"] = _full(sol.alpha(lid), n)
    for name in mech.point_names:
        _point_columns(sol, name, cols, rated)
    return cols


def _solution_of_block(eng: _Engine, blk: _Block) -> Solution:
    if blk.analytic is not None:
        return blk.analytic
    mech, pc = eng.mech, eng.pc
    assert pc is not None and blk.ev is not None
    pv = dict(blk.ev.values)
    if eng.label not in pv or np.shape(pv[eng.label]) != np.shape(blk.dv):
        pv[eng.label] = blk.dv
    vv = blk.evv.values if blk.evv is not None else None
    av = blk.eva.values if blk.eva is not None else None
    states = link_states(mech, pc, pv, vv, av, eng.pol)
    constructions = {"posture": pc.construction}
    values = {"posture": pv}
    if eng.pol is not None and vv is not None and av is not None:
        constructions["velocity"] = eng.pol.velocity
        constructions["acceleration"] = eng.pol.acceleration
        values["velocity"] = vv
        values["acceleration"] = av
    return Solution(mech, states, "construction", constructions, valid=_valid_of(blk),
                    notes=list(pc.notes), branches=dict(pc.branches), values=values)


def _valid_of(blk: _Block) -> Array:
    n = len(blk.dv)
    if blk.ev is not None and blk.ev is blk.evv and blk.ev.failed_at is None:
        return np.ones(n, dtype=bool)
    if blk.analytic is not None:
        return np.broadcast_to(np.asarray(blk.analytic.valid), (n,)).copy()
    assert blk.ev is not None  # a block is either analytic or has its posture replay
    ok = np.broadcast_to(np.asarray(blk.ev.valid), (n,)).copy()
    for e in (blk.evv, blk.eva):
        if e is not None and e is not blk.ev:
            ok &= np.broadcast_to(np.asarray(e.valid), (n,))
    return ok


def _assembled_of(blk: _Block) -> Array:
    n = len(blk.dv)
    if blk.analytic is not None:
        return np.broadcast_to(np.asarray(blk.analytic.valid), (n,)).copy()
    if blk.assembled is not None:
        return np.broadcast_to(blk.assembled, (n,)).copy()
    if blk.ev is blk.evv:  # one replay of everything, nothing failed
        return np.ones(n, dtype=bool)
    assert blk.ev is not None  # a block is either analytic or has its posture replay
    return np.broadcast_to(np.asarray(blk.ev.valid), (n,)).copy()


# ---------------------------------------------------------------------------
# the sweep
# ---------------------------------------------------------------------------

@dataclass(frozen=True)
class SingularPosture:
    """A special posture met by a sweep, located to the drive value.

    Attributes
    ----------
    kind : str
        ``"cannot-assemble"`` (a range: ``drive`` to ``end``), ``"dead-center"``
        (the two branches of ``label`` meet: the arcs are tangent, the
        transmission angle is 0° or 180°), or ``"limit"`` (a link pinned to the
        frame stops and turns back: ``ω = 0``; for a crank-rocker driven by its
        crank this is the toggle posture of Sec. 1.10, crank and coupler in line).
    drive : float
        The drive value (degrees, or the slider's travel).
    end : float or None
        The end of a range.
    label : str
        The construction step (``"C"``) or the link (``"4"``).
    note : str
        One line for the report.
    change_point : bool
        A dead center inside an assembled range: the branches touch without a
        gap, and beyond it the named branch need not be the continuous motion.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 1.10 (toggle and dead-center postures).
    """

    kind: str
    drive: float
    end: float | None
    label: str
    note: str
    change_point: bool = False


@dataclass
class Sweep:
    """A mechanism solved over many drive values at once.

    Attributes
    ----------
    mechanism : Mechanism
    drive : Drive
        The swept drive (the first one; the others are held at the file's values).
    values : ndarray, shape (N,)
        The drive values: radians for an angle, the file's length unit for a slider.
    columns : dict
        CSV column name (``spec/sweep.md``) -> 1-D array of length N; NaN
        where the posture cannot be assembled (and, for the rates only,
        where they are not defined).
    valid : ndarray of bool
        Postures that assemble and whose rates are finite.
    assembled : ndarray of bool
        Postures that assemble.
    method : str
        ``"construction"``, or ``"analytic"`` when the mechanism cannot be solved
        one group at a time (``notes`` says why).
    notes : list of str
    branches : dict
        Step label -> the branch kept through the sweep.

    Notes
    -----
    ``solution`` (the sweep as a :class:`Solution`), ``singular`` (ranges,
    dead centers, limit positions) and ``unassembled`` are computed when first
    asked for.  The evaluated constructions keep only the values the sweep
    reports (named points, link angles, rates and their images).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 2.8, 3.4-3.6, 4.2-4.6.

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... D = [10, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [4, 0]
    ... [links.3]
    ... B = [0, 0]
    ... C = [12, 0]
    ... [links.4]
    ... D = [0, 0]
    ... C = [11, 0]
    ... [drive]
    ... link = 2
    ... angle = 120
    ... omega = 10
    ... [assembly]
    ... C = [9, 11]
    ... ''')
    >>> sw = mech.sweep(count=8)
    >>> sw.columns["drive"]
    array([120., 165., 210., 255., 300., 345., 390., 435.])
    >>> bool(sw.valid.all()), list(sw.columns)[:5]
    (True, ['drive', 'angle_1', 'omega_1', 'alpha_1', 'angle_2'])
    """

    mechanism: Mechanism
    drive: Drive
    values: Array
    columns: dict[str, Array]
    valid: Array
    assembled: Array
    method: str = "construction"
    notes: list[str] = field(default_factory=list)
    branches: dict[str, str] = field(default_factory=dict)
    _engine: _Engine | None = field(default=None, repr=False, compare=False)
    _blocks: list[_Block] = field(default_factory=list, repr=False, compare=False)
    _cyclic: bool = field(default=False, repr=False, compare=False)

    def __len__(self) -> int:
        return len(self.values)

    @property
    def drive_values(self) -> Array:
        """The drive values as written in the CSV: degrees, or the slider's travel."""
        return self.columns["drive"]

    @cached_property
    def solution(self) -> Solution:
        """The sweep as a :class:`Solution` whose arrays have the leading shape (N,)."""
        assert self._engine is not None
        sols = [_solution_of_block(self._engine, b) for b in self._blocks]
        if len(sols) == 1:
            return sols[0]
        return _concat_solutions(sols)

    @cached_property
    def singular(self) -> list[SingularPosture]:
        """Ranges that cannot be assembled, dead centers and limit positions, in drive order.

        Boundaries are refined by bisection on the drive (to well below 0.01°).
        """
        return _singular(self)

    @property
    def unassembled(self) -> list[tuple[float, float]]:
        """Drive ranges (degrees or travel) where the mechanism cannot be assembled."""
        return [(s.drive, s.end if s.end is not None else s.drive) for s in self.singular
                if s.kind == "cannot-assemble"]

    def report(self, events: bool = False) -> list[str]:
        """Lines for standard error: notes, unassemblable ranges (and, with ``events``, the rest).

        Dead centers inside an assembled range (a change point, where the
        named branch may stop being the continuous one) are always reported.
        """
        out = list(self.notes)
        for s in self.singular:
            if s.kind == "cannot-assemble" or events:
                out.append(s.note)
            elif s.change_point:
                out.append(s.note)
        return out

    def to_csv(self, file: str | IO[str]) -> None:
        """Write the columns as CSV: one row per posture; empty cells where not defined."""
        if isinstance(file, str):
            with open(file, "w", newline="", encoding="utf-8") as fh:
                self._write(fh)
        else:
            self._write(file)

    def csv_text(self) -> str:
        """The CSV as a string."""
        buf = io.StringIO()
        self._write(buf)
        return buf.getvalue()

    def _write(self, fh: IO[str]) -> None:
        w = csv.writer(fh, lineterminator="\n")
        names = list(self.columns)
        w.writerow(names)
        cols = []
        for name in names:
            c = np.asarray(self.columns[name], dtype=float)
            lst: list[Any] = c.tolist()
            if not np.isfinite(c).all():
                lst = ["" if not math.isfinite(v) else v for v in lst]
            cols.append(lst)
        w.writerows(zip(*cols))


def _concat_solutions(sols: Sequence[Solution]) -> Solution:
    from graphkin.kinematics.solution import LinkState

    first = sols[0]
    links = {}
    for lid in first.links:
        parts = [s.links[lid] for s in sols]

        def cat(attr: str, parts: list[Any] = parts) -> Array | None:
            vals = [getattr(p, attr) for p in parts]
            if any(v is None for v in vals):
                return None
            return np.concatenate([np.atleast_1d(v) for v in vals], axis=0)

        angle, origin = cat("angle"), cat("origin")
        assert angle is not None and origin is not None  # every link state has both
        links[lid] = LinkState(angle, origin, cat("omega"), cat("alpha"),
                               cat("origin_velocity"), cat("origin_acceleration"))
    valid = np.concatenate([np.atleast_1d(s.valid) for s in sols])
    return Solution(first.mechanism, links, first.method, first.constructions, valid=valid,
                    notes=list(first.notes), branches=dict(first.branches))


def _drive_range(eng: _Engine, start: float | None, stop: float | None) -> tuple[float, float,
                                                                                 bool]:
    """Start and stop as the user writes them (degrees or travel), and whether it is one turn."""
    d = eng.drive
    if d.kind == "angle":
        # the file's angle as written (degrees), free of the round trip through radians
        a = round(math.degrees(d.value), 10) if start is None else float(start)
        b = a + 360.0 if stop is None else float(stop)
        return a, b, math.isclose(abs(b - a), 360.0, rel_tol=1e-12)
    if start is not None and stop is not None:
        return float(start), float(stop), False
    lo, hi = _travel(eng)
    return (lo if start is None else float(start)), (hi if stop is None else float(stop)), False


def _travel(eng: _Engine) -> tuple[float, float]:
    """The travel of a slider drive over which the mechanism assembles, around the file's value.

    Searched outward up to four times the size of the mechanism, then
    refined by bisection.
    """
    d, mech = eng.drive, eng.mech
    reach = 4.0 * mech.scale
    ok = _assembles(eng)
    out = []
    for sign in (-1.0, 1.0):
        xs = d.value + sign * reach * np.linspace(0.0, 1.0, 401)
        good = ok(xs)
        if not good[0]:
            raise AssemblyError(f"cannot assemble at the file's travel {d.value:g}",
                                key="drive", file=mech.source)
        bad = np.flatnonzero(~good)
        if bad.size == 0:
            out.append(float(xs[-1]))
            continue
        k = int(bad[0])
        lo, hi = _bisect(ok, np.array([xs[k - 1]]), np.array([xs[k]]))
        out.append(float(lo[0]))
    return min(out), max(out)


def _assembles(eng: _Engine) -> Callable[[Array], Array]:
    """Drive values (internal units) -> whether the posture assembles there."""
    if eng.method == "analytic":
        def ok_analytic(x: Array) -> Array:
            blk = eng.solve(np.atleast_1d(np.asarray(x, dtype=float)))
            return _assembled_of(blk)
        return ok_analytic

    def ok(x: Array) -> Array:
        x = np.atleast_1d(np.asarray(x, dtype=float))
        ev = eng.posture(x)
        return np.broadcast_to(np.asarray(ev.valid), x.shape).copy()

    return ok


def _bisect(ok: Callable[[Array], Array], good: Array, bad: Array,
            steps: int = 48) -> tuple[Array, Array]:
    """Narrow pairs (good, bad) of drive values around the boundaries of ``ok``."""
    good, bad = good.astype(float).copy(), bad.astype(float).copy()
    for _ in range(steps):
        mid = 0.5 * (good + bad)
        m = ok(mid)
        good = np.where(m, mid, good)
        bad = np.where(m, bad, mid)
    return good, bad


def sweep(mech: Mechanism, count: int = 360, start: float | None = None,
          stop: float | None = None, *, tol: Tolerance | None = None,
          transmission: bool = False, centers: bool = False, curvature: bool = False,
          progress: Callable[[float], None] | None = None) -> Sweep:
    """Solve a mechanism over ``count`` values of its (first) drive, all at once.

    Parameters
    ----------
    mech : Mechanism
    count : int
        Number of postures.
    start, stop : float, optional
        The drive range, as ``--from``/``--to`` of ``graphkin sweep``: degrees
        for a revolute drive, the travel in the file's length unit for a slider.
        Defaults: from the file's drive angle through one full turn (``stop``
        excluded); for a slider, the travel over which the mechanism assembles
        around the file's position.  The drive values are
        ``start + (stop - start) k / count``, ``k = 0 .. count - 1``.
    tol : Tolerance, optional
    transmission : bool
        Add ``transmission_<P>`` columns: the transmission angle (degrees,
        0-180) at each pin found by two arcs (case 4), between the two links'
        lines to their centers (Sec. 1.10).
    centers : bool
        Add the instant centers: ``x_I<i><j>``, ``y_I<i><j>`` (empty at
        infinity) and, for a center that goes to infinity, its direction
        ``dx_I<i><j>``, ``dy_I<i><j>`` (when :mod:`graphkin.kinematics.instant_centers`
        is installed).
    curvature : bool
        Add the radius and center of curvature of every moving point's path,
        ``rho_<P>``, ``cx_<P>``, ``cy_<P>`` (Eq. 4.49), and every moving link's
        inflection pole and inflection-circle diameter, ``jx_<k>``, ``jy_<k>``,
        ``inflection_diameter_<k>`` (Sec. 4.15), when the file gives rates.
    progress : callable, optional
        Called with the fraction done, for long sweeps (evaluated in blocks of
        :data:`BLOCK` postures).

    Returns
    -------
    Sweep

    Raises
    ------
    InputError
        A count below 1, or no drive.
    AssemblyError
        The mechanism cannot be assembled at the file's posture (where the
        branches are chosen).

    Notes
    -----
    The constructions are built once per mechanism (branches chosen at the
    file's posture by the assembly hints) and evaluated on whole arrays; the
    named branches are kept through the sweep (see the module notes on
    continuity).  With several drives the first is swept and the others are
    held at the file's values (their rates, if given, apply throughout).
    Mechanisms that cannot be solved one group at a time are solved by
    :func:`graphkin.kinematics.analytic.solve_analytic_many` (Newton-Raphson,
    each posture from the one before), and ``method`` and ``notes`` say so.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (posture), Secs. 3.4-3.6 and
    4.2-4.6 (polygons), Sec. 1.10 (transmission angle).

    Examples
    --------
    A crank-rocker (crank 4, coupler 12, rocker 11, frame 10) through one turn
    of its crank at 10 rad/s:

    >>> import graphkin
    >>> mech = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... D = [10, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [4, 0]
    ... [links.3]
    ... B = [0, 0]
    ... C = [12, 0]
    ... [links.4]
    ... D = [0, 0]
    ... C = [11, 0]
    ... [drive]
    ... link = 2
    ... angle = 0
    ... omega = 10
    ... [assembly]
    ... C = [9, 11]
    ... ''')
    >>> sw = sweep(mech, count=3600)
    >>> sw.columns["omega_3"].shape
    (3600,)
    >>> round(float(sw.columns["angle_4"][0]), 4)  # 180° - acos((6² + 11² - 12²)/(2·6·11))
    95.6519
    """
    if int(count) != count or count < 1:
        raise InputError(f"the number of postures must be a whole number of at least 1, not "
                         f"{count!r}", key="count", file=mech.source)
    count = int(count)
    tol = tol or DEFAULT_TOL
    eng = _engine(mech, tol)
    a, b, cyclic = _drive_range(eng, start, stop)
    user = a + (b - a) * (np.arange(count, dtype=float) / count)
    dv = np.radians(user) if eng.drive.kind == "angle" else user
    blocks: list[_Block] = []
    if count <= BLOCK:
        blk = eng.solve(dv)
        blk.user = user
        blocks.append(blk)
        cols = _columns(eng, blk)
    else:
        parts = []
        for i in range(0, count, BLOCK):
            blk = eng.solve(dv[i:i + BLOCK])
            blk.user = user[i:i + BLOCK]
            blocks.append(blk)
            parts.append(_columns(eng, blk))
            if progress is not None:
                progress(min(1.0, (i + BLOCK) / count))
        cols = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    if len(blocks) == 1:
        valid, assembled = _valid_of(blocks[0]), _assembled_of(blocks[0])
    else:
        valid = np.concatenate([_valid_of(blk) for blk in blocks])
        assembled = np.concatenate([_assembled_of(blk) for blk in blocks])
    notes: list[str] = []
    if eng.built_at is not None:
        notes.append(f"the file's drive cannot be assembled; the constructions were laid out "
                     f"at {math.degrees(eng.built_at):.2f}° (branches by the assembly hints there)")
    if eng.method == "analytic":
        notes.append("solved by the analytic solver (Newton-Raphson, each posture from the one "
                     f"before): {eng.reason}")
    if not valid.all():
        _blank(cols, assembled, valid)
    sw = Sweep(mech, eng.drive, dv, cols, valid, assembled, eng.method, notes,
               dict(eng.pc.branches) if eng.pc is not None else {}, eng, blocks, cyclic)
    if transmission:
        sw.columns.update(_transmission_columns(sw))
    if centers:
        sw.columns.update(_center_columns(sw))
    if curvature:
        sw.columns.update(_curvature_columns(sw))
    return sw


def _blank(cols: dict[str, Array], assembled: Array, valid: Array) -> None:
    """NaN where a posture cannot be assembled (every column but the drive)."""
    for k, c in cols.items():
        if k == "drive":
            continue
        c = np.array(c, dtype=float)
        c[~assembled] = np.nan
        c[~np.isfinite(c)] = np.nan
        if k[:2] in ("vx", "vy", "ax", "ay") or k.startswith(("omega_", "alpha_")):
            c[~valid] = np.nan
        cols[k] = c


# ---------------------------------------------------------------------------
# extra columns
# ---------------------------------------------------------------------------

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


def _angle_at(p: Array, a: Array, b: Array) -> Array:
    """The angle APB in degrees, 0-180."""
    u = g.xy(a) - g.xy(p)
    v = g.xy(b) - g.xy(p)
    return np.degrees(np.arctan2(np.abs(g.cross2(u, v)), g.dot2(u, v)))


def _transmission_columns(sw: Sweep) -> dict[str, Array]:
    eng = sw._engine
    out: dict[str, Array] = {}
    if eng is None or eng.pc is None:
        try:
            fb = fourbar(sw.mechanism)
        except InputError:
            return out
        out[f"transmission_{fb.pins[2]}"] = transmission_angle(sw)
        return out
    for pin, c1, c2 in _dyads(eng.pc):
        parts = []
        for blk in sw._blocks:
            assert blk.ev is not None  # eng.pc is set: every block has its posture replay
            v = blk.ev.values
            m = len(blk.dv)
            parts.append(np.broadcast_to(_angle_at(v[pin], v[c1], v[c2]), (m,)))
        col = np.concatenate(parts).astype(float)
        col[~sw.assembled] = np.nan
        out[f"transmission_{pin}"] = col
    return out


def _center_columns(sw: Sweep) -> dict[str, Array]:
    try:
        from graphkin.kinematics.instant_centers import instant_centers
    except ImportError:
        return {}
    sol = sw.solution
    if not sol.has_rates:
        sol = _with_unit_rates(sw)
    ic = instant_centers(sol)
    out: dict[str, Array] = {}
    n = len(sw)
    for c in ic:
        p = np.asarray(c.point, dtype=float)
        p = np.broadcast_to(p, (n, 3)) if p.ndim == 1 else p
        ideal = p[:, 2] == 0.0
        with np.errstate(invalid="ignore", divide="ignore"):
            xy = g.xy(p)
        name = c.label
        x, y = xy[:, 0].copy(), xy[:, 1].copy()
        x[~sw.assembled] = np.nan
        y[~sw.assembled] = np.nan
        out[f"x_{name}"], out[f"y_{name}"] = x, y
        if ideal.any():
            d = np.where(ideal[:, None], p[:, :2], np.nan)
            out[f"dx_{name}"], out[f"dy_{name}"] = d[:, 0].copy(), d[:, 1].copy()
    return out


def _with_unit_rates(sw: Sweep) -> Solution:
    """The sweep's solution with the unit input speed (for centers of a posture-only file)."""
    eng = sw._engine
    assert eng is not None
    if eng.pc is None:
        return sw.solution
    if eng.pol is None:
        eng.pol = build_polygons(eng.mech, eng.pc)
    blocks = []
    for blk in sw._blocks:
        assert blk.ev is not None  # eng.pc is set: every block has its posture replay
        evv, eva = eng.rates(blk.ev, unit=True)
        blocks.append(_Block(blk.dv, blk.ev, evv, eva))
    sols = [_solution_of_block(eng, b) for b in blocks]
    return sols[0] if len(sols) == 1 else _concat_solutions(sols)


def _curvature_columns(sw: Sweep) -> dict[str, Array]:
    try:
        from graphkin.kinematics.curvature import inflection_pole, path_curvature
    except ImportError:
        return {}
    mech = sw.mechanism
    if not mech.has_rates:
        return {}
    sol = sw.solution
    out: dict[str, Array] = {}
    n = len(sw)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for lid in mech.moving:
            st = sol.links[lid]
            w = np.broadcast_to(np.asarray(st.omega, dtype=float), (n,))
            # the velocity pole: V_O + ω k × (I - O) = 0, so I = O + k × V_O / ω
            vo = np.asarray(st.origin_velocity, dtype=float)
            pole = np.asarray(st.origin) + np.stack([-vo[:, 1], vo[:, 0]], axis=-1) / w[:, None]
            c, s = np.cos(st.angle), np.sin(st.angle)
            r = pole - st.origin
            local = np.stack([c * r[:, 0] + s * r[:, 1], -s * r[:, 0] + c * r[:, 1]], axis=-1)
            a_pole = st.acceleration(local)
            j = inflection_pole(pole, a_pole, w)
            dia = np.hypot(*(j - pole).T)
            bad = ~sw.valid | (w == 0.0)
            for arr in (j[:, 0], j[:, 1], dia):
                arr[bad | ~np.isfinite(arr)] = np.nan
            out[f"jx_{lid}"], out[f"jy_{lid}"] = j[:, 0], j[:, 1]
            out[f"inflection_diameter_{lid}"] = dia
        for name in mech.point_names:
            if sol.owner(name) == FRAME:
                continue
            rho, center = path_curvature(sol.position(name), sol.velocity(name),
                                         sol.acceleration(name))
            rho = np.array(np.broadcast_to(rho, (n,)), dtype=float)
            center = np.array(np.broadcast_to(center, (n, 2)), dtype=float)
            bad = ~sw.valid | ~np.isfinite(rho)
            rho[bad] = np.nan
            center[bad | ~np.isfinite(center).all(axis=-1)] = np.nan
            out[f"rho_{name}"] = rho
            out[f"cx_{name}"], out[f"cy_{name}"] = center[:, 0], center[:, 1]
    return out


# ---------------------------------------------------------------------------
# singular postures
# ---------------------------------------------------------------------------

def _fmt(eng: _Engine, v: float) -> str:
    if eng.drive.kind == "angle":
        return f"{v:.2f}°"
    return f"{v:.4g}"


def _to_user(eng: _Engine, x: float) -> float:
    return math.degrees(x) if eng.drive.kind == "angle" else float(x)


def _runs(mask: Array) -> list[tuple[int, int]]:
    """Maximal runs of True as (first, last) indices."""
    if not mask.any():
        return []
    m = np.concatenate([[False], mask, [False]]).astype(int)
    d = np.diff(m)
    starts = np.flatnonzero(d == 1)
    ends = np.flatnonzero(d == -1) - 1
    return list(zip(starts.tolist(), ends.tolist()))


def _singular(sw: Sweep) -> list[SingularPosture]:
    eng = sw._engine
    assert eng is not None
    out: list[SingularPosture] = []
    dv = sw.values
    n = len(dv)
    if n == 0:
        return out
    period = 2 * math.pi if sw._cyclic else None
    bad = ~sw.assembled
    if bad.all():
        a, b = _to_user(eng, dv[0]), _to_user(eng, dv[-1])
        out.append(SingularPosture("cannot-assemble", a, b, "",
                                   f"cannot assemble for drive {_fmt(eng, a)} to {_fmt(eng, b)}"))
        return out

    def value(i: int) -> float:
        """Drive value of sample i, continued past either end of a full turn."""
        if i < 0:
            assert period is not None  # only a full turn continues past its ends
            return float(dv[i + n]) - period
        if i >= n:
            assert period is not None
            return float(dv[i - n]) + period
        return float(dv[i])

    # ---- ranges that cannot be assembled --------------------------------
    runs = _runs(bad)
    if period is not None and len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == n - 1:
        first = runs.pop(0)
        last = runs.pop()
        runs.append((last[0], first[1] + n))
    goods: list[float] = []
    bads: list[float] = []
    where: list[tuple[str, int]] = []
    for k, (i0, i1) in enumerate(runs):
        if i0 > 0 or period is not None:
            goods.append(value(i0 - 1))
            bads.append(value(i0))
            where.append(("start", k))
        if i1 < n - 1 or period is not None:
            goods.append(value(i1 + 1))
            bads.append(value(i1))
            where.append(("end", k))
    refined: dict[tuple[str, int], float] = {}
    if goods:
        gd: list[float] | Array
        if eng.method == "analytic":
            gd = _refine_analytic(sw, goods, bads)
        else:
            gd, _ = _bisect(_assembles(eng), np.array(goods), np.array(bads))
        refined = {key: float(v) for key, v in zip(where, gd)}
    failing = _failing_labels(sw)
    for k, (i0, i1) in enumerate(runs):
        a = refined.get(("start", k), value(i0))
        b = refined.get(("end", k), value(i1))
        ua, ub = _to_user(eng, a), _to_user(eng, b)
        lab = failing.get(i0 % n, "")
        out.append(SingularPosture("cannot-assemble", ua, ub, lab,
                                   f"cannot assemble for drive {_fmt(eng, ua)} to {_fmt(eng, ub)}"))
        if lab and eng.pc is not None and _is_branch(eng.pc.construction, lab):
            for key, v in ((("start", k), a), (("end", k), b)):
                if key in refined:
                    u = _to_user(eng, v)
                    out.append(SingularPosture(
                        "dead-center", u, None, lab,
                        f"dead center at {lab}: its two branches meet at drive {_fmt(eng, u)} "
                        "(an end of a range where it cannot be assembled)"))
    if eng.pc is not None:
        # ---- change points: the branches touch inside an assembled range -----
        out.extend(_change_points(sw, eng))
        # ---- limit positions of the links pinned to the frame ----------------
        out.extend(_limits(sw, eng))
    out.sort(key=lambda s: (s.drive, s.kind))
    return out


def _refine_analytic(sw: Sweep, goods: list[float], bads: list[float],
                     steps: int = 24) -> list[float]:
    """Bisection of assembly boundaries with Newton's method started from the assembled side."""
    from graphkin.kinematics.analytic import solve_analytic_many

    mech = sw.mechanism
    sol = sw.solution
    dv = sw.values
    period = 2 * math.pi if sw._cyclic else 0.0
    out = []
    for good, bad in zip(goods, bads):
        # the sample nearest the assembled side seeds Newton's method
        gap = dv - good
        if period:
            gap = np.remainder(gap + period / 2, period) - period / 2
        i = int(np.argmin(np.abs(gap)))
        guess = {lid: (float(sol.links[lid].origin[i, 0]), float(sol.links[lid].origin[i, 1]),
                       float(sol.links[lid].angle[i])) for lid in mech.moving}
        for _ in range(steps):
            mid = 0.5 * (good + bad)
            full = np.array([[mid if k == 0 else d.value for k, d in enumerate(mech.drives)]])
            s = solve_analytic_many(mech, full, guess)
            if bool(np.asarray(s.valid).reshape(-1)[0]):
                good = mid
                guess = {lid: (float(np.reshape(s.links[lid].origin, (-1, 2))[0, 0]),
                               float(np.reshape(s.links[lid].origin, (-1, 2))[0, 1]),
                               float(np.reshape(s.links[lid].angle, (-1,))[0]))
                         for lid in mech.moving}
            else:
                bad = mid
        out.append(good)
    return out


def _failing_labels(sw: Sweep) -> dict[int, str]:
    eng = sw._engine
    out: dict[int, str] = {}
    if eng is None or eng.pc is None:
        return out
    cx = eng.combined if eng.combined is not None else eng.pc.construction
    off = 0
    for blk in sw._blocks:
        assert blk.ev is not None  # eng.pc is set: every block has its posture replay
        fa = blk.ev.failed_at
        if fa is not None:
            fa = np.broadcast_to(fa, (len(blk.dv),))
            for i in np.flatnonzero(fa >= 0):
                out[off + int(i)] = cx[int(fa[i])].label
        off += len(blk.dv)
    return out


def _is_branch(cx: Construction, label: str) -> bool:
    try:
        return cx.step_of(label).branch is not None
    except KeyError:
        return False


def _separations(cx: Construction, values: dict[str, Array]) -> dict[str, Array]:
    """For every two-way step: the half-distance between its two answers over the figure size.

    Zero where the branches meet (tangent arcs, a tangent line).
    """
    out: dict[str, Array] = {}
    for s in cx.steps:
        if s.branch is None or any(i not in values for i in s.inputs):
            continue
        with np.errstate(invalid="ignore", divide="ignore"):
            if s.op == "intersect_circles":
                c1, c2 = (np.asarray(values[i], dtype=float) for i in s.inputs)
                d = c2[..., :2] - c1[..., :2]
                dist = np.hypot(d[..., 0], d[..., 1])
                r1, r2 = c1[..., 2], c2[..., 2]
                a = (dist**2 + r1**2 - r2**2) / (2 * dist)
                h = np.sqrt(np.maximum(r1**2 - a**2, 0.0))
                out[s.label] = h / np.maximum(r1, r2)
            elif s.op == "intersect_line_circle":
                line, c = (np.asarray(values[i], dtype=float) for i in s.inputs)
                dd = line[..., 0] * c[..., 0] + line[..., 1] * c[..., 1] + line[..., 2]
                r = c[..., 2]
                out[s.label] = np.sqrt(np.maximum(r**2 - dd**2, 0.0)) / r
    return out


def _change_points(sw: Sweep, eng: _Engine) -> list[SingularPosture]:
    assert eng.pc is not None
    cx = eng.pc.construction
    seps: dict[str, list[Array]] = {}
    for blk in sw._blocks:
        full = eng.posture(blk.dv)
        for k, v in _separations(cx, full.values).items():
            seps.setdefault(k, []).append(np.broadcast_to(v, (len(blk.dv),)))
    out: list[SingularPosture] = []
    dv = sw.values
    n = len(dv)
    for lab, parts in seps.items():
        sep = np.concatenate(parts)
        sep = np.where(sw.assembled, sep, np.inf)
        idx = [i for i in range(1, n - 1)
               if sep[i] <= sep[i - 1] and sep[i] <= sep[i + 1] and sep[i] < 0.05]
        for i in idx:
            lo, hi = dv[i - 1], dv[i + 1]

            def f(x: Array, lab: str = lab) -> Array:
                ev = eng.posture(np.atleast_1d(x))
                s = _separations(cx, ev.values).get(lab)
                if s is None:
                    return np.full(np.shape(x), np.inf)
                return np.where(np.broadcast_to(ev.valid, np.shape(s)), s, np.inf)

            gr = (math.sqrt(5) - 1) / 2
            for _ in range(60):
                m1 = hi - gr * (hi - lo)
                m2 = lo + gr * (hi - lo)
                v = f(np.array([m1, m2]))
                if v[0] <= v[1]:
                    hi = m2
                else:
                    lo = m1
            x = 0.5 * (lo + hi)
            if float(f(np.array([x]))[0]) < 1e-6:
                u = _to_user(eng, x)
                br = eng.pc.branches.get(lab, "")
                out.append(SingularPosture(
                    "dead-center", u, None, lab,
                    f"dead center at {lab}: its two branches meet at drive {_fmt(eng, u)} "
                    f"(change point); the sweep keeps the branch named {br!r}, which need not "
                    "be the continuous motion beyond it", change_point=True))
    return out


def _limits(sw: Sweep, eng: _Engine) -> list[SingularPosture]:
    """Where a link pinned to the frame stops and turns back (``ω = 0``)."""
    assert eng.pc is not None
    mech = eng.mech
    frame_pts = set(mech.links[FRAME].points)
    slid = {s.link for s in mech.sliders}
    cands = [lid for lid in mech.moving
             if lid != eng.drive.link and lid not in slid
             and frame_pts & set(mech.links[lid].points)
             and any(lid in p.links and FRAME in p.links for p in mech.pins)]
    if not cands:
        return []
    if eng.pol is None:
        eng.pol = build_polygons(mech, eng.pc)
    out: list[SingularPosture] = []
    dv = sw.values

    def omegas(x: Array) -> tuple[dict[str, Array], Array]:
        ev = eng.posture(np.atleast_1d(x))
        evv, _ = eng.rates(ev, unit=True)
        ok = np.broadcast_to(ev.valid & evv.valid, np.shape(x))
        return {lid: np.broadcast_to(np.asarray(evv[f"ω{lid}"]), np.shape(x)) for lid in cands}, ok

    w_all, ok_all = omegas(dv)
    for lid in cands:
        w = w_all[lid]
        s = np.sign(w)
        idx = np.flatnonzero(ok_all[:-1] & ok_all[1:] & (s[:-1] * s[1:] < 0))
        if idx.size == 0:
            continue
        lo, hi = dv[idx].astype(float), dv[idx + 1].astype(float)
        slo = s[idx]
        for _ in range(48):
            mid = 0.5 * (lo + hi)
            wm, _ok = omegas(mid)
            same = np.sign(wm[lid]) == slo
            lo = np.where(same, mid, lo)
            hi = np.where(same, hi, mid)
        x = 0.5 * (lo + hi)
        ev = eng.posture(x)
        th = np.broadcast_to(np.asarray(ev.values[eng.pc.angles[lid]]), x.shape)
        for xi, ti in zip(x, th):
            u = _to_user(eng, float(xi))
            out.append(SingularPosture(
                "limit", u, None, lid,
                f"limit position of link {lid} (ω{lid} = 0) at drive {_fmt(eng, u)}, "
                f"θ{lid} = {float(wrap_degrees(np.array([ti]))[0]):.2f}°"))
    return out


# ---------------------------------------------------------------------------
# four-bars: Grashof's law and the transmission angle
# ---------------------------------------------------------------------------

@dataclass(frozen=True)
class FourBar:
    """A four-bar linkage found in a mechanism: frame, input, coupler, output.

    Attributes
    ----------
    frame, input, coupler, output : str
        Link ids.  The input is the driven link when it is pinned to the frame.
    pins : (str, str, str, str)
        ``(A, B, C, D)``: frame-input, input-coupler, coupler-output, output-frame.
    lengths : dict
        Link id -> the distance between its two pins.
    """

    frame: str
    input: str
    coupler: str
    output: str
    pins: tuple[str, str, str, str]
    lengths: dict[str, float] = field(hash=False, compare=False)


def fourbar(mech: Mechanism) -> FourBar:
    """Recognise a four-bar linkage (four links, four pins) in a mechanism.

    Raises
    ------
    InputError
        The mechanism is not a four-bar of revolute pairs.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 1.9, Fig. 1.28.

    Examples
    --------
    >>> import graphkin
    >>> fb = fourbar(graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... D = [10, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [4, 0]
    ... [links.3]
    ... B = [0, 0]
    ... C = [12, 0]
    ... [links.4]
    ... D = [0, 0]
    ... C = [11, 0]
    ... [drive]
    ... link = 2
    ... angle = 45
    ... [assembly]
    ... C = [9, 11]
    ... '''))
    >>> fb.pins, fb.lengths
    (('A', 'B', 'C', 'D'), {'1': 10.0, '2': 4.0, '3': 12.0, '4': 11.0})
    """
    def fail(why: str) -> InputError:
        return InputError(f"not a four-bar linkage: {why}", file=mech.source)

    if len(mech.links) != 4 or mech.sliders or mech.slots:
        raise fail("it needs exactly four links joined by four pins and no sliders or slots")
    pins = [p for p in mech.pins if len(p.links) == 2]
    if len(pins) != 4 or len(mech.pins) != 4:
        raise fail("it needs four pins, each joining two links")
    grounded = [p for p in pins if FRAME in p.links]
    if len(grounded) != 2:
        raise fail("the frame must carry exactly two pins")
    side = {next(k for k in p.links if k != FRAME): p.name for p in grounded}
    if len(side) != 2:
        raise fail("the two frame pins must go to two different links")
    drive_link = mech.drives[0].link if mech.drives else None
    ids = list(side)
    inp = drive_link if drive_link in side else ids[0]
    out = next(k for k in ids if k != inp)
    coupler = next(k for k in mech.moving if k not in side)
    byp = {frozenset(p.links): p.name for p in pins}
    try:
        b = byp[frozenset((inp, coupler))]
        c = byp[frozenset((coupler, out))]
    except KeyError:
        raise fail("the coupler must be pinned to both links that turn about the frame") from None
    a, d = side[inp], side[out]

    def length(lid: str, p: str, q: str) -> float:
        pts = mech.links[lid].points
        return math.hypot(pts[q][0] - pts[p][0], pts[q][1] - pts[p][1])

    lengths = {FRAME: length(FRAME, a, d), inp: length(inp, a, b),
               coupler: length(coupler, b, c), out: length(out, d, c)}
    return FourBar(FRAME, inp, coupler, out, (a, b, c, d), lengths)


@dataclass(frozen=True)
class Grashof:
    """Grashof's classification of a four-bar linkage (Sec. 1.9).

    Attributes
    ----------
    kind : str
        ``"crank-rocker"`` (the shortest link is beside the frame: it is the
        crank), ``"double-crank"`` (drag link: the shortest link is the
        frame), ``"double-rocker"`` (the shortest link is the coupler, which
        turns fully while both side links rock), or ``"non-Grashof"`` (``s + l >
        p + q``: no link turns fully relative to another; a triple rocker).
    s, l, p, q : float
        Shortest, longest and the other two lengths.
    shortest, longest : str
        Link ids.
    grashof : bool
        ``s + l <= p + q`` (Eq. 1.6).
    change_point : bool
        ``s + l == p + q`` (within the length tolerance): the links can fold
        flat, where the two branches meet.
    cranks : tuple of str
        Links that can turn through full turns relative to the frame.
    """

    kind: str
    s: float
    l: float  # noqa: E741 - the book's name
    p: float
    q: float
    shortest: str
    longest: str
    grashof: bool
    change_point: bool
    cranks: tuple[str, ...]

    def __str__(self) -> str:
        name = {"double-crank": "double-crank (drag link)"}.get(self.kind, self.kind)
        rel = "=" if self.change_point else ("<" if self.grashof else ">")
        text = f"{name}: s + l = {self.s + self.l:.6g} {rel} p + q = {self.p + self.q:.6g}"
        if self.change_point:
            text += " (change point)"
        if self.cranks:
            text += "; crank" + ("s" if len(self.cranks) > 1 else "") + ": link " + \
                ", ".join(self.cranks)
        return text


def grashof(mech: Mechanism | FourBar, tol: Tolerance | None = None) -> Grashof:
    """Classify a four-bar linkage by Grashof's law, ``s + l <= p + q`` (Eq. 1.6).

    Parameters
    ----------
    mech : Mechanism or FourBar
    tol : Tolerance, optional
        Decides ``s + l == p + q`` (a change point).

    Returns
    -------
    Grashof

    Raises
    ------
    InputError
        Not a four-bar linkage.

    Notes
    -----
    When ``s + l <= p + q`` the shortest link turns fully relative to the
    other three, and which link is fixed names the linkage (Fig. 1.28): the
    shortest link beside the frame, a crank-rocker; the shortest link as the
    frame, a double-crank (drag link); the shortest link as the coupler, a
    double-rocker.  Otherwise no link turns fully relative to another.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 1.9, Eq. 1.6, Fig. 1.28,
    Example 1.6.

    Examples
    --------
    Example 1.6: s = 3 in (the frame), l = 6 in, p = 4 in, q = 5 in; 3 + 6 <= 4 + 5,
    and the shortest link is the frame, so it is a drag link.

    >>> fb = FourBar("1", "2", "3", "4", ("A", "B", "C", "D"),
    ...              {"1": 3.0, "2": 4.0, "3": 6.0, "4": 5.0})
    >>> str(grashof(fb))
    'double-crank (drag link): s + l = 9 = p + q = 9 (change point); cranks: link 2, 4'
    """
    fb = mech if isinstance(mech, FourBar) else fourbar(mech)
    tol = tol or DEFAULT_TOL
    lengths = fb.lengths
    order = sorted(lengths, key=lambda k: (lengths[k], k))
    shortest, longest = order[0], order[-1]
    s, l = lengths[shortest], lengths[longest]  # noqa: E741
    p, q = (lengths[k] for k in order[1:3])
    excess = (s + l) - (p + q)
    eps = tol.length(max(lengths.values()))
    change = abs(excess) <= eps
    is_grashof = excess <= eps
    if not is_grashof:
        return Grashof("non-Grashof", s, l, p, q, shortest, longest, False, False, ())
    # ties for the shortest link: any of them may serve as s; prefer the frame, then a side link
    ties = [k for k in order if lengths[k] - s <= eps]
    if fb.frame in ties:
        return Grashof("double-crank", s, l, p, q, fb.frame, longest, True, change,
                       (fb.input, fb.output))
    side = [k for k in ties if k in (fb.input, fb.output)]
    if side:
        return Grashof("crank-rocker", s, l, p, q, side[0], longest, True, change,
                       tuple(side))
    return Grashof("double-rocker", s, l, p, q, fb.coupler, longest, True, change, ())


def transmission_angle(obj: Solution | Sweep | Mechanism) -> Array:
    """The transmission angle γ of a four-bar, in degrees (0-180), Sec. 1.10.

    The angle at the coupler-output pin C between the coupler (C to B) and
    the output link (C to D).  At a dead-center posture it is 0° or 180°.

    Parameters
    ----------
    obj : Solution, Sweep or Mechanism
        One posture (a mechanism is solved first) or many.

    Returns
    -------
    ndarray
        Shape () for one posture, (N,) for a sweep; NaN where not assembled.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 1.10, Fig. 1.31, Example 1.7.

    Examples
    --------
    Example 1.7: R_DA = 180 mm, R_BA = 60 mm, R_CB = 210 mm, R_CD = 120 mm,
    crank at 60°: γ = 48.65°.

    >>> import graphkin
    >>> mech = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... D = [180, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [60, 0]
    ... [links.3]
    ... B = [0, 0]
    ... C = [210, 0]
    ... [links.4]
    ... D = [0, 0]
    ... C = [120, 0]
    ... [drive]
    ... link = 2
    ... angle = 60
    ... [assembly]
    ... C = [150, 110]
    ... ''')
    >>> round(float(transmission_angle(mech)), 2)
    48.65
    """
    if isinstance(obj, Mechanism):
        from graphkin.kinematics.solve import solve

        obj = solve(obj)
    sol = obj.solution if isinstance(obj, Sweep) else obj
    fb = fourbar(sol.mechanism)
    _, b, c, d = fb.pins
    with np.errstate(invalid="ignore", divide="ignore"):
        pc = sol.position(c, fb.coupler)
        pb = sol.position(b, fb.coupler)
        pd = sol.position(d, fb.output)
        u, v = pb - pc, pd - pc
        cr = u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]
        dt = u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1]
        out = np.degrees(np.arctan2(np.abs(cr), dt))
    if isinstance(obj, Sweep):
        out = np.where(obj.assembled, out, np.nan)
    return out
