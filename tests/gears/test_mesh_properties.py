"""The layout of a pair in mesh, by construction, against the book's closed forms (Secs. 7.5-7.10).

Random pairs: teeth, module, pressure angle, tooth system, cutter offsets
(Sec. 7.11) and a center distance at or beyond where the teeth touch on both
flanks (Sec. 7.9).  Every quantity is measured on the evaluated construction
(:func:`graphkin.gears.layout`) and compared with
:mod:`graphkin.gears.analytic`, which shares no code with it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from graphkin.errors import InputError
from graphkin.gears import Contact, Gear, GearPair, layout
from graphkin.gears import analytic as an
from graphkin.gears.involute import Unwind, involute_construction, involute_xy
from graphkin.gears.tooth import ADDENDUM, DEDENDUM, ToothSystem


@st.composite
def pairs(draw: st.DrawFn) -> GearPair:
    n2 = draw(st.integers(8, 60))
    n3 = draw(st.integers(n2, 150))
    m = draw(st.floats(0.05, 20.0))
    phi = math.radians(draw(st.floats(14.0, 30.0)))
    system = draw(st.sampled_from(list(ToothSystem)))
    a, d = ADDENDUM[system] * m, DEDENDUM[system] * m
    e2 = draw(st.floats(-0.3, 0.6)) * m
    e3 = draw(st.sampled_from([0.0, -e2, draw(st.floats(-0.3, 0.3)) * m]))
    stretch = draw(st.sampled_from([0.0, draw(st.floats(0.0, 0.04))]))
    try:
        g2 = Gear("pinion", 2, n2, m, phi, a, d, e2, clearance=d - a)
        g3 = Gear("gear", 3, n3, m, phi, a, d, e3, clearance=d - a)
        tight = GearPair(g2, g3).tight_center_distance
        return GearPair(g2, g3, tight * (1.0 + stretch))
    except InputError:   # pointed teeth, offsets that leave no mesh: not a pair
        assume(False)
        raise


def _layout(pair_factory):
    try:
        return layout(pair_factory())
    except InputError:
        assume(False)
        raise


def _xy(p):
    return np.array(p)


@settings(max_examples=50, deadline=None)
@given(pairs())
def test_contact_ratio_by_construction_is_eq_7_9(pair):
    """CD / p_b measured on the construction equals Eq. (7.9) with (7.10)-(7.11), to 1e-9."""
    lay = _layout(lambda: pair)
    g2, g3 = pair.driver, pair.driven
    ra2, ra3 = pair.outside_radii
    phi_op = an.operating_pressure_angle(pair.standard_center_distance, pair.center,
                                         g2.pressure_angle)
    cp, pd = an.approach_recess(ra2, ra3, g2.base_radius, g3.base_radius, pair.center, phi_op)
    pb = an.base_pitch(g2.module, g2.pressure_angle)
    assert lay.contact_ratio == pytest.approx(an.contact_ratio(cp, pd, pb), rel=1e-9, abs=1e-9)
    assert lay.approach == pytest.approx(cp, rel=1e-9, abs=1e-9 * pair.center)
    assert lay.recess == pytest.approx(pd, rel=1e-9, abs=1e-9 * pair.center)
    # the operating pressure angle measured between the line of action and the common
    # tangent: cos φ' = C cos φ / C' (Sec. 7.9)
    assert lay.operating_pressure_angle == pytest.approx(phi_op, abs=1e-9)
    # Eq. (7.12): the verdicts agree with the book's inequalities (away from the boundary)
    over_a, over_b = an.interference(cp, pd, *pair.operating_pitch_radii, phi_op)
    scale = 1e-7 * pair.center
    if abs(over_a) > scale:
        assert (lay.start == Contact.INTERFERENCE) == (over_a > 0)
    if abs(over_b) > scale:
        assert (lay.end == Contact.INTERFERENCE) == (over_b > 0)


@settings(max_examples=40, deadline=None)
@given(pairs())
def test_layout_is_the_books_figure(pair):
    """A, B on the base circles with O2A, O3B perpendicular to the line of action through P;
    C, D on the addendum circles; the angles of approach turn the pinion's involute from C
    to P (Eq. 7.7)."""
    lay = _layout(lambda: pair)
    g2, g3 = pair.driver, pair.driven
    pts = {k: _xy(v) for k, v in lay.points.items()}
    s = pair.center
    u = pts["B"] - pts["A"]
    u /= np.linalg.norm(u)
    for center, foot, rb in (("O2", "A", g2.base_radius), ("O3", "B", g3.base_radius)):
        r = pts[foot] - pts[center]
        assert np.linalg.norm(r) == pytest.approx(rb, rel=1e-9)
        assert abs(r @ u) <= 1e-9 * s
    for q in ("P", "C", "D"):
        w = pts[q] - pts["A"]
        assert abs(w[0] * u[1] - w[1] * u[0]) <= 1e-9 * s
    ra2, ra3 = pair.outside_radii
    assert np.linalg.norm(pts["C"] - pts["O3"]) == pytest.approx(ra3, rel=1e-9)
    assert np.linalg.norm(pts["D"] - pts["O2"]) == pytest.approx(ra2, rel=1e-9)
    # Eq. (7.7) from the involute itself: the driving flank of the pinion has polar angle
    # ψ − β_b + inv ϕ (Sec. 7.10); to carry its contact from C to P the pinion turns
    # cw by (θ_C − inv ϕ_C) − (θ_P − inv ϕ_P).  (With interference C lies beyond A, where
    # the involute does not reach: the book's Eq. (7.7) then measures the cord, not a flank.)
    def tooth_angle(q: str) -> float:
        v = pts[q] - pts["O2"]
        return math.atan2(v[1], v[0]) - an.inv(math.acos(g2.base_radius / np.linalg.norm(v)))

    if lay.start == Contact.INSIDE:
        assert tooth_angle("C") - tooth_angle("P") == pytest.approx(lay.approach_angles[0],
                                                                    abs=1e-8)


@settings(max_examples=40, deadline=None)
@given(st.floats(0.1, 100.0), st.integers(1, 12), st.floats(0.05, 1.5),
       st.floats(-math.pi, math.pi), st.sampled_from(list(Unwind)))
def test_involute_construction_is_the_involute(base, parts, roll, origin, sense):
    """The points struck on the tangents (Step 6) satisfy r = r_b / cos ϕ (Eq. 7.15) and lie
    at the polar angle inv ϕ from the origin A0 (Eq. 7.14), with tan ϕ the angle rolled."""
    ev = involute_construction(base, parts=parts, roll=roll, origin=origin,
                               sense=sense).evaluate()
    s = 1.0 if sense == Unwind.CCW else -1.0
    for k in range(parts + 1):
        x, y, w = ev[f"T{k}"]
        varphi = math.atan(k * roll / parts)
        assert math.hypot(x / w, y / w) == pytest.approx(base / math.cos(varphi), rel=1e-9)
        turn = math.atan2(y / w, x / w) - origin
        turn = math.remainder(turn, 2 * math.pi)
        assert turn == pytest.approx(s * an.inv(varphi), abs=1e-9)


@settings(max_examples=40, deadline=None)
@given(pairs(), st.floats(0.0, 1.0))
def test_thickness_is_the_drawn_tooth(pair, where):
    """Eq. (7.16) equals the arc between the two involute flanks of a tooth drawn about ψ = 0."""
    g = pair.driver
    r_lo = max(g.base_radius, g.root_radius)
    r_hi = min(pair.outside_radii[0], g.pointed_radius())
    assume(r_hi > r_lo)
    r = r_lo + where * (r_hi - r_lo)
    beta_b = g.thickness / (2 * g.pitch_radius) + an.inv(g.pressure_angle)
    upper = involute_xy(g.base_radius, r, origin=beta_b, sense=Unwind.CW)
    lower = involute_xy(g.base_radius, r, origin=-beta_b, sense=Unwind.CCW)
    arc = r * (math.atan2(upper[1], upper[0]) - math.atan2(lower[1], lower[0]))
    assert float(g.thickness_at(r)) == pytest.approx(arc, rel=1e-9, abs=1e-12 * r)
    assert float(g.thickness_at(r)) == pytest.approx(
        float(an.tooth_thickness(r, g.pitch_radius, g.thickness, g.pressure_angle,
                                 g.base_radius)), rel=1e-12, abs=1e-12 * r)


@settings(max_examples=30, deadline=None)
@given(pairs())
def test_tight_mesh_is_eq_7_18(pair):
    """Where the teeth touch on both flanks: Eq. (7.18)'s φ' and Eqs. (7.19)-(7.20)'s radii;
    there the thicknesses on the operating pitch circles add up to the pitch."""
    g2, g3 = pair.driver, pair.driven
    phi = an.modified_pressure_angle(g2.teeth, g3.teeth, g2.pitch_radius, g2.thickness,
                                     g3.thickness, g2.pressure_angle)
    assert pair.tight_angle == pytest.approx(phi, abs=1e-9)
    r2 = an.modified_pitch_radius(g2.pitch_radius, g2.pressure_angle, phi)
    r3 = an.modified_pitch_radius(g3.pitch_radius, g3.pressure_angle, phi)
    assert pair.tight_center_distance == pytest.approx(r2 + r3, rel=1e-9)
    p_op = 2 * math.pi * r2 / g2.teeth
    assert float(g2.thickness_at(r2) + g3.thickness_at(r3)) == pytest.approx(p_op, rel=1e-8)


def _border_pair(scale: float = 1.0) -> GearPair:
    """A pair whose gear addendum circle passes exactly through the interference point A."""
    phi = math.radians(20)
    m = 2.0 * scale
    g2 = Gear("pinion", 2, 14, m, phi, m, 1.25 * m, clearance=0.25 * m)
    r3 = 30 * m / 2
    c = r3 + 14 * m / 2
    a3 = math.sqrt((r3 * math.cos(phi)) ** 2 + (c * math.sin(phi)) ** 2) - r3
    g3 = Gear("gear", 3, 30, m, phi, a3, a3 + 0.25 * m, clearance=0.25 * m)
    return GearPair(g2, g3)


@pytest.mark.parametrize("factor", [1.0, 1 + 1e-12, 1 - 1e-12])
def test_verdict_on_the_border_does_not_move_with_round_off(factor):
    """C exactly at A (Eq. 7.12 with equality): no interference, at any 1e-12 perturbation."""
    lay = layout(_border_pair(factor))
    assert abs(lay.beyond_a) < 1e-9 * lay.pair.center
    assert lay.start == Contact.INSIDE


@pytest.mark.parametrize("name", ["ex7_1.toml", "fig7_18.toml", "ex7_3.toml"])
@pytest.mark.parametrize("factor", [1 + 1e-12, 1 - 1e-12])
def test_book_verdicts_do_not_move_with_round_off(gear_examples, name, factor):
    from dataclasses import replace

    from graphkin.gears.file import load

    pair = load(gear_examples / name)
    base = layout(pair)
    moved = layout(replace(pair, driver=replace(pair.driver, module=pair.driver.module * factor),
                           driven=replace(pair.driven, module=pair.driven.module * factor)))
    assert (moved.start, moved.end) == (base.start, base.end)


@settings(max_examples=30, deadline=None)
@given(pairs())
def test_drawn_teeth_are_involutes_touching_at_p(pair):
    """The drawn flanks lie on the involute of Eqs. (7.14)-(7.15), and the teeth set in mesh
    touch at P with their common normal the line of action: the flank of 2 through P is
    generated from A, the flank of 3 from B (Sec. 7.3, Fig. 7.7)."""
    from graphkin.gears.profile import FLANK, gear_teeth, mesh_phases

    lay = _layout(lambda: pair)
    g2, g3 = pair.driver, pair.driven
    ra2, ra3 = pair.outside_radii
    # tooth 0 of gear 2 about the origin, phase 0: its clockwise flank (the first FLANK
    # points above the base circle) starts on the base circle at -β_b and unwinds ccw
    outline = gear_teeth(g2, ra2, (0.0, 0.0), 0.0)[0]
    flank = outline[: FLANK + (1 if g2.root_radius < g2.base_radius else 0)]
    r = np.hypot(flank[:, 0], flank[:, 1])
    on = r >= g2.base_radius * (1 + 1e-12)
    beta_b = g2.thickness / (2 * g2.pitch_radius) + an.inv(g2.pressure_angle)
    expect = involute_xy(g2.base_radius, r[on], origin=-beta_b, sense=Unwind.CCW)
    assert np.allclose(flank[on], expect, rtol=0, atol=1e-9 * ra2)
    # in mesh: the flank points at the operating pitch radii are P, generated from A and B
    psi2, psi3 = mesh_phases(pair)
    r2p, r3p = pair.operating_pitch_radii
    for g, psi, rp, o, foot in ((g2, psi2, r2p, "O2", "A"), (g3, psi3, r3p, "O3", "B")):
        center = np.array(lay.points[o])
        theta = psi - float(g.half_angle(rp))
        on_p = center + rp * np.array([math.cos(theta), math.sin(theta)])
        assert np.allclose(on_p, lay.points["P"], atol=1e-9 * pair.center)
        varphi = math.acos(g.base_radius / rp)
        t = center + g.base_radius * np.array([math.cos(theta + varphi),
                                               math.sin(theta + varphi)])
        assert np.allclose(t, lay.points[foot], atol=1e-9 * pair.center)


@settings(max_examples=25, deadline=None)
@given(n2=st.integers(3, 60), n3=st.integers(3, 120), phi=st.sampled_from([14.5, 20.0, 25.0]))
def test_the_report_says_interference_or_none_never_both(n2: int, n3: int, phi: float) -> None:
    # a report once said "Interference ... after B" and then "No interference: C and D
    # lie between A and B" for a 20/3-tooth pair (the no-interference line hung on the
    # tip-interference test). The words follow the layout's own verdict, once.
    from graphkin.gears import layout
    from graphkin.gears.file import loads
    from graphkin.output.gears import gears_text

    lay = layout(loads(f'units = "in"\ndiametral_pitch = 10\npressure_angle = {phi}\n'
                       f"[gears.pinion]\nteeth = {n2}\n[gears.gear]\nteeth = {n3}\n"))
    text = gears_text(lay)
    said_yes = "  Interference (Sec. 7.7" in text
    said_no = "  No interference:" in text
    assert said_yes != said_no
    assert said_yes == bool(lay.interference)
