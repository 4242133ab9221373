"""An arm carried by another arm, laid out as a mechanism (graphkin/gears/train_layout.py).

Arm 2 turns about the frame's axis; gear 3 turns on a pin of arm 2 and is itself
the arm of a second planetary stage (``arm = 3``, as Example 7.6's gear 4 is an arm,
or an arm joined to gear 3).  The layout puts the inner arm's axis on the outer arm
where the gears it carries put it, and the laid-out mechanism's solve gives every
member the train formula's ω (Eq. 7.25 once per arm) -- by hand below, and for
random such trains (tests/strategies_trains.py, ``arms_on_arms``); each gear has
turned by its ω ratio times the arm's turn after more than a turn of the driver.
"""

from __future__ import annotations

import json
import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from strategies_trains import RandomTrain, arms_on_arms
from train_checks import assert_meshes_touch_and_others_clear

import graphkin
from graphkin.cli import main
from graphkin.errors import InputError
from graphkin.gears.train_file import train_from_dict
from graphkin.gears.train_layout import train_mechanism

SLOW = settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])

# Suns 4 (40 teeth) and 7 (30) held on the frame's axis; arm 2 driven at 10 rad/s ccw.
# Gears 3 (20) and 5 (30) turn freely on one pin of arm 2, 3 in mesh with 4, 5 with 7
# (40 + 20 = 30 + 30: one center distance, 30 mm with R = N/2 mm).  Gear 3 is also the arm
# of planet 6 (20 teeth), in mesh with gear 5.
#
# Tabular method (Sec. 7.16, as Table 7.3), first stage, arm 2 (ω4 = ω7 = 0):
#
#   step                   | 2   | 4           | 3                      | 7        | 5
#   1. gears fixed to arm  | ω2  | ω2          | ω2                     | ω2       | ω2
#   2. arm 2 fixed         | 0   | ω4/2        | (-40/20) ω4/2          | ω7/2     | (-30/30) ω7/2
#   3. total               | ω2  | ω2 + ω4/2   | ω2 - 2 ω4/2            | ω2+ω7/2  | ω2 - ω7/2
#
#   ω4 = 0: ω4/2 = -10, so ω3 = 10 + 20 = 30 rad/s; ω7 = 0: ω7/2 = -10, so ω5 = 10 + 10 = 20.
#
# Second stage, arm 3 (ω3 = 30 from the first table):
#
#   step                   | 3   | 5                | 6
#   1. gears fixed to arm  | 30  | 30               | 30
#   2. arm 3 fixed         | 0   | ω5/3 = 20-30=-10 | (-30/20)(-10) = +15
#   3. total               | 30  | 20               | 45 rad/s
HAND = {"2": 10.0, "3": 30.0, "4": 0.0, "5": 20.0, "6": 45.0, "7": 0.0}


def _train(inner: str = "3", speeds: dict | None = None) -> dict:
    data: dict = {"title": "arm 3 on arm 2", "teeth": {"4": 40, "3": 20, "7": 30, "5": 30,
                                                       "6": 20},
                  "mesh": [{"gears": [4, 3], "arm": 2}, {"gears": [7, 5], "arm": 2},
                           {"gears": [5, 6], "arm": inner}],
                  "speeds": speeds or {"2": "10 rad/s ccw", "4": 0, "7": 0}}
    if inner != "3":
        data["joined"] = [{"members": [3, inner]}]
    return data


def _layout(data: dict):
    train = train_from_dict(data, "t.toml")
    lay = train_mechanism(train, "t.toml")
    return train, lay, graphkin.from_dict(lay.data, source="t.toml")


# the same train with the inner arm's motion given instead of sun 4's: 30 = 10 + (-2)(ω4 - 10)
# gives ω4 = 0 back; the inner arm turns on a pin of arm 2, so it is driven by its angle
# relative to arm 2, θ3/2, at ω3 - ω2 = 20 rad/s
INNER_GIVEN = {"2": "10 rad/s ccw", "3": "30 rad/s ccw", "7": 0}


@pytest.mark.parametrize("inner,speeds", [("3", None), ("B", None), ("3", INNER_GIVEN),
                                          ("B", INNER_GIVEN | {"B": "30 rad/s ccw"})])
def test_the_hand_example_turns_at_the_tables_speeds(inner: str, speeds: dict | None) -> None:
    if speeds is not None and "B" in speeds:
        speeds = {k: v for k, v in speeds.items() if k != "3"}
    _, lay, mech = _layout(_train(inner, speeds))
    if speeds is not None:
        rel = [d for d in lay.data["drive"] if "relative_to" in d]
        assert rel == [{"link": lay.link_of["3"], "relative_to": lay.link_of["2"],
                        "follows": {"link": lay.link_of["2"], "ratio": pytest.approx(2.0)}}]
    sol = mech.solve()
    for member, w in HAND.items():
        lid = lay.link_of[member]
        got = 0.0 if lid == "1" else float(sol.omega(lid))
        assert got == pytest.approx(w, abs=1e-9 * 45.0), member
    if inner == "B":
        assert lay.link_of["B"] == lay.link_of["3"]
    assert lay.link_of["4"] == ("1" if speeds is None else "4")
    # the pin of arm 2 30 mm from the axis (R4 + R3 = 20 + 10), planet 6 25 mm from the pin
    assert math.dist(lay.center["3"], lay.center["4"]) == pytest.approx(30.0, rel=1e-15)
    assert lay.center["5"] == lay.center["3"]
    assert math.dist(lay.center["6"], lay.center["3"]) == pytest.approx(25.0, rel=1e-15)
    # the inner arm's axis is a point of arm 2, planet 6's axis a point of arm 3, not the frame
    links = lay.data["links"]
    pin, axis6 = lay.axis_point["3"], lay.axis_point["6"]
    assert pin in links[lay.link_of["2"]] and pin not in links["1"]
    assert axis6 in links[lay.link_of["3"]] and axis6 not in links[lay.link_of["2"]]


def test_graphkin_gears_json_agrees_with_the_laid_out_solve(tmp_path, capsys) -> None:
    path = tmp_path / "aoa.toml"
    path.write_text('[teeth]\n4 = 40\n3 = 20\n7 = 30\n5 = 30\n6 = 20\n'
                    '[[mesh]]\ngears = [4, 3]\narm = 2\n[[mesh]]\ngears = [7, 5]\narm = 2\n'
                    '[[mesh]]\ngears = [5, 6]\narm = 3\n'
                    '[speeds]\n2 = "10 rad/s ccw"\n4 = 0\n7 = 0\n', encoding="utf-8")
    assert main(["gears", str(path), "--json"]) == 0
    ref = json.loads(capsys.readouterr().out)
    assert {m: v["omega"] for m, v in ref["members"].items()} == pytest.approx(HAND, abs=1e-9)
    assert main(["live", str(path), "-o", str(tmp_path / "p.html")]) == 0


def test_past_a_turn_every_gear_has_turned_by_its_ratio() -> None:
    """Arm 2 turned 0, 370° and 740°: each gear has turned ω_g/ω2 times as far (no slip,
    counted on continuously), and planet 6's axis is where the two arms put it:
    O6 = 30 (cos θ2, sin θ2) + 25 (cos θ3, sin θ3), θ3 = 3 θ2 (both 0 as drawn)."""
    _, lay, mech = _layout(_train())
    sw = mech.sweep(count=3, start=0.0, stop=740.0)
    assert sw.valid.all()
    t2 = np.radians(sw.columns["drive"])
    for member in ("3", "5", "6"):
        lid = lay.link_of[member]
        turned = np.radians(sw.columns[f"angle_{lid}"] - sw.columns[f"angle_{lid}"][0])
        want = HAND[member] / HAND["2"] * t2
        assert np.allclose(np.remainder(turned - want + np.pi, 2 * np.pi) - np.pi, 0.0,
                           atol=1e-9), member
        assert np.allclose(sw.columns[f"omega_{lid}"], HAND[member], atol=1e-9 * 45.0)
    o6 = lay.axis_point["6"]
    x = 30 * np.cos(t2) + 25 * np.cos(3 * t2)
    y = 30 * np.sin(t2) + 25 * np.sin(3 * t2)
    assert np.allclose(sw.columns[f"x_{o6}"], x, atol=1e-9 * 55)
    assert np.allclose(sw.columns[f"y_{o6}"], y, atol=1e-9 * 55)


def test_three_levels_of_arms() -> None:
    """Planet 6 of arm 3 is itself arm 6, carrying planet 8 round gear 9 on 6's pin, 9 in
    mesh with 5 on arm 3 (all external).  By hand, Eq. (7.25) from each arm: the example's
    ω5 = 20, ω6 = 45 (arm 3); seen from arm 3, ω9 = 30 + (-30/10)(20 - 30) = 60; seen from
    arm 6, ω8 = 45 + (-10/15)(60 - 45) = 35 rad/s."""
    data = _train()
    data["teeth"] |= {"9": 10, "8": 15}
    data["mesh"] += [{"gears": [5, 9], "arm": 3}, {"gears": [9, 8], "arm": 6}]
    _, lay, mech = _layout(data)
    sol = mech.solve()
    for member, w in (HAND | {"9": 60.0, "8": 35.0}).items():
        lid = lay.link_of[member]
        got = 0.0 if lid == "1" else float(sol.omega(lid))
        assert got == pytest.approx(w, abs=1e-9 * 60.0), member
    assert lay.center["9"] == lay.center["6"]


def test_a_given_motion_that_follows_from_those_before_it_is_not_a_drive() -> None:
    """ω3 = ω6 = ω5 = ω2 = 10 rad/s: every mesh turns as one, and seen from arm 3,
    ω6 − ω3 = (−30/20)(ω5 − ω3) = 0 (Eq. 7.25) follows from ω3 and ω6 (given first):
    gear 5's motion is left to follow, arm 2 is the third drive, and all turn at 10."""
    speeds = {"3": 10, "6": 10, "5": 10, "2": 10}
    _, lay, mech = _layout(_train("3", speeds))
    assert len(lay.data["drive"]) == 3
    assert lay.notes == [n for n in lay.notes if n.startswith("speeds.5: ")] and lay.notes
    sol = mech.solve()
    for member, lid in lay.link_of.items():
        assert float(sol.omega(lid)) == pytest.approx(10.0, abs=1e-9 * 10.0), member


@SLOW
@given(arms_on_arms())
def test_random_arms_on_arms_turn_at_the_formulas_speeds(t: RandomTrain) -> None:
    train, lay, mech = _layout(t.data)
    sol = mech.solve()
    scale = max(abs(w) for w in t.omega.values())
    for member, w in t.omega.items():
        lid = lay.link_of[member]
        got = 0.0 if lid == "1" else float(sol.omega(lid))
        assert got == pytest.approx(w, abs=1e-9 * scale), (t.kind, member)
    # meshes touch at their operating pitch circles; gears that do not mesh stand clear
    assert_meshes_touch_and_others_clear(train, lay, sol, t.kind)
    # arm 2 (the swept drive: given first, never 0) turned 0, 250° and 500°: every link at
    # the formula's ω, and turned ω/ω2 times as far as the arm (counted on continuously)
    assert lay.data["drive"][0]["link"] == lay.link_of["2"]
    sw = mech.sweep(count=3, start=0.0, stop=750.0)
    assert sw.valid.all()
    t2 = np.radians(sw.columns["drive"])
    for member, w in t.omega.items():
        lid = lay.link_of[member]
        if lid == "1":
            continue
        assert np.allclose(sw.columns[f"omega_{lid}"], w, rtol=0.0, atol=1e-9 * scale)
        turned = np.radians(sw.columns[f"angle_{lid}"] - sw.columns[f"angle_{lid}"][0])
        off = np.remainder(turned - w / t.omega["2"] * t2 + np.pi, 2 * np.pi) - np.pi
        assert np.allclose(off, 0.0, atol=1e-9 * max(1.0, abs(w / t.omega["2"]))), member


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(arms_on_arms(), st.lists(st.sampled_from([-1.0, 1.0]), min_size=6, max_size=6))
def test_radii_moved_by_round_off_move_no_verdict(t: RandomTrain, signs: list[float]) -> None:
    """Every size moved by 1e-12 of itself: the same links, carriers, notes and axes."""
    a = train_mechanism(train_from_dict(t.data, "t.toml"), "t.toml")
    moved = train_from_dict(t.data, "t.toml")
    moved.size = {g: Fraction(float(r) * (1.0 + 1e-12 * s))
                  for (g, r), s in zip(moved.size.items(), signs, strict=False)}
    b = train_mechanism(moved, "t.toml")
    assert a.link_of == b.link_of
    assert [n.split(":")[0] for n in a.notes] == [n.split(":")[0] for n in b.notes]
    assert {k: sorted(v) for k, v in a.data["links"].items()} == \
        {k: sorted(v) for k, v in b.data["links"].items()}
    size = max(a.radius.values())
    for g, c in a.center.items():
        assert math.dist(c, b.center[g]) <= 1e-9 * size, g


@pytest.mark.parametrize("data,words", [
    # gear 9 held, yet on the axis of arm 3, which turns on a pin of arm 2
    ({"teeth": {"4": 40, "3": 20, "9": 20, "6": 20},
      "mesh": [{"gears": [4, 3], "arm": 2}, {"gears": [9, 6], "arm": 3}],
      "speeds": {"2": 1, "4": 0, "9": 0}}, "'9' (given at rest, 0, so part of the frame)"),
    # the inner arm given at rest is part of the frame, yet it turns on a pin of arm 2
    ({"teeth": {"4": 40, "3": 20, "7": 30, "5": 30, "6": 20},
      "mesh": [{"gears": [4, 3], "arm": 2}, {"gears": [7, 5], "arm": 2},
               {"gears": [5, 6], "arm": 3}],
      "speeds": {"2": 10, "3": 0, "7": 0}}, "'3' (given at rest, 0, so part of the frame)"),
    # arm 2 turns on a pin of arm 3 (gear 2 is in mesh with h on arm 3, h a planet of arm 3
    # as it meshes with g given on 3's axis), and arm 3 on a pin of arm 2: a cycle
    ({"teeth": {"g": 20, "h": 20, "3": 20, "2": 20},
      "mesh": [{"gears": ["g", "h"], "arm": 3}, {"gears": ["h", 3], "arm": 2}],
      "speeds": {"g": 1, "2": 2}}, "would each be carried by the other"),
])
def test_an_arm_on_an_arm_that_cannot_be_laid_out_is_one_line(data: dict, words: str) -> None:
    with pytest.raises(InputError) as exc:
        train_mechanism(train_from_dict(data, "t.toml"), "t.toml")
    assert exc.value.key.startswith("mesh") and "\n" not in str(exc.value)
    assert words in str(exc.value), str(exc.value)
