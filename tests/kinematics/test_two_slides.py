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
from graphkin.geometry import ops as g
from graphkin.kinematics.analytic import solve_analytic_many
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.tolerance import DEFAULT_TOL

ROOT = Path(__file__).resolve().parents[2]
YOKE = ROOT / "gallery" / "centers" / "fig3_27_scotch_yoke.toml"


def _against_analytic(mech: graphkin.Mechanism, count: int, span: float = 360.0) -> None:
    d0 = math.degrees(mech.drives[0].value)
    sw = mech.sweep(count=count, start=d0 - span / 2, stop=d0 + span / 2)
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


CAMS = [ROOT / "gallery" / "mechanisms" / f for f in
        ("ex11_3_cam_follower_four_force.toml", "ex11_5_cam_follower_friction.toml")]


def _with_rates(path: Path) -> graphkin.Mechanism:
    from graphkin.files import load_toml
    from graphkin.mechanisms import from_dict

    data = load_toml(path)
    data["drive"].update(omega=12.0, alpha=-5.0)
    return from_dict(data, source=path.name)


def _face_height(t: float) -> float:
    """Height where the cam's face (through K1, K2 of Ex. 11.3, turned by t) meets x = 0."""
    k1, k2 = (-8.754645, 10.167176), (8.754645, 19.832824)
    m = (k2[1] - k1[1]) / (k2[0] - k1[0])
    c, s = math.cos(t), math.sin(t)
    x1, y1 = c * k1[0] - s * k1[1], s * k1[0] + c * k1[1]
    slope = math.tan(math.atan(m) + t)
    return y1 - slope * x1  # the face y = y1 + slope (x - x1) at x = 0


def test_the_cam_followers_of_chapter_11_are_constructed():
    # Example 11.3 (Fig. 11.10): the follower's slot passes through both bearings B and D of
    # the frame, so it lies along BD (θ3 from the line BD, kept as the frame's); its point A
    # is where the axis meets the cam's face (two lines, case 3).  A's height is the cam
    # face's height on the axis x = 0: the face through K1, K2 of the cam turned by θ2
    for path in CAMS:
        mech = graphkin.load(path)
        eng = _Engine(mech, DEFAULT_TOL)
        assert eng.method == "construction"
        assert [s.op for s in eng.pc.construction.steps if s.outputs == ("A",)] == ["meet"]
        # the face turns past the follower's axis near θ2 = ±64° (A runs off to infinity):
        # compared over 100° about the file's drive
        _against_analytic(mech, 41, 100.0)
        mech = _with_rates(path)
        _against_analytic(mech, 41, 100.0)
        sol = mech.solve()
        # by hand: the follower's axis is x = 0 (through B and D); the cam's face through K1,
        # K2 turned by θ2 about O2 meets it at the height h(θ2) below, so A = (0, h) and
        # V_A = (0, ω2 dh/dθ2), dh/dθ2 by a central difference of this closed form
        d = 1e-5
        v = (_face_height(d) - _face_height(-d)) / (2 * d) * 12.0
        np.testing.assert_allclose(sol.velocity("A"), [0.0, v], rtol=0, atol=1e-6 * abs(v))
        np.testing.assert_allclose(sol.position("A"), [0.0, _face_height(0.0)], rtol=0,
                                   atol=1e-9 * 60)


@st.composite
def _followers(draw, with_rates: bool) -> tuple[dict, dict]:
    # a follower 3 held in two bearings B, D of the frame (one straight slot line of it), its
    # point A on a straight face of a cam 2 turning about O2; every angle and offset at random
    f = lambda lo, hi: draw(st.floats(lo, hi, allow_nan=False))  # noqa: E731

    def e(t: float) -> np.ndarray:
        return np.array([math.cos(t), math.sin(t)])

    def rot(t: float, p) -> np.ndarray:
        c, s = math.cos(t), math.sin(t)
        return np.array([c * p[0] - s * p[1], s * p[0] + c * p[1]])

    psi = f(-math.pi, math.pi)  # the bearings' line
    p0 = np.array([f(-1.0, 1.0), f(0.5, 1.5)])
    b1 = f(-0.5, 0.5)
    b2 = b1 + draw(st.sampled_from([-1.0, 1.0])) * f(0.4, 1.0)
    beta = f(-math.pi, math.pi)  # the slot's direction in the follower
    s0 = np.array([f(-0.5, 0.5), f(-0.5, 0.5)])
    a_loc = s0 + e(beta) * f(-1.0, 1.0) + e(beta + math.pi / 2) * f(-0.3, 0.3)
    th3 = psi - beta + draw(st.sampled_from([0.0, math.pi]))
    t2 = f(-math.pi, math.pi)
    gamma = psi + f(0.5, math.pi - 0.5)  # the face's world angle, not along the bearings
    k1w = np.array([f(-0.3, 0.3), f(-0.3, 0.3)])
    # A on the face: p0 + λ u + R(θ3)(A - S0) = K1 + μ v
    u, v = e(psi), e(gamma)
    rhs = k1w - p0 - rot(th3, a_loc - s0)
    lam, mu = np.linalg.solve(np.column_stack([u, -v]), rhs)
    origin = p0 + lam * u - rot(th3, s0)
    k1 = rot(-t2, k1w)
    k2 = rot(-t2, k1w + v)
    world = lambda q: origin + rot(th3, q)  # noqa: E731
    e_loc = a_loc + e(beta + math.pi / 2) * 0.5 + e(beta) * 0.3
    data = {
        "units": {"length": "m"},
        "links": {"1": {"O2": [0.0, 0.0], "B": list(p0 + b1 * u), "D": list(p0 + b2 * u)},
                  "2": {"O2": [0.0, 0.0], "K1": list(k1), "K2": list(k2)},
                  "3": {"A": list(a_loc), "E": list(e_loc), "S1": list(s0),
                        "S2": list(s0 + e(beta))}},
        "slots": [{"link": 1, "on": 3, "point": "B", "line": ["S1", "S2"]},
                  {"link": 1, "on": 3, "point": "D", "line": ["S1", "S2"]},
                  {"link": 3, "on": 2, "point": "A", "line": ["K1", "K2"]}],
        "drive": {"link": 2, "angle": math.degrees(t2)},
        "assembly": {"A": list(world(a_loc)), "E": list(world(e_loc))},
    }
    if with_rates:
        data["drive"].update(omega=f(1.0, 20.0) * draw(st.sampled_from([-1, 1])),
                             alpha=f(-50.0, 50.0))
    return data, {"A": world(a_loc), "E": world(e_loc)}


@examples(30)
@given(case=st.one_of(_followers(True), _followers(False)))
def test_random_followers_in_two_bearings_sweep_like_the_analytic_solver(case):
    from graphkin.mechanisms import from_dict

    data, truth = case
    mech = from_dict(data, source="<random follower>")
    assert _Engine(mech, DEFAULT_TOL).method == "construction"
    sol = mech.solve()
    for n, xy in truth.items():  # the posture drawn, branch and all
        np.testing.assert_allclose(sol.position(n), xy, rtol=0, atol=1e-9 * 4, err_msg=n)
    # 25° each way from the drawn posture (each sweep starts where the file is drawn, so
    # that both solvers start from its branch)
    d0 = math.degrees(mech.drives[0].value)
    for stop in (d0 + 25.0, d0 - 25.0):
        sw = mech.sweep(count=16, start=d0, stop=stop)
        drive = np.radians(np.asarray(sw.drive_values, dtype=float))
        an = solve_analytic_many(mech, drive)
        ok = np.asarray(an.valid) & np.asarray(sw.assembled)
        assert ok[0]
        for n in ("A", "E"):
            np.testing.assert_allclose(np.asarray(sw.solution.position(n))[ok],
                                       np.asarray(an.position(n))[ok], rtol=0,
                                       atol=1e-9 * 10, err_msg=n)
            if mech.has_rates:
                for what in ("velocity", "acceleration"):
                    ref = np.asarray(getattr(an, what)(n))[ok]
                    np.testing.assert_allclose(
                        np.asarray(getattr(sw.solution, what)(n))[ok], ref, rtol=0,
                        atol=1e-9 * (1 + np.max(np.abs(ref))), err_msg=f"{what} {n}")


def test_the_verdicts_hold_under_round_off():
    # every coordinate of Example 11.3's and Fig. 3.27's files moved by 1e-12 of the size: the
    # same construction (two slides meet, the follower's slot along BD) with the same
    # branches, the same posture to round-off
    from graphkin.files import load_toml
    from graphkin.kinematics.posture import build_posture
    from graphkin.mechanisms import from_dict

    rng = np.random.default_rng(11)
    for path in (YOKE, CAMS[0]):
        data = load_toml(path)
        base = build_posture(graphkin.load(path))
        for _ in range(3):
            moved = {**data, "links": {lid: {n: [float(c) * (1 + 1e-12 * rng.normal())
                                                 + 1e-12 * 60 * rng.normal() for c in xy]
                                             for n, xy in pts.items()}
                                       for lid, pts in data["links"].items()}}
            mech = from_dict(moved, source=path.name)
            pc = build_posture(mech)
            assert [s.op for s in pc.construction.steps] == \
                [s.op for s in base.construction.steps]
            assert pc.branches == base.branches
            for n in ("A", "F") if path == YOKE else ("A", "E"):
                np.testing.assert_allclose(g.xy(pc.values[n]), g.xy(base.values[n]), rtol=0,
                                           atol=1e-9 * 60, err_msg=n)


def test_a_slot_parallel_to_the_guide_is_not_two_slides():
    # the yoke's slot turned along the guide: the two paths of F never meet (parallel within
    # round-off), so no construction step claims them: link 4 is left to the analytic solver
    import pytest

    from graphkin.files import load_toml
    from graphkin.kinematics.posture import NotDecomposable, build_posture
    from graphkin.mechanisms import from_dict

    data = load_toml(YOKE)
    data["links"]["4"]["S1"] = [1, 0]
    with pytest.raises(NotDecomposable, match="link 4"):
        build_posture(from_dict(data, source="parallel.toml"))
