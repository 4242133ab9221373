"""A results table keeps six significant figures at every scale (audit9, item 8).

A four-bar in nanometres (crank O2A = 2.5e-6 nm, ω2 = 120 rev/min cw) showed
V_A as "3.14e-5": three figures, against six at everyday sizes.  By hand:
|V_A| = ω2 · O2A = (120 · 2π/60 rad/s)(2.5e-6 nm) = 1e-5 π nm/s = 3.14159e-5 nm/s.
"""

from __future__ import annotations

import math
from pathlib import Path

import graphkin
from graphkin.render.results import result_rows
from graphkin.render.sources import as_source

DATA = Path(__file__).resolve().parents[1] / "data" / "results"


def test_a_nanometre_four_bar_keeps_six_figures():
    sol = graphkin.load(DATA / "fb_tiny.toml").solve()
    rows = {r.key: r for r in result_rows(as_source(sol), ["velocity"])}
    v_a = rows["V_A"].drawn.split()[0]
    assert v_a == f"{1e-5 * math.pi:.6g}".replace("e-05", "e-5") == "3.14159e-5"
    # ω2 = 4π rad/s = 12.5664 rad/s cw, at the ordinary scale
    assert rows["omega2"].drawn == "12.5664 cw"
    # every magnitude of the table has the figures of %.6g of its value (trailing zeros
    # dropped), as at a millimetre's scale
    for r in rows.values():
        size = math.hypot(*r.drawn_value)
        mantissa = f"{size:.6g}".split("e")[0]
        assert r.drawn.split()[0].split("e")[0] == mantissa, r
