"""Argument types shared by the sub-commands: numbers checked where argparse reads them.

A bad value (``--dpi 0``, ``--dpi nan``, ``--count 1e8``, ``--from nan``)
becomes argparse's one-line error and exit status 2, before any work starts.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable

__all__ = ["finite_float", "bounded_float", "bounded_int", "MAX_COUNT", "DPI_RANGE"]

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
