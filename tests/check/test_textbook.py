"""The textbook's own graphic answers pass; planted mistakes are caught and named.

Book values are from Uicker, Pennock & Shigley, 5th ed. (the reference text
has no page numbers; line numbers are of shared/reference/uicker-theory-of-machines-5e.md):

* Example 3.1 (line 3154), graphic solution: V_CB = 38.4 ft/s, V_C = 45.5 ft/s
  (line 3178), ω3 = 25.6 rad/s ccw (Ans. (4), line 3180), ω4 = 49.64 rad/s ccw
  (Ans. (5), line 3182), V_E = 27.6 ft/s ∠165.3° (line 3196), V_F = 31.8 ft/s
  ∠130.9° (line 3218).
* Example 4.2 (line 5192): α3 = 113 rad/s² ccw (line 5224), α4 = 1822 rad/s² cw
  (line 5230), A_E = 2580 ft/s² (line 5240), A_F = 1960 ft/s² (line 5244).
* Example 2.5 (line 2345): open θ3 = 59.46°, θ4 = 96.76°; crossed θ'3 = −57.56°,
  θ'4 = −94.86° (lines 2391-2399).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from spec_data import inline

import graphkin
from graphkin.check import check, loads_answers
from graphkin.cli import main
from graphkin.kinematics.analytic import solve_analytic

REPO = Path(__file__).resolve().parents[2]
ANSWERS = REPO / "examples" / "answers"


@pytest.fixture
def fourbar(examples: Path) -> Path:
    return examples / "ex3_1_fourbar.toml"


def _report(mech_path: Path, text: str):
    mech = graphkin.load(mech_path)
    return check(mech.solve(), loads_answers(text, mech))


def _only_row(mech_path: Path, text: str):
    rep = _report(mech_path, text)
    (row,) = rep.rows
    return row


# ---- the book's graphic answers ----------------------------------------------------

BOOK = inline("textbook-book.toml")


def test_book_answers_pass_at_default_tolerance(fourbar: Path) -> None:
    rep = _report(fourbar, BOOK)
    assert [r.verdict for r in rep.rows] == ["ok"] * 10
    assert rep.tolerance.relative == 0.02 and rep.tolerance.angle == 2.0


def test_book_answers_file_exits_0(fourbar: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", str(fourbar), str(ANSWERS / "ex3_1_book.toml")]) == 0
    out = capsys.readouterr().out
    assert "11 of 11 within tolerance" in out


def test_tighter_tolerance_fails_the_book(fourbar: Path, capsys: pytest.CaptureFixture[str],
                                          tmp_path: Path) -> None:
    # ω3: 25.6 vs the analytic 25.38 (Example 3.1's analytic solution) is 0.86 % off,
    # within 2 % but not within 0.5 %.
    f = tmp_path / "a.toml"
    f.write_text('omega3 = "25.6 rad/s ccw"\n')
    assert main(["check", str(fourbar), str(f)]) == 0
    assert main(["check", str(fourbar), str(f), "--relative", "0.5%"]) == 1
    f.write_text('tolerance = { relative = 0.005 }\nomega3 = "25.6 rad/s ccw"\n')
    assert main(["check", str(fourbar), str(f)]) == 1
    assert main(["check", str(fourbar), str(f), "--relative", "0.02"]) == 0
    capsys.readouterr()


def test_wrong_sense_and_factor_12_exit_1_and_are_named(
        fourbar: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # ω4 = 49.64 written cw (the book: ccw); V_E = 27.6 ft/s × 12 = 331 "ft/s"
    assert main(["check", str(fourbar), str(ANSWERS / "ex3_1_two_mistakes.toml")]) == 1
    out = capsys.readouterr().out
    assert "likely mistake: sense reversed: ω4 is ccw" in out
    assert "too large by a factor of 12" in out and "inches and feet" in out
    assert out.count("WRONG") == 2


# ---- each planted mistake, its value derived by hand ----------------------------------

def test_sense_reversed(fourbar: Path) -> None:
    row = _only_row(fourbar, 'alpha4 = "1822 rad/s^2 ccw"')   # book: 1822 cw
    assert row.verdict == "WRONG" and row.mistake.kind == "sense"


def test_unit_factor_rev_per_min(fourbar: Path) -> None:
    # ω3 = 25.6 rad/s written as rev/min: 25.6 rev/min = 25.6 × 2π/60 = 2.681 rad/s,
    # i.e. too small by 60/2π = 9.549.
    row = _only_row(fourbar, 'omega3 = "25.6 rev/min ccw"')
    assert row.verdict == "WRONG"
    assert row.mistake.kind == "unit" and "60/2π" in row.mistake.text


def test_unit_factor_mm(examples: Path) -> None:
    # Example 4.4: |A_A| = 3250 m/s² (Sec. 4.5); written as 3250 in a mm file (mm/s²),
    # 1000 times too small.
    row = _only_row(examples / "ex4_4_coriolis_block.toml", "A_A = 3250")
    assert row.mistake.kind == "unit" and "1000" in row.mistake.text


def test_velocity_image_flipped(fourbar: Path) -> None:
    # E is (10, -4) in link 3's frame (B at the origin, C on +x).  Flipped about bc,
    # the image gives the velocity of the mirror point E' = (10, +4):
    #   R_E'B = rot(θ3 = 20.92°)(10, 4) = (7.913, 7.307) in,
    #   ω3 × R_E'B = 25.38 k × (7.913, 7.307) = (-185.5, 200.8) in/s,
    #   V_B = ω2 k × R_BA = 94.25 k × (-2, 3.464) = (-326.5, -188.5) in/s,
    #   V_E' = (-511.9, 12.3) in/s = 42.67 ft/s at 178.6°  (the exact V_E is 27.8 ft/s).
    row = _only_row(fourbar, 'V_E = "42.67 ft/s at 178.6 deg"')
    assert row.verdict == "WRONG"
    assert row.mistake.kind == "flipped" and "link 3" in row.mistake.text
    assert "bce" in row.mistake.text


def test_normal_component_drawn_outward(fourbar: Path) -> None:
    # A_E = A_B + A_EB^n + A_EB^t with A_EB^n = -ω3² R_EB laid off away from B gives
    # A_E - 2 A_EB^n = A_E + 2 ω3² R_EB; ω3, R_EB and A_E from the analytic solver.
    mech = graphkin.load(fourbar)
    an = solve_analytic(mech)
    r_eb = an.position("E") - an.position("B")
    wrong = an.acceleration("E") + 2 * an.omega("3") ** 2 * r_eb
    mag = math.hypot(*wrong) / 12.0
    ang = math.degrees(math.atan2(wrong[1], wrong[0]))
    assert mag == pytest.approx(3217, rel=2e-3)   # by hand: 38604 in/s² at -50.2°
    row = _only_row(fourbar, f'A_E = "{mag:.1f} ft/s^2 at {ang:.2f} deg"')
    assert row.verdict == "WRONG"
    assert row.mistake.kind == "normal" and "A_EB^n" in row.mistake.text


def test_normal_component_drawn_outward_in_the_polygon(fourbar: Path) -> None:
    # Eq. (1) of Example 4.2: A_B + A_CB^n + α3 k×R_CB = A_CD^n + α4 k×R_CD.
    # With A_CD^n laid off away from D (+ω4² R_CD instead of -ω4² R_CD) the two
    # perpendiculars meet elsewhere: solve the 2×2 system for α3, α4.
    mech = graphkin.load(fourbar)
    an = solve_analytic(mech)
    R = {p: an.position(p) for p in "ABCD"}
    w2, w3, w4 = (float(an.omega(k)) for k in "234")

    def kx(v: np.ndarray) -> np.ndarray:
        return np.array([-v[1], v[0]])

    a_b = -w2**2 * (R["B"] - R["A"])
    a_cb_n = -w3**2 * (R["C"] - R["B"])
    a_cd_n_wrong = +w4**2 * (R["C"] - R["D"])
    m = np.column_stack([kx(R["C"] - R["B"]), -kx(R["C"] - R["D"])])
    alpha3, alpha4 = np.linalg.solve(m, a_cd_n_wrong - a_b - a_cb_n)
    sense = "ccw" if alpha4 > 0 else "cw"
    row = _only_row(fourbar, f'alpha4 = "{abs(alpha4):.0f} rad/s^2 {sense}"')
    assert row.verdict == "WRONG"
    assert row.mistake.kind == "normal" and "A_CD^n" in row.mistake.text


def test_difference_given_for_absolute(fourbar: Path) -> None:
    # the book measures V_CB = 38.4 ft/s and V_C = 45.5 ft/s: giving the first for V_C
    row = _only_row(fourbar, 'V_C = "38.4 ft/s"')
    assert row.verdict == "WRONG"
    assert row.mistake.kind == "relative" and "V_CB" in row.mistake.text


def test_absolute_given_for_difference(fourbar: Path) -> None:
    row = _only_row(fourbar, 'V_CB = "45.5 ft/s"')
    assert row.mistake.kind == "relative" and "V_C given" in row.mistake.text


def test_other_assembly_branch(examples: Path) -> None:
    # Example 2.5: the open posture has θ3 = 59.46°, the crossed θ'3 = -57.56°.
    rep = _report(examples / "ex2_5_open.toml", "theta3 = 59.46\ntheta4 = -94.86")
    ok, wrong = rep.rows
    assert ok.verdict == "ok"
    assert wrong.verdict == "WRONG" and wrong.mistake.kind == "branch"


# ---- Coriolis -----------------------------------------------------------------------

def test_coriolis_wrong_sense_example_4_4(examples: Path) -> None:
    # Example 4.4: ω2 = 50 rad/s ccw, R_AO2 = 0.5 m at 30°, V_A/2 = 30 m/s outward.
    #   A_A2 = ω2² R toward O2 = 1250 m/s² at 210°;  A^c = 2 ω2 V = 3000 m/s² at 120°;
    #   A_A = 3250 m/s² at 210° - atan(3000/1250) = 142.62° (the book: 3250 m/s²).
    # Coriolis reversed (at 300°): 3250 m/s² at 210° + 67.38° = 277.38°.
    mech = examples / "ex4_4_coriolis_block.toml"
    rep = _report(mech, 'A_A = "3250 m/s^2 at 142.6 deg"\n"A_A^c" = "3000 m/s^2 at 120 deg"')
    assert [r.verdict for r in rep.rows] == ["ok", "ok"]
    row = _only_row(mech, 'A_A = "3250 m/s^2 at 277.38 deg"')
    assert row.mistake.kind == "coriolis" and "wrong sense" in row.mistake.text
    row = _only_row(mech, 'A_A = "1250 m/s^2 at 210 deg"')
    assert row.mistake.kind == "coriolis" and "left out" in row.mistake.text


SLOTTED = inline("textbook-slotted.toml")


@pytest.mark.parametrize(("given", "kind", "words"), [
    ("13.44 rad/s^2 ccw", None, None),
    ("48 rad/s^2 cw", "coriolis", "with ω3 instead of ω2"),
    ("82.56 rad/s^2 ccw", "coriolis", "wrong sense"),
    ("48 rad/s^2 ccw", "coriolis", "left out"),
])
def test_coriolis_mistakes_slotted_arm(tmp_path: Path, given: str, kind: str | None,
                                       words: str | None) -> None:
    # By hand: B = (3, 4), u = (0.6, 0.8) along the slot, n = (-0.8, 0.6).
    #   V_B = ω3 k × (3, 0) = (0, 30): V_B·u = 24 = V_B/2, V_B·n = 18 = ω2·5, ω2 = 3.6 ccw.
    #   A_B = -ω3² (3, 0) = (-300, 0): A_B·n = 240, A_B·u = -180.
    #   n: 240 = A_B2^t + 2 ω2 V_B/2 = 5 α2 + 172.8  ->  α2 = 13.44 ccw.
    #   ω3 in the Coriolis term: 5 α2 = 240 - 2·10·24 = -240  ->  α2 = 48 cw.
    #   the Coriolis term reversed: 5 α2 = 240 + 172.8  ->  α2 = 82.56 ccw.
    #   the Coriolis term left out: 5 α2 = 240  ->  α2 = 48 ccw.
    f = tmp_path / "slotted.toml"
    f.write_text(SLOTTED)
    row = _only_row(f, f'alpha2 = "{given}"')
    if kind is None:
        assert row.verdict == "ok"
    else:
        assert row.verdict == "WRONG"
        assert row.mistake.kind == kind and words in row.mistake.text


def test_no_hint_when_nothing_explains_it(fourbar: Path) -> None:
    row = _only_row(fourbar, 'omega3 = "31 rad/s ccw"')
    assert row.verdict == "WRONG" and row.mistake is None


# ---- instant centers and curvature (values of tests/data/spec/expected.toml) -----------

def test_instant_center_and_radius_of_curvature(fourbar: Path) -> None:
    rep = _report(fourbar, 'I13 = [5.43, -9.40]\nI24 = [-11.06, 0]\nrho_E = "4.32 in"\n'
                           "I34 = [14.81, 9.89]")
    assert [r.verdict for r in rep.rows] == ["ok"] * 4
    row = _only_row(fourbar, "I13 = [-5.43, 9.40]")
    assert row.verdict == "WRONG"


def test_fallbacks_without_the_instant_center_and_curvature_modules(
        fourbar: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # the same values from the velocities alone: I13 is where links 1 and 3 have equal
    # (zero) velocity, ρ_E = |V_E|³/|V_E × A_E| (Sec. 4.14); values of expected.toml
    import graphkin.check.exact as exact

    monkeypatch.setattr(exact, "_optional_instant_centers", lambda sol: {})
    monkeypatch.setattr(exact, "_optional_paths", lambda sol: {})
    mech = graphkin.load(fourbar)
    ev = exact.Evaluator(mech.solve())
    i13 = ev.value(graphkin.check.parse_key("I13", mech)).xy
    assert list(i13) == pytest.approx([5.42613, -9.39833], abs=1e-4)
    i24 = ev.value(graphkin.check.parse_key("I24", mech)).xy
    assert list(i24) == pytest.approx([-11.0627, 0.0], abs=1e-4)
    rho = ev.value(graphkin.check.parse_key("rho_E", mech)).value
    assert rho == pytest.approx(4.320695, abs=1e-5)
