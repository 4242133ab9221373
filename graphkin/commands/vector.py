"""``graphkin vector FILE [--json] [--steps]``: solve ``C = A + B`` from a small TOML file.

Solve C = A + B for its two unknowns by the graphic construction of Sec. 2.8 (Table 2.2,
cases 1-4).

The file (its keys: :mod:`graphkin.kinematics.vector_file`) is read by
:func:`~graphkin.kinematics.vector_file.load`, the equation solved by
:func:`graphkin.kinematics.vector_equation.solve_vector_equation` and the
report written by :mod:`graphkin.output.vector`; this module parses the
arguments and prints.  Every mistake in the file becomes an
:class:`~graphkin.errors.InputError` naming the file and the key, which the
CLI prints as one line (exit status 2).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 and Table 2.2 (the four cases).
"""

from __future__ import annotations

import argparse
import json
import sys

from graphkin.commands._args import about, command
from graphkin.errors import InputError
from graphkin.kinematics.vector_equation import NAMES, solve_vector_equation
from graphkin.kinematics.vector_file import VectorFile, load, loads
from graphkin.output.vector import vector_json as to_dict
from graphkin.output.vector import vector_text as text_report

__all__ = ["add_parser", "run", "VectorFile", "load", "loads", "text_report", "to_dict"]


HELP = "solve the planar vector equation C = A + B"
DESCRIPTION = about(__doc__)


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "vector", help=HELP, description=DESCRIPTION,
                file="vector file (TOML: [A], [B], [C] with magnitude and angle)")
    for flag, what in (("--json", "print the result as JSON"),
                       ("--steps", "also list every construction step with its marked equation")):
        p.add_argument(flag, action="store_true", help=what)
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    vf = load(args.file)
    try:
        result = solve_vector_equation(*(vf.knowns[n] for n in NAMES), branch=vf.branch)
    except InputError as exc:
        raise InputError(exc.message, key=exc.info.get("key"), file=vf.source) from None
    if args.json:
        json.dump(to_dict(vf, result, args.steps), sys.stdout, ensure_ascii=False, indent=1,
                  allow_nan=False)
        sys.stdout.write("\n")
    else:
        sys.stdout.write(text_report(vf, result, args.steps))
    return 0
