"""The generated sweep function (graphkin/construction/codegen.py) is the recorded construction.

The function is written from the recorded steps; these tests hold it to the
two independent references: the step-by-step replay through the general
operations (``Construction.replay``, to 1e-12 relative) and the analytic
solver (Newton on the loop equations, ``solve_analytic_many``), over random
four-bars, slider-cranks, inverted slider-cranks, slotted links, double
sliders, six-bars and five-bars (tests/strategies.py).  A sweep that goes
through the generated function gives the columns the replay gives.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from strategies import RandomMechanism, examples, mechanisms

import graphkin
from graphkin.construction import Construction
from graphkin.construction.codegen import PYTHON_GENERIC, TEMPLATES, Unsupported, generate
from graphkin.kinematics.posture import NotDecomposable
from graphkin.kinematics.sweep.columns import (
    _assembled_of,
    _columns,
    _columns_of_solution,
    _valid_of,
)
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.kinematics.sweep.fast import fast_columns
from graphkin.tolerance import DEFAULT_TOL

REL = 1e-12


def _engine_of(mech: graphkin.Mechanism) -> _Engine | None:
    try:
        eng = _Engine(mech, DEFAULT_TOL)
    except NotDecomposable:
        return None
    return None if eng.method != "construction" else eng


def _construction(eng: _Engine) -> tuple[Construction, dict]:
    cx = eng.combined if eng.combined is not None else eng.pc.construction
    consts = dict(eng.held)
    if eng.combined is not None:
        consts.update(eng.rate_given)
    return cx, consts


def _kind(label: str) -> str:
    """The quantity a label is of (``A_P/3^c`` -> ``A``, ``V_B`` -> ``V``; a point: its place)."""
    return label.split("_")[0] if "_" in label else "place"


def _same(got: dict, ref: dict, rel: float = REL) -> None:
    """Every generated value equals the replay's (angles a whole turn apart are the same).

    The absolute tolerance is round-off of the scale of the label's kind (the largest
    acceleration for an acceleration), not of the label alone: a Coriolis term of 1e-5
    in a mechanism whose accelerations are 1e2 is summed in another order by the two
    and differs by 3e-12, round-off of 1e2 (seen with random seeds).
    """
    kinds: dict[str, float] = {}
    for k in got:
        r = np.abs(np.asarray(ref[k], dtype=float))
        kinds[_kind(k)] = max(kinds.get(_kind(k), 0.0), float(r.max(initial=0.0)))
    for k, v in got.items():
        r = np.asarray(ref[k], dtype=float)
        v = np.broadcast_to(np.asarray(v, dtype=float), np.broadcast_shapes(np.shape(v),
                                                                             r.shape))
        r = np.broadcast_to(r, v.shape)
        if k.startswith("θ"):
            v = r + np.remainder(v - r + np.pi, 2 * np.pi) - np.pi
        scale = 1.0 + (np.pi if k.startswith("θ") else kinds[_kind(k)])
        np.testing.assert_allclose(v, r, rtol=rel, atol=rel * scale, err_msg=k)


def _drive_values(mech: graphkin.Mechanism, span: float, n: int = 23) -> np.ndarray:
    d = mech.drives[0]
    scale = 1.0 if d.kind == "angle" else mech.scale
    return d.value + span * scale * np.linspace(-1.0, 1.0, n)


@examples(60)
@given(rm=mechanisms(), span=st.floats(1e-4, 0.02))
def test_generated_function_equals_the_replay(rm: RandomMechanism, span: float) -> None:
    # near the file's posture (transmission angles 25-155°: clean) the generated function
    # answers, and every label it writes equals the step-by-step replay
    mech = rm.mechanism()
    eng = _engine_of(mech)
    if eng is None:
        return
    cx, consts = _construction(eng)
    labels = list(dict.fromkeys(o for s in cx.steps for o in s.outputs if s.op != "input"))
    gen = generate(cx.steps, varying=[eng.label], constants=consts,
                   requests=[(lab, "value") for lab in labels])
    dv = _drive_values(mech, span)
    got = gen.values(dv)
    ref = cx.replay({**consts, eng.label: dv}, strict=False)
    if not bool(np.all(ref.valid)):  # a limit of the travel close by: not clean, replayed
        assert got is None
        return
    assert got is not None, rm.kind
    assert set(got) == set(labels)
    _same(got, ref.values)


@examples(40)
@given(rm=mechanisms(), span=st.floats(1e-3, 0.02))
def test_generated_sweep_equals_the_analytic_solver(rm: RandomMechanism, span: float) -> None:
    # the columns of a sweep written out by the generator against Newton on the loop
    # equations, each posture from the one before (an independent solver)
    from graphkin.kinematics.analytic import solve_analytic_many

    mech = rm.mechanism()
    eng = _engine_of(mech)
    if eng is None or (eng.pol is not None and eng.combined is None):
        return  # [rates] of another link: the input's rates are found posture by posture
    dv = _drive_values(mech, span, 9)
    user = np.degrees(dv) if eng.drive.kind == "angle" else dv
    cols = fast_columns(eng, dv, user)
    if not bool(np.all(_valid_of(eng.solve(dv)))):
        assert cols is None  # a limit of the travel close by: not clean, replayed
        return
    assert cols is not None, rm.kind
    full = np.array([[dv_i if i == 0 else d.value for i, d in enumerate(mech.drives)]
                     for dv_i in dv])
    sol = solve_analytic_many(mech, full)
    assert bool(np.all(sol.valid))
    ref = _columns_of_solution(mech, sol, {"drive": user}, len(dv), mech.has_rates)
    assert list(cols) == list(ref)
    for k, r in ref.items():
        v = cols[k]
        if k.startswith("angle_"):
            v = r + np.remainder(v - r + 180.0, 360.0) - 180.0
        scale = 1.0 + float(np.abs(r).max())
        np.testing.assert_allclose(v, r, rtol=1e-7, atol=1e-7 * scale, err_msg=k)


@examples(40)
@given(rm=mechanisms(), span=st.floats(0.001, 3.0))
def test_sweep_columns_equal_the_replayed_columns(rm: RandomMechanism, span: float) -> None:
    # a whole sweep, near its posture or far enough to leave the range where it assembles:
    # written out or replayed (where a posture is not clean), the same columns, valid and
    # assembled as the replay of the constructions gives them
    mech = rm.mechanism()
    eng = _engine_of(mech)
    if eng is None:
        return
    d = mech.drives[0]
    scale = 1.0 if d.kind == "angle" else mech.scale
    half = span * scale
    start, stop = ((math.degrees(d.value - half), math.degrees(d.value + half))
                   if d.kind == "angle" else (d.value - half, d.value + half))
    sw = mech.sweep(count=31, start=start, stop=stop)
    blk = eng.solve(sw.values)
    blk.user = sw.columns["drive"]
    ref = _columns(eng, blk)
    np.testing.assert_array_equal(sw.valid, _valid_of(blk))
    np.testing.assert_array_equal(sw.assembled, _assembled_of(blk))
    assert list(sw.columns) == list(ref)
    for k, r in ref.items():
        r = np.where(sw.assembled, r, np.nan) if k != "drive" else r
        v = sw.columns[k]
        if k.startswith(("vx", "vy", "ax", "ay", "omega_", "alpha_")):
            r = np.where(sw.valid, r, np.nan)
        r = np.where(np.isfinite(r), r, np.nan)
        np.testing.assert_array_equal(np.isnan(v), np.isnan(r), err_msg=k)
        ok = ~np.isnan(r)
        scale = 1.0 + float(np.abs(r[ok]).max(initial=0.0))
        np.testing.assert_allclose(v[ok], r[ok], rtol=REL, atol=REL * scale, err_msg=k)
    # what a sweep keeps for later (Sweep.solution, singular postures) is still there
    assert sw.solution.valid.shape == (31,)


def test_unclean_postures_are_replayed(examples: Path) -> None:
    # ex3_1's four-bar does not assemble over part of a turn: the generated function says
    # so and the sweep replays the constructions, which mark those postures
    mech = graphkin.load(examples / "ex3_1_fourbar.toml")
    eng = _Engine(mech, DEFAULT_TOL)
    dv = np.radians(np.arange(0.0, 360.0, 5.0))
    assert fast_columns(eng, dv, np.degrees(dv)) is None
    sw = mech.sweep(count=72, start=0)
    assert not sw.assembled.all() and sw.assembled.any()
    assert np.isnan(sw.columns["x_C"][~sw.assembled]).all()


@pytest.mark.parametrize("name", ["ex4_7_cam_follower.toml", "ex4_4_coriolis_block.toml",
                                  "ex3_2_slider_driven.toml", "ex4_11_rapsons_slide.toml",
                                  "ex5_4_fivebar.toml"])
def test_example_functions_equal_the_replay(examples: Path, name: str) -> None:
    # the textbook's examples, near their own posture; the cam follower's steps without a
    # template are called through their general operations
    mech = graphkin.load(examples / name)
    eng = _Engine(mech, DEFAULT_TOL)
    cx, consts = _construction(eng)
    labels = list(dict.fromkeys(o for s in cx.steps for o in s.outputs if s.op != "input"))
    gen = generate(cx.steps, varying=[eng.label], constants=consts,
                   requests=[(lab, "value") for lab in labels])
    dv = _drive_values(mech, 1e-3, 7)
    got = gen.values(dv)
    assert got is not None
    _same(got, cx.replay({**consts, eng.label: dv}, strict=False).values)


def _small() -> Construction:
    """An arc about A meets an arc about D at C; B turns with θ about A (Table 2.2, case 4)."""
    cx = Construction()
    cx.add("input", (), ("θ",), name="θ")
    cx.add("point", (), ("A",), xy=(0.0, 0.0))
    cx.add("point", (), ("D",), xy=(8.0, 0.0))
    cx.add("rigid", ("A", "θ"), ("B",), local_p=(0.0, 0.0), local_q=(3.0, 0.0))
    cx.add("circle", ("B",), ("k_B",), radius=4.0)
    cx.add("circle", ("D",), ("k_D",), radius=5.0)
    cx.add("intersect_circles", ("k_B", "k_D"), ("C",), branch="left")
    return cx


def test_operations_without_a_template_are_called_through_their_general_function() -> None:
    # the drives a later branch adds come with new operations: a step the generator has
    # no template for (here a copy of a point, and the circle on a diameter) is called as
    # it is, and a templated step reading its value then is too
    # (their templates, if any, are the JavaScript writer's only: PYTHON_GENERIC)
    assert all(op not in TEMPLATES or op in PYTHON_GENERIC
               for op in ("copy_point", "circle_on_diameter"))
    cx = _small()
    cx.add("copy_point", ("C",), ("C2",))
    cx.add("rigid", ("C2", "θ"), ("E",), local_p=(0.0, 0.0), local_q=(1.0, 2.0))
    cx.add("circle_on_diameter", ("B", "D"), ("k_T",))
    cx.add("intersect_circles", ("k_T", "k_D"), ("T",), branch="right")
    th = np.linspace(0.2, 0.9, 11)
    labels = ["B", "C", "C2", "E", "k_T", "T"]
    gen = generate(cx.steps, varying=["θ"], requests=[(lab, "value") for lab in labels])
    assert "rigid" in TEMPLATES and "_op" in gen.source
    got = gen.values(th)
    assert got is not None
    _same(got, cx.replay({"θ": th}).values)
    # and as Cartesian rows
    xy = generate(cx.steps, varying=["θ"], requests=[("E", "x"), ("E", "y")]).fn(th)
    assert xy is not None
    ref = cx.replay({"θ": th})["E"]
    np.testing.assert_allclose(np.stack(xy, -1), ref[:, :2] / ref[:, 2:], rtol=REL)


def test_arcs_that_do_not_meet_are_not_clean() -> None:
    # at θ = π, B at (-3, 0) is 11 from D: the arcs (radii 4 and 5) do not meet
    cx = _small()
    gen = generate(cx.steps, varying=["θ"], requests=[("C", "x")])
    assert gen.fn(np.array([0.1, 0.5])) is not None
    assert gen.fn(np.array([0.1, math.pi])) is None
    assert gen.fn(np.array([0.1, np.nan])) is None


def test_what_is_not_given_or_not_made_cannot_be_written() -> None:
    cx = _small()
    with pytest.raises(Unsupported):
        generate(cx.steps, varying=[], requests=[("C", "x")])
    with pytest.raises(Unsupported):
        generate(cx.steps, varying=["θ"], requests=[("Z", "x")])


def test_a_repeated_step_is_written_once() -> None:
    # the acceleration polygon redraws the velocity polygon's lines: computed once
    cx = _small()
    cx.add("join", ("B", "C"), ("l",))
    cx.add("join", ("B", "C"), ("l",))
    gen = generate(cx.steps, varying=["θ"], requests=[("l", "value")])
    assert gen.source.count("_sqrt(") == 2  # the arcs' intersection and one join


def test_a_tangency_within_the_tolerance_is_clean() -> None:
    # |BD| = 9 = 4 + 5 where 73 - 48 cos θ = 81, cos θ = -1/6: the arcs touch (a dead
    # center); around it the replay rounds a tiny negative h² to zero, and so does the
    # generated function, with the same C: the compiled kernels' to rounding, the general
    # operations' to √ε (h = √(h²) turns a rounding of h² into one of √ε)
    cx = _small()
    th0 = math.acos(-1.0 / 6.0)
    th = th0 + np.arange(-8, 9) * 2e-16
    ref = cx.replay({"θ": th}, strict=False)
    assert bool(np.all(ref.valid))
    gen = generate(cx.steps, varying=["θ"], requests=[("C", "value")])
    got = gen.values(th)
    assert got is not None
    _same(got, cx.evaluate({"θ": th}).values)
    _same(got, ref.values, rel=1e-7)
