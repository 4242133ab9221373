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
from live_edit import edited, same_curvature
from spec_data import EXAMPLES

import graphkin
from graphkin.construction.ops import OPS, templates  # noqa: F401  (registers bresse.py)
from graphkin.files import load_toml
from graphkin.kinematics.curvature.inflection import acceleration_center
from graphkin.kinematics.curvature.link import curvature
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_data
from graphkin.render.live_app import LIVE_LIB
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


def _page(data: dict, js: str, drive: float):
    src = (js + LIVE_LIB + f"\nconst D = {json.dumps(data)};"
           "\nconst I = Object.assign({}, D.inputs);"
           f"\nI[D.drive.label] = {float(drive)!r};"
           "\nconst r = construction(I, D.K);"
           "\nconst RESULT = r === null ? null : {r: r, v: gkCurvature(D.curvature, r)};")
    return run_js(src)


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
        out = _page(data, js, drive)
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
