"""Time a drag on the live page (issue 29): re-solve the posture and redraw every panel.

For each spec example, the page of ``graphkin live`` is opened in headless
Chromium and timed inside the page with ``performance.now()``:

* ``solve``: one call of the written-out construction (posture, velocity and
  acceleration polygons), the mean of 20 000 calls at drive values a drag
  would give;
* ``drag``: one pointer move's work, re-solve plus redraw of the three
  panels and the table (``graphkinLive.setDrive``), the mean of 300 moves;

and the page's size. Run::

    python benchmarks/bench_live.py

The issue's targets: a drag under 16 ms (60 frames a second), the page under
1 MB.  Nothing is asserted.
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))

from cdp import Browser  # noqa: E402
from spec_data import EXAMPLES  # noqa: E402

import graphkin  # noqa: E402
from graphkin.files import load_toml  # noqa: E402
from graphkin.render.live import live_html  # noqa: E402

TIMING = """(function () {
  var L = window.graphkinLive, s = L.state(), d0 = s.drive, n = 20000, m = 300;
  var I = {}; var D = JSON.parse(document.getElementById('gk-data').textContent);
  Object.assign(I, D.inputs);
  var t0 = performance.now(), ok = 0;
  for (var k = 0; k < n; k++) {
    I[D.drive.label] = d0 + 1e-3 * Math.sin(k);
    if (construction(I, s.K) !== null) ok++;
  }
  var t1 = performance.now();
  for (var j = 0; j < m; j++) L.setDrive(d0 + 0.02 * Math.sin(j));
  var t2 = performance.now();
  L.setDrive(d0);
  return {solve: (t1 - t0) / n, drag: (t2 - t1) / m, ok: ok / n};
})()"""


def main() -> None:
    b = Browser(1300, 1000)
    try:
        print(f"{'example':28s} {'KiB':>6s} {'solve µs':>9s} {'drag ms':>8s}")
        with tempfile.TemporaryDirectory() as tmp:
            for path in sorted(EXAMPLES.glob("ex[0-9]*.toml")):
                page = Path(tmp) / (path.stem + ".html")
                text = live_html(graphkin.load(path), load_toml(path), path.name)
                page.write_text(text, encoding="utf-8")
                b.open(page)
                time.sleep(0.1)
                r = b.js(TIMING)
                print(f"{path.stem:28s} {len(text.encode()) / 1024:6.0f} "
                      f"{1000 * r['solve']:9.2f} {r['drag']:8.2f}")
    finally:
        b.close()


if __name__ == "__main__":
    main()
