"""``graphkin solve``: the textbook-style report, the JSON contract and the steps."""

from __future__ import annotations

import json

from spec_data import EXAMPLES

from graphkin.cli import main


def test_text_report_reads_like_the_book(capsys):
    assert main(["solve", str(EXAMPLES / "ex3_1_fourbar.toml")]) == 0
    out = capsys.readouterr().out
    # expected.toml: θ3 = 20.91871° (book 20.92), ω3 = 25.38276 ccw, α4 = 1819.361 cw
    assert "θ3 = 20.9187°" in out
    assert "ω3 = 25.3828 rad/s ccw" in out
    assert "α4 = 1819.36 rad/s² cw" in out
    assert "V_E = " in out and "∠165.25°" in out  # book: 27.6 ft/s at 165.3°


def test_json_has_the_contract_keys_and_no_nan(capsys):
    assert main(["solve", str(EXAMPLES / "ex4_14_inflection_bresse.toml"), "--json"]) == 0
    text = capsys.readouterr().out
    assert "NaN" not in text and "Infinity" not in text
    data = json.loads(text)
    # the JSON format's three keys, then the unit of each quantity (issue 13: JSON has units)
    assert data["units"] == {"length": "in", "time": "s", "angle": "deg", "position": "in",
                             "velocity": "in/s", "acceleration": "in/s^2", "omega": "rad/s",
                             "alpha": "rad/s^2"}
    for key in ("links", "points", "instant_centers", "curvature", "paths"):
        assert key in data
    assert set(data["links"]) == {"1", "2", "3", "4"}
    assert set(data["instant_centers"]) == {"1-2", "1-3", "1-4", "2-3", "2-4", "3-4"}


def test_steps_list_every_construction_with_marked_equations(capsys):
    assert main(["solve", str(EXAMPLES / "ex3_1_fourbar.toml"), "--json", "--steps"]) == 0
    data = json.loads(capsys.readouterr().out)
    cons = data["constructions"]
    assert list(cons)[:3] == ["posture", "velocity", "acceleration"]
    assert "instant centers" in cons and "curvature of link 3" in cons
    # the case-4 step that finds C has two unknown directions (Table 2.2)
    (c,) = [s for s in cons["posture"] if s["label"] == "C"]
    assert c["equation"]["case"] == 4 and c["equation"]["text"].count("?") == 2
    assert c["branch"] == "left"
    # the velocity image of C: a case-3 meet with two unknown magnitudes
    (vc,) = [s for s in cons["velocity"] if s["label"] == "v(C)"]
    assert vc["op"] == "meet" and vc["equation"]["text"].count("?") == 2


def test_text_report_prints_round_off_as_zero(capsys):
    # Example 3.2 is driven by its slider C at a constant speed (the file gives
    # acceleration = 0), so A_C = 0 exactly; the construction leaves ~1e-10 mm/s² of
    # round-off, which must print as 0 (and so the same on every machine)
    assert main(["solve", str(EXAMPLES / "ex3_2_slider_driven.toml")]) == 0
    out = capsys.readouterr().out
    assert "A_C = 0 mm/s²" in out
    assert "e-1" not in out  # no 1e-10-sized leftovers anywhere in the report
