"""The gear file (docs/formats/gears.md): every mistake is one line naming file and key, exit 2."""

from __future__ import annotations

import json
import re
import textwrap

import pytest

from graphkin.cli import main

PAIR = """\
units = "in"
diametral_pitch = 10
pressure_angle = 20
[gears.pinion]
teeth = 20
[gears.gear]
teeth = 50
"""

CASES = [
    ("non-integer teeth", PAIR.replace("teeth = 20", "teeth = 20.5"), "gears.pinion.teeth",
     "whole number"),
    ("teeth as text", PAIR.replace("teeth = 20", 'teeth = "20"'), "gears.pinion.teeth",
     "whole number"),
    ("teeth as bool", PAIR.replace("teeth = 20", "teeth = true"), "gears.pinion.teeth",
     "whole number"),
    ("too few teeth", PAIR.replace("teeth = 20", "teeth = 2"), "gears.pinion.teeth", "from 3"),
    ("no teeth", PAIR.replace("teeth = 20\n", ""), "gears.pinion.teeth", "missing"),
    ("pressure angle 90", PAIR.replace("pressure_angle = 20", "pressure_angle = 90"),
     "pressure_angle", "between 0° and 90°"),
    ("pressure angle 0", PAIR.replace("pressure_angle = 20", "pressure_angle = 0"),
     "pressure_angle", "between 0° and 90°"),
    ("pressure angle in rad", PAIR.replace("pressure_angle = 20", 'pressure_angle = "2 rad"'),
     "pressure_angle", "between 0° and 90°"),
    ("pressure angle nan", PAIR.replace("pressure_angle = 20", "pressure_angle = nan"),
     "pressure_angle", "finite"),
    ("no pressure angle", PAIR.replace("pressure_angle = 20\n", ""), "pressure_angle",
     "missing"),
    ("unknown key", PAIR.replace("teeth = 50", "teeht = 50"), "gears.gear.teeht",
     "did you mean 'teeth'"),
    ("unknown top key", PAIR.replace("units", "unit"), "unit", "did you mean 'units'"),
    ("different pitches", PAIR.replace("teeth = 50", "teeth = 50\ndiametral_pitch = 8"),
     "gears.gear", "cannot mesh"),
    ("different pressure angles", PAIR.replace("teeth = 50", "teeth = 50\npressure_angle = 25"),
     "gears.gear", "cannot mesh"),
    ("center distance too small", PAIR.replace("units", "center_distance = 3.4\nunits"),
     "center_distance", "jam"),
    ("center distance too large", PAIR.replace("units", "center_distance = 4.0\nunits"),
     "center_distance", "do not reach"),
    ("negative center distance", PAIR.replace("units", "center_distance = -3.5\nunits"),
     "center_distance", "positive"),
    ("one gear", PAIR[: PAIR.index("[gears.gear]")], "gears", "two gears"),
    ("module and pitch", PAIR.replace("units", 'module = "2 mm"\nunits'), "diametral_pitch",
     "not both"),
    ("no size", PAIR.replace("diametral_pitch = 10\n", ""), "module", "missing"),
    ("bad pitch text", PAIR.replace("diametral_pitch = 10", 'diametral_pitch = "ten"'),
     "diametral_pitch", "teeth per length"),
    ("unknown system", PAIR.replace("units", 'system = "fine"\nunits'), "system",
     "tooth system"),
    ("bad unit", PAIR.replace('units = "in"', 'units = "bananas"'), "units.length", "unit"),
    ("bad toml", PAIR + "[[[", "", "TOML"),
    ("module too small", PAIR.replace("diametral_pitch = 10", "module = 1e-300"), "module",
     "too small"),
]


@pytest.mark.parametrize("name,text,key,reason", CASES, ids=[c[0] for c in CASES])
def test_bad_gear_file_exits_2_with_one_line(tmp_path, capsys, name, text, key, reason):
    path = tmp_path / "pair.toml"
    path.write_text(textwrap.dedent(text))
    code = main(["gears", str(path)])
    out, err = capsys.readouterr()
    assert code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1, err
    assert str(path) in lines[0]
    if key:
        assert f": {key}: " in lines[0], lines[0]
    assert reason in lines[0], lines[0]


def test_units_on_values(tmp_path, capsys):
    """Lengths and pitches may carry units: a module in mm read in a file in inches."""
    path = tmp_path / "pair.toml"
    path.write_text(PAIR.replace("diametral_pitch = 10", 'diametral_pitch = "10 teeth/in"')
                    .replace('units = "in"', 'units = "mm"'))
    assert main(["gears", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    # P = 10 teeth/in is m = 2.54 mm: R2 = 20 · 2.54 / 2 = 25.4 mm
    assert data["gears"]["pinion"]["pitch_radius"] == pytest.approx(25.4)
    assert data["units"]["length"] == "mm"


def test_report_with_units(gear_examples, capsys):
    assert main(["gears", str(gear_examples / "ex7_1.toml")]) == 0
    out = capsys.readouterr().out
    assert re.search(r"contact ratio CD/p_b, construction +1\.65576", out)
    assert "pitch radius R" in out and " in\n" in out
    assert "No interference" in out


def test_json_and_steps(gear_examples, capsys):
    assert main(["gears", str(gear_examples / "fig7_18.toml"), "--json", "--steps"]) == 0
    text = capsys.readouterr().out
    data = json.loads(text)
    assert data["mesh"]["interference"] is True
    assert data["mesh"]["contact_ratio"] == pytest.approx(data["mesh"]["contact_ratio_eq_7_9"],
                                                          rel=1e-9)
    labels = [s["label"] for s in data["construction"]]
    assert labels.index("A") < labels.index("C") and "D" in labels
    assert "NaN" not in text


def test_solve_reads_gear_files_too(gear_examples, capsys):
    """`graphkin solve` on a gear file or a train file gives the gear report (issue 26)."""
    assert main(["solve", str(gear_examples / "ex7_3.toml"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    # Example 7.3: m_c = 1.443
    assert data["mesh"]["contact_ratio"] == pytest.approx(1.443, abs=1e-3)
    assert main(["solve", str(gear_examples / "trains" / "ex7_9.toml")]) == 0
    assert "350 rev/min ccw" in capsys.readouterr().out   # Example 7.9
    assert main(["solve", str(gear_examples / "ex7_1.toml"), "--units", "mm"]) == 2
    assert "--units" in capsys.readouterr().err
