"""``graphkin draw FILE --diagram D -o OUT``: draw a construction to scale (SVG, PDF, PNG, TikZ)."""

from __future__ import annotations

import argparse
import sys

from graphkin.commands._args import DPI_RANGE, bounded_float, bounded_int, command

__all__ = ["add_parser", "run", "DIAGRAM_CHOICES"]

FORMAT_CHOICES = ("svg", "pdf", "png", "tikz", "dxf")
"""What --format accepts; ``tikz`` is written to a ``.tex`` file."""

DIAGRAM_CHOICES = ("posture", "velocity", "acceleration", "centers", "curvature", "inflection",
                   "bobillier", "hartmann", "cubic", "forces", "gears", "all")


HELP = "draw a diagram to scale (SVG, PDF or PNG)"
DESCRIPTION = ("Draw the mechanism and its construction to a stated scale: the posture, "
               "the velocity or acceleration polygon beside the mechanism, the instant "
               "centers, the curvature construction, the free bodies and force polygons "
               "(-d forces, Fig. 11.5), or all of them on one sheet, with "
               "a results table comparing the drawing with the analytic solution. A gear "
               "file (docs/formats/gears.md) draws the pair in mesh (-d gears, Figs. 7.8-7.9, "
               "7.18, 7.21). The output's suffix chooses the format (.svg, .pdf, .png, .tex: "
               "a TikZ picture that compiles with pdflatex). Without -o, the drawing is "
               "written to FILE-STEM-DIAGRAM.svg in the current directory; -o - writes the SVG "
               "(or, with --format tikz, the TikZ) to standard output.")


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "draw", help=HELP, description=DESCRIPTION)
    p.add_argument("--diagram", "-d", default="all", choices=DIAGRAM_CHOICES,
                   help="which diagram (default: all)")
    p.add_argument("-o", "--output", default=None,
                   help="output file: .svg, .pdf, .png, .tex (TikZ, standalone for pdflatex), "
                        "or .dxf (a CAD drawing of the posture, velocity or acceleration "
                        "construction, e.g. a started drawing to hand out with --upto); "
                        "- for standard output (default: FILE-STEM-DIAGRAM.svg here)")
    p.add_argument("--format", choices=(*FORMAT_CHOICES,), default=None,
                   help="the format when the suffix does not say it (with -o - or no -o)")
    p.add_argument("--upto", type=bounded_int(0, 100_000), default=None, metavar="K",
                   help="draw the construction only up to step K (0-based)")
    p.add_argument("--link", default=None, metavar="K",
                   help="curvature: the link whose motion is drawn (default: the coupler)")
    p.add_argument("--sheet", choices=("a4", "letter"), default=None,
                   help="one page of that paper (portrait or landscape) to hand out: round "
                        "1-2-5 scales, a compact results table in the scale bars' units (no "
                        "analytic column), a line-style legend and a title block; -d all "
                        "shows curvature figure (a) only (-d curvature for all four)")
    p.add_argument("--no-table", action="store_true", help="leave out the results table")
    p.add_argument("--dpi", type=bounded_float(*DPI_RANGE), default=150.0,
                   help="resolution of a PNG, 10 to 1200 (default 150)")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    from pathlib import Path

    import graphkin
    from graphkin.errors import GraphkinError, InputError
    from graphkin.files import check_output
    from graphkin.render import DiagramUnavailable, draw, save
    from graphkin.render.svg import FORMATS

    fmt = args.format
    if args.output is None:  # FILE-STEM-DIAGRAM.svg in the current directory
        suffix = {"tikz": "tex"}.get(fmt or "svg", fmt or "svg")
        args.output = f"{Path(args.file).stem}-{args.diagram}.{suffix}"
    to_stdout = args.output == "-"
    check_output(args.output, [args.file], "--output")
    out = Path(args.output)
    if not to_stdout:
        given = out.suffix.lower().lstrip(".")
        given = "tikz" if given == "tex" else given
        if fmt is not None and given != fmt:
            raise InputError(f"--format {fmt} does not match the suffix of {out.name!r}",
                             key="--format")
        fmt = given
    fmt = fmt or ("svg" if to_stdout else "")
    dxf = fmt == "dxf"
    if fmt not in (*FORMATS, "dxf", "tikz"):
        raise InputError(f"cannot tell the format from {out.name!r}; use "
                         + ", ".join("." + f for f in (*FORMATS, "tex", "dxf")), key="--output")
    if to_stdout and fmt in ("pdf", "png", "dxf"):
        raise InputError(f"-o - writes text (SVG or TikZ), not {fmt.upper()}; name a file",
                         key="--output")
    if _is_gear_file(args.file, args.diagram):
        if to_stdout or fmt == "tikz":
            raise InputError("a gear drawing is written to a .svg, .pdf or .png file",
                             key="--output", file=args.file)
        return _draw_gears(args, out)
    mech = graphkin.load(args.file)
    sol = mech.solve()
    if dxf:
        from graphkin.io.dxf import write_dxf

        if args.diagram not in ("posture", "velocity", "acceleration"):
            raise InputError("DXF holds one construction: --diagram posture, velocity or "
                             "acceleration", key="--diagram", file=args.file)
        if args.diagram not in sol.constructions:
            raise InputError(f"no {args.diagram} construction: the file gives no rates",
                             key="--diagram", file=args.file)
        write_dxf(sol, args.diagram, out, upto=args.upto)
        print(f"wrote {out}", file=sys.stderr)
        return 0
    try:
        d = draw(sol, args.diagram, upto=args.upto, table=not args.no_table, link=args.link,
                 sheet=args.sheet)
    except DiagramUnavailable as exc:
        raise InputError(str(exc), key="--diagram", file=args.file) from None
    assert d.figure is not None
    try:
        if fmt == "tikz":
            from graphkin.render.tikz import drawing_tikz

            try:
                text = drawing_tikz(d)
            except GraphkinError as exc:
                raise InputError(str(exc), key="--output") from None
            if to_stdout:
                sys.stdout.write(text)
                return 0
            out.write_text(text, encoding="utf-8")
        elif to_stdout:
            from graphkin.render.svg import to_svg

            sys.stdout.write(to_svg(d.figure))
            return 0
        else:
            save(d.figure, out, dpi=args.dpi)
    except OSError as exc:
        raise InputError(f"cannot write {out}: {exc.strerror or exc}", key="--output") from None
    print(f"wrote {out}", file=sys.stderr)
    return 0


def _is_gear_file(path: str, diagram: str) -> bool:
    """Whether ``path`` is a gear file; ``-d gears`` of anything else is one line, exit 2."""
    from graphkin.errors import InputError
    from graphkin.gears.file import gear_kind

    found = gear_kind(path)
    if found is not None and found[0] == "train":
        raise InputError("a gear-train file is solved by graphkin gears FILE; only a pair in "
                         "mesh is drawn", key="--diagram", file=path)
    gears = found is not None
    if diagram == "gears" and not gears:
        raise InputError("-d gears draws a gear file (docs/formats/gears.md): a [gears.<name>] "
                         "table for each gear of the pair", key="--diagram", file=path)
    if gears and diagram not in ("gears", "all"):
        raise InputError(f"a gear file is drawn with -d gears, not -d {diagram}",
                         key="--diagram", file=path)
    return gears


def _draw_gears(args: argparse.Namespace, out: object) -> int:
    """A pair of gears in mesh (Figs. 7.8-7.9, 7.17, 7.18, 7.21)."""
    from pathlib import Path

    from graphkin.errors import InputError
    from graphkin.gears import layout
    from graphkin.gears.file import load
    from graphkin.render.gears import draw_gears
    from graphkin.render.svg import save

    assert isinstance(out, Path)
    for option, value in (("--link", args.link), ("--sheet", args.sheet)):
        if value is not None:
            raise InputError(f"{option} is not used by a gear drawing", key=option,
                             file=args.file)
    if out.suffix.lower() == ".dxf":
        raise InputError("a gear drawing is written as .svg, .pdf or .png", key="--output")
    lay = layout(load(args.file))
    if args.upto is not None and args.upto >= len(lay.construction):
        raise InputError(f"the layout has {len(lay.construction)} steps (0 to "
                         f"{len(lay.construction) - 1})", key="--upto", file=args.file)
    d = draw_gears(lay, table=not args.no_table and args.upto is None, upto=args.upto)
    try:
        save(d.figure, out, dpi=args.dpi)
    except OSError as exc:
        raise InputError(f"cannot write {out}: {exc.strerror or exc}", key="--output") from None
    print(f"wrote {out}", file=sys.stderr)
    return 0
