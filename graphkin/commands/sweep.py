"""``graphkin sweep FILE [--from DEG] [--to DEG] [--count N] --csv OUT.csv``: whole cycles.

The contract is ``spec/sweep.md``: one CSV row per posture, the drive first,
then every link's angle, ω and α, then every named point's position,
velocity and acceleration; empty cells where the mechanism cannot be
assembled, reported once on standard error as a range of the drive.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

__all__ = ["add_parser", "run"]

#: Sweeps at least this long get a progress bar (when standard error is a terminal).
PROGRESS_FROM = 200_000


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = sub.add_parser(
        "sweep", help="solve a mechanism over a whole cycle of its drive and write a CSV",
        description="Solve a mechanism at many values of its (first) drive at once, by the same "
                    "constructions as solve, and write one CSV row per posture. Other drives are "
                    "held at the file's values.")
    p.add_argument("file", help="mechanism file (TOML)")
    p.add_argument("--from", dest="start", type=float, default=None, metavar="DEG",
                   help="first drive value: degrees, or a slider's travel (default: the file's)")
    p.add_argument("--to", dest="stop", type=float, default=None, metavar="DEG",
                   help="end of the range, excluded (default: one full turn on; for a slider, "
                        "the end of the travel over which the mechanism assembles)")
    p.add_argument("--count", type=int, default=360, metavar="N",
                   help="number of postures (default 360)")
    p.add_argument("--csv", default="-", metavar="OUT.csv",
                   help="where to write the CSV (default: standard output)")
    p.add_argument("--transmission", action="store_true",
                   help="add the transmission angle at every pin found by two arcs "
                        "(transmission_<P>, degrees)")
    p.add_argument("--centers", action="store_true",
                   help="add every instant center (x_I13, y_I13; dx_/dy_ for one at infinity)")
    p.add_argument("--curvature", action="store_true",
                   help="add radii and centers of curvature of the paths (rho_P, cx_P, cy_P) and "
                        "the inflection poles and diameters of the links")
    p.add_argument("--torque", action="store_true",
                   help="add the drive's torque (torque_2) or input force (force_4) that holds "
                        "the loads and inertia forces of the file (docs/forces.md)")
    p.add_argument("--joint-forces", action="store_true",
                   help="with --torque: also the magnitude of every joint force (F_3-4)")
    p.add_argument("--singular", action="store_true",
                   help="also report dead centers, limit positions and Grashof's classification "
                        "on standard error")
    return p


def _progress(frac: float) -> None:
    width = 30
    done = int(round(width * frac))
    sys.stderr.write(f"\rsweep [{'#' * done}{' ' * (width - done)}] {100 * frac:5.1f}%")
    if frac >= 1.0:
        sys.stderr.write("\n")
    sys.stderr.flush()


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    import graphkin
    from graphkin.errors import InputError
    from graphkin.kinematics.sweep import grashof, sweep

    mech = graphkin.load(args.file)
    if args.count < 1:
        raise InputError(f"--count must be at least 1, not {args.count}", key="count",
                         file=args.file)
    progress: Any = None
    if args.count >= PROGRESS_FROM and sys.stderr.isatty():
        progress = _progress
    sw = sweep(mech, count=args.count, start=args.start, stop=args.stop,
               transmission=args.transmission, centers=args.centers, curvature=args.curvature,
               progress=progress)
    if args.torque or args.joint_forces:
        from graphkin.forces.sweep import force_columns

        sw.columns.update(force_columns(sw, joints=args.joint_forces))
    if args.csv == "-":
        sw.to_csv(sys.stdout)
    else:
        try:
            sw.to_csv(args.csv)
        except OSError as exc:
            raise InputError(f"cannot write the CSV: {exc.strerror}", key="csv",
                             file=args.csv) from None
    for line in sw.report(events=args.singular):
        print(f"graphkin: {args.file}: {line}", file=sys.stderr)
    if args.singular:
        try:
            print(f"graphkin: {args.file}: Grashof: {grashof(mech)}", file=sys.stderr)
        except InputError:
            pass
    return 0
