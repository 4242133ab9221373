"""The ``graphkin`` command line: a thin shell over the library.

Each sub-command lives in its own module of :mod:`graphkin.commands` with two
functions, ``add_parser(subparsers)`` and ``run(args) -> int``.  User mistakes
(:class:`~graphkin.errors.GraphkinError`) become one line on standard error
naming the file and key, and exit status 2 — never a traceback.
"""

from __future__ import annotations

import argparse
import importlib
import pkgutil
import sys
from collections.abc import Sequence

from graphkin.errors import AssemblyError, GraphkinError, InputError

__all__ = ["main", "build_parser"]


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with every sub-command of :mod:`graphkin.commands`."""
    import graphkin.commands as commands

    parser = argparse.ArgumentParser(
        prog="graphkin",
        description="Graphic constructions of planar mechanism kinematics "
                    "(Uicker, Pennock & Shigley), exact and drawn.",
        epilog="To start: graphkin example list; graphkin example fourbar > fourbar.toml; "
               "graphkin solve fourbar.toml. 'graphkin COMMAND --help' for each command.")
    parser.add_argument("--version", action="version", version=_version())
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for info in sorted(pkgutil.iter_modules(commands.__path__), key=lambda m: m.name):
        if info.name.startswith("_"):
            continue
        module = importlib.import_module(f"graphkin.commands.{info.name}")
        p = module.add_parser(sub)
        p.set_defaults(_run=module.run)
    return parser


def _version() -> str:
    from graphkin import __version__

    return f"graphkin {__version__}"


def main(argv: Sequence[str] | None = None) -> int:
    """Run the command line; returns the exit status."""
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "_run", None):
        parser.print_help()
        return 2
    try:
        return int(args._run(args) or 0)
    except InputError as exc:
        print(f"graphkin: {exc.one_line()}", file=sys.stderr)
        return 2
    except GraphkinError as exc:
        where = getattr(args, "file", None)
        key = getattr(exc, "key", None) or ("drive" if isinstance(exc, AssemblyError) else None)
        parts = [p for p in (where, key) if p]
        print(f"graphkin: {': '.join([*parts, str(exc)])}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
