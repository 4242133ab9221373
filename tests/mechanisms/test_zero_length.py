"""A moving link of zero length between two joints is noted; meaningful zero lengths are not.

Defect found in the session-7 acceptance audit: a crank with ``B = [0, 0]``
(pivot and crank pin at one place) was solved and reported ω2 = 10 rad/s while
every other link stood still, with nothing said.  It is not refused: the book's
equivalent linkage of a cam in a dwell (Sec. 4.7) is such a crank, and
``graphkin cam --equivalent`` writes it.  docs/formats/mechanism.md, "Zero
lengths", says which zero lengths are meaningful (not noted).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from spec_data import inline

import graphkin
from graphkin.cli import main

FOURBAR = inline("parse_errors-fourbar.toml")   # A-D 10, AB 4, BC 18, DC 11 (in)
SLIDER = inline("parse_errors-slider.toml")     # crank 50, coupler 140, line y = -20

ZERO = [
    ("zero crank", FOURBAR.replace("B = [4, 0]", "B = [0, 0]"), "links.2.B"),
    # 1e-12 of the size is round-off of a zero length: the same verdict
    ("crank at round-off", FOURBAR.replace("B = [4, 0]", "B = [1e-12, 0]"), "links.2.B"),
]
# a coupler or rocker of zero length cannot close the loop here: C would have to be at B
# (55.36 mm from the slider's line) or at D (12.49 in from B, the coupler 18 in long)
UNASSEMBLED = [
    ("zero coupler", SLIDER.replace("C = [140, 0]", "C = [0, 0]"), "BC = 0 mm"),
    ("zero rocker", FOURBAR.replace("C = [11, 0]", "C = [0, 0]"), "DC = 0 in"),
]


@pytest.mark.parametrize("name,text,key", ZERO, ids=[z[0] for z in ZERO])
def test_a_zero_length_link_is_noted_naming_the_key(tmp_path, capsys, name, text, key):
    path = tmp_path / "zero.toml"
    path.write_text(text)
    assert main(["solve", str(path)]) == 0
    out, err = capsys.readouterr()
    notes = [ln for ln in out.splitlines() if "zero length" in ln]
    assert len(notes) == 1, out
    assert notes[0].strip().startswith(f"note: {key}: "), notes


@pytest.mark.parametrize("name,text,said", UNASSEMBLED, ids=[z[0] for z in UNASSEMBLED])
def test_a_zero_link_that_cannot_close_the_loop_says_its_length(tmp_path, capsys, name, text,
                                                                said):
    path = tmp_path / "zero.toml"
    path.write_text(text)
    assert main(["solve", str(path)]) == 2
    out, err = capsys.readouterr()
    assert out == "" and len(err.strip().splitlines()) == 1 and said in err, err


def test_a_zero_crank_moves_nothing(tmp_path) -> None:
    """Crank O2-B of zero length: V_B = V_A + ω2 × 0 = 0, so the four-bar's B, and with it
    links 3 and 4, stand still whatever ω2 (Sec. 3.4)."""
    text = FOURBAR.replace("B = [4, 0]", "B = [0, 0]").replace("angle = 120",
                                                             "angle = 120\nomega = 10")
    sol = graphkin.loads(text).solve()
    assert sol.omega(2) == pytest.approx(10.0)
    assert sol.omega(3) == pytest.approx(0.0, abs=1e-12)
    assert sol.omega(4) == pytest.approx(0.0, abs=1e-12)
    assert any(n.startswith("links.2.B: ") for n in sol.notes)


def test_coaxial_frame_pivots_are_meaningful():
    """Pivots A and D of the frame at one place: the triangle A-B-C turns as one body.

    With D at A, the sides AB = 4, BC = 18 and CA = DC = 11 of triangle ABC are
    all fixed lengths, so links 2, 3 and 4 turn together: ω3 = ω4 = ω2.
    """
    text = FOURBAR.replace("D = [10, 0]", "D = [0, 0]").replace("C = [18, 0]", "C = [12, 0]")
    text = text.replace("angle = 120", "angle = 120\nomega = 10").replace("[15, 10]", "[5, 8]")
    sol = graphkin.loads(text).solve()
    assert sol.omega(3) == pytest.approx(10.0, abs=1e-9)
    assert sol.omega(4) == pytest.approx(10.0, abs=1e-9)


def test_in_line_slider_crank_has_offset_zero():
    """The slider's line through the crank pivot (offset 0) is the in-line slider-crank.

    Crank r = 50 at 45°, coupler l = 140, the line y = 0: x_C = r cos θ + sqrt(l² - r² sin² θ).
    """
    text = SLIDER.replace("S = [0, -20]", "S = [0, 0]").replace("T = [100, -20]", "T = [100, 0]")
    sol = graphkin.loads(text).solve()
    r, lc, th = 50.0, 140.0, math.radians(45)
    x = r * math.cos(th) + math.sqrt(lc**2 - (r * math.sin(th))**2)
    assert sol.position("C")[0] == pytest.approx(x, rel=1e-9)
    assert sol.position("C")[1] == pytest.approx(0.0, abs=1e-9)


def test_a_cams_dwell_is_not_a_zero_length_slip(tmp_path) -> None:
    """A cam's equivalent linkage (Sec. 4.7) in a dwell has its crank O2-K4 of zero length:
    the profile there is an arc about O2, so its center of curvature is O2.  The user never
    wrote that length; the file loads at every cam angle, and in a dwell the follower
    stands still (Sec. 6.2: a dwell is no motion of the follower)."""
    data = Path(__file__).resolve().parents[1] / "data" / "audit7"
    (tmp_path / "cam630.toml").write_text((data / "cam630.toml").read_text())
    text = (data / "cam_mech.toml").read_text()
    dwells = 0
    for angle in range(0, 360, 10):
        path = tmp_path / "mech.toml"
        path.write_text(text.replace("angle = 230", f"angle = {angle}"))
        mech = graphkin.load(path)                      # no InputError at any angle
        assert mech.notes == ()                         # and no note: the user wrote no K4
        k4 = np.subtract(mech.links["2"].points["K4"], mech.links["2"].points["O2"])
        if float(np.hypot(*k4)) < 1e-9 * mech.size:
            dwells += 1
            omega2 = 2.0 * math.pi * 200.0 / 60.0
            assert abs(mech.solve().omega("6")) < 1e-12 * omega2
    assert dwells >= 4            # four dwells of 45°, 10°, 30°, 20° in Problem 6.30's cam
