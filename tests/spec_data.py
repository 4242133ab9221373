"""Where the test copies of the spec examples are, and their expected values.

``tests/data/spec/`` holds the project's own copies of the textbook examples
(mechanism files and ``expected.toml`` with their exact results), so that a
clone with nothing beside it runs every test.  ``benchmarks/bench_fourbar.toml``
is the sweep benchmark's four-bar.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "tests" / "data" / "spec"
BENCH = ROOT / "benchmarks" / "bench_fourbar.toml"


def _expected() -> dict:
    with open(EXAMPLES / "expected.toml", "rb") as fh:
        return tomllib.load(fh)


EXPECTED = _expected()
