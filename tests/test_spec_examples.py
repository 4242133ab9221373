"""Every spec example gives the values of expected.toml (exact geometry; see its comments).

The expected values are exact results for the geometry in each file, derived
independently of graphkin (the comments in expected.toml give what the
textbook prints beside them).
"""

from __future__ import annotations

import math

import pytest
from spec_data import EXAMPLES, EXPECTED

import graphkin
from graphkin.output import solution_to_dict

CASES = [(f, k, v) for f, checks in EXPECTED.items() for k, v in checks.items()]


def _lookup(obj, path):
    mag = path.endswith("|")
    for part in path.rstrip("|").split("."):
        obj = obj[part]
    return math.hypot(*obj) if mag else obj


_SOLVED: dict[str, dict] = {}


def _solved(fname: str) -> dict:
    if fname not in _SOLVED:
        _SOLVED[fname] = solution_to_dict(graphkin.load(EXAMPLES / fname).solve())
    return _SOLVED[fname]


@pytest.mark.parametrize("fname,key,want", CASES, ids=[f"{f}:{k}" for f, k, _ in CASES])
def test_spec_example_value(fname, key, want):
    value, tol = want
    got = _lookup(_solved(fname), key)
    if isinstance(value, list):
        assert got is not None and len(got) == len(value)
        for g, w in zip(got, value):
            assert abs(g - w) <= tol, (got, value)
    elif key.endswith("angle"):
        assert abs((got - value + 180) % 360 - 180) <= tol
    else:
        assert abs(got - value) <= tol
