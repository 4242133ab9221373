"""Instant centers (Secs. 3.12-3.17, 3.19 and 5.4) against independent values.

The independent oracle is the definition of Sec. 3.12: the instant center of
links i and j is the point where the two links have the same absolute
velocity.  With the velocity field of each link read from the *analytic*
solution (``LinkState.velocity``, never the centers), the relative velocity
``f(P) = V_i(P) - V_j(P)`` is affine in P, ``f(P) = f0 + Δω J P`` with
``J`` the quarter turn, so ``f(P) = 0`` gives, in homogeneous coordinates,
``P = (J f0, Δω)`` — at infinity, perpendicular to the relative velocity,
when ``Δω = 0``.  The Kennedy search never reads a velocity (except for the
centers it flags as found from the velocities), so agreement is a real check.

Textbook numbers are measured from the book's drawings; they are compared
with a tolerance that fits a scale drawing (the exact values are in the
comments).
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from itertools import combinations
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from spec_data import EXPECTED
from strategies import RandomMechanism, examples, five_bars, fourbars, mechanisms, slider_cranks

from graphkin.cli import main
from graphkin.construction import Role
from graphkin.errors import (
    ConstructionError,
    DegenerateError,
    GraphkinError,
    IdealPointError,
    InputError,
)
from graphkin.kinematics.analytic import solve_analytic, solve_analytic_many
from graphkin.kinematics.instant_centers import (
    FAR_AS_INFINITY,
    How,
    KnownCenter,
    KnownLine,
    angular_velocity_ratio,
    center_label,
    instant_center,
    instant_centers,
    instant_centers_json,
    instant_centers_text,
    kinematic_coefficient,
    line_of_centers_velocity,
    mechanical_advantage,
    pair_key,
    sort_links,
)
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms import from_dict, load
from graphkin.output import solution_to_dict
from graphkin.tolerance import DEFAULT_TOL

GALLERY = Path(__file__).resolve().parents[2] / "gallery" / "centers"
HYP = examples(60)

# The centers are meets of lines through exact pins: rounding only.  Compared
# as points of the projective plane (unit homogeneous vectors with the
# coordinates divided by the size of the mechanism), which is the natural
# measure for centers near or at infinity.
REL = 1e-9


# ---------------------------------------------------------------------------
# the oracle
# ---------------------------------------------------------------------------

def _local(sol: Solution, lid: str, p: np.ndarray) -> np.ndarray:
    st = sol.links[lid]
    c, s = math.cos(float(st.angle)), math.sin(float(st.angle))
    d = p - st.origin
    return np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])


def _velocity_at(sol: Solution, lid: str, p: np.ndarray) -> np.ndarray:
    """Absolute velocity of the point of link ``lid`` that is at world ``p``."""
    return sol.links[lid].velocity(_local(sol, lid, p))


def equal_velocity_point(sol: Solution, i: str, j: str, size: float) -> np.ndarray:
    """Homogeneous (x/size, y/size, w): where links i and j have equal velocities."""
    o = np.zeros(2)
    ex, ey = np.array([size, 0.0]), np.array([0.0, size])
    f0 = _velocity_at(sol, i, o) - _velocity_at(sol, j, o)
    fx = (_velocity_at(sol, i, ex) - _velocity_at(sol, j, ex) - f0) / size
    fy = (_velocity_at(sol, i, ey) - _velocity_at(sol, j, ey) - f0) / size
    # f(P) = f0 + M P with M = Δω J: Δω from the antisymmetric part of M
    dw = (fx[1] - fy[0]) / 2.0
    return np.array([-f0[1] / size, f0[0] / size, dw])


def cross(u: np.ndarray, v: np.ndarray) -> float:
    return float(u[0] * v[1] - u[1] * v[0])


def projective(p: np.ndarray, size: float) -> np.ndarray:
    """A center (x, y, w) as a unit homogeneous vector with lengths divided by ``size``."""
    q = np.array([p[0] / size, p[1] / size, p[2]], dtype=float)
    return q / np.linalg.norm(q)


def assert_same_center(p: np.ndarray, q: np.ndarray, size: float, what: str,
                       rel: float = REL) -> None:
    a, b = projective(p, size), q / np.linalg.norm(q)
    if a @ b < 0:
        b = -b
    assert np.linalg.norm(a - b) <= rel, f"{what}: {p} vs equal-velocity point {q}"


def analytic_twin(sol: Solution) -> Solution:
    """The analytic solution on the same branch as ``sol``.

    Where the analytic solver declines (it does not know rolling contact's
    no-slip condition yet), the graphic solution's own velocities serve: they
    come from the velocity polygons, not from the instant centers.
    """
    guess = {lid: (float(s.origin[0]), float(s.origin[1]), float(s.angle))
             for lid, s in sol.links.items() if lid != "1"}
    try:
        return solve_analytic(sol.mechanism, guess=guess)
    except ConstructionError:
        if not sol.mechanism.rolling:
            raise
        return sol


def size_of(sol: Solution) -> float:
    pts = [sol.position(n) for n in sol.mechanism.point_names]
    return max(1.0, max(float(np.hypot(*p)) for p in pts))


def velocity_scale(sol: Solution, size: float) -> float:
    """Largest speed of the mechanism's points, or ω times its size."""
    w = max(abs(float(s.omega)) for s in sol.links.values())
    v = max(float(np.hypot(*sol.velocity(n))) for n in sol.mechanism.point_names)
    return max(w * size, v)


def check_all_centers(sol: Solution, rel: float = REL) -> int:
    """Compare every center with the equal-velocity point; return how many were compared."""
    ref = analytic_twin(sol)
    ic = instant_centers(sol)
    size = size_of(sol)
    n = len(sol.mechanism.links)
    assert len(ic) == n * (n - 1) // 2  # Eq. 3.20
    vs = velocity_scale(ref, size)
    compared = 0
    for c in ic:
        q = equal_velocity_point(ref, c.pair[0], c.pair[1], size)
        # q comes from velocity differences: its rounding error is ~eps·vs/size,
        # so its relative error grows as the relative motion of the pair vanishes
        cond = (vs / size) / max(float(np.linalg.norm(q)), 1e-300)
        if cond > 1e6:
            continue  # (nearly) no relative motion: every point has equal velocities
        far = FAR_AS_INFINITY * sol.mechanism.scale
        if bool(c.is_ideal) and q[2] != 0 and float(np.hypot(*q[:2])) * size > 0.5 * far * abs(
                float(q[2])):
            # farther than FAR_AS_INFINITY sizes: recorded at infinity, in the same direction
            u = q[:2] / np.linalg.norm(q[:2]) * np.sign(q[2])
            assert abs(cross(u, c.point[:2])) <= rel * cond + DEFAULT_TOL.angle, c.label
            compared += 1
            continue
        # (+ the angle tolerance: a meet whose w is below it is put at infinity)
        assert_same_center(c.point, q, size, c.label, rel * cond + DEFAULT_TOL.angle)
        compared += 1
    return compared


# ---------------------------------------------------------------------------
# names
# ---------------------------------------------------------------------------

def test_labels_and_pairs() -> None:
    assert center_label(3, 1) == "I13"
    assert center_label("1", "13") == "I1-13"
    assert center_label(12, 3) == "I3-12"
    assert pair_key("10", "9") == ("9", "10")  # numeric, not string, order
    assert sort_links(["b", "10", "2", "1"]) == ["1", "2", "10", "b"]
    with pytest.raises(InputError):
        pair_key(2, 2)


def test_lookup_by_any_name() -> None:
    ic = instant_centers(load(GALLERY / "ex3_13_fourbar.toml").solve())
    c = ic["I13"]
    assert ic["1-3"] is c and ic[3, 1] is c and ic[("1", "3")] is c and ic.center(3, 1) is c
    assert "I24" in ic and "I25" not in ic
    with pytest.raises(KeyError):
        ic["I15"]
    assert ic.count == 6


# ---------------------------------------------------------------------------
# spec examples
# ---------------------------------------------------------------------------

RATED = ["ex3_1_fourbar.toml", "ex3_2_slider_driven.toml", "ex3_3_inverted_slider.toml",
         "ex4_11_rapsons_slide.toml", "ex4_14_inflection_bresse.toml", "ex4_16_cubic.toml",
         "ex4_4_coriolis_block.toml", "ex4_7_cam_follower.toml", "ex5_4_fivebar.toml"]


@pytest.mark.parametrize("name", RATED)
def test_spec_examples_every_center_is_an_equal_velocity_point(examples: Path,
                                                                name: str) -> None:
    sol = load(examples / name).solve()
    n = len(sol.mechanism.links)
    assert check_all_centers(sol) == n * (n - 1) // 2  # every pair moves relative to the other


@pytest.mark.parametrize("name", ["ex3_1_fourbar.toml", "ex3_2_slider_driven.toml"])
def test_spec_expected_values(examples: Path, name: str) -> None:
    out = solution_to_dict(load(examples / name).solve())
    for key, (value, tol) in EXPECTED[name].items():
        if not key.startswith("instant_centers."):
            continue
        _, pair, field = key.split(".")
        np.testing.assert_allclose(out["instant_centers"][pair][field], value, atol=tol)


@pytest.mark.parametrize("name", ["ex2_5_open.toml", "ex2_5_crossed.toml"])
def test_posture_only_fourbar(examples: Path, name: str) -> None:
    # No rates: Kennedy needs none.  Check the theorem directly: I13 is on
    # lines O2-A and O4-B, I24 on lines O2-O4 and A-B.
    sol = load(examples / name).solve()
    ic = instant_centers(sol)
    o2, o4, a, b = (sol.position(n) for n in ("O2", "O4", "A", "B"))

    def on(p: np.ndarray, u: np.ndarray, v: np.ndarray) -> float:
        d, e = v - u, p - u
        return abs(float(d[0] * e[1] - d[1] * e[0])) / float(np.hypot(*d))

    assert on(ic["I13"].xy, o2, a) < 1e-9 * 400 and on(ic["I13"].xy, o4, b) < 1e-9 * 400
    assert on(ic["I24"].xy, o2, o4) < 1e-9 * 400 and on(ic["I24"].xy, a, b) < 1e-9 * 400
    assert all(c.how is not How.VELOCITIES for c in ic)


def test_json_section(examples: Path) -> None:
    out = instant_centers_json(load(examples / "ex3_2_slider_driven.toml").solve())
    assert out is not None
    assert sorted(out) == ["1-2", "1-3", "1-4", "2-3", "2-4", "3-4"]
    # I14: the slider moves along x, so its center is at infinity along ±y
    np.testing.assert_allclose(out["1-4"]["direction"], [0.0, 1.0], atol=1e-12)
    assert "position" not in out["1-4"]
    assert out["1-4"]["how"] == "primary" and out["1-3"]["how"] == "kennedy"
    assert sorted(e["order"] for e in out.values()) == [1, 2, 3, 4, 5, 6]
    text = json.dumps(out, allow_nan=False)  # no NaN anywhere
    assert "I24" in text


def test_cli_json_and_text(examples: Path, capsys: pytest.CaptureFixture[str]) -> None:
    f = str(examples / "ex5_4_fivebar.toml")
    assert main(["solve", f, "--json"]) == 0
    out = json.loads(capsys.readouterr().out)["instant_centers"]
    assert len(out) == 10
    assert out["2-3"]["how"] == "velocities" and out["2-3"]["speed_ratio_dependent"] is True
    text = instant_centers_text(load(examples / "ex5_4_fivebar.toml").solve())
    assert text is not None and "I23" in text and "speed ratio" in text


# ---------------------------------------------------------------------------
# random mechanisms
# ---------------------------------------------------------------------------

@HYP
@given(mechanisms())
def test_random_every_center_is_an_equal_velocity_point(rm: RandomMechanism) -> None:
    assert check_all_centers(rm.mechanism().solve()) >= 1



def _centers_of(rm: RandomMechanism):  # type: ignore[no-untyped-def]
    """A random mechanism solved, its instant centers, and its size."""
    sol = rm.mechanism().solve()
    return sol, instant_centers(sol), size_of(sol)

@HYP
@given(mechanisms())
def test_random_kennedy_collinear_and_replay(rm: RandomMechanism) -> None:
    sol, ic, size = _centers_of(rm)
    ev = ic.construction.evaluate()
    for c in ic:
        np.testing.assert_allclose(ev[c.label], c.point, rtol=1e-12, atol=1e-12 * size)
        assert ic.construction.step_of(c.label).diagram == "centers"
    # Aronhold-Kennedy: the three centers of any three links are collinear
    # (when each pair moves relative to the other: a pair at relative rest has
    # no single center, Sec. 3.12)
    ref = analytic_twin(sol)
    vs = velocity_scale(ref, size) / size
    moving = {p for p in ic.centers
              if np.linalg.norm(equal_velocity_point(ref, p[0], p[1], size)) > 1e-6 * vs}
    for i, j, k in combinations(ic.links, 3):
        pairs = [pair_key(*p) for p in ((i, j), (i, k), (j, k))]
        if not all(p in moving for p in pairs):
            continue
        m = np.array([projective(ic[p].point, size) for p in pairs])
        assert abs(np.linalg.det(m)) < 1e-8, (i, j, k)
    # one degree of freedom: Kennedy alone, unless its lines coincide here
    if len(sol.mechanism.drives) == 1:
        for c in ic:
            if c.how is How.VELOCITIES:
                assert not c.speed_dependent and "coincide" in c.note


@HYP
@given(mechanisms(with_rates=False))
def test_random_posture_only(rm: RandomMechanism) -> None:
    # Without rates Kennedy still finds every center of a one-degree-of-freedom
    # mechanism (they do not depend on the speed); the same mechanism with rates
    # has the same centers.
    sol = rm.mechanism().solve()
    assert not sol.has_rates
    ic = instant_centers(sol)
    rated = dict(rm.data)
    drives = rated["drive"] if isinstance(rated["drive"], list) else [rated["drive"]]
    rated["drive"] = [dict(d, **({"omega": 1.0} if "angle" in d else {"velocity": 1.0}))
                      for d in drives]
    if len(drives) == 1:
        rated["drive"] = rated["drive"][0]
    ref = instant_centers(from_dict(rated).solve())
    size = size_of(sol)
    if len(drives) > 1:
        # Example 5.5: five pins; the other five need the input speeds
        assert len(ic.missing) == 5 and "Sec. 5.4" in ic.notes[0]
        text = instant_centers_text(sol)
        assert text is not None
        assert sum(row.endswith(": not found") for row in text.splitlines()) == 5
        return
    assert ic.missing == ref.missing
    for c in ic:
        assert_same_center(c.point, projective(ref[c.pair].point, size), size, c.label, 1e-9)


@HYP
@given(mechanisms())
def test_random_angular_velocity_ratio(rm: RandomMechanism) -> None:
    sol, ic, size = _centers_of(rm)
    wscale = velocity_scale(sol, size) / size
    for i, j in combinations(sol.mechanism.moving, 2):
        wi, wj = float(sol.omega(i)), float(sol.omega(j))
        if abs(wi) < 1e-6 * wscale:
            continue  # ω_j/ω_i unbounded or 0/0 (a link that does not turn)
        r = float(angular_velocity_ratio(ic, i, j))
        # a center farther than ~1e9 sizes is at infinity by the angle tolerance
        # (1e-9 rad), so a ratio below ~1e-8 may read as 0
        assert r == pytest.approx(wj / wi, rel=1e-8, abs=1e-8)
        # the sign rule of Eq. 3.22, from the geometry alone
        a, b, c = ic[("1", i)], ic[("1", j)], ic[(i, j)]
        if not (a.is_ideal or b.is_ideal or c.is_ideal) and abs(r) > 1e-6:
            # C is outside the segment AB when C->A and C->B point the same way
            outside = float(np.dot(a.xy - c.xy, b.xy - c.xy)) > 0
            assert (r > 0) == outside


@HYP
@given(mechanisms())
def test_random_line_of_centers_velocity(rm: RandomMechanism) -> None:
    sol = rm.mechanism().solve()
    mech = sol.mechanism
    ic = instant_centers(sol)
    size = size_of(sol)
    vscale = max(1e-300, max(float(np.hypot(*sol.velocity(n))) for n in mech.point_names))
    for d in mech.drives:
        for lid in mech.moving:
            if lid == d.link:
                continue
            c = ic[(d.link, lid)]
            b = ic[("1", lid)]
            if not c.is_ideal and not b.is_ideal and np.hypot(*(c.xy - b.xy)) < 1e-6 * size:
                continue  # the method degenerates; not the case generated here
            if c.is_ideal and b.is_ideal and ic[("1", d.link)].is_ideal:
                continue
            for name, loc in mech.links[lid].points.items():
                r = line_of_centers_velocity(ic, name, lid, given=d.link)
                want = sol.links[lid].velocity(loc)
                np.testing.assert_allclose(r.velocity, want, atol=1e-8 * vscale)
                assert float(r.omega) == pytest.approx(float(sol.omega(lid)),
                                                       abs=1e-8 * vscale / size)


@HYP
@given(fourbars(other_rates=False))
def test_random_fourbar_mechanical_advantage(rm: RandomMechanism) -> None:
    # Eq. 3.35: T4/T2 = ω2/ω4 = R_CD sin γ / (R_BA sin β), β and γ the angles
    # the coupler line makes with the input and output links (magnitudes).
    sol = rm.mechanism().solve()
    o2, a, b, o4 = (sol.position(n) for n in ("O2", "A", "B", "O4"))
    u = (b - a) / np.hypot(*(b - a))
    sin_beta = abs(cross(u, a - o2)) / np.hypot(*(a - o2))
    sin_gamma = abs(cross(u, b - o4)) / np.hypot(*(b - o4))
    eq335 = np.hypot(*(b - o4)) * sin_gamma / (np.hypot(*(a - o2)) * sin_beta)
    ma = float(mechanical_advantage(sol, 4))
    assert abs(ma) == pytest.approx(eq335, rel=1e-8)
    assert ma == pytest.approx(float(sol.omega("2") / sol.omega("4")), rel=1e-8)
    assert float(kinematic_coefficient(sol, 4)) == pytest.approx(
        float(sol.omega("4") / sol.omega("2")), rel=1e-8)


@HYP
@given(slider_cranks())
def test_random_slider_crank_kinematic_coefficients(rm: RandomMechanism) -> None:
    # Eqs. 3.24-3.26: θ'_j = ω_j/ω_2 (crank input) or ω_j/ṙ_4 (slider input);
    # for a sliding output, ṙ_4/ω_2.  ṙ_4 is the slider's speed along its line.
    sol = rm.mechanism().solve()
    mech = sol.mechanism
    (s,) = mech.sliders
    u = np.array([math.cos(s.direction_angle), math.sin(s.direction_angle)])
    rdot = float(sol.velocity(s.point, "4") @ u)
    speed = {"2": float(sol.omega("2")), "3": float(sol.omega("3")), "4": rdot}
    inp = mech.drives[0].link
    for out in ("2", "3", "4"):
        k = float(kinematic_coefficient(sol, out))
        assert k == pytest.approx(speed[out] / speed[inp], rel=1e-8, abs=1e-12)


@HYP
@given(five_bars())
def test_random_five_bar_speed_dependent(rm: RandomMechanism) -> None:
    sol = rm.mechanism().solve()
    ic = instant_centers(sol)
    # exactly one center found from the velocities (the book's I23), the rest by Kennedy
    vel = [c for c in ic if c.how is How.VELOCITIES]
    assert [c.label for c in vel] == ["I23"] and vel[0].speed_dependent
    assert vel[0].order == 6  # after the five pins
    assert all(c.how is How.PRIMARY for c in ic if c.order <= 5)


# ---------------------------------------------------------------------------
# the textbook
# ---------------------------------------------------------------------------

def test_example_3_13_fourbar() -> None:
    # Example 3.13: R(I23,I13) = 15 in and R(I24,I12) = 11.2 in measured from
    # Fig. 3.29; θ'3 = 0.267, θ'4 = 0.528; ω3 = 25.16, ω4 = 49.77 rad/s ccw for
    # ω2 = 94.25 rad/s.  Exact (Example 3.1): ω3 = 25.383, ω4 = 49.502.
    sol = load(GALLERY / "ex3_13_fourbar.toml").solve()
    ic = instant_centers(sol)
    assert ic.order[:4] == ["I12", "I14", "I23", "I34"]  # the four pins (Fig. 3.22)
    assert np.hypot(*(ic["I23"].xy - ic["I13"].xy)) == pytest.approx(15.0, rel=0.015)
    assert np.hypot(*(ic["I24"].xy - ic["I12"].xy)) == pytest.approx(11.2, rel=0.015)
    t3, t4 = float(kinematic_coefficient(sol, 3)), float(kinematic_coefficient(sol, 4))
    assert t3 == pytest.approx(0.267, rel=0.015) and t4 == pytest.approx(0.528, rel=0.015)
    w2 = 900 * 2 * math.pi / 60  # 94.25 rad/s
    assert t3 * w2 == pytest.approx(25.16, rel=0.015)
    assert t4 * w2 == pytest.approx(49.77, rel=0.015)
    # Both ratios positive: I23 lies outside I12-I13 and I24 outside I12-I14 (Eq. 3.22)
    assert t3 > 0 and t4 > 0
    assert ic["I13"].note == "I13 lies on the line I12-I23 and on the line I14-I34 (Kennedy)."
    assert ic["I24"].triangles == (("1", "2", "4"), ("2", "3", "4"))


def test_example_3_14_slider_input() -> None:
    # Example 3.14 (slider 4 the input, 10 m/s to the right): R(I24,I12) = +51 mm,
    # R(I34,I13) = -185 mm, θ'2 = -19.6 rad/m, θ'3 = +5.41 rad/m, ω2 = 196 rad/s
    # cw, ω3 = 54.1 rad/s ccw (graphic; Example 3.8 analytic: 198.56 and 54.47).
    sol = load(GALLERY / "ex3_14_slider_crank.toml").solve()
    ic = instant_centers(sol)
    assert ic["I14"].is_ideal and ic["I14"].how is How.PRIMARY
    up = np.array([0.0, 1.0])  # u^n = k × u^t with u^t = +x
    assert float((ic["I24"].xy - ic["I12"].xy) @ up) == pytest.approx(51.0, rel=0.015)
    assert float((ic["I34"].xy - ic["I13"].xy) @ up) == pytest.approx(-185.0, rel=0.015)
    t2 = float(kinematic_coefficient(sol, 2)) * 1000.0  # rad/mm -> rad/m
    t3 = float(kinematic_coefficient(sol, 3)) * 1000.0
    assert t2 == pytest.approx(-19.6, rel=0.015) and t3 == pytest.approx(5.41, rel=0.015)
    assert t2 * 10.0 == pytest.approx(-196.0, rel=0.015)   # cw
    assert t3 * 10.0 == pytest.approx(54.1, rel=0.015)     # ccw
    # the book's reading of the signs: I24 between I12 and I14 (at infinity upward)
    assert float((ic["I24"].xy - ic["I12"].xy) @ up) > 0 and t2 < 0


def test_example_5_5_five_bar() -> None:
    # Example 5.5: I23 is 2.0 in right of I12 (Eq. 4: ω2/ω3 = -2 on a 6 in
    # line: -2 R = R - 6); measured R(I24,I14) = -4.24, R(I25,I12) = -13.41,
    # R(I25,I15) = -26.29, R(I35,I15) = -3.92, R(P,I14) = 6.46 in; ω4/ω2 =
    # -0.590, ω5/ω2 = 0.510, ω5/ω3 = -1.020; V_P = 38.11 in/s at -55.5°.
    sol = load(GALLERY / "ex5_5_fivebar.toml").solve()
    ic = instant_centers(sol)
    i23 = ic["I23"]
    assert i23.how is How.VELOCITIES and i23.speed_dependent
    np.testing.assert_allclose(i23.xy, [2.0, 0.0], atol=1e-12)  # exact: 2 = 6/3
    assert "depends on the ratio of the input speeds" in i23.note
    assert ic.order[5] == "I23"
    assert all(c.how is How.KENNEDY for c in ic if c.order > 6)

    def dist(a: str, b: str) -> float:
        return float(np.hypot(*(ic[a].xy - ic[b].xy)))

    # upward positive along each line of centers (signs from the book)
    assert dist("I24", "I14") == pytest.approx(4.24, rel=0.01)
    assert ic["I24"].xy[1] < ic["I14"].xy[1]
    assert dist("I25", "I12") == pytest.approx(13.41, rel=0.01)
    assert dist("I25", "I15") == pytest.approx(26.29, rel=0.01)
    assert dist("I35", "I15") == pytest.approx(3.92, rel=0.01)
    p = sol.position("P")
    assert float(np.hypot(*(p - ic["I14"].xy))) == pytest.approx(6.46, rel=0.01)
    assert float(angular_velocity_ratio(sol, 2, 4)) == pytest.approx(-0.590, rel=0.005)
    assert float(angular_velocity_ratio(sol, 2, 5)) == pytest.approx(0.510, rel=0.005)
    assert float(angular_velocity_ratio(sol, 3, 5)) == pytest.approx(-1.020, rel=0.005)
    assert float(angular_velocity_ratio(sol, 2, 3)) == pytest.approx(-0.5, rel=1e-12)
    # V_P = ω4 × R(P, I14): 38.11 in/s at -55.5° (Eq. 9)
    w4 = float(angular_velocity_ratio(sol, 2, 4)) * 10.0
    r = p - ic["I14"].xy
    vp = w4 * np.array([-r[1], r[0]])
    assert float(np.hypot(*vp)) == pytest.approx(38.11, rel=0.01)
    assert math.degrees(math.atan2(vp[1], vp[0])) == pytest.approx(-55.5, abs=0.5)
    np.testing.assert_allclose(vp, sol.velocity("P"), rtol=1e-9)


def test_geared_five_bar_rolling_contact() -> None:
    # The end of Sec. 5.4: with I23 fixed on I12-I13, gears 2 and 3 roll at
    # I23.  Given as a rolling contact, I23 is primary and every other center
    # is found by Kennedy alone, at the same places as with the velocities.
    sol = load(GALLERY / "ex5_5_fivebar.toml").solve()
    free = instant_centers(sol)
    geared = instant_centers(sol, contacts=[KnownCenter((3, 2), (2.0, 0.0))])
    assert geared["I23"].how is How.PRIMARY and geared["I23"].source == "rolling contact"
    assert all(c.how is not How.VELOCITIES for c in geared)
    for c in free:
        np.testing.assert_allclose(geared[c.pair].point, c.point, rtol=1e-12, atol=1e-12)
    with pytest.raises(InputError):
        instant_centers(sol, contacts=[KnownCenter((2, 9), (0.0, 0.0))])


def test_rolling_contact_from_the_file() -> None:
    # Example 3.9 (Fig. 3.18): crank O2A = 150 mm at 90°, coupler AB = 200 mm,
    # wheel 4 of radius 100 mm with B 50 mm above its center G, rolling on the
    # ground y = 0.  Fig. 3.25: I14 is the point of contact, (200, 0), below G.
    # Kennedy: I13 on I12-I23 (the y axis) and I14-I34 (the vertical x = 200):
    # parallel, so at infinity (the coupler translates here, θ'3 = 0); I24 on
    # I12-I14 (the x axis) and I23-I34 (the line y = 150): at infinity too.
    data = {"units": {"length": "mm"},
            "links": {"1": {"O2": [0, 0], "G1": [0, 0], "G2": [1, 0]},
                      "2": {"O2": [0, 0], "A": [150, 0]},
                      "3": {"A": [0, 0], "B": [200, 0]},
                      "4": {"G": [0, 0], "B": [0, 50]}},
            "rolling": [{"link": 4, "on": 1, "circle": {"center": "G", "radius": 100},
                         "line": ["G1", "G2"], "side": "left"}],
            "drive": {"link": 2, "angle": 90, "omega": "10 rad/s"},
            "assembly": {"B": [200, 150]}}
    sol = from_dict(data).solve()
    ic = instant_centers(sol)
    i14 = ic["I14"]
    assert i14.how is How.PRIMARY and "rolling contact" in i14.source
    np.testing.assert_allclose(i14.xy, [200.0, 0.0], atol=1e-9)
    assert ic.construction.step_of("I14").op == "meet"  # the foot of the perpendicular
    assert ic["I13"].is_ideal and ic["I24"].is_ideal
    assert abs(ic["I13"].direction[0]) < 1e-12 and abs(ic["I24"].direction[1]) < 1e-12
    assert float(kinematic_coefficient(sol, 3)) == pytest.approx(0.0, abs=1e-12)
    check_all_centers(sol)
    # the wheel turns about I14: V_G = ω4 × R(G, I14) (Sec. 3.15)
    r = line_of_centers_velocity(sol, "G", 4, given=2)
    np.testing.assert_allclose(r.velocity, sol.velocity("G"), rtol=1e-9, atol=1e-9)


def test_direct_contact_line(examples: Path) -> None:
    # Fig. 3.24: for a cam and follower in direct contact, I23 is on the common
    # normal at the contact.  Example 4.7's equivalent pin-in-slot states it as a
    # slot; the same normal given as a KnownLine (for a file without the slot:
    # through B, perpendicular to the follower's face) gives the same center.
    sol = load(examples / "ex4_7_cam_follower.toml").solve()
    ic = instant_centers(sol)
    c = ic["I23"]
    assert c.how is How.KENNEDY and c.lines[0].startswith("n(B)")
    assert "common normal at B" in c.note
    b = sol.position("B")
    face = sol.position("S2", "3") - sol.position("S1", "3")
    normal = (-face[1], face[0])
    again = instant_centers(sol, contacts=[KnownLine((2, 3), tuple(b), normal)])
    np.testing.assert_allclose(projective(again["I23"].point, 5.0),
                               projective(c.point, 5.0), atol=1e-12)


def test_scotch_yoke_center_at_infinity() -> None:
    # Fig. 3.27: I24 is on the vertical through O2 (I12-I14) and the horizontal
    # through A (I23-I34): (0, 40 sin 30°) = (0, 20).  I13 is on I12-I23 and,
    # since I14 and I34 are both at infinity, at infinity along O2-A (30°).
    sol = load(GALLERY / "fig3_27_scotch_yoke.toml").solve()
    ic = instant_centers(sol)
    np.testing.assert_allclose(ic["I24"].xy, [0.0, 20.0], atol=1e-9)
    i13 = ic["I13"]
    assert i13.is_ideal
    d = i13.direction
    assert abs(d[0] * math.sin(math.radians(30)) - d[1] * math.cos(math.radians(30))) < 1e-12
    assert i13.triangles == (("1", "2", "3"), ("1", "3", "4"))
    assert "do not turn relative to each other" in i13.note
    with pytest.raises(IdealPointError):
        _ = i13.xy
    with pytest.raises(GraphkinError):
        _ = ic["I24"].direction
    # the yoke translates: its speed per unit crank speed is the velocity of I24
    # as a point of the crank along x: ω2 k × (0, 20) = (-20 ω2, 0)
    assert float(kinematic_coefficient(sol, 4)) == pytest.approx(-20.0, rel=1e-12)
    assert float(angular_velocity_ratio(sol, 2, 3)) == 0.0  # the block does not turn
    check_all_centers(sol)


def test_example_3_12_translating_link_line_of_centers() -> None:
    # Example 3.12's lesson: when the given link translates (its absolute center
    # at infinity) every point of it has the same velocity, which carries over
    # at the common center.  Slider-driven slider-crank: V_B from link 4.
    sol = load(GALLERY / "ex3_14_slider_crank.toml").solve()
    r = line_of_centers_velocity(sol, "B", 2, given=4)
    assert r.common == "I24"
    np.testing.assert_allclose(r.common_velocity, [10000.0, 0.0], rtol=1e-12)
    np.testing.assert_allclose(r.velocity, sol.velocity("B"), rtol=1e-9)
    d = line_of_centers_velocity(sol, "D", 3, given=4)
    np.testing.assert_allclose(d.velocity, sol.velocity("D"), rtol=1e-9)


# ---------------------------------------------------------------------------
# construction, batches, degenerate input
# ---------------------------------------------------------------------------

def test_construction_records_the_kennedy_steps() -> None:
    ic = instant_centers(load(GALLERY / "ex3_13_fourbar.toml").solve())
    cx = ic.construction
    steps = {s.label: s for s in cx}
    assert steps["I13"].op == "meet" and steps["I13"].inputs == ("I12-I23", "I14-I34")
    assert steps["I12-I23"].op == "join" and steps["I12-I23"].inputs == ("I12", "I23")
    assert steps["I12"].role is Role.GIVEN and steps["I13"].role is Role.RESULT
    assert all(s.diagram == "centers" for s in cx)
    # the order of discovery is the order of the steps
    idx = [steps[lab].index for lab in ic.order]
    assert idx == sorted(idx)
    circle = ic.kennedy_circle()
    assert circle["links"] == ["1", "2", "3", "4"]
    assert [e["label"] for e in circle["edges"]] == ic.order
    np.testing.assert_allclose(circle["positions"]["1"], (0.0, 1.0), atol=1e-15)


def test_batch_matches_single_postures() -> None:
    # The four-bar 4-18-11-10 is not a Grashof linkage: at θ2 = 0, |AD| = 6 and
    # 6 + 11 < 18, so that posture cannot be assembled (NaN, not valid).
    mech = load(GALLERY / "ex3_13_fourbar.toml")
    angles = np.radians([100.0, 120.0, 0.0, 150.0])
    batch = solve_analytic_many(mech, angles)
    assert batch.valid.tolist() == [True, True, False, True]
    assert instant_centers_json(batch) is None and instant_centers_text(batch) is None
    ic = instant_centers(batch)
    assert not ic.missing
    for k in (0, 1, 3):
        one = instant_centers(_posture(batch, k))
        for c in one:
            np.testing.assert_allclose(ic[c.pair].point[k], c.point, rtol=1e-12, atol=1e-12)
    assert np.isnan(ic["I13"].point[2]).all()
    ratio = angular_velocity_ratio(ic, 2, 4)
    np.testing.assert_allclose(ratio, batch.links["4"].omega / batch.links["2"].omega,
                               rtol=1e-9)
    np.testing.assert_allclose(mechanical_advantage(ic, 4), 1.0 / ratio, rtol=1e-12)
    assert ic.construction.evaluate(strict=False)["I24"].shape == (4, 3)


def _posture(batch: Solution, k: int) -> Solution:
    from dataclasses import replace

    from graphkin.kinematics.solution import LinkState

    links = {}
    for lid, s in batch.links.items():
        links[lid] = LinkState(*(None if v is None else np.asarray(v)[k] for v in (
            s.angle, s.origin, s.omega, s.alpha, s.origin_velocity, s.origin_acceleration)))
    return replace(batch, links=links, valid=np.array(True), constructions={}, values={})


def test_two_inputs_without_rates_leave_centers_missing(examples: Path) -> None:
    data = {"links": {"1": {"O2": [0, 0], "O3": [6, 0]}, "2": {"O2": [0, 0], "A": [2.5, 0]},
                      "3": {"O3": [0, 0], "C": [4, 0]}, "4": {"A": [0, 0], "B": [6, 0]},
                      "5": {"C": [0, 0], "B": [6, 0]}},
            "drive": [{"link": 2, "angle": 120}, {"link": 3, "angle": 45}],
            "assembly": {"B": [3.6, 6.0]}}
    sol = from_dict(data).solve()
    ic = instant_centers(sol)
    assert len(ic) == 5 and len(ic.missing) == 5
    assert "I23" in " ".join(ic.notes)
    out = instant_centers_json(sol)
    assert out is not None and sorted(out) == ["1-2", "1-3", "2-4", "3-5", "4-5"]
    text = instant_centers_text(sol)
    assert text is not None and "I23: not found" in text
    with pytest.raises(KeyError):
        ic["I23"]
    assert [e["known"] for e in ic.kennedy_circle()["edges"]].count(False) == 5


def test_instant_center_function_and_errors() -> None:
    sol = load(GALLERY / "ex3_13_fourbar.toml").solve()
    np.testing.assert_allclose(instant_center(sol, 4, 2), [-11.0627, 0.0, 1.0], atol=1e-4)
    with pytest.raises(InputError):
        line_of_centers_velocity(sol, "C", 4, given=4)
    sl = load(GALLERY / "fig3_27_scotch_yoke.toml").solve()
    with pytest.raises(DegenerateError):
        angular_velocity_ratio(sl, 3, 2)  # the block does not turn: ω2/ω3 unbounded


def test_importing_does_not_import_matplotlib() -> None:
    code = ("import sys, graphkin.kinematics.instant_centers; "
            "print('matplotlib' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    assert out.stdout.strip() == "False"
