"""The Python API says what happened (issue 25, item 4).

At a dead point the file's rates cannot be carried through the posture:
``sol.velocity('C')`` says so (a toggle or dead-center posture, Sec. 3.5),
not "the file gives no rates", which it does.
"""

from __future__ import annotations

import pytest

import graphkin
from graphkin.examples import text


def _slider_crank(position: float, rates: bool = True) -> graphkin.Mechanism:
    # centred slider-crank: crank 50, rod 140 on the line through A; at a travel of 90 the
    # crank lies back along the line (θ2 = 180°) and the rod along it: a dead center
    t = text("slider_crank").replace("S = [0, -20]", "S = [0, 0]").replace(
        "T = [100, -20]", "T = [100, 0]").replace("position = 164", f"position = {position}")
    t = t.replace("B = [35, 35]", "B = [-50, 0.1]")
    if not rates:
        t = t.replace('velocity = "-10 m/s"', "").replace("acceleration = 0", "")
    return graphkin.loads(t)


@pytest.mark.parametrize("ask", [lambda s: s.velocity("C"), lambda s: s.omega(3),
                                 lambda s: s.acceleration("B"), lambda s: s.alpha(2)])
def test_rates_at_a_dead_point_say_it_is_a_dead_point(ask) -> None:
    sol = _slider_crank(90).solve()
    with pytest.raises(ValueError, match="dead-center") as info:
        ask(sol)
    assert "gives no rates" not in str(info.value)


def test_no_rates_in_the_file_says_so() -> None:
    sol = _slider_crank(90, rates=False).solve()
    with pytest.raises(ValueError, match="the file gives no rates"):
        sol.velocity("C")
