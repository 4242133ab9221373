"""The live page's letters placed by draw's rule when the pointer stops (issue 29, item 2).

Read back from the page in headless Chromium, on every panel that letters its
points (posture, velocity, acceleration, curvature, forces), after the page is
opened and after a drag let go: each letter's box (the browser's own
``getBBox`` of the text drawn), its point (where the page drew the point: a
marker, or an image at the tip of its arrow) and the points' markers.  The
rules (Sec. 1.6 of Uicker, Pennock & Shigley, 5th ed.: the lettering must be
read as written; graphkin/render/label_points.py for draw):

* no two letters' boxes overlap;
* no letter's box covers another point's marker;
* every letter of a point on the panel reads as its point's: its box's centre is nearer
  its own point than any other lettered point, or, where the place is
  crowded, its box is (draw's ``astray_labels``); points closer than half a
  pixel are one point (an image at its pole), and a point with another closer
  than a letter's height (12 px) is left out of this rule (no box fits
  between them);
* every letter of a point on the panel stays inside the panel.

Each check fails on the page's old placement (every letter 6 px up and to the
right of its point), shown on the crowded compound gear train (18/54, 24/48,
module 2.5 mm) whose acceleration images heap by the pole O_A, and on
Example 3.1.  The timing is in benchmarks/bench_live.py, not here.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from live_cams_shared import drag
from live_edit import open_random_page, page_file
from strategies import RandomMechanism, examples, mechanisms

from graphkin.cli import main

ROOT = Path(__file__).resolve().parents[2]
SAME = 0.5
"""Points closer than this (px) are one point."""
SHRINK = 0.5
"""Pixels taken off each side of a letter's box (glyph boxes that only touch)."""
LETTER = 12.0
"""A letter's height (px): points apart by less, but not one point, leave no room between
them for a box nearer one than the other (a mechanism drawn a few pixels small)."""

TRAIN = """title = "compound train 18/54, 24/48"
module = "2.5 mm"
[teeth]
2 = 18
3 = 54
4 = 24
5 = 48
[[mesh]]
gears = [2, 3]
[[mesh]]
gears = [4, 5]
[[joined]]
members = [3, 4]
[speeds]
2 = "100 rev/min"
"""

# every panel's letters (box, text, point), markers (small circles, not the drag handles)
# and the ends of its lines, in the panel's own units (its viewBox, 420 x 360)
_READ = """(function () {
  var out = {};
  ['posture', 'velocity', 'acceleration', 'curvature', 'forces'].forEach(function (p) {
    var svg = document.getElementById('gk-' + p);
    if (!svg || !(svg.getBoundingClientRect().width > 0)) return;
    var vb = svg.viewBox.baseVal, num = function (e, a) { return parseFloat(e.getAttribute(a)); };
    out[p] = {
      size: [vb.width, vb.height],
      letters: [].map.call(svg.querySelectorAll('text.gk-label'), function (t) {
        var b = t.getBBox();
        return {text: t.textContent, box: [b.x, b.y, b.x + b.width, b.y + b.height],
                at: [num(t, 'data-ax'), num(t, 'data-ay')],
                point: t.getAttribute('data-point') === '1'};
      }),
      markers: [].filter.call(svg.querySelectorAll('circle'), function (c) {
        return !c.classList.contains('gk-handle') && num(c, 'r') <= 6;
      }).map(function (c) { return [num(c, 'cx'), num(c, 'cy'), num(c, 'r')]; }),
      tips: [].map.call(svg.querySelectorAll('line'), function (l) {
        return [num(l, 'x2'), num(l, 'y2')]; })
    };
  });
  return out;
})()"""

# the page's old placement: every letter at (+6, -6) px from its point, its text starting there
_OLD = """(function () {
  [].forEach.call(document.querySelectorAll('text.gk-label'), function (t) {
    t.setAttribute('x', parseFloat(t.getAttribute('data-ax')) + 6);
    t.setAttribute('y', parseFloat(t.getAttribute('data-ay')) - 6);
    t.removeAttribute('text-anchor');
  });
  return true;
})()"""


def _gap(box: np.ndarray, p: np.ndarray) -> float:
    """Distance from a box (x0, y0, x1, y1) to a point (0 inside)."""
    return float(np.hypot(max(box[0] - p[0], p[0] - box[2], 0.0),
                          max(box[1] - p[1], p[1] - box[3], 0.0)))


def faults(panels: dict[str, Any]) -> dict[str, list[str]]:
    """Every broken rule of the module's docstring: {rule: [panel: letter ...]}."""
    out: dict[str, list[str]] = {"overlap": [], "marker": [], "astray": [], "outside": []}
    for name, P in panels.items():
        W, H = P["size"]
        letters = P["letters"]
        boxes = [np.asarray(t["box"], float) + [SHRINK, SHRINK, -SHRINK, -SHRINK]
                 for t in letters]
        markers = np.asarray(P["markers"], float).reshape(-1, 3)
        tips = np.asarray(P["tips"], float).reshape(-1, 2)
        points = [np.asarray(t["at"], float) for t in letters if t["point"]]
        for i, t in enumerate(letters):
            b, a = boxes[i], np.asarray(t["at"], float)
            where = f"{name}: {t['text']}"
            if t["point"]:  # its point is drawn there: a marker or an image's arrow tip
                # (an image within a pixel of its pole has no arrow: the pole's marker)
                drawn = np.vstack([markers[:, :2], tips]) if len(tips) else markers[:, :2]
                assert len(drawn) and np.min(np.hypot(*(drawn - a).T)) <= 1.01, where
            for j in range(i + 1, len(letters)):
                o = boxes[j]
                if min(b[2], o[2]) > max(b[0], o[0]) and min(b[3], o[3]) > max(b[1], o[1]):
                    out["overlap"].append(f"{where} / {letters[j]['text']}")
            for m in markers:
                own = t["point"] and np.hypot(*(m[:2] - a)) <= SAME
                if not own and _gap(b, m[:2]) < m[2]:
                    out["marker"].append(where)
            # a point off the panel (an axis's tip, a far center): its letter kept on the
            # panel, as near it as the panel lets it be
            if t["point"] and 0 <= a[0] <= W and 0 <= a[1] <= H:
                others = [p for p in points if np.hypot(*(p - a)) > SAME]
                c = np.array([(b[0] + b[2]) / 2, (b[1] + b[3]) / 2])
                by_centre = any(np.hypot(*(c - p)) < np.hypot(*(c - a)) for p in others)
                by_box = any(_gap(b, p) < _gap(b, a) for p in others)
                packed = any(np.hypot(*(p - a)) < LETTER for p in others)
                if by_centre and by_box and not packed:
                    out["astray"].append(where)
                if b[0] < 0 or b[1] < 0 or b[2] > W or b[3] > H:
                    out["outside"].append(where)
    return out


def _clean(panels: dict[str, Any]) -> None:
    got = faults(panels)
    assert got == {"overlap": [], "marker": [], "astray": [], "outside": []}, got
    assert sum(len(P["letters"]) for P in panels.values()) > 0


def _handle(browser: Any, kind: str) -> tuple[float, float]:
    r = browser.js(f"(function () {{ var h = document.querySelector('.gk-handle[data-kind="
                   f"\"{kind}\"]'); var r = h.getBoundingClientRect();"
                   " return [r.x + r.width / 2, r.y + r.height / 2]; })()")
    return float(r[0]), float(r[1])


def test_a_crowded_gear_train_is_lettered_clean(browser, tmp_path: Path) -> None:
    path = tmp_path / "train.toml"
    path.write_text(TRAIN, encoding="utf-8")
    assert main(["live", str(path), "-o", str(tmp_path / "train.html")]) == 0
    browser.open(tmp_path / "train.html")
    assert browser.errors() == []
    placed = browser.js(_READ)
    _clean(placed)
    # "c′₃ (3/2)" by the right edge is written leftward (text-anchor end) when first drawn:
    # while dragging it keeps its place all the same
    d = browser.js("window.graphkinLive.state()")["drive"]
    assert browser.js(f"window.graphkinLive.setDrive({d + 1e-3!r})") is not None
    before, during = _offsets(placed), _offsets(browser.js(_READ))
    assert before.keys() == during.keys()
    for k, v in before.items():
        assert np.allclose(during[k], v, atol=0.05), k
    browser.js("window.graphkinLive.redraw(true)")
    # the old placement heaps a′₅, c′₃ (3/2) and a′₄ by O_A: every rule broken somewhere
    # (the acceleration panel's images by the pole; "c′₃ (3/2)" off the panel's right edge)
    browser.js(_OLD)
    old = faults(browser.js(_READ))
    assert all(old[k] for k in ("overlap", "astray", "outside")), old
    # the driver dragged and let go: the letters placed again for the posture reached
    x, y = _handle(browser, "drive")
    drag(browser, (x, y), (x - 25.0, y + 20.0))
    assert browser.errors() == []
    _clean(browser.js(_READ))


def _offsets(panels: dict[str, Any]) -> dict[tuple[str, str], tuple[float, float]]:
    """Each letter's box corner from its point, by panel and text."""
    return {(name, t["text"]): (t["box"][0] - t["at"][0], t["box"][1] - t["at"][1])
            for name, P in panels.items() for t in P["letters"]}


def test_example_3_1_is_lettered_clean(browser, tmp_path: Path) -> None:
    browser.open(page_file(tmp_path, ROOT / "tests/data/spec/ex3_1_fourbar.toml"))
    placed = browser.js(_READ)
    _clean(placed)
    # while dragging (the drive moved, the pointer not let go) each letter keeps the offset
    # from its point it was given when the pointer last stopped: the cheap placement
    d = browser.js("window.graphkinLive.state()")["drive"]
    assert browser.js(f"window.graphkinLive.setDrive({d + 0.02!r})") is not None
    moved = browser.js(_READ)
    assert moved["posture"]["letters"][0]["at"] != placed["posture"]["letters"][0]["at"]
    before, during = _offsets(placed), _offsets(moved)
    assert before.keys() == during.keys()
    for k, v in before.items():
        assert np.allclose(during[k], v, atol=0.02), k
    assert browser.js(f"window.graphkinLive.setDrive({d!r})") is not None
    browser.js(_OLD)
    old = faults(browser.js(_READ))
    assert old["marker"], old  # J and U on the inflection circle: each on the other's marker
    # the frame pivot D dragged and let go
    x, y = _handle(browser, "frame")
    drag(browser, (x, y), (x + 15.0, y - 12.0))
    assert browser.errors() == []
    _clean(browser.js(_READ))


def test_random_mechanisms_are_lettered_clean(browser, tmp_path: Path) -> None:

    @examples(6)
    @given(rm=mechanisms())
    def check(rm: RandomMechanism) -> None:
        mech = rm.mechanism()
        data = open_random_page(browser, tmp_path, mech, rm.data)
        if data is None:
            return
        _clean(browser.js(_READ))
        # the slider moved and let go ("change"): placed again
        d = data["drive"]
        step = 0.3 if d["degrees"] else 0.05 * mech.scale
        browser.js(f"window.graphkinLive.setDrive({d['value'] + step!r})")
        browser.js("window.graphkinLive.redraw(true)")
        if browser.js("window.graphkinLive.state()")["result"] is not None:
            _clean(browser.js(_READ))
        assert browser.errors() == []

    check()


def test_the_rules_are_draws_in_the_pages_pixels() -> None:
    """draw's 9 pt labels are the page's 12 px letters: 96 px to draw's inch (12 / (9/72)).

    draw's first place (render/labels.py ``_DIRS``) is up and to the right of the point,
    on paper y up, so on the screen (y down) the direction (1, -1); its first ring stands
    LabelRequest's gap, 0.045 in = 4.32 px, from the point; its box keeps 0.012 in = 1.152 px
    clear of its glyphs.
    """
    from graphkin.render.live_labels_js import LABELS_JS, PX_PER_INCH, RULES

    assert PX_PER_INCH == 96.0
    assert RULES["dirs"][0] == [1.0, -1.0]
    assert RULES["gaps"][0] == pytest.approx(4.32, rel=1e-12)
    assert RULES["pad"] == pytest.approx(1.152, rel=1e-12)
    assert "const GK_LABEL_RULES = {" in LABELS_JS
