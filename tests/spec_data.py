"""Where the test copies of the spec examples are, and their expected values.

``tests/data/spec/`` holds the project's own copies of the textbook examples
(mechanism files and ``expected.toml`` with their exact results), so that a
clone with nothing beside it runs every test.  ``benchmarks/bench_fourbar.toml``
is the sweep benchmark's four-bar.  ``tests/data/inline/`` holds the small
mechanism (and answers) files the tests write variations of (``inline(name)`` reads one as
text), so that the same file is not written out again in each test module.
"""

from __future__ import annotations

import functools
import math
import tomllib
from pathlib import Path
from typing import Any

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


def lookup(obj: Any, path: str) -> Any:
    """The value at a dotted ``path`` of a solution's JSON (``|`` at the end: its magnitude)."""
    mag = path.endswith("|")
    for part in path.rstrip("|").split("."):
        obj = obj[part]
    return math.hypot(*obj) if mag else obj


def assert_expected(got: Any, want: tuple[Any, float], key: str) -> None:
    """``got`` is the expected value within its tolerance (angles modulo 360°)."""
    value, tol = want
    if isinstance(value, list):
        assert got is not None and len(got) == len(value)
        for g, w in zip(got, value):
            assert abs(g - w) <= tol, (got, value)
    elif key.endswith("angle"):
        assert abs((got - value + 180) % 360 - 180) <= tol
    else:
        assert abs(got - value) <= tol


@functools.cache
def solved_json(path: Path) -> dict:
    """The JSON of a mechanism file solved (once per session)."""
    import graphkin
    from graphkin.output import solution_to_dict

    return solution_to_dict(graphkin.load(path).solve())


def assert_round_scales(sheet: Any) -> None:
    """Every panel of a handout page at a round scale: 1, 2 or 5 times a power of ten."""
    for p in sheet.panels:
        if p.scale is not None:
            mant = p.scale.value / 10 ** math.floor(math.log10(p.scale.value) + 1e-9)
            assert min(abs(mant - m) for m in (1.0, 2.0, 5.0)) < 1e-9, p.scale.text
