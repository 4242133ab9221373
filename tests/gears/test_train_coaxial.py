"""A sun and a ring about one axis with one planet between them (audit9, item 3).

Standard teeth of one module put the planet's centre (N_s + N_p)/2 m from the
sun's axis and (N_r - N_p)/2 m from the ring's; the two axes are the arm's, so
N_r = N_s + 2 N_p (pitch radii alike, Fig. 7.40: 200 = 100 + 2 × 50 mm).  The
speeds still follow from the teeth (Eq. 7.25), so the report notes it in one
line; Ferguson's paradox (Example 7.10, profile-shifted, all external) has no note.
"""

from __future__ import annotations

from fractions import Fraction
from pathlib import Path

from graphkin.cli import main
from graphkin.gears.train import Contact, Mesh, Train
from graphkin.gears.train_file import load_train

DATA = Path(__file__).parent / "data"


def _planetary(sun: int, planet: int, ring: int, by_teeth: bool = True) -> Train:
    size = {"s": Fraction(sun), "p": Fraction(planet), "r": Fraction(ring)}
    return Train(size, [Mesh("s", "p", Contact.EXTERNAL, "a"),
                        Mesh("p", "r", Contact.INTERNAL, "a")],
                 given={"s": 100.0, "r": 0.0}, by_teeth=by_teeth)


def test_the_audit_train_is_noted_with_the_ring_it_needs(capsys):
    # sun 24, planet 18: N_ring = 24 + 2 * 18 = 60, the file says 61
    assert main(["gears", str(DATA / "ring_mismatch.toml")]) == 0
    notes = [ln for ln in capsys.readouterr().out.splitlines() if "note:" in ln]
    assert len(notes) == 1
    assert "N_ring = N_sun + 2 N_planet = 60, not 61" in notes[0]
    assert "Sec. 7.11" in notes[0]


def test_teeth_that_fit_have_no_note():
    assert _planetary(24, 18, 60).coaxial_notes() == []
    assert _planetary(20, 30, 80).coaxial_notes() == []        # 20 + 60 = 80
    assert len(_planetary(20, 30, 81).coaxial_notes()) == 1
    assert len(_planetary(20, 30, 79).coaxial_notes()) == 1


def test_pitch_radii_of_figure_7_40():
    # R_h = 200, R_j = 50, R_k = 100 mm (Sec. 7.15, Fig. 7.40)
    assert _planetary(100, 50, 200, by_teeth=False).coaxial_notes() == []
    (note,) = _planetary(100, 50, 210, by_teeth=False).coaxial_notes()
    assert "R_r = R_s + 2 R_p = 200, not 210" in note


def test_fergusons_paradox_is_not_flagged(gear_examples):
    # Example 7.10: gears 2, 4, 5 (100, 101, 99) all mesh planet 6 externally
    assert load_train(gear_examples / "trains" / "ex7_10.toml").coaxial_notes() == []


def test_the_member_table_prints_a_size_and_a_sense_not_a_sign_too(capsys):
    # audit9 #4: sun 24 at 1000 rev/min ccw, ring 61 fixed.  Arm: ω_A = 1000 · 24/(24 + 61)
    # = 282.353 ccw; planet from the arm: (ω_p − ω_A) = −(24/18)(ω_s − ω_A) = −956.863, so
    # ω_p = −674.510 rev/min: printed "674.51 rev/min cw", as solve prints ω (no sign with cw)
    assert main(["gears", str(DATA / "ring_mismatch.toml")]) == 0
    rows = {ln.split()[0]: ln for ln in capsys.readouterr().out.splitlines()[3:7]}
    assert "674.51 rev/min cw" in rows["planet"] and "-674.51" not in rows["planet"]
    assert "282.353 rev/min ccw" in rows["arm"]


def test_fergusons_gear_5_turns_one_99th_cw(gear_examples, capsys):
    # Example 7.10 (Table 7.4): Δθ5 = 1/99 rev cw = 0.010101 rev
    assert main(["gears", str(gear_examples / "trains" / "ex7_10.toml")]) == 0
    (row,) = [ln for ln in capsys.readouterr().out.splitlines() if ln.startswith("  5 ")]
    assert row.split()[3:6] == ["0.010101", "rev", "cw"]
