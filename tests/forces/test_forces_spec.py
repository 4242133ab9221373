"""The forces examples (docs/forces.md) give the values of their expected.toml.

``tests/data/forces/`` holds the project's copies of Examples 11.1 and 12.4 with
their expected values (derived independently: see the comments in expected.toml).
"""

from __future__ import annotations

import json
import tomllib
from pathlib import Path

import pytest
from spec_data import assert_expected, lookup, solved_json

import graphkin
from graphkin.cli import main
from graphkin.output import solution_to_dict

DATA = Path(__file__).resolve().parent.parent / "data" / "forces"
with open(DATA / "expected.toml", "rb") as _fh:
    EXPECTED = tomllib.load(_fh)
CASES = [(f, k, v) for f, checks in EXPECTED.items() for k, v in checks.items()]


@pytest.mark.parametrize("fname,key,want", CASES, ids=[f"{f}:{k}" for f, k, _ in CASES])
def test_forces_spec_value(fname, key, want):
    assert_expected(lookup(solved_json(DATA / fname), key), want, key)


def test_forces_units_and_absence(capsys):
    """``forces.units`` names force and torque units; no forces object without loads."""
    data = solved_json(DATA / "ex11_1_static_fourbar.toml")
    assert data["forces"]["units"] == {"force": "lbf", "torque": "lbf*in"}
    data = solved_json(DATA / "ex12_4_dynamic_fourbar.toml")
    assert data["forces"]["units"] == {"force": "N", "torque": "N*mm"}
    plain = solution_to_dict(graphkin.examples.fourbar().solve())
    assert "forces" not in plain


def test_cli_json_and_text(capsys):
    assert main(["solve", str(DATA / "ex11_1_static_fourbar.toml"), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert set(out["forces"]["joints"]) == {"1-2", "2-3", "3-4", "1-4"}
    assert main(["solve", str(DATA / "ex11_1_static_fourbar.toml")]) == 0
    text = capsys.readouterr().out
    # Ex 11.1: F34 = 33.33 lb (analytic), link 3 in compression, T12 cw
    assert "F₃₄ = 33.33 lbf ∠22.66°" in text
    assert "link 3 is a two-force member in compression" in text
    assert "T₁₂ = 184.980 lbf·in cw" in text
