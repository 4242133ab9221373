"""``graphkin sweep FILE [--from DEG] [--to DEG] [--count N] --csv OUT.csv``: whole cycles.

Solve a mechanism at many values of its (first) drive at once, by the same constructions
as solve, and write one CSV row per posture. Other drives are held at the file's values,
except those that follow the first by a law (follows = {link, ratio, offset} or a
table of pairs). --turn sweeps from 0° (or limit to limit) instead of the file's angle.

The contract is ``docs/formats/sweep-csv.md``: one CSV row per posture, the drive first,
then every link's angle, ω and α, then every named point's position,
velocity and acceleration; empty cells where the mechanism cannot be
assembled, reported once on standard error as a range of the drive.  On a
terminal, a job longer than a second shows a progress bar (the sweep, then
the writing of the CSV, which takes longer).
"""

from __future__ import annotations

import argparse
import sys
from typing import IO, cast

from graphkin.commands._args import MAX_COUNT, about, bounded_int, command, finite_float

__all__ = ["add_parser", "run"]


_COLUMNS = {
    "--transmission": "add the transmission angle at every pin found by two arcs "
                      "(transmission_<P>, degrees)",
    "--centers": "add every instant center (x_I13, y_I13; dx_/dy_ for one at infinity)",
    "--curvature": "add radii and centers of curvature of the paths (rho_P, cx_P, cy_P) and "
                   "the inflection poles and diameters and the centers of acceleration Γ of "
                   "the links (jx_k, inflection_diameter_k, gx_k, ...)",
}
"""The optional columns of the CSV: flag, help."""

HELP = "solve a mechanism over a whole cycle of its drive and write a CSV"
DESCRIPTION = about(__doc__)


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "sweep", help=HELP, description=DESCRIPTION)
    p.add_argument("--from", dest="start", type=finite_float, default=None, metavar="DEG",
                   help="first drive value: degrees, or a slider's travel (default: the file's)")
    p.add_argument("--to", dest="stop", type=finite_float, default=None, metavar="DEG",
                   help="end of the range, excluded (default: one full turn on; for a slider, "
                        "the end of the travel over which the mechanism assembles)")
    p.add_argument("--count", type=bounded_int(1, MAX_COUNT), default=360, metavar="N",
                   help="number of postures (default 360)")
    p.add_argument("--csv", default="-", metavar="OUT.csv",
                   help="where to write the CSV (default: standard output)")
    for flag, what in _COLUMNS.items():
        p.add_argument(flag, action="store_true", help=what)
    p.add_argument("--units", default=None, metavar="UNITS",
                   help="write lengths, velocities, accelerations and angular rates in these "
                        "units, e.g. \"ft, ft/s, ft/s^2\" (angles stay in degrees)")
    p.add_argument("--units-row", action="store_true",
                   help="write each column's unit on a second header line (the column names "
                        "stay those of docs/formats/sweep-csv.md)")
    p.add_argument("--torque", action="store_true",
                   help="add the drive's torque (torque_2) or input force (force_4) that holds "
                        "the loads and inertia forces of the file (docs/forces.md)")
    p.add_argument("--joint-forces", action="store_true",
                   help="with --torque: also the magnitude of every joint force (F_3-4)")
    p.add_argument("--turn", action="store_true",
                   help="from 0° to 360° instead of from the file's angle; a drive that "
                        "cannot turn fully: from one limit position to the other")
    p.add_argument("--follow", action="store_true",
                   help="keep the motion continuous: where the file's branch would jump (a "
                        "stretched or folded posture), go on along the other branch and say "
                        "where on standard error")
    p.add_argument("--singular", action="store_true",
                   help="also report dead centers, limit positions (of links pinned to the "
                        "frame and of sliders on it) and Grashof's classification on standard "
                        "error")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    import graphkin
    from graphkin.errors import InputError
    from graphkin.files import check_output
    from graphkin.kinematics.sweep import grashof, sweep
    from graphkin.output import OutputUnits
    from graphkin.output.csv import column_unit, convert_columns
    from graphkin.progress import CountingWriter, bar

    check_output(args.csv, [args.file], "--csv")
    from graphkin.mechanisms.cam_joint import for_sweep

    loaded = graphkin.load(args.file)
    if loaded.cams and (args.torque or args.joint_forces):
        raise InputError("the forces of a cam mechanism over the cycle are not supported "
                         "(graphkin solve gives them at the file's cam angle)",
                         key="--joint-forces" if args.joint_forces and not args.torque
                         else "--torque", file=args.file)
    mech = for_sweep(loaded)  # its followers moved by the cams' programs (Sec. 6.3)
    OutputUnits.of(mech.length_unit, args.units)  # a bad --units fails before the sweep runs
    if args.count < 1:
        raise InputError(f"--count must be at least 1, not {args.count}", key="count",
                         file=args.file)
    with bar("sweep", total=args.count, unit="posture") as b:
        sw = sweep(mech, count=args.count, start=args.start, stop=args.stop,
                   transmission=args.transmission, centers=args.centers,
                   curvature=args.curvature, progress=b.fraction, follow=args.follow,
                   turn=args.turn)
    if args.torque or args.joint_forces:
        from graphkin.forces.sweep import force_columns

        sw.columns.update(force_columns(sw, joints=args.joint_forces))
    units = OutputUnits.of(mech.length_unit, args.units)
    slider = not sw.drive.is_angle
    try:
        columns = convert_columns(sw.columns, units, slider) if args.units else None
    except KeyError as exc:
        raise InputError(f"no unit is known for the column {exc.args[0]!r}",
                         key="--units") from None
    units_row = ([column_unit(n, units, slider, mech.force_unit) for n in sw.columns]
                 if args.units_row else None)
    with bar("write CSV", total=args.count + 1, unit="row") as b:
        if args.csv == "-":
            sw.to_csv(cast(IO[str], CountingWriter(sys.stdout, b)), columns=columns,
                      units_row=units_row)
        else:
            try:
                with open(args.csv, "w", newline="", encoding="utf-8") as fh:
                    sw.to_csv(cast(IO[str], CountingWriter(fh, b)), columns=columns,
                              units_row=units_row)
            except OSError as exc:
                raise InputError(f"cannot write the CSV: {exc.strerror}", key="csv",
                                 file=args.csv) from None
    if args.csv != "-":
        print(f"wrote {args.csv}", file=sys.stderr)
    for line in sw.report(events=args.singular):
        print(f"graphkin: {args.file}: {line}", file=sys.stderr)
    if args.singular:
        try:
            print(f"graphkin: {args.file}: Grashof: {grashof(mech)}", file=sys.stderr)
        except InputError:
            pass
    return 0
