"""Where the test copies of the spec examples are, and their expected values.

``tests/data/spec/`` holds the project's own copies of the textbook examples
(mechanism files and ``expected.toml`` with their exact results), so that a
clone with nothing beside it runs every test.  ``benchmarks/bench_fourbar.toml``
is the sweep benchmark's four-bar.  ``tests/data/inline/`` holds the small
mechanism (and answers) files the tests write variations of (``inline(name)`` reads one as
text), so that the same file is not written out again in each test module.
"""

from __future__ import annotations

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "tests" / "data" / "spec"
BENCH = ROOT / "benchmarks" / "bench_fourbar.toml"
INLINE = ROOT / "tests" / "data" / "inline"


def inline(name: str) -> str:
    """The text of a small test mechanism file in ``tests/data/inline/``."""
    return (INLINE / name).read_text(encoding="utf-8")


def _expected() -> dict:
    with open(EXAMPLES / "expected.toml", "rb") as fh:
        return tomllib.load(fh)


EXPECTED = _expected()
