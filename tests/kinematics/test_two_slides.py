"""A translating link held by two slides, found by one construction step (case 3).

The yoke of the Scotch yoke (Sec. 3.14, Fig. 3.27) slides on the frame's guide,
so it keeps its angle; the block pinned to the crank at A slides in its slot.
One point F of the yoke runs on two lines: the guide, and the parallel to the
slot laid off from A.  The two lines meet at F (Sec. 2.8, case 3), so the sweep
is the construction; it must equal the analytic solver (Newton's method on
the loop's rows, kinematics/analytic), which shares no code with it.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from hypothesis import given
from hypothesis import strategies as st
from strategies import examples, scotch_yokes

import graphkin
from graphkin.kinematics.analytic import solve_analytic_many
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.tolerance import DEFAULT_TOL

ROOT = Path(__file__).resolve().parents[2]
YOKE = ROOT / "gallery" / "centers" / "fig3_27_scotch_yoke.toml"


def _against_analytic(mech: graphkin.Mechanism, count: int) -> None:
    d0 = math.degrees(mech.drives[0].value)
    sw = mech.sweep(count=count, start=d0, stop=d0 + 360.0)
    assert sw.method == "construction"
    drive = np.radians(np.asarray(sw.drive_values, dtype=float))
    an = solve_analytic_many(mech, drive)
    assert np.asarray(an.valid).all() and np.asarray(sw.assembled).all()
    sol = sw.solution
    size = mech.scale
    names = [n for lid, lk in mech.links.items() if lid != "1" for n in lk.points]
    for n in names:
        np.testing.assert_allclose(sol.position(n), an.position(n), rtol=0, atol=1e-9 * size,
                                   err_msg=n)
    if not mech.has_rates:
        return
    for what in ("velocity", "acceleration"):
        ref = {n: np.asarray(getattr(an, what)(n)) for n in names}
        s = 1.0 + max(float(np.max(np.abs(v))) for v in ref.values())
        for n in names:
            np.testing.assert_allclose(getattr(sol, what)(n), ref[n], rtol=0, atol=1e-9 * s,
                                       err_msg=f"{what} {n}")


def test_the_scotch_yoke_is_constructed():
    # the yoke's point F: the two paths meet (one `meet` of two lines), no Newton
    mech = graphkin.load(YOKE)
    eng = _Engine(mech, DEFAULT_TOL)
    assert eng.method == "construction"
    meet = [s for s in eng.pc.construction.steps if s.op == "meet" and s.outputs == ("F",)]
    assert len(meet) == 1
    sol = mech.solve()
    # Fig. 3.27 by hand: F runs with A's x, x_F = 40 cos θ2, so V_F = -40 ω sin θ2 and
    # A_F = -40 ω² cos θ2 along the guide (α2 = 0); the block does not turn
    w, th = 120.0, math.radians(30.0)
    np.testing.assert_allclose(sol.position("F"), [40 * math.cos(th), -60.0], atol=1e-9 * 60)
    np.testing.assert_allclose(sol.velocity("F"), [-40 * w * math.sin(th), 0.0],
                               atol=1e-9 * 40 * w)
    np.testing.assert_allclose(sol.acceleration("F"), [-40 * w * w * math.cos(th), 0.0],
                               atol=1e-9 * 40 * w * w)
    assert abs(float(sol.omega("3"))) < 1e-9 and abs(float(sol.omega("4"))) < 1e-9
    _against_analytic(mech, 73)


@examples(30)
@given(rm=st.one_of(scotch_yokes(), scotch_yokes(with_rates=False)))
def test_random_scotch_yokes_sweep_by_the_construction_like_the_analytic_solver(rm):
    # Scotch yokes at any guide and slot angle, slot offset and crank (tests/strategies.py),
    # with and without rates
    mech = rm.mechanism()
    sol = mech.solve()
    for name, xy in rm.world_points().items():
        np.testing.assert_allclose(sol.position(name), xy, rtol=0, atol=1e-9 * rm.scale(),
                                   err_msg=name)
    _against_analytic(mech, 37)


def test_a_crank_too_slow_for_its_square_draws_no_curvature():
    # ω2 = 1e-200 rad/s: ω² underflows to 0, and J = I + A_I/ω² (Eq. 4.46) cannot be drawn;
    # the curvature constructions leave the crank out instead of dividing 0 by 0
    import warnings

    from graphkin.files import load_toml
    from graphkin.kinematics.curvature.link import curvature
    from graphkin.mechanisms import from_dict

    data = load_toml(YOKE)
    data["drive"]["omega"] = 1e-200
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        out = curvature(from_dict(data, source="slow.toml").solve())
    assert "2" not in out
