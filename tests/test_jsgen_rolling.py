"""The JavaScript writer on gear trains: roll_circle_angle and planetary_arm (Sec. 7.15).

The same property as tests/test_jsgen.py, for the two operations of gears
rolling on circles: the function written out from the one table of templates
computes, on JavaScript numbers, every value of the step-by-step numpy replay
(``Construction.replay``, the general functions: no template) to 1e-9, at
drive values several turns from the file's, where the angles must not be
taken modulo 2π (the covering).
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from jsrun import close, js_or_skip, run_js
from strategies import examples
from strategies_rolling import rolling_arrangements

from graphkin.construction.jsgen import RUNTIME, generate_js
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.tolerance import DEFAULT_TOL


@pytest.fixture(scope="module", autouse=True)
def _js():
    js_or_skip()
    yield
    close()


@examples(10)
@given(rm=st.one_of(rolling_arrangements("gears"), rolling_arrangements("gear chain"),
                    rolling_arrangements("planet")),
       offsets=st.lists(st.floats(-20.0, 20.0), min_size=1, max_size=4))
def test_javascript_equals_the_replay_turns_away(rm, offsets):
    mech = rm.mechanism()
    eng = _Engine(mech, DEFAULT_TOL)
    assert eng.method == "construction", rm.kind
    cx = eng.combined if eng.combined is not None else eng.pc.construction
    assert {"roll_circle_angle"} <= {s.op for s in cx.steps}
    consts = {**eng.held, **(eng.rate_given if eng.combined is not None else {})}
    labels = list(dict.fromkeys(o for s in cx.steps for o in s.outputs if s.op != "input"))
    fn = generate_js(cx.steps, requests=labels)
    cases = [{**consts, eng.label: mech.drives[0].value + o} for o in offsets]
    src = (RUNTIME + fn.source + f"\nconst K = {json.dumps(fn.values)};"
           f"\nconst RESULT = {json.dumps(cases)}.map((I) => {fn.name}(I, K));")
    kinds = {o: s.kind for s in cx.steps for o in s.outputs}
    for inputs, got in zip(cases, run_js(src)):
        ref = cx.replay(inputs, strict=False)
        assert bool(np.all(ref.valid)) and got is not None
        for lab in fn.requests:
            r = np.asarray(ref.values[lab], dtype=float)
            v = np.asarray(got[lab], dtype=float)
            if kinds[lab] == "point":
                r = r[:2] / r[2]
            # angles as they are, not modulo 2π: the covering is the same in both
            np.testing.assert_allclose(v, r, rtol=1e-9, atol=1e-9 * (1 + np.abs(r).max()),
                                       err_msg=lab)
