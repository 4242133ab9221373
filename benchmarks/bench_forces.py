"""Time the force analysis: one posture (graphic and matrix method) and a torque sweep.

Usage::

    python benchmarks/bench_forces.py [--count 3600] [--repeat 10]

Example 12.4's four-bar (``tests/data/forces/ex12_4_dynamic_fourbar.toml``): the
graphic construction with its superposition, the matrix method alone, and
the drive's torque over ``--count`` postures (the force construction built
once and replayed on the sweep's arrays, against a loop of one matrix solve
per posture).  CPU times, best of ``--repeat``; nothing is asserted.
"""

from __future__ import annotations

import argparse
import dataclasses
import math
import pathlib

from timing import best  # benchmarks/timing.py

import graphkin
from graphkin.forces import solve_forces
from graphkin.forces.sweep import force_columns

FILE = pathlib.Path(__file__).resolve().parents[1] / "tests" / "data" / "forces" / \
    "ex12_4_dynamic_fourbar.toml"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--count", type=int, default=3600)
    ap.add_argument("--repeat", type=int, default=10)
    args = ap.parse_args()
    mech = graphkin.load(FILE)
    sol = mech.solve()
    g = best(lambda: solve_forces(sol), args.repeat)
    a = best(lambda: solve_forces(sol, method="analytic"), args.repeat)
    print(f"one posture: graphic {g * 1e3:.2f} ms, matrix method {a * 1e3:.2f} ms")
    start = math.degrees(mech.drives[0].value)
    sw = mech.sweep(count=args.count, start=start - 40, stop=start + 40)
    s = best(lambda: force_columns(sw), max(1, args.repeat // 5))
    print(f"torque over {args.count} postures (replayed construction): {s * 1e3:.1f} ms "
          f"({s / args.count * 1e6:.1f} µs per posture)")
    n = min(args.count, 200)
    drives = sw.columns["drive"][:n]

    def loop() -> None:
        for deg in drives:
            d = dataclasses.replace(mech.drives[0], value=math.radians(float(deg)))
            solve_forces(dataclasses.replace(mech, drives=(d,)).solve(), method="analytic")

    lp = best(loop, 1)
    print(f"a Python loop of kinematics + matrix method: {lp / n * 1e6:.0f} µs per posture")


if __name__ == "__main__":
    main()
