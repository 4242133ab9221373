"""Every value a sweep computes is the value ``solve`` finds at the same posture (issue 25).

A sweep evaluates the recorded constructions on arrays of postures (and the
force construction with the rough joints' lines leant at every posture); a
single posture is solved by :meth:`Mechanism.solve` and
:func:`graphkin.forces.solve_forces`.  Here both are run on random
mechanisms of every family with random loads, masses and rough sliders
(friction, Sec. 11.10), and on the rolling and geared examples: at each
swept posture the file is re-solved with its drive set to the swept value
(and the swept positions as the assembly hint, so the same branch), and
every column -- angles, rates, positions, velocities, accelerations, the
drive's torque and every joint force -- must agree.  A posture the sweep
leaves empty (self-locking, a dead center for these loads) is one where
``solve`` refuses with one line.  The first wrong answer this found: the
swept torque of Example 11.4 with μ = 0.25 was the frictionless one (429.16
lbf·in instead of 399.08).
"""

from __future__ import annotations

import copy
import dataclasses
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.errors import GraphkinError, InputError
from graphkin.forces import solve_forces
from graphkin.forces.sweep import force_columns
from graphkin.mechanisms import from_dict

ROOT = Path(__file__).resolve().parents[2]
sys_path = str(ROOT / "tests")
import sys  # noqa: E402

if sys_path not in sys.path:
    sys.path.insert(0, sys_path)
from forces.test_forces_properties import loaded  # noqa: E402


def _at(mech: graphkin.Mechanism, sol: Any, k: int, value: float) -> graphkin.Mechanism:
    """The file with its drive at the swept ``value`` and the swept points as the hint."""
    d = mech.drives[0]
    v = math.radians(value) if d.kind in ("angle", "relative") else value
    hint = {}
    for name in mech.point_names:
        if name in mech.links["1"].points:
            continue
        p = np.asarray(sol.position(name), dtype=float)[k]
        if np.all(np.isfinite(p)):
            hint[name] = (float(p[0]), float(p[1]))
    # a rolling link's angle is the file's at the file's drive: the swept one here
    rolling = tuple(dataclasses.replace(r, angle=float(np.asarray(sol.angle_rad(r.link))[k]))
                    for r in mech.rolling)
    return dataclasses.replace(mech, drives=(dataclasses.replace(d, value=v),), assembly=hint,
                               rolling=rolling)


def _same_angle(a: float, b: float) -> bool:
    return abs((a - b + 180.0) % 360.0 - 180.0) <= 1e-7


def compare(mech: graphkin.Mechanism, span: float = 40.0, count: int = 4,
            torque: bool = True) -> int:
    """Sweep ``count`` postures around the file's and re-solve each; the postures checked."""
    d = mech.drives[0]
    start = math.degrees(d.value) if d.kind == "angle" else d.value
    step = span if d.kind == "angle" else span / 100 * mech.scale
    sw = mech.sweep(count=count, start=start - step, stop=start + step)
    cols = dict(sw.columns)
    if torque:
        cols.update(force_columns(sw, joints=True))
    size = mech.scale
    checked = 0
    for k, value in enumerate(np.asarray(sw.columns["drive"], dtype=float)):
        if not bool(np.asarray(sw.assembled)[k]):
            continue
        one = _at(mech, sw.solution, k, float(value)).solve()
        w = max([abs(float(one.omega(lid))) for lid in mech.moving] + [1e-300]) \
            if one.has_rates else 0.0
        for name in mech.links:
            assert _same_angle(cols[f"angle_{name}"][k], float(one.angle(name))), name
        for p in mech.point_names:
            xy = np.asarray(one.position(p), dtype=float)
            assert abs(cols[f"x_{p}"][k] - xy[0]) <= 1e-8 * size, p
            assert abs(cols[f"y_{p}"][k] - xy[1]) <= 1e-8 * size, p
            if one.has_rates:
                v = np.asarray(one.velocity(p), dtype=float)
                assert abs(cols[f"vx_{p}"][k] - v[0]) <= 1e-8 * size * w, p
                assert abs(cols[f"vy_{p}"][k] - v[1]) <= 1e-8 * size * w, p
        if torque:
            try:
                fs = solve_forces(one)
            except InputError as exc:
                # solve refuses the posture (self-locking, a dead center): the cells are empty
                assert any(w in str(exc) for w in ("self-locking", "cannot be held",
                                                   "at rest relative to its guide")), exc
                for dd in mech.drives:
                    name = ("torque_" if dd.kind == "angle" else "force_") + dd.link
                    assert math.isnan(cols[name][k]), (name, cols[name][k], exc)
                checked += 1
                continue
            big = max([float(np.hypot(*f[:2])) for f in fs.forces.values()] + [1e-300])
            for dd in mech.drives:
                kind, t = fs.drives[dd.link]
                name = ("torque_" if kind == "torque" else "force_") + dd.link
                arm = size if kind == "torque" else 1.0
                assert abs(cols[name][k] - t) <= 1e-8 * max(big * arm, abs(t)), \
                    (name, value, cols[name][k], t)
            for key, f in fs.forces.items():
                assert abs(cols[f"F_{key}"][k] - float(np.hypot(*f[:2]))) <= 1e-8 * big, key
        checked += 1
    return checked


@settings(max_examples=25, deadline=None,
          suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much,
                                 HealthCheck.data_too_large])
@given(loaded(), st.sampled_from([None, 0.1, 0.3]), st.sampled_from([None, "ahead", "behind"]))
def test_every_swept_column_is_what_solve_finds(case: Any, mu: float | None,
                                                impending: str | None) -> None:
    rm, data = case
    data = copy.deepcopy(data)
    static = impending is not None or not any(
        k in (data["drive"] if isinstance(data["drive"], dict) else data["drive"][0])
        for k in ("omega", "velocity"))
    for s in data.get("sliders", []):
        if mu is not None:
            s["friction"] = mu
            if impending is not None or static:
                s["impending"] = impending or "ahead"
    try:
        mech = from_dict(data, source=f"<random {rm.kind}>")
        mech.solve()
    except GraphkinError:
        return
    compare(mech)


EXAMPLES = [ROOT / "gallery" / "mechanisms" / "ex11_4_slider_crank_friction.toml",
            ROOT / "gallery" / "mechanisms" / "ex11_5_cam_follower_friction.toml",
            ROOT / "tests" / "forces" / "data" / "rolling_wheel_loaded.toml",
            ROOT / "tests" / "forces" / "data" / "spur_gears.toml",
            ROOT / "tests" / "data" / "forces" / "ex12_4_dynamic_fourbar.toml"]


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_rough_and_rolling_examples(path: Path) -> None:
    assert compare(graphkin.load(path), span=30.0, count=5) >= 3


def test_example_11_4_swept_torque_is_the_rough_one() -> None:
    """Ex 11.4, μ = 0.25: T12 = 399.08 lbf·in cw at θ2 = 120° (solve), not 429.16 (no friction)."""
    mech = graphkin.load(EXAMPLES[0])
    sw = mech.sweep(count=1, start=120.0, stop=121.0)
    t = force_columns(sw)["torque_2"][0]
    assert t == pytest.approx(solve_forces(mech.solve()).torque(2), rel=1e-9)
    assert abs(t + 429.16) > 10.0
