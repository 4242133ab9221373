"""``graphkin check FILE ANSWERS... [--drawing D] [--scan P] [--csv OUT]``: mark hand solutions.

Compare the values measured on a hand drawing (an answers file, see the README), a
velocity/acceleration polygon drawn in CAD (DXF or SVG with labelled vertices), or one
drawn in pencil on a ``graphkin worksheet`` (--scan: a photo or scan) with the exact
constructions; name the likely mistake under each wrong answer. Several answers
files (or a PDF of scanned worksheets) mark a stack of students.

Exit status 0 when every answer is within tolerance, 1 when any is not, 2
when a file cannot be read (``docs/formats/answers.md``).
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
from pathlib import Path
from typing import TYPE_CHECKING, TextIO

from graphkin.commands._args import about, command

if TYPE_CHECKING:
    from graphkin.check import Report

__all__ = ["add_parser", "run"]

_TOLERANCES = (
    ("--relative", "FRACTION", 'relative tolerance of magnitudes, e.g. 0.02 or "2%%" (overrides '
     "the answers files)"),
    ("--angle", "DEG", "angle tolerance of directions and link angles, degrees (overrides the "
     "answers files)"),
    ("--drawing-tolerance", "LENGTH", 'drawing accuracy as a length on the sheet, e.g. "0.5 mm": '
     "a vector whose end is that close on the paper is right (needs the drawing's scale: the "
     "answers file's tolerance.scale, or the drawing's own)"),
)
"""The options that override an answers file's tolerances: flag, metavar, help."""


HELP = "check measured answers or a drawn polygon against the exact solution"
DESCRIPTION = about(__doc__)


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "check", help=HELP, description=DESCRIPTION)
    p.add_argument("answers", nargs="*", help="answers file(s) (TOML)")
    p.add_argument("--drawing", action="append", default=[], metavar="DXF_OR_SVG",
                   help="a velocity or acceleration polygon drawn with labelled vertices "
                        "(O_V or O_A, b, c ...); may be repeated")
    p.add_argument("--scan", action="extend", nargs="+", default=[], metavar="IMAGE_OR_PDF",
                   help="photos or scans of graphkin worksheets with the polygon drawn in "
                        "pencil (JPEG, PNG, or a PDF of one page per student); needs the "
                        "extra graphkin[scan]")
    p.add_argument("--show", metavar="PNG",
                   help="with --scan: write the rectified sheet with what was read drawn over "
                        "it (one file per page: PNG-2.png ...)")
    p.add_argument("--scale", metavar="SCALE",
                   help='drawing scale, e.g. "1 in = 20 ft/s" (default: the scale noted in the '
                        "drawing, else fitted to the input crank's image)")
    for flag, metavar, what in _TOLERANCES:
        p.add_argument(flag, metavar=metavar, help=what)
    p.add_argument("--csv", metavar="OUT",
                   help="write one row of marks per answers file (counts, a summary, and per "
                        "answer the given and exact values, the error, the verdict and a "
                        "mistake code)")
    p.add_argument("--quiet", action="store_true",
                   help="print only one summary line per file")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    import graphkin
    from graphkin.check import CheckTolerance, Diagnoser, Evaluator, check, loads_answers, marks_csv
    from graphkin.check.answers import parse_degrees, parse_fraction, read_limited, student_of
    from graphkin.check.report import UNREADABLE, Report, printable
    from graphkin.errors import InputError
    from graphkin.units import parse_quantity

    if not args.answers and not args.drawing and not args.scan:
        raise InputError("give an answers file, --drawing or --scan", file=args.file)
    if args.show and not args.scan:
        raise InputError("--show draws what --scan read: give --scan PHOTO", key="--show")
    from graphkin.commands.cam import check_answers, is_cam_file

    if is_cam_file(args.file):  # a cam file's own answers (graphkin.cams.answers)
        return check_answers(args)
    if args.scan:
        from graphkin.scan import need_cv2

        need_cv2()
    override: dict[str, float] = {}
    if args.relative is not None:
        override["relative"] = parse_fraction(args.relative, key="--relative")
    if args.angle is not None:
        override["angle"] = parse_degrees(args.angle, key="--angle")
    if args.drawing_tolerance is not None:
        try:
            mm = parse_quantity(args.drawing_tolerance, "length", "mm")[0]
        except ValueError as exc:
            raise InputError(f"{exc} (write \"0.5 mm\")", key="--drawing-tolerance") from None
        if not mm > 0:
            raise InputError("must be a positive length", key="--drawing-tolerance")
        override["drawing"] = mm

    def tol_for(base: CheckTolerance) -> CheckTolerance:
        return dataclasses.replace(base, **override)  # type: ignore[arg-type]

    mech = graphkin.load(args.file)
    sol = mech.solve()
    diag = Diagnoser(Evaluator(sol))
    single = len(args.answers) + len(args.drawing) == 1 and not args.csv and not args.scan
    results: list[tuple[str, Report | None, str]] = []
    status = 0
    out = sys.stdout

    def warn(line: str) -> None:
        print(f"graphkin: {printable(line)}", file=sys.stderr)

    for path in args.answers:
        text = ""
        try:
            text = read_limited(path)
            answers = loads_answers(text, mech, source=path)
            rep = check(sol, answers, tol_for(answers.tolerance), diagnoser=diag)
        except InputError as exc:
            if single:
                raise
            warn(exc.one_line())
            bad = Report([], CheckTolerance(), path, student_of(text), error=exc.message)
            results.append((path, bad, exc.message))
            status = 2
            continue
        rep.title = "" if single else f"== {path}" + (f" ({rep.student})" if rep.student else "")
        _print(rep, args.quiet, path, out)
        for r in rep.rows:
            if r.verdict == UNREADABLE:
                warn(f"{path}: {r.key}: {r.error}")
        results.append((path, rep, ""))
        status = _worse(status, rep)
    for path in args.drawing:
        from graphkin.check.drawing import check_drawing

        try:
            rep = check_drawing(sol, path, scale=args.scale, tolerance=tol_for(CheckTolerance()),
                                diagnoser=diag)
        except InputError as exc:
            if single:
                raise
            warn(exc.one_line())
            results.append((path, None, exc.message))
            status = 2
            continue
        rep.title = f"== {path}" if not single else rep.title
        _print(rep, args.quiet, path, out)
        results.append((path, rep, ""))
        status = _worse(status, rep)
    if args.scan:
        from graphkin.scan.batch import scan_reports

        for name, srep, err in scan_reports(sol, args.file, args.scan, tol_for(CheckTolerance()),
                                            diag, show=args.show):
            if srep is None:
                warn(err)
                status = 2
            else:
                srep.title = f"== {name}: {srep.title}"
                _print(srep, args.quiet, name, out)
                status = _worse(status, srep)
            results.append((name, srep, err))
    if args.csv:
        text = marks_csv(results)
        if args.csv == "-":
            out.write(text)
        else:
            if any(Path(args.csv).resolve() == Path(p).resolve()
                   for p in [args.file, *args.answers, *args.drawing, *args.scan]):
                raise InputError("the marks would overwrite an input file", file=args.csv)
            try:
                Path(args.csv).write_text(text, encoding="utf-8")
            except OSError as exc:
                raise InputError(f"cannot write the marks: {exc.strerror or exc}",
                                 file=args.csv) from None
            print(f"wrote {args.csv}", file=sys.stderr)
    return status


def _worse(status: int, rep: Report) -> int:
    """Exit status: 2 when anything was unreadable, else 1 when any answer is not right."""
    if rep.unreadable:
        return 2
    if not rep.ok and status == 0:
        return 1
    return status


def _print(rep: Report, quiet: bool, path: str, out: TextIO) -> None:
    from graphkin.check.report import printable

    if quiet:
        print(printable(f"{path}: {rep.summary()}"), file=out)
        return
    print(rep.text(), file=out)
