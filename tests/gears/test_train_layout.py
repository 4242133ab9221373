"""A gear-train file laid out as a mechanism (graphkin/gears/train_layout.py).

For random trains (tests/strategies_trains.py: chains on fixed axes, simple and
compound; planetary trains, reverted, with a ring, with a third gear on the
planet as in Ferguson's paradox; teeth that close the center distances or
not) the laid-out mechanism, solved by graphkin's constructions, gives every
member the ω the train formula gives by hand (Eqs. 7.22, 7.24-7.25); every
mesh's axes are as far apart as its rolling circles need, and those circles
are in the ratio of the teeth (Eq. 7.2); no two gears overlap in the drawing
unless they share an axis or stand on the two axes of a mesh.
"""

from __future__ import annotations

import math
from fractions import Fraction

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from strategies_trains import RandomTrain, gear_trains
from train_checks import assert_meshes_touch_and_others_clear

import graphkin
from graphkin.cli import main
from graphkin.errors import InputError
from graphkin.gears.train_file import load_train, train_from_dict
from graphkin.gears.train_layout import train_mechanism

SLOW = settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def _layout(t: RandomTrain):
    train = train_from_dict(t.data, "random.toml")
    lay = train_mechanism(train, "random.toml")
    return train, lay, graphkin.from_dict(lay.data, source="random.toml").solve()


@SLOW
@given(gear_trains())
def test_the_laid_out_train_turns_at_the_formulas_speeds(t: RandomTrain) -> None:
    _, lay, sol = _layout(t)
    scale = max(abs(w) for w in t.omega.values())
    for member, w in t.omega.items():
        lid = lay.link_of[member]
        got = 0.0 if lid == "1" else float(sol.omega(lid))
        assert got == pytest.approx(w, abs=1e-9 * scale), (t.kind, member)


@SLOW
@given(gear_trains())
def test_meshes_touch_and_other_gears_stand_clear(t: RandomTrain) -> None:
    train, lay, sol = _layout(t)
    assert_meshes_touch_and_others_clear(train, lay, sol, t.kind)


def test_gears_that_cannot_clear_are_drawn_overlapping_and_said_so() -> None:
    """Pinion 2 inside ring 3, ring 3 inside ring 4, gear 5 (6.5 mm) on ring 4's shaft: gear 2
    is within 12 mm of 4's axis to stay inside ring 4 (18 − 6), and 5 needs 12.5 mm (6 + 6.5)
    to clear it: no direction does, and the layout says so in one line."""
    train = train_from_dict({"radii": {"2": 6.0, "3": 12.0, "4": 18.0, "5": 6.5},
                             "mesh": [{"gears": [2, 3], "contact": "internal"},
                                      {"gears": [3, 4], "contact": "internal"}],
                             "joined": [{"members": [4, 5]}], "speeds": {"2": 1.0}},
                            "crowded.toml")
    lay = train_mechanism(train, "crowded.toml")
    assert len(lay.notes) == 1 and lay.notes[0].startswith("mesh[1]: ")
    assert "overlap" in lay.notes[0]


def test_fergusons_paradox_is_drawn_with_operating_pitch_circles() -> None:
    """Example 7.10: the planet (20 teeth) meets gears of 100, 101 and 99 teeth on one axis.

    Mesh 2-6 places the planet 60 mm from the axis (R = N/2 mm); 6-4 and 6-5 are drawn at
    that distance with operating pitch circles in the ratio of the teeth:
    R4' = 60 × 101/121, R6' = 60 × 20/121 (Sec. 7.9)."""
    train = train_from_dict({"teeth": {"2": 100, "4": 101, "5": 99, "6": 20},
                             "mesh": [{"gears": [2, 6], "arm": 3}, {"gears": [6, 4], "arm": 3},
                                      {"gears": [6, 5], "arm": 3}],
                             "turns": {"3": "1 rev ccw", "2": 0}}, "ex7_10.toml")
    lay = train_mechanism(train, "ex7_10.toml")
    assert lay.operating[0] == (50.0, 10.0)
    assert lay.operating[1] == pytest.approx((60 * 20 / 121, 60 * 101 / 121), rel=1e-15)
    assert lay.operating[2] == pytest.approx((60 * 20 / 119, 60 * 99 / 119), rel=1e-15)
    assert len(lay.notes) == 1 and lay.notes[0].startswith("mesh[1]: ")


@pytest.mark.parametrize("data,key", [
    # 2 and 6 on fixed axes in mesh, and both coaxial with the arm carrying planet 4
    ({"teeth": {"2": 20, "6": 40, "4": 20},
      "mesh": [{"gears": [2, 6]}, {"gears": [2, 4], "arm": 3}, {"gears": [4, 6], "arm": 3}],
      "speeds": {"2": 1}}, "mesh[0].gears"),
    # nothing turns: the only given motion holds gear 2
    ({"teeth": {"2": 20, "3": 40}, "mesh": [{"gears": [2, 3]}], "speeds": {"2": 0}}, "speeds"),
    # a ring no larger than the gear inside it
    ({"teeth": {"2": 20, "3": 20}, "mesh": [{"gears": [2, 3], "contact": "internal"}],
      "speeds": {"2": 1}}, "mesh[0].contact"),
])
def test_a_train_that_cannot_be_laid_out_is_one_line(data, key) -> None:
    with pytest.raises(InputError) as exc:
        train_mechanism(train_from_dict(data, "t.toml"), "t.toml")
    assert exc.value.key == key and "\n" not in str(exc.value)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(gear_trains(), st.lists(st.sampled_from([-1.0, 1.0]), min_size=12, max_size=12))
def test_radii_moved_by_round_off_move_no_verdict(t: RandomTrain, signs: list[float]) -> None:
    """Every radius moved by 1e-12 of itself: the same directions, links and notes.

    The sizes are put in the train as exact fractions of the moved floats (the file's
    reader would round them back to 1e-9)."""
    radii = t.data.get("radii") or {g: n / 2.0 for g, n in t.data["teeth"].items()}
    base = {k: v for k, v in t.data.items() if k != "teeth"} | {"radii": radii}
    a = train_mechanism(train_from_dict(base, "t.toml"), "t.toml")
    moved = train_from_dict(base, "t.toml")
    moved.size = {g: Fraction(float(r) * (1.0 + 1e-12 * s))
                  for (g, r), s in zip(moved.size.items(), signs, strict=False)}
    assert moved.size != train_from_dict(base, "t.toml").size
    b = train_mechanism(moved, "t.toml")
    assert a.link_of == b.link_of
    assert [n.split(":")[0] for n in a.notes] == [n.split(":")[0] for n in b.notes]
    size = max(a.radius.values())
    for g, c in a.center.items():
        assert math.dist(c, b.center[g]) <= 1e-9 * size, g


def test_a_train_with_its_diametral_pitch_is_drawn_at_its_size(tmp_path, capsys) -> None:
    """Example 7.4's teeth with P = 10 teeth/in (Example 11.7's gears): R = N/(2P), so
    R2 = 1.0 in, R4 = 1.5 in, and the planet's axis 2.5 in from the sun's (Fig. 11.17); the
    live page then says nothing of a nominal module."""
    path = tmp_path / "ex7_4_sized.toml"
    path.write_text('units = "in"\ndiametral_pitch = 10\n[teeth]\n2 = 20\n4 = 30\n5 = 16\n'
                    '6 = 34\n[[mesh]]\ngears = [2, 4]\narm = 3\n[[mesh]]\ngears = [5, 6]\n'
                    'arm = 3\n[[joined]]\nmembers = [4, 5]\n[speeds]\n2 = "250 rev/min cw"\n'
                    '6 = 0\n', encoding="utf-8")
    lay = train_mechanism(load_train(path), path)
    assert lay.data["units"] == "in"
    assert lay.radius == pytest.approx({"2": 1.0, "4": 1.5, "5": 0.8, "6": 1.7}, rel=1e-15)
    assert math.dist(lay.center["2"], lay.center["4"]) == pytest.approx(2.5, rel=1e-15)
    assert main(["live", str(path), "-o", str(tmp_path / "p.html")]) == 0
    assert "nominal" not in capsys.readouterr().err
    text = path.read_text(encoding="utf-8").replace("[teeth]", "[radii]")
    path.write_text(text, encoding="utf-8")
    with pytest.raises(InputError) as exc:
        load_train(path)
    assert exc.value.key == "diametral_pitch"
