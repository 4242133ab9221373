"""``graphkin live CAMFILE``: a cam file opens as the turning page of the mechanism it means.

The cam (link 2) turns on O2 at the file's speed and sense, its follower (link 4)
on its guide or about its pivot (graphkin/cams/as_mechanism.py).  Every gallery
cam file either opens — and after the drive is set and the cam dragged by its
contact point, the page's values equal ``graphkin solve`` of the mechanism it
saves, to 1e-9 (a translating flat face too: its slot's offset −ρ turns with the cam).
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import pytest
from live_cams_shared import drag, page_state, same_as_solve

import graphkin
from graphkin.cli import main

GALLERY = Path(__file__).resolve().parents[2] / "gallery" / "cams"
FILES = sorted(GALLERY.glob("*.toml"))
STATUS = "document.getElementById('gk-status').textContent"


def test_the_gallery_has_cam_files_of_every_kind_of_linkage() -> None:
    kinds = {tomllib.loads(p.read_text(encoding="utf-8"))["follower"]["kind"] for p in FILES}
    assert "flat-face" in kinds and "roller" in kinds and "oscillating-roller" in kinds


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_a_gallery_cam_file_opens_turning(browser, tmp_path: Path, path: Path,
                                  capsys) -> None:
    _check(browser, tmp_path, path, capsys)


def test_a_clockwise_cam_turns_clockwise(browser, tmp_path: Path, capsys) -> None:
    # the gallery's cams all turn counterclockwise: Ex 6.7's oscillating follower turned cw
    text = (GALLERY / "ex6_7_oscillating.toml").read_text(encoding="utf-8")
    assert 'rotation = "ccw"' in text
    cw = tmp_path / "cw.toml"
    cw.write_text(text.replace('rotation = "ccw"', 'rotation = "cw"'), encoding="utf-8")
    _check(browser, tmp_path, cw, capsys)


def _check(browser, tmp_path: Path, path: Path, capsys) -> None:
    given = tomllib.loads(path.read_text(encoding="utf-8"))
    page = tmp_path / "cam.html"
    rc = main(["live", str(path), "-o", str(page)])
    err = capsys.readouterr().err.strip()
    assert rc == 0, err
    browser.open(page)
    assert browser.js("document.title") == f"{given['title']} (live)"
    # the saved mechanism: the cam file's cam, driven at its speed in its sense
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    mech = graphkin.load(saved)
    sol = mech.solve()
    sense = 1.0 if given["cam"].get("rotation", "ccw") == "ccw" else -1.0
    # 150 rev/min = 150·2π/60 = 5π rad/s (the gallery's only speed); 1 rad/s when none given
    speed = {None: 1.0, "150 rev/min": 5.0 * math.pi}[given["cam"].get("speed")]
    assert math.copysign(1.0, sol.omega("2")) == sense
    assert abs(abs(sol.omega("2")) - speed) < 1e-12 * speed
    if given["follower"]["kind"].startswith("oscillating"):
        pivot = [float(v) for v in given["follower"]["pivot"]]
        assert sol.position("O4") == pytest.approx(pivot, abs=1e-12)
    drive0 = page_state(browser)["drive"]
    for a in (0.0, 47.0, -100.0):            # three cam angles set, then a drag of the cam
        browser.js(f"window.graphkinLive.setDrive({drive0 + math.radians(a)})")
        state = page_state(browser)
        if state["result"] is None:          # no linkage there: said in one line, no number
            said = browser.js(STATUS)
            assert said and "\n" not in said and "NaN" not in said
            continue
        same_as_solve(browser, tmp_path, mech, state)
    r = browser.js("(function () { var r = document.querySelector('.gk-handle[data-kind="
                   "\"drive\"]').getBoundingClientRect(); return [r.x + r.width / 2, "
                   "r.y + r.height / 2]; })()")
    before = page_state(browser)["drive"]
    drag(browser, (r[0], r[1]), (r[0] + 25.0, r[1] + 15.0))
    state = page_state(browser)
    assert state["drive"] != before          # the cam turned with the pointer
    if state["result"] is not None:
        same_as_solve(browser, tmp_path, mech, state)
    assert browser.errors() == []
