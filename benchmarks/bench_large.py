"""Time the posture solve of large mechanisms: chains of four-bars and many driven cranks.

Usage::

    python benchmarks/bench_large.py [--stages 4 8 14 30 100] [--cranks 100 300 1000]

The files come from ``tests/chains.py`` (a chain of ``k`` four-bar stages has
``2 + 2k`` links; 14 stages are 30 links; ``n`` driven cranks are ``n + 1``
links).  Each branch is chosen locally from the assembly hints, so the time
should grow about linearly with the number of links (issue 14: 30 links under
1 s, 1000 links under 5 s).  ``solve`` times ``mech.solve()`` (positions,
velocity and acceleration polygons); ``report`` what ``graphkin solve`` does
(read the file, solve, the text report with the instant centers, n(n-1)/2 of
them, and the curvature of every link); ``json`` what ``graphkin solve --json``
does.  Beyond 1000 instant centers (46 links) the report finds them all at
once from the velocities (graphkin.kinematics.instant_centers.direct) instead
of step by step.  CPU seconds; nothing is asserted.
"""

from __future__ import annotations

import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent.parent / "tests"))

from chains import driven_cranks, fourbar_chain  # noqa: E402
from timing import best  # benchmarks/timing.py

import graphkin  # noqa: E402


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--stages", type=int, nargs="*", default=[4, 8, 14, 30, 100])
    ap.add_argument("--cranks", type=int, nargs="*", default=[100, 300, 1000])
    ap.add_argument("--report", action="store_true", help="also time the text report")
    args = ap.parse_args()
    import json

    from graphkin.output import solution_to_dict, text_report

    def report(text: str) -> None:
        text_report(graphkin.loads(text).solve())

    def as_json(text: str) -> None:
        json.dumps(solution_to_dict(graphkin.loads(text).solve()), ensure_ascii=False)

    print(f"{'mechanism':<28}{'links':>7}{'solve s':>10}{'report s':>10}{'json s':>10}")
    cases = [(f"chain of {k} four-bars", fourbar_chain(k), 3) for k in args.stages]
    cases += [(f"{n} driven cranks", driven_cranks(n), 1) for n in args.cranks]
    for name, text, repeat in cases:
        mech = graphkin.loads(text)
        t = best(mech.solve, repeat)
        r = best(lambda x=text: report(x), 1) if args.report else float("nan")
        j = best(lambda x=text: as_json(x), 1) if args.report else float("nan")
        print(f"{name:<28}{len(mech.links):>7}{t:>10.3f}{r:>10.3f}{j:>10.3f}")


if __name__ == "__main__":
    main()
