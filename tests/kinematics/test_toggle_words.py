"""At a toggle or dead point the report says why in the book's and the file's words.

Defect noticed at the session-8 stop: the dead-point note named a step of the
code ("step 9 (ω4): the step has no answer (B, rolling[0]:C, v(B), o_v)").  The
note must name the posture (the drive's value and the branch), the points in
line and the quantity that is undetermined (Sec. 3.5), never a step label.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import graphkin
from graphkin.cli import main

DATA = Path(__file__).resolve().parents[1] / "data" / "rolling" / "wheel_dead_point.toml"

# A four-bar at the crank's limit: A = (0, 0), D = (4, 0), crank AB = 3 at θ2 = 90°, so
# B = (0, 3) and |BD| = 5 = BC + CD with BC = 2, CD = 3: C lies on BD, 2/5 of the way,
# C = (0, 3) + 0.4 (4, -3) = (1.6, 1.8).  B, C and D are in line: the lines ⊥ BC and ⊥ CD
# of the velocity polygon are parallel and V_C is undetermined (Sec. 3.5).
LIMIT = """
title = "four-bar at the crank's limit"
units = { length = "mm" }
[links.1]
A = [0, 0]
D = [4, 0]
[links.2]
A = [0, 0]
B = [3, 0]
[links.3]
B = [0, 0]
C = [2, 0]
[links.4]
D = [0, 0]
C = [3, 0]
[drive]
link = 2
angle = {angle!r}
omega = "10 rad/s"
alpha = 0
[assembly]
C = [1.6, 1.8]
"""

STEP_WORDS = re.compile(r"step \d|rolling\[|has no answer|o_v|v\([A-Z]")


def _toggle_note(sol: graphkin.Solution) -> str:
    notes = [n for n in sol.notes if n.startswith("toggle or dead-center")]
    assert len(notes) == 1, sol.notes
    return notes[0]


def test_rolling_dead_point_note_names_the_points_in_line_not_a_step() -> None:
    # Example 3.9 with A, B and the contact C on the vertical x = 141.42 mm (the file)
    note = _toggle_note(graphkin.load(DATA).solve())
    assert not STEP_WORDS.search(note), note
    assert "θ2 = -19.4712°" in note            # the posture: the file's drive angle
    assert "(branch: B behind)" in note        # and the branch the posture took
    assert "A, B and the contact C lie on one line" in note
    assert "V_BA (⊥ AB)" in note and "V_BC (⊥ CB)" in note
    assert "the velocity of B is undetermined" in note


def test_fourbar_at_the_crank_limit_says_b_c_d_in_line() -> None:
    sol = graphkin.loads(LIMIT.replace("{angle!r}", "90.0")).solve()
    note = _toggle_note(sol)
    assert not STEP_WORDS.search(note), note
    assert "θ2 = 90° (branch: C left)" in note
    assert "B, C and D lie on one line" in note
    assert "the velocity of C is undetermined" in note


def test_solve_prints_the_words(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["solve", str(DATA)]) == 0
    out = capsys.readouterr().out
    assert "A, B and the contact C lie on one line" in out
    assert not re.search(r"step \d+ \(", out)
