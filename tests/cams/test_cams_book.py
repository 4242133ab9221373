"""Examples 6.6 and 6.7 (Sec. 6.10), every answer, and the mirror image of every cam."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
from cam_strategies import cams
from hypothesis import given, settings

from graphkin.cams import Sense, profile, stations
from graphkin.cams.examples import example_6_6, example_6_7


def test_example_6_6():
    """Ex 6.6 at Θ = 30°: (a) (23.473, 29.139) mm (the book prints 23.413, a slip),
    (b) ρ_cam = −60.757 mm in the book's sign (it prints −60.775, a slip), (c) φ = 28.68°.

    By hand (Eq. 6.33): tan φ = y'/(R0 + Y) = 25.981/47.5, φ = 28.68°.
    """
    pr = profile(example_6_6(), [math.radians(30)])
    assert abs(pr.contact[0] - (23.473 + 29.139j)) < 7e-4
    assert abs(pr.rho[0] - 60.757) < 5e-4 and abs(pr.rho_pitch[0] - 72.757) < 5e-4
    assert abs(math.degrees(pr.pressure[0]) - math.degrees(math.atan(25.981 / 47.5))) < 1e-3
    assert abs(math.degrees(pr.pressure[0]) - 28.68) < 5e-3


def test_example_6_7():
    """Ex 6.7 at Θ = 45°: θ4 = 121.35°, contact (2.358, 0.074) in, ρ_cam = −1.775 in (book's
    sign), φ = 54.83° (the book's four-figure intermediates; exactly 54.825°)."""
    cam = example_6_7()
    assert abs(math.degrees(cam.arm0) - 150) < 1e-5                 # Eq. (1): 5π/6
    pr = profile(cam, [math.radians(45)])
    assert abs(pr.contact[0] - (2.358 + 0.074j)) < 7e-4
    assert abs(pr.rho[0] - 1.775) < 5e-4 and abs(pr.rho_pitch[0] - 2.275) < 5e-4
    assert abs(math.degrees(pr.pressure[0]) - 54.83) < 0.01
    # the pitch point, Eqs. (9): u = 2.734, v = 0.403 in
    assert abs(pr.pitch[0] - (2.734 + 0.403j)) < 7e-4


@settings(max_examples=30, deadline=None)
@given(cams())
def test_a_cam_turning_the_other_way_is_its_mirror_image(cam):
    """Mirror the frame in the y axis: the cam turns the other way, the offset, the pivot's x
    and the arm's sense change sign; the profile is the mirror image, φ and ρ are the same."""
    f = cam.follower
    other = Sense.CW if cam.sense is Sense.CCW else Sense.CCW
    rise = Sense.CW if f.rise is Sense.CCW else Sense.CCW
    mirror = dataclasses.replace(cam, sense=other, follower=dataclasses.replace(
        f, offset=-f.offset, pivot=(-f.pivot[0], f.pivot[1]), rise=rise))
    th = stations(360)
    a, b = profile(cam, th), profile(mirror, th)
    ok = np.isfinite(a.contact) & np.isfinite(b.contact)
    size = cam.prime + cam.program.lift + math.hypot(*f.pivot)
    assert np.allclose(a.contact[ok], -np.conj(b.contact[ok]), rtol=0, atol=1e-9 * size)
    assert np.allclose(a.pressure[ok], b.pressure[ok], rtol=0, atol=1e-9)
    assert np.allclose(a.rho[ok], b.rho[ok], rtol=1e-6, atol=1e-9 * size)


def test_example_6_1_parabolic_motion():
    """Ex 6.1: two parabolas meeting at mid-rise; y'max = 2L/β there (Eq. 5), y'' = ±4L/β²
    (Eqs. 6.5c, 6.6c), y''' = 0; the "acceleration" steps at 0, β/2 and β (Fig. 6.12)."""
    from graphkin.cams import Motion, Program, Segment
    from graphkin.cams.program import Jump

    L, beta = 2.0, math.radians(120)
    p = Program((Segment(Motion.PARABOLIC, L, beta), Segment(Motion.DWELL, 0.0, math.radians(60)),
                 Segment(Motion.PARABOLIC, -L, math.radians(180))))
    k = p.evaluate(np.array([beta / 2, beta / 4, 3 * beta / 4]))
    assert abs(k.y1[0] - 2 * L / beta) < 1e-12
    assert abs(k.y2[1] - 4 * L / beta**2) < 1e-12 and abs(k.y2[2] + 4 * L / beta**2) < 1e-12
    assert np.all(k.y3 == 0)
    assert abs(k.Y[0] - L / 2) < 1e-12
    # the joints: y'' jumps at every one, y' at none
    kinds = [set(j.jumps) for j in p.joints()]
    assert kinds and all(s == {Jump.ACCELERATION} for s in kinds)
