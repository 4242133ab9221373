"""``graphkin plot FILE --what omega,alpha -o out.svg``: curves over a sweep of the drive.

Items: ``angle``, ``omega``, ``alpha`` (every moving link, or ``omega:4``),
``velocity:P``, ``acceleration:P`` (magnitudes), ``path:P`` (a coupler curve)
and ``transmission`` (Sec. 1.10).  The drawing is deterministic SVG (or PDF,
PNG by the suffix).
"""

from __future__ import annotations

import argparse
import sys

from graphkin.commands._args import MAX_COUNT, bounded_int, command, finite_float

__all__ = ["add_parser", "run"]

HELP = "plot angles, rates, coupler curves or transmission angles over a sweep"
DESCRIPTION = ("Sweep the drive (as graphkin sweep) and plot curves over it: angle, omega, "
               "alpha (omega:4 for one link), velocity:P, acceleration:P, path:P (coupler "
               "curve, with its osculating circle and Ball's point), center:I24 (the path "
               "of an instant center), centrode:3 (fixed and moving centrodes), "
               "transmission.")


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "plot", help=HELP, description=DESCRIPTION)
    p.add_argument("--what", default="angle,omega,alpha", metavar="ITEMS",
                   help="comma-separated items (default angle,omega,alpha)")
    p.add_argument("-o", "--output", default=None, metavar="OUT.svg",
                   help="the drawing: .svg, .pdf or .png (default: FILE-STEM-plot.svg in the "
                        "current directory)")
    p.add_argument("--from", dest="start", type=finite_float, default=None, metavar="DEG",
                   help="first drive value (default: the file's)")
    p.add_argument("--to", dest="stop", type=finite_float, default=None, metavar="DEG",
                   help="end of the range, excluded (default: one full turn on)")
    p.add_argument("--count", type=bounded_int(2, MAX_COUNT), default=360, metavar="N",
                   help="number of postures (default 360)")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    import graphkin
    from graphkin.errors import InputError
    from graphkin.files import check_output
    from graphkin.kinematics.sweep import sweep
    from graphkin.progress import bar
    from graphkin.render.plots import parse_what, save_figure, sweep_figure

    if args.output is None:  # beside the user, named for the file (as draw does)
        from pathlib import Path

        args.output = f"{Path(args.file).stem}-plot.svg"
    check_output(args.output, [args.file], "--output")
    items = parse_what(args.what)
    mech = graphkin.load(args.file)
    if args.count < 2:
        raise InputError(f"--count must be at least 2 to draw a curve, not {args.count}",
                         key="count", file=args.file)
    # three stages: the sweep, the figure, the file (a bar only past a second, on a terminal)
    with bar("plot", total=3, unit="stage") as b:
        sw = sweep(mech, count=args.count, start=args.start, stop=args.stop,
                   transmission=any(i == "transmission" for i, _ in items))
        b.update(1)
        fig = sweep_figure(sw, [f"{i}:{w}" if w else i for i, w in items])
        b.update(1)
        try:
            save_figure(fig, args.output)
        except OSError as exc:
            raise InputError(f"cannot write the drawing: {exc.strerror}", key="output",
                             file=args.output) from None
    for line in sw.report():
        print(f"graphkin: {args.file}: {line}", file=sys.stderr)
    print(f"wrote {args.output}", file=sys.stderr)
    return 0
