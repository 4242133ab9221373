"""Point names that a construction label could be confused with are refused (issue 14).

The constructions name their own points from the file's: ``C#3`` (a construction
point, graphkin.kinematics.posture.fresh), ``sliders[0]:L0`` (a path's points),
``C@4`` (the point of link 4 at C, polygons.coincident), ``v(C)``/``a(C)`` (images),
``k_C(B)`` (a locus) and ``R_CB:B>C`` (a posture line).
"""

from __future__ import annotations

import pytest

import graphkin
from graphkin.mechanisms.parse import RESERVED_CHARACTERS


def _file(name: str) -> dict:
    return {"links": {"1": {"A": [0, 0], "D": [10, 0]},
                      "2": {"A": [0, 0], "B": [4, 0], name: [2, 1]},
                      "3": {"B": [0, 0], "C": [18, 0]},
                      "4": {"D": [0, 0], "C": [11, 0]}},
            "drive": {"link": 2, "angle": 120}, "assembly": {"C": [15, 10]}}


@pytest.mark.parametrize("name", ["C#1", "sliders[0]:L0", "B@3", "v(B)", "R>", "k_(B"])
def test_reserved_characters_are_refused(name):
    with pytest.raises(graphkin.InputError) as exc:
        graphkin.from_dict(_file(name), source="m.toml")
    assert exc.value.key == f"links.2.{name}"
    line = exc.value.one_line()
    assert "m.toml" in line and "cannot contain" in line and "\n" not in line


def test_the_reserved_characters_are_those_the_labels_use():
    # the posture's construction points and lines, and the polygons' images and
    # coincident points, of a slider-crank: every character in them that is not a letter,
    # digit or the book's marks is reserved
    sol = graphkin.examples.slider_crank().solve()
    labels = {o for cx in sol.constructions.values() for st in cx.steps for o in st.outputs}
    used = {c for lab in labels for c in lab if c in "#:@()>"}
    assert used <= set(RESERVED_CHARACTERS)
    assert {":", "(", ")", ">"} <= used  # "#" marks construction points (posture.fresh)


@pytest.mark.parametrize("name", ["E", "C'", "B_2", "P1", "Q-3"])
def test_ordinary_names_are_accepted(name):
    mech = graphkin.from_dict(_file(name))
    assert name in mech.point_names
