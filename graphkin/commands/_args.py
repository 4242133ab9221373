"""What the sub-commands share: their parser, numbers checked where argparse reads them, writing.

A bad value (``--dpi 0``, ``--dpi nan``, ``--count 1e8``, ``--from nan``)
becomes argparse's one-line error and exit status 2, before any work starts;
a file that cannot be written becomes one line naming the option
(:func:`writing`, :func:`write_text`), exit status 2.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

from graphkin.errors import InputError

__all__ = ["finite_float", "bounded_float", "bounded_int", "MAX_COUNT", "DPI_RANGE", "command",
           "writing", "write_text", "about", "page_options"]

#: The most postures a sweep or plot computes at once (memory grows with it).
MAX_COUNT = 1_000_000
#: The resolutions a PNG may be drawn at (dots per inch).
DPI_RANGE = (10.0, 1200.0)


def finite_float(text: str) -> float:
    """A finite number (no nan, no inf)."""
    try:
        v = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not math.isfinite(v):
        raise argparse.ArgumentTypeError(f"must be a finite number, not {text!r}")
    return v


def bounded_float(lo: float, hi: float) -> Callable[[str], float]:
    """A finite number in ``[lo, hi]``."""

    def read(text: str) -> float:
        v = finite_float(text)
        if not lo <= v <= hi:
            raise argparse.ArgumentTypeError(f"must be between {lo:g} and {hi:g}, not {text}")
        return v

    read.__name__ = "number"
    return read


def bounded_int(lo: int, hi: int) -> Callable[[str], int]:
    """A whole number in ``[lo, hi]``."""

    def read(text: str) -> int:
        try:
            v = int(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
        if not lo <= v <= hi:
            raise argparse.ArgumentTypeError(f"must be between {lo} and {hi}, not {text}")
        return v

    read.__name__ = "whole number"
    return read


def about(doc: str | None) -> str:
    r"""A command's description for ``--help``: the second paragraph of its module's docstring.

    Examples
    --------
    >>> about("Title.\n\nWhat it does,\n  in two lines.\n\nMore.")
    'What it does, in two lines.'
    """
    parts = (doc or "").split("\n\n")
    return " ".join(parts[1].split()) if len(parts) > 1 else ""


def command(sub: argparse._SubParsersAction, name: str, *, help: str | None,
            description: str, file: str | None = "mechanism file (TOML)"
            ) -> argparse.ArgumentParser:
    """A sub-command's parser, its first argument the file it reads (``file`` is its help)."""
    p = sub.add_parser(name, help=help, description=description)
    if file is not None:
        p.add_argument("file", help=file)
    return p


@contextmanager
def writing(what: str, key: str) -> Iterator[None]:
    """Writing ``what`` (``"out.html"``, ``"into frames/"``): an OSError becomes one line.

    Examples
    --------
    >>> with writing("into /nonexistent/dir", "--frames"):
    ...     Path("/nonexistent/dir/f.svg").write_text("x")
    Traceback (most recent call last):
    ...
    graphkin.errors.InputError: cannot write into /nonexistent/dir: No such file or directory
    """
    try:
        yield
    except OSError as exc:
        raise InputError(f"cannot write {what}: {exc.strerror or exc}", key=key) from None


def write_text(path: str | Path, text: str, key: str) -> Path:
    """Write a text file (UTF-8) for an option; its path."""
    out = Path(path)
    with writing(str(out), key):
        out.write_text(text, encoding="utf-8")
    return out


def page_options(p: argparse.ArgumentParser, frames: str) -> None:
    """``-o OUT.html`` (the page) and ``--frames DIR`` (one SVG per ``frames``) of a web page."""
    p.add_argument("-o", "--output", default=None, help="the HTML file to write")
    p.add_argument("--frames", default=None, metavar="DIR",
                   help=f"also write one {frames} into DIR")
