"""``check --scan``: every page of every scan, one report each (a class in one PDF).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity polygon), Sec. 4.3
(the acceleration polygon).
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path
from typing import Any

from graphkin.check.answers import CheckTolerance
from graphkin.check.diagnose import Diagnoser
from graphkin.check.report import Report
from graphkin.errors import InputError
from graphkin.scan import ScanExtraMissing, need_cv2

__all__ = ["scan_reports", "show_path"]


def show_path(show: str, index: int, count: int) -> Path:
    """The debug image of page ``index`` of ``count``: ``out.png``, or ``out-3.png`` for many."""
    p = Path(show)
    return p if count == 1 else p.with_name(f"{p.stem}-{index + 1}{p.suffix or '.png'}")


def scan_reports(sol: Any, mech_file: str, scans: list[str], tol: CheckTolerance,
                 diag: Diagnoser, show: str | None = None, upto: int | None = None
                 ) -> Iterator[tuple[str, Report | None, str]]:
    """``(page name, report or None, error)`` for each page of each scan, in order.

    A page that cannot be read (no markers, an unreadable file) gives
    ``None`` and the one-line reason; the others go on.
    """
    from graphkin.render.worksheet_layout import mechanism_hash
    from graphkin.scan.mark import debug_image, mark_scan
    from graphkin.scan.read import read_sheet
    from graphkin.scan.sheet import read_pages

    cv2 = need_cv2()
    digest = mechanism_hash(Path(mech_file).read_bytes())
    title = getattr(sol.mechanism, "title", "") or Path(mech_file).name
    pages: list[Any] = []
    for path in scans:
        try:
            pages += read_pages(path)
        except InputError as exc:
            if isinstance(exc, ScanExtraMissing):
                raise
            pages.append((path, exc))
    for i, page in enumerate(pages):
        if isinstance(page, tuple):
            yield page[0], None, page[1].one_line()
            continue
        try:
            read = read_sheet(sol, page, diag, digest, title, upto)
        except InputError as exc:
            yield page.name, None, exc.one_line()
            continue
        rep = mark_scan(sol, read, page.name, tol, diag)
        if show:
            out = show_path(show, i, len(pages))
            if not cv2.imwrite(str(out), debug_image(read)):
                raise InputError("cannot write the debug image (use .png or .jpg)",
                                 key="--show", file=str(out))
        yield page.name, rep, ""
