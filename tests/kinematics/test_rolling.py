"""Rolling contact without slip (Sec. 3.7, 4.7; Eq. 3.13 and 4.19) against hand derivations."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import graphkin

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_example_3_9_wheel_rolling_on_the_ground():
    # Uicker Ex. 3.9 (p. 3.18 figure): θ2 = 90°, θ3 = 0, θ4 = -90°, r2 = 150, r3 = 200,
    # r4 = 50, ρ = 100 mm, ω2 = 10 rad/s ccw.  The book: θ'3 = 0, θ'4 = r2/(r4 + ρ) = 1,
    # so ω3 = 0 and ω4 = 10 rad/s ccw; V_G = ω4 ρ to the left = 1000 mm/s.
    sol = graphkin.load(EXAMPLES / "ex3_9_rolling_wheel.toml").solve()
    assert sol.omega("3") == pytest.approx(0.0, abs=1e-9)
    assert sol.omega("4") == pytest.approx(10.0, rel=1e-12)
    np.testing.assert_allclose(sol.velocity("G"), [-1000.0, 0.0], atol=1e-9)
    # Accelerations by hand (α2 = 0): A_B = A_A + α3 k×R_BA − ω3² R_BA
    #   = (0, −ω2² r2) + α3 (0, 200) = (0, −15000 + 200 α3);
    # A_B = A_G + α4 k×R_BG − ω4² R_BG = (a_G − 50 α4, −100·50), and rolling to the left
    # a_G = −ρ α4.  x: 0 = −150 α4 → α4 = 0;  y: −15000 + 200 α3 = −5000 → α3 = 50 rad/s².
    assert sol.alpha("4") == pytest.approx(0.0, abs=1e-9)
    assert sol.alpha("3") == pytest.approx(50.0, rel=1e-12)
    np.testing.assert_allclose(sol.acceleration("G"), [0.0, 0.0], atol=1e-9)


def test_example_4_8_roller_on_the_oscillating_follower():
    # Uicker Ex. 4.8 extends Ex. 4.7: ω2 = 10 cw, α2 = 25 cw; roller 4 (radius 1.5 in)
    # pinned to the crank at B rolls on the face of follower 3.  Follower: ω3 = −10,
    # α3 = −258.38 (spec example ex4_7, exact; book 262 cw graphic).
    sol = graphkin.load(EXAMPLES / "ex4_8_roller_follower.toml").solve()
    w3, a3 = float(sol.omega("3")), float(sol.alpha("3"))
    assert w3 == pytest.approx(-10.0, abs=1e-6)
    assert a3 == pytest.approx(-258.38, abs=0.01)
    # Hand derivation of the roller.  B runs along the face direction u = (0, 1) (θ3 = 0
    # here) at the apparent speed s' = (V_B − V_B3)·u, where V_B3 = ω3 k×(B − D);
    # no slip with B on the left of u gives ω4 − ω3 = −s'/ρ, and differentiating,
    # α4 − α3 = −s''/ρ with s'' the apparent tangential acceleration
    # (A_B − A_B3 − 2ω3 k×V_B/3)·u.
    B, D = sol.position("B"), sol.position("D")
    r = B - D
    kx = np.array([-r[1], r[0]])
    vb3 = w3 * kx
    vrel = sol.velocity("B") - vb3
    u = np.array([0.0, 1.0])
    rho = 1.5
    assert float(sol.omega("4")) == pytest.approx(w3 - float(vrel @ u) / rho, rel=1e-9)
    ab3 = a3 * kx - w3**2 * r
    cor = 2 * w3 * np.array([-vrel[1], vrel[0]])
    s2 = float((sol.acceleration("B") - ab3 - cor) @ u)
    alpha4 = a3 - s2 / rho
    assert float(sol.alpha("4")) == pytest.approx(alpha4, rel=1e-9)
    # The book prints α4 = 527 rad/s² ccw, dividing the *normal* component
    # A^n_C4B4 = 65.9 ft/s² by R_CB: a misprint; the right value is about 276 ccw.
    assert float(sol.alpha("4")) == pytest.approx(276.15, abs=0.05)


def test_rolling_needs_a_side(tmp_path):
    text = (EXAMPLES / "ex4_8_roller_follower.toml").read_text().replace('side = "left"\n', "")
    path = tmp_path / "m.toml"
    path.write_text(text)
    with pytest.raises(graphkin.InputError) as info:
        graphkin.load(path)
    assert info.value.key == "rolling[0].side"


PLANET = """
units = {{ length = "mm" }}
[links.1]
O = [0, 0]
[links.2]            # the arm
O = [0, 0]
P = [{arm}, 0]
[links.3]            # the planet, pinned to the arm at its center P
P = [0, 0]
Q = [20, 0]
[[rolling]]
link = 3
on = 1
circle = {{ center = "P", radius = 20 }}
on_circle = {{ center = "O", radius = {big} }}
contact = "{contact}"
[drive]
link = 2
angle = 30
omega = 10
alpha = 3
"""


@pytest.mark.parametrize("contact,big,arm,ratio", [("outside", 40, 60, 3.0),
                                                    ("inside", 80, 60, -3.0)])
def test_planet_rolling_on_a_fixed_sun_or_ring(contact, big, arm, ratio):
    # A planet of radius r = 20 on an arm of length R ± r about the center O of a fixed
    # circle of radius R.  No slip at the contact point C (on OP, R from O):
    # V_C = V_P + ω3 × R_CP = 0 with |V_P| = ω2 |OP| and R_CP = ∓r along OP gives
    # ω3 = ω2 (R + r)/r = 3 ω2 outside, ω3 = −ω2 (R − r)/r = −3 ω2 inside; α3 likewise.
    # Seen from the fixed circle the planet's contact point accelerates toward P by
    # ω3² r R/(R ± r) (a circle rolling on a circle, Eq. 4.19).
    sol = graphkin.loads(PLANET.format(contact=contact, big=big, arm=arm)).solve()
    assert float(sol.omega("3")) == pytest.approx(ratio * 10.0, rel=1e-12)
    assert float(sol.alpha("3")) == pytest.approx(ratio * 3.0, rel=1e-12)
    st = sol.links["3"]
    p = sol.position("P")
    c = p / np.hypot(*p) * big                      # the contact point, on OP
    assert float(st.angle) == 0.0                   # the planet's reference angle
    cl = np.asarray(c - st.origin)                  # so its local coordinates are c − origin
    np.testing.assert_allclose(st.velocity(cl), [0.0, 0.0], atol=1e-9)
    w3, r = ratio * 10.0, 20.0
    a_c = st.acceleration(cl)
    expect = w3**2 * r * big / (big + r if contact == "outside" else big - r)
    assert float(np.hypot(*a_c)) == pytest.approx(expect, rel=1e-9)
    assert float(a_c @ (p - c)) > 0                 # toward the planet's center
