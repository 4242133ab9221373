"""A refused line X names the directions that do give a crank-rocker (Sec. 9.3, Fig. 9.3).

Acceptance input (Problem 9.4: a 500 mm rocker through 45°, Q = 1.25): of the
directions of X tried every 20°, only 40° and 60° were accepted, and each
refusal said only "turn line X".  The refusal now gives the range; every
direction in it is checked here by the definitions of Sec. 9.3: in the
extended limit posture O2B1 = r3 + r2, in the folded one O2B2 = r3 − r2, and
O2 sees B1B2 under α = 180° (Q − 1)/(Q + 1) (Eq. 9.1).
"""

from __future__ import annotations

import cmath
import math
import re

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin.errors import InputError
from graphkin.synthesis.limits import crank_rocker


def _ranges(msg: str) -> list[tuple[int, int]]:
    tail = msg.split("x_angle ", 1)[1].split(" (or", 1)[0]
    return [(int(a), int(b or a)) for a, b in re.findall(r"(\d+)°(?: to (\d+)°)?", tail)]


def _check(cr, o4: complex, b1: complex, swing: float, q: float) -> None:
    b2 = o4 + (b1 - o4) * cmath.exp(1j * swing)
    assert abs(cr.b2 - b2) < 1e-9 * abs(b1 - o4)
    assert abs(cr.b1 - cr.o2) == pytest.approx(cr.r3 + cr.r2, rel=1e-9)
    assert abs(b2 - cr.o2) == pytest.approx(cr.r3 - cr.r2, rel=1e-9)
    alpha = math.pi * (q - 1) / (q + 1)
    seen = cmath.phase((b2 - cr.o2) / (b1 - cr.o2))
    assert seen == pytest.approx(alpha, abs=1e-9)


def test_problem_9_4_refusal_names_the_working_directions() -> None:
    o4, b1, swing, q = 0j, complex(-353.553, 353.553), math.radians(-45), 1.25
    with pytest.raises(InputError) as info:
        crank_rocker(o4, b1, swing, q, math.radians(10), "p94.toml")
    msg = info.value.one_line()
    runs = _ranges(msg)
    assert runs and "\n" not in msg and "p94.toml" in msg
    for lo, hi in runs:
        for deg in range(lo, hi + 1):
            _check(crank_rocker(o4, b1, swing, q, math.radians(deg)), o4, b1, swing, q)
            _check(crank_rocker(o4, b1, swing, q, math.radians(deg + 180)), o4, b1, swing, q)


@settings(max_examples=25, deadline=None)
@given(st.floats(-math.pi, math.pi), st.floats(0.2, 2.5),
       st.sampled_from([1.0, -1.0]), st.floats(1.05, 3.0), st.floats(0, 179))
def test_every_named_direction_gives_the_crank_rocker(th: float, swing: float, sense: float,
                                                      q: float, x: float) -> None:
    o4, b1 = 0j, cmath.exp(1j * th)
    try:
        crank_rocker(o4, b1, sense * swing, q, math.radians(x))
        return
    except InputError as exc:
        msg = exc.one_line()
    if "x_angle " not in msg or "gives one" not in msg:
        return                                   # no direction works: φ's other sense
    for lo, hi in _ranges(msg):
        mid = (lo + hi) // 2
        _check(crank_rocker(o4, b1, sense * swing, q, math.radians(mid)), o4, b1,
               sense * swing, q)
