"""The equivalent linkage of a cam at one angle (Sec. 4.7), solved by graphkin's kinematics,
gives the follower the program's velocity y'ω and acceleration y''ω² (Eq. 6.11)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from cam_strategies import cams
from hypothesis import given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.cams.equivalent import equivalent_linkage, equivalent_toml
from graphkin.cams.examples import example_6_6, example_6_7
from graphkin.errors import GraphkinError


def _check(cam, theta, omega=1.0):
    mech = graphkin.loads(equivalent_toml(cam, theta))
    sol = mech.solve()
    k = cam.program.evaluate([theta])
    f = cam.follower
    size = cam.prime + cam.program.lift + math.hypot(*f.pivot) + f.arm
    if f.kind.oscillating:
        sig = f.rise.sign
        w4 = sig * k.y1[0] * omega
        a4 = sig * k.y2[0] * omega**2
        assert abs(float(sol.omega(4)) - w4) < 1e-7 * max(1, abs(w4))
        assert abs(float(sol.alpha(4)) - a4) < 1e-6 * max(1, abs(a4), abs(w4) ** 2)
    else:
        v = sol.velocity("T")
        a = sol.acceleration("T")
        assert abs(v[0]) < 1e-9 * size and abs(v[1] - k.y1[0] * omega) < 1e-8 * size
        assert abs(a[1] - k.y2[0] * omega**2) < 1e-7 * size


def test_example_6_6_at_30_degrees():
    """Ex 6.6 at Θ = 30°: y' = 25.981 mm/rad, y'' = 30.000 mm/rad² (the book's Eqs. 2a-2b)."""
    _check(example_6_6(), math.radians(30))
    d = equivalent_linkage(example_6_6(), math.radians(30))
    # the coupler is the pitch curve's radius of curvature: |ρ| = 72.757 mm (Ex 6.6 (b))
    assert abs(d["links"]["3"]["T"][0] - 72.757) < 5e-4


def test_example_6_7_at_45_degrees():
    """Ex 6.7 at Θ = 45°: θ4' = −1, θ4'' = 0 (the book's Eq. 8), ω4 = ω2 in size."""
    _check(example_6_7(), math.radians(45))


@settings(max_examples=25, deadline=None)
@given(cams(), st.floats(0.0, 2 * math.pi, exclude_max=True))
def test_random_cams_at_random_angles(cam, theta):
    try:
        d = equivalent_linkage(cam, theta)
    except GraphkinError:           # a straight piece of surface: refused, said so
        return
    prof = graphkin.cams.profile(cam, [theta])
    if not np.isfinite(prof.contact[0]) or ("3" in d["links"] and
                                            d["links"]["3"]["T"][0] < 1e-6):
        return
    try:
        _check(cam, theta)
    except GraphkinError as exc:    # a posture the linkage cannot be assembled at: not a pass
        pytest.fail(f"equivalent linkage did not solve: {exc}")
