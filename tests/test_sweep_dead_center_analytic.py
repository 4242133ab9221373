"""A sweep by the analytic solver leaves the rates empty at a dead center at the end of
a travel drive's range, as the constructions do (issue 25).

The planet driven by a point (tests/data/hostile/point_drive_planetary.toml): the arm
2 (O P = 60 mm) turns about O, the drive is the coordinate ``x_P`` at ``vx = 1``,
``ax = 0``, and the planet 3 (radius 20) rolls outside the sun 1 (radius 40).  Its
travel is ``-60 <= x_P <= 60``; at both ends P crosses the x axis and the arm cannot be
turned by ``x_P`` (a dead center, Sec. 1.10): ``x_P = 60 cos θ2`` gives

    ``ẋ_P = -y_P ω2``  so  ``ω2 = -1 / y_P``,
    ``0 = ẍ_P = -ẏ_P ω2 - y_P α2 = -x_P ω2² - y_P α2``  so  ``α2 = -x_P ω2² / y_P``,

which grow without bound as ``y_P -> 0``.  Rolling outside, the planet turns
``(R + r)/r = 3`` times as fast as the line of centers (Sec. 2.19, Eq. 10.8 for the
planetary train): ``ω3 = 3 ω2``, ``α3 = 3 α2``.
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.cli import main
from graphkin.mechanisms import loads

DATA = Path(__file__).parent / "data"
PLANETARY = DATA / "hostile" / "point_drive_planetary.toml"

RATES = ("omega_2", "alpha_2", "omega_3", "alpha_3", "vx_P", "vy_P", "ax_P", "ay_P",
         "vx_Q", "vy_Q", "ax_Q", "ay_Q")
POSITIONS = ("angle_2", "angle_3", "x_P", "y_P", "x_Q", "y_Q")


@pytest.fixture(scope="module")
def planetary() -> tuple[graphkin.Mechanism, graphkin.Sweep]:
    mech = graphkin.load(PLANETARY)
    return mech, mech.sweep(count=7)


def test_first_row_at_the_end_of_the_travel_has_empty_rates(planetary) -> None:
    mech, sw = planetary
    cols = sw.columns
    x = np.asarray(cols["drive"], dtype=float)
    # the first row is the end of the travel, x_P = -60, within round-off of the size
    assert abs(x[0] + 60.0) <= 1e-9 * 60.0
    for k in RATES:
        assert math.isnan(cols[k][0]), k
        assert np.all(np.isfinite(np.asarray(cols[k][1:], dtype=float))), k
    for k in POSITIONS:
        assert np.all(np.isfinite(np.asarray(cols[k], dtype=float))), k
    assert cols["x_P"][0] == pytest.approx(-60.0, abs=1e-9 * 60.0)
    assert abs(cols["y_P"][0]) < 1e-3  # P on the x axis: the dead center
    assert list(sw.assembled) == [True] * 7
    assert list(sw.valid) == [False] + [True] * 6
    # the rates of the Solution are empty too, its posture kept
    sol = sw.solution
    assert math.isnan(float(np.asarray(sol.omega("2"))[0]))
    assert np.isfinite(np.asarray(sol.position("Q"))[0]).all()


def test_singular_lists_both_ends_of_the_travel(planetary) -> None:
    _, sw = planetary
    dead = [s.drive for s in sw.singular if s.kind == "dead-center"]
    assert len(dead) == 2
    assert dead[0] == pytest.approx(-60.0, abs=1e-9 * 60.0)
    assert dead[1] == pytest.approx(60.0, abs=1e-9 * 60.0)


def test_rows_away_from_the_ends_are_the_hand_derivation_and_solve(planetary) -> None:
    mech, sw = planetary
    cols = sw.columns
    sol = sw.solution
    for k in range(1, 7):
        x, y = float(cols["x_P"][k]), float(cols["y_P"][k])
        assert x == pytest.approx(float(cols["drive"][k]), abs=1e-9 * 60)
        assert math.hypot(x, y) == pytest.approx(60.0, rel=1e-9)
        w2 = -1.0 / y
        a2 = -x * w2**2 / y
        assert cols["omega_2"][k] == pytest.approx(w2, rel=1e-8)
        assert cols["alpha_2"][k] == pytest.approx(a2, rel=1e-8, abs=1e-12)
        assert cols["omega_3"][k] == pytest.approx(3.0 * w2, rel=1e-8)
        assert cols["alpha_3"][k] == pytest.approx(3.0 * a2, rel=1e-8, abs=1e-12)
        # solve at the same drive value, the planet at its swept angle (the reference of
        # the no-slip condition) and the swept points as assembly hints
        d = mech.drives[0]
        rolling = tuple(dataclasses.replace(r, angle=float(np.asarray(sol.angle_rad(r.link))[k]))
                        for r in mech.rolling)
        hint = {p: tuple(float(c) for c in np.asarray(sol.position(p))[k])
                for p in ("P", "Q")}
        one = dataclasses.replace(mech, drives=(dataclasses.replace(d, value=x),),
                                  assembly=hint, rolling=rolling).solve()
        assert float(one.omega("2")) == pytest.approx(cols["omega_2"][k], rel=1e-8)
        assert float(one.alpha("3")) == pytest.approx(cols["alpha_3"][k], rel=1e-7, abs=1e-12)
        v = np.asarray(one.velocity("Q"), dtype=float)
        assert v[0] == pytest.approx(cols["vx_Q"][k], rel=1e-8, abs=1e-12)
        assert v[1] == pytest.approx(cols["vy_Q"][k], rel=1e-8, abs=1e-12)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_blank_rows_do_not_move_under_a_perturbation_of_1e_12(sign: float) -> None:
    e = 1.0 + sign * 1e-12
    text = PLANETARY.read_text(encoding="utf-8")
    for old, new in (("P = [60, 0]", f"P = [{60 * e!r}, 0]"),
                     ("radius = 20 }", f"radius = {20 * e!r} }}"),
                     ("radius = 40 }", f"radius = {40 * e!r} }}"),
                     ("x = 51.96", f"x = {51.96 * e!r}")):
        assert old in text
        text = text.replace(old, new)
    sw = loads(text).sweep(count=7)
    assert list(sw.valid) == [False] + [True] * 6
    assert list(sw.assembled) == [True] * 7
    assert len([s for s in sw.singular if s.kind == "dead-center"]) == 2


def test_constructions_slider_crank_unchanged(tmp_path: Path, capsys) -> None:
    """The constructions' sweep of the slider-crank driven by its slider, as before."""
    assert main(["example", "slider_crank"]) == 0
    sc = tmp_path / "sc.toml"
    sc.write_text(capsys.readouterr().out, encoding="utf-8")
    mech = graphkin.load(sc)
    sw = mech.sweep(count=5)
    assert sw.method == "construction"
    cols = sw.columns
    assert list(sw.valid) == [False] + [True] * 4
    assert list(sw.assembled) == [True] * 5
    for k in ("omega_2", "alpha_2", "omega_3", "vx_B"):
        assert math.isnan(cols[k][0]) and np.isfinite(cols[k][1]), k
    for k in ("angle_2", "x_B", "y_B"):
        assert np.isfinite(cols[k][0]), k
    dead = [s for s in sw.singular if s.kind == "dead-center"]
    assert [s.label for s in dead] == ["B", "B"]
