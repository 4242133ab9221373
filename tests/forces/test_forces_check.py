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


def _torque_by_power(sol, sf: float, st: float) -> float:
    """T_12 from the power balance alone (Sec. 11.11): T_12 ω2 + Σ F·V + Σ T·ω = 0.

    Each inertia force is taken as ``sf m A_G`` at G with the couple ``st I_G α``
    (``sf = st = -1`` is d'Alembert's; ``+1, +1`` the force not reversed; ``-1, +1``
    h on the wrong side).  No joint force and no graphic step enters.
    """
    mech = sol.mechanism
    power = 0.0
    for ld in mech.loads:
        power += float(np.asarray(ld.force) @ sol.velocity(ld.point, ld.link))
    for lid, inr in mech.inertia.items():
        f = sf * inr.mass * np.asarray(sol.acceleration(inr.center, lid))
        power += float(f @ sol.velocity(inr.center, lid))
        power += st * inr.moment * float(sol.alpha(lid)) * float(sol.omega(lid))
    return -power / float(sol.omega(2))


def test_torque_mistakes_diagnosed_against_the_power_balance():
    """Ex 12.4: a T_12 worked with +m A_G (or h on the wrong side) is named as that mistake.

    The wrong answers are derived here from the power balance, independently of the
    force construction and of the matrix method the diagnoser uses.
    """
    mech = graphkin.load(DATA / "ex12_4_dynamic_fourbar.toml")
    sol = mech.solve()
    right = _torque_by_power(sol, -1.0, -1.0)
    assert abs(right - solve_forces(sol).torque(2)) <= 1e-9 * abs(right)
    diag = Diagnoser(Evaluator(sol))
    for (sf, st), words in (((1.0, 1.0), "not reversed"), ((-1.0, 1.0), "wrong side")):
        wrong = _torque_by_power(sol, sf, st)
        assert abs(wrong - right) > 1e-3 * abs(right)  # the mistake changes the answer
        sense = "ccw" if wrong > 0 else "cw"
        ans = loads_answers(f'T_12 = "{abs(wrong)!r} N*mm {sense}"', mech)
        found = diag.diagnose(ans.given[0], CheckTolerance())
        assert found is not None and words in found.text, (words, found)


def test_reaction_and_torque_sense_in_the_report(tmp_path, capsys):
    """Ex 11.1 by hand: F_43 = -F_34 given for F_34, and T_12 with its sense reversed.

    F_34 read off the book's polygon (Fig. 11.5f): 33.09 lb at 22.7°, so F_43 is
    33.09 lb at 202.7°; T_12 = 183.3 in·lb cw (Ex 11.1 step 7).
    """
    f = tmp_path / "a.toml"
    f.write_text('F_34 = "33.09 lbf at 202.7 deg"\nT_12 = "183.3 lbf*in ccw"\n')
    assert main(["check", str(DATA / "ex11_1_static_fourbar.toml"), str(f)]) == 1
    out = capsys.readouterr().out
    assert "action for reaction: F_43 given for F_34" in out
    assert "sense reversed: T_12 is cw" in out
