"""The body's points in the mechanism file written (issue 28): the user's, and no invented one.

Postures given as a point and an angle name one point of the body (D, or the first of
``[body] points``); the second point the construction uses to find the poles is not the
user's, so the file written carries the reference point alone.  Postures given as two
points carry both, under the user's names; path generation carries its coupler point S.
"""

from __future__ import annotations

import json
import math

import numpy as np

import graphkin
from graphkin.synthesis import loads_spec, synthesize

ANGLES = """[[postures]]
point = [0, 0]
angle = 0
[[postures]]
point = [1.5, 0.6]
angle = 40
[[postures]]
point = [2.6, 0.4]
angle = 75
[pivots]
circle_points = [[0.5, -1], [1.8, -0.8]]
"""


def _coupler_points(text: str) -> set[str]:
    mech = synthesize(loads_spec(text)).mechanism_toml()
    block = mech.split("[links.3]")[1].split("[links.4]")[0]
    return {line.split("=")[0].strip() for line in block.strip().splitlines()}


def test_point_and_angle_write_the_reference_point_alone() -> None:
    assert _coupler_points(ANGLES) == {"A", "B", "D"}
    named = '[body]\npoints = ["P", "Q"]\n' + ANGLES
    assert _coupler_points(named) == {"A", "B", "P"}
    # the reference point is where the user put it, in every design posture
    res = synthesize(loads_spec(ANGLES))
    link = res.chosen
    assert link is not None
    for k, xy in enumerate(([0, 0], [1.5, 0.6], [2.6, 0.4])):
        sol = graphkin.loads(link.mechanism_toml(k)).solve()
        assert np.abs(sol.position("D") - np.array(xy)).max() < 1e-9


def test_two_points_write_both_under_the_users_names() -> None:
    # the same postures given by two points of the body, C and F, 2 apart along it
    text = '[body]\npoints = ["C", "F"]\n' + "".join(
        f"[[postures]]\nC = [{x}, {y}]\nF = [{x + 2 * math.cos(math.radians(a))!r}, "
        f"{y + 2 * math.sin(math.radians(a))!r}]\n"
        for x, y, a in ((0, 0, 0), (1.5, 0.6, 40), (2.6, 0.4, 75))) + \
        "[pivots]\ncircle_points = [[0.5, -1], [1.8, -0.8]]\n"
    assert _coupler_points(text) == {"A", "B", "C", "F"}


def test_path_generation_writes_the_coupler_point_only() -> None:
    text = ('[path]\npoints = [[0.26795, 0], [2.0, 0], [3.73205, 0]]\ncrank = [-6, -45, -84]\n'
            'coupler = [0, -20, -50]\nrocker_pin = 0.5\n')
    assert _coupler_points(text) == {"A", "B", "S"}


def test_two_points_typed_to_three_figures_are_one_body(capsys) -> None:
    """Audit 8: postures typed as the body's two points to three figures were refused.

    P = (1.5, 0.8), Q = (3.3, 1.67): PQ = |(1.8, 0.87)| = 1.99922, not the 2 of posture 1
    (0.04 % off, the rounding of typed figures).  The angle is the direction of PQ, so by
    hand θ2 = atan2(0.87, 1.8) = 25.796°, θ3 = atan2(1.2, 1.6) = 36.870°, and the pole P31
    of postures 1 (P = 0, 0°) and 3 (P = (3, 0.9), 36.87°) solves (I − R) X = P3 with R the
    turn by 36.87° (cos 0.8, sin 0.6): X = (0.15, 4.95).  A 1 % slip is still refused.
    """
    from spec_data import ROOT

    from graphkin.cli import main
    from graphkin.errors import InputError

    path = ROOT / "tests" / "data" / "audit8" / "three_postures_typed.toml"
    spec = loads_spec(path.read_text())
    np.testing.assert_allclose(np.degrees(spec.postures.angles),
                               [0.0, math.degrees(math.atan2(0.87, 1.8)), 36.86989764584402],
                               atol=1e-9)
    assert main(["synthesize", str(path), "--json"]) == 0
    poles = json.loads(capsys.readouterr().out)["poles"]
    np.testing.assert_allclose(poles["P31"], [0.15, 4.95], atol=1e-12)
    slip = path.read_text().replace("Q = [4.6, 2.1]", "Q = [4.6, 2.12]")   # PQ = 2.0199: 1 %
    try:
        loads_spec(slip)
    except InputError as exc:
        assert exc.key == "postures[2].Q" and "keeps its length" in str(exc)
    else:
        raise AssertionError("a 1 % slip of the body's length was accepted")
