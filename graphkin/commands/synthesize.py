"""``graphkin synthesize FILE``: find a four-bar by the constructions of Chapter 9.

Guide a body through two to five postures (poles, pole triangle, center-point
and circle-point curves, Burmester points), generate a function (Chebyshev
spacing, Freudenstein's equation) or a path with timing (dyads); report the
linkage with its checks and write it as a mechanism file that solve, draw and
sweep take as it is; ``--draw`` draws it, ``--steps`` writes the construction
step by step as a web page.

The file format is ``docs/formats/synthesis.md``; the work is done in
:mod:`graphkin.synthesis` and the report written by
:mod:`graphkin.output.synthesis`.

References
----------
Uicker, Pennock & Shigley, 5th ed., Ch. 9.
"""

from __future__ import annotations

import argparse
import json
import sys

from graphkin.commands._args import about, command, write_text

__all__ = ["add_parser", "run"]

HELP = "synthesize a four-bar through given postures or for a function (Ch. 9)"


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "synthesize", help=HELP, description=about(__doc__),
                file="synthesis file (TOML: [[postures]], [function] or [path])")
    p.add_argument("--json", action="store_true", help="print the result as JSON")
    p.add_argument("-o", "--output", metavar="MECH.toml",
                   help="write the synthesized linkage as a mechanism file")
    p.add_argument("--draw", metavar="FIG.svg", help="draw the construction and the linkage")
    p.add_argument("--steps", metavar="STEPS.html",
                   help="write the construction step by step as a web page (one frame per "
                        "step, the newest highlighted)")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    from graphkin.output.synthesis import synthesis_json, synthesis_text
    from graphkin.synthesis.run import synthesize
    from graphkin.synthesis.spec import load_spec

    res = synthesize(load_spec(args.file))
    if args.output:
        write_text(args.output, res.mechanism_toml(), "--output")
    if args.draw:
        from graphkin.render.synthesis import save_synthesis

        save_synthesis(res, args.draw)
    if args.steps:
        from graphkin.render.synthesis_steps import synthesis_steps_html

        write_text(args.steps, synthesis_steps_html(res), "--steps")
    if args.json:
        json.dump(synthesis_json(res), sys.stdout, ensure_ascii=False, indent=1,
                  allow_nan=False)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(synthesis_text(res))
    return 0
