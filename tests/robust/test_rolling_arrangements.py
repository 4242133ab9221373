"""Rolling contact in the arrangements the format allows, against the analytic solver.

Issue 14, item 7: a pinion on a crank rolling on a rack carried by a link
pivoted to the frame (it crashed when the pinion carried a point besides its
center), and a planet on an arm rolling on a driven sun gear, with ``link``
and ``on`` in either order.  Hypothesis draws the sizes, angles and rates;
every ω and α of the graphic solution must equal the analytic solver's
(loop closure, Secs. 3.9 and 4.9), which shares no code with the polygons.
"""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.kinematics.analytic import solve_analytic


def compare(text: str) -> graphkin.Solution:
    mech = graphkin.loads(text)
    sol = mech.solve()
    # LinkState.angle is in radians
    guess = {lid: (float(s.origin[0]), float(s.origin[1]), float(s.angle))
             for lid, s in sol.links.items() if lid != "1"}
    exact = solve_analytic(mech, guess=guess)
    for lid, s in sol.links.items():
        e = exact.links[lid]
        w = max(1.0, abs(float(e.omega)))
        assert math.isclose(float(s.omega), float(e.omega), rel_tol=1e-7, abs_tol=1e-9 * w)
        a = max(1.0, abs(float(e.alpha)), w * w)
        assert math.isclose(float(s.alpha), float(e.alpha), rel_tol=1e-7, abs_tol=1e-9 * a)
    return sol


def rack(extra: bool, pivot: tuple[float, float], crank: float, radius: float, angle: float,
         omega: float, alpha: float) -> str:
    # the crank O2P stands at `angle`; the rack's line is drawn `radius` below P, level,
    # so the file's drawing is assembled; the rack turns about `pivot`
    px, py = crank * math.cos(math.radians(angle)), crank * math.sin(math.radians(angle))
    y = py - radius
    return f"""
[links.1]
O2 = [0, 0]
O3 = [{pivot[0]}, {pivot[1]}]
[links.2]
O2 = [0, 0]
P = [{crank}, 0]
[links.3]
O3 = [{pivot[0]}, {pivot[1]}]
L0 = [{px - 50}, {y}]
L1 = [{px + 50}, {y}]
[links.4]
P = [0, 0]
{'Q = [' + str(radius) + ', 0]' if extra else ''}
[[rolling]]
link = 4
on = 3
circle = {{ center = "P", radius = {radius} }}
line = ["L0", "L1"]
side = "left"
[drive]
link = 2
angle = {angle}
omega = {omega}
alpha = {alpha}
"""


def planet(order: str, extra: bool, sun: float, planet_r: float, contact: str, angle: float,
           w_arm: float, w_sun: float, a_arm: float) -> str:
    arm = sun + planet_r if contact == "outside" else sun - planet_r
    if order == "planet on sun":
        roll = (f'link = 3\non = 4\ncircle = {{ center = "P", radius = {planet_r} }}\n'
                f'on_circle = {{ center = "O", radius = {sun} }}\ncontact = "{contact}"')
    else:
        roll = (f'link = 4\non = 3\ncircle = {{ center = "O", radius = {sun} }}\n'
                f'on_circle = {{ center = "P", radius = {planet_r} }}\ncontact = "outside"')
    return f"""
[links.1]
O = [0, 0]
[links.2]
O = [0, 0]
P = [{arm}, 0]
[links.3]
P = [0, 0]
{'Q = [' + str(planet_r / 2) + ', 1]' if extra else ''}
[links.4]
O = [0, 0]
S = [{sun}, 0]
[[rolling]]
{roll}
[[drive]]
link = 2
angle = {angle}
omega = {w_arm}
alpha = {a_arm}
[[drive]]
link = 4
angle = 0
omega = {w_sun}
alpha = 0
"""


@pytest.mark.parametrize("extra", [False, True])
@pytest.mark.parametrize("pivot", [(60.0, 0.0), (60.0, 30.0), (-20.0, -40.0)])
def test_pinion_on_a_pivoted_rack(extra: bool, pivot: tuple[float, float]) -> None:
    sol = compare(rack(extra, pivot, 40.0, 10.0, 90.0, 1.0, 0.0))
    # hand check at this posture: P = (0, 40) moves at V_P = ω2 k × R_PO2 = (-40, 0), parallel
    # to the rack, so the rack does not turn (ω3 = 0) and the pinion rolls on a resting rack:
    # V_P = ω4 k × R_PC with R_PC = (0, 10): -10 ω4 = -40, ω4 = 4 rad/s ccw
    assert abs(float(sol.links["3"].omega)) < 1e-12
    assert math.isclose(float(sol.links["4"].omega), 4.0)


@pytest.mark.parametrize("order", ["planet on sun", "sun on planet"])
@pytest.mark.parametrize("extra", [False, True])
def test_planet_on_an_arm_rolling_on_a_driven_sun(order: str, extra: bool) -> None:
    sol = compare(planet(order, extra, 40.0, 20.0, "outside", 30.0, 10.0, -5.0, 3.0))
    # hand check: V_P = 60 ω2 = 600 (⊥ arm); the sun's pitch point moves at 40 ω4 = -200;
    # the planet: 600 = -200 + 20 ω3, so ω3 = 40 rad/s ccw (both orders of link and on)
    assert math.isclose(float(sol.links["3"].omega), 40.0)


@settings(max_examples=25, deadline=None)
@given(extra=st.booleans(), px=st.floats(-80, 80), py=st.floats(-80, 80),
       crank=st.floats(10, 60), radius=st.floats(2, 15), angle=st.floats(0, 360),
       omega=st.floats(-20, 20), alpha=st.floats(-20, 20))
def test_random_pinions_on_pivoted_racks(extra: bool, px: float, py: float, crank: float,
                                         radius: float, angle: float, omega: float,
                                         alpha: float) -> None:
    text = rack(extra, (px, py), crank, radius, angle, omega, alpha)
    try:
        compare(text)
    except graphkin.GraphkinError as exc:
        # the rack's pivot on the path of the pinion's contact: ω3 is undetermined there
        assert "singular" in str(exc) or "coincide" in str(exc), exc


@settings(max_examples=25, deadline=None)
@given(order=st.sampled_from(["planet on sun", "sun on planet"]), extra=st.booleans(),
       sun=st.floats(10, 60), planet_r=st.floats(3, 30), angle=st.floats(0, 360),
       w_arm=st.floats(-20, 20), w_sun=st.floats(-20, 20), a_arm=st.floats(-20, 20))
def test_random_planets_on_driven_suns(order: str, extra: bool, sun: float, planet_r: float,
                                       angle: float, w_arm: float, w_sun: float,
                                       a_arm: float) -> None:
    compare(planet(order, extra, sun, planet_r, "outside", angle, w_arm, w_sun, a_arm))
