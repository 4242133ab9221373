"""A mechanism whose lengths span more than the tolerances can hold gets the right message.

A coupler point at 1e14 on a mechanism of size ~10 used to end with "the posture is
singular": the tolerances, 1e-9 of the size, swallowed the short links.  The class is
the ratio of the longest to the shortest length (graphkin.mechanisms.parse.MAX_RANGE),
whatever the point, link or offset.
"""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.mechanisms.parse import MAX_RANGE


def _fourbar(far: float, where: str = "3", offset: float = 0.0) -> dict:
    links = {"1": {"A": [offset, offset], "D": [offset + 10, offset]},
             "2": {"A": [0, 0], "B": [4, 0]},
             "3": {"B": [0, 0], "C": [18, 0]},
             "4": {"D": [0, 0], "C": [11, 0]}}
    links[where]["E"] = [far, -far]
    return {"links": links, "drive": {"link": 2, "angle": 120, "omega": 10},
            "assembly": {"B": [offset - 2, offset + 3.5], "C": [offset + 15, offset + 10]}}


@settings(max_examples=30, deadline=None)
@given(exponent=st.floats(10, 15), where=st.sampled_from(["2", "3", "4"]))
def test_a_point_far_beyond_the_range_is_named(exponent, where):
    far = 10.0 ** exponent
    with pytest.raises(graphkin.InputError) as exc:
        graphkin.from_dict(_fourbar(far, where), source="m.toml")
    line = exc.value.one_line()
    assert f"links.{where}.E" in line and "singular" not in line
    assert "shortest length" in line


@pytest.mark.parametrize("far", [1e3, 1e5, MAX_RANGE / 20])
def test_a_far_point_within_the_range_is_solved(far):
    # E = (far, −far) in link 3's own coordinates: its distance from B is far·√2, and
    # the rigid link carries it: |R_E − R_B| = far·√2 at any posture
    mech = graphkin.from_dict(_fourbar(far))
    sol = mech.solve()
    d = sol.position("E") - sol.position("B")
    assert float((d @ d) ** 0.5) == pytest.approx(far * 2 ** 0.5, rel=1e-9)


def test_an_offset_mechanism_is_not_a_range_problem():
    # moved 1e9 from the origin, its lengths still span 10 to 18: it is solved
    sol = graphkin.from_dict(_fourbar(5.0, offset=1e9)).solve()
    d = sol.position("C") - sol.position("B")
    assert float((d @ d) ** 0.5) == pytest.approx(18.0, rel=1e-6)
