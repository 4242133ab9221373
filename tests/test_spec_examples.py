"""Every spec example gives the values of expected.toml (exact geometry; see its comments).

The expected values are exact results for the geometry in each file, derived
independently of graphkin (the comments in expected.toml give what the
textbook prints beside them).
"""

from __future__ import annotations

import pytest
from spec_data import EXAMPLES, EXPECTED, assert_expected, lookup, solved_json

CASES = [(f, k, v) for f, checks in EXPECTED.items() for k, v in checks.items()]


@pytest.mark.parametrize("fname,key,want", CASES, ids=[f"{f}:{k}" for f, k, _ in CASES])
def test_spec_example_value(fname, key, want):
    assert_expected(lookup(solved_json(EXAMPLES / fname), key), want, key)
