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
from hypothesis import assume, given
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


@examples(15)
@given(xy=st.lists(st.floats(-10.0, 10.0), min_size=8, max_size=8))
def test_the_curvature_templates_equal_the_general_functions(xy: list[float]) -> None:
    # the JavaScript-only templates of the curvature constructions (Secs. 4.13-4.17) against
    # the numpy operations (Construction.replay): the circle through three points, the second
    # meet of two circles through a point, of a line through a point of a circle, and the
    # fourth vertex of a parallelogram
    from graphkin.construction import Construction

    cx = Construction()
    names = ["P", "Q", "R", "S"]
    for n in names:
        cx.add("input", (), (f"{n}x",), name=f"{n}x")
        cx.add("input", (), (f"{n}y",), name=f"{n}y")
        cx.add("point_xy", (f"{n}x", f"{n}y"), (n,))
    cx.add("circumcircle", ("P", "Q", "R"), ("c1",))
    cx.add("circumcircle", ("P", "R", "S"), ("c2",))
    cx.add("other_intersection", ("c1", "c2", "P"), ("X",))
    cx.add("join", ("P", "S"), ("PS",))
    cx.add("second_on_circle", ("PS", "c1", "P"), ("Y",))
    cx.add("parallelogram", ("P", "Q", "S"), ("G",))
    inputs = {f"{n}{a}": xy[2 * k + (a == "y")] for k, n in enumerate(names) for a in "xy"}
    # a well-conditioned figure (points apart, triangles not flat, circles' centers apart):
    # otherwise both evaluations are right only to the problem's own conditioning
    pts = np.reshape(xy, (4, 2))

    def area(i: int, j: int, k: int) -> float:
        u, w = pts[j] - pts[i], pts[k] - pts[i]
        return abs(float(u[0] * w[1] - u[1] * w[0]))

    assume(min(float(np.hypot(*(pts[i] - pts[j]))) for i in range(4) for j in range(i)) > 1.0)
    assume(area(0, 1, 2) > 2.0 and area(0, 2, 3) > 2.0)
    ref = cx.replay(inputs, strict=False)
    if not bool(np.all(ref.valid)):
        return
    c1, c2 = (np.asarray(ref.values[c], dtype=float) for c in ("c1", "c2"))
    assume(float(np.hypot(*(c1[:2] - c2[:2]))) > 1.0 and max(c1[2], c2[2]) < 100.0)
    fn = generate_js(cx.steps, requests=["c1", "c2", "X", "Y", "G"])
    got = _run(fn, [inputs])[0]
    if got is None:
        return
    for lab in fn.requests:
        r = np.asarray(ref.values[lab], dtype=float)
        if lab in ("X", "Y", "G"):
            r = r[:2] / r[2]
        scale = 1.0 + float(np.abs(r).max())
        np.testing.assert_allclose(got[lab], r, rtol=0, atol=1e-9 * scale, err_msg=lab)


@examples(15)
@given(xy=st.lists(st.floats(-10.0, 10.0), min_size=6, max_size=6),
       t=st.floats(-3.0, 3.0))
def test_the_centers_templates_work_at_infinity(xy: list[float], t: float) -> None:
    # Kennedy's lines through a center at infinity (a slider's, [-sin t, cos t, 0]) and the
    # meet of parallel lines, in homogeneous coordinates, against the numpy replay: the same
    # points of the projective plane (unit vectors, equal up to sign)
    from graphkin.construction import Construction

    cx = Construction()
    cx.add("point", (), ("A",), xy=(xy[0], xy[1]))
    cx.add("point", (), ("B",), xy=(xy[2], xy[3]))
    cx.add("point", (), ("C",), xy=(xy[4], xy[5]))
    cx.add("ideal_point", (), ("U",), direction=(-np.sin(t), np.cos(t)))
    cx.add("join", ("A", "U"), ("AU",))
    cx.add("join", ("B", "U"), ("BU",))     # parallel to AU: they meet at U
    cx.add("join", ("B", "C"), ("BC",))
    cx.add("meet", ("AU", "BC"), ("X",))
    cx.add("meet", ("AU", "BU"), ("Y",))
    cx.add("at_infinity_on", ("BC",), ("Z",))
    ref = cx.replay({}, strict=False)
    fn = generate_js(cx.steps, requests=["X", "Y", "Z"], given=["A", "B", "C", "U"])
    src = (RUNTIME + fn.source + "\nconst RESULT = " + fn.name + "(" + json.dumps(
        {"A": [xy[0], xy[1], 1], "B": [xy[2], xy[3], 1], "C": [xy[4], xy[5], 1],
         "U": [-np.sin(t), np.cos(t), 0]}) + ", " + json.dumps(fn.values) + ");")
    got = run_js(src)
    if got is None:  # two given points coincide (or the line BC is along U): no line
        return
    for lab in ("X", "Y", "Z"):
        g = np.asarray(got[lab], dtype=float)
        r = np.asarray(ref.values[lab], dtype=float)
        if not np.all(np.isfinite(r)) or np.linalg.norm(r) == 0:
            continue
        g, r = g / np.linalg.norm(g), r / np.linalg.norm(r)
        if float(np.dot(g, r)) < 0:
            g = -g
        np.testing.assert_allclose(g, r, rtol=0, atol=1e-9, err_msg=lab)
    # Y is the point at infinity U itself
    y = np.asarray(got["Y"], dtype=float)
    assert abs(y[2]) <= 1e-12 * np.linalg.norm(y)


def _moving_points(names: list[str], xy: list[float]):
    """A construction whose points turn with one input θ: ``X = O_X + R(θ) d_X``.

    Each point is a ``rigid`` step from a fixed point, so it varies with θ and
    both writers take it in their own Cartesian form (no general function).
    """
    from graphkin.construction import Construction

    cx = Construction()
    cx.add("input", (), ("θ",), name="θ")
    for k, n in enumerate(names):
        o = (xy[4 * k], xy[4 * k + 1])
        cx.add("point", (), (f"O{n}",), xy=o)
        cx.add("rigid", (f"O{n}", "θ"), (n,), local_p=(0.0, 0.0),
               local_q=(xy[4 * k + 2], xy[4 * k + 3]))
    return cx


def _both_writers(cx, requests: list[str], th: np.ndarray) -> None:
    """The Python and the JavaScript function of ``cx`` against its replay, posture by posture."""
    from graphkin.construction.codegen import generate

    ref = cx.replay({"θ": th}, strict=False)
    py = generate(cx.steps, varying=["θ"], requests=[(lab, "value") for lab in requests])
    assert "_op" not in py.source  # the template, not the general function
    got = py.values(th)
    if bool(np.all(ref.valid)):
        assert got is not None
        for lab in requests:
            r = np.asarray(ref.values[lab], dtype=float)
            # a value that does not depend on θ is returned once (the caller broadcasts it)
            np.testing.assert_allclose(np.broadcast_to(got[lab], r.shape), r, rtol=1e-12,
                                       atol=1e-12 * (1.0 + np.abs(ref.values[lab]).max()),
                                       err_msg=lab)
    fn = generate_js(cx.steps, requests=requests)
    out = _run(fn, [{"θ": float(t)} for t in th])
    for k, t in enumerate(th):
        one = cx.replay({"θ": float(t)}, strict=False)
        if not bool(np.all(one.valid)):
            assert out[k] is None  # never a NaN: the page says it cannot construct it
            continue
        assert out[k] is not None
        for lab in requests:
            r = np.asarray(one.values[lab], dtype=float)
            r = r[:2] / r[2]
            np.testing.assert_allclose(out[k][lab], r, rtol=0, atol=REL * (1 + np.abs(r).max()),
                                       err_msg=lab)


@examples(15)
@given(xy=st.lists(st.floats(-10.0, 10.0), min_size=20, max_size=20),
       th=st.lists(st.floats(-3.2, 3.2), min_size=1, max_size=4))
def test_the_image_template_equals_the_general_function(xy: list[float],
                                                        th: list[float]) -> None:
    # Mehmke's theorem (Secs. 3.5, 4.3): the image p' of P from the images a', b' of A, B,
    # p' = a' + (b' - a')(P - A)/(B - A), the step that finds the inflection pole J from the
    # acceleration images (Sec. 4.15); the one template, written by both writers, against
    # the numpy operation (Construction.replay) at every posture
    cx = _moving_points(["A", "B", "a", "b", "P"], xy)
    cx.add("image", ("A", "B", "a", "b", "P"), ("p",))
    t = np.asarray(th)
    v = cx.replay({"θ": t}, strict=False).values
    # A and B apart (else both evaluations are only as good as the ratio's conditioning)
    assume(float(np.min(np.hypot(*(v["B"][:, :2] - v["A"][:, :2]).T))) > 0.5)
    _both_writers(cx, ["p"], t)


@examples(15)
@given(xy=st.lists(st.floats(-10.0, 10.0), min_size=12, max_size=12),
       th=st.lists(st.floats(-3.2, 3.2), min_size=1, max_size=4))
def test_the_euler_savary_template_equals_the_general_function(xy: list[float],
                                                               th: list[float]) -> None:
    # Eq. 4.43 laid off from A along the ray IA: R_AJ_A = R_AI²/R_AA' (Examples 4.14, 4.16)
    import graphkin.kinematics.curvature.euler_savary  # noqa: F401  (registers the operation)

    cx = _moving_points(["I", "A", "C"], xy)
    cx.add("euler_savary_inflection", ("I", "A", "C"), ("J_A",))
    t = np.asarray(th)
    v = cx.replay({"θ": t}, strict=False).values
    i, a, c = (v[n][:, :2] for n in ("I", "A", "C"))
    xa = np.hypot(*(a - i).T)
    # a ray of some length, A' apart from A along it (the lay-off divides by x_A' - x_A)
    assume(float(xa.min()) > 0.5)
    assume(float(np.min(np.abs(np.sum((c - i) * (a - i), axis=-1) / xa - xa))) > 0.5)
    _both_writers(cx, ["J_A"], t)


def test_the_image_of_a_link_whose_two_points_coincide_is_not_clean() -> None:
    # A = B: the ratio (P - A)/(B - A) does not exist; the replay marks the posture, the
    # Python function hands it to the replay (None) and the JavaScript says null, never NaN
    cx = _moving_points(["A", "B", "a", "b", "P"],
                        [0, 0, 1, 0, 0, 0, 1, 0, 2, 1, 1, 1, 3, 0, 1, 1, 4, 4, 1, 2])
    cx.add("image", ("A", "B", "a", "b", "P"), ("p",))
    from graphkin.construction.codegen import generate

    assert not bool(np.all(cx.replay({"θ": 0.3}, strict=False).valid))
    py = generate(cx.steps, varying=["θ"], requests=[("p", "value")])
    assert py.fn(np.array([0.3])) is None
    # even when nothing asked for reads it: the replay marks the posture, so must the function
    py = generate(cx.steps, varying=["θ"], requests=[("P", "value")])
    assert py.fn(np.array([0.3])) is None
    fn = generate_js(cx.steps, requests=["p"])
    assert _run(fn, [{"θ": 0.3}]) == [None]


@examples(8)
@given(xy=st.lists(st.floats(-10.0, 10.0), min_size=4, max_size=4), t=st.floats(-3.2, 3.2))
def test_a_conjugate_at_infinity_lays_off_the_point_itself(xy: list[float], t: float) -> None:
    # A' at infinity (A moves on a straight line: a slider's point, Sec. 4.13): J_A = A,
    # with A' given to the JavaScript as the page gives it, [x, y, 0] (Eq. 4.43, R_AA' → ∞)
    import graphkin.kinematics.curvature.euler_savary  # noqa: F401
    from graphkin.construction import Construction

    cx = Construction()
    cx.add("point", (), ("I",), xy=(xy[0], xy[1]))
    cx.add("point", (), ("A",), xy=(xy[2], xy[3]))
    cx.add("ideal_point", (), ("C",), direction=(-np.sin(t), np.cos(t)))
    cx.add("euler_savary_inflection", ("I", "A", "C"), ("J_A",))
    ref = np.asarray(cx.replay({}).values["J_A"], dtype=float)
    fn = generate_js(cx.steps, requests=["J_A"], given=["I", "A", "C"], homogeneous=False,
                     ideal=["C"])
    src = (RUNTIME + fn.source + "\nconst RESULT = " + fn.name + "(" + json.dumps(
        {"I": xy[:2], "A": xy[2:], "C": [-np.sin(t), np.cos(t), 0.0]}) + ", []);")
    got = run_js(src)
    np.testing.assert_allclose(got["J_A"], ref[:2] / ref[2], rtol=0, atol=1e-12)
    np.testing.assert_allclose(got["J_A"], xy[2:], rtol=0, atol=1e-12)


def test_soft_leaves_out_only_what_reads_a_step_with_no_clean_answer() -> None:
    # two parallel lines have no Cartesian meet: with soft=True the meet and what reads it
    # are null, the other results are returned (the curvature panel keeps its inflection
    # circle where Hain's G_T is at infinity, Example 4.16); without, the whole is null
    from graphkin.construction import Construction

    cx = Construction()
    for n, p in (("A", (0.0, 0.0)), ("B", (1.0, 0.0)), ("C", (0.0, 1.0)), ("D", (1.0, 1.0)),
                 ("E", (0.0, 2.0))):
        cx.add("point", (), (n,), xy=p)
    cx.add("join", ("A", "B"), ("AB",))
    cx.add("join", ("C", "D"), ("CD",))   # parallel to AB
    cx.add("join", ("A", "D"), ("AD",))
    cx.add("meet", ("AB", "CD"), ("X",))  # at infinity
    cx.add("meet", ("CD", "AD"), ("Y",))  # D
    cx.add("circle_on_diameter", ("X", "E"), ("k",))  # reads X
    given = ["A", "B", "C", "D", "E"]
    args = json.dumps({"A": [0, 0], "B": [1, 0], "C": [0, 1], "D": [1, 1], "E": [0, 2]})
    soft = generate_js(cx.steps, requests=["X", "Y", "k"], given=given, homogeneous=False,
                       soft=True)
    got = run_js(RUNTIME + soft.source + f"\nconst RESULT = {soft.name}({args}, []);")
    assert got["X"] is None and got["k"] is None
    np.testing.assert_allclose(got["Y"], [1.0, 1.0], rtol=0, atol=1e-12)
    hard = generate_js(cx.steps, requests=["X", "Y", "k"], given=given, homogeneous=False)
    assert run_js(RUNTIME + hard.source + f"\nconst RESULT = {hard.name}({args}, []);") is None
