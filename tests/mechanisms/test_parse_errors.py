"""Every malformed mechanism file ends with exit 2 and one line naming file and key."""

from __future__ import annotations

import textwrap

import pytest
from spec_data import inline

from graphkin.cli import main

FOURBAR = inline("parse_errors-fourbar.toml")

SLIDER = inline("parse_errors-slider.toml")

SLOT = inline("parse_errors-slot.toml")

CASES = [
    ("syntax", "[links.1\nA = [0, 0]", None, "TOML syntax"),
    ("unknown unit", FOURBAR.replace('"in"', '"furlongz"'), "units.length", "unit"),
    ("not a length", FOURBAR.replace('"in"', '"kg"'), "units.length", "length"),
    ("nan", FOURBAR.replace("D = [10, 0]", "D = [nan, 0]"), "links.1.D", "finite"),
    ("inf", FOURBAR.replace("B = [4, 0]", "B = [inf, 0]"), "links.2.B", "finite"),
    ("three numbers", FOURBAR.replace("B = [4, 0]", "B = [4, 0, 1]"), "links.2.B", "two numbers"),
    ("string point", FOURBAR.replace("B = [4, 0]", 'B = "4, 0"'), "links.2.B", "two numbers"),
    ("bool coordinate", FOURBAR.replace("B = [4, 0]", "B = [true, 0]"), "links.2.B",
     "two numbers"),
    ("unknown drive link", FOURBAR.replace("link = 2", "link = 9"), "drive.link", "no link"),
    # a drive on a floating link is solved by the analytic solver since issue 25
    # (tests/robust/test_api_round3.py)
    ("wrong mobility", FOURBAR.replace("C = [11, 0]", "E = [11, 0]"), "drive",
     "degree(s) of freedom"),
    ("no drive", FOURBAR.split("[drive]")[0], "drive", "needs a [drive]"),
    ("unknown slider link", SLIDER.replace("link = 4\non", "link = 7\non"), "sliders[0].link",
     "no link"),
    ("unknown slider point", SLIDER.replace('point = "C"', 'point = "Z"'), "sliders[0].point",
     "no point"),
    ("degenerate line", SLIDER.replace('line = ["S", "T"]', "line = [[0, 0], [0, 0]]"),
     "sliders[0].line", "degenerate"),
    ("slot radius", SLOT, "slots[0].circle.radius", "positive"),
    ("cannot assemble", FOURBAR.replace("C = [18, 0]", "C = [1, 0]"), "drive", "assemble"),
    ("assembly hint of nothing", FOURBAR.replace("C = [15, 10]", "Q = [15, 10]"),
     "assembly.Q", "no point"),
    ("bad rate", FOURBAR.replace("angle = 120", 'angle = 120\nomega = "10 kg"'),
     "drive.omega", "omega"),
    # audit 8: it said "'5 m/s^2' is not a alpha (expected units like rad/s**2)"
    ("linear unit for alpha", FOURBAR.replace("angle = 120", 'angle = 120\nalpha = "5 m/s^2"'),
     "drive.alpha", "is not an angular acceleration (give a unit like rad/s^2)"),
    ("length for an angle", FOURBAR.replace("angle = 120", 'angle = "30 mm"'),
     "drive.angle", "is not an angle (give a unit like deg)"),
    # audit 8: alpha without omega was silently dropped (no accelerations, no word)
    ("alpha without omega", FOURBAR.replace("angle = 120", "angle = 120\nalpha = 5"),
     "drive.alpha", "alpha is given without omega"),
    ("acceleration without velocity", SLIDER.replace("link = 2\nangle = 45",
                                                     "link = 4\nposition = 120\nacceleration = 2"),
     "drive.acceleration", "acceleration is given without velocity"),
]


@pytest.mark.parametrize("name,text,key,reason", CASES, ids=[c[0] for c in CASES])
def test_malformed_file_exits_2_with_one_line(tmp_path, capsys, name, text, key, reason):
    path = tmp_path / "mech.toml"
    path.write_text(textwrap.dedent(text))
    code = main(["solve", str(path), "--json"])
    out, err = capsys.readouterr()
    assert code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert str(path) in lines[0]
    if key:
        assert f": {key}: " in lines[0], lines[0]
    assert reason in lines[0]
    assert "Traceback" not in err


def test_missing_file(tmp_path, capsys):
    assert main(["solve", str(tmp_path / "nope.toml")]) == 2
    err = capsys.readouterr().err
    assert "nope.toml" in err and len(err.strip().splitlines()) == 1
