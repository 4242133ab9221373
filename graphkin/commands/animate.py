"""``graphkin animate FILE -o cycle.html``: the whole cycle in motion, as one web page.

Sweep the mechanism through its cycle (as `graphkin sweep`) and write one HTML file (no
network needed) where it turns, with its velocity and acceleration polygons redrawn to
scale at every posture: play/pause, a drive slider, step ±1, speed; ω, α and a chosen
point's velocity and acceleration; ranges that cannot be assembled and limit postures
marked.
"""

from __future__ import annotations

import argparse
import sys

from graphkin.commands._args import about, command, write_text, writing

__all__ = ["add_parser", "run"]


HELP = ("write a self-contained HTML page of the mechanism turning through "
        "its cycle, with its velocity and acceleration polygons")
DESCRIPTION = about(__doc__)


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "animate", help=HELP, description=DESCRIPTION)
    p.add_argument("-o", "--output", default=None,
                   help="the HTML file to write (default, when nothing else is asked for: "
                        "FILE-STEM-cycle.html in the current directory)")
    p.add_argument("--count", type=int, default=360, help="number of postures (default 360)")
    p.add_argument("--from", dest="start", type=float, default=None, metavar="DRIVE",
                   help="first drive value: degrees, or a slider's travel (default: the "
                        "file's drive)")
    p.add_argument("--to", dest="stop", type=float, default=None, metavar="DRIVE",
                   help="last drive value, excluded (default: one full turn on)")
    p.add_argument("--centers", action="store_true", help="also draw the instant centers")
    p.add_argument("--inflection", action="store_true",
                   help="also draw each moving link's inflection circle (needs rates)")
    p.add_argument("--polygons", choices=("cycle", "posture"), default="cycle",
                   help="size the velocity and acceleration polygons at one scale for the "
                        "whole cycle (default: lengths compare between postures) or each "
                        "posture at the round scale that fits it (the page's 'fit polygons')")
    p.add_argument("--frames", default=None, metavar="DIR",
                   help="also write one SVG per posture into DIR (for slides)")
    p.add_argument("--gif", default=None, metavar="FILE",
                   help="also write the cycle as an animated GIF")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    import graphkin
    from graphkin.errors import InputError
    from graphkin.progress import bar
    from graphkin.render.animate import animate_html

    if args.count < 2 or args.count > 20000:
        raise InputError(f"the number of postures must be 2 to 20000, not {args.count}",
                         key="--count")
    if args.output is None and args.frames is None and args.gif is None:
        from pathlib import Path  # the page beside the user, named for the file

        args.output = f"{Path(args.file).stem}-cycle.html"
    from graphkin.files import check_output

    if args.output is not None:
        check_output(args.output, [args.file], "--output")
    if args.gif is not None:
        if not str(args.gif).lower().endswith(".gif"):
            raise InputError(f"the animated picture is a .gif file, not {args.gif!r}",
                             key="--gif")
        check_output(args.gif, [args.file], "--gif")
    from graphkin.mechanisms.cam_joint import for_sweep

    # a cam mechanism: its followers moved by the cams' programs over the cycle (Sec. 6.3)
    mech = for_sweep(graphkin.load(args.file))
    # one step per thing written (the page, the frames, the GIF); drawn on a terminal only
    jobs = sum(x is not None for x in (args.output, args.frames, args.gif))
    with bar("animate", total=jobs, unit="file") as progress:
        if args.output is not None:
            text = animate_html(mech, count=args.count, start=args.start, stop=args.stop,
                                centers=args.centers, inflection=args.inflection,
                                polygons=args.polygons)
            out = write_text(args.output, text, "--output")
            print(f"wrote {out} ({len(text.encode('utf-8')) / 1024:.0f} KiB)", file=sys.stderr)
            progress.update(1)
        if args.frames is not None or args.gif is not None:
            from graphkin.render.cycle_frames import write_cycle_frames, write_cycle_gif

            if args.frames is not None:
                with writing(f"into {args.frames}", "--frames"):
                    paths = write_cycle_frames(mech, args.frames, count=args.count,
                                               start=args.start, stop=args.stop,
                                               keep=[args.file])
                print(f"wrote {len(paths)} frames into {args.frames}", file=sys.stderr)
                progress.update(1)
            if args.gif is not None:
                with writing(args.gif, "--gif"):
                    write_cycle_gif(mech, args.gif, count=args.count, start=args.start,
                                    stop=args.stop)
                print(f"wrote {args.gif}", file=sys.stderr)
                progress.update(1)
    return 0
