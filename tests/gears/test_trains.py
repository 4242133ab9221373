"""Gear trains, Examples 7.4-7.11: the book's answers by the mesh equations, Eq. (7.25) and the
book's table (Sec. 7.16), and the three methods against each other on random trains."""

from __future__ import annotations

import json
from fractions import Fraction

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin.cli import main
from graphkin.gears.train import Contact, Mesh, Train, formula, solve, tabular
from graphkin.gears.train_file import load_train

# (file, {member: the book's answer}, tolerance of its printed figures)
BOOK = [
    # Example 7.4: ω_A = 114.3 rev/min ccw
    ("ex7_4.toml", {"3": 114.3}, 0.05),
    # Example 7.5: ω_j = -30 rad/s (cw), ω_k = 30 rad/s (ccw)
    ("ex7_5.toml", {"j": -30.0, "k": 30.0}, 1e-9),
    # Example 7.6: ω4 = 40, ω3 = -20, ω6 = 160, ω5 = -80 rad/s
    ("ex7_6.toml", {"3": -20.0, "4": 40.0, "5": -80.0, "6": 160.0}, 1e-9),
    # Example 7.7: ω5 = -20, ω3 = -60, ω4 = -30 rad/s
    ("ex7_7.toml", {"3": -60.0, "4": -30.0, "5": -20.0}, 1e-9),
    # Example 7.8: ω5 = 250 rev/min ccw
    ("ex7_8.toml", {"5": 250.0}, 1e-9),
    # Example 7.9: ω5 = 350 rev/min ccw
    ("ex7_9.toml", {"5": 350.0}, 1e-9),
    # Example 7.10: Δθ4 = 1/101 rev ccw, Δθ5 = -1/99 rev (cw)
    ("ex7_10.toml", {"4": 1 / 101, "5": -1 / 99}, 1e-12),
    # Example 7.11: ω5 = 1.429 ω3
    ("ex7_11.toml", {"5": 1.429}, 5e-4),
]


@pytest.mark.parametrize("name,answers,tol", BOOK, ids=[b[0] for b in BOOK])
def test_book_examples(gear_examples, name, answers, tol):
    train = load_train(gear_examples / "trains" / name)
    sol = solve(train)
    for member, value in answers.items():
        assert sol.omega[member] == pytest.approx(value, abs=tol), member
    tab = tabular(train)
    if tab is not None:   # one arm: the book's table gives the same
        for member, value in sol.omega.items():
            assert tab.omega[member] == pytest.approx(value, abs=1e-9 * max(1, abs(value)))


def test_example_7_11_percentage(gear_examples):
    """"(1.429 ω3 − 1.0 ω3)/(1.429 ω3) = 0.300 = 30 %"."""
    w5 = solve(load_train(gear_examples / "trains" / "ex7_11.toml")).omega["5"]
    assert (w5 - 1.0) / w5 == pytest.approx(0.300, abs=5e-4)


@pytest.mark.parametrize("name,cells", [
    # Table 7.3, row 2: gear 4 (-40/20)ω2/3, gear 5 (20/80)(-40/20)ω2/3
    ("ex7_8.toml", {"4": "(-40/20)ω2/3", "5": "(20/80)(-40/20)ω2/3", "3": "0"}),
    # Table 7.4, row 2: (-20/101)(-100/20)Δθ2/3, (-20/99)(-100/20)Δθ2/3, (-100/20)Δθ2/3
    ("ex7_10.toml", {"4": "(-20/101)(-100/20)Δθ2/3", "5": "(-20/99)(-100/20)Δθ2/3",
                     "6": "(-100/20)Δθ2/3"}),
    # Table 7.5, row 2: (-18/12)ω2/3, (12/42)(-18/12)ω2/3
    ("ex7_11.toml", {"4": "(-18/12)ω2/3", "5": "(12/42)(-18/12)ω2/3"}),
])
def test_the_books_tables(gear_examples, name, cells):
    tab = tabular(load_train(gear_examples / "trains" / name))
    assert tab is not None
    assert [r.name for r in tab.rows] == ["1. Gears fixed to arm", "2. Arm fixed", "3. Total"]
    for member, text in cells.items():
        assert tab.rows[1].cells[member] == text


def test_example_7_4_formula(gear_examples):
    """θ'_62 = (-16/34)(-20/30) = 16/51, seen from the arm (Eq. 7.24)."""
    value, arm = formula(load_train(gear_examples / "trains" / "ex7_4.toml"), "2", "6")
    assert value == Fraction(16, 51) and arm == "3"


@settings(max_examples=40, deadline=None)
@given(st.integers(12, 60), st.integers(12, 40), st.floats(-500, 500), st.floats(-500, 500),
       st.sampled_from(["sun", "ring", "arm"]))
def test_three_methods_agree(sun, planet, w_in, w_arm, held):
    """A sun, a planet and a ring on one arm: the mesh equations, the table and Eq. (7.25)
    (ω_L = ω_A + θ'_LF/A (ω_F − ω_A)) give the same ring speed."""
    ring = sun + 2 * planet
    size = {"2": Fraction(sun), "4": Fraction(planet), "5": Fraction(ring)}
    given_ = {"2": w_in, "3": w_arm} if held == "arm" else \
        ({"3": w_arm, "5": 0.0} if held == "ring" else {"3": w_arm, "2": 0.0})
    train = Train(size, [Mesh("2", "4", Contact.EXTERNAL, "3"),
                         Mesh("4", "5", Contact.INTERNAL, "3")], given=given_)
    sol = solve(train)
    tab = tabular(train)
    assert tab is not None
    value, _ = formula(train, "2", "5")
    assert value == Fraction(-sun, ring)   # (-N2/N4)(N4/N5)
    w2, w3, w5 = sol.omega["2"], sol.omega["3"], sol.omega["5"]
    scale = max(1.0, abs(w_in), abs(w_arm))
    assert w5 == pytest.approx(w3 + float(value) * (w2 - w3), abs=1e-9 * scale)
    for m in sol.omega:
        assert tab.omega[m] == pytest.approx(sol.omega[m], abs=1e-9 * scale)


def test_cli_train_report(gear_examples, capsys):
    assert main(["gears", str(gear_examples / "trains" / "ex7_8.toml")]) == 0
    out = capsys.readouterr().out
    assert "250 rev/min ccw" in out and "(20/80)(-40/20)ω2/3" in out
    assert main(["gears", str(gear_examples / "trains" / "ex7_6.toml"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["members"]["6"]["omega"] == pytest.approx(160.0)
    assert data["size"] == "radius" and data["table"] is None


TRAIN = """\
[teeth]
2 = 40
4 = 20
5 = 80
[[mesh]]
gears = [2, 4]
arm = 3
[[mesh]]
gears = [4, 5]
contact = "internal"
arm = 3
[speeds]
2 = "100 rev/min ccw"
3 = "200 rev/min ccw"
"""


@pytest.mark.parametrize("text,key,reason", [
    (TRAIN.replace("2 = 40", "2 = 40.5"), "teeth.2", "whole number"),
    (TRAIN.replace('3 = "200 rev/min ccw"\n', ""), "speeds", "degree(s) of freedom"),
    (TRAIN + "5 = 3\n", "speeds", "contradict"),
    (TRAIN.replace('2 = "100', '7 = "100'), "speeds.7", "no gear or arm"),
    (TRAIN.replace('contact = "internal"', 'contact = "inside"'), "mesh[1].contact",
     "internal"),
    (TRAIN.replace("arm = 3\n[[mesh]]", "arms = 3\n[[mesh]]"), "mesh[0].arms",
     "did you mean 'arm'"),
    (TRAIN.replace("gears = [2, 4]", "gears = [2, 9]"), "mesh[0].gears", "no size"),
    (TRAIN.replace('"100 rev/min ccw"', '"100 kg"'), "speeds.2", "not an angular velocity"),
])
def test_bad_train_file(tmp_path, capsys, text, key, reason):
    path = tmp_path / "train.toml"
    path.write_text(text)
    assert main(["gears", str(path)]) == 2
    out, err = capsys.readouterr()
    assert out == "" and len(err.strip().splitlines()) == 1
    assert f": {key}: " in err and reason in err, err


def test_named_members_read_apart(capsys):
    """A train whose members have names: the train value's subscript is ``ring,sun``, not
    ``ringsun``, and an arm named "arm" is "the arm", not "the arm arm" (audit 8).

    By hand, Eq. (7.25) seen from the arm with the ring held: (0 − ω_A)/(600 − ω_A) =
    −30/66, so ω_A = 600 · 30/96 = 187.5 rev/min; the planet: (ω_p − 187.5)/(600 − 187.5) =
    −30/18, ω_p = −500 rev/min.
    """
    from spec_data import ROOT

    assert main(["gears", str(ROOT / "tests" / "data" / "audit8" / "planetary_named.toml")]) == 0
    out = capsys.readouterr().out
    assert "θ'_ring,sun/arm = -5/11" in out and "θ'_planet,sun/arm = -5/3" in out
    assert "arm arm" not in out and "seen from the arm: ωplanet = -500 rev/min" in out
    assert "187.5 rev/min ccw" in out
