"""Time the first use of a unit string (issue 25): the common units without pint's registry.

Each case runs in a fresh interpreter (the registry is built once per process,
so only a fresh one shows the first use): ``import graphkin`` first, then
``graphkin.load(FILE)`` timed, and whether ``pint`` was imported.  The same
files are timed once more with the fast table switched off (every unit through
pint), which is what the first use cost before.  Run::

    python benchmarks/bench_units.py

Nothing is asserted; ``tests/test_units_fast.py`` checks that the fast path
gives pint's values bit for bit and that these files load without pint.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FILES = ["examples/fourbar.toml", "graphkin/examples/data/slider_crank.toml",
         "examples/planetary_outside.toml",
         "gallery/mechanisms/ex11_4_slider_crank_friction.toml",
         "gallery/mechanisms/ex12_4_fourbar_dynamic.toml"]

CODE = """
import sys, time
import graphkin, graphkin.units as U
if {slow}:
    U._common = lambda *a: None              # every rate through pint, as before
    U._COMMON_LENGTHS.clear()
t = time.perf_counter()
graphkin.load({path!r})
print(f"{{(time.perf_counter() - t) * 1000:.1f}} {{'pint' in sys.modules}}")
"""


def main() -> None:
    print(f"{'file':55s} {'fast ms':>8s} {'pint?':>6s} {'before ms':>10s}")
    for f in FILES:
        row = []
        for slow in (False, True):
            out = subprocess.run([sys.executable, "-c", CODE.format(slow=slow, path=str(ROOT / f))],
                                 capture_output=True, text=True, check=True).stdout.split()
            row.append(out)
        print(f"{f:55s} {row[0][0]:>8s} {row[0][1]:>6s} {row[1][0]:>10s}")


if __name__ == "__main__":
    main()
