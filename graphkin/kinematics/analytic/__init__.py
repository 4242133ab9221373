"""The independent analytic solver: the oracle every graphic construction is checked against.

Each moving link ``k`` gets three generalized coordinates ``q = (x_k, y_k, θ_k)``:
where its local origin is and the direction of its own x axis.  A point with
local coordinates ``p`` is then at ``P = o_k + R(θ_k) p``.  Every joint of the
mechanism file becomes scalar constraint equations ``Φ(q) = 0`` (the
loop-closure equations of Sec. 2.7 written link by link, as in the
"relative coordinates" form of Sec. 2.9), the drives add one equation each,
and the posture is found by damped Newton-Raphson (Levenberg-Marquardt, then
plain Newton to polish).  Velocities and accelerations follow by one linear
solve each (Secs. 3.9 and 4.9, the algebraic velocity and acceleration
analyses)::

    Φ_q q̇ = -Φ_t,        Φ_q q̈ = -(Φ_q q̇)_q q̇ - Φ_tt.

Nothing here uses the graphic constructions (``graphkin.construction``,
``graphkin.geometry``): it is a second, independent route to the same numbers.

The constraint rows
-------------------
With ``perp(v) = k × v`` (``(-v_y, v_x)``), for a body point
``P = o + R(θ) p`` we have ``∂P/∂o = I``, ``∂P/∂θ = perp(R p)`` and

    ``dP/dt = ȯ + ω perp(R p)``,
    ``d²P/dt² = ö + α perp(R p) - ω² R p``          (Eqs. 3.4 and 4.5).

The last term, ``-ω² R p``, is the only part of a point's acceleration that
is *not* linear in ``q̈``: it is the point's contribution to the quadratic
velocity terms ``γ = (Φ_q q̇)_q q̇`` that go to the right-hand side.

* **Pin** (a point name shared by links ``a`` and ``b``):
  ``P_a - P_b = 0`` (two rows).  ``γ = -ω_a² R_a p_a + ω_b² R_b p_b``.
* **Point on a line of link** ``o`` (slider, straight slot, slider drive):
  ``f = v·(P - L0)`` with ``v = R_o v_loc`` a unit vector fixed in ``o``
  (the line's normal ``n`` for "on the line", its direction ``u`` for the
  travel of a slider drive) and ``L0 = o_o + R_o l0`` its first point.
  Writing ``r = P - L0``, ``v̇ = ω_o perp(v)`` and
  ``v̈ = α_o perp(v) - ω_o² v``, so

      ``f̈ = v̈·r + 2 v̇·ṙ + v·r̈``

  whose part free of second derivatives is
  ``γ = -ω_o² v·r + 2 ω_o perp(v)·ṙ + v·(-ω_s² R_s p_s + ω_o² R_o l0)``
  (the middle term is the Coriolis term of Sec. 4.5).
* **Slider angle** (the slider cannot turn relative to ``on``):
  ``θ_s - θ_o - φ = 0`` with ``φ`` the line's angle in ``on``'s coordinates;
  linear, ``γ = 0``.  A revolute drive ``θ_k - value = 0`` likewise.
* **Circular slot** (centre ``c`` fixed in ``o``, radius ``ρ``):
  ``f = (|r|² - ρ²) / (2ρ)`` with ``r = P - C``; ``ḟ = r·ṙ/ρ``,
  ``f̈ = (ṙ·ṙ + r·r̈)/ρ`` so ``γ = (ṙ·ṙ + r·(-ω_s² R_s p_s + ω_o² R_o c))/ρ``.
* **Rolling contact without slip** (``[[rolling]]``: a circle of radius
  ``ρ`` of link ``l`` on a line of link ``o``).  The contact is the
  equivalent slot of the center (among the slots, as the parser gives it);
  no slip adds ``g = (θ_l - θ_o) + σ s/ρ - c`` with ``s = u·(P - L0)`` the
  travel of the center along the line in ``o``'s coordinates (``σ = +1``
  when the circle lies on the left of the line, -1 on the right): an angle
  row plus ``σ/ρ`` times a travel row, so ``γ = σ/ρ γ_travel``.  At the
  file's drive the posture row is ``θ_l - angle = 0`` instead (the rolling
  link stands at the file's angle); over a sweep it is ``g`` with ``c``
  taken from the file's posture.  See :class:`_Rolling` for the derivation.
* **Rolling contact on a circle** (a circle of radius ``r`` of link ``l``
  on a circle of radius ``R`` of link ``o``, center ``O`` fixed in ``o``:
  gears).  The center distance is the equivalent circular slot of radius
  ``R + r`` (outside) or ``R - r`` (inside), unless one link already holds
  both centers (a planet on its arm: then no slot).  No slip adds
  ``g = (θ_l - θ_o) - k φ - c`` with ``φ`` the angle of ``P - O`` in
  ``o``'s axes and ``k = (R + r)/r`` (outside) or ``-(R - r)/r`` (inside),
  so ``γ = -k γ_φ``; the posture rows are as for a line.  See
  :class:`_RollingCircle`.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 2.7 (loop-closure equations), Secs. 2.9-2.11 (algebraic posture
analysis), Sec. 2.19 (apparent angular displacement: the rolling
constraint), Sec. 3.7 (rolling contact, Eq. 3.13), Sec. 3.9 (algebraic
velocity analysis), Sec. 3.11 and Sec. 4.11 (kinematic coefficients; Example
3.9, a wheel rolling on the ground), Sec. 4.5 (Coriolis), Sec. 4.7 (Eq.
4.19), Sec. 4.9 (algebraic acceleration analysis).
"""

from __future__ import annotations

from graphkin.kinematics.analytic.many import solve_analytic_many
from graphkin.kinematics.analytic.posture import solve_analytic

__all__ = ["solve_analytic", "solve_analytic_many"]
