"""A translating flat-face cam in a mechanism is solved by the constructions (Sec. 4.7).

Its equivalent linkage (Example 4.7) is a Scotch yoke: the cam's center of
curvature K (a point of the cam, which turns) runs in a slot of the follower
parallel to its face, and the follower translates on the frame's guide.  The
follower keeps its angle, so each of its points has two straight paths: along
the guide, and parallel to the slot through K (Sec. 2.8, case 3).  The oracles
are the analytic (Newton) solver, which builds none of the constructions, and
the cam's program differentiated by hand: V = y'Θ̇, A = y''Θ̇² + y'Θ̈ (Eq. 6.11).
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np
from cam_strategies import cam_toml, cams
from hypothesis import given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.cams import FollowerKind
from graphkin.cams.equivalent import equivalent_toml
from graphkin.errors import InputError
from graphkin.kinematics.analytic.posture import solve_analytic
from graphkin.mechanisms import from_dict

ROOT = Path(__file__).resolve().parents[2]
_TMP = Path(tempfile.mkdtemp(prefix="graphkin-cam-tff-"))


def _agree(sol: graphkin.Solution, mech: graphkin.Mechanism, size: float, big: float) -> None:
    """Every link's angle, ω, α and every point's R, V, A: construction = analytic, 1e-9."""
    ref = solve_analytic(mech)
    for lid, link in mech.links.items():
        for q in ("omega", "alpha"):
            a, b = float(getattr(sol, q)(lid)), float(getattr(ref, q)(lid))
            assert abs(a - b) < 1e-9 * big, (lid, q, a, b)
        for name in link.points:
            for q, s in (("position", size), ("velocity", size * big),
                         ("acceleration", size * big)):
                a, b = getattr(sol, q)(name, lid), getattr(ref, q)(name, lid)
                assert float(np.hypot(*(np.asarray(a) - np.asarray(b)))) < 1e-9 * s, \
                    (lid, name, q, a, b)


@settings(max_examples=30, deadline=None)
@given(cams(kinds=(FollowerKind.FLAT_FACE,)), st.floats(0.0, 360.0, exclude_max=True),
       st.floats(-20.0, 20.0), st.floats(-50.0, 50.0), st.sampled_from([90.0, 0.0, 210.0]))
def test_random_translating_flat_faces_are_constructed(cam, theta2, omega, alpha, axis):
    """Any translating flat face, cam angle, rates and guide direction: both polygons,
    equal to Newton's solution and to the program's y'Θ̇ and y''Θ̇² + y'Θ̈."""
    path = _TMP / f"cam-{abs(hash(cam_toml(cam)))}.toml"
    path.write_text(cam_toml(cam))
    theta = cam.s * math.radians(theta2 - (axis - 90.0))
    if not np.isfinite(graphkin.cams.profile(cam, [theta]).contact[0]):
        return
    try:
        mech = from_dict({"units": "mm", "links": {"1": {"O2": [3.0, -2.0]}},
                          "cams": {"link": 2, "follower": 4, "file": str(path), "axis": axis},
                          "drive": {"link": 2, "angle": theta2, "omega": omega,
                                    "alpha": alpha}})
    except InputError as exc:     # a straight piece of surface: no center of curvature
        assert "straight" in str(exc), str(exc)
        return
    sol = mech.solve()
    assert sol.method == "construction", sol.notes
    size = cam.prime + abs(cam.program.lift)
    big = max(1.0, omega**2, abs(alpha))
    _agree(sol, mech, size, big)
    k = cam.program.evaluate([theta])
    dth, ddth = cam.s * omega, cam.s * alpha
    d = np.array([math.cos(math.radians(axis)), math.sin(math.radians(axis))])
    vt, at = np.asarray(sol.velocity("T4")), np.asarray(sol.acceleration("T4"))
    assert abs(float(vt @ d) - k.y1[0] * dth) < 1e-9 * size * big
    assert abs(float(at @ d) - (k.y2[0] * dth**2 + k.y1[0] * ddth)) < 1e-9 * size * big


@settings(max_examples=20, deadline=None)
@given(cams(kinds=(FollowerKind.FLAT_FACE,)), st.floats(0.0, 2 * math.pi, exclude_max=True))
def test_the_equivalent_linkage_file_is_constructed(cam, theta):
    """``graphkin cam --equivalent``'s file of a translating flat face: the constructions."""
    try:
        mech = graphkin.loads(equivalent_toml(cam, theta))
    except InputError as exc:
        assert "straight" in str(exc), str(exc)
        return
    sol = mech.solve()
    assert sol.method == "construction", sol.notes
    _agree(sol, mech, cam.prime + abs(cam.program.lift), max(1.0, (cam.omega or 1.0) ** 2))


def test_example_6_3_drives_a_rod_and_a_slider_by_the_constructions(tmp_path):
    """examples/cams/cam_mechanism.toml with Example 6.3's flat face (gallery/cams)."""
    text = (ROOT / "examples" / "cams" / "cam_mechanism.toml").read_text()
    (tmp_path / "ex6_3_flat_face.toml").write_text(
        (ROOT / "gallery" / "cams" / "ex6_3_flat_face.toml").read_text())
    (tmp_path / "m.toml").write_text(text.replace("ex6_6_roller.toml", "ex6_3_flat_face.toml"))
    mech = graphkin.load(tmp_path / "m.toml")
    sol = mech.solve()
    assert sol.method == "construction", sol.notes
    _agree(sol, mech, 100.0, 100.0)
