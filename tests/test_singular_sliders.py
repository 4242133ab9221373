"""``--singular`` for slider mechanisms: limit positions of sliders, dead centers of slider drives.

Sec. 1.10 of Uicker, Pennock & Shigley: a slider-crank driven by its crank has
two limit positions of the slider, with crank and connecting rod in line; driven
by its slider, those postures are dead centers. Every expected value below is
derived by hand in its comment.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from spec_data import inline

import graphkin
from graphkin.cli import main

ROOT = Path(__file__).resolve().parents[1]

INLINE = inline("singular_sliders-inline.toml")


def _of(sw, kind):
    return [s for s in sw.singular if s.kind == kind]


def test_crank_driven_slider_crank_limit_positions():
    # r = 2, l = 8, in line: V_C = 0 with crank and rod in line, θ2 = 180° (C at l - r = 6)
    # and θ2 = 360° (C at l + r = 10); no rates in the file: found all the same
    sw = graphkin.loads(INLINE).sweep(count=3600)
    limits = _of(sw, "limit")
    assert [s.label for s in limits] == ["4", "4"]
    assert [s.drive for s in limits] == pytest.approx([180.0, 360.0], abs=1e-6)
    assert "C at 6 in along its line" in limits[0].note
    assert "C at 10 in along its line" in limits[1].note


def test_whitworth_ram_limit_positions(capsys, tmp_path):
    # the ram stops when link 4 lies along the ram's line (C at (±4, 1)): then the
    # crank pin A is on y = 1 with |O2A| = 3, sin θ2 = 1/3, θ2 = 19.47° or 160.53°;
    # D = C + 8 along the line: x_D = 4 + 8 = 12 or -4 + 8 = 4 (from S at x = 0)
    path = ROOT / "tests" / "data" / "whitworth.toml"
    sw = graphkin.load(path).sweep(count=3600)
    limits = sorted(_of(sw, "limit"), key=lambda s: s.drive % 360)
    th = math.degrees(math.asin(1 / 3))
    assert [s.drive % 360 for s in limits] == pytest.approx([th, 180 - th], abs=1e-6)
    assert "D at 12 in" in limits[0].note and "D at 4 in" in limits[1].note
    assert main(["sweep", str(path), "--singular", "--count", "360",
                 "--csv", str(tmp_path / "w.csv")]) == 0
    err = capsys.readouterr().err
    assert err.count("limit position of slider 6 (V_D = 0)") == 2


def test_slider_driven_slider_crank_dead_centers_at_the_ends_of_its_travel():
    # Example 3.2's offset slider-crank driven by its slider: e = 20, r = 50, l = 140.
    # B's arcs (about A, radius r; about C, radius l) are tangent where |AC| = l ∓ r:
    # x_C = sqrt((l - r)² - e²) = 87.75 and sqrt((l + r)² - e²) = 188.94
    sw = graphkin.examples.slider_crank().sweep(count=720)
    dead = _of(sw, "dead-center")
    assert [s.label for s in dead] == ["B", "B"]
    assert [s.drive for s in dead] == pytest.approx(
        [math.sqrt(90**2 - 20**2), math.sqrt(190**2 - 20**2)], abs=1e-6)
    # a range the user cut short ends at no dead center
    assert not _of(graphkin.examples.slider_crank().sweep(count=50, start=100, stop=150),
                   "dead-center")


def test_slider_drive_is_not_its_own_limit():
    # the driven slider moves at unit speed everywhere: it never stops
    sw = graphkin.examples.slider_crank().sweep(count=720)
    assert not [s for s in _of(sw, "limit") if s.label == "4"]
