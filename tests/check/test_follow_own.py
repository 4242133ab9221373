"""Follow-through from the student's own images (``graphkin.check.carry``) in ``check --drawing``.

Example 3.1's four-bar (A-B crank, B-C-E coupler, D-C-F rocker) with the
crank's image b drawn wrong and every later image constructed right from
that b, by hand geometry here (Sec. 3.4: c where ⊥CB through b meets ⊥CD
through the pole; Sec. 3.5: e and f similar to their links): b is wrong,
the rest ``follows`` from it.  A right c drawn beside the wrong b is not
spoilt, and an image drawn wrong in its own way stays wrong.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.check import Diagnoser, Evaluator
from graphkin.check.drawing import check_polygons
from graphkin.check.polygon import Polygon
from graphkin.check.report import FOLLOWS, OK, WRONG

SOL = graphkin.examples.fourbar().solve()
POS = {n: complex(*np.asarray(SOL.position(n), dtype=float)) for n in "ABCDEF"}
PER = 10.0   # 1 mm = 10 in/s
DIAG = Diagnoser(Evaluator(SOL))


def _from(b: complex) -> dict[str, complex]:
    """b, c, e, f (mm from the pole) constructed right from the crank's image b."""
    cb, cd = POS["C"] - POS["B"], POS["C"] - POS["D"]
    u, w = 1j * cb, 1j * cd
    # b + s u = t w  ->  s from the 2-D cross product with w
    s = -(b.real * w.imag - b.imag * w.real) / (u.real * w.imag - u.imag * w.real)
    c = b + s * u
    e = b + (c - b) * (POS["E"] - POS["B"]) / cb
    f = c * (POS["F"] - POS["D"]) / cd
    return {"b": b, "c": c, "e": e, "f": f}


def _mark(points: dict[str, complex]) -> dict[str, tuple[str, str]]:
    poly = Polygon("velocity", (0.0, 0.0), {n: (z.real, z.imag) for n, z in points.items()},
                   scale=f"1 mm = {PER} in/s", unit="mm")
    rep = check_polygons(SOL, [poly], "drawn.dxf", diagnoser=DIAG)
    return {r.key: (r.verdict, r.code) for r in rep.rows}


def _b() -> complex:
    return complex(*np.asarray(SOL.velocity("B"), dtype=float)) / PER


@settings(max_examples=30, deadline=None)
@given(factor=st.floats(0.8, 1.25), turn=st.floats(-12.0, 12.0))
def test_images_drawn_right_from_a_wrong_b_follow_it(factor: float, turn: float) -> None:
    b = _b() * factor * np.exp(1j * np.radians(turn))
    exact = _from(_b())
    drawn = _from(b)
    # b off by more than 2 % and 2° and 0.5 mm, the rest moved well beyond the tolerance
    assume(abs(b - exact["b"]) > 1.0 and (abs(factor - 1) > 0.03 or abs(turn) > 3))
    got = _mark(drawn)
    # moved by round-off of their size, the marks do not change
    assert _mark({n: z * (1 + 1e-12) + 1e-12 * abs(z) for n, z in drawn.items()}) == got
    assert got.pop("V_B")[0] == WRONG
    for n, v in got.items():
        d, x = drawn[n[-1].lower()], exact[n[-1].lower()]
        # the drawing rule (docs/checking.md): right within 2 % and 2°, or within 0.5 mm; an
        # image clearly outside it (a tenth of the rule's margin) is not right, so follows
        size_off = abs(abs(d) - abs(x)) / abs(x)
        turn_off = abs(np.degrees(np.angle(d / x)))
        if abs(d - x) > 0.55 and (size_off > 0.022 or turn_off > 2.2):
            assert v == (FOLLOWS, "follows:V_B"), (n, got)
        else:
            assert v[0] in (OK, FOLLOWS), (n, got)


def test_a_right_image_beside_a_wrong_b_stays_right() -> None:
    drawn = {**_from(_b()), "b": 1.1 * _b()}
    got = _mark(drawn)
    # c, e, f drawn at their exact places: right, whatever b is
    assert got == {"V_B": (WRONG, "unexplained"), "V_C": (OK, ""), "V_E": (OK, ""),
                   "V_F": (OK, "")}


@pytest.mark.parametrize("off", [3.0, -4.0])
def test_an_image_wrong_in_its_own_way_stays_wrong(off: float) -> None:
    # b 10 % long, c from it, but e moved 3-4 mm across the link's image: its own mistake
    drawn = _from(1.1 * _b())
    c, b = drawn["c"], drawn["b"]
    drawn["e"] += off * 1j * (c - b) / abs(c - b)
    got = _mark(drawn)
    assert got["V_C"] == (FOLLOWS, "follows:V_B")
    assert got["V_E"][0] == WRONG
