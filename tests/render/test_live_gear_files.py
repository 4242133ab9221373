"""``graphkin live GEARFILE``: a pair in mesh opens as two gears rolling on fixed centers.

graphkin/gears/as_mechanism.py writes the driver (link 2) on O2 and the driven
gear (link 3) on O3 at the operating center distance, their operating pitch
circles rolling (one ``[[rolling]]`` contact).  Every gallery gear file that is
not itself a mechanism either opens — the gears turn in the ratio of their
teeth (Eq. 7.2) and, after the drive is set and dragged, the page equals
``graphkin solve`` of the mechanism it saves to 1e-9.  A rack and a train file
open too; their values are held to the train's analysis in
tests/render/test_live_gear_trains.py.
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from live_cams_shared import drag, page_state, same_as_solve

import graphkin
from graphkin.cli import main

GALLERY = Path(__file__).resolve().parents[2] / "gallery" / "gears"
FILES = sorted(p for p in GALLERY.glob("*.toml")
               if "links" not in tomllib.loads(p.read_text(encoding="utf-8")))


def test_the_gallery_has_pairs_racks_and_trains() -> None:
    kinds = set()
    for p in FILES:
        d = tomllib.loads(p.read_text(encoding="utf-8"))
        kinds.add("mesh" if "mesh" in d else "rack" if any(
            g.get("kind") == "rack" for g in d["gears"].values()) else "pair")
    assert kinds == {"mesh", "rack", "pair"}


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_a_gallery_gear_file_opens_rolling(browser, tmp_path: Path, path: Path,
                                                         capsys) -> None:
    given = tomllib.loads(path.read_text(encoding="utf-8"))
    page = tmp_path / "gears.html"
    rc = main(["live", str(path), "-o", str(page)])
    err = capsys.readouterr().err.strip()
    assert rc == 0, err
    if "mesh" in given or any(g.get("kind") == "rack" for g in given["gears"].values()):
        return   # opened; their values: tests/render/test_live_gear_trains.py
    gears = list(given["gears"].items())            # the first is the driver, link 2
    browser.open(page)
    assert browser.js("document.title") == f"{given.get('title', path.stem)} (live)"
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    mech = graphkin.load(saved)
    sol = mech.solve()
    # Eq. 7.2: ω3/ω2 = -N2/N3 outside, +N2/N3 inside a ring (Sec. 7.5)
    (_, g2), (_, g3) = gears
    ratio = g2["teeth"] / g3["teeth"] * (1.0 if g3.get("kind") == "internal" else -1.0)
    assert sol.omega("3") == pytest.approx(ratio * sol.omega("2"), rel=1e-12)
    c = float(np.hypot(*(np.subtract(sol.position("O3"), sol.position("O2")))))
    book = [b["value"] for b in given.get("gallery", {}).get("book", [])
            if b["path"] == "mesh.center_distance"]
    if "center_distance" in given:
        assert c == pytest.approx(given["center_distance"], rel=1e-12)
    elif book:                                       # the book's answer, to its 5 figures
        assert c == pytest.approx(book[0], rel=5e-5)
    elif "diametral_pitch" in given and "offset" not in str(given["gears"]):
        # standard teeth: C = (N3 ± N2)/(2P) (Eqs. 7.1, 7.3)
        n2, n3 = g2["teeth"], g3["teeth"]
        n = n3 - n2 if g3.get("kind") == "internal" else n3 + n2
        assert c == pytest.approx(n / (2.0 * given["diametral_pitch"]), rel=1e-12)
    drive0 = page_state(browser)["drive"]
    for a in (0.0, 47.0, -100.0):
        browser.js(f"window.graphkinLive.setDrive({drive0 + math.radians(a)})")
        state = page_state(browser)
        assert state["result"] is not None
        same_as_solve(browser, tmp_path, mech, state)
    r = browser.js("(function () { var h = document.querySelector('.gk-handle[data-kind="
                   "\"drive\"]'); if (!h) return null; var r = h.getBoundingClientRect(); "
                   "return [r.x + r.width / 2, r.y + r.height / 2]; })()")
    assert r is not None                         # A2, the driver's handle
    before = page_state(browser)["drive"]
    drag(browser, (r[0], r[1]), (r[0] + 25.0, r[1] + 15.0))
    state = page_state(browser)
    assert state["drive"] != before              # the driver turned with the pointer
    same_as_solve(browser, tmp_path, mech, state)
    assert browser.errors() == []
