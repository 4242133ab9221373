"""``graphkin check FILE ANSWERS... [--drawing D] [--csv OUT]``: mark hand solutions.

Exit status 0 when every answer is within tolerance, 1 when any is not, 2
when a file cannot be read (``docs/formats/answers.md``).
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from pathlib import Path
from typing import TYPE_CHECKING, TextIO

if TYPE_CHECKING:
    from graphkin.check import Report

__all__ = ["add_parser", "run"]


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = sub.add_parser(
        "check", help="check measured answers or a drawn polygon against the exact solution",
        description="Compare the values measured on a hand drawing (an answers file, see the "
                    "README) or a velocity/acceleration polygon drawn in CAD (DXF or SVG with "
                    "labelled vertices) with the exact constructions; name the likely mistake "
                    "under each wrong answer. Several answers files mark a stack of students.")
    p.add_argument("file", help="mechanism file (TOML)")
    p.add_argument("answers", nargs="*", help="answers file(s) (TOML)")
    p.add_argument("--drawing", action="append", default=[], metavar="DXF_OR_SVG",
                   help="a velocity or acceleration polygon drawn with labelled vertices "
                        "(O_V or O_A, b, c ...); may be repeated")
    p.add_argument("--scale", metavar="SCALE",
                   help='drawing scale, e.g. "1 in = 20 ft/s" (default: the scale noted in the '
                        "drawing, else fitted to the input crank's image)")
    p.add_argument("--relative", metavar="FRACTION",
                   help='relative tolerance of magnitudes, e.g. 0.02 or "2%%" (overrides the '
                        "answers files)")
    p.add_argument("--angle", metavar="DEG",
                   help="angle tolerance of directions and link angles, degrees (overrides the "
                        "answers files)")
    p.add_argument("--csv", metavar="OUT", help="write one row of marks per answers file")
    p.add_argument("--quiet", action="store_true",
                   help="print only one summary line per file")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    import graphkin
    from graphkin.check import CheckTolerance, check, load_answers, marks_csv
    from graphkin.check.answers import parse_degrees, parse_fraction
    from graphkin.errors import InputError

    if not args.answers and not args.drawing:
        raise InputError("give an answers file or --drawing", file=args.file)
    override: dict[str, float] = {}
    if args.relative is not None:
        override["relative"] = parse_fraction(args.relative, key="--relative")
    if args.angle is not None:
        override["angle"] = parse_degrees(args.angle, key="--angle")

    def tol_for(base: CheckTolerance) -> CheckTolerance:
        return dataclasses.replace(base, **override)

    mech = graphkin.load(args.file)
    sol = mech.solve()
    single = len(args.answers) + len(args.drawing) == 1 and not args.csv
    results: list[tuple[str, Report | None, str]] = []
    status = 0
    out = sys.stdout
    for path in args.answers:
        try:
            answers = load_answers(path, mech)
            rep = check(sol, answers, tol_for(answers.tolerance))
        except InputError as exc:
            if single:
                raise
            print(f"graphkin: {exc.one_line()}", file=sys.stderr)
            results.append((path, None, exc.message))
            status = 2
            continue
        rep.title = "" if single else f"== {path}" + (f" ({rep.student})" if rep.student else "")
        _print(rep, args.quiet, path, out)
        results.append((path, rep, ""))
        if not rep.ok and status == 0:
            status = 1
    for path in args.drawing:
        from graphkin.check.drawing import check_drawing

        try:
            rep = check_drawing(sol, path, scale=args.scale, tolerance=tol_for(CheckTolerance()))
        except InputError as exc:
            if single:
                raise
            print(f"graphkin: {exc.one_line()}", file=sys.stderr)
            results.append((path, None, exc.message))
            status = 2
            continue
        rep.title = f"== {path}" if not single else rep.title
        _print(rep, args.quiet, path, out)
        results.append((path, rep, ""))
        if not rep.ok and status == 0:
            status = 1
    if args.csv:
        text = marks_csv(results)
        if args.csv == "-":
            out.write(text)
        else:
            try:
                Path(args.csv).write_text(text, encoding="utf-8")
            except OSError as exc:
                raise InputError(f"cannot write the marks: {exc.strerror or exc}",
                                 file=args.csv) from None
    return status


def _print(rep: Report, quiet: bool, path: str, out: TextIO) -> None:
    if quiet:
        good = sum(r.ok for r in rep.counted)
        line = f"{path}: {good} of {len(rep.counted)} within tolerance"
        print(line, file=out)
        return
    print(rep.text(), file=out)
