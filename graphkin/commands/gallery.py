"""``graphkin gallery [--check] [--dir gallery]``: rebuild or check the textbook-figure gallery.

Solve and draw every mechanism file of the gallery (gallery/mechanisms, gallery/centers,
gallery/curvature), write the drawings into gallery/drawings and the index
gallery/README.md with the book's numbers beside graphkin's. With --check, write nothing
and exit 1 when a committed drawing or the index is out of date.
"""

from __future__ import annotations

import argparse
import sys

from graphkin.commands._args import about

__all__ = ["add_parser", "run"]


DESCRIPTION = about(__doc__)


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    # a maintainer's tool (it works on a checkout's gallery/ folder): no help= keeps it
    # out of `graphkin --help`, and it still runs for CI and the gallery's maintainers
    p = sub.add_parser("gallery", description=DESCRIPTION)
    p.add_argument("--dir", default="gallery", help="the gallery folder (default: gallery)")
    p.add_argument("--check", action="store_true",
                   help="exit 1 when a committed drawing is out of date; write nothing")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    from pathlib import Path

    from graphkin.errors import InputError
    from graphkin.render.gallery import build, check, discover

    root = Path(args.dir)
    if not root.is_dir() or not discover(root):
        raise InputError(f"{root} is not a gallery folder (no mechanisms/*.toml in it)",
                         key="--dir")
    if args.check:
        problems = check(root)
        for p in problems:
            print(p, file=sys.stderr)
        if problems:
            print(f"graphkin: the gallery is out of date ({len(problems)} files); run "
                  f"`graphkin gallery --dir {root}`", file=sys.stderr)
            return 1
        print("the gallery is up to date", file=sys.stderr)
        return 0
    written = build(root)
    print(f"wrote {len(written)} drawings and {root / 'README.md'}", file=sys.stderr)
    return 0
