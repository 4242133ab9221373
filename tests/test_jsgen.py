"""The JavaScript writer (graphkin/construction/jsgen.py) computes the recorded construction.

The function is written from the same templates as the Python writer; these
tests run it (node, else headless Chromium: tests/jsrun.py) on JavaScript
numbers and hold it to the step-by-step replay through the general numpy
operations (``Construction.replay``, an independent path: no template, no
kernel) to 1e-9, for random mechanisms of every family of tests/strategies.py
at random drive values, and check that the mechanism's dimensions are
parameters: moving a frame pivot in ``K`` gives the construction recorded from
the edited file.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from jsrun import close, js_or_skip, run_js
from strategies import RandomMechanism, examples, mechanisms

import graphkin
from graphkin.construction.codegen import TEMPLATES, Unsupported
from graphkin.construction.jsgen import RUNTIME, generate_js, js_string
from graphkin.kinematics.posture import NotDecomposable
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.tolerance import DEFAULT_TOL

REL = 1e-9


@pytest.fixture(scope="module", autouse=True)
def _js():
    js_or_skip()
    yield
    close()


def _setup(mech: graphkin.Mechanism):
    try:
        eng = _Engine(mech, DEFAULT_TOL)
    except NotDecomposable:
        return None
    if eng.method != "construction":
        return None
    cx = eng.combined if eng.combined is not None else eng.pc.construction
    consts = dict(eng.held)
    if eng.combined is not None:
        consts.update(eng.rate_given)
    return eng, cx, consts


def _run(fn, cases: list[dict[str, float]], k: list[float] | None = None) -> list:
    src = (RUNTIME + fn.source + f"\nconst K = {json.dumps(k if k is not None else fn.values)};"
           f"\nconst RESULT = {json.dumps(cases)}.map((I) => {fn.name}(I, K));")
    return run_js(src)


def _compare(cx, fn, got: dict, inputs: dict) -> None:
    ref = cx.replay(inputs, strict=False)
    kinds = {o: s.kind for s in cx.steps for o in s.outputs}
    for lab in fn.requests:
        r = np.asarray(ref.values[lab], dtype=float)
        v = np.asarray(got[lab], dtype=float)
        if kinds[lab] == "point":
            r = r[:2] / r[2]
        if kinds[lab] == "scalar" and lab.startswith("θ"):
            v = r + np.remainder(v - r + np.pi, 2 * np.pi) - np.pi
        scale = 1.0 + float(np.abs(r).max(initial=0.0))
        np.testing.assert_allclose(v, r, rtol=REL, atol=REL * scale, err_msg=lab)


@examples(30)
@given(rm=mechanisms(), offsets=st.lists(st.floats(-0.05, 0.05), min_size=1, max_size=4))
def test_javascript_equals_the_replay(rm: RandomMechanism, offsets: list[float]) -> None:
    # every value the emitted JavaScript computes is the numpy replay's, posture by posture;
    # where the replay cannot construct a posture the function says so (null), never NaN
    mech = rm.mechanism()
    got_setup = _setup(mech)
    if got_setup is None:
        return
    eng, cx, consts = got_setup
    labels = list(dict.fromkeys(o for s in cx.steps for o in s.outputs if s.op != "input"))
    fn = generate_js(cx.steps, requests=labels)  # every family: no Unsupported
    d = mech.drives[0]
    scale = 1.0 if d.kind == "angle" else mech.scale
    cases = [{**consts, eng.label: d.value + o * scale} for o in offsets]
    out = _run(fn, cases)
    for inputs, got in zip(cases, out):
        ref = cx.replay(inputs, strict=False)
        if not bool(np.all(ref.valid)):
            assert got is None
            continue
        if got is None:  # the clean case only: the Python writer refuses the same posture
            from graphkin.construction.codegen import generate
            py = generate(cx.steps, varying=[eng.label], constants=consts,
                          requests=[(labels[0], "value")])
            assert py.fn(np.array([inputs[eng.label]])) is None
            continue
        _compare(cx, fn, got, inputs)


@examples(20)
@given(rm=mechanisms(), moves=st.lists(st.tuples(st.floats(-0.02, 0.02), st.floats(-0.02, 0.02)),
                                       min_size=4, max_size=4))
def test_frame_points_are_parameters(rm: RandomMechanism,
                                     moves: list[tuple[float, float]]) -> None:
    # every family: frame points moved in K give the replay of the construction recorded with
    # those points moved (the same steps, the 'point' steps' coordinates changed)
    from graphkin.construction import Construction

    mech = rm.mechanism()
    got_setup = _setup(mech)
    if got_setup is None:
        return
    eng, cx, consts = got_setup
    labels = list(dict.fromkeys(o for s in cx.steps for o in s.outputs if s.op != "input"))
    fn = generate_js(cx.steps, requests=labels)
    names = [n for n, _ in fn.slots]
    k = fn.values
    given = [s for s in cx.steps if s.op == "point"]
    # a frame point that is also a slider's line point is a path, not a pivot: not moved
    frame = [s for s in given if s.outputs[0] in mech.links["1"].points and
             sum(tuple(t.params["xy"]) == tuple(s.params["xy"]) for t in given) == 1]
    moved = Construction()
    for s in cx.steps:
        params = dict(s.params)
        if s in frame[:len(moves)]:
            dx, dy = moves[frame.index(s)]
            x, y = s.params["xy"]
            params["xy"] = (x + dx * mech.scale, y + dy * mech.scale)
            k[names.index(f"{s.outputs[0]}.0")] = params["xy"][0]
            k[names.index(f"{s.outputs[0]}.1")] = params["xy"][1]
        moved.add(s.op, s.inputs, s.outputs, **params)
    inputs = {**consts, eng.label: mech.drives[0].value}
    got = _run(fn, [inputs], k)[0]
    ref = moved.replay(inputs, strict=False)
    if not bool(np.all(ref.valid)):
        assert got is None  # moved too far: this posture cannot be constructed
        return
    if got is None:  # the clean case only (a tangency within the margin): refused, not wrong
        return
    _compare(moved, fn, got, inputs)


def test_dimensions_are_parameters(examples, tmp_path) -> None:
    # Example 3.1 (Fig. 3.6): the written function with the frame pivot D moved in K is the
    # construction recorded from the file with D moved (nothing of the file written in)
    text = (examples / "ex3_1_fourbar.toml").read_text(encoding="utf-8")
    mech = graphkin.load(examples / "ex3_1_fourbar.toml")
    eng, cx, consts = _setup(mech)
    labels = list(dict.fromkeys(o for s in cx.steps for o in s.outputs if s.op != "input"))
    fn = generate_js(cx.steps, requests=labels)
    names = [n for n, _ in fn.slots]
    k = fn.values
    assert (k[names.index("D.0")], k[names.index("D.1")]) == (10.0, 0.0)
    k[names.index("D.0")] = 10.5
    k[names.index("D.1")] = -0.25
    got = _run(fn, [{**consts, eng.label: mech.drives[0].value}], k)[0]
    assert text.count("D = [10, 0]") == 1
    edited = tmp_path / "edited.toml"
    edited.write_text(text.replace("D = [10, 0]", "D = [10.5, -0.25]"), encoding="utf-8")
    mech2 = graphkin.load(edited)
    eng2, cx2, consts2 = _setup(mech2)
    _compare(cx2, fn, got, {**consts2, eng2.label: mech2.drives[0].value})
    # and it is not the unedited construction (C moves with D, if less than D)
    c = np.asarray(cx.replay({**consts, eng.label: mech.drives[0].value},
                             strict=False).values["C"])
    assert np.hypot(got["C"][0] - c[0] / c[2], got["C"][1] - c[1] / c[2]) > 1e-3


def test_every_template_writes_javascript() -> None:
    # the one table: every operation with a template is written in both languages (a
    # template written only for Python would raise here)
    from graphkin.construction.ops import templates  # noqa: F401
    assert {"rigid", "intersect_circles", "intersect_line_circle", "meet", "join",
            "velocity_difference", "acceleration_difference", "coriolis", "point",
            "scalar"} <= set(TEMPLATES)


def test_an_operation_without_a_template_is_refused() -> None:
    from graphkin.construction import Construction

    cx = Construction()
    cx.add("input", (), ("θ",), name="θ")
    cx.add("point", (), ("A",), xy=(0.0, 0.0))
    cx.add("ideal_point", (), ("P",), direction=(1.0, 0.0))
    with pytest.raises(Unsupported, match="ideal_point"):
        generate_js(cx.steps, requests=["P"])


def test_labels_are_escaped_for_a_script() -> None:
    s = js_string('</script><!--"\u2028')
    assert "<" not in s and ">" not in s and "\u2028" not in s
    assert run_js(f"const RESULT = {s};") == '</script><!--"\u2028'
