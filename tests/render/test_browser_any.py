"""The cycle and teaching pages of random mechanisms in headless Chromium (issue 24).

A handful of random slider-cranks, quick-returns and six-bars: the ``animate``
page and a ``steps`` page are opened as a reader opens them, and what the
browser lays out is measured: every letter at least 6 pt on the screen, inside
its picture, no two letters of a picture on each other (the cycle page's, and
every step of a ``steps`` page), and every moving point drawn (by its
``data-point``).  Skipped when Chromium is
missing (tests/cdp.py).
"""

from __future__ import annotations

import numpy as np
import pytest
from cdp import browser_or_skip
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st
from strategies import six_bars, slider_cranks
from strategies_quick import quick_returns

from graphkin.errors import GraphkinError
from graphkin.render.animate import animate_html
from graphkin.render.teach import steps_html

MIN_PX = 6 * 96 / 72  # 6 pt as CSS pixels
SETTINGS = settings(max_examples=3, deadline=None, phases=[Phase.explicit, Phase.generate],
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much,
                                           HealthCheck.function_scoped_fixture])


@pytest.fixture(scope="module")
def browser():
    b = browser_or_skip(1300, 900)
    yield b
    b.close()


_LETTERS = """(function (ids) {
  var out = {};
  ids.forEach(function (id) {
    var svg = document.getElementById(id); if (!svg) return;
    var r = svg.getBoundingClientRect();
    out[id] = {box: [r.left, r.top, r.right, r.bottom], points: [].slice.call(
        svg.querySelectorAll('circle[data-point]')).map(function (c) {
          return c.getAttribute('data-point'); }),
      texts: [].slice.call(svg.querySelectorAll('text')).map(function (t) {
        var b = t.getBoundingClientRect();
        // the attribute where the page sets it (exact at any view), else the style
        var size = parseFloat(t.getAttribute('font-size')) ||
                   parseFloat(getComputedStyle(t).fontSize);
        return {text: t.textContent, px: size * t.getScreenCTM().a,
                box: [b.left, b.top, b.right, b.bottom]}; })};
  });
  return out; })"""


def _overlap(a: list[float], b: list[float], slack: float = 1.0) -> bool:
    return (min(a[2], b[2]) - max(a[0], b[0]) > slack
            and min(a[3], b[3]) - max(a[1], b[1]) > slack)


def _check_letters(pictures: dict, moving: set[str], *, collide: bool) -> None:
    for pid, pic in pictures.items():
        x0, y0, x1, y1 = pic["box"]
        for t in pic["texts"]:
            if not t["text"].strip():
                continue
            assert t["px"] >= MIN_PX - 1e-6, (pid, t["text"], t["px"], pic["box"], t["box"])
            bx0, by0, bx1, by1 = t["box"]
            assert bx0 >= x0 - 2 and by0 >= y0 - 2 and bx1 <= x1 + 2 and by1 <= y1 + 2, \
                (pid, t["text"], t["box"], pic["box"])
        if collide:
            boxes = [t for t in pic["texts"] if t["text"].strip()]
            for i, a in enumerate(boxes):
                for b in boxes[i + 1:]:
                    assert not _overlap(a["box"], b["box"]), (pid, a["text"], b["text"])
        if pid == "mechanism":
            assert moving <= set(pic["points"]), (moving - set(pic["points"]))


@given(rm=st.one_of(slider_cranks(), quick_returns(), six_bars()))
@SETTINGS
def test_cycle_page_of_a_random_mechanism(browser, tmp_path_factory, rm):
    mech = rm.mechanism()
    try:
        text = animate_html(mech, count=24)
    except GraphkinError:
        return  # refused in one line (a mechanism that cannot be swept): nothing to draw
    path = tmp_path_factory.mktemp("cycle") / "page.html"
    path.write_text(text, encoding="utf-8")
    b = browser
    b.open(path)
    b.pump(0.2)
    sw = mech.sweep(count=24)
    moving = {p for p in mech.point_names
              if p not in mech.links["1"].points and p not in mech.helper_points}
    for k in np.flatnonzero(sw.valid)[::8][:2]:
        b.js(f"graphkinCycle.show({int(k)})")
        pics = b.js(_LETTERS + "(['mechanism', 'velocity', 'acceleration'])")
        _check_letters(pics, moving & set(b.js("Object.keys(JSON.parse(document."
                                               "getElementById('cycle-data').textContent)"
                                               ".points)")), collide=True)
    assert b.errors() == []


@given(rm=st.one_of(slider_cranks(), six_bars()),
       diagram=st.sampled_from(["velocity", "acceleration", "centers"]))
@SETTINGS
def test_steps_page_of_a_random_mechanism(browser, tmp_path_factory, rm, diagram):
    sol = rm.mechanism().solve()
    try:
        text = steps_html(sol, diagram)
    except GraphkinError:
        return
    path = tmp_path_factory.mktemp("steps") / "page.html"
    path.write_text(text, encoding="utf-8")
    b = browser
    b.open(path)
    b.pump(0.2)
    # every other step and the last (the section after it is the table of results, with no
    # drawing; every other one keeps the test under 15 s): its letters read, inside the
    # picture, none on another
    n = b.js("document.querySelectorAll('main > section.step:not(.results)').length")
    assert n >= 2
    for k in sorted({*range(0, n, 2), n - 1}):
        b.js(f"graphkinSteps.show({k})")
        ids = b.js("[].slice.call(document.querySelectorAll('main > section.current figure "
                   "svg')).map(function (s, i) { if (!s.id) s.id = 'fig-' + i; return s.id; })")
        assert ids, ("a step without its figure", k)
        pics = b.js(_LETTERS + f"({ids!r})".replace("'", '"'))
        _check_letters(pics, set(), collide=True)
    assert b.errors() == []
