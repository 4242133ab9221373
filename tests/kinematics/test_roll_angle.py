"""A roller's angle laid off from its travel (the ``roll_angle`` step, Sec. 2.19).

A circle rolling on a line without slip turns with its travel,
``θ_l = θ_o + c - σ s/ρ`` (Example 3.9, Eq. 5 integrated).  When its center
and the line are drawn before its angle is needed (a roller pinned to a
crank, a pinion on a crank over a rack), the sweep is the construction with
that step; it must equal the analytic solver (Newton's method on the
integrated no-slip row, kinematics/analytic/rolling.py) at every posture.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from hypothesis import assume, given
from hypothesis import strategies as st
from strategies import examples
from strategies_rolling import rolling_arrangements

import graphkin
from graphkin.kinematics.analytic import solve_analytic_many
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.tolerance import DEFAULT_TOL

ROOT = Path(__file__).resolve().parents[2]


def _same_as_analytic(mech: graphkin.Mechanism, count: int) -> None:
    eng = _Engine(mech, DEFAULT_TOL)
    assert eng.method == "construction"
    assert any(s.op == "roll_angle" for s in eng.pc.construction.steps)
    sw = mech.sweep(count=count)
    drive = sw.columns["drive"]
    vals = np.radians(drive) if mech.drives[0].is_angle else drive
    if len(mech.drives) > 1:
        vals = np.column_stack([vals] + [np.full_like(vals, d.value) for d in mech.drives[1:]])
    an = solve_analytic_many(mech, vals)
    ok = np.asarray(sw.assembled) & np.asarray(an.valid)
    # where both stand on the same branch (every other link at the same angle; a sweep's
    # branch is the construction's named side, the solver's the posture before), the
    # roller's angle is a function of the posture: it must agree there too
    rollers = {r.link for r in mech.rolling}

    def turn(lid: str) -> tuple[np.ndarray, np.ndarray]:
        got = np.radians(sw.columns[f"angle_{lid}"])
        return got, np.angle(np.exp(1j * (got - np.asarray(an.links[lid].angle))))

    both = ok.copy()
    for lid in mech.links:
        if lid != "1" and lid not in rollers:
            ok &= np.abs(turn(lid)[1]) < 1e-6
    # from the file's posture, up to the postures that cannot be assembled, the two
    # follow one branch (the solver continues from the posture before, the construction
    # keeps its named side); past a gap in the cycle the solver may come back on the other
    # (a pinion whose rack's pivot it passes over: no tangent from inside the circle)
    first = np.asarray(vals if np.ndim(vals) == 1 else vals[:, 0], dtype=float)
    d0 = float(mech.drives[0].value)
    gap = (np.abs(np.angle(np.exp(1j * (first - d0)))) if mech.drives[0].is_angle
           else np.abs(first - d0))
    i0 = int(np.argmin(gap))   # the sample at the file's drive (a travel's range may start
    lo = hi = i0               # elsewhere), and the run of assembled postures around it
    while lo > 0 and both[lo - 1]:
        lo -= 1
    while hi + 1 < len(both) and both[hi + 1]:
        hi += 1
    assert both[i0] and ok[lo:hi + 1].all()
    assert ok.sum() >= min(count // 4, hi + 1 - lo)
    for lid in rollers:
        np.testing.assert_allclose(turn(lid)[1][ok], 0.0, rtol=0, atol=1e-9, err_msg=f"θ{lid}")
    for lid in mech.links:
        if lid == "1" or not mech.has_rates:
            continue
        w = np.asarray(an.links[lid].omega)[ok]
        a = np.asarray(an.links[lid].alpha)[ok]
        np.testing.assert_allclose(sw.columns[f"omega_{lid}"][ok], w, rtol=0,
                                   atol=1e-9 * (1 + np.max(np.abs(w))), err_msg=f"ω{lid}")
        np.testing.assert_allclose(sw.columns[f"alpha_{lid}"][ok], a, rtol=0,
                                   atol=1e-8 * (1 + np.max(np.abs(a))), err_msg=f"α{lid}")

def test_the_roller_follower_sweeps_by_the_construction():
    # Example 4.8 (Fig. 4.20): roller 4 pinned to the crank at its center B, rolling on the
    # flat face of follower 3
    _same_as_analytic(graphkin.load(ROOT / "gallery/mechanisms/fig4_20_roller_follower.toml"),
                      72)


@examples(12)
@given(rm=st.one_of(rolling_arrangements("wheel on a carriage"),
                    rolling_arrangements("pinion on a pivoted rack"),
                    rolling_arrangements("sliding rack")))
def test_random_rollers_sweep_by_the_construction_where_it_can(rm):
    # the arrangements whose roller's center and line are drawn before its angle: a wheel on
    # a driven carriage, a pinion on a crank or a slider over a pivoted rack, a driven rack
    # under a pinion on a fixed pivot (tests/strategies_rolling.py)
    mech = rm.mechanism()
    assume(_Engine(mech, DEFAULT_TOL).method == "construction")
    _same_as_analytic(mech, 72)
