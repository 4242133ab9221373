"""The live curvature panel's Bresse circle and Γ hold at every posture the page reaches.

A file with α = 0 of its link (Example 4.4's block at a constant ω2, Example
3.9's wheel: tests/render/test_live_newton_curvature.py, in Chromium) has,
in graphkin's construction, no Bresse circle and Γ = J (Sec. 4.15).  The
page does not replay that identity: it constructs the Bresse circle and Γ
with the operations ``bresse_circle`` and ``acceleration_center``
(graphkin/construction/ops/bresse.py) on the ω and α of each posture, so
after a drag (α ≠ 0) it draws them, equal to graphkin's curvature of the file
the page saves, to 1e-9 of the size; where α = 0 it draws Γ = J and no
circle, as graphkin does.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from jsrun import close, js_or_skip, run_js
from live_edit import curvature_page, edited, same_curvature
from spec_data import EXAMPLES

import graphkin
from graphkin.construction.ops import OPS, templates  # noqa: F401  (registers bresse.py)
from graphkin.files import load_toml
from graphkin.kinematics.curvature.inflection import acceleration_center
from graphkin.kinematics.curvature.link import curvature
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_data
from graphkin.tolerance import DEFAULT_TOL

_num = st.floats(-50.0, 50.0, allow_nan=False)


@settings(max_examples=40)
@given(i=st.tuples(_num, _num), u=st.tuples(_num, _num), w=st.floats(0.1, 10.0),
       a=st.floats(-100.0, 100.0))
def test_the_bresse_circle_and_gamma_by_hand(i, u, w, a) -> None:
    # Sec. 4.15: the Bresse circle passes through I with its center on the centrode tangent at
    # (ω²/2α) k × R_JI from I (Eq. 4.48); Γ is on it and on the inflection circle on IJ; at
    # α = 0 there is no circle and Γ = J.  Γ also from one point's acceleration (Sec. 4.14,
    # Eqs. 4.44-4.45, inflection.acceleration_center): any point A = I + R of the link has
    # A_A = A_I + α k × R - ω² R (Eq. 4.5), the pole's A_I = ω² R_JI (Sec. 4.13)
    i, u = np.array(i), np.array(u)
    if np.hypot(*u) < 1e-3:
        return
    j = i + u
    h = [np.array([*i, 1.0]), np.array([*j, 1.0])]
    ref = w * w + abs(a)
    circle = OPS["bresse_circle"](*h, tol=DEFAULT_TOL, omega=w, alpha=a, ref=ref)[0]
    gam = OPS["acceleration_center"](*h, tol=DEFAULT_TOL, omega=w, alpha=a, ref=ref)[0]
    g = gam[:2] / gam[2]
    size = 1.0 + float(np.abs([*i, *j]).max())
    if abs(a) <= DEFAULT_TOL.angle * ref:
        assert np.all(np.isnan(circle))
        np.testing.assert_allclose(g, j, rtol=0, atol=1e-12 * size)
        return
    k = w * w / a
    np.testing.assert_allclose(circle[:2], i + 0.5 * k * np.array([-u[1], u[0]]), rtol=0,
                               atol=1e-9 * size * (1 + abs(k)))
    assert abs(np.hypot(*(circle[:2] - i)) - circle[2]) <= 1e-9 * size * (1 + abs(k))
    # on the inflection circle: IΓ ⊥ JΓ
    assert abs(np.dot(g - i, g - j)) <= 1e-9 * size * size
    r = np.array([3.0, -2.0])
    acc = w * w * u + a * np.array([-r[1], r[0]]) - w * w * r
    closed = np.asarray(acceleration_center(i + r, acc, w, a), dtype=float)
    np.testing.assert_allclose(g, closed, rtol=0, atol=1e-9 * size)


@pytest.fixture(scope="module")
def _js():
    js_or_skip()
    yield
    close()


def _drags(name: str, turns: list[float]) -> list[bool]:
    """The page's curvature after each turn of the drive against graphkin's of the saved file;
    for each posture reached, whether graphkin (and the page) has a Bresse circle there."""
    path = EXAMPLES / name
    mech = graphkin.load(path)
    data, js = live_data(mech, load_toml(path), path.name)
    V = data["curvature"]
    # nothing of draw's panel left out: Γ and the Bresse circle are constructed per posture
    assert "note" not in V and {"Bresse circle", "Γ"} <= set(V["labels"])
    lid, size = V["link"], 1.0 + mech.scale
    has = []
    for turn in np.radians(turns):
        drive = data["drive"]["value"] + float(turn)
        out = curvature_page(data, js, drive)
        if out is None or out["v"] is None:
            continue
        sol = from_dict(edited(data, drive, out["r"]), source="e").solve()
        lc = curvature(sol)[lid]
        assert lc.construction is not None
        v = out["v"]
        # graphkin draws the Bresse circle where α is not zero, and the page then does
        assert (v["Bresse circle"] is not None) == ("Bresse circle" in lc.values)
        if v["Bresse circle"] is None:  # α = 0 (Sec. 4.15): the circle is the normal, Γ = J
            np.testing.assert_allclose(v["Γ"], v["J"], rtol=0, atol=1e-12 * size)
        n = same_curvature(data, v, lc.values, size, steps=lc.construction.steps)
        assert n == len(V["labels"]) - (v["Bresse circle"] is None)
        has.append(v["Bresse circle"] is not None)
    return has


@pytest.mark.usefixtures("_js")
def test_example_4_4_alpha_zero_at_every_posture() -> None:
    # Example 4.4: the slotted crank turns at a constant ω2 and the block with it, so α3 = 0
    # at every posture: graphkin has Γ = J and no Bresse circle at each, and so has the page
    has = _drags("ex4_4_coriolis_block.toml", [0.0, -40.0, 15.0, 150.0])
    assert len(has) >= 3 and not any(has)


@pytest.mark.usefixtures("_js")
def test_example_3_1_bresse_circle_at_other_postures() -> None:
    # Example 3.1 (α3 ≠ 0 in the file): the page no longer lays off the file's ω²/α; the
    # circle of each posture is graphkin's
    has = _drags("ex3_1_fourbar.toml", [0.0, 30.0, -60.0, 120.0])
    assert len(has) >= 3 and all(has)


def _steps(w: float, a: float, ref: float) -> list:
    from graphkin.construction import Role
    from graphkin.construction.step import Step

    rates = {"omega": w, "alpha": a, "ref": ref}
    return [Step(0, "I", "point", (), ("I",), {"xy": (0.0, 0.0)}, Role.GIVEN),
            Step(1, "J", "point", (), ("J",), {"xy": (0.0, 1.0)}, Role.GIVEN),
            Step(2, "Bresse circle", "bresse_circle", ("I", "J"), ("Bresse circle",),
                 dict(rates), Role.RESULT, kind="circle"),
            Step(3, "Γ", "acceleration_center", ("I", "J"), ("Γ",), dict(rates), Role.RESULT)]


@pytest.mark.usefixtures("_js")
def test_the_javascript_templates_are_the_numpy_operations() -> None:
    # one table for both writers: the written-out function, its ω, α and scale set in K as
    # the page sets them, equals the numpy operations to 1e-12, on both sides of the α = 0
    # verdict (|α| <= tol.angle · ref) and at values of α only round-off from it
    from graphkin.construction.jsgen import RUNTIME, generate_js

    fn = generate_js(_steps(1.0, 1.0, 2.0), requests=["Bresse circle", "Γ"], tol=DEFAULT_TOL,
                     name="bresse", given=["I", "J"], homogeneous=False, soft=True)
    names = [n for n, _ in fn.slots]
    slots = [[names.index(f"{lab}.{k}") for k in range(3)] for lab in ("Bresse circle", "Γ")]
    rng = np.random.default_rng(29)
    cases = []
    for w, a, ref in [(2.0, 0.0, 4.0), (2.0, 3e-9, 7.0), (2.0, 1e-8, 4.0), (2.0, -5e-9, 4.0),
                      (-1.5, 0.7, 3.0), (0.5, -40.0, 41.0)]:
        i, j = rng.uniform(-100, 100, 2), rng.uniform(-100, 100, 2)
        k = list(fn.values)
        for kw, ka, kr in slots:
            k[kw], k[ka], k[kr] = w, a, ref
        cases.append(({"I": list(i), "J": list(j)}, k, (i, j, w, a, ref)))
    src = RUNTIME + fn.source + f"\nconst C = {json.dumps([[c[0], c[1]] for c in cases])};" + (
        "\nconst RESULT = C.map(([g, k]) => bresse(g, k));")
    got = run_js(src)
    # by hand: |α| <= 1e-9 ref for the first two (0 and 3e-9 <= 7e-9), not for the others
    assert [o["Bresse circle"] is None for o in got] == [True, True, False, False, False, False]
    for out, (_, _, (i, j, w, a, ref)) in zip(got, cases):
        h = [np.array([*i, 1.0]), np.array([*j, 1.0])]
        circle = OPS["bresse_circle"](*h, tol=DEFAULT_TOL, omega=w, alpha=a, ref=ref)[0]
        gam = OPS["acceleration_center"](*h, tol=DEFAULT_TOL, omega=w, alpha=a, ref=ref)[0]
        if np.all(np.isnan(circle)):
            assert out["Bresse circle"] is None
        else:
            np.testing.assert_allclose(out["Bresse circle"], circle,
                                       rtol=1e-12, atol=1e-12 * float(np.abs(circle).max()))
        np.testing.assert_allclose(out["Γ"], gam[:2] / gam[2], rtol=0, atol=1e-12 * 100)


@pytest.mark.usefixtures("_js")
def test_the_alpha_zero_verdict_does_not_move_with_round_off() -> None:
    # Example 4.4 with every point moved by 1e-12 of the size: α3 is still round-off of the
    # accelerations (0 by hand: ω2 constant, the block turns with the crank), so neither
    # graphkin nor the page draws a Bresse circle, and Γ = J on both
    path = EXAMPLES / "ex4_4_coriolis_block.toml"
    data0 = load_toml(path)
    eps = 1e-12 * graphkin.load(path).scale
    moved = json.loads(json.dumps(data0))
    for k, lk in enumerate(moved["links"].values()):
        for j, n in enumerate(lk):
            lk[n] = [lk[n][0] + eps * ((k + j) % 3 - 1), lk[n][1] - eps * ((k * j) % 3 - 1)]
    mech = from_dict(moved, source=path.name)
    data, js = live_data(mech, moved, path.name)
    out = curvature_page(data, js, data["drive"]["value"])
    v, lc = out["v"], curvature(mech.solve())[data["curvature"]["link"]]
    assert v["Bresse circle"] is None and "Bresse circle" not in lc.values
    assert same_curvature(data, v, lc.values, 1.0 + mech.scale) == len(
        data["curvature"]["labels"]) - 1
