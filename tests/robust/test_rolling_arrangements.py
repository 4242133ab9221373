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


@settings(max_examples=25, deadline=None)
@given(extra=st.booleans(), ring=st.floats(30, 80), fraction=st.floats(0.1, 0.8),
       angle=st.floats(0, 360), w_arm=st.floats(-20, 20), w_ring=st.floats(-20, 20),
       a_arm=st.floats(-20, 20))
def test_random_planets_inside_driven_rings(extra: bool, ring: float, fraction: float,
                                            angle: float, w_arm: float, w_ring: float,
                                            a_arm: float) -> None:
    # a circle rolling inside a circle (contact = "inside", the planet in a ring gear); the
    # format states it with the smaller circle as the rolling one only (radius < on's)
    compare(planet("planet on sun", extra, ring, fraction * ring, "inside", angle, w_arm,
                   w_ring, a_arm))


def test_planet_inside_a_ring_by_hand() -> None:
    # ring radius 60 (link 4, at rest), planet radius 20 on an arm of 40 (ω2 = 10):
    # V_P = 40·10 = 400; the contact point of the planet is at rest (it touches the resting
    # ring 20 beyond P, away from O): 400 = ω3 · (−20)·(−1)... with R_PC = −20 along the arm,
    # V_P = ω3 k × R_PC gives ω3 = −400/20 = −20 rad/s (cw), the classic −ω_arm(R−r)/r
    sol = compare(planet("planet on sun", False, 60.0, 20.0, "inside", 0.0, 10.0, 0.0, 0.0))
    assert math.isclose(float(sol.links["3"].omega), -20.0)


def _floating(order: str, shape: str, extra: bool, wx: float, wy: float, radius: float,
              phi: float, big: float, omega: float, alpha: float, arm: float) -> str:
    """A four-bar (links 2-4) whose coupler 3 carries a surface; wheel 5 on the arm 6.

    The wheel turns about W, the end of the arm 6 pivoted to the frame at O6; neither
    the wheel nor the coupler is pinned to the frame.  Every point is written in
    world coordinates of the posture drawn (each link's own axes along the frame's), so the
    drawing is assembled at θ2 = 0 (the direction of link 2's own x axis) and the wheel at
    its angle 0.  W, the wheel's center, is a point of the arm; the coupler's surface is
    a line at distance `radius` from W (shape "line"), or a circle of radius `big` touching
    the wheel from outside (shape "circle": link and on in either order).
    """
    a, b = (-2.0, 3.4641016), (14.8135832, 9.8908751)  # Example 3.1 at θ2 = 120°
    d = (10.0, 0.0)
    w = (d[0] + wx, d[1] + wy)
    o6 = (w[0] + 5 * math.cos(math.radians(arm)), w[1] + 5 * math.sin(math.radians(arm)))
    ux, uy = math.cos(math.radians(phi)), math.sin(math.radians(phi))
    q = "\nQ{} = [{}, {}]"
    if shape == "line":
        l0 = (w[0] - uy * radius - 40 * ux, w[1] + ux * radius - 40 * uy)  # W on the right
        l1 = (l0[0] + 80 * ux, l0[1] + 80 * uy)
        surface = f"L0 = [{l0[0]}, {l0[1]}]\nL1 = [{l1[0]}, {l1[1]}]"
        roll = (f'link = 5\non = 3\ncircle = {{ center = "W", radius = {radius} }}\n'
                'line = ["L0", "L1"]\nside = "right"')
    else:
        c = (w[0] + (radius + big) * ux, w[1] + (radius + big) * uy)
        surface = f"K = [{c[0]}, {c[1]}]"
        if order == "wheel on coupler":
            roll = (f'link = 5\non = 3\ncircle = {{ center = "W", radius = {radius} }}\n'
                    f'on_circle = {{ center = "K", radius = {big} }}\ncontact = "outside"')
        else:
            roll = (f'link = 3\non = 5\ncircle = {{ center = "K", radius = {big} }}\n'
                    f'on_circle = {{ center = "W", radius = {radius} }}\ncontact = "outside"')
    return f"""
[links.1]
O2 = [0, 0]
D = [{d[0]}, {d[1]}]
O6 = [{o6[0]}, {o6[1]}]
[links.2]
O2 = [0, 0]
A = [{a[0]}, {a[1]}]{q.format(2, a[0] / 2, a[1] / 2 + 1) if extra else ''}
[links.3]
A = [{a[0]}, {a[1]}]
B = [{b[0]}, {b[1]}]
{surface}{q.format(3, 5, 9) if extra else ''}
[links.4]
D = [{d[0]}, {d[1]}]
B = [{b[0]}, {b[1]}]{q.format(4, 12, 3) if extra else ''}
[links.6]
O6 = [{o6[0]}, {o6[1]}]
W = [{w[0]}, {w[1]}]{q.format(6, o6[0] + 1, o6[1]) if extra else ''}
[links.5]
W = [{w[0]}, {w[1]}]{q.format(5, w[0] + radius / 2, w[1]) if extra else ''}
[[rolling]]
{roll}
[drive]
link = 2
angle = 0
omega = {omega}
alpha = {alpha}
[assembly]
B = [{b[0]}, {b[1]}]
"""


@settings(max_examples=30, deadline=None)
@given(order=st.sampled_from(["wheel on coupler", "coupler on wheel"]),
       shape=st.sampled_from(["line", "circle"]), extra=st.booleans(),
       wx=st.floats(-3, 8), wy=st.floats(1, 9), radius=st.floats(1, 4),
       phi=st.floats(0, 360), big=st.floats(2, 12), omega=st.floats(-20, 20),
       alpha=st.floats(-20, 20), arm=st.floats(0, 360))
def test_random_floating_rolling_contacts(order: str, shape: str, extra: bool, wx: float,
                                          wy: float, radius: float, phi: float, big: float,
                                          omega: float, alpha: float, arm: float) -> None:
    text = _floating(order, shape, extra, wx, wy, radius, phi, big, omega, alpha, arm)
    try:
        compare(text)
    except graphkin.GraphkinError as exc:
        # the contact normal through a pivot of the wheel's motion: ω5 undetermined there
        assert "singular" in str(exc) or "coincide" in str(exc), exc
