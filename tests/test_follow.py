"""``sweep --follow``: the motion kept continuous where the named branch turns back (issue 25).

examples/fivebar_stretched.toml: a five-bar with θ3 = θ2 + 180°, |AB| = 5,
|BC| = 7.5; A = 2.5 e(θ2), C = (6, 0) − 4 e(θ2), so |AC| = |(6, 0) − 6.5 e(θ2)|
reaches 12.5 = |AB| + |BC| at θ2 = 180°: links 4 and 5 in line.  The angle β
at A between A→C and A→B, cos β = (5² + d² − 7.5²)/(2·5·d), vanishes there
like |θ2 − 180°| (d has a maximum, 12.5 − d is quadratic, β its square root),
so the smooth motion has β change sign: B left of A→C before 180°, right of it
after.  The named branch keeps B left and turns back; the followed sweep is held
to θ4 = atan2(C − A) ± β on both sides.  The five-bar of Fig. 5.5 with θ3 =
3 θ2 − 315° (examples/fivebar_coupled.toml), which passes no such posture, is
followed at fine steps without a change and agrees with graphkin's Newton
solver of the loop equations at every posture of the turn.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.cli import main

ROOT = Path(__file__).resolve().parents[1]
FILE = ROOT / "examples" / "fivebar_coupled.toml"
STRETCHED = ROOT / "examples" / "fivebar_stretched.toml"


def _theta4(t2: np.ndarray) -> np.ndarray:
    """θ4 of the smooth motion through the stretched posture (degrees), by hand."""
    a = np.stack([2.5 * np.cos(t2), 2.5 * np.sin(t2)], -1)
    c = np.stack([6 - 4 * np.cos(t2), -4 * np.sin(t2)], -1)
    d = np.hypot(*(c - a).T)
    beta = np.arccos(np.clip((25 + d**2 - 56.25) / (10 * d), -1.0, 1.0))
    sigma = np.where(np.degrees(t2) < 180.0, 1.0, -1.0)   # left before the stretch, right after
    return np.degrees(np.arctan2(c[:, 1] - a[:, 1], c[:, 0] - a[:, 0]) + sigma * beta)


def _same(a: np.ndarray, b: np.ndarray, tol: float) -> bool:
    return bool(np.all(np.abs((a - b + 180.0) % 360.0 - 180.0) <= tol))


def test_through_the_stretched_posture_the_motion_goes_on() -> None:
    mech = graphkin.load(STRETCHED)
    sw = mech.sweep(count=360, follow=True)
    t2 = np.asarray(sw.columns["drive"], dtype=float)
    run = (t2 < 337.0) & np.asarray(sw.assembled, dtype=bool)   # up to where it cannot assemble
    assert run.sum() > 200
    # d² is quadratic near its maximum: β = √(…) loses half the digits there (1e-8 → 1e-4°)
    near = np.abs(t2 - 180.0) < 0.5
    got = np.asarray(sw.columns["angle_4"], dtype=float)
    want = _theta4(np.radians(t2))
    assert _same(got[run & ~near], want[run & ~near], 1e-7)
    assert _same(got[run & near], want[run & near], 1e-3)
    notes = [n for n in sw.notes if n.startswith("--follow")]
    assert len(notes) == 1 and "between drive 180.00° and 181.00°" in notes[0] \
        and "B from LEFT to RIGHT" in notes[0], sw.notes
    # the named branch turns back at the stretch: θ4 after it is the mirror of θ4 before
    plain = mech.sweep(count=360)
    k = int(np.flatnonzero(t2 == 190.0)[0])
    assert not _same(np.asarray(plain.columns["angle_4"])[k:k + 1], want[k:k + 1], 1.0)


def test_coupled_five_bar_followed_is_the_newton_motion() -> None:
    from graphkin.kinematics.analytic import solve_analytic_many

    mech = graphkin.load(FILE)
    sw = mech.sweep(count=360, follow=True)
    assert not [n for n in sw.notes if n.startswith("--follow")]  # no branch change here
    t2 = np.radians(np.asarray(sw.columns["drive"], dtype=float))
    sol = solve_analytic_many(mech, np.stack([t2, 3 * t2 - math.radians(315)], -1))
    ok = np.asarray(sol.valid, dtype=bool) & np.asarray(sw.assembled, dtype=bool)
    assert ok.all()
    for p in ("B", "P"):
        xy = np.stack([sw.columns[f"x_{p}"], sw.columns[f"y_{p}"]], -1)
        assert np.allclose(xy, np.asarray(sol.position(p)), atol=1e-8), p
    for lid in ("4", "5"):
        assert np.allclose(sw.columns[f"omega_{lid}"], np.asarray(sol.omega(lid)),
                           rtol=1e-6, atol=1e-6), lid


def test_the_followed_solution_is_what_torque_and_plots_read() -> None:
    mech = graphkin.load(STRETCHED)
    sw = mech.sweep(count=72, follow=True)
    good = np.asarray(sw.assembled, dtype=bool)
    b = np.asarray(sw.solution.position("B"))
    assert np.allclose(b[good], np.stack([sw.columns["x_B"], sw.columns["y_B"]], -1)[good])


def test_cli_says_where_the_branch_changes(capsys: pytest.CaptureFixture[str],
                                           tmp_path: Path) -> None:
    assert main(["sweep", str(STRETCHED), "--count", "72", "--follow", "--csv",
                 str(tmp_path / "f.csv")]) == 0
    err = capsys.readouterr().err
    assert "--follow: the motion goes on along the other branch between drive 180.00° and " \
           "185.00° (B from LEFT to RIGHT)" in err
    assert main(["plot", str(STRETCHED), "--count", "72", "--follow", "--what", "angle", "-o",
                 str(tmp_path / "p.svg")]) == 0


def test_a_mechanism_without_a_branch_change_is_unchanged() -> None:
    mech = graphkin.examples.crank_rocker()
    a = mech.sweep(count=36)
    b = mech.sweep(count=36, follow=True)
    for k, v in a.columns.items():
        assert np.array_equal(np.asarray(v), np.asarray(b.columns[k]), equal_nan=True), k
    assert not [n for n in b.notes if n.startswith("--follow")]
