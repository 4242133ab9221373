"""A fitted drawing scale is written in the SVG's millimetres (audit9, item 12).

The SVG is 200 mm wide with a 200-unit viewBox: one drawing unit is 1 mm.  Its
line a runs from (100, 100) to (136.03887, 151.46884): 62.832 mm long; V_A of
fb_q3 is ω2 · O2A = (120 rev/min = 4π rad/s)(2.5 in) = 10π = 31.416 in/s, so
the fitted scale is 1 mm = 31.416/62.832 = 0.5 in/s.
"""

from __future__ import annotations

import math
from pathlib import Path

from graphkin.cli import main

DATA = Path(__file__).resolve().parents[1] / "data" / "check_units"


def test_the_fit_is_said_in_millimetres(capsys):
    main(["check", str(DATA / "fb_q3.toml"), "--drawing", str(DATA / "v_reversed_noscale.svg")])
    title, tol = capsys.readouterr().out.splitlines()[:2]
    per_mm = 10 * math.pi / math.hypot(136.0388703742532 - 100, 151.46884089022714 - 100)
    assert f"1 mm = {per_mm:.4g} in/s" == "1 mm = 0.5 in/s"
    assert "1 mm = 0.5 in/s, turned" in title and "drawing unit" not in title
    assert tol.endswith("(1 mm = 0.5 in/s, fitted)")
