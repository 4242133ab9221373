"""Where the shared spec examples are, and their expected values."""

from __future__ import annotations

import tomllib
from pathlib import Path

SPEC = Path(__file__).resolve().parents[2] / "shared" / "spec"
EXAMPLES = SPEC / "examples"


def _expected() -> dict:
    path = EXAMPLES / "expected.toml"
    if not path.exists():
        return {}
    with open(path, "rb") as fh:
        return tomllib.load(fh)


EXPECTED = _expected()
