"""Per photo, what ``check --scan`` read against what was drawn: the misreads' causes.

Usage::

    python benchmarks/scan_misreads.py [--mechanisms 15] [--levels scan mild]
        [--case right] [--all] [--save DIR]

The same mechanisms and photos as ``scan_reading_rate.py`` (derandomized).
For every image point of every photo it prints the error of the point read
(mm on the sheet) along and across its vector from the pole, the angles at
which the other strokes drawn to that image meet the vector, and the
segments found ending within 4 mm of the image (their length, their angle
to the vector, how far their end is from the image along and across their
own line), so that each misread can be put down to its cause: an end run on
by an arrowhead barb or a letter, a line misfitted, a narrow crossing, a
stroke lost.  ``--all`` prints every image, not only those marked wrong;
``--save DIR`` writes the rectified sheet of each misread photo with the
segments drawn (``check --scan --show``'s debug image).
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
sys.path.insert(0, str(HERE))

from scan.photos import (  # noqa: E402
    LEVELS,
    hand_photo,
    links_of,
    sheet_pixels,
)
from scan_reading_rate import sample  # noqa: E402

from graphkin.check import CheckTolerance, Diagnoser, Evaluator  # noqa: E402
from graphkin.check.report import OK  # noqa: E402
from graphkin.scan.mark import debug_image, mark_scan  # noqa: E402
from graphkin.scan.read import read_sheet  # noqa: E402
from graphkin.scan.sheet import Page  # noqa: E402


def _angle(u: np.ndarray, v: np.ndarray) -> float:
    """The angle between two lines (0-90°)."""
    c = abs(float(u @ v)) / (float(np.hypot(*u)) * float(np.hypot(*v)))
    return math.degrees(math.acos(min(c, 1.0)))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--mechanisms", type=int, default=15)
    ap.add_argument("--levels", nargs="+", choices=list(LEVELS), default=list(LEVELS))
    ap.add_argument("--case", choices=["right", "reversed", "length"], default="right")
    ap.add_argument("--all", action="store_true", help="print every image, not only misreads")
    ap.add_argument("--save", type=Path, default=None)
    args = ap.parse_args()
    stats: list[tuple[str, float, float, float, bool]] = []

    drawn_all, _skipped = sample(args.mechanisms)
    for mech_no, m in enumerate(drawn_all, 1):
        sol, lay, diagram, seed = m.sol, m.lay, m.diagram, m.seed
        pole = np.array(lay.pole)
        diag = Diagnoser(Evaluator(sol))
        sheet = sheet_pixels(sol, lay)
        drawn = m.cases[args.case]
        links = links_of(sol)
        for level in args.levels:
            photo = hand_photo(sol, lay, sheet, drawn, level, seed)
            try:
                read = read_sheet(sol, Page("p", photo), diag, lay.digest)
                rows = mark_scan(sol, read, "p", CheckTolerance(), diag).rows
            except Exception as exc:  # noqa: BLE001 - reported
                print(f"#{mech_no} {m.kind} {diagram} {level}: {exc}")
                continue
            verdict = {r.key.split("_", 1)[-1]: r for r in rows}
            bad = [n for n, r in verdict.items() if r.verdict != OK]
            head = (f"#{mech_no} {m.kind} {diagram} {level} seed={seed}: "
                    + ("read" if not bad else "MISREAD " + " ".join(bad)))
            print(head)
            if bad and args.save is not None:
                import cv2

                args.save.mkdir(parents=True, exist_ok=True)
                cv2.imwrite(str(args.save / f"m{mech_no}_{diagram[0]}_{level}.png"),
                            debug_image(read))
            for n, truth in drawn.items():
                if n not in read.places:
                    continue
                r = verdict.get(n)
                ok = r is not None and r.verdict == OK
                v = truth - pole
                length = float(np.hypot(*v))
                u = v / length
                nrm = np.array([-u[1], u[0]])
                got = read.points.get(n)
                if got is None:
                    stats.append((level, math.nan, math.nan, length, ok))
                    if not ok or args.all:
                        print(f"   {n}: NOT FOUND  |v|={length:.1f}")
                    continue
                e = got - truth
                stats.append((level, float(e @ u), float(e @ nrm), length, ok))
                if ok and not args.all:
                    continue
                others = [m for link in links if n in link for m in link
                          if m != n and m in drawn]
                crossing = [f"{m}:{_angle(v, drawn[m] - truth):.0f}°" for m in others]
                print(f"   {n}: {'ok ' if ok else 'BAD'} |v|={length:.1f} along={e @ u:+.2f} "
                      f"across={e @ nrm:+.2f}  links {' '.join(crossing)}"
                      + ("" if ok else f"  [{r.verdict} {r.code} {r.error}]" if r else ""))
                for s in read.segments:
                    for k in (0, 1):
                        end, other = s[k], s[1 - k]
                        if float(np.hypot(*(end - truth))) > 4.0:
                            continue
                        d = end - other
                        ln = float(np.hypot(*d))
                        du = d / ln
                        # the true line through the image nearest this segment's direction
                        cands = [pole] + [drawn[m] for m in others]
                        best = min(cands, key=lambda c: _angle(d, truth - c))
                        t = truth - best
                        tu = t / float(np.hypot(*t))
                        # end's overshoot along its own line, and its line's miss of the image
                        over = float((end - truth) @ du)
                        miss = float((truth - end) @ np.array([-du[1], du[0]]))
                        src = "pole" if best is pole else next(
                            m for m in others if drawn[m] is best)
                        print(f"      seg len={ln:5.1f} vs {src:>4} "
                              f"ang={_angle(d, tu * 1.0):4.1f}° over={over:+.2f} "
                              f"line-miss={miss:+.2f}")

    print()
    for level in args.levels:
        rows = [s for s in stats if s[0] == level]
        along = np.array([s[1] for s in rows if not math.isnan(s[1])])
        across = np.array([s[2] for s in rows if not math.isnan(s[2])])
        if not len(along):
            continue
        print(f"{level}: {len(rows)} images, {sum(not s[4] for s in rows)} wrong; "
              f"along median {np.median(along):+.2f} |90%| {np.quantile(abs(along), 0.9):.2f} "
              f"max {abs(along).max():.2f}; across |90%| {np.quantile(abs(across), 0.9):.2f} "
              f"max {abs(across).max():.2f}")


if __name__ == "__main__":
    main()
