"""Time ``mech.sweep(count=3600)`` against a closed-form numpy four-bar (and pylinkage).

Usage::

    python benchmarks/bench_sweep.py [--count 3600] [--repeat 30] [FILE]

All three do the same work for every posture of one turn of the crank of
``benchmarks/bench_fourbar.toml``: positions, velocities and accelerations of every
point (and every link's angle, ω, α).  The closed form is Freudenstein's
equation with the loop-closure derivatives (``fourbar_closed_form.py``); it
produces the same CSV columns.  pylinkage is timed if it is installed (its
solver is compiled with numba when numba is installed, pure Python
otherwise: the report says which).

Times are CPU times of this process (``time.process_time``), the best of
``--repeat`` interleaved rounds, so that other programs on the machine
disturb them as little as possible.  The ratios are printed; nothing is asserted.
"""

from __future__ import annotations

import argparse
import gc
import importlib.util
import math
import pathlib
import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
DEFAULT = pathlib.Path(__file__).resolve().parent / "bench_fourbar.toml"


def _closed_form_module() -> Any:
    spec = importlib.util.spec_from_file_location("fourbar_closed_form",
                                                  HERE / "fourbar_closed_form.py")
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    sys.modules["fourbar_closed_form"] = mod
    spec.loader.exec_module(mod)
    return mod


def best_time(fn: Callable[[], Any], number: int) -> float:
    """CPU seconds of one call: the best of one round of ``number`` calls."""
    t0 = time.process_time()
    for _ in range(number):
        fn()
    return (time.process_time() - t0) / number


def pylinkage_fourbar(mech: Any, count: int) -> Callable[[], Any] | None:
    """A pylinkage model of the bench four-bar, or None when pylinkage is missing."""
    try:
        import pylinkage as pl
    except ImportError:
        return None
    pts = {lid: link.points for lid, link in mech.links.items()}
    d = mech.drives[0]
    a, dd = pts["1"]["A"], pts["1"]["D"]
    r2 = math.dist(pts["2"]["A"], pts["2"]["B"])
    r3 = math.dist(pts["3"]["B"], pts["3"]["C"])
    r4 = math.dist(pts["4"]["D"], pts["4"]["C"])
    hint = mech.assembly["C"]
    A = pl.Ground(*a, name="A")
    D = pl.Ground(*dd, name="D")
    B = pl.Crank(A, r2, angular_velocity=2 * math.pi / count, initial_angle=d.value, name="B")
    C = pl.RRRDyad(B, D, r3, r4, x=hint[0], y=hint[1], name="C")
    others = []
    for name, (lid, p, q) in {"E": ("3", "B", "C"), "F": ("4", "D", "C")}.items():
        loc = pts[lid]
        u = np.subtract(loc[q], loc[p])
        v = np.subtract(loc[name], loc[p])
        ang = math.atan2(v[1], v[0]) - math.atan2(u[1], u[0])
        anchor = B if p == "B" else D
        others.append(pl.FixedDyad(anchor, C, math.hypot(*v), ang, name=name))
    lk = pl.Linkage([A, D, B, C, *others], name="bench")
    lk.set_input_velocity(B, omega=d.rate, alpha=d.rate2 or 0.0)

    def run() -> Any:
        return lk.step_fast_with_kinematics(iterations=count)

    return run


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("file", nargs="?", default=str(DEFAULT))
    ap.add_argument("--count", type=int, default=3600)
    ap.add_argument("--repeat", type=int, default=30)
    ap.add_argument("--number", type=int, default=5)
    ap.add_argument("--no-pylinkage", action="store_true")
    args = ap.parse_args(argv)

    import graphkin

    cf = _closed_form_module()
    mech = graphkin.load(args.file)
    d = mech.drives[0]
    fb = cf.fourbar_from_mechanism(mech)
    theta = d.value + 2 * math.pi * np.arange(args.count) / args.count

    t0 = time.process_time()
    sw = mech.sweep(count=args.count)
    cold = time.process_time() - t0

    # the same numbers, at a few postures
    ref = fb.solve(theta, d.rate, d.rate2 or 0.0)
    worst = max(float(np.max(np.abs(sw.columns[k] - ref[k]) / (1.0 + np.abs(ref[k]))))
                for k in ref)

    def graphkin_sweep() -> Any:
        return mech.sweep(count=args.count)

    def closed_form() -> Any:
        return fb.solve(theta, d.rate, d.rate2 or 0.0)

    cands: dict[str, Callable[[], Any]] = {"graphkin": graphkin_sweep, "closed form": closed_form}
    best = {k: math.inf for k in cands}
    gc.collect()
    gc.disable()
    try:
        for _ in range(args.repeat):
            for name, fn in cands.items():
                best[name] = min(best[name], best_time(fn, args.number))
    finally:
        gc.enable()

    pyl = None if args.no_pylinkage else pylinkage_fourbar(mech, args.count)
    pyl_time = None
    if pyl is not None:
        pyl()
        pyl_time = min(best_time(pyl, 1) for _ in range(3))

    g, c = best["graphkin"], best["closed form"]
    print(f"{args.count} postures of {pathlib.Path(args.file).name}: positions, velocities and "
          f"accelerations of every point ({len(sw.columns)} columns)")
    print(f"  graphkin mech.sweep       {g * 1e3:9.3f} ms   (first call, building the "
          f"constructions: {cold * 1e3:.1f} ms)")
    print(f"  closed-form numpy         {c * 1e3:9.3f} ms")
    print(f"  ratio graphkin/closed     {g / c:9.2f}   (goal 1.5, acceptance 2)")
    print(f"  largest difference        {worst:9.1e}   (relative, over every column)")
    if pyl_time is not None:
        try:
            import numba  # noqa: F401
            how = "numba-compiled"
        except ImportError:
            how = "pure Python: numba is not installed"
        print(f"  pylinkage ({how}) {pyl_time * 1e3:9.1f} ms   ratio pylinkage/graphkin "
              f"{pyl_time / g:.1f}")
    elif args.no_pylinkage:
        print("  pylinkage                 not timed (--no-pylinkage)")
    else:
        print("  pylinkage                 not installed (pip install pylinkage)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
