"""Every link is numbered once on a drawing, and the number is seen (session 8, cosmetic).

The planetary examples (examples/planetary_outside.toml, planetary_inside.toml) had no
"3" on their planet: the planet's link has two points (its center P and Q on its pitch
circle), so it was numbered beside its bar P-Q, and the planet's disc, drawn over the
bar in white, hid the number; a random planet larger than its arm hid the arm and its
"2" as well.  A gear (a roller that is its whole link) is now drawn under the links and
numbered on its disc.  Read back from the SVG: the texts of the ``number-K`` groups, and
what is painted after them (tests/svg_boxes.py).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from hypothesis import given
from strategies import examples
from strategies_rolling import rolling_arrangements
from svg_boxes import hidden_texts, texts

import graphkin
from graphkin.render import draw
from graphkin.render.style import rc_context
from graphkin.render.svg import to_bytes

ROOT = Path(__file__).resolve().parents[2]


def _numbers(mech, diagram: str = "posture") -> tuple[dict[str, list[str]], list]:
    with rc_context():
        root = ET.fromstring(to_bytes(draw(mech.solve(), diagram).figure))
    found: dict[str, list[str]] = {}
    for n in texts(root):
        if n.gid.startswith("number-"):
            found.setdefault(n.gid.removeprefix("number-"), []).append(n.text)
    hidden = [h for h in hidden_texts(root) if h[0].startswith("number-")]
    return found, hidden


@pytest.mark.parametrize("name", ["planetary_outside", "planetary_inside"])
def test_the_planet_is_numbered_and_seen(name):
    mech = graphkin.load(ROOT / "examples" / f"{name}.toml")
    found, hidden = _numbers(mech)
    # the frame 1 (the sun or the ring), the arm 2 and the planet 3: one number each
    assert found == {"1": ["1"], "2": ["2"], "3": ["3"]}, found
    assert not hidden, hidden


def test_the_check_sees_a_hidden_number(monkeypatch):
    # the measurement can fail: as before, the planet's disc drawn over the links and the
    # planet numbered beside its bar P-Q: the number is reported hidden under the disc
    from graphkin.render import mechanism

    monkeypatch.setattr(mechanism, "GEAR_Z", 1.6)

    real = mechanism._number
    asked: dict[str, int] = {}

    def once(panel, g, lid, anchor, pre, gap=0.05):
        asked[lid] = asked.get(lid, 0) + 1
        if lid == "3" and asked[lid] > 1:
            return            # the disc's number dropped: the bar's stays, under the disc
        real(panel, g, lid, anchor, pre, gap)

    monkeypatch.setattr(mechanism, "_number", once)
    found, hidden = _numbers(graphkin.load(ROOT / "examples" / "planetary_outside.toml"))
    assert found.get("3") == ["3"]
    assert [h[:2] for h in hidden] == [("number-3", "3")]


@given(rm=rolling_arrangements("planet"))
@examples(15)
def test_every_link_of_a_random_planetary_train_is_numbered_once_and_seen(rm):
    mech = rm.mechanism()
    found, hidden = _numbers(mech)
    assert found == {lid: [lid] for lid in mech.links}, found
    assert not hidden, hidden


@given(rm=rolling_arrangements())
@examples(15)
def test_every_link_of_a_random_rolling_arrangement_is_numbered_once_and_seen(rm):
    # gears on fixed centers, a wheel on a carriage or driven by a coupler, racks and
    # pinions, gear chains: each link one number, none painted over
    mech = rm.mechanism()
    found, hidden = _numbers(mech)
    assert found == {lid: [lid] for lid in mech.links}, found
    assert not hidden, hidden


@pytest.mark.parametrize("rim", [20.0 * (1 + 1e-12), 20.0 * (1 - 1e-12)])
def test_a_rim_point_moved_by_round_off_keeps_the_planet_a_gear(rim):
    # Q on the planet's pitch circle (radius 20) moved by 1e-12 of it either way: the planet is
    # still its whole disc, numbered on it, and the arm 2 is seen over it
    text = (ROOT / "examples" / "planetary_outside.toml").read_text(encoding="utf-8")
    text = text.replace("Q = [20, 0]", f"Q = [{rim!r}, 0]")
    assert repr(rim) in text
    found, hidden = _numbers(graphkin.loads(text))
    assert found == {"1": ["1"], "2": ["2"], "3": ["3"]}, found
    assert not hidden, hidden


def test_a_link_named_by_a_word_stands_clear_of_the_kennedy_circle() -> None:
    # audit9: a four-bar whose crank is [links.crank]; its name was centered 0.16 in
    # outside its vertex on the Kennedy circle, so "crank" (five letters, ~0.5 in) ran
    # back over the vertex's dot and the chords, and off the panel's right edge.
    text = """units = "in"
[links.1]
O2 = [0, 0]
O4 = [7, 1.5]
[links.crank]
O2 = [0, 0]
A = [2.5, 0]
[links.3]
A = [0, 0]
B = [8, 0]
[links.4]
O4 = [0, 0]
B = [5, 0]
[drive]
link = "crank"
angle = 215
omega = 10
[assembly]
B = [6, 6]
"""
    with rc_context():
        root = ET.fromstring(to_bytes(draw(graphkin.loads(text).solve(), "centers").figure))
    from svg_boxes import page, strokes

    notes = {n.gid: n for n in texts(root)}
    for lid in ("1", "crank", "3", "4"):
        box = notes[f"kennedy-link-{lid}"].box
        assert page(root).contains(box), lid
        circle = [s for g, s in strokes(root) if g.startswith("kennedy-")]
        assert circle and not any(box.intersects(s) for s in circle), lid
