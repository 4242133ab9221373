"""``graphkin worksheet FILE -d velocity|acceleration --sheet a4|letter -o sheet.pdf``.

Print a worksheet to draw a polygon on by hand: the mechanism to a round scale,
the pole O_V (or O_A) placed and the polygon's scale printed, an empty polygon
area, and ArUco markers that let ``graphkin check FILE --scan photo.jpg`` find
the sheet in a phone photo or a scan and mark the drawing. ``--upto K`` prints
the construction's first K steps as a start.
"""

from __future__ import annotations

import argparse
import sys

from graphkin.commands._args import about, bounded_int, command

__all__ = ["add_parser", "run"]

HELP = "print a worksheet for a hand-drawn polygon, to mark from a photo (check --scan)"


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "worksheet", help=HELP, description=about(__doc__))
    p.add_argument("--diagram", "-d", required=True, choices=("velocity", "acceleration"),
                   help="the polygon to draw")
    p.add_argument("--sheet", choices=("a4", "letter"), default="a4",
                   help="the paper (default a4, portrait)")
    p.add_argument("-o", "--output", required=True,
                   help="the worksheet: .pdf (with its identity in the metadata), .png or .svg")
    p.add_argument("--upto", type=bounded_int(0, 33), default=None, metavar="K",
                   help="print the construction's first K steps (0 to 33)")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    from pathlib import Path

    import graphkin
    from graphkin.commands._args import writing
    from graphkin.errors import InputError
    from graphkin.files import check_output
    from graphkin.render.worksheet import fit_mechanism, save_worksheet, worksheet_figure
    from graphkin.render.worksheet_layout import mechanism_hash, worksheet_layout

    out = Path(args.output)
    check_output(args.output, [args.file], "--output")
    if out.suffix.lower() not in (".pdf", ".png", ".svg"):
        raise InputError(f"write the worksheet to a .pdf, .png or .svg file, not {out.name!r}",
                         key="--output")
    mech = graphkin.load(args.file)
    sol = mech.solve()
    digest = mechanism_hash(Path(args.file).read_bytes())
    layout = fit_mechanism(sol, worksheet_layout(sol, args.diagram, args.sheet, digest,
                                                  args.upto))
    fig = worksheet_figure(sol, layout, title=getattr(mech, "title", "") or Path(args.file).name)
    with writing(str(out), "--output"):
        save_worksheet(fig, layout, out)
    print(f"wrote {out}", file=sys.stderr)
    return 0
