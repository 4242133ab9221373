"""What the benchmark scripts share: the best CPU time of a call.

The scripts run as ``python benchmarks/bench_*.py``, so this folder is on the
path and ``from timing import best`` finds this module.
"""

from __future__ import annotations

import time
from collections.abc import Callable


def best(fn: Callable[[], object], repeat: int = 3) -> float:
    """The least CPU time (``time.process_time``) of ``repeat`` calls of ``fn``."""
    least = float("inf")
    for _ in range(repeat):
        t = time.process_time()
        fn()
        least = min(least, time.process_time() - t)
    return least
