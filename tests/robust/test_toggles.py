"""Exactly at a toggle or dead center the velocities are reported undetermined (issue 14, 6).

At a toggle of a four-bar the coupler and the rocker are in line, so the two
lines of the velocity polygon that meet at ``c`` (⊥ BC and ⊥ DC) are parallel
and V_C is undetermined (Sec. 3.5); at the dead center of a slider-crank
driven by its slider, crank and coupler are in line and ω2 is undetermined.
Both give the positions, no velocities (null in JSON) and one note saying so.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.cli import main

HOSTILE = Path(__file__).parent.parent / "data" / "hostile"


def run(argv: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        rc = main(argv)
    return rc, out.getvalue(), err.getvalue()


@pytest.mark.parametrize("name", ["toggle_fourbar", "dead_center_slider"])
def test_singular_postures_say_so(name: str) -> None:
    f = HOSTILE / f"{name}.toml"
    sol = graphkin.load(f).solve()
    assert not sol.has_rates
    assert any("toggle or dead-center posture" in n for n in sol.notes)
    rc, out, err = run(["solve", str(f), "--json"])
    assert rc == 0, err
    data = json.loads(out)
    assert all(e["omega"] is None for lid, e in data["links"].items())
    assert any("undetermined" in n for n in data["notes"])
    rc, out, err = run(["solve", str(f)])
    assert rc == 0 and "undetermined" in out and "nan" not in out


def test_the_toggle_positions_are_exact() -> None:
    # crank 4 at 180°: B = (-4, 0); |BD| = 14 = coupler 8 + rocker 6, so C lies on BD,
    # 8 from B: C = (4, 0)
    sol = graphkin.load(HOSTILE / "toggle_fourbar.toml").solve()
    assert math.dist(sol.position("C"), (4.0, 0.0)) < 1e-6


@pytest.mark.parametrize("off", [1e-3, 1e-2])
def test_near_a_toggle_the_velocities_are_found(off: float) -> None:
    text = (HOSTILE / "toggle_fourbar.toml").read_text(encoding="utf-8")
    sol = graphkin.loads(text.replace("angle = 180", f"angle = {180 - math.degrees(off)}"))\
        .solve()
    assert sol.has_rates
    # near the toggle ω4 stays finite while ω3 grows like 1/sin(transmission angle); the
    # velocity of C must be perpendicular to DC (it turns about D)
    c, d = sol.position("C"), np.array([10.0, 0.0])
    v = sol.velocity("C")
    assert abs(float(np.dot(v, c - d))) <= 1e-6 * float(np.linalg.norm(v)) * 6



