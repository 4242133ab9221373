"""Cams (Chapter 6): displacement programs, the graphic layout of the profile, design checks.

Built on :mod:`graphkin.geometry` and :mod:`graphkin.construction` like
:mod:`graphkin.kinematics`, with its own independent analytic check
(:mod:`graphkin.cams.analytic`).

References
----------
Uicker, Pennock & Shigley, 5th ed., Chapter 6.
"""

from __future__ import annotations

from graphkin.cams.analytic import Profile, profile
from graphkin.cams.layout import Layout, layout, stations
from graphkin.cams.model import Cam, Follower, FollowerKind, Sense
from graphkin.cams.motions import Motion, Rest
from graphkin.cams.program import Kinematics, Program, Segment

__all__ = ["Cam", "Follower", "FollowerKind", "Sense", "Motion", "Rest", "Program", "Segment",
           "Kinematics", "Layout", "layout", "stations", "Profile", "profile"]
