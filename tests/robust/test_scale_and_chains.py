"""Branch choice: local, near-linear, and the same at any scale and offset (issue 14).

The chains come from ``tests/chains.py``, which computes their posture by
plain circle intersections; the timings are in ``benchmarks/bench_large.py``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from chains import chain_posture, driven_cranks, fourbar_chain

import graphkin
from graphkin.mechanisms import from_dict

# Example 3.2's offset slider-crank (graphkin.examples.slider_crank): crank AB = 50,
# coupler BC = 140, the slider line 20 below A, the slider at x = 164.
# Hand derivation of B: |B| = 50, |B - (164, -20)| = 140; subtracting the circle equations,
# 328 x - 40 y = 164² + 20² + 50² - 140² = 10196, i.e. y = 8.2 x - 254.9; with x² + y² = 2500:
# 68.24 x² - 4180.36 x + 62474.01 = 0, x = (4180.36 ± 650.0) / 136.48, so the branches are
# B ≈ (35.392, 35.318) above the slider line's side or (25.867, -42.789) below.
ABOVE, BELOW = (35.392, 35.318), (25.867, -42.789)


def slider_crank(scale: float, offset: float, hint: tuple[float, float]) -> dict:
    def p(x: float, y: float, moved: bool = True) -> list[float]:
        o = offset if moved else 0.0
        return [x * scale + o, y * scale + o]

    return {
        "links": {"1": {"A": p(0, 0), "S": p(0, -20), "T": p(100, -20)},
                  "2": {"A": p(0, 0, False), "B": p(50, 0, False)},
                  "3": {"B": p(0, 0, False), "C": p(140, 0, False)},
                  "4": {"C": p(0, 0, False)}},
        "sliders": [{"link": 4, "on": 1, "point": "C", "line": ["S", "T"]}],
        "drive": {"link": 4, "position": 164 * scale},
        "assembly": {"B": p(*hint)},
    }


# (scale, offset): scaled by 1e-12 ... 1e12, moved 1e9 mm, and moved ~1e7 of its own size
@pytest.mark.parametrize("scale,offset", [(1.0, 0.0), (1e-12, 0.0), (1e-6, 0.0), (1e6, 0.0),
                                          (1e12, 0.0), (1.0, 1e9), (1.0, -1e9), (1e-6, 1.0),
                                          (1e-12, 1e-5), (1e6, 1e15)])
@pytest.mark.parametrize("hint,expected", [(ABOVE, ABOVE), (BELOW, BELOW)])
def test_hints_are_obeyed_at_any_scale_and_offset(scale: float, offset: float, hint: tuple,
                                                   expected: tuple) -> None:
    sol = from_dict(slider_crank(scale, offset, hint)).solve()
    b = (np.asarray(sol.position("B")) - offset) / scale
    assert np.hypot(*(b - expected)) < 0.01, (b, expected)
    assert not sol.notes, sol.notes


@pytest.mark.parametrize("stages", [1, 3, 14])
def test_a_chain_of_four_bars_takes_every_hinted_branch(stages: int) -> None:
    mech = graphkin.loads(fourbar_chain(stages))
    sol = mech.solve()
    assert len(mech.links) == 2 + 2 * stages
    for k, s in enumerate(chain_posture(stages)):
        # chain_posture intersects the circles itself (left of B→D: the hinted branch)
        assert math.dist(sol.position(f"C{k}"), s["C"]) < 1e-9 * 10 * stages


def test_a_chain_without_hints_keeps_the_drawing() -> None:
    # the file is drawn at its posture, so "nearest the file's drawing" is that posture
    sol = graphkin.loads(fourbar_chain(6, hints=False)).solve()
    for k, s in enumerate(chain_posture(6)):
        assert math.dist(sol.position(f"C{k}"), s["C"]) < 1e-9 * 60


def test_many_driven_cranks() -> None:
    sol = graphkin.loads(driven_cranks(40)).solve()
    for i in range(40):
        a = math.radians((7 * i) % 360)
        # P_i is 3 from its pivot O_i = (10 i, 0), turned by its drive angle
        assert math.dist(sol.position(f"P{i}"), (10 * i + 3 * math.cos(a), 3 * math.sin(a))) \
            < 1e-12 * 400
