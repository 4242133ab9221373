"""The live page's first line names what its user drags, for each kind of page.

``graphkin live`` opens a linkage, a gear pair, a pinion on a rack, a gear
train, a cam, a synthesis file (the linkage it synthesizes) and a vector
file.  The line under the title (``<p class="hint">``) must name the handle
that drives that page (the crank's moving pin, the driving gear, the pinion,
the arm, the cam; the drive's control where the driving link has no handle)
and the frame pivots and link points it lets the user drag, by their names in
the file.  Read from the HTML ``graphkin live`` writes; no browser needed.
"""

from __future__ import annotations

import html
import re
from pathlib import Path

import pytest

from graphkin.cli import main

ROOT = Path(__file__).resolve().parents[2]

CASES = [
    # a linkage (Example 3.1): crank A-B, pivots A and D, coupler points E and F
    ("tests/data/spec/ex3_1_fourbar.toml",
     "Drag the crank's moving pin B, a frame pivot A or D, or a point of a link E or F"),
    # a slider-driven slider-crank (Example 3.2): no handle on the slider, its travel s4
    ("tests/data/spec/ex3_2_slider_driven.toml", "Set the drive s4 with the drive control"),
    # a gear pair on fixed centers (Example 7.1): gear 2 drives, gear 3 follows
    ("gallery/gears/ex7_1.toml",
     "Turn the driving gear 2 about O2 by its handle A2, drag a frame pivot O2 or O3"),
    # a pinion and a rack (Fig. 7.10)
    ("gallery/gears/fig7_10.toml",
     "Turn the pinion 2 about O2 by its handle A2 (the rack slides under it)"),
    # a reverted planetary train driven by its gear 2 (Example 7.4, gear 6 fixed)
    ("gallery/gears/ex7_4.toml", "Turn the driving gear 2 about O2 by its handle A2"),
    # a planetary train driven by its arm (Example 7.10)
    ("gallery/gears/ex7_10.toml", "Turn the arm 3, which carries the planets, about O2"),
    # a cam file (Example 6.1): the cam turns under its follower
    ("gallery/cams/ex6_1_parabolic.toml", "Turn the cam about O2 by its handle"),
    # a synthesis file (Example 9.1): the four-bar it synthesizes, crank O_A-A
    ("gallery/synthesis/ex9_1_image_point.toml",
     "Drag the crank's moving pin A, a frame pivot O_A or O_B, or a point of a link D"),
    # a vector file (C = A + B, Sec. 2.8): its own page, what is given
    ("gallery/vector/case2.toml", "Drag what is given"),
]


def _hint(path: Path, tmp_path: Path) -> str:
    page = tmp_path / (path.stem + ".html")
    assert main(["live", str(path), "-o", str(page)]) == 0
    text = page.read_text(encoding="utf-8")
    got = re.search(r'<p class="hint">(.*?)</p>', text, re.S)
    assert got is not None
    return " ".join(html.unescape(got.group(1)).split())


@pytest.mark.parametrize(("name", "words"), CASES, ids=[Path(c[0]).stem for c in CASES])
def test_the_intro_names_what_is_dragged(name: str, words: str, tmp_path, capsys) -> None:
    hint = _hint(ROOT / name, tmp_path)
    capsys.readouterr()
    assert hint.startswith(words), hint
    assert "\n" not in hint and "None" not in hint
    # only the linkage pages speak of a crank
    assert ("crank" in hint) == words.startswith("Drag the crank"), hint
