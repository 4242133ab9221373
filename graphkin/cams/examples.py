"""The book's cams of Chapter 6, built in code (the same as the files in examples/cams/).

References
----------
Uicker, Pennock & Shigley, 5th ed., Ex 6.2 (the program), 6.3-6.5 (its flat-face
and roller cams), 6.6 and 6.7.
"""

from __future__ import annotations

import math

from graphkin.cams.model import Cam, Follower, FollowerKind, Sense
from graphkin.cams.motions import Motion, Rest
from graphkin.cams.program import Program, Segment

__all__ = ["example_6_2", "example_6_6", "example_6_7", "double_harmonic"]

_D = math.radians


def example_6_2() -> Program:
    """Ex 6.2: the program the book solves (its printed L and β), inches.

    Half-cycloidal rise AB (Eq. 6.22), uniform BC, half-harmonic rise CD
    (Eq. 6.19), eighth-order polynomial return DE (Eq. 6.17), dwell.
    """
    return Program((
        Segment(Motion.HALF_CYCLOIDAL, 1.1831, _D(85.184), Rest.START, "AB"),
        Segment(Motion.UNIFORM, 1.2500, _D(45.000), None, "BC"),
        Segment(Motion.HALF_HARMONIC, 0.5669, _D(32.058), Rest.END, "CD"),
        Segment(Motion.POLYNOMIAL8, -3.0000, _D(107.758), None, "DE"),
        Segment(Motion.DWELL, 0.0, _D(90.000), None, "EA"),
    ))


def double_harmonic(lift: float) -> Program:
    """``Y = (L/2)(1 − cos 2Θ)``: full harmonic rises and returns of 90° (Ex 6.6, 6.7)."""
    return Program(tuple(Segment(Motion.HARMONIC, lift * sign, _D(90.0))
                         for sign in (1, -1, 1, -1)))


def example_6_6() -> Cam:
    """Ex 6.6: radial roller follower, Y = 15(1 − cos 2Θ) mm, R0 = 40 mm, R_r = 12 mm, ccw."""
    return Cam(double_harmonic(30.0), 40.0, Follower(FollowerKind.ROLLER, roller=12.0),
               Sense.CCW, unit="mm", title="Example 6.6")


def example_6_7() -> Cam:
    """Ex 6.7: oscillating roller follower, Y = 0.5(1 − cos 2Θ) rad (Fig. 6.35), inches."""
    return Cam(double_harmonic(1.0), 1.5,
               Follower(FollowerKind.OSCILLATING_ROLLER, roller=0.5, pivot=(3.0, 0.0),
                        arm=2.598, rise=Sense.CW),
               Sense.CCW, unit="in", title="Example 6.7")
