"""Time the step-by-step page of a curvature construction (issue 24).

Run::

    python benchmarks/bench_steps.py                 # Example 3.1, -d curvature

It prints the CPU and wall time of ``steps_html`` and the page's size.
Nothing is asserted; the target is under 10 s.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import graphkin
from graphkin.render.teach import steps_html

EX = Path(__file__).resolve().parents[1] / "tests" / "data" / "spec" / "ex3_1_fourbar.toml"


def main(path: Path, diagram: str) -> None:
    sol = graphkin.load(path).solve()
    c0, w0 = time.process_time(), time.perf_counter()
    page = steps_html(sol, diagram)
    c1, w1 = time.process_time(), time.perf_counter()
    print(f"steps -d {diagram}: cpu {c1 - c0:6.2f} s  wall {w1 - w0:6.2f} s  "
          f"({len(page.encode()) // 1024} kB)")


if __name__ == "__main__":
    main(Path(sys.argv[1]) if len(sys.argv) > 1 else EX,
         sys.argv[2] if len(sys.argv) > 2 else "curvature")
