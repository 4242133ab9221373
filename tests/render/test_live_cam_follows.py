"""A cam on a link that is not the first drive's turns with its link on the live page.

tests/data/live19/cam_follows_crank.toml: Example 6.6's cam (link 2) turned by
a crank (link 5, the first drive) through a law, θ2 = θ5 / 2 + 10° (the cam's
drive ``follows`` the crank), the crank also driving a four-bar.  The page used to
hold the whole page at the file's angle; now dragging the crank moves the
four-bar and turns the cam to the law's angle, its equivalent linkage rebuilt
there (render/live_cam_turn.py).  Tested in headless Chromium against
``graphkin solve`` of the file the page saves (the crank's new angle; the cam's
angle from the law, the linkage rebuilt by cams/joint.py): every point,
velocity, acceleration, angular rate and instant center, at several crank
angles; the status line gives the cam's Θ = θ5 / 2 + 10°.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from live_cams_shared import page_state, same_as_solve

import graphkin
from graphkin.files import load_toml
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_data, live_html

ROOT = Path(__file__).resolve().parents[2]
SRC = ROOT / "tests" / "data" / "live19" / "cam_follows_crank.toml"
STATUS = "document.getElementById('gk-status').textContent"


def _file() -> dict:
    """The test file, its cam file's path made absolute (the page's saved file reads it)."""
    data = load_toml(SRC)
    data["cams"][0]["file"] = str((SRC.parent / data["cams"][0]["file"]).resolve())
    return data


def test_the_cam_on_the_following_drive_turns() -> None:
    data = _file()
    mech = from_dict(data, source=SRC.name)
    d, _ = live_data(mech, data, SRC.name)
    assert d.get("turn") is not None and d["cam"]["why"] == ""
    assert d["turn"]["cams"][0]["input"] == "θ2"
    # the crank keeps its handle (its pin A): the page is dragged by it
    assert d["drive"]["pivot"] == "O5" and d["drive"]["tip"] == "A"
    assert d["centers"]["fn"] is not None, d["centers"]["why"]


def test_the_page_equals_solve_as_the_crank_turns(browser, tmp_path) -> None:
    data = _file()
    mech = from_dict(data, source=SRC.name)
    page = tmp_path / "page.html"
    page.write_text(live_html(mech, data, SRC.name), encoding="utf-8")
    browser.open(page)
    shown = 0
    for crank in (40.0, 100.0, 163.0, 250.0, -70.0):
        browser.js(f"window.graphkinLive.setDrive({math.radians(crank)})")
        state = page_state(browser)
        said = browser.js(STATUS)
        if state["result"] is None:            # the four-bar cannot reach: said, in one line
            assert said and "\n" not in said
            continue
        shown += 1
        # the cam's angle is the law's: Θ = θ2 (axis 90°) = θ5 / 2 + 10°, in [0°, 360°)
        m = re.match(r"cams\[0\]: Θ = ([-0-9.]+)°", said)
        assert m, said
        assert abs(float(m.group(1)) - (crank / 2 + 10.0) % 360.0) < 1e-3
        assert "keeps the cam angle" not in said
        assert abs(state["result"]["θ2"] - math.radians(crank / 2 + 10.0)) < 1e-12
        same_as_solve(browser, tmp_path, mech, state)
        # graphkin solve of the saved file has the cam at the law's angle too
        saved = graphkin.load(tmp_path / "saved.toml")
        assert abs(saved.cams[0].theta - math.radians(crank / 2 + 10.0) % (2 * math.pi)) < 1e-9
    assert shown >= 3


def test_a_cam_link_following_by_a_table_is_refused_in_one_line() -> None:
    # the cam's angle at the file's posture comes from a linear law only (Sec. 4.7 needs it
    # to lay out the equivalent linkage); a table is refused, naming the file and the key
    from graphkin.errors import InputError

    data = _file()
    data["drive"][1]["follows"] = {"link": 5, "table": [[0, 0], [360, 180]]}
    with pytest.raises(InputError) as e:
        from_dict(data, source="t.toml")
    said = e.value.one_line()
    assert "drive[1].follows" in said and "table" in said and "t.toml" in said
    assert "\n" not in said
