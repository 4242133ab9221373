"""The gear examples shipped in examples/gears (Examples 7.1, 7.3; Figs. 7.18, 7.21)."""

from __future__ import annotations

from pathlib import Path

import pytest

GEAR_EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "gears"


@pytest.fixture
def gear_examples() -> Path:
    return GEAR_EXAMPLES
