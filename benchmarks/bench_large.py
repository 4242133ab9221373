"""Time the posture solve of large mechanisms: chains of four-bars and many driven cranks.

Usage::

    python benchmarks/bench_large.py [--stages 4 8 14 30 100] [--cranks 100 300 1000]

The files come from ``tests/chains.py`` (a chain of ``k`` four-bar stages has
``2 + 2k`` links; 14 stages are 30 links; ``n`` driven cranks are ``n + 1``
links).  Each branch is chosen locally from the assembly hints, so the time
should grow about linearly with the number of links (issue 14: 30 links under
1 s, 1000 links under 5 s).  ``mech.solve()`` is timed (positions, velocity
and acceleration polygons); ``report`` adds the text report with every
instant center (n(n-1)/2 of them), which is printed for the chains only.
Nothing is asserted.
"""

from __future__ import annotations

import argparse
import pathlib
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "tests"))

from chains import driven_cranks, fourbar_chain  # noqa: E402

import graphkin  # noqa: E402


def best_of(fn, repeat: int = 3) -> float:
    """The best CPU time of ``repeat`` calls."""
    best = float("inf")
    for _ in range(repeat):
        t = time.process_time()
        fn()
        best = min(best, time.process_time() - t)
    return best


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--stages", type=int, nargs="*", default=[4, 8, 14, 30, 100])
    ap.add_argument("--cranks", type=int, nargs="*", default=[100, 300, 1000])
    ap.add_argument("--report", action="store_true", help="also time the text report")
    args = ap.parse_args()
    from graphkin.output import text_report

    print(f"{'mechanism':<28}{'links':>7}{'solve s':>10}{'report s':>10}")
    for k in args.stages:
        mech = graphkin.loads(fourbar_chain(k))
        t = best_of(mech.solve)
        r = best_of(lambda m=mech: text_report(m.solve()), 1) if args.report else float("nan")
        print(f"{f'chain of {k} four-bars':<28}{len(mech.links):>7}{t:>10.3f}{r:>10.3f}")
    for n in args.cranks:
        mech = graphkin.loads(driven_cranks(n))
        t = best_of(mech.solve, 1)
        print(f"{f'{n} driven cranks':<28}{len(mech.links):>7}{t:>10.3f}{'':>10}")


if __name__ == "__main__":
    main()
