"""Four-posture Burmester curves: the construction evaluated on 2001 values of t (< 50 ms asked).

Run: ``python benchmarks/bench_synthesis.py``.
"""

from __future__ import annotations

import time

import numpy as np

from graphkin.synthesis import burmester_construction, curves
from graphkin.synthesis.postures import Postures


def main() -> None:
    rng = np.random.default_rng(5)
    post = Postures(rng.normal(size=(4, 2)), rng.uniform(-2, 2, 4))
    t0 = time.perf_counter()
    cx = burmester_construction(post)
    curves(post, 2001, cx=cx)
    t1 = time.perf_counter()
    best = min(_time(post, cx) for _ in range(20))
    print(f"first (recording + compiling): {1e3 * (t1 - t0):.1f} ms; "
          f"curves of 2001 t: {1e3 * best:.2f} ms")


def _time(post: Postures, cx: object) -> float:
    t0 = time.perf_counter()
    curves(post, 2001, cx=cx)  # type: ignore[arg-type]
    return time.perf_counter() - t0


if __name__ == "__main__":
    main()
