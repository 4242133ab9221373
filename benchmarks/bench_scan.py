"""Mark a class: a 30-page PDF of worksheet photos through ``check --scan`` (issue 30: < 60 s).

Usage::

    python benchmarks/bench_scan.py [--pages 30] [--level phone]

The pages are synthetic phone photos of the textbook four-bar's velocity
worksheet (``tests/scan/photos.py``), one student each, every fifth with the
sense of ω2 reversed.  Prints the wall time of ``graphkin check FILE --scan
class.pdf --csv marks.csv`` run in this process (OpenCV's own threads
included); nothing is asserted.
"""

from __future__ import annotations

import argparse
import contextlib
import io
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from scan.photos import (  # noqa: E402
    LEVELS,
    class_pdf,
    exact_images,
    hand_photo,
    layout_for,
    sheet_pixels,
)

import graphkin  # noqa: E402
from graphkin.cli import main  # noqa: E402


def run(pages: int, level: str) -> None:
    src = Path(graphkin.examples.__file__).parent / "data" / "fourbar.toml"
    sol = graphkin.load(src).solve()
    lay = layout_for(sol, "velocity", src.read_text())
    sheet = sheet_pixels(sol, lay)
    right = exact_images(sol, lay)
    pole = np.array(lay.pole)
    wrong = {n: 2 * pole - p for n, p in right.items()}
    with tempfile.TemporaryDirectory() as tmp:
        pdf = Path(tmp) / "class.pdf"
        t = time.perf_counter()
        photos = [hand_photo(sol, lay, sheet, wrong if k % 5 == 4 else right, level, k)
                  for k in range(pages)]
        class_pdf(pdf, photos)
        made = time.perf_counter() - t
        csv = Path(tmp) / "marks.csv"
        t = time.perf_counter()
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            code = main(["check", str(src), "--scan", str(pdf), "--csv", str(csv)])
        took = time.perf_counter() - t
        rows = csv.read_text().splitlines()[1:]
        ok = sum(1 for r in rows if ",100," in r)
    print(f"{pages} pages ({level}) made in {made:.1f} s; marked in {took:.1f} s "
          f"({took / pages:.2f} s a page), exit {code}, {ok} of {pages} full marks "
          f"(intended: {pages - pages // 5})")


if __name__ == "__main__":
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--pages", type=int, default=30)
    ap.add_argument("--level", choices=list(LEVELS), default="phone")
    a = ap.parse_args()
    run(a.pages, a.level)
