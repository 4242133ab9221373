"""``graphkin steps FILE --diagram D -o OUT.html``: the construction step by step, as a web page.

Write one HTML file (no network needed) that walks through the construction of a
diagram: for each step the vector equation with its ✓/? marks, one sentence, and the
drawing up to that step with the new elements highlighted; previous/next buttons and
arrow keys.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable
from typing import Any

from graphkin.commands._args import about, command, page_options, write_text, writing

__all__ = ["add_parser", "run"]


HELP = "write a self-contained HTML page walking through a construction"
DESCRIPTION = about(__doc__)


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "steps", help=HELP, description=DESCRIPTION)
    p.add_argument("--diagram", "-d", default="posture",
                   choices=("posture", "velocity", "acceleration", "centers", "curvature",
                            "inflection", "bobillier", "hartmann", "cubic", "forces", "gears",
                            "cam", "synthesis"),
                   help="which construction (default: posture); inflection, bobillier, "
                        "hartmann and cubic walk through one figure of the curvature sheet "
                        "(as draw -d does: the inflection and Bresse circles, Bobillier's "
                        "construction, conjugate points, the cubic of stationary curvature); "
                        "gears a gear file's pair in mesh; cam a cam file's profile laid out "
                        "by inversion (Sec. 6.4); synthesis a synthesis file's construction "
                        "(Ch. 9, as synthesize --steps; taken when FILE is one)")
    page_options(p, "numbered SVG per step")
    p.add_argument("--link", default=None, metavar="K",
                   help="curvature: the link whose motion is drawn (default: the coupler)")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    import graphkin
    from graphkin.errors import InputError
    from graphkin.render import DiagramUnavailable
    from graphkin.render.teach import steps_html, write_frames
    from graphkin.synthesis.spec import is_synthesis_file

    synth = args.diagram != "cam" and is_synthesis_file(args.file)
    if synth and args.diagram == "posture":   # the default diagram: the file says which
        args.diagram = "synthesis"
    if args.output is None and args.frames is None:  # the page beside the user
        from pathlib import Path

        args.output = f"{Path(args.file).stem}-steps-{args.diagram}.html"
    if args.output is not None:
        from graphkin.files import check_output

        check_output(args.output, [args.file], "--output")
    from graphkin.gears.file import gear_kind

    if args.diagram == "cam":  # a cam file's layout by inversion (graphkin.render.cam_steps)
        return _cam(args)
    if args.diagram == "synthesis" or synth:   # Ch. 9 (graphkin.render.synthesis_steps)
        return _synthesis(args)
    gears = gear_kind(args.file)
    if args.diagram == "gears" or gears is not None:
        return _gears(gears, args)
    sol = graphkin.load(args.file).solve()
    if args.diagram == "forces":  # free bodies and force polygons (graphkin.render.forces)
        return _forces(sol, args)
    try:
        if args.output is not None:
            from graphkin.progress import bar

            with bar("steps", total=100, unit="%") as b:  # a long page shows its progress
                page = steps_html(sol, args.diagram, link=args.link, progress=b.fraction)
            out = write_text(args.output, page, "--output")
            print(f"wrote {out}", file=sys.stderr)
        if args.frames is not None:
            with writing(f"into {args.frames}", "--frames"):
                paths = write_frames(sol, args.diagram, args.frames, link=args.link)
            print(f"wrote {len(paths)} frames into {args.frames}", file=sys.stderr)
    except DiagramUnavailable as exc:
        raise InputError(str(exc), key="--diagram", file=args.file) from None
    return 0


def _forces(sol: object, args: argparse.Namespace) -> int:
    """The force construction, one frame per step."""
    from pathlib import Path

    from graphkin.errors import InputError
    from graphkin.render import DiagramUnavailable
    from graphkin.render.forces import forces_frames, forces_steps_html

    try:
        if args.output is not None:
            out = write_text(args.output, forces_steps_html(sol), "--output")
            print(f"wrote {out}", file=sys.stderr)
        if args.frames is not None:
            d = Path(args.frames)
            with writing(f"into {d}", "--frames"):
                d.mkdir(parents=True, exist_ok=True)
                frames = forces_frames(sol)
                for k, (_, svg) in enumerate(frames):
                    (d / f"forces-{k:02d}.svg").write_text(svg, encoding="utf-8")
            print(f"wrote {len(frames)} frames into {d}", file=sys.stderr)
    except DiagramUnavailable as exc:
        raise InputError(str(exc), key="--diagram", file=args.file) from None
    return 0


def _gears(found: tuple[str, dict] | None, args: argparse.Namespace) -> int:
    """The layout of a pair in mesh, one frame per step (Sec. 7.5, Figs. 7.8-7.9)."""
    from graphkin.errors import InputError
    from graphkin.gears import layout
    from graphkin.gears.file import from_dict
    from graphkin.render.gears import gear_frames, gear_steps_html

    if found is None or found[0] != "pair":
        raise InputError("-d gears walks through the layout of a pair of gears in mesh: a gear "
                         "file with [gears.<name>] tables (docs/formats/gears.md)",
                         key="--diagram", file=args.file)
    if args.diagram not in ("gears", "posture"):
        raise InputError(f"a gear file is taught with -d gears, not -d {args.diagram}",
                         key="--diagram", file=args.file)
    lay = layout(from_dict(found[1], args.file))
    return _pages(args, lambda: gear_steps_html(lay), lambda: gear_frames(lay), "gears")


def _cam(args: argparse.Namespace) -> int:
    """The layout of a cam's profile by inversion, one frame per step (Sec. 6.4)."""
    from graphkin.cams.parse import load_cam
    from graphkin.render.cam_steps import cam_frames, cam_steps_html

    cam = load_cam(args.file).cam
    return _pages(args, lambda: cam_steps_html(cam), lambda: cam_frames(cam), "cam")


def _synthesis(args: argparse.Namespace) -> int:
    """A synthesis file's construction, one frame per step (Ch. 9, ``synthesize --steps``)."""
    from graphkin.errors import InputError
    from graphkin.render.synthesis_steps import synthesis_frames, synthesis_steps_html
    from graphkin.synthesis.run import synthesize
    from graphkin.synthesis.spec import is_synthesis_file, load_spec

    if not is_synthesis_file(args.file):
        raise InputError("-d synthesis walks through a synthesis file's construction: a file "
                         "with [[postures]], [function], [path], [dwell], [crank_rocker]... "
                         "(docs/formats/synthesis.md)", key="--diagram", file=args.file)
    if args.diagram != "synthesis":
        raise InputError(f"a synthesis file is taught with -d synthesis, not -d {args.diagram}",
                         key="--diagram", file=args.file)
    res = synthesize(load_spec(args.file))
    return _pages(args, lambda: synthesis_steps_html(res), lambda: synthesis_frames(res),
                  "synthesis")


def _pages(args: argparse.Namespace, html: Callable[[], str],
           frames: Callable[[], list[tuple[Any, Any, str]]], prefix: str) -> int:
    """Write a design file's step page (``-o``) and its frames (``--frames DIR``)."""
    from pathlib import Path

    if args.output is not None:
        out = write_text(args.output, html(), "--output")
        print(f"wrote {out}", file=sys.stderr)
    if args.frames is not None:
        d = Path(args.frames)
        with writing(f"into {d}", "--frames"):
            d.mkdir(parents=True, exist_ok=True)
            made = frames()
            for k, (_, _, svg) in enumerate(made):
                (d / f"{prefix}-{k:02d}.svg").write_text(svg, encoding="utf-8")
        print(f"wrote {len(made)} frames into {d}", file=sys.stderr)
    return 0
