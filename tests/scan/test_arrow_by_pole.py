"""An image marked by its arrowhead beside a broken stroke from the pole is read at the tip.

A slider-driven slider-crank with the slider at constant speed has A_C = 0,
so the acceleration image d of a coupler point on the rod lies on the line
from the pole to a (Uicker, Pennock & Shigley, 5th ed., Sec. 4.2: the
acceleration image of a link is similar to the link); o_d's arrowhead in
the middle of that one straight stroke marks d (Sec. 3.4: each absolute
vector drawn from the pole with its arrowhead at the image).  The line
segment detector breaks the stroke where the barbs widen it, into two
pieces overlapping beside the tip.  The tip was found
(:func:`graphkin.scan.arrows.arrow_tips` keeps a tip beside such broken
ends), but the matching listed a broken piece's end first (other ends near
it made it "strong") and dropped the tip 0.5 mm from it as the same vertex:
d was read from the pieces' ends, 1.3 mm off, and marked ``unexplained``
(the fresh sample's #44, benchmarks/data/scan_sample_fresh.json, at scan,
the polygon drawn reversed).  An end of a stroke broken beside a tip is now
no vertex (:func:`graphkin.scan.arrows.broken_by_tips`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from scan.photos import between_pole_and, exact_images, layout_for, read_photo  # noqa: E402

from graphkin.mechanisms import from_dict  # noqa: E402
from graphkin.scan.arrows import broken_by_tips  # noqa: E402

# The fresh sample's #44 (drawn by tests/strategies.py): A_C = 0, d on the rod A-C
_SC44: dict[str, Any] = {
    "title": "random slider-crank, slider-driven", "units": {"length": "in"},
    "links": {"1": {"O2": [0.0, 1.9217004745777286],
                    "L1a": [12.590989497427184, -7.292263701173216],
                    "L1b": [10.283251011964616, -4.3382308835581895]},
              "2": {"A": [7.874003796231609, -0.7184951416890835],
                    "O2": [3.7928729842211113, -0.7184951416890835]},
              "3": {"A": [-1.0438026928732864, -3.859550048871106],
                    "C": [1.043802692873286, 3.8595500488711068], "D": [0.0, 0.0]},
              "4": {"C": [-2.6840112611861318, -3.4356827683631095]}},
    "drive": {"link": 4, "position": 4.570535626833818, "velocity": 14.61664418973357},
    "assembly": {"A": [4.081130812010497, 1.9217004745777286],
                 "C": [9.77724192254799, -3.690511280334346],
                 "D": [6.929186367279243, -0.8844054028783086]},
    "sliders": [{"link": 4, "on": 1, "point": "C", "line": ["L1a", "L1b"]}]}


def test_a_reversed_polygon_reads_d_at_its_arrowhead_beside_the_broken_stroke() -> None:
    sol = from_dict(_SC44).solve()
    lay = layout_for(sol, "acceleration", "slider-crank, slider-driven")
    images = exact_images(sol, lay)
    pole = np.array(lay.pole)
    # (what the test means: d on o-a within 0.01 mm, between o and a)
    assert between_pole_and(pole, images["A"], images["D"])
    drawn = {k: 2 * pole - p for k, p in images.items()}       # ω taken the wrong way
    read, _, rows = read_photo(sol, lay, drawn, "scan", 1173)
    # the hand puts the arrowhead's tip exactly at d: read there (the tip found 0.1-0.3 mm
    # off, tests/scan/test_arrows.py), not at the broken pieces' ends 1.3 mm away
    assert "D" in read.points
    assert float(np.hypot(*(read.points["D"] - drawn["D"]))) < 0.5, read.points["D"] - drawn["D"]
    # the whole polygon turned 180°: a_A's sense named, d following (or its own sense)
    assert rows["A_A"].code == "sense"
    assert rows["A_D"].code in ("sense", "follows:A_A")


def test_broken_ends_beside_a_tip_are_named() -> None:
    # o-a from (0, 0) to (60, 0), broken beside the tip at (30.2, 0) into pieces 0-31.5 and
    # 28.5-60 (each running on 1.5 mm into the other); a link line ending at the tip from
    # 40° (a vertex, not a break) and a piece of another line broken at (45, 20), far away
    segs = np.array([[[0.0, 0.0], [31.5, 0.0]], [[28.5, 0.05], [60.0, 0.05]],
                     [[30.2 + 10 * math.cos(0.7), 10 * math.sin(0.7)], [30.2, 0.0]],
                     [[45.0, 10.0], [45.0, 21.0]], [[45.0, 19.0], [45.0, 30.0]]])
    tips = np.array([[30.2, 0.0]])
    got = broken_by_tips(segs, tips)
    # ends (2 per segment): only 31.5 and 28.5 are a break within 2.5 mm of the tip
    assert got.tolist() == [False, True, True, False, False, False, False, False, False, False]
    assert not broken_by_tips(segs, np.zeros((0, 2))).any()
    # the tip 4.8 mm along the line: the break's ends 3.5 and 6.5 mm from it (over 2.5)
    assert not broken_by_tips(segs, np.array([[35.0, 0.0]])).any()


@settings(max_examples=40, deadline=None)
@given(ang=st.floats(0.0, 2 * math.pi), at=st.floats(12.0, 40.0), over=st.floats(-1.0, 2.0),
       off=st.floats(-0.3, 0.3), along=st.floats(-0.4, 0.4), near=st.booleans())
def test_a_break_counts_only_beside_a_tip(ang: float, at: float, over: float, off: float,
                                         along: float, near: bool) -> None:
    # a straight stroke from the pole at any angle, 60 mm, broken at ``at`` into two
    # pieces overlapping by ``over`` (a gap where negative: up to 1 mm), the second piece
    # ``off`` across (the refitted lines' wobble); the tip beside the break, or 6 mm away
    u = np.array([math.cos(ang), math.sin(ang)])
    n = np.array([-u[1], u[0]])
    segs = np.array([[0.0 * u, (at + over / 2) * u],
                     [(at - over / 2) * u + off * n, 60.0 * u + off * n]])
    tip = (at + along + (0.0 if near else 6.0)) * u
    got = broken_by_tips(segs, tip[None, :])
    # the inner ends are within |over|/2 + |along| + |off| <= 1.7 mm of the tip when near,
    # over 6 - 1.7 = 4.3 mm when not; the outer ends are 12 mm or more from it
    assert got.tolist() == [False, near, near, False]
