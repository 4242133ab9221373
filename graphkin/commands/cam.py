"""``graphkin cam FILE``: a plate cam's program, profile and design checks (Chapter 6).

Read a cam file (docs/formats/cam.md), check its program (segments over
360°, the matching of y, y', y'' at the joints), lay out its profile by
kinematic inversion, and report the pressure angle, radii of curvature,
undercutting, the flat face's width and the least prime circle; -o writes
the profile layout or the displacement diagram (SVG, PNG, PDF), the profile
to true scale (DXF, a closed polyline) or a table of its coordinates (CSV).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., Chapter 6.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from graphkin.commands._args import about, bounded_int, command, finite_float, write_text, writing
from graphkin.errors import InputError

__all__ = ["add_parser", "run"]

HELP = "lay out a plate cam's profile and check its design (Ch. 6)"
DESCRIPTION = about(__doc__)
DRAWINGS = (".svg", ".png", ".pdf")


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "cam", help=HELP, description=DESCRIPTION,
                file="cam file (TOML: [cam], [follower], [[segment]]; docs/formats/cam.md)")
    p.add_argument("--json", action="store_true", help="print the report as JSON")
    p.add_argument("-o", "--output", default=None, metavar="OUT",
                   help="write OUT: .svg/.png/.pdf a drawing (-d), .dxf the profile to true "
                        "scale, .csv a table of the profile's coordinates")
    p.add_argument("-d", "--diagram", choices=("layout", "displacement", "design"),
                   default="layout",
                   help="the drawing: the profile's layout by inversion (Figs. 6.8-6.11), "
                        "the displacement diagram with y', y'' (Figs. 6.12-6.24), or the "
                        "pressure angle and radius of curvature over the cycle (design)")
    p.add_argument("--stations", type=bounded_int(4, 360), default=12,
                   help="inverted postures drawn in the layout (default 12)")
    p.add_argument("--points", type=bounded_int(8, 100_000), default=360,
                   help="points of the profile in the CSV and DXF (default 360)")
    p.add_argument("--equivalent", type=finite_float, default=None, metavar="ANGLE",
                   help="write the cam mechanism at cam angle ANGLE (degrees) as its "
                        "equivalent linkage, a mechanism file (to -o OUT.toml, or print it), "
                        "for solve, draw, steps (Sec. 4.7)")
    p.add_argument("--steps", action="store_true",
                   help="also list the recorded steps of one station of the layout")
    p.add_argument("--allow-undercut", action="store_true",
                   help="report and draw an undercut cam instead of refusing it")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    from graphkin.cams.parse import load_cam
    from graphkin.cams.report import cam_json, cam_text, profile_csv, refuse_undercut, steps_text

    if args.output is not None:
        from graphkin.files import check_output

        check_output(args.output, [args.file], "--output")
    cf = load_cam(args.file)
    if not args.allow_undercut:
        refuse_undercut(cf)
    angular = cf.cam.follower.kind.oscillating
    for w in cf.cam.program.warnings("rad" if angular else cf.cam.unit):
        sys.stderr.write(f"{args.file}: warning: {w}\n")
    if args.equivalent is not None:
        import math

        from graphkin.cams.equivalent import equivalent_toml

        text = equivalent_toml(cf.cam, math.radians(args.equivalent))
        if args.output is None:
            sys.stdout.write(text)
        elif Path(args.output).suffix.lower() != ".toml":
            raise InputError("--equivalent writes a mechanism file: -o OUT.toml",
                             key="--output")
        else:
            write_text(args.output, text, "--output")
            print(f"wrote {args.output}", file=sys.stderr)
        return 0
    if args.output:
        out = Path(args.output)
        ext = out.suffix.lower()
        if ext == ".csv":
            write_text(out, profile_csv(cf, args.points), "--output")
        elif ext == ".dxf":
            from graphkin.io.cam import write_profile_dxf

            with writing(str(out), "--output"):
                write_profile_dxf(cf.cam, out, args.points)
        elif ext in DRAWINGS:
            from graphkin.render.cams import save_cam_figure

            with writing(str(out), "--output"):
                save_cam_figure(cf.cam, out, diagram=args.diagram, stations=args.stations)
        else:
            raise InputError(f"cannot write {out.name!r}: the output is .svg, .png, .pdf, .dxf "
                             "or .csv", key="--output")
        print(f"wrote {out}", file=sys.stderr)   # as every command that writes a file says
    if args.json:
        json.dump(cam_json(cf), sys.stdout, ensure_ascii=False, indent=1, allow_nan=False)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(cam_text(cf))
        if args.steps:
            sys.stdout.write("\n" + steps_text(cf))
    return 0


def is_cam_file(path: str) -> bool:
    """True when ``path`` is a cam file (a ``[cam]`` table and no ``[links]``).

    An unreadable file is left to the caller's own reading (False).
    """
    from graphkin.errors import GraphkinError
    from graphkin.files import load_toml

    try:
        data = load_toml(path)
    except (GraphkinError, OSError):
        return False
    return "cam" in data and "links" not in data


def check_answers(args: argparse.Namespace) -> int:
    """``graphkin check CAMFILE ANSWERS...``: mark cam answers (:mod:`graphkin.cams.answers`).

    Exit status 0 when every answer is within tolerance, 1 when any is not, 2 when
    a file cannot be read (as for a mechanism's answers).
    """
    from graphkin.cams.answers import check_cam
    from graphkin.cams.parse import load_cam
    from graphkin.check.answers import parse_degrees, parse_fraction
    from graphkin.files import read_text

    if args.drawing or not args.answers:
        raise InputError("a cam file's answers are checked from an answers file (no "
                         "--drawing)", key="--drawing" if args.drawing else None,
                         file=args.file)
    cf = load_cam(args.file)
    rel = None if args.relative is None else parse_fraction(args.relative, key="--relative")
    ang = None if args.angle is None else parse_degrees(args.angle, key="--angle")
    status = 0
    for path in args.answers:
        rows, text = check_cam(cf, read_text(path), path, relative=rel, angle=ang)
        if len(args.answers) > 1:
            print(f"== {path}")
        if args.quiet:
            print(f"{path}: {text.splitlines()[-1]}")
        else:
            print(text, end="")
        if not all(r.ok for r in rows):
            status = 1
    return status
