"""Shared fixtures, and the Hypothesis profiles.

Hypothesis runs derandomized under CI (``CI`` set, as ``.ci/run`` runs): the
same examples on every machine and every run, so a red CI is never luck.
Locally it draws new random examples each run (the ``dev`` profile) and keeps
what fails in its example database; every failure ever found is pinned to
its test with ``@example``.  Choose one with ``--hypothesis-profile``.

Neither profile has a deadline: an example slower than 200 ms on a loaded or
slower machine made Hypothesis hunt for a "failing" example by shrinking, and
the hunt tried other examples than the derandomized run's, so the same commit
went red on one machine and green on another.  Timings are measured in
benchmarks/, never asserted in a test.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import settings
from spec_data import EXAMPLES

settings.register_profile("ci", derandomize=True, database=None, print_blob=True,
                          deadline=None)
settings.register_profile("dev", print_blob=True, deadline=None)
settings.load_profile("ci" if os.environ.get("CI") else "dev")


@pytest.fixture
def examples() -> Path:
    return EXAMPLES
