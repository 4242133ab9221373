"""The drive's torque over a sweep: the construction replayed on arrays, checked posture by
posture against the matrix method."""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.cli import main
from graphkin.forces import solve_forces
from graphkin.forces.sweep import force_columns

DATA = Path(__file__).resolve().parent.parent / "data" / "forces"


@pytest.mark.parametrize("fname", ["ex11_1_static_fourbar.toml", "ex12_4_dynamic_fourbar.toml"])
def test_torque_column_matches_matrix_method(fname):
    mech = graphkin.load(DATA / fname)
    start = math.degrees(mech.drives[0].value)
    sw = mech.sweep(count=6, start=start - 30, stop=start + 30)
    cols = force_columns(sw, joints=True)
    sol = sw.solution
    for k, deg in enumerate(sw.columns["drive"]):
        d = dataclasses.replace(mech.drives[0], value=math.radians(deg))
        hint = {"B": tuple(float(v) for v in sol.position("B")[k])}
        one = dataclasses.replace(mech, drives=(d,), assembly=hint).solve()
        ref = solve_forces(one, method="analytic")
        assert cols["torque_2"][k] == pytest.approx(ref.torque(2), rel=1e-9, abs=1e-9)
        assert cols["F_3-4"][k] == pytest.approx(float(np.hypot(*ref.force(3, 4))), rel=1e-9)


def test_sweep_cli_and_plot(tmp_path, capsys):
    f = DATA / "ex11_1_static_fourbar.toml"
    assert main(["sweep", str(f), "--count", "4", "--torque"]) == 0
    head = capsys.readouterr().out.splitlines()[0].split(",")
    assert "torque_2" in head
    out = tmp_path / "t.svg"
    assert main(["plot", str(f), "--what", "torque", "--count", "12", "-o", str(out)]) == 0
    assert 'id="curve-torque_2"' in out.read_text()


def test_no_forces_no_columns():
    from graphkin.errors import InputError

    with pytest.raises(InputError):
        force_columns(graphkin.examples.fourbar().sweep(count=4))
