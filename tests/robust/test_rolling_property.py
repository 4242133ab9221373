"""Random rolling arrangements of every kind against the analytic solver and the truth.

Issue 26, item 1.  Each kind of :mod:`strategies_rolling` (a wheel on the
ground or on a carriage, a pinion on a crank or a slider rolling on a pivoted
rack, a sliding rack, gears on fixed centers outside and inside, planets on
arms round fixed or driven suns and in rings) is generated from a known world
posture.  The graphic solution must give that posture, the analytic solver's
velocities and accelerations (loop closure, Secs. 3.9 and 4.9, which shares no
code with the polygons), and instant centers where the two links' velocities
(from the analytic solver) are equal (Sec. 3.12).
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import assume, given
from strategies import RandomMechanism, examples
from strategies_rolling import rolling_arrangements

import graphkin
from graphkin.errors import ConstructionError
from graphkin.kinematics.analytic import solve_analytic
from graphkin.kinematics.instant_centers import instant_centers


def _ic_from_rates(sol: graphkin.Solution, j: str, k: str) -> np.ndarray | None:
    """The point where links j and k have one velocity (None when they turn together)."""
    a, b = sol.links[j], sol.links[k]
    dw = float(a.omega) - float(b.omega)
    scale = max(1.0, abs(float(a.omega)), abs(float(b.omega)))
    if abs(dw) < 1e-3 * scale:
        return None

    def perp(v: np.ndarray) -> np.ndarray:
        return np.array([-v[1], v[0]])

    # V_oj + ω_j perp(P − o_j) = V_ok + ω_k perp(P − o_k)  →  (ω_j − ω_k) perp(P) = rhs
    rhs = (np.asarray(b.origin_velocity) - float(b.omega) * perp(np.asarray(b.origin))
           - np.asarray(a.origin_velocity) + float(a.omega) * perp(np.asarray(a.origin)))
    return -perp(rhs / dw)  # perp(perp(P)) = −P


def check(rm: RandomMechanism) -> None:
    mech = rm.mechanism()
    try:
        exact = solve_analytic(mech)  # from the hints and the drives, not from the drawing
    except ConstructionError:
        assume(False)  # a toggle of the generated posture: nothing to compare
        return
    sol = mech.solve()
    assert sol.method == "construction", (rm.kind, sol.notes)
    assert not any("toggle" in n or "analytic" in n for n in sol.notes), (rm.kind, sol.notes)
    size = rm.scale()
    for lid, (x, y, t) in rm.truth.items():
        s, e = sol.links[lid], exact.links[lid]
        for st in (s, e):
            assert abs(math.remainder(float(st.angle) - t, 2 * math.pi)) < 1e-8, (rm.kind, lid)
            assert np.allclose(np.asarray(st.origin), (x, y), atol=1e-8 * size), (rm.kind, lid)
        w = max(1.0, abs(float(e.omega)))
        assert math.isclose(float(s.omega), float(e.omega), rel_tol=1e-7, abs_tol=1e-9 * w)
        a = max(1.0, abs(float(e.alpha)), w * w)
        assert math.isclose(float(s.alpha), float(e.alpha), rel_tol=1e-7, abs_tol=1e-9 * a)
    for name in mech.point_links:
        v, va = sol.velocity(name), exact.velocity(name)
        assert np.allclose(v, va, atol=1e-7 * max(1.0, float(np.hypot(*va)))), (rm.kind, name)
        ac, aa = sol.acceleration(name), exact.acceleration(name)
        assert np.allclose(ac, aa, atol=1e-7 * max(1.0, float(np.hypot(*aa)))), (rm.kind, name)
    ic = instant_centers(sol)
    for label in ic.order:
        c = ic[label]
        want = _ic_from_rates(exact, *c.pair)
        pt = np.asarray(c.point, dtype=float)
        if want is None or float(np.hypot(*want)) > 1e4 * size:
            continue
        assert abs(pt[2]) > 0, (rm.kind, label)
        got = pt[:2] / pt[2]
        assert np.allclose(got, want, atol=1e-6 * max(size, float(np.hypot(*want)))), \
            (rm.kind, label, got, want)


@examples(15)
@given(rm=rolling_arrangements("wheel by coupler"))
def test_wheel_driven_by_a_coupler(rm: RandomMechanism) -> None:
    check(rm)


@examples(15)
@given(rm=rolling_arrangements("wheel on a carriage"))
def test_wheel_on_a_carriage(rm: RandomMechanism) -> None:
    check(rm)


@examples(20)
@given(rm=rolling_arrangements("pinion on a pivoted rack"))
def test_pinion_on_a_pivoted_rack(rm: RandomMechanism) -> None:
    check(rm)


@examples(15)
@given(rm=rolling_arrangements("sliding rack"))
def test_sliding_rack(rm: RandomMechanism) -> None:
    check(rm)


@examples(20)
@given(rm=rolling_arrangements("gears"))
def test_gears_on_fixed_centers(rm: RandomMechanism) -> None:
    check(rm)


@examples(15)
@given(rm=rolling_arrangements("gear chain"))
def test_gear_chains(rm: RandomMechanism) -> None:
    check(rm)


@examples(30)
@given(rm=rolling_arrangements("planet"))
def test_planets(rm: RandomMechanism) -> None:
    check(rm)
