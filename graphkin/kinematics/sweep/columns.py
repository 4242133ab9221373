"""The CSV columns of ``docs/formats/sweep-csv.md`` read from an evaluated block of postures.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 2.2 (angles), Secs. 3.4-3.6 and 4.2-4.6 (velocities and accelerations of points).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from graphkin.geometry import ops as g
from graphkin.kinematics.solution import Solution
from graphkin.kinematics.solve import link_states
from graphkin.kinematics.sweep.engine import _Block, _Engine
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.text import wrap_degrees

Array = np.ndarray


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
    """The columns of ``docs/formats/sweep-csv.md`` for one block."""
    mech = eng.mech
    dv = blk.dv
    n = len(dv)
    cols: dict[str, Array] = {}
    cols["drive"] = blk.user if blk.user is not None else (
        np.degrees(dv) if eng.drive.is_angle else np.array(dv, dtype=float))
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
        ok = np.broadcast_to(np.asarray(blk.analytic.valid), (n,)).copy()
        for st in blk.analytic.links.values():  # rates left empty at a dead center
            if st.omega is not None:
                ok &= np.isfinite(np.broadcast_to(st.omega, (n,)))
        return ok
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
