"""The gear formulas of Chapter 7 in closed form: the independent check of the constructions.

Nothing here uses a construction step or the gear model: each function is
one equation of the book, written with plain floats (or numpy arrays), so
that the tests can hold the recorded constructions of
:mod:`graphkin.gears.mesh` and :mod:`graphkin.gears.involute` against it, as
:mod:`graphkin.kinematics.analytic` checks the mechanism constructions.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Secs. 7.1-7.11, Eqs. (7.1)-(7.21).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

__all__ = ["inv", "inv_inverse", "circular_pitch", "base_pitch", "pitch_radius",
           "approach_recess", "contact_ratio", "interference", "operating_pressure_angle",
           "tooth_thickness", "offset_thickness", "modified_pressure_angle",
           "modified_pitch_radius", "offset_for_no_undercut", "minimum_teeth",
           "minimum_teeth_rack", "involute_point", "approach_recess_internal",
           "minimum_teeth_internal",
           "approach_recess_rack"]


def inv(phi: Any) -> Any:
    """The involute function ``inv φ = tan φ - φ`` (Eq. 7.14), φ in radians.

    Examples
    --------
    >>> round(inv(math.radians(20)), 6)   # Example 7.2: 0.014904
    0.014904
    """
    if isinstance(phi, (int, float)):
        return math.tan(phi) - phi
    return np.tan(phi) - phi


def inv_inverse(x: float) -> float:
    """The angle φ (radians, in [0, π/2)) with ``inv φ = x``.

    The root the book reads from its Appendix A, Table 6 (Sec. 7.10), found
    by Newton's method from ``φ ≈ (3x)^(1/3)``.

    Examples
    --------
    >>> round(math.degrees(inv_inverse(0.01908)), 2)   # Example 7.3: 21.65°
    21.65
    """
    if x < 0 or not math.isfinite(x):
        raise ValueError(f"inv φ = {x!r} has no angle in [0°, 90°)")
    if x == 0:
        return 0.0
    # tan φ - φ ≈ φ³/3 for small φ; the derivative is tan² φ > 0, and the function is convex
    # on (0, π/2): Newton from an estimate above the root converges monotonically.
    phi = min((3.0 * x) ** (1.0 / 3.0), math.atan(x + math.pi / 2))
    if inv(phi) < x:
        phi = math.atan(x + math.pi / 2)   # tan φ = x + φ < x + π/2: an upper bound
    for _ in range(100):
        step = (math.tan(phi) - phi - x) / math.tan(phi) ** 2
        phi -= step
        if abs(step) <= 1e-16 * max(phi, 1e-300):
            break
    return phi


def pitch_radius(teeth: int, module: float) -> float:
    """``R = N m / 2`` (Eq. 7.2; with a diametral pitch, ``m = 1/P``, Eq. 7.1)."""
    return teeth * module / 2.0


def circular_pitch(module: float) -> float:
    """``p = π m = π / P`` (Eq. 7.4)."""
    return math.pi * module


def base_pitch(module: float, phi: float) -> float:
    """``p_b = p cos φ`` (Eq. 7.6)."""
    return circular_pitch(module) * math.cos(phi)


def approach_recess(outside2: float, outside3: float, base2: float, base3: float,
                    center: float, phi: float) -> tuple[float, float]:
    """The approach and recess lengths ``CP`` and ``PD`` (Eqs. 7.10 and 7.11).

    Written with the outside and base radii and the operating pressure angle
    φ, so that it holds at any center distance (Sec. 7.9; Example 7.3 uses
    it so): ``CP = √(R_a3² − r_3²) − R'_3 sin φ'`` with ``R'_3 = r_3 / cos φ'``.

    Parameters
    ----------
    outside2, outside3 : float
        Addendum-circle radii of the driver (2) and the driven gear (3).
    base2, base3 : float
        Base-circle radii.
    center : float
        The center distance (only its split ``R'_2 + R'_3`` by the base radii is used).
    phi : float
        Operating pressure angle (radians).
    """
    r2p = center * base2 / (base2 + base3)
    r3p = center * base3 / (base2 + base3)
    cp = math.sqrt(outside3 ** 2 - base3 ** 2) - r3p * math.sin(phi)
    pd = math.sqrt(outside2 ** 2 - base2 ** 2) - r2p * math.sin(phi)
    return cp, pd


def approach_recess_internal(outside2: float, inside3: float, base2: float, base3: float,
                             pitch2: float, pitch3: float, phi: float) -> tuple[float, float]:
    """CP and PD for a pinion inside an internal gear (Sec. 7.5, Fig. 7.11).

    Both centers lie on one side of P, so the foot B of the ring's center on
    the line of action lies beyond A, and the ring's addendum circle (radius
    ``R_3 − a``, inside its pitch circle) crosses the line of action twice on
    that side; first contact is the crossing nearer P:
    ``CP = R_3 sin φ − √((R_3 − a)² − r_3²)``.  The recess is the pinion's, as
    for external gears: ``PD = √((R_2 + a)² − r_2²) − R_2 sin φ``.
    """
    cp = pitch3 * math.sin(phi) - math.sqrt(inside3 ** 2 - base3 ** 2)
    pd = math.sqrt(outside2 ** 2 - base2 ** 2) - pitch2 * math.sin(phi)
    return cp, pd


def approach_recess_rack(outside2: float, base2: float, pitch2: float, addendum3: float,
                         phi: float) -> tuple[float, float]:
    """CP and PD for a pinion in mesh with a rack (Sec. 7.5, Fig. 7.10).

    Eq. (7.10) as ``R_3 → ∞``: ``√((R_3 + a)² − R_3² cos² φ) − R_3 sin φ =
    (2 R_3 a + a² ) / (√(...) + R_3 sin φ) → a / sin φ``, which is also read off
    the figure: C lies on the rack's addendum line, ``a`` from the pitch line,
    on a line of action at φ to it.  The recess is Eq. (7.11) unchanged:
    ``PD = √(R_a2² − r_2²) − R_2 sin φ``.
    """
    cp = addendum3 / math.sin(phi)
    pd = math.sqrt(outside2 ** 2 - base2 ** 2) - pitch2 * math.sin(phi)
    return cp, pd


def minimum_teeth_internal(k: float, phi: float, ring: int) -> float:
    """The least pinion teeth that mesh inside a ring of ``ring`` teeth without interference.

    Eq. (7.12)'s first condition, ``CP ≤ R_2 sin φ``, with the internal CP
    (:func:`approach_recess_internal`, addendum ``k m``), squared and
    divided by ``m²/4``: ``(N_3 − N_2)² sin² φ ≤ N_3² sin² φ − 4k (N_3 − k)``,
    so ``N_2 ≥ N_3 − √(N_3² − 4k (N_3 − k)/sin² φ)``; NaN when no pinion fits
    (the ring's tips inside its base circle).
    """
    s2 = math.sin(phi) ** 2
    disc = ring * ring - 4.0 * k * (ring - k) / s2
    return ring - math.sqrt(disc) if disc >= 0 else math.nan


def contact_ratio(cp: float, pd: float, pb: float) -> float:
    """``m_c = CD / p_b`` with ``CD = CP + PD`` (Eq. 7.9)."""
    return (cp + pd) / pb


def interference(cp: float, pd: float, pitch2: float, pitch3: float, phi: float
                 ) -> tuple[float, float]:
    """How far contact begins before A and ends after B (Eq. 7.12): positive means interference.

    Returns ``(CP − R'_2 sin φ', PD − R'_3 sin φ')``: the first is the length
    AC by which the driven gear's tip cuts into the driver's flank inside
    its base circle, the second BD.
    """
    return cp - pitch2 * math.sin(phi), pd - pitch3 * math.sin(phi)


def operating_pressure_angle(standard_center: float, center: float, phi: float) -> float:
    """The pressure angle at an increased center distance (Sec. 7.9).

    The base circles do not change, ``R cos φ = R' cos φ'`` (Eqs. 7.19-7.20),
    and the pitch radii share the center distance in the same ratio, so
    ``cos φ' = C cos φ / C'``.
    """
    return math.acos(standard_center * math.cos(phi) / center)


def tooth_thickness(r: Any, rp: float, tp: float, phi: float, base: float) -> Any:
    """The tooth thickness at radius ``r`` (Eq. 7.16).

    ``t = 2r (t_p / 2r_p + inv φ − inv ϕ)`` with ``cos ϕ = r_b / r`` (Eq. 7.15).

    Examples
    --------
    Example 7.2 (22 teeth, P = 2, 20°): 0.892 in at the base circle.

    >>> rp = 5.5; rb = rp * math.cos(math.radians(20))
    >>> round(float(tooth_thickness(rb, rp, math.pi / 2 / 2, math.radians(20), rb)), 3)
    0.892
    """
    varphi = np.arccos(np.clip(base / np.asarray(r, dtype=float), -1.0, 1.0))
    return 2.0 * np.asarray(r) * (tp / (2.0 * rp) + inv(phi) - inv(varphi))


def offset_thickness(e: float, phi: float, p: float) -> float:
    """The thickness at the standard pitch circle of a tooth cut with the rack offset ``e``.

    Eq. (7.17): ``t = 2e tan φ + p/2``.

    The book prints ``P/2``; it means the circular pitch ``p`` (Example 7.3
    uses ``p/2 = 3.142/2``).
    """
    return 2.0 * e * math.tan(phi) + p / 2.0


def modified_pressure_angle(n2: int, n3: int, r2: float, t2: float, t3: float,
                            phi: float) -> float:
    """The pressure angle at which two modified gears mesh with no backlash (Eq. 7.18).

    ``inv φ' = [N_2 (t'_2 + t'_3) − 2π R_2] / [2 R_2 (N_2 + N_3)] + inv φ``,
    the thicknesses measured on the standard pitch circles.
    """
    x = (n2 * (t2 + t3) - 2.0 * math.pi * r2) / (2.0 * r2 * (n2 + n3)) + float(inv(phi))
    return inv_inverse(x)


def modified_pitch_radius(r: float, phi: float, phi_mod: float) -> float:
    """``R' = R cos φ / cos φ'`` (Eqs. 7.19, 7.20)."""
    return r * math.cos(phi) / math.cos(phi_mod)


def offset_for_no_undercut(addendum: float, r: float, phi: float) -> float:
    """The least rack-cutter offset that cuts no undercut: ``e = a − R sin² φ`` (Eq. 7.21)."""
    return addendum - r * math.sin(phi) ** 2


def minimum_teeth(k: float, phi: float, mate: float) -> float:
    """The least (real) number of pinion teeth that mesh with ``mate`` teeth without interference.

    From Eq. (7.12) with the mate's addendum ``k m``: the mate's addendum
    circle must not cross the line of action beyond the pinion's
    interference point A, ``(R_3 + k m)² ≤ r_3² + (C sin φ)²``.  With
    ``R_3 = N_3 m/2``, ``r_3 = R_3 cos φ`` and ``C = (N_2 + N_3) m/2`` this is
    ``N_2² + 2 N_3 N_2 ≥ 4k (N_3 + k) / sin² φ``, so
    ``N_2 ≥ −N_3 + √(N_3² + 4k (N_3 + k)/sin² φ)``.  Round up for whole teeth.

    Examples
    --------
    >>> math.ceil(minimum_teeth(1.0, math.radians(20), 40))   # Example 7.3: 12 < 15 undercuts
    15
    """
    s2 = math.sin(phi) ** 2
    return -mate + math.sqrt(mate * mate + 4.0 * k * (mate + k) / s2)


def minimum_teeth_rack(k: float, phi: float) -> float:
    """The limit of :func:`minimum_teeth` for a rack (the cutter): ``N ≥ 2k / sin² φ``.

    Examples
    --------
    >>> math.ceil(minimum_teeth_rack(1.0, math.radians(20)))
    18
    """
    return 2.0 * k / math.sin(phi) ** 2


def involute_point(base: float, varphi: Any) -> tuple[Any, Any]:
    """A point of the involute of a circle of radius ``base`` in polar form (Sec. 7.10).

    Returns ``(r, θ)``: ``r = r_b / cos ϕ`` (Eq. 7.15) and the polar angle from
    the involute's origin ``θ = inv ϕ`` (Eq. 7.14), for the involute angle ϕ.
    """
    varphi = np.asarray(varphi, dtype=float)
    return base / np.cos(varphi), inv(varphi)
