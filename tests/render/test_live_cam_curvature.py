"""The curvature panel of a turning cam page holds at every cam angle the page reaches.

A cam's equivalent linkage (Sec. 4.7) is another one at every cam angle; the
curvature construction graphkin records at the file's angle used to carry Γ by
the four circles (Fig. 4.33) from auxiliary points chosen at that angle, so the
page said "the curvature construction found at the file's cam angle is another
one at other angles" and drew no panel while the cam turned.  Γ is now made at
every posture (construction/ops/bresse.py) and the four circles are not carried:
read back from headless Chromium at several cam angles, the page's I, J,
inflection circle, Bresse circle, Γ, Hain's points and U equal graphkin's
curvature of the file the page saves, to 1e-9 of the size; where the coupler
stands still (a dwell: ω = 0, no curvature in graphkin) the panel says so.
"""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest
from live_cams_shared import page_state
from live_edit import same_curvature

import graphkin
from graphkin.files import load_toml
from graphkin.kinematics.curvature.link import curvature
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_data, live_html

ROOT = Path(__file__).resolve().parents[2]
FILES = {"ex6_6": ROOT / "examples" / "cams" / "cam_mechanism.toml",
         "follows": ROOT / "tests" / "data" / "live19" / "cam_follows_crank.toml"}


def _file(src: Path) -> dict:
    """The file, its cam files' paths made absolute (the page's saved file reads them)."""
    data = load_toml(src)
    for cam in data.get("cams", []):
        if "file" in cam:
            cam["file"] = str((src.parent / cam["file"]).resolve())
    return data


@pytest.mark.parametrize("name", sorted(FILES))
def test_the_cam_pages_curvature_equals_graphkins_as_the_cam_turns(browser, tmp_path,
                                                                    name) -> None:
    src = FILES[name]
    data = _file(src)
    mech = from_dict(data, source=src.name)
    D, _ = live_data(mech, data, src.name)
    assert D.get("turn") is not None
    V = D["curvature"]
    assert "why" not in V and "note" not in V, V.get("why")
    assert {"I", "J", "inflection circle", "Bresse circle", "Γ"} <= set(V["labels"])
    for f in src.parent.glob("*.toml"):
        if f.name != src.name and "[cam]" in f.read_text(encoding="utf-8"):
            shutil.copy(f, tmp_path / f.name)
    page = tmp_path / "page.html"
    page.write_text(live_html(mech, data, src.name), encoding="utf-8")
    browser.open(page)
    drawn = 0
    for deg in (0.0, 23.0, 61.0, 117.0, -35.0, 200.0):
        browser.js(f"window.graphkinLive.setDrive({mech.drives[0].value + math.radians(deg)})")
        state = page_state(browser)
        if state["result"] is None:
            continue  # no equivalent linkage, or no assembly: said so (test_live_cam_turn.py)
        saved = tmp_path / "saved.toml"
        saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
        sol = graphkin.load(saved).solve()
        lcs = curvature(sol)
        note = browser.js("document.getElementById('gk-curvature-note').textContent")
        assert "another one" not in note and "No live curvature" not in note, note
        if state["curvature"] is None:
            # the page draws no panel only where graphkin has no construction of the link
            # (it does not turn there: a dwell, where the coupler's pin is the cam's center)
            assert V["link"] not in lcs, deg
            continue
        lc = lcs[V["link"]]
        assert same_curvature(D, state["curvature"], lc.values, 1.0 + mech.scale,
                              steps=lc.construction.steps) >= 6
        drawn += 1
    assert drawn >= 3
    assert browser.errors() == []
