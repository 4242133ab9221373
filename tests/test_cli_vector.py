"""``graphkin vector FILE``: the textbook report, --json, and one-line errors (exit 2).

The numbers are those of the gallery files: Fig. 2.13 with a 3-4-5 triangle
(θ_A = ±acos(3/5) = ±53.1301°, θ_B = ∓acos(4/5) = ∓36.8699°) and Fig. 2.11 with
C = 8∠0°, θ_A = 30°, B = 5 (A = 8 cos 30° ∓ 3 = 3.9282, 9.9282).  Uicker,
Pennock & Shigley, 5th ed., Sec. 2.8 and Sec. 2.11.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from graphkin.cli import main

GALLERY = Path(__file__).resolve().parents[1] / "gallery" / "vector"

CASE_4 = """\
title = "3-4-5"
units = "in"
[A]
magnitude = 3
[B]
magnitude = 4
[C]
magnitude = 5
angle = 0
"""


def _write(tmp_path: Path, text: str, name: str = "v.toml") -> str:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return str(path)


def test_text_report_case_4(tmp_path, capsys):
    assert main(["vector", _write(tmp_path, CASE_4)]) == 0
    out, err = capsys.readouterr()
    assert err == ""
    lines = out.splitlines()
    assert lines[0] == "3-4-5"
    assert lines[1] == "case 4 of Table 2.2 (Fig. 2.13, two arcs): unknowns θ_A and θ_B"
    assert lines[2] == "C(✓✓) = A(✓?) + B(✓?)"
    assert lines[3].startswith("solution 1 (left):")
    assert "A = 3 in ∠53.1301°" in lines[3] and "B = 4 in ∠-36.8699°" in lines[3]
    assert lines[4].startswith("solution 2 (right):")
    assert "A = 3 in ∠-53.1301°" in lines[4] and "C = 5 in ∠0°" in lines[4]


def test_json(tmp_path, capsys):
    assert main(["vector", _write(tmp_path, CASE_4), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["case"] == 4 and data["unknowns"] == ["θ_A", "θ_B"]
    assert data["units"] == "in" and data["equation"]["text"] == "C(✓✓) = A(✓?) + B(✓?)"
    assert data["knowns"]["A"] == {"magnitude": 3.0, "angle_deg": None}
    left, right = data["solutions"]
    assert left["branch"] == "left" and right["branch"] == "right"
    assert left["A"]["angle_deg"] == pytest.approx(math.degrees(math.acos(3 / 5)))
    assert (left["A"]["x"], left["A"]["y"]) == pytest.approx((1.8, 2.4))
    assert "steps" not in data


def test_steps_table_and_json_steps(tmp_path, capsys):
    path = _write(tmp_path, CASE_4)
    assert main(["vector", path, "--steps"]) == 0
    out = capsys.readouterr().out
    assert "intersect_circles" in out and "left" in out and "k_A" in out
    assert main(["vector", path, "--json", "--steps"]) == 0
    steps = json.loads(capsys.readouterr().out)["steps"]
    assert [s["id"] for s in steps][:3] == ["step-00-O", "step-01-theta_C", "step-02-T"]
    assert all(s["equation"]["text"].count("?") == 2 for s in steps)


def test_branch_and_units_in_the_file(tmp_path, capsys):
    text = CASE_4.replace('units = "in"', 'units = "in"\nbranch = "right"').replace(
        "magnitude = 4", 'magnitude = "101.6 mm"').replace("angle = 0", 'angle = "0 rad"')
    assert main(["vector", _write(tmp_path, text)]) == 0
    out = capsys.readouterr().out
    assert "solution 1 (right):" in out and "solution 2" not in out
    assert "B = 4 in ∠36.8699°" in out


def test_unknowns_written_as_question_marks(tmp_path, capsys):
    text = '[A]\nmagnitude = "?"\nangle = 30\n[B]\nmagnitude = 5\nangle = "?"\n' \
           '[C]\nmagnitude = 8\nangle = 0\n'
    assert main(["vector", _write(tmp_path, text)]) == 0
    out = capsys.readouterr().out
    assert "unknowns A and θ_B" in out and "C(✓✓) = A(?✓) + B(✓?)" in out


@pytest.mark.parametrize("name, expect", [
    ("case2.toml", ["case 2 of Table 2.2", "(behind):", "A = 3.9282 in ∠30°",
                    "(ahead):", "A = 9.9282 in ∠30°"]),
    ("case4.toml", ["case 4 of Table 2.2", "A = 3 in ∠53.1301°", "B = 4 in ∠36.8699°"]),
])
def test_gallery_files(name, expect, capsys):
    assert main(["vector", str(GALLERY / name)]) == 0
    out = capsys.readouterr().out
    for text in expect:
        assert text in out


@pytest.mark.parametrize("text, where", [
    ("[A\n", "TOML syntax error"),
    ("colour = 1\n", "colour: unknown key"),
    ("[A]\nsize = 2\n", "A.size: unknown key 'size' (valid keys: magnitude, angle)"),
    ("[A]\nmagnitud = 2\n", "A.magnitud: unknown key 'magnitud' (did you mean 'magnitude'?)"),
    ("titel = \"x\"\n", "titel: unknown key 'titel' (did you mean 'title'?)"),
    ("units = { angle = \"rad\" }\n", "units.angle: unknown key 'angle'"),
    ("units = { length = \"furlongz\" }\n", "units: unknown unit"),
    ("A = 3\n", "A: expected a table"),
    ("[A]\nmagnitude = true\n", "A.magnitude: expected a number"),
    ("[A]\nmagnitude = \"x\"\n", "A.magnitude: cannot read"),
    ("[A]\nmagnitude = \"3 in\"\n", "A.magnitude: '3 in' has a unit, so the file needs"),
    ("units = \"in\"\n[A]\nmagnitude = \"3 s\"\n", "A.magnitude: cannot convert"),
    ("units = \"furlongz\"\n", "units: unknown unit"),
    ("[C]\nangle = \"30\"\n", "C.angle: '30' has no unit"),
    ("[C]\nangle = nan\n", "C.angle: expected a finite number"),
    ("[A]\nmagnitude = 3\n[B]\nmagnitude = 4\n[C]\nmagnitude = 5\n",
     "exactly two unknowns (Sec. 2.8); this one has 3"),
    ("branch = \"up\"\n[A]\nmagnitude = 3\n[B]\nmagnitude = 4\n[C]\nmagnitude = 5\nangle = 0\n",
     "branch: case 4 has the branches left, right, not 'up'"),
    ("[A]\nmagnitude = 0\n[B]\nmagnitude = 4\n[C]\nmagnitude = 5\nangle = 0\n",
     "A.magnitude: A has an unknown direction"),
    # the construction has no answer: said in the book's words (Sec. 2.8), as the live page
    ("[A]\nmagnitude = 1\n[B]\nmagnitude = 2\n[C]\nmagnitude = 8\nangle = 0\n",
     ": case 4 has no solution: the arcs do not meet: |A| + |B| = 3 < |C| = 8"),
    ("[A]\nangle = 10\n[B]\nangle = 10\n[C]\nmagnitude = 8\nangle = 0\n",
     ": case 3 has no solution: the directions of A (10°) and B (10°) are parallel"),
    ("[A]\nangle = 90\n[B]\nmagnitude = 1\n[C]\nmagnitude = 8\nangle = 0\n",
     ": case 2 has no solution: the line with the direction of A passes"),
])
def test_bad_files_give_one_line_and_exit_2(tmp_path, capsys, text, where):
    path = _write(tmp_path, text)
    assert main(["vector", path]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.endswith("\n") and err.count("\n") == 1, err
    assert err.startswith(f"graphkin: {path}: ")
    assert where in err
    assert "Traceback" not in err
    assert "step " not in err and "(P)" not in err   # no construction step labels (audit9)


def test_missing_and_undecodable_files(tmp_path, capsys):
    assert main(["vector", str(tmp_path / "nowhere.toml")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "cannot read the file" in err
    bad = tmp_path / "latin1.toml"
    bad.write_bytes(b"title = \"caf\xe9\"\n")
    assert main(["vector", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "not UTF-8" in err
