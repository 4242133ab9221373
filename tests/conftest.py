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

Nor do the CI examples draw on the constants of the code under test.
Hypothesis (6.1xx) mixes into its examples the numeric constants of every
local module loaded so far: a constant added anywhere in graphkin, or a test
module imported earlier in the run, changed which examples a derandomized test
drew, and a commit that touched nothing near a test turned it red (session 15:
a collision of a six-bar's link number, present before, drawn only after
``render/labels.py`` gained a constant).  Under the ``ci`` profile that pool
is empty, so each test's examples depend on its own strategy alone.
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


def _no_local_constants() -> None:
    """Keep the code's own constants out of the derandomized examples (see above)."""
    try:
        from hypothesis.internal.conjecture import providers
    except ImportError:  # pragma: no cover - another Hypothesis layout
        return
    if hasattr(providers, "_get_local_constants") and hasattr(providers, "Constants"):
        providers._get_local_constants = providers.Constants  # an empty pool, every time


if os.environ.get("CI"):
    _no_local_constants()


@pytest.fixture
def examples() -> Path:
    return EXAMPLES
