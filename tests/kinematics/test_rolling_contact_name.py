"""A rolling contact's point is named so that it cannot collide with the file's points.

Defect of the session-7 audit: the point of contact was always lettered "C" on
drawings and in the steps' labels (``A_GC^n``, ``⊥GC:v``), so a user's own pin C
or a second contact was drawn and named twice.  The book names the point of
rolling contact C (Example 4.8, V_C4 = V_C3) or P (Sec. 3.7, Fig. 3.14, P2 = P3);
graphkin keeps C and takes P, then C1, C2 ... only when C is taken
(docs/formats/mechanism.md, "Rolling contact").
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import numpy as np
import pytest

import graphkin
from graphkin.mechanisms.names import contact_names

# Example 3.9's wheel (radius 100 on the ground y = 0), its pin named C instead of B
WHEEL_C = """
units = "mm"
[links.1]
O2 = [0, 0]
G1 = [0, 0]
G2 = [1, 0]
[links.2]
O2 = [0, 0]
A = [150, 0]
[links.3]
A = [0, 0]
C = [200, 0]
[links.4]
G = [0, 0]
C = [0, 50]
[[rolling]]
link = 4
on = 1
circle = { center = "G", radius = 100 }
line = ["G1", "G2"]
side = "left"
[drive]
link = 2
angle = 90
omega = "10 rad/s"
alpha = 0
[assembly]
C = [200, 150]
"""


def test_contact_names_never_repeat_a_point_or_each_other() -> None:
    taken = {"C", "P", "C1", "A"}
    names = contact_names(3, taken)
    assert names == ["C2", "C3", "C4"]
    assert contact_names(2, set()) == ["C", "P"]


def test_a_users_pin_c_and_the_contact_point_are_two_points() -> None:
    """Hand solution at θ2 = 90°: A = (0, 150), V_A = ω2 × R_A = (-1500, 0) mm/s.  The
    coupler AC is horizontal (C = (200, 150)) and V_C is horizontal too (C is straight
    above the contact I14 = (200, 0), the wheel's center of rotation), so the coupler
    translates: ω3 = 0, V_C = V_A.  Then ω4 = -V_Cx / 150 = 10 rad/s ccw and
    V_G = (-ω4 · 100, 0) = (-1000, 0) mm/s."""
    mech = graphkin.loads(WHEEL_C)
    assert [r.contact_name for r in mech.rolling] == ["P"]
    sol = mech.solve()
    np.testing.assert_allclose(sol.velocity("C"), [-1500.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(sol.velocity("G"), [-1000.0, 0.0], atol=1e-9)
    assert float(sol.omega(4)) == pytest.approx(10.0, rel=1e-12)
    assert float(sol.omega(3)) == pytest.approx(0.0, abs=1e-12)
    from graphkin.render import draw, to_bytes

    root = ET.fromstring(to_bytes(draw(sol, "posture").figure))
    texts = {}
    for g in root.iter("{http://www.w3.org/2000/svg}g"):
        gid = g.get("id", "")
        if gid.startswith("label-"):
            texts[gid] = "".join(g.itertext()).strip()
    assert texts["label-C"] == "C"
    contact = [t for gid, t in texts.items() if gid.startswith("label-rolling_0")]
    assert contact == ["P"]
    # the steps' labels are the contact's: A_P4/1^r, not a second A_C...
    labels = [o for s in sol.constructions["acceleration"].steps for o in s.outputs]
    assert "A_P4/1^r" in labels and not any(lab.startswith("A_C4/") for lab in labels)
    assert len(labels) == len(set(labels))


def test_two_contacts_are_c_and_p() -> None:
    """Example 11.7's planet meshes with the sun and the ring: two contacts, C and P."""
    from spec_data import ROOT

    mech = graphkin.load(ROOT / "gallery" / "gears" / "ex11_7.toml")
    assert [r.contact_name for r in mech.rolling] == ["C", "P"]
    assert len({r.contact_label for r in mech.rolling}) == 2
