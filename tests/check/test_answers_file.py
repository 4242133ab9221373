"""Reading answers files: keys, values, units; malformed files exit 2 with one line."""

from __future__ import annotations

import math
from pathlib import Path

import pytest
from spec_data import inline

import graphkin
from graphkin.check import loads_answers, parse_key
from graphkin.cli import main
from graphkin.errors import InputError

FOURBAR = inline("answers_file-fourbar.toml")


@pytest.fixture
def mech() -> graphkin.Mechanism:
    return graphkin.loads(FOURBAR)


@pytest.mark.parametrize(("key", "kind", "args"), [
    ("theta3", "theta", ("3",)), ("θ3", "theta", ("3",)), ("omega4", "omega", ("4",)),
    ("ω2", "omega", ("2",)), ("alpha3", "alpha", ("3",)), ("V_E", "V", ("E",)),
    ("V_CB", "V", ("C", "B")), ("V_C-B", "V", ("C", "B")), ("A_CB", "A", ("C", "B")),
    ("A_CB^n", "An", ("C", "B")), ("A_CB^t", "At", ("C", "B")), ("A_CB_n", "An", ("C", "B")),
    ("I13", "I", ("1", "3")), ("I31", "I", ("1", "3")), ("I2-4", "I", ("2", "4")),
    ("rho_E", "rho", ("E",)), ("R_CB", "R", ("C", "B")), ("A_C^c", "Ac", ("C",)),
])
def test_keys(mech: graphkin.Mechanism, key: str, kind: str, args: tuple[str, ...]) -> None:
    k = parse_key(key, mech)
    assert (k.kind, k.args) == (kind, args)


@pytest.mark.parametrize("key", ["omega9", "V_Q", "V_CQ", "I11", "I19", "speed", "rho_Z",
                                 "A_E^n"])
def test_bad_keys(mech: graphkin.Mechanism, key: str) -> None:
    with pytest.raises(InputError) as e:
        parse_key(key, mech)
    assert e.value.key == key


def test_values_and_units(mech: graphkin.Mechanism) -> None:
    ans = loads_answers("""
omega3 = "25.6 rad/s ccw"
omega4 = -49.6
alpha3 = 113
V_E = "27.6 ft/s at 165.3 deg"
V_B = [-326.5, -188.5]
A_E = "2580 ft/s^2"
I13 = ["5.4 in", "-9.4 in"]
I24 = [-11.06, 0]
rho_E = "110 mm"
theta3 = "20.9°"
""", mech)
    g = {x.key.text: x for x in ans.given}
    assert g["omega3"].value == pytest.approx(25.6) and g["omega3"].signed
    assert g["omega4"].value == -49.6 and g["omega4"].signed       # a minus sign is cw
    assert g["alpha3"].value == 113 and g["alpha3"].signed         # a number is signed (ccw +)
    assert g["V_E"].value == pytest.approx(27.6 * 12) and g["V_E"].direction == 165.3
    assert g["V_E"].unit == "ft/s" and g["V_E"].factor == pytest.approx(12)
    assert g["V_B"].direction == pytest.approx(math.degrees(math.atan2(-188.5, -326.5)))
    assert g["A_E"].value == pytest.approx(2580 * 12) and g["A_E"].direction is None
    assert list(g["I13"].point) == pytest.approx([5.4, -9.4])
    assert g["rho_E"].value == pytest.approx(110 / 25.4)
    assert g["theta3"].value == pytest.approx(20.9)


def _run(tmp_path: Path, examples: Path, text: str, capsys: pytest.CaptureFixture[str]
         ) -> tuple[int, str, str]:
    f = tmp_path / "answers.toml"
    f.write_text(text, encoding="utf-8")
    code = main(["check", str(examples / "ex3_1_fourbar.toml"), str(f)])
    out, err = capsys.readouterr()
    return code, out, err


@pytest.mark.parametrize(("text", "words"), [
    ("omega3 = ", "not valid TOML"),
    ("omega3 = \"25 furlongs\"", "omega3"),
    ("V_Q = 3", "V_Q"),
    ("speed = 3", "unknown answer key"),
    ("omega3 = true", "omega3"),
    ("I13 = [1, 2, 3]", "I13"),
    ("I13 = \"somewhere\"", "I13"),
    ("tolerance = { relative = -1 }", "tolerance.relative"),
    ("tolerance = { percent = 2 }", "tolerance.percent"),
    # audit9: a sense on a vector or a length was dropped without a word (marked on its size)
    ("V_E = \"27.6 ft/s cw\"", "V_E: '27.6 ft/s cw': cw/ccw is the sense of an ω or α"),
    ("A_CB = { magnitude = \"2580 ft/s^2 ccw\" }", "A_CB: '2580 ft/s^2 ccw': cw/ccw"),
    ("rho_E = \"4.3 in cw\"", "rho_E: '4.3 in cw': cw/ccw"),
    ("student = \"x\"", "no answers"),
    ("[V_E]\nx = 1", "V_E"),
])
def test_malformed_answers_exit_2_with_one_line(tmp_path: Path, examples: Path, text: str,
                                                words: str,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = _run(tmp_path, examples, text, capsys)
    assert code == 2
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "answers.toml" in lines[0] and words in lines[0]
    assert "Traceback" not in err


def test_missing_answers_file_exits_2(examples: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", str(examples / "ex3_1_fourbar.toml"), "/nonexistent/a.toml"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and "a.toml" in err


def test_rates_needed(tmp_path: Path, examples: Path, capsys: pytest.CaptureFixture[str]) -> None:
    f = tmp_path / "a.toml"
    f.write_text("omega3 = 2\n")
    assert main(["check", str(examples / "ex2_5_open.toml"), str(f)]) == 2
    assert "no rates" in capsys.readouterr().err


# ---- a class of forty: one bad entry costs one answer -----------------------------------

@pytest.mark.parametrize(("text", "key", "words"), [
    # Example 3.1: ω3 = 25.38 rad/s ccw (analytic), so omega3 is right and marked
    ('V_X = 3\nomega3 = "25.4 rad/s ccw"', "V_X", "did you mean"),
    ('tolerance = { percent = 2 }\nomega3 = "25.4 rad/s ccw"', "tolerance.percent",
     "valid: relative, angle, drawing, scale"),
    ('tolerance = { relative = -1 }\nomega3 = "25.4 rad/s ccw"', "tolerance.relative",
     "positive"),
    # audit9: relative = 2 meant 2 %; read as 200 % it passed every answer of the right sign
    ('tolerance = { relative = 2 }\nomega3 = "25.4 rad/s ccw"', "tolerance.relative",
     "2 is 200 %: a relative tolerance is a fraction below 1"),
    ('tolerance = { relative = "150 %" }\nomega3 = "25.4 rad/s ccw"', "tolerance.relative",
     "is 150 %"),
    ('omgea3 = 2\nomega3 = "25.4 rad/s ccw"', "omgea3", "did you mean 'omega3'"),
])
def test_bad_entry_is_reported_and_the_rest_marked(tmp_path: Path, examples: Path, text: str,
                                                   key: str, words: str,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = _run(tmp_path, examples, text, capsys)
    assert code == 2                                   # answers.md: 2 = unreadable
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "answers.toml" in lines[0] and key in lines[0]
    assert words in lines[0]
    assert "Traceback" not in err
    row = next(line for line in out.splitlines() if line.startswith("omega3"))
    assert " ok " in row                               # the rest is still marked
    assert "UNREADABLE" in out and "1 unreadable" in out


def test_invalid_toml_in_a_class_gives_a_row_with_the_student(tmp_path: Path, examples: Path,
                                                               capsys: pytest.CaptureFixture[str]
                                                               ) -> None:
    import csv
    import io

    bad = tmp_path / "bad.toml"
    bad.write_text('student = "B. Student"\nω3 = 25.4\n', encoding="utf-8")  # unquoted ω
    good = tmp_path / "good.toml"
    good.write_text('student = "C. Student"\nomega3 = 25.4\n', encoding="utf-8")
    code = main(["check", str(examples / "ex3_1_fourbar.toml"), str(bad), str(good), "--csv",
                 "-", "--quiet"])
    out = capsys.readouterr().out
    assert code == 2
    rows = list(csv.DictReader(io.StringIO(out[out.index("file,"):])))
    assert rows[0]["student"] == "B. Student" and rows[0]["status"] == "unreadable"
    assert "not valid TOML" in rows[0]["summary"]
    assert rows[1]["student"] == "C. Student" and rows[1]["status"] == "ok"
