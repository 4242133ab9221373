"""Instant centers of velocity: primary centers by inspection, the rest by Kennedy's theorem.

A mechanism of ``n`` links has ``N = n(n-1)/2`` instant centers (Eq. 3.20).
They are found the way the book teaches (Secs. 3.12-3.14):

1. **Primary centers, by inspection.**  A pin is the instant center of the
   links it joins.  A slider (prismatic pair) gives a center at infinity,
   perpendicular to the line of sliding: the two links do not turn relative to
   each other (Fig. 3.26, Eq. 3.21).  A point of rolling contact is the center
   of the two rolling bodies (Fig. 3.25).  A pin in a slot (direct contact
   with slipping, Fig. 3.24) does not give the center, only a **line** through
   it: the common normal at the pin (for a straight slot, the perpendicular to
   the slot through the pin; for a circular slot, the line through the pin and
   the slot's center).  A circle rolling on a line (``[[rolling]]``) touches
   it at the foot of the perpendicular from its center; contacts the file
   cannot state are passed as :class:`KnownCenter` and :class:`KnownLine`.
2. **Secondary centers, by the Aronhold-Kennedy theorem** (Sec. 3.13): the
   three centers of any three links lie on one straight line.  Following the
   *Kennedy circle*, an unknown center ``Iij`` is found as soon as two lines of
   centers through it are known: two triangles ``i, j, k`` with ``Iik`` and
   ``Ijk`` both known, or one triangle and the common normal of a slot.  The
   two lines meet at ``Iij``.
3. **Several degrees of freedom** (Sec. 5.4, Example 5.5): some centers
   cannot be reached by Kennedy's theorem; they depend on the ratio of the
   input speeds.  They are found from the velocities as the point where both
   links have the same velocity, and flagged so.  The same is done, for one
   degree of freedom, at a posture where the lines of centers of a pair
   coincide (the velocities of a unit input speed serve when the file gives
   none).

Points at infinity are handled in homogeneous coordinates with no special
case: the line through a finite center and a center at infinity is the
parallel through the finite one, and two parallel lines meet at infinity.
Two special triangles are named: when ``Iik`` and ``Ijk`` are both at
infinity, links ``i`` and ``j`` do not turn relative to each other, so ``Iij``
is the point at infinity of its other line of centers (the Scotch yoke of
Fig. 3.27); when ``Iik`` and ``Ijk`` coincide, ``Iij`` is that same point.

Every step is recorded in a :class:`~graphkin.construction.Construction`
(``diagram="centers"``) with the book's words, so that the drawings can show
the Kennedy circle and the order of discovery, and ``construction.evaluate()``
replays to the same centers.

The module also gives the velocity analyses that use the centers: the
line-of-centers method (Sec. 3.15), the angular-velocity-ratio theorem
(Sec. 3.16, Eq. 3.22), the first-order kinematic coefficients from instant
centers (Sec. 3.17, Eqs. 3.24 and 3.26) and the mechanical advantage
(Sec. 3.19, Eq. 3.34).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Secs. 3.12-3.17 and 3.19; Sec. 5.4 (Example 5.5).

Examples
--------
The four-bar of Examples 3.1 and 3.13:

>>> import graphkin
>>> sol = graphkin.examples.fourbar().solve()
>>> ic = instant_centers(sol)
>>> ic.order
['I12', 'I14', 'I23', 'I34', 'I13', 'I24']
>>> print(ic["I13"].note)
I13 lies on the line I12-I23 and on the line I14-I34 (Kennedy).
>>> [round(float(v), 4) for v in ic["I24"].xy]
[-11.0627, 0.0]
>>> round(float(angular_velocity_ratio(sol, "2", "4")), 4)  # ω4/ω2 (Eq. 3.22)
0.5252
"""

from __future__ import annotations

from graphkin.kinematics._moved import moved_to
from graphkin.kinematics.instant_centers.centers import (
    Center,
    How,
    InstantCenters,
    KnownCenter,
    KnownLine,
)
from graphkin.kinematics.instant_centers.kennedy import (
    FAR_AS_INFINITY,
    instant_center,
    instant_centers,
)
from graphkin.kinematics.instant_centers.labels import center_label, pair_key, sort_links
from graphkin.kinematics.instant_centers.line_of_centers import (
    LineOfCentersVelocity,
    line_of_centers_velocity,
)
from graphkin.kinematics.instant_centers.ratios import (
    angular_velocity_ratio,
    kinematic_coefficient,
    mechanical_advantage,
)

__all__ = ["How", "Center", "InstantCenters", "KnownCenter", "KnownLine", "LineOfCentersVelocity",
           "center_label", "pair_key", "sort_links", "instant_centers", "instant_center",
           "angular_velocity_ratio", "kinematic_coefficient", "mechanical_advantage",
           "line_of_centers_velocity", "instant_centers_json", "instant_centers_text",
           "FAR_AS_INFINITY"]


# the reports moved to the output layer (graphkin.output); the old import path still works
__getattr__ = moved_to("graphkin.output.centers", ("instant_centers_json", "instant_centers_text"),
                       __name__)
