"""Time the graphic layout of a cam profile by inversion (issue 27: 3600 points < 50 ms).

Usage::

    python benchmarks/bench_cams.py [--count 3600] [--repeat 10]

For every follower kind: the recorded layout (``graphkin.cams.layout``) built
once and evaluated on ``--count`` stations at once (the displacement diagram
read at those angles included), against the analytic profile of Secs.
6.9-6.10 at the same angles.  CPU times, best of ``--repeat``; nothing is asserted.
"""

from __future__ import annotations

import argparse
import dataclasses

from timing import best  # benchmarks/timing.py

from graphkin.cams import Follower, FollowerKind, layout, profile, stations
from graphkin.cams.examples import example_6_6, example_6_7


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--count", type=int, default=3600)
    ap.add_argument("--repeat", type=int, default=10)
    args = ap.parse_args()
    th = stations(args.count)
    cams = {}
    for kind in FollowerKind:
        if kind.oscillating:
            base = example_6_7()
            cams[kind] = dataclasses.replace(base, follower=dataclasses.replace(
                base.follower, kind=kind, face_offset=0.1))
        else:
            cams[kind] = dataclasses.replace(example_6_6(), follower=Follower(
                kind, roller=12.0, offset=5.0))
    for kind, cam in cams.items():
        lay = layout(cam)
        lay.contact(th)                       # compile once
        t_lay = best(lambda lay=lay: lay.contact(th), args.repeat)
        t_new = best(lambda cam=cam: layout(cam).contact(th), args.repeat)
        t_ana = best(lambda cam=cam: profile(cam, th), args.repeat)
        print(f"{kind.value:22s} layout of {args.count} points: {t_lay * 1e3:6.2f} ms "
              f"(recorded afresh {t_new * 1e3:6.2f} ms); analytic {t_ana * 1e3:6.2f} ms")


if __name__ == "__main__":
    main()
