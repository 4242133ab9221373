"""The analytic solver's rows written out from the one table (kinematics/analytic/jsrows.py).

The Python the table writes must compute, at any state, exactly the rows the
solver computes with its own records (constraints.py, rolling.py, system.py):
the residual Φ(q), the Jacobian Φ_q, the rows of the known rates and γ
(Secs. 2.7, 3.9, 4.9).  The JavaScript is written from the same table by the
same code, line for line but for the syntax of an assignment; the page's
values are held to ``graphkin solve`` in tests/render/test_live_newton.py.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from strategies import examples, mechanisms, scotch_yokes
from strategies_rolling import rolling_arrangements

import graphkin
from graphkin.kinematics.analytic.jsrows import compile_python, write_rows
from graphkin.kinematics.analytic.newton import _Search
from graphkin.kinematics.analytic.rolling import _RollingCircle
from graphkin.kinematics.analytic.system import _System
from graphkin.mechanisms.model import FRAME
from graphkin.tolerance import DEFAULT_TOL

ROOT = Path(__file__).resolve().parents[2]

#: the gallery's mechanisms that only Newton's method sweeps: two sliders closing one loop,
#: rolling contacts on a line and on circles, a cam follower's linkage
NEWTON = ["centers/fig3_27_scotch_yoke.toml", "mechanisms/fig3_18_rolling_wheel.toml",
          "mechanisms/fig4_20_roller_follower.toml", "gears/ex11_7.toml",
          "mechanisms/ex11_3_cam_follower_four_force.toml",
          "mechanisms/ex11_5_cam_follower_friction.toml"]


def _check(mech: graphkin.Mechanism, seed: int) -> None:
    eqs = _System(mech, DEFAULT_TOL)
    values = np.array([d.value for d in mech.drives], dtype=float)
    q0 = _Search(eqs).solve(values)
    eqs = eqs.integrated(q0)  # the no-slip rows with their constants, as a sweep has them
    eqs.follow(q0)
    rows = write_rows(eqs, "python", dict(mech.links[FRAME].points))
    ns = compile_python(rows)
    K = [v for _, v in rows.slots]
    anchors = [c.anchor for c in eqs.cons if isinstance(c, _RollingCircle)]
    rng = np.random.default_rng(seed)
    size = float(eqs.size)
    for _ in range(4):
        # any state, not only an assembled one: the rows are functions of q
        q = q0 + rng.normal(size=q0.shape) * np.tile([0.1 * size, 0.1 * size, 0.3], eqs.nlinks)
        r, J = ns["gkRowsPhi"](q, K, values, anchors)
        r0, J0 = eqs.residual(q, values)
        m = len(r0)
        assert rows.m == m
        np.testing.assert_allclose(r[:m], r0, rtol=0, atol=1e-12 * size)
        np.testing.assert_allclose(J[:m], J0, rtol=0, atol=1e-12 * size)
        if eqs.rate_functions is None:
            continue
        A, _ = eqs.velocity_system(q)
        np.testing.assert_allclose(np.vstack([J[:eqs.ncons], J[m:]]), A, rtol=0,
                                   atol=1e-12 * size)
        qd = rng.normal(size=q.shape) * np.tile([size, size, 1.0], eqs.nlinks)
        g = np.array(ns["gkRowsGam"](q, qd, K, anchors))
        want = eqs.acceleration_rhs(q, qd)  # -γ, and g̈ - γ_g for the rate rows
        acc = np.array([a for _, a in eqs.rate_values or []])
        mine = np.concatenate([-g[:eqs.ncons], acc - g[eqs.ncons:]])
        np.testing.assert_allclose(mine, want, rtol=0, atol=1e-10 * size * (1 + size))


@pytest.mark.parametrize("name", NEWTON)
def test_the_gallerys_newton_mechanisms_rows_are_the_solvers(name):
    _check(graphkin.load(ROOT / "gallery" / name), 29)


def test_the_rolling_wheel_example_rows_are_the_solvers():
    _check(graphkin.load(ROOT / "examples" / "ex3_9_rolling_wheel.toml"), 3)


@examples(30)
@given(rm=mechanisms(), seed=st.integers(0, 2**16))
def test_random_mechanisms_rows_are_the_solvers(rm, seed):
    # every family of tests/strategies.py: pins, sliders, slots, angle rows, drives of
    # every kind, [rates] tables
    _check(rm.mechanism(), seed)


def test_a_pinned_frame_point_is_a_number_of_K():
    # the page drags a frame pivot by its K slots: the pin rows read them, and moving O2
    # moves the pin's rows by exactly the drag, with the sign of O2's side (Φ = P_a - P_b)
    mech = graphkin.load(ROOT / "gallery" / "centers" / "fig3_27_scotch_yoke.toml")
    eqs = _System(mech, DEFAULT_TOL)
    values = np.array([d.value for d in mech.drives], dtype=float)
    q0 = _Search(eqs).solve(values)
    eqs = eqs.integrated(q0)
    rows = write_rows(eqs, "python", dict(mech.links[FRAME].points))
    names = [n for n, _ in rows.slots]
    assert names[:2] == ["O2.0", "O2.1"]
    ns = compile_python(rows)
    K = [v for _, v in rows.slots]
    r0, _ = ns["gkRowsPhi"](q0, K, values, [])
    K2 = [K[0] + 3.0, K[1] - 2.0] + K[2:]
    r1, _ = ns["gkRowsPhi"](q0, K2, values, [])
    moved = np.subtract(r1, r0)
    assert np.count_nonzero(np.abs(moved) > 1e-12) == 2
    got = moved[np.abs(moved) > 1e-12]
    assert np.allclose(got, [3.0, -2.0], atol=1e-12) or np.allclose(got, [-3.0, 2.0], atol=1e-12)


@examples(30)
@given(rm=st.one_of(rolling_arrangements(), scotch_yokes()), seed=st.integers(0, 2**16))
def test_random_newton_mechanisms_rows_are_the_solvers(rm, seed):
    # the families Newton's method sweeps: every rolling arrangement of
    # tests/strategies_rolling.py (the no-slip rows on a line and on circles) and Scotch
    # yokes (two sliders closing one loop); first, the file's posture is the one the family
    # drew (the solver is the oracle only if it finds that posture)
    mech = rm.mechanism()
    sol = mech.solve()
    for name, xy in rm.world_points().items():
        np.testing.assert_allclose(sol.position(name), xy, rtol=0, atol=1e-9 * rm.scale(),
                                   err_msg=name)
    _check(mech, seed)


@pytest.fixture(scope="module")
def _js():
    from jsrun import close, js_or_skip

    js_or_skip()
    yield
    close()


@examples(15)
@given(rm=st.one_of(mechanisms(), rolling_arrangements(), scotch_yokes()),
       seed=st.integers(0, 2**16))
def test_the_javascript_rows_are_the_python_rows(_js, rm, seed):
    # the same table written twice: the JavaScript (node, else Chromium) computes the rows,
    # the Jacobian, γ and the anchors the Python does, at random states and rates
    import json

    from jsrun import run_js

    from graphkin.construction.jsgen import RUNTIME
    from graphkin.kinematics.analytic.jsrows import JS_RUNTIME

    mech = rm.mechanism()
    eqs = _System(mech, DEFAULT_TOL)
    values = np.array([d.value for d in mech.drives], dtype=float)
    q0 = _Search(eqs).solve(values)
    eqs = eqs.integrated(q0)
    eqs.follow(q0)
    frame = dict(mech.links[FRAME].points)
    py = compile_python(write_rows(eqs, "python", frame))
    js = write_rows(eqs, "js", frame)
    K = [v for _, v in js.slots]
    anchors = [c.anchor for c in eqs.cons if isinstance(c, _RollingCircle)]
    rng = np.random.default_rng(seed)
    size = float(eqs.size)
    qs = [list(q0 + rng.normal(size=q0.shape) * 0.1 * size) for _ in range(3)]
    qds = [list(rng.normal(size=q0.shape) * size) for _ in range(3)]
    src = (RUNTIME + JS_RUNTIME + js.source
           + f"const K = {json.dumps(K)}, V = {json.dumps(list(values))}, "
           f"A = {json.dumps(anchors)};\n"
           f"const RESULT = {json.dumps(qs)}.map((q, i) => [gkRowsPhi(q, K, V, A), "
           f"gkRowsGam(q, {json.dumps(qds)}[i], K, A), gkRowsAnchors(q, K, A)]);")
    got = run_js(src)
    for q, qd, (phi, gam, anc) in zip(qs, qds, got):
        r, J = py["gkRowsPhi"](np.array(q), K, values, anchors)
        np.testing.assert_allclose(phi[0], r, rtol=0, atol=1e-12 * size)
        np.testing.assert_allclose(np.array(phi[1]), J, rtol=0, atol=1e-12 * size)
        g = py["gkRowsGam"](np.array(q), np.array(qd), K, anchors)
        np.testing.assert_allclose(gam, g, rtol=0, atol=1e-10 * size * size)
        np.testing.assert_allclose(anc, py["gkRowsAnchors"](np.array(q), K, anchors), rtol=0,
                                   atol=1e-12)
