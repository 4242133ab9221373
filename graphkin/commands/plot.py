"""``graphkin plot FILE --what omega,alpha -o out.svg``: curves over a sweep of the drive.

Items: ``angle``, ``omega``, ``alpha`` (every moving link, or ``omega:4``),
``velocity:P``, ``acceleration:P`` (magnitudes), ``path:P`` (a coupler curve)
and ``transmission`` (Sec. 1.10).  The drawing is deterministic SVG (or PDF,
PNG by the suffix).
"""

from __future__ import annotations

import argparse
import sys
from typing import Any

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
    p.add_argument("--turn", action="store_true",
                   help="from 0° to 360° instead of from the file's angle; a drive that "
                        "cannot turn fully: from one limit position to the other")
    p.add_argument("--follow", action="store_true",
                   help="keep the motion continuous through stretched or folded postures "
                        "(as sweep --follow)")
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
    try:
        items = parse_what(args.what)
    except InputError as exc:
        raise InputError(exc.message, key="--what", file=args.file) from None
    from graphkin.mechanisms.cam_joint import for_sweep

    loaded = graphkin.load(args.file)
    if loaded.cams and any(i == "torque" for i, _ in items):
        raise InputError("the drive's torque of a cam mechanism over the cycle is not "
                         "supported (graphkin solve gives it at the file's cam angle)",
                         key="--what", file=args.file)
    mech = for_sweep(loaded)  # its followers moved by the cams' programs (Sec. 6.3)
    _check_items(mech, items)
    if args.count < 2:
        raise InputError(f"--count must be at least 2 to draw a curve, not {args.count}",
                         key="count", file=args.file)
    # three stages: the sweep, the figure, the file (a bar only past a second, on a terminal)
    with bar("plot", total=3, unit="stage") as b:
        sw = sweep(mech, count=args.count, start=args.start, stop=args.stop,
                   transmission=any(i == "transmission" for i, _ in items),
                   follow=args.follow, turn=args.turn)
        b.update(1)
        try:
            fig = sweep_figure(sw, [f"{i}:{w}" if w else i for i, w in items])
        except InputError as exc:  # an item this sweep cannot draw: the file and the option
            raise InputError(exc.message, key="--what", file=exc.file or args.file) from None
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


def _check_items(mech: Any, items: list[tuple[str, str | None]]) -> None:
    """Every ``--what`` item and its suffix checked against the file before the sweep.

    A suffix an item does not take (``torque:99``, ``transmission:Q``) is refused, not
    ignored; an item that needs rates or loads the file lacks names the file and the option.
    """
    from graphkin.errors import InputError

    def fail(message: str) -> InputError:
        return InputError(message, key="--what", file=mech.source)

    driven = [d.link for d in mech.drives]
    for item, which in items:
        name = f"{item}:{which}" if which else item
        if item in ("omega", "alpha", "velocity", "acceleration") and not mech.has_rates:
            raise fail(f"{name} needs rates, and the file gives none (add omega or velocity "
                       "to [drive])")
        if item in ("angle", "omega", "alpha") and which is not None \
                and which not in mech.links:
            raise fail(f"no link {which!r} for {item}; the links are {', '.join(mech.links)}")
        if item in ("velocity", "acceleration", "path") and which not in mech.point_links:
            raise fail(f"no point {which!r} for {item}; the points are "
                       f"{', '.join(mech.point_names)}")
        if item == "centrode" and which not in mech.moving:
            raise fail(f"no moving link {which!r} for a centrode; the moving links are "
                       f"{', '.join(mech.moving)}")
        if item == "torque":
            if not mech.has_forces:
                raise fail("torque needs forces: the file has no [[loads]] and no [inertia.N]")
            if which is not None and which not in driven:
                raise fail(f"torque:{which}: link {which!r} is not driven; the driven links "
                           f"are {', '.join(driven)} (or give torque alone)")
        if item == "transmission" and which is not None:
            raise fail(f"transmission takes no suffix ({name!r}): it plots the angle at every "
                       "pin found by two arcs")
