"""A pinion inside an internal (annular) gear, Sec. 7.5 and Fig. 7.11.

Hand derivation (both centers on one side of P, the line of action through P at φ):
the foot B of O3 lies beyond A at R3 sin φ from P, and the ring's addendum circle
(radius R3 − a) crosses the line of action twice on that side; first contact C is the
crossing nearer P, CP = R3 sin φ − √((R3 − a)² − r3²); the recess is the pinion's,
PD = √((R2 + a)² − r2²) − R2 sin φ; m_c = (CP + PD)/p_b (Eq. 7.9).  Interference
(Eq. 7.12) when CP > R2 sin φ.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin.cli import main
from graphkin.errors import InputError
from graphkin.gears import layout
from graphkin.gears.file import loads
from graphkin.gears.profile import gear_teeth, mesh_phases

RING = """title = "ring"
units = "in"
diametral_pitch = 10
pressure_angle = {phi}
[gears.pinion]
teeth = {n2}
[gears.ring]
teeth = {n3}
kind = "internal"
"""


def _hand(n2: int, n3: int, phi_deg: float, m: float = 0.1) -> tuple[float, float, float]:
    phi = math.radians(phi_deg)
    r2, r3, a = n2 * m / 2, n3 * m / 2, m
    cp = r3 * math.sin(phi) - math.sqrt((r3 - a) ** 2 - (r3 * math.cos(phi)) ** 2)
    pd = math.sqrt((r2 + a) ** 2 - (r2 * math.cos(phi)) ** 2) - r2 * math.sin(phi)
    return cp, pd, (cp + pd) / (math.pi * m * math.cos(phi))


def test_fig_7_11_by_hand():
    """Example 7.1's pinion (20 teeth, P = 10) inside a 72-tooth ring, 20°: C' = 2.6 in."""
    lay = layout(loads(RING.format(phi=20, n2=20, n3=72)))
    cp, pd, mc = _hand(20, 72, 20)
    assert lay.pair.center == pytest.approx(2.6, rel=1e-12)
    assert lay.approach == pytest.approx(cp, rel=1e-9)
    assert lay.recess == pytest.approx(pd, rel=1e-9)
    assert lay.contact_ratio == pytest.approx(mc, rel=1e-9)
    assert not lay.interference          # CP = 0.3335 < R2 sin 20° = 0.3420
    # both centers above P, O3 = (0, R3), and B beyond A on the same side of P
    assert lay.points["O3"] == pytest.approx((0.0, 3.6))
    a, b = np.array(lay.points["A"]), np.array(lay.points["B"])
    assert b == pytest.approx(a * 3.6, rel=1e-9)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(8, 60), st.integers(2, 90), st.sampled_from([20.0, 22.5, 25.0]))
def test_construction_equals_eq_7_9_and_eq_7_12(n2, extra, phi):
    n3 = n2 + extra
    try:
        pair = loads(RING.format(phi=phi, n2=n2, n3=n3))
        lay = layout(pair)
    except InputError as exc:   # the ring's tips inside its base circle: refused
        r3 = n3 * 0.05
        assert r3 - 0.1 <= r3 * math.cos(math.radians(phi)) * (1 + 1e-12) or \
            "path of contact" in exc.message, exc.message
        return
    cp, pd, mc = _hand(n2, n3, phi)
    assert lay.approach == pytest.approx(cp, rel=1e-9, abs=1e-12)
    assert lay.contact_ratio == pytest.approx(mc, rel=1e-9)
    limit = n2 * 0.05 * math.sin(math.radians(phi))
    if abs(cp - limit) > 1e-9:
        assert lay.interference == (cp > limit)


def test_the_ring_tooth_touches_the_pinion_tooth_at_p():
    pair = loads(RING.format(phi=20, n2=20, n3=72))
    lay = layout(pair)
    psi2, psi3 = mesh_phases(pair)
    ra2, ra3 = pair.outside_radii
    ring = gear_teeth(pair.driven, ra3, lay.points["O3"], psi3).reshape(-1, 2)
    pinion = gear_teeth(pair.driver, ra2, lay.points["O2"], psi2).reshape(-1, 2)
    # the flanks pass through P (sampled curves: within a fraction of the module)
    assert np.min(np.hypot(*ring.T)) < 0.02 and np.min(np.hypot(*pinion.T)) < 0.02
    # the ring's teeth point inward: every tip nearer O3 than its roots
    r = np.hypot(*(ring - np.array(lay.points["O3"])).T)
    assert r.min() == pytest.approx(ra3, rel=1e-9) and r.max() == pytest.approx(3.725)


def test_the_ring_is_drawn_with_its_teeth(tmp_path):
    out = tmp_path / "ring.svg"
    src = tmp_path / "ring.toml"
    src.write_text(RING.format(phi=20, n2=20, n3=72), encoding="utf-8")
    assert main(["draw", str(src), "-d", "gears", "-o", str(out)]) == 0
    ids = {el.get("id") for el in ET.fromstring(out.read_bytes()).iter()}
    assert {"pair-teeth-3", "action-teeth-2", "action-step-14-C"} <= ids


@pytest.mark.parametrize(("change", "key"), [
    ('kind = "internal"', None),
    ('kind = "rack"', "gears.ring.teeth"),   # a rack has no count of teeth
    ('kind = "annular"', "gears.ring.kind"),
    ('kind = "internal"\noffset = 0.01', "gears.ring.offset"),
])
def test_bad_internal_input_is_one_line(change, key, tmp_path, capsys):
    text = RING.format(phi=20, n2=20, n3=72).replace('kind = "internal"', change)
    src = tmp_path / "bad.toml"
    src.write_text(text, encoding="utf-8")
    if key is None:
        assert main(["gears", str(src)]) == 0
        capsys.readouterr()
        return
    assert main(["gears", str(src)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and key in err


def test_a_ring_smaller_than_its_pinion_and_tips_inside_the_base_circle_are_refused():
    with pytest.raises(InputError) as info:
        loads(RING.format(phi=20, n2=40, n3=30))
    assert info.value.key == "gears.ring.teeth"
    with pytest.raises(InputError) as info:
        loads(RING.format(phi=20, n2=12, n3=30))   # R3 − a = 1.4 < r3 = 1.4095
    assert info.value.key == "gears.ring.addendum"


@pytest.mark.parametrize("scale", [1 - 1e-12, 1 + 1e-12])
def test_verdicts_do_not_move_under_round_off(scale):
    """20 teeth inside 72 is just clear of interference (CP = 0.33348 < 0.34202 in)."""
    text = RING.format(phi=20, n2=20, n3=72).replace("diametral_pitch = 10",
                                                     f"diametral_pitch = {10 * scale!r}")
    lay = layout(loads(text))
    assert not lay.interference
    assert lay.contact_ratio == pytest.approx(_hand(20, 72, 20)[2], rel=1e-9)
