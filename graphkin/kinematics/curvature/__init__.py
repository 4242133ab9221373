"""Curvature theory: Euler-Savary, inflection and Bresse circles, Γ, cubic of stationary curvature.

For every moving link ``k`` that turns (``ω_k ≠ 0``) the motion ``k/1`` is
studied the way Secs. 4.12-4.17 of the book do it, as a recorded
:class:`~graphkin.construction.Construction` (``diagram="curvature"``) whose
steps carry the book's words, with a closed-form evaluation beside it:

1. **Velocity pole I** (Sec. 4.12): the meet of the perpendiculars to the
   velocities of two points of ``k`` -- the rays ``AA'`` and ``BB'`` of two
   pairs of conjugate points when they are known by inspection.
2. **Inflection pole J and the inflection circle** (diameter ``IJ``,
   Eq. 4.41).  *By Bobillier's construction* (Sec. 4.13, Fig. 4.29, Example
   4.13) when two pairs of conjugate points are known by inspection: a pin
   ``A`` of ``k`` whose other link turns about a frame pivot ``O`` has its
   center of curvature ``A' = O``; a point held on a frame-fixed straight line
   (a pin to a slider on the frame, a pin in a straight slot of the frame) has
   ``A'`` at infinity, normal to the line.  When the construction through
   ``W`` degenerates (``AB ∥ A'B'``, as in Example 4.16) the inflection points
   ``J_A``, ``J_B`` are laid off by Eq. 4.43, ``R_AJ_A = R_AI²/R_AA'``, as in
   Examples 4.14 and 4.16.  *From accelerations* otherwise: the point of ``k``
   at ``I`` has the acceleration ``A_I = ω² R_JI`` directed from ``I`` toward
   ``J`` (Eqs. 4.46-4.47), so ``J = I + A_I/ω²``; it is found from two points'
   accelerations by the acceleration image (Mehmke's theorem).
3. **Centrode normal and tangent.**  The positive centrode normal ``N``
   points from ``I`` toward ``J`` (the direction of ``A_I``, Sec. 4.15); the
   positive centrode tangent ``T`` is ``N`` turned 90° clockwise, so that
   ``N`` is 90° counterclockwise from ``T`` as Sec. 4.12 requires.  This is
   the book's own choice in Example 4.16 ("the centrode normal N is directed
   from I toward J, and the centrode tangent T is 90° clockwise from N"), and
   it makes ``R_JI`` positive.  With it the pole velocity is
   ``v = ω k × R_JI = -ω R_JI T`` (Eq. 4.47).
4. **Conjugate points** (centers of curvature of the paths): the
   Euler-Savary equation ``1/R_AI - 1/R_A'I = 1/R_J_AI`` (Eq. 4.42,
   ``R_J_AI = R_JI sin ψ``, Eq. 4.41) in closed form; graphically by
   Bobillier's construction of Fig. 4.30 (Example 4.13) or by the Hartmann
   construction of Fig. 4.25, which needs only the pole velocity and works
   for every point but ``I``.
5. **Bresse circle and Γ** (Secs. 4.14-4.15): the Bresse circle has the
   diameter ``b = R_JI ω²/α`` (Eq. 4.48) along the centrode tangent, on its
   negative side when ``α > 0``; it meets the inflection circle at ``I`` and at
   the instantaneous center of acceleration ``Γ``, which the four-circle
   method of Fig. 4.33 also finds from two points' accelerations.
6. **The cubic of stationary curvature** by Hain's construction (Sec. 4.17,
   Fig. 4.38) from two points of constant path curvature, its parameters of
   Eq. 4.55, ``1/r = 1/(M sin ψ) - 1/(N cos ψ)`` with ``r`` from ``I`` and
   ``ψ`` counterclockwise from ``T``; Ball's point (its intersection with the
   inflection circle); and the curvatures of the two centrodes from
   Eq. 4.56, ``1/M = (1/R_JI - 1/R_IO_M)/3``, and Eq. 4.40 with ``A = J``:
   ``1/R_IO_F = 1/R_JI + 1/R_IO_M`` (``R_IO = I - O`` measured along ``N``).

Signs of the cubic
------------------
In coordinates ``x`` along ``T`` and ``y`` along ``N`` from ``I``, Eq. 4.57
``(x² + y²)(x/M - y/N) = xy`` is linear in ``1/M`` and ``1/N``: two points of
the cubic give them.  In Hain's construction a point ``S`` of the cubic gives
``S_G = (r/cos ψ, r/sin ψ)``, and Eq. 4.55 becomes the straight line
``Y/M - X/N = 1``: the auxiliary line ``G``.  Hence ``G`` meets ``N`` at
``G_N = I + M N̂`` and ``T`` at ``G_T = I - N T̂``: ``M`` is the diameter of the
circle centered on the centrode *normal* that osculates the branch of the
cubic tangent to ``T``, and ``|N|`` that of the circle centered on the
centrode *tangent*.  (The sentence after Eq. 4.56 in the book, "M and N are,
respectively, the diameters IG_T and IG_N", has the two swapped; the
paragraph before it and Example 4.16 agree with the above.)

Ball's point ``U`` is on the inflection circle, so its ``S_G`` lies on the
tangent to that circle at ``J``: ``U`` is found by Hain's construction from
the point where ``G`` crosses that tangent.  When ``N`` is infinite the cubic
contains the centrode normal and ``U = J`` (Example 4.16); ``G`` is then
parallel to that tangent, and the construction makes ``U`` with the operation
``ball_point`` (:mod:`graphkin.construction.ops.ball`): Eq. 4.57 through the
two points for ``(d/M, d/N, 1)`` as one homogeneous triple, met with the
inflection circle, so that ``N = ∞`` gives ``U = J`` by the formula itself and
the same step (replayed on the live page) finds ``U`` at any other posture.

Example 4.16: two misprinted centrode radii
-------------------------------------------
The book's Example 4.16 (``R_JI = 2√2`` in, ``M = -2√2`` in, ``N = ∞``)
substitutes ``R_JI = M = -2√2`` in Eq. 4.56 ("M = -R_BI = R_JI = -2√2 in",
Eq. 7), although its own Ans. (3) and its sign rule (``N`` from ``I`` toward
``J``) make ``R_JI = +2√2`` in, so ``M = -R_JI``.  It then finds
``R_IO_M = √2`` in (the moving centrode "coalesces with the inflection
circle") and ``R_IO_F = 2√2`` in (``O_F`` "coincident with J").  With
``M = -R_JI`` the same equations give::

    1/R_IO_M = 1/R_JI - 3/M = 4/R_JI   ->  R_IO_M = R_JI/4 = √2/2 = 0.7071 in
    1/R_IO_F = 1/R_JI + 1/R_IO_M = 5/R_JI -> R_IO_F = R_JI/5 = 2√2/5 = 0.5657 in

both positive: ``O_M`` and ``O_F`` lie on the side of ``I`` away from ``J``,
at ``O_M = (0.5, -0.5)`` in and ``O_F = (0.4, -0.6)`` in with ``O_2`` at the
origin (``I = (0, -1)``, ``J = (-2, -3)``).  The evidence is independent of
these formulas: the loci of ``I13`` in the frame and in the coupler,
differentiated numerically over the crank angle, have exactly these
curvatures (``tests/kinematics/test_curvature.py``); the book's values fail
the same check.  (Its figure caption also gives ``R_BO4 = 5.657`` in where the
solution uses ``R_BB' = √2 = 1.414`` in, Eq. 2, which the posture requires.)

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Secs. 4.12-4.17 (Eqs. 4.40-4.57, Figs. 4.25-4.40, Examples 4.12-4.16).

Examples
--------
Example 4.16: the four-bar with link 2 perpendicular to the frame and the
coupler parallel to it.

>>> import graphkin
>>> import numpy as np
>>> sol = graphkin.loads('''
... units = { length = "in" }
... [links.1]
... O2 = [0, 0]
... O4 = [1, 0]
... [links.2]
... O2 = [0, 0]
... A = [1, 0]
... [links.3]
... A = [0, 0]
... B = [2, 0]
... C = [1, 0]
... [links.4]
... O4 = [0, 0]
... B = [1.4142135623730951, 0]
... [drive]
... link = 2
... angle = 90
... omega = 1
... [assembly]
... B = [2, 1]
... ''').solve()
>>> k = link_curvature(sol, "3")

Here ``AB ∥ A'B'``, so the construction through ``W`` has no answer and the
inflection points are laid off by Eq. 4.43, as the book does:

>>> k.method
'euler-savary'
>>> np.round(k.velocity_pole, 6) + 0.0, np.round(k.inflection_pole, 6) + 0.0
(array([ 0., -1.]), array([-2., -3.]))
>>> round(k.inflection_diameter, 6), round(k.cubic.M, 6), k.cubic.N
(2.828427, -2.828427, inf)
>>> np.round(k.ball_point, 6)
array([-2., -3.])
>>> round(k.moving_centrode[0], 6), round(k.fixed_centrode[0], 6)
(0.707107, 0.565685)
"""

from __future__ import annotations

from graphkin.kinematics._moved import moved_to
from graphkin.kinematics.curvature.bresse import bresse_pole
from graphkin.kinematics.curvature.centrodes import centrode_radii
from graphkin.kinematics.curvature.conjugates import known_conjugates
from graphkin.kinematics.curvature.cubic import Cubic, ball_point, stationary_curvature_cubic
from graphkin.kinematics.curvature.euler_savary import (
    euler_savary,
    inflection_points_on_ray,
    radius_of_curvature,
)
from graphkin.kinematics.curvature.inflection import (
    acceleration_center,
    inflection_pole,
    pole_velocity,
)
from graphkin.kinematics.curvature.link import (
    LinkCurvature,
    curvature,
    curvature_constructions,
    link_curvature,
    path_curvatures,
)
from graphkin.kinematics.curvature.paths import PathCurvature, path_curvature

__all__ = ["Cubic", "LinkCurvature", "PathCurvature", "euler_savary", "inflection_points_on_ray",
           "radius_of_curvature", "inflection_pole", "pole_velocity", "acceleration_center",
           "bresse_pole", "stationary_curvature_cubic", "ball_point", "centrode_radii",
           "path_curvature", "known_conjugates", "link_curvature", "curvature",
           "curvature_constructions", "path_curvatures", "curvature_json", "paths_json",
           "curvature_text"]


# the reports moved to the output layer (graphkin.output); the old import path still works
__getattr__ = moved_to("graphkin.output.curvature",
                       ("curvature_json", "paths_json", "curvature_text"), __name__)
