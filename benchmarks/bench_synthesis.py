"""Four-posture Burmester curves (< 50 ms asked) and five-posture Burmester points.

The curves: the construction evaluated on 2001 values of t (6 ms of CPU, 12 ms with
the construction recorded, on the 2-core CI machine); the Burmester points: the roots
along the 1234 curve closed by regula falsi (0.11 s of CPU; 0.4 s before brackets that
jump through infinity were given up).

Run: ``python benchmarks/bench_synthesis.py``.
"""

from __future__ import annotations

import time

import numpy as np

from graphkin.synthesis import burmester_construction, burmester_points, curves, five_construction
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
    five = Postures(np.array([[0, 0], [1, 0.5], [2, 0.7], [2.8, 0.4], [3.5, -0.2]]),
                    np.radians([0, 20, 45, 70, 100]))
    cx5 = five_construction(five)
    burmester_points(five, cx=cx5)
    times = []
    for _ in range(5):
        t0 = time.process_time()
        burmester_points(five, cx=cx5)
        times.append(time.process_time() - t0)
    print(f"Burmester points of five postures: {1e3 * min(times):.0f} ms of CPU")


def _time(post: Postures, cx: object) -> float:
    t0 = time.perf_counter()
    curves(post, 2001, cx=cx)  # type: ignore[arg-type]
    return time.perf_counter() - t0


if __name__ == "__main__":
    main()
