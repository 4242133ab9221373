"""Friction at a pin in a slot (Sec. 11.10, Ex 11.5): a follower in two rough bearings.

The follower of Example 11.3 in bearings B and D with μ = 0.15, its motion
impending downward (the least force at A).  The expected forces are derived
here from the follower's three equilibrium equations written by hand (no
graphkin solver), and the book's printed answers are shown not to balance it.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.errors import InputError
from graphkin.forces import solve_forces

GALLERY = Path(__file__).resolve().parents[2] / "gallery" / "mechanisms"
EX11_5 = GALLERY / "ex11_5_cam_follower_friction.toml"
MU = 0.15


def _cross(p, f) -> float:
    return float(p[0] * f[1] - p[1] * f[0])


def _by_hand(mech, sol):
    """ΣF = 0 and ΣM_O2 = 0 for the follower: F_A along the cam's normal at A, F_B and F_D
    through the bearings' pins, each leaning φ = atan μ from the horizontal normal with its
    vertical (friction) component upward, against the follower's downward impending motion;
    the normal at B pushes to the right, at D to the left (Ex 11.3, Fig. 11.10c)."""
    k1, k2 = sol.position("K1", "2"), sol.position("K2", "2")
    t = (k2 - k1) / np.hypot(*(k2 - k1))
    n_a = np.array([-t[1], t[0]])            # the cam's normal at A (pushing the follower up)
    if n_a[1] < 0:
        n_a = -n_a
    c = 1 / math.hypot(1, MU)
    u_b, u_d = np.array([c, MU * c]), np.array([-c, MU * c])
    a, b, d = (sol.position(n) for n in ("A", "B", "D"))
    m = np.array([[n_a[0], u_b[0], u_d[0]], [n_a[1], u_b[1], u_d[1]],
                  [_cross(a, n_a), _cross(b, u_b), _cross(d, u_d)]])
    rhs = np.zeros(3)
    for ld in mech.loads:
        p = sol.position(ld.point, ld.link)
        rhs -= np.array([ld.force[0], ld.force[1], _cross(p, ld.force)])
    return np.linalg.solve(m, rhs), (n_a, u_b, u_d, a, b, d)


@pytest.fixture(scope="module")
def ex11_5():
    mech = graphkin.load(EX11_5)
    return mech, mech.solve()


def test_ex11_5_against_the_hand_equations(ex11_5):
    mech, sol = ex11_5
    fs = solve_forces(sol)
    assert fs.method == "construction"  # the graphic method, not the fallback
    (fa, fb, fd), _ = _by_hand(mech, sol)
    assert fa > 0 and fb > 0 and fd > 0
    got_a = float(np.hypot(*fs.force(2, 3)))
    got_b = float(np.hypot(*fs.forces["1-3@B"][:2]))
    got_d = float(np.hypot(*fs.forces["1-3@D"][:2]))
    for got, want in ((got_a, fa), (got_b, fb), (got_d, fd)):
        assert got == pytest.approx(want, rel=1e-9)
    # each bearing's force leans by the friction angle, its friction component upward
    for key in ("1-3@B", "1-3@D"):
        f = fs.forces[key][:2]
        assert math.degrees(math.atan2(abs(f[1]), abs(f[0]))) == pytest.approx(
            math.degrees(math.atan(MU)), abs=1e-9)
        assert f[1] > 0
    # friction helps to hold the follower: less force at A than without it (Ex 11.3, 51.8 N)
    plain = solve_forces(graphkin.load(GALLERY / "ex11_3_cam_follower_four_force.toml").solve())
    assert got_a < float(np.hypot(*plain.force(2, 3)))


def test_the_books_answers_do_not_balance_the_follower(ex11_5):
    """The gallery note's evidence: F_B = 39.1, F_D = 34.7, F_A = 39.1 N (Ex 11.5) leave
    ΣF_x ≈ -3.4 N and ΣM_O2 ≈ 347 N·mm; graphkin's leave nothing."""
    mech, sol = ex11_5
    (fa, fb, fd), (n_a, u_b, u_d, a, b, d) = _by_hand(mech, sol)

    def residual(fa, fb, fd):
        f = fa * n_a + fb * u_b + fd * u_d
        m = _cross(a, fa * n_a) + _cross(b, fb * u_b) + _cross(d, fd * u_d)
        for ld in mech.loads:
            f = f + np.asarray(ld.force)
            m += _cross(sol.position(ld.point, ld.link), ld.force)
        return f, m

    f, m = residual(39.1, 39.1, 34.7)
    assert f[0] == pytest.approx(-3.4, abs=0.05) and abs(f[1]) < 0.05
    assert m == pytest.approx(347, abs=2)
    f, m = residual(fa, fb, fd)
    assert np.allclose(f, 0, atol=1e-9) and abs(m) < 1e-7
    # the book's normal components do not match its own φ = 8.5°
    assert abs(39.1 * math.cos(math.atan(MU)) - 37.7) > 0.9
    assert abs(34.7 * math.cos(math.atan(MU)) - 33.6) > 0.6


def test_a_negative_friction_in_a_slot_is_refused(tmp_path):
    src = (GALLERY / "ex11_5_cam_follower_friction.toml").read_text()
    assert 'line = ["S1", "S2"]\nfriction = 0.15' in src
    bad = src.replace('line = ["S1", "S2"]\nfriction = 0.15', 'line = ["S1", "S2"]\n'
                      'friction = -1', 1)
    f = tmp_path / "bad.toml"
    f.write_text(bad)
    with pytest.raises(InputError) as info:
        graphkin.load(f)
    assert info.value.key == "slots[0].friction"
