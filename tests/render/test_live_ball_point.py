"""Ball's point U on Example 4.16's live page, at the file's posture and after a drag.

At the file's posture of Example 4.16 (Fig. 4.39) the cubic of stationary
curvature contains the centrode normal (N = ∞) and Ball's point is the
inflection pole, U = J (Uicker, Pennock & Shigley, 5th ed., Sec. 4.17).
graphkin's construction makes U there with the operation ``ball_point``
(graphkin/construction/ops/ball.py), which the page replays on every move.
After a turn of the crank N is finite: the page (``ball_point`` on the
posture's I, J, A and B, in JavaScript) must draw U where graphkin's
curvature construction of the file the page saves puts it (Hain's
construction of Fig. 4.38 there: another route), to 1e-9 of the size.  One
page load in headless Chromium; skipped without it.
"""

from __future__ import annotations

import math

import numpy as np
from live_edit import page_file
from spec_data import EXAMPLES

import graphkin
from graphkin.kinematics.curvature.link import curvature

REL = 1e-9


def _u_drawn(browser) -> list[float] | None:
    """The page's U as drawn: the centre of its marker, in the panel's pixels (None: none)."""
    return browser.js(
        "(function () { var c = document.querySelector('#gk-curvature "
        ".gk-curvature-point[data-name=\"U\"]'); return c ? [+c.getAttribute('cx'), "
        "+c.getAttribute('cy')] : null; })()")


def test_example_4_16_ball_point_after_a_drag(browser, tmp_path) -> None:
    path = EXAMPLES / "ex4_16_cubic.toml"
    mech = graphkin.load(path)
    size = 1.0 + float(mech.scale)
    browser.open(page_file(tmp_path, path))
    assert browser.errors() == []
    state = browser.js("window.graphkinLive.state()")
    v = state["curvature"]
    # the file's posture: U = J (the book's Example 4.16; graphkin's value), drawn
    j_file = curvature(mech.solve())["3"].inflection_pole
    np.testing.assert_allclose(v["U"], j_file, rtol=0, atol=REL * size)
    np.testing.assert_allclose(v["U"], v["J"], rtol=0, atol=REL * size)
    assert _u_drawn(browser) is not None
    # a drag of the crank by 20°: U leaves J, drawn where graphkin puts it for the saved file
    d = state["drive"]
    assert browser.js(f"window.graphkinLive.setDrive({d + math.radians(20.0)!r})") is not None
    v = browser.js("window.graphkinLive.state()")["curvature"]
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    lc = curvature(graphkin.load(saved).solve())["3"]
    assert lc.ball_point is not None and math.isfinite(lc.cubic.N)
    np.testing.assert_allclose(v["U"], lc.ball_point, rtol=0, atol=REL * size)
    assert float(np.hypot(*(np.asarray(v["U"]) - np.asarray(v["J"])))) > 1e-3 * size
    assert _u_drawn(browser) is not None
    body = browser.js("document.body.innerText")
    assert "NaN" not in body and "Ball's point U is not drawn" not in body
    assert browser.errors() == []
