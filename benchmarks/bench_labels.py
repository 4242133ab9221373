"""Time the drawing of a four-bar whose coupler carries many lettered points (issue 11).

Label placement scores a ring of positions per label against a raster of the
panel's ink (a summed-area table), so its cost grows linearly with the number
of labels.  Run::

    python benchmarks/bench_labels.py            # 300 coupler points
    python benchmarks/bench_labels.py 50 100 300

It prints the CPU and wall time of solving, drawing (placing every label) and
writing the SVG, for the posture, the velocity polygon and the default sheet
(``all``: what ``graphkin draw FILE -o x.svg`` draws).  Nothing is asserted;
the target (issues 11 and 24) is under 10 s for 300 points.

Measured for 300 points, ``all``, CPU seconds on the shared 2-core machine
(loaded): 19.6 s for the whole ``graphkin draw`` before issue 24's second
round, 10.7 s after it (curvature's choice of two candidate points over all
pairs at once instead of 46 000 Python iterations, label sizes measured once
per digit pattern, the ring and grid of label places scored by one look-up,
one clip box per panel instead of one per artist).
"""

from __future__ import annotations

import math
import sys
import time

import graphkin
from graphkin.render import draw, to_bytes

FOURBAR = """
title = "Four-bar with {n} coupler points"
units = {{ length = "in" }}
[links.1]
A = [0, 0]
D = [10, 0]
[links.2]
A = [0, 0]
B = [4, 0]
[links.3]
B = [0, 0]
C = [18, 0]
{points}
[links.4]
D = [0, 0]
C = [11, 0]
[drive]
link = 2
angle = 120
omega = "900 rev/min"
alpha = 0
[assembly]
C = [15, 10]
"""


def coupler(n: int) -> graphkin.Mechanism:
    """A four-bar (Example 3.1) with ``n`` points on an ellipse on its coupler."""
    pts = "\n".join(f"P{i} = [{9 + 6 * math.cos(2 * math.pi * i / n):.4f}, "
                    f"{-2 + 5 * math.sin(2 * math.pi * i / n):.4f}]" for i in range(n))
    return graphkin.loads(FOURBAR.format(n=n, points=pts))


def main(counts: list[int]) -> None:
    for n in counts:
        sol = coupler(n).solve()
        for diagram in ("posture", "velocity", "all"):
            c0, w0 = time.process_time(), time.perf_counter()
            data = to_bytes(draw(sol, diagram).figure)
            c1, w1 = time.process_time(), time.perf_counter()
            print(f"{n:5d} points  {diagram:9s} cpu {c1 - c0:6.2f} s  wall {w1 - w0:6.2f} s  "
                  f"({len(data) // 1024} kB SVG)")


if __name__ == "__main__":
    main([int(a) for a in sys.argv[1:]] or [300])
