"""graphkin check answers F_34, F_14, T_12 and diagnoses the usual mistakes of Ch. 11-12."""

from __future__ import annotations

from pathlib import Path

import numpy as np

import graphkin
from graphkin.check.answers import CheckTolerance, loads_answers
from graphkin.check.diagnose import Diagnoser
from graphkin.check.exact import Evaluator
from graphkin.cli import main
from graphkin.forces import solve_forces

DATA = Path(__file__).resolve().parent.parent / "data" / "forces"


def _fmt(v) -> str:
    return f"{float(np.hypot(*v))!r} at {float(np.degrees(np.arctan2(v[1], v[0])))!r} deg"


def test_static_answers_and_mistakes(tmp_path, capsys):
    """Ex 11.1 read off a drawing: F34 = 33.09 lb, F14 = 89.0 lb, T12 = 183.3 in·lb cw."""
    f = tmp_path / "a.toml"
    f.write_text('F_34 = "33.09 lbf at 22.7 deg"\nF_14 = "89.0 lbf at 46.4 deg"\n'
                 'T_12 = "183.3 lbf*in cw"\n')
    assert main(["check", str(DATA / "ex11_1_static_fourbar.toml"), str(f)]) == 0
    f.write_text('F_43 = "33.09 lbf at 22.7 deg"\nT_12 = "183.3 lbf*in ccw"\n')
    assert main(["check", str(DATA / "ex11_1_static_fourbar.toml"), str(f)]) == 1
    out = capsys.readouterr().out
    assert "action for reaction" in out and "sense reversed: T_12 is cw" in out


def test_inertia_mistakes_are_diagnosed():
    """Ex 12.4: F_34 computed with +m A_G, or with h on the wrong side, is recognised."""
    mech = graphkin.load(DATA / "ex12_4_dynamic_fourbar.toml")
    sol = mech.solve()
    diag = Diagnoser(Evaluator(sol))
    for mistake, words in (("not-reversed", "not reversed"), ("h-side", "wrong side")):
        wrong = solve_forces(sol, mistake=mistake)
        ans = loads_answers(f'F_34 = "{_fmt(wrong.force(3, 4))}"', mech)
        found = diag.diagnose(ans.given[0], CheckTolerance())
        assert found is not None and words in found.text, (mistake, found)
