"""Shared fixtures."""

from __future__ import annotations

from pathlib import Path

import pytest
from spec_data import EXAMPLES


@pytest.fixture
def examples() -> Path:
    if not EXAMPLES.exists():
        pytest.skip("the shared spec examples are not beside this checkout")
    return EXAMPLES
