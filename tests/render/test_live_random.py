"""The live page itself, for random mechanisms of every family and a random drag, in Chromium.

Each family of tests/strategies.py: the page is opened in headless Chromium,
the drive moved (``graphkinLive.setDrive``, what a drag of the crank does),
and every value the page holds is compared with graphkin's in Python for the
file the page saves (solve, instant_centers, curvature: numpy) to 1e-9; the
page logs no error and shows no NaN anywhere (text or drawing attributes).
"""

from __future__ import annotations

import numpy as np
import pytest
from cdp import browser_or_skip
from hypothesis import given
from hypothesis import strategies as st
from live_edit import same_center, same_curvature
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
from graphkin.kinematics.curvature.link import curvature
from graphkin.kinematics.instant_centers import instant_centers
from graphkin.render.live import live_data, live_html

FAMILIES = {"fourbar": fourbars, "slider-crank": slider_cranks,
            "inverted slider-crank": inverted_slider_cranks, "slotted": slotted,
            "double slider": double_sliders, "six-bar": six_bars, "five-bar": five_bars}


@pytest.fixture(scope="module")
def browser():
    b = browser_or_skip(1300, 1000)
    yield b
    b.close()


@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_the_page_equals_graphkin_after_a_drag(browser, tmp_path, family):

    @examples(3)
    @given(rm=FAMILIES[family](), offset=st.floats(-0.06, 0.06))
    def check(rm: RandomMechanism, offset: float) -> None:
        mech = rm.mechanism()
        try:
            data, _ = live_data(mech, rm.data, "random.toml")
        except InputError:
            return
        page = tmp_path / "random.html"
        page.write_text(live_html(mech, rm.data, "random.toml"), encoding="utf-8")
        browser.open(page)
        d = data["drive"]
        drive = d["value"] + offset * (1.0 if d["degrees"] else mech.scale)
        browser.js(f"window.graphkinLive.setDrive({float(drive)!r})")
        state = browser.js("window.graphkinLive.state()")
        assert browser.errors() == []
        shown = browser.js(
            "document.body.innerText + ' ' + [].map.call(document.querySelectorAll('svg *'),"
            " function (e) { return [].map.call(e.attributes, function (a) {"
            " return a.value; }).join(' '); }).join(' ')")
        assert "NaN" not in shown and "Infinity" not in shown
        r = state["result"]
        if r is None:
            status = browser.js("document.getElementById('gk-status').textContent")
            assert "cannot be assembled" in status
            return
        saved = tmp_path / "saved.toml"
        saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
        try:
            sol = graphkin.load(saved).solve()
        except GraphkinError:
            return
        if not bool(np.all(sol.valid)):
            return
        size = 1.0 + mech.scale
        for lk in mech.links.values():
            for n in lk.points:
                if n in r:
                    np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=1e-9 * size,
                                               err_msg=n)
        if state["centers"] is not None:
            ic = instant_centers(sol)
            for lab in data["centers"]["labels"]:
                same_center(state["centers"][lab], ic.values[lab], lab)
        if state.get("curvature") is not None:
            lid = data["curvature"]["link"]
            same_curvature(data, state["curvature"], curvature(sol)[lid].values, size)

    check()
