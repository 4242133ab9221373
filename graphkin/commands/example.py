"""``graphkin example list`` / ``graphkin example NAME``: the textbook mechanisms shipped inside.

Print one of the mechanism files shipped with graphkin (Examples 3.1, 3.2, 3.3, 3.9,
4.4, 4.7, 4.11, 5.4 of the textbook, and a planetary train), to save and edit: graphkin
example fourbar > fourbar.toml. 'graphkin example list' names them.

Something to start from right after ``pip install graphkin``, with no
checkout::

    graphkin example list                 # the names and titles
    graphkin example fourbar > fourbar.toml
    graphkin solve fourbar.toml

References
----------
Uicker, Pennock & Shigley, 5th ed.: the worked examples named in each file's title.
"""

from __future__ import annotations

import argparse
import sys

from graphkin.commands._args import about, command

__all__ = ["add_parser", "run"]


HELP = "list the shipped textbook mechanisms, or print one to start from"
DESCRIPTION = about(__doc__)


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "example", help=HELP, description=DESCRIPTION, file=None)
    p.add_argument("name", metavar="NAME", help="an example's name, or 'list'")
    p.add_argument("-o", "--output", metavar="FILE.toml", default=None,
                   help="write the file here instead of standard output")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    from graphkin import examples
    from graphkin.errors import InputError
    from graphkin.keys import nearest

    names = examples.names()
    if args.name == "list":
        width = max(len(n) for n in names)
        for n in names:
            print(f"{n:<{width}}  {examples.load(n).title}")
        return 0
    if args.name not in names:
        guess = nearest(args.name, names)
        hint = f"did you mean {guess!r}? " if guess else ""
        raise InputError(f"no example {args.name!r} ({hint}examples: {', '.join(names)}; "
                         "'graphkin example list' shows their titles)", key="NAME")
    text = examples.text(args.name)
    if args.output is None:
        sys.stdout.write(text)
        return 0
    try:
        with open(args.output, "w", encoding="utf-8") as fh:
            fh.write(text)
    except OSError as exc:
        raise InputError(f"cannot write the file: {exc.strerror}", key="output",
                         file=args.output) from None
    print(f"wrote {args.output}", file=sys.stderr)
    return 0
