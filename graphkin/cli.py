r"""The ``graphkin`` command line: a thin shell over the library.

Each sub-command lives in its own module of :mod:`graphkin.commands` with two
functions, ``add_parser(subparsers)`` and ``run(args) -> int``.  User mistakes
(:class:`~graphkin.errors.GraphkinError`) become one line on standard error
naming the file and key, and exit status 2 — never a traceback.

Everything written to the terminal passes through :class:`SafeStream`, which
shows control characters (an ESC sequence in a title, a bell, a bidi
override) as ``\u001b``-style escapes instead of letting the terminal run
them.  A last-resort guard turns any unexpected exception into one line and
exit status 2; the classes of hostile input are handled where they arise.
"""

from __future__ import annotations

import argparse
import importlib
import pkgutil
import re
import sys
import warnings
from collections.abc import Sequence
from typing import Any, TextIO

from graphkin.errors import AssemblyError, GraphkinError, InputError

__all__ = ["main", "build_parser", "SafeStream", "escape_controls"]

# C0 controls except tab and newline, DEL, C1 controls, and the bidi overrides
_CONTROLS = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u200e\u200f\u202a-\u202e"
                       "\u2066-\u2069]")
_CONTROLS_CR = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f\u200e\u200f"
                          "\u202a-\u202e\u2066-\u2069]")
#: The longest message line the CLI prints (a hostile value is cut, not echoed whole).
MAX_MESSAGE = 500


def escape_controls(text: str, keep_cr: bool = False) -> str:
    r"""Show control characters as ``\uXXXX`` escapes (valid in JSON strings too).

    Examples
    --------
    >>> escape_controls("a\x1b]0;owned\x07b\n")
    'a\\u001b]0;owned\\u0007b\n'
    """
    pattern = _CONTROLS_CR if keep_cr else _CONTROLS
    return pattern.sub(lambda m: f"\\u{ord(m.group()):04x}", text)


class SafeStream:
    """A text stream that escapes control characters before they reach the terminal.

    ``keep_cr`` keeps carriage returns (the progress bar on standard error).
    """

    def __init__(self, stream: TextIO, keep_cr: bool = False) -> None:
        self._stream = stream
        self._keep_cr = keep_cr

    def write(self, text: str) -> int:
        """Write ``text`` with its control characters escaped."""
        self._stream.write(escape_controls(text, self._keep_cr))
        return len(text)

    def writelines(self, lines: Any) -> None:
        """Write each line (escaped)."""
        for line in lines:
            self.write(line)

    def __getattr__(self, name: str) -> Any:
        return getattr(self._stream, name)


class _Parser(argparse.ArgumentParser):
    """argparse with one-line errors (``graphkin: sweep: argument --count: ...``)."""

    def error(self, message: str) -> Any:  # type: ignore[override]
        verb = self.prog.split()[-1]
        where = "" if verb == "graphkin" else f"{verb}: "   # the top level: no verb to name
        self.exit(2, f"graphkin: {where}{_clip(message)}\n")


def _clip(text: str) -> str:
    """One line of at most :data:`MAX_MESSAGE` characters."""
    line = " ".join(str(text).split())
    return line if len(line) <= MAX_MESSAGE else line[:MAX_MESSAGE - 1] + "…"


def build_parser() -> argparse.ArgumentParser:
    """The argument parser with every sub-command of :mod:`graphkin.commands`."""
    import graphkin.commands as commands

    parser = _Parser(
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
    out, err = sys.stdout, sys.stderr
    if not isinstance(out, SafeStream):
        sys.stdout = SafeStream(out)  # type: ignore[assignment]
    if not isinstance(err, SafeStream):
        sys.stderr = SafeStream(err, keep_cr=True)  # type: ignore[assignment]
    try:
        return _main(argv)
    finally:
        sys.stdout, sys.stderr = out, err


def _main(argv: Sequence[str] | None) -> int:
    import numpy as np

    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "_run", None):
        parser.print_help()
        return 2
    where = getattr(args, "file", None)
    try:
        # library warnings (numpy's RuntimeWarnings, matplotlib's missing glyphs) never reach
        # the user: results are checked for finiteness, and errors are one line each
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore")
            from graphkin.files import check_outputs

            check_outputs(vars(args))  # nothing the user gave may be lost, in every command
            return int(args._run(args) or 0)
    except InputError as exc:
        print(f"graphkin: {_clip(exc.one_line())}", file=sys.stderr)
        return 2
    except GraphkinError as exc:
        key = getattr(exc, "key", None) or ("drive" if isinstance(exc, AssemblyError) else None)
        parts = [p for p in (where, key) if p]
        print(f"graphkin: {_clip(': '.join([*parts, str(exc)]))}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return 0
    except KeyboardInterrupt:
        print("graphkin: interrupted", file=sys.stderr)
        return 130
    except (RecursionError, OverflowError, MemoryError, FloatingPointError) as exc:
        reason = {RecursionError: "the input is nested or chained too deeply",
                  OverflowError: "a number in the input is too large",
                  MemoryError: "the input is too large to hold in memory",
                  }.get(type(exc), "a number in the input is not finite")
        print(f"graphkin: {_clip(': '.join(p for p in (where, reason) if p))}",
              file=sys.stderr)
        return 2
    except Exception as exc:  # the last-resort net: one line, never a traceback
        what = "cannot handle this input" if where else "internal error"
        parts = [p for p in (where, what, f"{type(exc).__name__}: {exc}") if p]
        print(f"graphkin: {_clip(': '.join(parts))}", file=sys.stderr)
        return 2


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
