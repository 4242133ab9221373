"""Units in the report: the JSON ``units`` object, ``solve --units`` and the sweep CSV's units.

Oracles: the conversions 1 ft = 12 in and 1 rev/min = 2π/60 rad/s applied to
the default report (whose values the other tests check against the analytic
solver and the book), and the book itself: Example 3.1 gives V_E = 27.8 ft/s
at 165.3° for a four-bar drawn in inches (Uicker, Pennock & Shigley, 5th ed.,
Sec. 3.4).
"""

from __future__ import annotations

import csv
import io
import json
import math

import pytest
from spec_data import EXAMPLES

from graphkin.cli import main

FOURBAR = str(EXAMPLES / "ex3_1_fourbar.toml")


def _json(capsys, *extra):
    assert main(["solve", FOURBAR, "--json", *extra]) == 0
    return json.loads(capsys.readouterr().out)


def test_default_json_states_every_unit(capsys):
    units = _json(capsys)["units"]
    assert units == {"length": "in", "time": "s", "angle": "deg", "position": "in",
                     "velocity": "in/s", "acceleration": "in/s^2", "omega": "rad/s",
                     "alpha": "rad/s^2"}


def test_feet_as_the_book_reports_example_3_1(capsys):
    base = _json(capsys)
    ft = _json(capsys, "--units", "ft, ft/s, ft/s^2")
    assert ft["units"]["length"] == "ft" and ft["units"]["velocity"] == "ft/s"
    assert ft["units"]["acceleration"] == "ft/s^2"
    vx, vy = ft["points"]["E"]["velocity"]
    assert math.hypot(vx, vy) == pytest.approx(27.8, abs=0.05)  # book: 27.8 ft/s
    assert math.degrees(math.atan2(vy, vx)) == pytest.approx(165.3, abs=0.1)  # book: 165.3°
    for name, p in base["points"].items():
        for key in ("position", "velocity", "acceleration"):
            assert ft["points"][name][key] == pytest.approx([c / 12 for c in p[key]],
                                                            rel=1e-12, abs=1e-12)
    for lid, link in base["links"].items():  # angles and angular rates do not change
        assert ft["links"][lid] == pytest.approx(link, rel=1e-12, abs=1e-12)
    for pair, c in base["instant_centers"].items():
        if "position" in c:
            assert ft["instant_centers"][pair]["position"] == pytest.approx(
                [x / 12 for x in c["position"]], rel=1e-12, abs=1e-12)
    assert ft["paths"]["C"]["radius_of_curvature"] == pytest.approx(
        base["paths"]["C"]["radius_of_curvature"] / 12, rel=1e-12)


def test_a_length_alone_sets_velocity_and_acceleration(capsys):
    units = _json(capsys, "--units", "ft")["units"]
    assert (units["length"], units["velocity"], units["acceleration"]) == \
        ("ft", "ft/s", "ft/s^2")


def test_angular_velocity_in_rev_per_min(capsys):
    data = _json(capsys, "--units", "rev/min")
    assert data["units"]["omega"] == "rev/min" and data["units"]["length"] == "in"
    assert data["links"]["2"]["omega"] == pytest.approx(900.0, rel=1e-12)  # the file's 900 rev/min


def test_text_report_in_feet(capsys):
    assert main(["solve", FOURBAR, "--units", "ft"]) == 0
    out = capsys.readouterr().out
    assert "V_E = 27.77" in out and "ft/s ∠165.25°" in out and "ft/s²" in out


@pytest.mark.parametrize("spec, words", [
    ("flurbs", "unknown unit"),
    ("deg", "not a length, velocity"),
    ("ft, m", "two units for the length"),
])
def test_bad_units_are_one_line_and_exit_2(capsys, spec, words):
    assert main(["solve", FOURBAR, "--units", spec]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "--units" in err and words in err


def test_sweep_units_row_and_conversion(capsys):
    assert main(["sweep", FOURBAR, "--count", "4"]) == 0
    plain = list(csv.reader(io.StringIO(capsys.readouterr().out)))
    assert main(["sweep", FOURBAR, "--count", "4", "--units", "ft", "--units-row"]) == 0
    rows = list(csv.reader(io.StringIO(capsys.readouterr().out)))
    assert rows[0] == plain[0]  # the column names of docs/formats/sweep-csv.md are unchanged
    unit = dict(zip(rows[0], rows[1]))
    assert (unit["drive"], unit["angle_3"], unit["omega_3"], unit["alpha_3"]) == \
        ("deg", "deg", "rad/s", "rad/s^2")
    assert (unit["x_E"], unit["vx_E"], unit["ay_E"]) == ("ft", "ft/s", "ft/s^2")
    # each table is written rounded at 1e-12 of its quantity's scale (the largest |value|
    # of all its columns, sweep-csv.md), so the two agree to 2e-12 of that scale
    scale: dict[str, float] = {}
    for row in rows[2:]:
        for name, g in zip(rows[0], row):
            if g:
                scale[unit[name]] = max(scale.get(unit[name], 0.0), abs(float(g)))
    for got, want in zip(rows[2:], plain[1:]):
        for name, g, w in zip(rows[0], got, want):
            if not w:
                assert not g
            elif unit[name] in ("ft", "ft/s", "ft/s^2"):
                assert float(g) == pytest.approx(float(w) / 12, rel=0,
                                                 abs=2e-12 * scale[unit[name]])
            else:
                assert g == w


def test_sweep_torque_follows_the_length_unit(tmp_path):
    # Example 11.1: T12 = 184.98 lbf*in cw at the file's posture (forces.md's example); a
    # torque is force x length, so in a foot report it is the same number / 12 in lbf*ft
    from pathlib import Path

    data = Path(__file__).resolve().parent / "data" / "forces" / "ex11_1_static_fourbar.toml"
    rows = {}
    for units in (None, "ft"):
        out = tmp_path / f"{units}.csv"
        args = ["sweep", str(data), "--count", "4", "--torque", "--csv", str(out), "--units-row"]
        if units:
            args += ["--units", units]
        assert main(args) == 0
        rows[units] = list(csv.reader(out.open(encoding="utf-8")))
    head, unit_row, first = rows[None][0], rows[None][1], rows[None][2]
    k = head.index("torque_2")
    assert unit_row[k] == "lbf*in" and rows["ft"][1][k] == "lbf*ft"
    assert float(first[k]) == pytest.approx(-184.98, abs=0.01)
    assert float(rows["ft"][2][k]) == pytest.approx(float(first[k]) / 12, rel=1e-12)
