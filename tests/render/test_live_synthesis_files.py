"""``graphkin live SYNTHFILE``: a synthesis file opens as its synthesized linkage's page.

The page is that of the mechanism file ``graphkin synthesize FILE -o MECH.toml``
writes (the first candidate passing every check, else the first), and says so
in one line on stderr.  Tested for every gallery synthesis file in headless
Chromium: the page's linkage is the written file's, and after the drive is set
the page equals ``graphkin solve`` of the mechanism it saves to 1e-9 (or says
in one line that it cannot be assembled there).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from live_cams_shared import page_state, same_as_solve

import graphkin
from graphkin.cli import main

GALLERY = Path(__file__).resolve().parents[2] / "gallery" / "synthesis"
FILES = sorted(GALLERY.glob("*.toml"))
STATUS = "document.getElementById('gk-status').textContent"


def test_the_gallery_has_synthesis_files() -> None:
    assert len(FILES) >= 8


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_a_synthesis_file_opens_its_first_linkage(browser, tmp_path: Path, path: Path,
                                                  capsys) -> None:
    written = tmp_path / "written.toml"
    assert main(["synthesize", str(path), "-o", str(written)]) == 0
    capsys.readouterr()
    page = tmp_path / "s.html"
    assert main(["live", str(path), "-o", str(page)]) == 0
    err = capsys.readouterr().err
    assert "synthesized linkage 'graphkin synthesize -o' writes" in err.splitlines()[0]
    browser.open(page)
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    mech = graphkin.load(saved)
    ref = graphkin.load(written).solve()
    sol = mech.solve()
    # the page's linkage, unedited, is the one synthesize writes: every point at its place
    size = 1.0 + mech.scale
    for lk in graphkin.load(written).links.values():
        for n in lk.points:
            np.testing.assert_allclose(sol.position(n), ref.position(n), rtol=0,
                                       atol=1e-9 * size, err_msg=n)
    drive0 = page_state(browser)["drive"]
    for a in (0.0, 5.0, -7.0):
        browser.js(f"window.graphkinLive.setDrive({drive0 + math.radians(a)})")
        state = page_state(browser)
        if state["result"] is None:              # cannot be assembled there: said in one line
            said = browser.js(STATUS)
            assert said and "\n" not in said and "NaN" not in said
            continue
        same_as_solve(browser, tmp_path, mech, state)
    assert browser.errors() == []
