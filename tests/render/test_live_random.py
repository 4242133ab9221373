"""The live page itself, for random mechanisms of every family and a random drag, in Chromium.

Each family of tests/strategies.py: the page is opened in headless Chromium,
the drive moved (``graphkinLive.setDrive``, what a drag of the crank does),
and every value the page holds is compared with graphkin's in Python for the
file the page saves (solve, instant_centers, curvature: numpy) to 1e-9; the
page logs no error and shows no NaN anywhere (text or drawing attributes).

The curvature panel of the families whose inflection pole graphkin finds from
the accelerations (Sec. 4.15: inverted slider-cranks, Rapson's slide, the
two-input five-bars) is held to ``graphkin draw -d curvature``'s values (the
kinematics curvature module) after random drags of the drive and of a frame
pivot, several per page.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from live_edit import homogeneous, open_random_page, same_center, same_curvature
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


@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_the_page_equals_graphkin_after_a_drag(browser, tmp_path, family):

    @examples(3)
    @given(rm=FAMILIES[family](), offset=st.floats(-0.06, 0.06))
    def check(rm: RandomMechanism, offset: float) -> None:
        mech = rm.mechanism()
        data = open_random_page(browser, tmp_path, mech, rm.data)
        if data is None:
            return
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
                same_center(homogeneous(state["centers"][lab]), ic.values[lab], lab)
        if state.get("curvature") is not None:
            lc = curvature(sol)[data["curvature"]["link"]]
            same_curvature(data, state["curvature"], lc.values, size,
                           steps=lc.construction.steps)

    check()


CURVATURE_FAMILIES = {"inverted slider-crank": inverted_slider_cranks,
                      "Rapson's slide": double_sliders, "five-bar": five_bars}


def _draws_link(sol) -> str | None:
    """The link ``graphkin draw -d curvature`` draws: the first coupler with a construction.

    None when every link with one turns about a frame pivot (the inflection
    circle is the pivot itself: the page says why it has no panel).
    """
    links = [k for k, v in curvature(sol).items()
             if v.construction is not None and v.method != "pivot"]
    frame = set(sol.mechanism.links["1"].points)
    couplers = [k for k in links if not frame & set(sol.mechanism.links[k].points)]
    return (couplers or links or [None])[0]


# found by this test: a block whose pin A and slider point B coincide (their ratio has no
# conditioning: its points are taken from A and the link's angle), and a file posture where
# A's acceleration drawn from A falls on the rod's end R (A_A is A's, not R's, after a drag)
_BLOCK_AB = {
    "title": "block: A and B coincide", "units": {"length": "mm"},
    "links": {"1": {"D": [2.7076581228782004, 0.0], "E": [9.307574797393814, 0.0]},
              "4": {"D": [-1.3538290614391002, 0.0], "R": [1.3538290614391002, 0.0]},
              "2": {"E": [0.3200211715954953, -0.49840344469593634],
                    "A": [-0.3200211715954943, 0.49840344469593484]},
              "3": {"A": [0.0, 0.0], "B": [0.0, 0.0]}},
    "drive": {"link": 2, "angle": 57.29577951308232, "omega": "1.0 rad/s cw"},
    "assembly": {"R": [5.415316245756401, 0.0], "A": [8.122974368634601, 0.0],
                 "B": [8.122974368634601, 0.0]},
    "sliders": [{"link": 3, "on": 4, "point": "B",
                 "line": [[1.3538290614391002, 0.0], [6.769145307195501, 0.0]]}]}
_A_A_ON_R = {
    "title": "A_A on R", "units": {"length": "mm"},
    "links": {"1": {"D": [0.0, 0.0], "E": [-0.5, 0.0]}, "4": {"D": [-0.5, 0.0], "R": [0.5, 0.0]},
              "2": {"E": [0.25, 0.0], "A": [-0.25, 0.0]}, "3": {"A": [0.0, 0.0]}},
    "drive": {"link": 2, "angle": 0.0, "omega": "1.0 rad/s cw"},
    "assembly": {"R": [1.0, 0.0], "A": [-1.0, 0.0]},
    "sliders": [{"link": 3, "on": 4, "point": "A", "line": [[-2.5, 0.0], [-0.5, 0.0]]}]}


@pytest.mark.parametrize("family", sorted(CURVATURE_FAMILIES))
def test_the_curvature_panel_equals_draws_after_random_drags(browser, tmp_path, family):
    compared: list[int] = []

    @examples(4)
    @example(rm=RandomMechanism("inverted slider-crank", _BLOCK_AB, {}, {}),
             drags=[(0.0, 0.0, 0.0), (0.02, 0.0, 0.0)])
    @example(rm=RandomMechanism("inverted slider-crank", _A_A_ON_R, {}, {}),
             drags=[(0.0, 0.0, 0.0), (0.0, 0.0, 0.015625)])
    @given(rm=CURVATURE_FAMILIES[family](),
           drags=st.lists(st.tuples(st.floats(-0.08, 0.08), st.floats(-0.03, 0.03),
                                    st.floats(-0.03, 0.03)), min_size=2, max_size=3))
    def check(rm: RandomMechanism, drags: list[tuple[float, float, float]]) -> None:
        mech = rm.mechanism()
        try:
            data, _ = live_data(mech, rm.data, "random.toml")
        except InputError:
            return
        V = data["curvature"]
        # the panel appears wherever draw -d curvature draws a link's inflection circle
        try:
            drawn = _draws_link(mech.solve())
        except GraphkinError:
            return
        if drawn is None:
            assert V["why"]
            return
        assert V.get("link") == drawn, V.get("why")
        page = tmp_path / "random.html"
        page.write_text(live_html(mech, rm.data, "random.toml"), encoding="utf-8")
        browser.open(page)
        k0 = browser.js("window.graphkinLive.state().K")
        d = data["drive"]
        frame = sorted(data["frame"])
        size = 1.0 + mech.scale
        for turn, dx, dy in drags:
            # a drag of the drive, and of a frame pivot (its coordinates in K)
            k = list(k0)
            if frame:
                i, j = data["frame"][frame[0]]
                k[i] += dx * mech.scale
                k[j] += dy * mech.scale
            drive = d["value"] + turn * (1.0 if d["degrees"] else mech.scale)
            browser.js(f"window.graphkinLive.load({{K: {k!r}, drive: {float(drive)!r}}})")
            state = browser.js("window.graphkinLive.state()")
            assert browser.errors() == []
            if state["result"] is None or state["curvature"] is None:
                continue  # not assembled, or no clean construction: said so on the page
            saved = tmp_path / "saved.toml"
            saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
            try:
                sol = graphkin.load(saved).solve()
                lc = curvature(sol)[V["link"]]
            except (GraphkinError, KeyError):
                continue
            if not bool(np.all(sol.valid)) or lc.construction is None:
                continue
            compared.append(same_curvature(data, state["curvature"], lc.values, size,
                                           steps=lc.construction.steps))
        shown = browser.js("document.getElementById('gk-curvature').textContent")
        assert "NaN" not in shown and "Infinity" not in shown

    check()
    assert sum(compared) > 0  # the panel was there, and held to graphkin's values


def test_a_mechanism_without_a_panel_says_why(browser, tmp_path):
    # Example 4.7's cam and follower both turn about frame pivots: no inflection circle but
    # the pivots themselves (Sec. 4.13); the page says so in one line, with no empty drawing
    from spec_data import EXAMPLES

    from graphkin.files import load_toml

    path = EXAMPLES / "ex4_7_cam_follower.toml"
    page = tmp_path / "cam.html"
    page.write_text(live_html(graphkin.load(path), load_toml(path), path.name),
                    encoding="utf-8")
    browser.open(page)
    note = browser.js("document.getElementById('gk-curvature-note').textContent")
    assert note.startswith("No live curvature: links 2 and 3 each turn about a frame pivot")
    assert "\n" not in note
    assert browser.js("getComputedStyle(document.getElementById('gk-curvature')).display") \
        == "none"
    assert browser.js("window.graphkinLive.state().curvature") is None
    assert browser.errors() == []
