"""``graphkin live`` of a train with an arm carried by another arm (examples/gears/trains).

The page opens in headless Chromium, and every gear's ω on it equals ``graphkin gears
FILE --json`` (the mesh equations solved together) to 1e-9: at the file's posture,
with arm 2 set 400° further (past a turn, the angles counted on continuously), and
after a drag of the driver.  The same with the inner arm's motion given instead of
sun 4's, so that the inner arm is driven by its angle relative to arm 2.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

from live_cams_shared import drag, page_state

from graphkin.cli import main
from graphkin.gears.train_file import load_train
from graphkin.gears.train_layout import train_mechanism

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "gears" / "trains" / "arm_on_arm.toml"


def _check(state: dict, link_of: dict[str, str], want: dict[str, float]) -> None:
    r = state["result"]
    assert r is not None
    for member, w in want.items():
        lid = link_of[member]
        got = 0.0 if lid == "1" else r[f"ω{lid}"]
        assert abs(got - w) <= 1e-9 * 45.0, (member, got, w)


def test_an_arm_on_an_arm_turns_on_the_page_as_the_train_says(browser, tmp_path: Path,
                                                              capsys) -> None:
    inner = tmp_path / "inner_given.toml"   # ω3 given, sun 4 free: 30 = 10 - 2 (ω4 - 10)
    inner.write_text(EXAMPLE.read_text(encoding="utf-8").replace('4 = 0\n', '3 = 30\n'),
                     encoding="utf-8")
    for path in (EXAMPLE, inner):
        page = tmp_path / f"{path.stem}.html"
        assert main(["live", str(path), "-o", str(page)]) == 0
        assert main(["gears", str(path), "--json"]) == 0
        out = capsys.readouterr().out
        ref = json.loads(out[out.index("{"):])
        want = {m: v["omega"] for m, v in ref["members"].items()}   # rad/s
        assert abs(want["6"] - 45.0) < 1e-9          # the hand table (the file's comment)
        link_of = train_mechanism(load_train(path), path).link_of
        browser.open(page)
        state = page_state(browser)
        _check(state, link_of, want)
        browser.js(f"window.graphkinLive.setDrive({state['drive'] + math.radians(400.0)})")
        _check(page_state(browser), link_of, want)
        r = browser.js("(function () { var h = document.querySelector('.gk-handle[data-kind="
                       "\"drive\"]'); var r = h.getBoundingClientRect(); "
                       "return [r.x + r.width / 2, r.y + r.height / 2]; })()")
        before = page_state(browser)["drive"]
        drag(browser, (r[0], r[1]), (r[0] - 20.0, r[1] + 25.0))
        state = page_state(browser)
        assert state["drive"] != before             # the driver turned with the pointer
        _check(state, link_of, want)
        assert browser.errors() == []
