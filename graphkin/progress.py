"""Progress bars for the long jobs: sweeps, plots, animations, gallery builds.

A bar is drawn on standard error with tqdm, only when standard error is a
terminal (never into a pipe, a log or a test's captured output) and only
once the job has run for :data:`DELAY` seconds, so short jobs print nothing.
The whole API is two functions::

    from graphkin.progress import bar, track

    for frame in track(frames, "animate", unit="frame"):   # a loop
        ...

    with bar("sweep", total=count, unit="posture") as b:    # a job that reports
        sweep(mech, count=count, progress=b.fraction)       # a fraction done
        b.update(10)                                        # or steps done

Library code does not draw bars itself: it takes a ``progress`` callback (a
fraction in [0, 1]), and the command line passes :meth:`Bar.fraction`.
"""

from __future__ import annotations

import sys
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from typing import IO, Any, TypeVar

__all__ = ["DELAY", "Bar", "bar", "track", "enabled", "CountingWriter"]

T = TypeVar("T")

DELAY = 1.0
"""Seconds a job runs before its bar appears: short jobs print nothing."""


def enabled(stream: IO[str] | None = None) -> bool:
    """True when bars should be drawn: ``stream`` (default standard error) is a terminal."""
    stream = sys.stderr if stream is None else stream
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):  # a closed or unusual stream
        return False


class Bar:
    """One progress bar (a thin wrapper over :class:`tqdm.tqdm`, or nothing at all).

    Parameters
    ----------
    desc : str
        What is running (``"sweep"``, ``"write CSV"``, ``"gallery"``).
    total : float, optional
        How many steps make the whole job (unknown: a counter without a bar).
    unit : str
        The name of one step (``"posture"``, ``"row"``, ``"frame"``).
    show : bool, optional
        Force the bar on or off (default: :func:`enabled`).
    """

    def __init__(self, desc: str, total: float | None = None, unit: str = "it",
                 show: bool | None = None) -> None:
        self.total = total
        self._tqdm: Any = None
        if enabled() if show is None else show:
            from tqdm import tqdm

            big = total is not None and total >= 10_000  # 200k rather than 200000.0
            self._tqdm = tqdm(total=total, desc=desc, unit=unit, delay=DELAY, leave=False,
                              file=sys.stderr, dynamic_ncols=True, unit_scale=big)

    def update(self, n: float = 1) -> None:
        """``n`` more steps are done."""
        if self._tqdm is not None:
            self._tqdm.update(n)

    def fraction(self, done: float) -> None:
        """The fraction ``done`` (0 to 1) of the job is done: a ``progress`` callback."""
        if self._tqdm is not None and self.total:
            self._tqdm.update(done * self.total - self._tqdm.n)

    def close(self) -> None:
        """Remove the bar (it is left off the terminal when the job is done)."""
        if self._tqdm is not None:
            self._tqdm.close()
            self._tqdm = None

    def __enter__(self) -> Bar:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


@contextmanager
def bar(desc: str, total: float | None = None, unit: str = "it",
        show: bool | None = None) -> Iterator[Bar]:
    """A progress bar for the ``with`` block (see :class:`Bar`).

    Examples
    --------
    Off a terminal nothing is drawn and the calls cost nothing:

    >>> with bar("sweep", total=4, unit="posture") as b:
    ...     b.fraction(0.5)
    ...     b.update(2)
    """
    b = Bar(desc, total, unit, show)
    try:
        yield b
    finally:
        b.close()


def track(items: Iterable[T], desc: str, total: int | None = None, unit: str = "it",
          show: bool | None = None) -> Iterator[T]:
    """Iterate over ``items`` with a progress bar (one step per item).

    Examples
    --------
    >>> [x * x for x in track(range(4), "squares")]
    [0, 1, 4, 9]
    """
    if total is None:
        try:
            total = len(items)  # type: ignore[arg-type]
        except TypeError:
            total = None
    with bar(desc, total, unit, show) as b:
        for item in items:
            yield item
            b.update(1)


class CountingWriter:
    """A text file that moves a bar on by one step for each line written.

    ``csv.writer`` writes one row per ``write`` call, so wrapping the file
    gives a bar over the rows of a CSV without touching the writer.
    """

    def __init__(self, fh: IO[str], progress: Bar, every: int = 2048) -> None:
        self._fh = fh
        self._bar = progress
        self._every = every
        self._pending = 0

    def write(self, text: str) -> int:
        """Write ``text``; every ``every`` calls, move the bar on."""
        self._pending += 1
        if self._pending >= self._every:
            self._bar.update(self._pending)
            self._pending = 0
        return self._fh.write(text)

    def flush(self) -> None:
        """Flush the file and bring the bar up to date."""
        if self._pending:
            self._bar.update(self._pending)
            self._pending = 0
        self._fh.flush()
