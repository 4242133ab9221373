"""Compare scan readers on one sample: draw it once, read it with any checkout's code.

Usage::

    python benchmarks/scan_fixed_sample.py save sample.json [--draws 160] [--seed S]
    python benchmarks/scan_fixed_sample.py read sample.json [--levels scan mild phone harsh]
        [--cases right reversed length] [--why] [--only N ...]

``save`` writes the raw draws of ``tests/strategies.py`` (four-bars and
slider-cranks, a diagram, a photo seed, a wrong length) as JSON; ``read``,
run from any checkout (its ``tests/scan/photos.py`` and its ``graphkin``),
photographs and reads the same drawings: right, reversed (turned 180°) and
one image 3-10 % too long or short.  That image is intended ``WRONG`` only
when its end is moved at least the drawing tolerance (0.5 mm on the sheet,
``mark_scan``'s default): an end within it is right by the tolerance's own
rule (docs/checking.md "Tolerances"), so such a drawing is intended all
right; the old count (that image always ``WRONG``) is printed as well.
``scan_reading_rate.py`` draws its
sample anew each run, and the sample changes with the code (docs/checking.md
"How well it reads"), so two readers are compared here.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import defaultdict
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path.cwd() / "tests"))


def save(path: str, draws: int, seed: int | None = None) -> None:
    from hypothesis import HealthCheck, Phase, given, settings
    from hypothesis import seed as with_seed
    from hypothesis import strategies as st
    from strategies import fourbars, slider_cranks

    out: list[dict[str, Any]] = []

    @settings(max_examples=draws, derandomize=seed is None, database=None, deadline=None,
              phases=[Phase.generate], suppress_health_check=list(HealthCheck))
    @given(rm=st.one_of(fourbars(), slider_cranks()),
           diagram=st.sampled_from(["velocity", "acceleration"]),
           seed=st.integers(0, 2**16), factor=st.floats(0.03, 0.10), longer=st.booleans())
    def one(rm: Any, diagram: str, seed: int, factor: float, longer: bool) -> None:
        out.append({"kind": rm.kind, "data": rm.data, "diagram": diagram, "seed": seed,
                    "factor": factor, "longer": longer})

    (with_seed(seed)(one) if seed is not None else one)()
    Path(path).write_text(json.dumps(out), encoding="utf-8")
    print(f"{len(out)} draws written to {path}")


#: The drawing tolerance ``mark_scan`` uses when none is given (mm on the sheet).
DRAWING_MM = 0.5

#: A photo not read as intended whose every image was read within this of where it was
#: drawn (mm on the sheet) is counted apart: the reading is right, and the verdict differs
#: only because the drawn image lies near the tolerance's edge (docs/checking.md).
EDGE_MM = 0.25


def planted_wrong(name: str, image: Any, pole: Any, factor: float) -> str | None:
    """The image a wrong-length drawing intends ``WRONG``, or None when it moved too little.

    ``image`` is scaled by ``factor`` from ``pole`` (sheet mm): its end moves
    ``|factor - 1|`` times its length, and an end moved under the drawing
    tolerance is right by the tolerance's rule (docs/checking.md).
    """
    moved = abs(factor - 1) * float(np.hypot(*(np.asarray(image) - np.asarray(pole))))
    return name if moved >= DRAWING_MM else None


def read_right(points: dict[str, Any], drawn: dict[str, Any]) -> bool:
    """Whether every drawn image was read, each within :data:`EDGE_MM` of where it was drawn."""
    return set(points) == set(drawn) and all(
        float(np.hypot(*(np.asarray(points[k]) - np.asarray(drawn[k])))) <= EDGE_MM
        for k in drawn)


def _intended(case: str, rows: list[Any], wrong: str | None) -> bool:
    """Whether every row is marked as the drawing intends.

    ``wrong``: the wrong-length drawing's image intended ``WRONG``; None, none
    is (the reversed drawing is intended reversed all the same).
    """
    from graphkin.check.report import OK, WRONG

    if case == "right" or (case == "length" and wrong is None):
        return all(r.verdict == OK for r in rows)
    if case == "reversed":
        return all(r.code == "sense" or r.code.startswith("follows:") for r in rows) and \
            any(r.code == "sense" for r in rows)
    return all((r.verdict == WRONG) if r.key.endswith(f"_{wrong}") else (r.verdict == OK)
               for r in rows)


def read(path: str, levels: list[str], only: list[str], why: bool = False,
         numbers: list[int] | None = None) -> None:
    from scan.photos import exact_images, hand_photo, layout_for, sheet_pixels

    from graphkin.check import CheckTolerance, Diagnoser, Evaluator
    from graphkin.check.report import OK
    from graphkin.mechanisms import from_dict
    from graphkin.scan.mark import mark_scan
    from graphkin.scan.read import read_sheet
    from graphkin.scan.sheet import Page

    tally: dict[tuple[str, str], list[int]] = defaultdict(lambda: [0, 0])
    false, n, seen, small, edge = 0, 0, set(), 0, 0
    for d in json.loads(Path(path).read_text(encoding="utf-8")):
        sol = from_dict(d["data"]).solve()
        lay = layout_for(sol, d["diagram"], d["kind"])
        images = exact_images(sol, lay)
        key = (d["diagram"], d["seed"],
               tuple(sorted((k, *np.round(v, 2)) for k, v in images.items())))
        pole, pts = np.array(lay.pole), list(images.values())
        if key in seen or not images or any(np.hypot(*(p - pole)) < 7 for p in pts) or any(
                np.hypot(*(p - q)) < 5 for i, p in enumerate(pts) for q in pts[i + 1:]):
            seen.add(key)
            continue
        seen.add(key)
        n += 1
        if numbers and n not in numbers:
            continue
        name = sorted(images)[d["seed"] % len(images)]
        f = 1 + d["factor"] if d["longer"] else 1 - d["factor"]
        wrong = planted_wrong(name, images[name], pole, f)
        small += wrong is None
        cases = {"right": images, "reversed": {k: 2 * pole - p for k, p in images.items()},
                 "length": {**images, name: pole + f * (images[name] - pole)}}
        cases = {c: v for c, v in cases.items() if c in only}
        diag, sheet = Diagnoser(Evaluator(sol)), sheet_pixels(sol, lay)
        for level in levels:
            for case, drawn in cases.items():
                photo = hand_photo(sol, lay, sheet, drawn, level, d["seed"])
                got = None
                try:
                    got = read_sheet(sol, Page("p", photo), diag, lay.digest)
                    rows = mark_scan(sol, got, "p", CheckTolerance(), diag).rows
                    good = _intended(case, rows, wrong)
                    old = case == "length" and _intended(case, rows, name)
                except Exception as exc:  # noqa: BLE001 - counted as not read
                    rows, good, old = [], False, False
                    if why:
                        print(f"  #{n} raised {type(exc).__name__}: {exc}", flush=True)
                if why and not good:
                    bad = [f"{r.key} {r.verdict} {r.code}" for r in rows
                           if r.verdict != OK or r.key.endswith(f"_{wrong}")]
                    print(f"  #{n} {d['kind']} {d['diagram']} seed {d['seed']} {level} {case}"
                          f" (wrong {wrong}): " + ("; ".join(bad) or "no rows"), flush=True)
                if not good and got is not None and read_right(got.points, drawn):
                    edge += 1                      # read right: the verdict is on the edge
                tally[(level, case)][0] += good
                tally[(level, case)][1] += 1
                tally[(level, "old length")][0] += old
                tally[(level, "old length")][1] += case == "length"
                false += case == "right" and any(
                    r.verdict != OK and r.code not in ("unexplained", "not-found") for r in rows)
    print(f"{n} mechanisms; {small} wrong lengths move their image under {DRAWING_MM} mm "
          "(intended all right)")
    for level in levels:
        print(level, "  ".join(f"{c} {tally[(level, c)][0]}/{tally[(level, c)][1]}"
                               for c in (*only, "old length") if tally[(level, c)][1]))
    print("right drawings with a usual mistake named:", false)
    print(f"photos not read as intended whose every image was read within {EDGE_MM} mm of "
          f"where it was drawn (a wrong length moved near the tolerance): {edge}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=["save", "read"])
    ap.add_argument("sample")
    ap.add_argument("--draws", type=int, default=160)
    ap.add_argument("--seed", type=int, default=None,
                    help="draw at random from this seed instead of Hypothesis's derandomized "
                         "order (which starts from the simplest mechanisms)")
    ap.add_argument("--levels", nargs="+", default=["scan", "mild", "phone", "harsh"])
    ap.add_argument("--cases", nargs="+", choices=["right", "reversed", "length"],
                    default=["right", "reversed", "length"])
    ap.add_argument("--only", nargs="+", type=int, metavar="N",
                    help="read only these mechanisms (the numbers --why prints)")
    ap.add_argument("--why", action="store_true",
                    help="print each photo not read as intended, with its rows")
    args = ap.parse_args()
    if args.what == "save":
        save(args.sample, args.draws, args.seed)
    else:
        read(args.sample, args.levels, args.cases, args.why, args.only)


if __name__ == "__main__":
    main()
