"""Force analysis against the book: Examples 11.1 and 12.4 (the spec examples).

The expected numbers are the book's (Uicker, Pennock & Shigley, 5th ed.),
recomputed where its rounded angles or misprints make them inexact; each
comment gives the derivation.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.forces import solve_forces

DATA = Path(__file__).resolve().parent.parent / "data" / "forces"


@pytest.fixture(scope="module")
def ex11_1():
    return solve_forces(graphkin.load(DATA / "ex11_1_static_fourbar.toml").solve())


@pytest.fixture(scope="module")
def ex12_4():
    return solve_forces(graphkin.load(DATA / "ex12_4_dynamic_fourbar.toml").solve())


def test_ex11_1_by_hand(ex11_1):
    """Ex 11.1 (Sec. 11.7): link 3 is a two-force member, so F_34 lies along AB.

    By hand: Σ M_O4 on link 4 = R_BO4 × F_34 + R_QO4 × P = 0 with F_34 = F (cos θ3, sin θ3),
    θ3 = 22.658°, θ4 = 68.653°, |R_BO4| = 12, |R_QO4| = 5, P = 120 lb at 220°:
    12 F sin(θ3 - θ4) + 5·120 sin(220° - θ4) = 0  ->  F = 600 sin(151.347°) / (12 sin 45.995°).
    """
    sol = ex11_1.solution
    t3, t4 = math.radians(float(sol.angle(3))), math.radians(float(sol.angle(4)))
    f = 600 * math.sin(math.radians(220) - t4) / (12 * math.sin(t4 - t3))
    assert f == pytest.approx(33.33, abs=0.01)  # the book's analytic 33.333 lb
    np.testing.assert_allclose(ex11_1.force(3, 4), [f * math.cos(t3), f * math.sin(t3)],
                               rtol=1e-12)
    # book: F14 = 61.165 i + 64.292 j lb (analytic)
    np.testing.assert_allclose(ex11_1.force(1, 4), [61.165, 64.292], atol=0.005)
    # F12 = -F32 = F23 = F34 (links 2 and 3 carry the same force)
    np.testing.assert_allclose(ex11_1.force(1, 2), ex11_1.force(3, 4), rtol=1e-12)
    np.testing.assert_allclose(ex11_1.force(2, 3), ex11_1.force(3, 4), rtol=1e-12)
    # T12 = -R_AO2 × F32 = R_AO2 × F23 with R_AO2 = 6 ∠135°: book -184.987 in·lb (cw)
    a = 6 * np.array([math.cos(math.radians(135)), math.sin(math.radians(135))])
    f23 = ex11_1.force(2, 3)
    assert ex11_1.torque(2) == pytest.approx(-(a[0] * -f23[1] - a[1] * -f23[0]), rel=1e-12)
    assert ex11_1.torque(2) == pytest.approx(-184.98, abs=0.01)


def test_ex11_1_construction_is_the_books(ex11_1):
    """The steps are the book's: two-force member 3, three-force member 4, then link 2."""
    assert ex11_1.method == "construction"
    ops = [s.op for s in ex11_1.construction]
    assert ops.index("join") < ops.index("force_three") < ops.index("force_drive_torque")
    three = next(s for s in ex11_1.construction if s.op == "force_three")
    assert three.inputs == ("P_4", "l_3", "O4")
    assert three.equation is not None and three.equation.case == 3


def test_ex11_1_concurrency_point(ex11_1):
    """Fig. 11.5e: the lines of P, F_34 and F_14 meet in one point X_4."""
    env = ex11_1.built.values
    x = env["X_4"][:2] / env["X_4"][2]
    q, b, o4 = (ex11_1.solution.position(n) for n in ("Q", "B", "O4"))
    for p, d in ((q, ex11_1.mechanism.loads[0].force), (b, ex11_1.force(3, 4)),
                 (o4, ex11_1.force(1, 4))):
        r = x - p
        assert abs(r[0] * d[1] - r[1] * d[0]) <= 1e-9 * np.hypot(*r) * np.hypot(*d)


def test_ex12_4_inertia_forces(ex12_4):
    """Ex 12.4: -m3 A_G3 = -70.2 i + 233 j N, -I_G3 α3 = 1.43 N·m, h3 = I α / (m A_G)."""
    f3 = ex12_4.inertia["3"]
    np.testing.assert_allclose(f3.force, [-70.2, 233], atol=1.0)
    assert f3.torque == pytest.approx(1430, rel=0.01)  # N·mm
    assert f3.offset == pytest.approx(f3.torque / np.hypot(*f3.force), rel=1e-12)
    # the offset force's moment about G3 is -I_G3 α3 (Eq. 12.18)
    g = ex12_4.solution.position("G3")
    r = f3.point - g
    assert r[0] * f3.force[1] - r[1] * f3.force[0] == pytest.approx(f3.torque, rel=1e-12)
    f4 = ex12_4.inertia["4"]
    np.testing.assert_allclose(f4.force, [313, 415], atol=2.0)  # book: 313 i + 415 j N
    assert f4.torque == pytest.approx(33.8e3, rel=0.01)          # book: 33.8 N·m


def test_ex12_4_superposition(ex12_4):
    """Ex 12.5: one analysis per loaded link; the partial forces add up to the total."""
    assert [p.link for p in ex12_4.partials] == ["3", "4"]
    env = ex12_4.built.values
    for key, total in ex12_4.forces.items():
        parts = sum(env[p.forces[key]] for p in ex12_4.partials)
        np.testing.assert_allclose(parts, total, rtol=1e-12, atol=1e-9)
    t = sum(float(env[p.drives["2"]]) for p in ex12_4.partials)
    assert t == pytest.approx(ex12_4.torque(2), rel=1e-12)


def test_ex12_4_against_matrix_method(ex12_4):
    """The book's own matrix equations (Ex 12.4) with the loop-closing posture."""
    ana = solve_forces(ex12_4.solution, method="analytic")
    for key in ex12_4.forces:
        np.testing.assert_allclose(ex12_4.forces[key], ana.forces[key], rtol=1e-9, atol=1e-9)
    assert ex12_4.torque(2) == pytest.approx(ana.torque(2), rel=1e-9)
    # the book prints T12 = 19.2 N·m from its misprinted R_BO4 (spec expected.toml): ~5% off
    assert ex12_4.torque(2) == pytest.approx(19.2e3, rel=0.06)


def test_shaking_force_is_the_sum_of_inertia_forces(ex12_4):
    """Eq. 12.23: F_s = Σ(-m A_G)."""
    fs, _ = ex12_4.shaking
    np.testing.assert_allclose(fs, ex12_4.inertia["3"].force + ex12_4.inertia["4"].force,
                               rtol=1e-12)


@pytest.mark.parametrize("name", ["ex11_1", "ex12_4"])
def test_construction_replays(name, request):
    """The recorded steps are the whole construction: a replay from the givens alone
    (pin positions, accelerations of G, α) gives every force again."""
    fs = request.getfixturevalue(name)
    cx = fs.construction
    made = {o for s in cx for o in s.outputs}
    givens = {k: v for k, v in fs.built.values.items() if k not in made}
    for run in (cx.replay, cx.evaluate):
        ev = run(givens)
        for label in made:
            np.testing.assert_allclose(ev[label], fs.built.values[label], rtol=1e-12,
                                       atol=1e-12, err_msg=label)


def test_ex11_4_friction_at_the_slider():
    """Ex 11.4: Ex 11.2 with μ = 0.25, block's motion impending to the left.

    By hand: F_34 along the rod at θ3 = -16.78°, F_14 = F (sin φ, cos φ) leaning right by
    φ = atan 0.25; ΣF on the block with P = -100 i: F34 cos θ3 + F sin φ = 100 and
    F34 sin θ3 + F cos φ = 0.  The book (graphic): F34 = 97 lb, F14 = 29 lb, T12 = 399 in·lb cw.
    """
    root = Path(__file__).resolve().parents[2]
    fs = solve_forces(graphkin.load(root / "gallery" / "mechanisms"
                                    / "ex11_4_slider_crank_friction.toml").solve())
    t3 = math.radians(float(fs.solution.angle(3)))
    phi = math.atan(0.25)
    a = np.array([[math.cos(t3), math.sin(phi)], [math.sin(t3), math.cos(phi)]])
    f34, f14 = np.linalg.solve(a, [100.0, 0.0])
    assert float(np.hypot(*fs.force(3, 4))) == pytest.approx(f34, rel=1e-9)
    assert float(np.hypot(*fs.force(1, 4))) == pytest.approx(f14, rel=1e-9)
    assert f34 == pytest.approx(97, abs=0.5) and f14 == pytest.approx(29, abs=0.5)
    assert fs.torque(2) == pytest.approx(-399, abs=1.0)
    # Coulomb: the tangential part is μ times the normal part, pointing right (+x)
    fx, fy = fs.force(1, 4)
    assert fx == pytest.approx(0.25 * fy, rel=1e-12) and fx > 0
