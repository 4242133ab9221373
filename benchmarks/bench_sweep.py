"""graphkin's sweeps and batches against a closed-form numpy four-bar (and pylinkage).

Usage::

    python benchmarks/bench_sweep.py [--rounds 15] [--markdown] [--no-pylinkage] [FILE]

Every contestant does the same work on the four-bar of ``bench_fourbar.toml``:
positions, velocities and accelerations of every point and every link's
angle, ω and α, for

* one design at 36, 360, 3600 and 360 000 postures of a turn of the crank
  (``mech.sweep``), and
* 1000 designs (coupler and rocker lengths) x 360 postures (``graphkin.batch``),

against the closed form (Freudenstein's equation with the loop-closure
derivatives, ``fourbar_closed_form.py``; it produces the same columns, one
design or ``(designs, postures)`` arrays).  The instant-center and curvature
columns of a 3600-posture sweep are timed against the plain sweep, and a
36-posture sweep whose constructions are written out as one function
(``graphkin/construction/codegen.py``) against the same sweep replayed step
by step.
pylinkage's fast path (``Linkage.step_fast_with_kinematics``) is timed if it
is installed (compiled with numba when numba is installed, pure Python
otherwise: the report says which), and skipped otherwise.

Times are CPU times of this process (``time.process_time``), the best of
``--rounds`` interleaved rounds, so that the other programs on a shared
machine disturb them as little as possible; pylinkage, much slower, is timed
over fewer rounds.  The ratios are printed; nothing is asserted (the tests
check the numbers, never the times).
"""

from __future__ import annotations

import argparse
import gc
import importlib.util
import math
import os
import pathlib
import platform
import sys
import time
from collections.abc import Callable
from typing import Any

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
DEFAULT = HERE / "bench_fourbar.toml"
COUNTS = (36, 360, 3600, 360_000)
DESIGNS, DESIGN_POSTURES = 1000, 360


def _closed_form_module() -> Any:
    spec = importlib.util.spec_from_file_location("fourbar_closed_form",
                                                  HERE / "fourbar_closed_form.py")
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    sys.modules["fourbar_closed_form"] = mod
    spec.loader.exec_module(mod)
    return mod


def cpu_time(fn: Callable[[], Any], number: int) -> float:
    """CPU seconds of one call, averaged over ``number`` calls."""
    t0 = time.process_time()
    for _ in range(number):
        fn()
    return (time.process_time() - t0) / number


def best_of(cands: dict[str, Callable[[], Any]], rounds: int, number: int) -> dict[str, float]:
    """The best CPU time of each candidate over interleaved rounds."""
    best = {k: math.inf for k in cands}
    gc.collect()
    gc.disable()
    try:
        for _ in range(rounds):
            for name, fn in cands.items():
                best[name] = min(best[name], cpu_time(fn, number))
    finally:
        gc.enable()
    return best


def pylinkage_fourbar(mech: Any, count: int, lengths: tuple[float, float] | None = None
                      ) -> Callable[[], Any] | None:
    """pylinkage's model of the bench four-bar (coupler and rocker lengths), or None."""
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
    if lengths is not None:
        r3, r4 = lengths
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


def machine() -> str:
    """One line: CPU model, cores, Python, numpy."""
    model = platform.processor() or platform.machine()
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                model = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return (f"{model}, {os.cpu_count()} cores, Python {platform.python_version()}, "
            f"numpy {np.__version__}")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("file", nargs="?", default=str(DEFAULT))
    ap.add_argument("--rounds", type=int, default=15)
    ap.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    ap.add_argument("--no-pylinkage", action="store_true")
    args = ap.parse_args(argv)

    import graphkin

    cf = _closed_form_module()
    mech = graphkin.load(args.file)
    d = mech.drives[0]
    w, al = d.rate, d.rate2 or 0.0
    fb = cf.fourbar_from_mechanism(mech)
    rows: list[tuple[str, float, float, str]] = []  # case, graphkin, closed form, pylinkage
    pyl_ok = not args.no_pylinkage and pylinkage_fourbar(mech, 4) is not None
    try:
        import numba  # noqa: F401
        pyl_how = "numba"
    except ImportError:
        pyl_how = "pure Python"

    for count in COUNTS:
        theta = d.value + 2 * math.pi * np.arange(count) / count
        sw = mech.sweep(count=count)
        ref = fb.solve(theta, w, al)
        worst = max(float(np.max(np.abs(sw.columns[k] - ref[k]) / (1.0 + np.abs(ref[k]))))
                    for k in ref)
        assert worst < 1e-8, worst
        number = max(1, 20_000 // count)
        rounds = args.rounds if count < 100_000 else max(3, args.rounds // 3)
        best = best_of({"g": lambda c=count: mech.sweep(count=c),
                        "c": lambda t=theta: fb.solve(t, w, al)}, rounds, number)
        pyl = ""
        if pyl_ok:
            run = pylinkage_fourbar(mech, count)
            assert run is not None
            run()
            pyl_rounds = 3 if count <= 3600 else 1
            pyl = f"{min(cpu_time(run, 1) for _ in range(pyl_rounds)) * 1e3:.3g} ms"
        rows.append((f"1 design, {count} postures", best["g"], best["c"], pyl))

    # a thousand designs
    r3 = np.linspace(10.0, 14.0, DESIGNS)
    r4 = np.linspace(9.0, 12.5, DESIGNS)
    dims = {"links.3.C": np.stack([r3, 0 * r3], 1), "links.4.C": np.stack([r4, 0 * r4], 1)}
    theta = d.value + 2 * math.pi * np.arange(DESIGN_POSTURES) / DESIGN_POSTURES
    fbb = cf.fourbar_batch(mech, dims)
    b = graphkin.batch(mech, dims, count=DESIGN_POSTURES)
    ref = fbb.solve(theta, w, al)
    for k, v in ref.items():
        v = np.broadcast_to(v, b.columns[k].shape)
        assert np.allclose(b.columns[k], v, rtol=1e-8, atol=1e-8 * (1 + np.abs(v).max())), k
    best = best_of({"g": lambda: graphkin.batch(mech, dims, count=DESIGN_POSTURES),
                    "c": lambda: fbb.solve(theta, w, al)}, max(3, args.rounds // 3), 1)
    pyl = ""
    if pyl_ok:
        runs = [pylinkage_fourbar(mech, DESIGN_POSTURES, (float(a), float(c)))
                for a, c in zip(r3, r4)]
        t0 = time.process_time()
        for run in runs:
            assert run is not None
            run()
        pyl = f"{(time.process_time() - t0) * 1e3:.3g} ms"
    rows.append((f"{DESIGNS} designs x {DESIGN_POSTURES} postures", best["g"], best["c"], pyl))

    # centers and curvature over a sweep
    extras = best_of({"plain": lambda: mech.sweep(count=3600),
                      "centers": lambda: mech.sweep(count=3600, centers=True),
                      "curvature": lambda: mech.sweep(count=3600, curvature=True)},
                     args.rounds, 3)

    # the same 36-posture sweep with its constructions replayed step by step (the generated
    # function switched off): what writing them out saves
    from graphkin.kinematics.sweep.engine import _engine
    from graphkin.tolerance import DEFAULT_TOL

    eng = _engine(mech, DEFAULT_TOL)

    def replayed() -> Any:
        saved, eng.fast = eng.fast, None
        try:
            return mech.sweep(count=36)
        finally:
            eng.fast = saved

    small = best_of({"written": lambda: mech.sweep(count=36), "replayed": replayed},
                    args.rounds, 200)

    print(f"{pathlib.Path(args.file).name}: positions, velocities and accelerations of every "
          f"point; CPU time, best of {args.rounds} interleaved rounds")
    print(f"machine: {machine()}")
    pyl_head = f"pylinkage ({pyl_how})" if pyl_ok else "pylinkage (not installed)"
    if args.markdown:
        print(f"\n| case | graphkin | closed-form numpy | ratio | {pyl_head} |")
        print("|---|---|---|---|---|")
        for case, g, c, p in rows:
            print(f"| {case} | {g * 1e3:.3g} ms | {c * 1e3:.3g} ms | {g / c:.2f} | {p} |")
        print("\n| 3600 postures | time | ratio to the plain sweep |")
        print("|---|---|---|")
        for k in ("plain", "centers", "curvature"):
            print(f"| sweep{'' if k == 'plain' else f' + {k}'} | {extras[k] * 1e3:.3g} ms | "
                  f"{extras[k] / extras['plain']:.2f} |")
        print("\n| 36 postures | time |\n|---|---|")
        print(f"| constructions written out (one generated function) | "
              f"{small['written'] * 1e3:.3g} ms |")
        print(f"| constructions replayed step by step | {small['replayed'] * 1e3:.3g} ms |")
        return 0
    print(f"\n  {'case':32s} {'graphkin':>11s} {'closed form':>12s} {'ratio':>6s}   {pyl_head}")
    for case, g, c, p in rows:
        print(f"  {case:32s} {g * 1e3:8.3f} ms {c * 1e3:9.3f} ms {g / c:6.2f}   {p}")
    print("\n  3600 postures: sweep + centers "
          f"{extras['centers'] / extras['plain']:.2f}x, + curvature "
          f"{extras['curvature'] / extras['plain']:.2f}x the plain sweep "
          f"({extras['plain'] * 1e3:.3f} ms)")
    print(f"  36 postures: constructions written out {small['written'] * 1e3:.3f} ms, replayed "
          f"step by step {small['replayed'] * 1e3:.3f} ms")
    return 0


if __name__ == "__main__":
    sys.exit(main())
