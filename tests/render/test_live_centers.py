"""The live page's instant centers equal graphkin's, for random mechanisms and random drags.

The page's two written-out functions (the posture construction and the
Aronhold-Kennedy construction, both from the one table of templates) and its
own glue (``gkCenters``: the primary centers from the posture, homogeneous)
are run on JavaScript numbers (node, else headless Chromium) at a drive moved
from the file's; the file is edited the way the page saves it (the new drive,
``[assembly]`` hints at the page's points) and solved by graphkin in Python,
whose :func:`instant_centers` (numpy, the recorded steps replayed on the new
solution) is the reference.  Centers are compared as points of the
projective plane: unit homogeneous vectors, equal up to sign, to 1e-9, so a
center at infinity (a slider's, or two parallel lines of centers) is compared
as the direction it is.
"""

from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from jsrun import close, js_or_skip, run_js
from live_edit import edited
from strategies import (
    RandomMechanism,
    double_sliders,
    examples,
    five_bars,
    fourbars,
    inverted_slider_cranks,
    six_bars,
    slider_cranks,
    slotted,
)

import graphkin
from graphkin.errors import GraphkinError, InputError
from graphkin.kinematics.instant_centers import instant_centers
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_data
from graphkin.render.live_app import LIVE_LIB

REL = 1e-9


@pytest.fixture(scope="module", autouse=True)
def _js():
    js_or_skip()
    yield
    close()


def _page_centers(data: dict, js: str, drive: float) -> dict | None:
    """What the page computes at the drive value ``drive``: the posture and the centers."""
    src = (js + LIVE_LIB + f"\nconst D = {json.dumps(data)};"
           "\nconst I = Object.assign({}, D.inputs);"
           f"\nI[D.drive.label] = {float(drive)!r};"
           "\nconst r = construction(I, D.K);"
           "\nconst RESULT = r === null ? null : {r: r, c: gkCenters(D.centers, r)};")
    return run_js(src)


def _unit(h) -> np.ndarray:
    h = np.asarray(h, dtype=float)
    return h / np.linalg.norm(h)


def _same_center(got, ref, lab: str) -> None:
    g, r = _unit(got), _unit(ref)
    if float(np.dot(g, r)) < 0:
        g = -g
    np.testing.assert_allclose(g, r, rtol=0, atol=REL * 10, err_msg=lab)


FAMILIES = {"fourbar": fourbars, "slider-crank": slider_cranks,
            "inverted slider-crank": inverted_slider_cranks, "slotted": slotted,
            "double slider": double_sliders, "six-bar": six_bars, "five-bar": five_bars}


@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_page_centers_equal_graphkins_after_a_drag(family: str) -> None:
    # every family of tests/strategies.py, each with its own examples

    @examples(6)
    @given(rm=FAMILIES[family](), offset=st.floats(-0.08, 0.08))
    def check(rm: RandomMechanism, offset: float) -> None:
        _check(rm, offset)

    check()


def _check(rm: RandomMechanism, offset: float) -> None:
    mech = rm.mechanism()
    try:
        data, js = live_data(mech, rm.data, "<random>")
    except InputError:
        return  # no construction (Newton): refused in one line, tested in test_live.py
    # every family's centers are written out: pins and sliders, a slot's common normal, a
    # center found from the velocities (the page has them: the families give rates)
    assert data["centers"]["fn"] == "centers", data["centers"]["why"]
    d = data["drive"]
    scale = 1.0 if d["degrees"] else mech.scale
    drive = d["value"] + offset * scale
    out = _page_centers(data, js, drive)
    if out is None:
        return  # this posture cannot be assembled: the page says so (test_live.py)
    r, c = out["r"], out["c"]
    try:
        sol = from_dict(edited(data, drive, r), source="<edited>").solve()
        ic = instant_centers(sol)
    except GraphkinError:
        return  # graphkin cannot find the centers at this posture either
    if not bool(np.all(sol.valid)):
        return
    # the page's posture is graphkin's (so the branch is the same), then every center
    for lk in mech.links.values():
        for n in lk.points:
            if n in r:
                np.testing.assert_allclose(r[n], sol.position(n), rtol=0,
                                           atol=REL * (1 + mech.scale), err_msg=n)
    if c is None:
        # the page refuses (two lines of centers coincide): so does graphkin's construction
        # up to the same margin; nothing to compare
        return
    for lab in data["centers"]["labels"]:
        _same_center(c[lab], ic.values[lab], lab)


def test_a_slider_center_is_at_infinity_and_drawn_as_a_direction(tmp_path) -> None:
    # Example 3.2 (slider-crank, Fig. 3.20): I14 is at infinity normal to the slider's line
    # y = -20 (horizontal): the direction (0, ±1); the page draws it as a direction
    from spec_data import EXAMPLES

    path = EXAMPLES / "ex3_2_slider_driven.toml"
    mech = graphkin.load(path)
    from graphkin.files import load_toml

    data, js = live_data(mech, load_toml(path), path.name)
    out = _page_centers(data, js, data["drive"]["value"])
    h = np.asarray(out["c"]["I14"], dtype=float)
    assert h[2] == 0.0
    np.testing.assert_allclose(np.abs(_unit(h)), [0.0, 1.0, 0.0], rtol=0, atol=1e-15)
    # I24 lies on the line I12-I14 (the vertical through A) and on I23-I34 (Kennedy)
    ic = instant_centers(mech.solve())
    for lab in ("I13", "I24"):
        _same_center(out["c"][lab], ic.values[lab], lab)
