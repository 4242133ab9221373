"""The teaching page and the cycle page in a real browser (headless Chromium, DevTools protocol).

Skipped when Chromium (Debian ``chromium``) or ``websocket-client`` is missing;
``.ci/run`` installs Chromium.  Every wait is bounded (see ``tests/cdp.py``).
"""

from __future__ import annotations

import re

import numpy as np
import pytest
from cdp import browser_or_skip
from spec_data import EXAMPLES

import graphkin
from graphkin.render.animate import animate_html
from graphkin.render.teach import steps_html

INTERNAL = re.compile(r"\S:\S|[>⊥∥@\[\]]|\b[va]\(|\bdds?\d|\bo_[va]\b")

PAGES = [("ex3_1_fourbar", "acceleration"), ("ex4_4_coriolis_block", "acceleration"),
         ("ex3_3_inverted_slider", "velocity"), ("ex3_2_slider_driven", "velocity"),
         # one figure of the curvature sheet (Sec. 4.13, Fig. 4.30; Sec. 4.17, Fig. 4.38)
         ("ex3_1_fourbar", "hartmann"), ("ex3_1_fourbar", "cubic")]


@pytest.fixture(scope="module")
def browser():
    b = browser_or_skip(1300, 900)
    yield b
    b.close()


@pytest.fixture(scope="module", params=PAGES, ids=["-".join(p) for p in PAGES])
def step_page(request, tmp_path_factory, gk):
    name, diagram = request.param
    path = tmp_path_factory.mktemp("steps") / f"{name}-{diagram}.html"
    path.write_text(steps_html(gk.solved(name), diagram), encoding="utf-8")
    return path


_STATE = """(function () {
  var s = document.querySelector('main > section.current');
  var eq = s.querySelector('.equation');
  var vis = [].slice.call(document.querySelectorAll('main > section')).filter(
      function (x) { return getComputedStyle(x).display !== 'none'; }).length;
  var texts = [].slice.call(s.querySelectorAll('figure svg text')).map(
      function (t) { return parseFloat(getComputedStyle(t).fontSize) * t.getScreenCTM().a; });
  var ans = s.querySelector('.answer .val');
  return {heading: s.querySelector('h2').textContent, vector: s.getAttribute('data-vector'),
          eq: eq ? eq.textContent : null,
          eqShown: eq ? eq.getBoundingClientRect().height > 0 : false,
          visible: vis, letters: texts,
          answer: ans ? getComputedStyle(ans).visibility : null,
          scroll: document.scrollingElement.scrollHeight, inner: innerHeight};
})()"""


def test_step_page_walks_every_step(browser, step_page):
    b = browser
    b.viewport(1300, 900)
    b.open(step_page)
    n = b.js("graphkinSteps.count")
    assert n >= 3
    seen = []
    for k in range(n):
        if k:
            b.js("document.getElementById('next').click()")
        st = b.js(_STATE)
        assert b.js("graphkinSteps.current()") == k
        assert st["visible"] == 1  # one step at a time
        heading = st["heading"]
        assert heading.startswith(f"Step {k + 1} of {n}")
        assert not INTERNAL.search(heading), heading
        if st["vector"] == "1":
            assert st["eq"] and st["eqShown"], heading  # each vector step shows its equation
        if st["letters"]:
            # every label of the drawing reads at 14 px or more in a 1300 px window
            assert min(st["letters"]) >= 14.0, (heading, st["letters"])
        seen.append(heading)
    assert len(set(seen)) == n
    assert b.errors() == []


def test_answers_toggle_hides_and_shows_the_numbers(browser, step_page):
    b = browser
    b.viewport(1300, 900)
    b.open(step_page)
    k = b.js("""(function () { var s = [].slice.call(document.querySelectorAll('main > section'));
        for (var i = 0; i < s.length; i++) { if (s[i].querySelector('.answer')) return i; }
        return -1; })()""")
    assert k >= 0
    b.js(f"graphkinSteps.show({k})")
    assert b.js(_STATE)["answer"] == "hidden"  # the numbers to find start hidden
    b.js("document.getElementById('answers').click()")
    assert b.js(_STATE)["answer"] == "visible"
    b.js("document.dispatchEvent(new KeyboardEvent('keydown', {key: 'a'}))")
    assert b.js(_STATE)["answer"] == "hidden"
    # the rates found, printed on the drawings, and the results table hide with them
    found = b.js("""[].slice.call(document.querySelectorAll(
        '[id$="label-ω3"], [id$="label-α3"], [id$="label-ω4"], [id$="label-α4"],'
        + ' table.results .answer .val')).map(function (e) {
          return getComputedStyle(e).visibility; })""")
    assert found and set(found) == {"hidden"}
    b.js("document.getElementById('answers').click()")
    assert set(b.js("""[].slice.call(document.querySelectorAll('table.results .answer .val'))
        .map(function (e) { return getComputedStyle(e).visibility; })""")) <= {"visible"}


def test_print_media_shows_every_step_in_order(browser, step_page):
    b = browser
    b.open(step_page)
    b.send("Emulation.setEmulatedMedia", media="print")
    try:
        shown = b.js("""[].slice.call(document.querySelectorAll('main > section')).map(
            function (s) { return [s.getAttribute('data-step'),
                                   getComputedStyle(s).display !== 'none'
                                   && s.getBoundingClientRect().height > 0]; })""")
        nav = b.js("getComputedStyle(document.querySelector('nav')).display")
    finally:
        b.send("Emulation.setEmulatedMedia", media="")
    assert all(ok for _, ok in shown)
    assert [int(k) for k, _ in shown] == list(range(len(shown)))
    assert nav == "none"


def test_projector_shows_a_whole_step_without_scrolling(browser, step_page):
    b = browser
    b.viewport(1024, 768)
    try:
        b.open(step_page)
        n = b.js("graphkinSteps.count")
        for k in range(n):
            b.js(f"graphkinSteps.show({k})")
            st = b.js(_STATE)
            assert st["scroll"] <= st["inner"] + 1, (k, st["heading"], st["scroll"])
    finally:
        b.viewport(1300, 900)


def test_without_javascript_every_step_is_shown(browser, step_page):
    b = browser
    b.send("Emulation.setScriptExecutionDisabled", value=True)
    try:
        b.open(step_page)
        shown = b.js("""[].slice.call(document.querySelectorAll('main > section')).map(
            function (s) { return getComputedStyle(s).display !== 'none'; })""")
    finally:
        b.send("Emulation.setScriptExecutionDisabled", value=False)
    assert len(shown) >= 3 and all(shown)


# ---- the cycle ---------------------------------------------------------------------------

CYCLES = ["fourbar", "slider_crank", "inverted_slider_crank", "fivebar"]
COUNT = 360


@pytest.fixture(scope="module", params=CYCLES)
def cycle(request, tmp_path_factory):
    mech = getattr(graphkin.examples, request.param)()
    text = animate_html(mech, count=COUNT)
    path = tmp_path_factory.mktemp("cycle") / f"{request.param}.html"
    path.write_text(text, encoding="utf-8")
    return mech, path, len(text.encode("utf-8"))


_IMAGES = """(function (kind) {
  var out = {};
  [].slice.call(document.querySelectorAll('#' + kind + ' circle[data-point]')).forEach(
    function (c) { out[c.getAttribute('data-point')] = [Number(c.getAttribute('cx')),
                                                        -Number(c.getAttribute('cy'))]; });
  return out; })"""


def test_cycle_page_draws_the_sweep(browser, cycle):
    mech, path, size = cycle
    assert size < 2 * 1024 * 1024  # light: 360 postures as data, not pictures
    b = browser
    b.viewport(1300, 900)
    b.open(path)
    b.pump(0.3)
    assert b.errors() == []
    sw = mech.sweep(count=COUNT)  # the sweep the page must show
    good = np.flatnonzero(sw.valid)
    i, j = int(good[len(good) // 5]), int(good[3 * len(good) // 5])
    drawn = {}
    for k in (i, j):
        # move the drive slider as a user does
        b.js(f"(function () {{ var s = document.getElementById('drive'); s.value = {k}; "
             "s.dispatchEvent(new Event('input')); })()")
        assert b.js("Number(document.body.getAttribute('data-posture'))") == k
        pos = b.js(_IMAGES + "('mechanism')")
        vel = b.js(_IMAGES + "('velocity')")
        acc = b.js(_IMAGES + "('acceleration')")
        assert vel and acc
        for p, (x, y) in pos.items():
            scale = np.nanmax(np.abs([sw.columns[f"x_{p}"], sw.columns[f"y_{p}"]])) + 1
            assert np.allclose([x, y], [sw.columns[f"x_{p}"][k], sw.columns[f"y_{p}"][k]],
                               atol=1e-4 * scale), p
        for images, v in ((vel, "v"), (acc, "a")):
            big = max(np.nanmax(np.abs(sw.columns[f"{v}{c}_{p}"])) for p in images
                      for c in "xy")
            for p, (x, y) in images.items():
                want = [sw.columns[f"{v}x_{p}"][k], sw.columns[f"{v}y_{p}"][k]]
                assert np.allclose([x, y], want, atol=1e-4 * big), (p, v, x, y, want)
        drawn[k] = vel
    # two postures, two different polygons
    moving = [p for p in drawn[i] if p not in mech.links["1"].points]
    assert any(not np.allclose(drawn[i][p], drawn[j][p]) for p in moving)
    # play advances the posture; pause stops it
    b.js(f"graphkinCycle.show({i})")
    b.js("document.getElementById('play').click()")
    b.pump(0.8)
    assert b.js("graphkinCycle.playing()") is True
    moved = b.js("graphkinCycle.current()")
    b.js("document.getElementById('play').click()")
    assert moved != i
    assert b.errors() == []


def test_cycle_marks_what_cannot_be_assembled(browser, tmp_path):
    """Example 3.1's four-bar is no crank-rocker: its crank cannot turn through 327°-393°."""
    mech = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml")
    path = tmp_path / "fb.html"
    path.write_text(animate_html(mech, count=COUNT), encoding="utf-8")
    b = browser
    b.open(path)
    sw = mech.sweep(count=COUNT)
    bad = np.flatnonzero(~sw.assembled)
    assert bad.size
    assert b.js("document.querySelectorAll('#marks .bad').length") >= 1
    # stepping from just before the gap jumps over it
    b.js(f"graphkinCycle.show({int(bad[0]) - 1})")
    b.js("document.getElementById('next').click()")
    assert b.js("graphkinCycle.current()") not in set(bad.tolist())
    b.js(f"graphkinCycle.show({int(bad[0])})")
    assert "cannot be assembled" in b.js("document.getElementById('status').textContent")
    assert b.errors() == []


def test_cycle_fit_redraws_each_polygon_at_its_own_round_scale(browser, tmp_path):
    mech = graphkin.examples.inverted_slider_crank()
    path = tmp_path / "inv.html"
    path.write_text(animate_html(mech, count=90), encoding="utf-8")
    b = browser
    b.open(path)
    fixed = b.js("document.getElementById('acceleration-scale').textContent")
    b.js("document.getElementById('fit').click()")
    sw = mech.sweep(count=90)
    k = int(np.flatnonzero(sw.valid)[10])
    b.js(f"graphkinCycle.show({k})")
    images = b.js(_IMAGES + "('acceleration')")
    for p, (x, y) in images.items():  # the vertices stay the sweep's values
        big = np.nanmax(np.abs([sw.columns[f"ax_{p}"], sw.columns[f"ay_{p}"]]))
        assert np.allclose([x, y], [sw.columns[f"ax_{p}"][k], sw.columns[f"ay_{p}"][k]],
                           atol=1e-4 * big)
    assert re.match(r"drawn to scale: bar = [\d.]+ ", fixed)
    assert b.errors() == []
