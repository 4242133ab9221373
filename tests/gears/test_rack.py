"""A pinion in mesh with a rack (``kind = "rack"``, Sec. 7.5 Fig. 7.10, Sec. 7.7).

The independent checks, derived by hand:

* the rack is a gear of infinite radius, so Eq. (7.10) becomes, as R3 → ∞,
  ``CP = (2 R3 a + a²) / (√((R3 + a)² − R3² cos² φ) + R3 sin φ) → a / sin φ``
  (C on the addendum line, a above the pitch line, on a line at φ to it);
  PD is Eq. (7.11) unchanged; ``m_c = (CP + PD) / (π m cos φ)`` (Eqs. 7.6, 7.9);
* interference (Eq. 7.12, CP > R2 sin φ) is ``a / sin φ > (N m / 2) sin φ``,
  i.e. ``N < 2 (a/m) / sin² φ``: 18 teeth for 20° full depth (17.097...),
  32 for 14.5° (31.9...);
* a very large gear (N3 = 10 000) nearly is a rack: its CP agrees to O(m/R3).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin.cli import main
from graphkin.gears import Gear, GearPair, layout
from graphkin.gears.file import load, loads
from graphkin.gears.tooth import GearKind
from graphkin.render.gears import draw_gears

from .test_drawing import _check

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "gears" / "prob7_19.toml"

RACK = """units = "mm"
module = {m}
pressure_angle = {phi}
system = "{system}"
[gears.pinion]
teeth = {n}
[gears.rack]
kind = "rack"
"""


def _pair(n: int, phi: float, m: float = 2.0, system: str = "full depth") -> GearPair:
    return loads(RACK.format(n=n, phi=phi, m=m, system=system))


def _hand(n: int, phi_deg: float, m: float, k: float) -> tuple[float, float, float]:
    """CP, PD and m_c of a pinion and a rack from the equations (module docstring)."""
    phi = math.radians(phi_deg)
    r = n * m / 2
    cp = k * m / math.sin(phi)
    pd = math.sqrt((r + k * m) ** 2 - (r * math.cos(phi)) ** 2) - r * math.sin(phi)
    return cp, pd, (cp + pd) / (math.pi * m * math.cos(phi))


@settings(max_examples=40, deadline=None)
@given(st.integers(8, 400), st.floats(14.5, 30.0), st.floats(0.1, 20.0),
       st.sampled_from(["full depth", "stub"]))
def test_contact_ratio_by_construction_is_the_rack_form_of_eq_7_9(n, phi, m, system):
    lay = layout(_pair(n, phi, m, system))
    k = 1.0 if system == "full depth" else 0.8
    cp, pd, mc = _hand(n, phi, m, k)
    assert lay.approach == pytest.approx(cp, rel=1e-9)
    assert lay.recess == pytest.approx(pd, rel=1e-9)
    assert lay.contact_ratio == pytest.approx(mc, rel=1e-9)
    # the rack does not turn: α3 = β3 = 0; the pinion's angles are CP/r2, PD/r2 (Eqs. 7.7-7.8)
    r2 = n * m / 2 * math.cos(math.radians(phi))
    assert lay.approach_angles == pytest.approx((cp / r2, 0.0), rel=1e-9)
    # interference exactly when N < 2k / sin² φ (clearly away from the limit)
    limit = 2 * k / math.sin(math.radians(phi)) ** 2
    if abs(n - limit) > 1e-6:
        assert lay.interference == (n < limit)
        assert lay.end.value == "inside"   # the rack's B is at infinity


@pytest.mark.parametrize(("phi", "least"), [(20.0, 18), (14.5, 32), (25.0, 12)])
def test_the_fewest_teeth_without_interference(phi, least, capsys):
    # 2/sin²φ: 17.097 (20°), 31.9 (14.5°), 11.198 (25°)
    assert layout(_pair(least, phi)).interference is False
    assert layout(_pair(least - 1, phi)).interference is True
    for scale in (1 - 1e-12, 1 + 1e-12):   # the verdict does not move with round-off
        assert layout(_pair(least, phi, 2.0 * scale)).interference is False


def test_a_very_large_gear_is_nearly_a_rack():
    m, phi = 2.0, math.radians(20)
    g2 = Gear("pinion", 2, 20, m, phi, m, 1.25 * m, clearance=0.25 * m)
    big = Gear("gear", 3, 10_000, m, phi, m, 1.25 * m, clearance=0.25 * m)
    rack = Gear("rack", 3, 0, m, phi, m, 1.25 * m, clearance=0.25 * m, kind=GearKind.RACK)
    near, exact = layout(GearPair(g2, big)), layout(GearPair(g2, rack))
    assert near.approach == pytest.approx(exact.approach, rel=1e-3)
    assert near.recess == pytest.approx(exact.recess, rel=1e-12)


@pytest.mark.parametrize("n", [26, 12])   # Problem 7.19's pinion; 12 teeth interfere (Fig. 7.25)
def test_the_rack_drawing_reads_back(n):
    lay = layout(_pair(n, 20.0, 0.5) if n != 26 else load(EXAMPLE))
    ids = _check(lay, draw_gears(lay))
    # the rack's pitch, addendum and dedendum lines are named; its B is not drawn
    for which in ("tangent", "addendum3", "dedendum3"):
        assert "action-" + lay.construction.step_of(which).step_id in ids
    assert "B" not in lay.points
    assert ("action-undercut-2" in ids) == lay.interference


def test_cli_gears_json_draw_and_steps(tmp_path, capsys):
    assert main(["gears", str(EXAMPLE), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    mesh = data["mesh"]
    cp, pd, mc = _hand(26, 20.0, 0.5, 1.0)
    assert mesh["kind"] == "rack" and mesh["center_distance"] is None
    assert mesh["contact_ratio_eq_7_9"] == pytest.approx(mc, rel=1e-12)
    assert mesh["contact_ratio"] == pytest.approx(mc, rel=1e-9)
    # the rack moves R2 per radian of the pinion; contact moves r2 = R2 cos φ along AB
    assert mesh["rack_approach"] == pytest.approx(cp / math.cos(math.radians(20)), rel=1e-9)
    assert data["gears"]["rack"]["pitch_radius"] is None
    assert main(["gears", str(EXAMPLE)]) == 0
    assert "a/sin φ" in capsys.readouterr().out
    assert main(["draw", str(EXAMPLE), "-d", "gears", "-o", str(tmp_path / "r.svg")]) == 0
    assert main(["steps", str(EXAMPLE), "-d", "gears", "-o", str(tmp_path / "r.html")]) == 0
    assert "pitch line of the rack" in (tmp_path / "r.html").read_text(encoding="utf-8")


@pytest.mark.parametrize(("change", "key"), [
    ('[gears.rack]\nkind = "rack"\nteeth = 40', "gears.rack.teeth"),
    ('[gears.rack]\nkind = "rack"\noffset = 0.1', "gears.rack.offset"),
    ('[gears.rack]\nkind = "rack"\n[gears.third]\nteeth = 3', "gears"),
    ('center_distance = 30\n[gears.rack]\nkind = "rack"', "center_distance"),
])
def test_bad_rack_input_is_one_line(change, key, tmp_path, capsys):
    text = RACK.format(n=20, phi=20, m=2, system="full depth").replace(
        '[gears.rack]\nkind = "rack"', change)
    if change.startswith("center_distance"):
        text = "center_distance = 30\n" + RACK.format(n=20, phi=20, m=2, system="full depth")
    src = tmp_path / "bad.toml"
    src.write_text(text, encoding="utf-8")
    assert main(["gears", str(src)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and key in err and "bad.toml" in err


def test_a_rack_cannot_drive(tmp_path, capsys):
    src = tmp_path / "bad.toml"
    src.write_text('module = 2\npressure_angle = 20\n[gears.rack]\nkind = "rack"\n'
                   '[gears.pinion]\nteeth = 20\n', encoding="utf-8")
    assert main(["gears", str(src)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "gears.rack.kind" in err
