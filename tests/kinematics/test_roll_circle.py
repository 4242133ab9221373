"""A gear rolling on a circle laid off by a construction step (``roll_circle_angle``).

A circle of radius r rolling without slip on a circle of radius R, both
centers on one link m (a planet on its arm, gears on fixed centers), turns
with ``ω_l - ω_o = k (ω_m - ω_o)``, ``k = (R + r)/r`` outside and
``-(R - r)/r`` inside (Eq. 3.13; Sec. 7.15, Eq. 7.25); integrated on the
covering, ``θ_l = θ_o + k (θ_m + β - θ_o) + c``.  The sweep is then the
construction, and it must equal the analytic solver (Newton's method on the
integrated no-slip row with φ followed from posture to posture,
kinematics/analytic/rolling.py), which shares no code with it, over several
turns of the drive: past 2π the angles go on continuously.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from strategies import examples
from strategies_rolling import rolling_arrangements

import graphkin
from graphkin.construction.codegen import generate
from graphkin.kinematics.analytic import solve_analytic, solve_analytic_many
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.tolerance import DEFAULT_TOL

ROOT = Path(__file__).resolve().parents[2]
FILES = ["gallery/gears/ex11_7.toml", "examples/planetary_outside.toml",
         "examples/planetary_inside.toml"]


def _turns(mech: graphkin.Mechanism, turns: float, count: int, sense: float = 1.0):
    """The sweep over ``turns`` whole turns from the file's drive, and the analytic one."""
    d0 = math.degrees(mech.drives[0].value)
    sw = mech.sweep(count=count, start=d0, stop=d0 + sense * 360.0 * turns)
    first = np.radians(np.asarray(sw.drive_values, dtype=float))
    vals = first
    if len(mech.drives) > 1:
        vals = np.column_stack([first] + [np.full_like(first, d.value)
                                          for d in mech.drives[1:]])
    return sw, first, solve_analytic_many(mech, vals)


def _agree(mech: graphkin.Mechanism, sw, an) -> None:
    ok = np.asarray(an.valid)
    assert ok.all() and np.asarray(sw.assembled).all()
    sol = sw.solution
    for lid in mech.links:
        got = np.asarray(sol.links[lid].angle)
        ref = np.asarray(an.links[lid].angle)
        # the analytic solver's angle is one of the same posture's: equal modulo 2π
        np.testing.assert_allclose(np.angle(np.exp(1j * (got - ref))), 0.0, rtol=0, atol=1e-9,
                                   err_msg=f"θ{lid}")
        if not mech.has_rates:
            continue
        for what in ("omega", "alpha"):
            g = np.asarray(getattr(sol.links[lid], what))
            r = np.asarray(getattr(an.links[lid], what))
            np.testing.assert_allclose(g, r, rtol=0, atol=1e-9 * (1 + np.max(np.abs(r))),
                                       err_msg=f"{what}{lid}")


def _continuous(mech: graphkin.Mechanism, sw, first: np.ndarray) -> None:
    """Each link's angle goes on with the drive at the train's speed ratio, past 2π.

    With one input the train's ratio ω_l/ω_drive is a constant of the train,
    read off the analytic solver's rates at the file's posture (Sec. 7.15):
    θ_l - θ_l(0) = (ω_l/ω_drive)(θ_drive - θ_drive(0)) exactly on the covering,
    whereas an angle taken modulo 2π would jump by 2π k.
    """
    ex = solve_analytic(mech)
    w_in = float(ex.links[mech.drives[0].link].omega)
    for lid in mech.links:
        got = np.asarray(sw.solution.links[lid].angle)
        ratio = float(ex.links[lid].omega) / w_in
        np.testing.assert_allclose(got - got[0], ratio * (first - first[0]), rtol=0,
                                   atol=1e-9 * (1 + abs(ratio) * np.ptp(first)),
                                   err_msg=f"θ{lid} on the covering")


@pytest.mark.parametrize("name", FILES)
def test_the_planetary_files_sweep_by_the_construction_over_three_turns(name):
    # Example 11.7 (Fig. 11.17) and the planet round a fixed sun or in a fixed ring: the
    # sweep is the construction (no Newton), with a roll_circle_angle step per contact
    mech = graphkin.load(ROOT / name)
    eng = _Engine(mech, DEFAULT_TOL)
    assert eng.method == "construction"
    steps = [s for s in eng.pc.construction.steps if s.op == "roll_circle_angle"]
    assert len(steps) == len(mech.rolling)
    for sense in (1.0, -1.0):
        sw, first, an = _turns(mech, 3.0, 241, sense)
        assert sw.method == "construction"
        _agree(mech, sw, an)
        _continuous(mech, sw, first)


def test_example_11_7_turns_at_the_books_ratio():
    # Example 11.7 with Example 7.4's train: gear 6 fixed, θ'62/3 = 16/51 ... as speeds,
    # ω2/ω3 = 1 - (R5/R6)(R4/R2)⁻¹... by the book: (ω2 - ω3)/(ω6 - ω3) = (R6/R5)(R4/R2)
    # = (1.70/0.80)(1.50/1.00) = 51/16, ω6 = 0: ω2 = ω3 (1 - 51/16) = -35/16 ω3; the planet
    # (ω4 - ω3)/(ω6 - ω3) = -R6/R5 = -17/8: ω4 = ω3 (1 + 17/8) = 25/8 ω3
    mech = graphkin.load(ROOT / FILES[0])
    sw, first, _ = _turns(mech, 2.5, 181)
    th = {lid: np.asarray(sw.solution.links[lid].angle) for lid in ("2", "3", "4")}
    np.testing.assert_allclose(th["3"] - th["3"][0], first - first[0], atol=1e-12)
    for lid, ratio in (("2", -35 / 16), ("4", 25 / 8)):
        np.testing.assert_allclose(th[lid] - th[lid][0], ratio * (first - first[0]), rtol=0,
                                   atol=1e-9 * 60)


@examples(25)
@given(rm=st.one_of(rolling_arrangements("gears"), rolling_arrangements("gear chain"),
                    rolling_arrangements("planet")))
def test_random_trains_sweep_by_the_construction_like_the_analytic_solver(rm):
    # gears on fixed centers (outside, inside), three in a row, a planet round a fixed sun
    # or in a fixed ring, with a driven sun, or driving a ring, between a driven sun and a
    # fixed ring with the arm the output (tests/strategies_rolling.py), over two turns:
    # every angle, ω and α equals the analytic solver's to 1e-9
    mech = rm.mechanism()
    eng = _Engine(mech, DEFAULT_TOL)
    assert eng.method == "construction", rm.kind
    if rm.kind == "planet, sun and ring":  # the arm from both contacts at once (Eq. 7.25)
        assert any(s.op == "planetary_arm" for s in eng.pc.construction.steps)
    sw, first, an = _turns(mech, 2.0, 97)
    _agree(mech, sw, an)
    if len(mech.drives) == 1:
        _continuous(mech, sw, first)


@examples(20)
@given(rm=st.one_of(rolling_arrangements("gear chain"), rolling_arrangements("planet")),
       span=st.floats(1.0, 30.0))
def test_the_written_out_function_equals_the_replay_on_arrays(rm, span):
    # the construction written out once (codegen, from the one table of templates) equals
    # the step-by-step replay through the general numpy operations, on an array of drive
    # values at once (no loop over postures), several turns wide: no value taken mod 2π
    mech = rm.mechanism()
    eng = _Engine(mech, DEFAULT_TOL)
    if eng.method != "construction":
        return
    cx = eng.combined if eng.combined is not None else eng.pc.construction
    given_ = dict(eng.held)
    if eng.combined is not None:
        given_.update(eng.rate_given)
    x = mech.drives[0].value + np.linspace(-span, span, 64)
    labels = [f"θ{lid}" for lid in mech.links
              if any(f"θ{lid}" in st_.outputs for st_ in cx.steps)]
    fn = generate(cx.steps, varying=[eng.label], constants=given_,
                  requests=[(lab, "value") for lab in labels])
    got = fn.values(x)
    ref = cx.replay({**given_, eng.label: x}, strict=False)
    assert got is not None
    for lab in labels:
        np.testing.assert_allclose(np.broadcast_to(got[lab], x.shape),
                                   np.broadcast_to(ref.values[lab], x.shape), rtol=0,
                                   atol=1e-12 * (1 + span * 50), err_msg=lab)


def test_an_arm_angle_measured_modulo_2pi_is_left_to_the_analytic_solver():
    # the arm of tests/data/hostile/point_drive_planetary.toml is turned by its point's
    # x_P: its angle is measured from two points (atan2, in (-π, π]), so a planet laid off
    # from it would jump by 2π k where it wraps (k = 3 here): no roll_circle_angle step,
    # the analytic solver (φ followed from posture to posture) sweeps it
    mech = graphkin.load(ROOT / "tests/data/hostile/point_drive_planetary.toml")
    eng = _Engine(mech, DEFAULT_TOL)
    assert eng.method == "analytic"


SUN_AND_RING = ROOT / "tests/data/sun_and_ring_planetary.toml"


def test_the_arm_between_a_driven_sun_and_a_fixed_ring_is_the_train_formula():
    # sun R2 = 30 driven, planet r3 = 15, ring R1 = 60 fixed, arm 4 the output. By the
    # train formula (Sec. 7.15, Eq. 7.25) with the arm: (ω1 - ω4)/(ω2 - ω4) = -R2/R1 = -1/2,
    # ω1 = 0: ω4 = ω2/3; the planet (ω3 - ω4)/(ω2 - ω4) = -R2/r3 = -2: ω3 = ω4 - 2(ω2 - ω4)
    # = -ω2. Over three turns of the sun, θ4 turns a third as far and θ3 as far back, and
    # every angle, ω and α equals the analytic solver's
    mech = graphkin.load(SUN_AND_RING)
    eng = _Engine(mech, DEFAULT_TOL)
    assert eng.method == "construction"
    ops = [s.op for s in eng.pc.construction.steps]
    assert ops.count("planetary_arm") == 1 and ops.count("roll_circle_angle") == 1
    sw, first, an = _turns(mech, 3.0, 181)
    _agree(mech, sw, an)
    th = {lid: np.asarray(sw.solution.links[lid].angle) for lid in ("3", "4")}
    np.testing.assert_allclose(th["4"] - th["4"][0], (first - first[0]) / 3, rtol=0,
                               atol=1e-12 * 60)
    np.testing.assert_allclose(th["3"] - th["3"][0], -(first - first[0]), rtol=0,
                               atol=1e-12 * 60)
