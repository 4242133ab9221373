"""``graphkin draw`` then ``graphkin check --drawing``: graphkin's own drawings read back exactly.

The drawn image points are compared with the analytic solver (not with the
construction that drew them): the sheet is drawn to scale, so every image
point, measured from the pole in paper units and multiplied by the scale
printed on the sheet, is the exact velocity or acceleration.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.check.drawing import _on_link, _point_name, parse_scale, read_polygons
from graphkin.cli import main
from graphkin.kinematics.analytic import solve_analytic

EXAMPLES = ["ex3_1_fourbar", "ex3_2_slider_driven", "ex3_3_inverted_slider",
            "ex4_4_coriolis_block", "ex4_7_cam_follower", "ex5_4_fivebar"]


def _exact(an: graphkin.Solution, mech: graphkin.Mechanism, label: str,
           diagram: str) -> np.ndarray | None:
    upper = {n.upper(): n for n in mech.point_names}
    name = _point_name(label, upper)
    if name in mech.helper_points:
        return None
    f = an.velocity if diagram == "velocity" else an.acceleration
    if name is not None:
        return np.asarray(f(name), dtype=float)
    on = _on_link(label, mech)
    if on is None or on[0] in mech.helper_points:
        return None
    # the point of link on[1] at on[0]: the link's rigid motion there (Eqs. 3.4, 4.5)
    st = an.links[on[1]]
    r = np.asarray(an.position(on[0])) - np.asarray(st.origin)
    w = float(st.omega)
    v = np.asarray(st.origin_velocity) + w * np.array([-r[1], r[0]])
    if diagram == "velocity":
        return v
    return (np.asarray(st.origin_acceleration) + float(st.alpha) * np.array([-r[1], r[0]])
            - w**2 * r)


@pytest.mark.parametrize("fmt", ["svg", "dxf"])
@pytest.mark.parametrize("diagram", ["velocity", "acceleration"])
@pytest.mark.parametrize("name", EXAMPLES)
def test_draw_then_check_is_exact(examples: Path, tmp_path: Path, name: str, diagram: str,
                                  fmt: str, capsys: pytest.CaptureFixture[str]) -> None:
    src = examples / f"{name}.toml"
    out = tmp_path / f"{diagram}.{fmt}"
    assert main(["draw", str(src), "-d", diagram, "-o", str(out)]) == 0
    capsys.readouterr()
    mech = graphkin.load(src)
    an = solve_analytic(mech)
    (poly,) = read_polygons(out)                 # only the polygon panel, not the mechanism
    assert poly.diagram == diagram
    kind = "velocity" if diagram == "velocity" else "acceleration"
    per, _, _ = parse_scale(poly.scale or "", kind, mech.length_unit, poly.unit)
    exacts = [_exact(an, mech, lab, diagram) for lab in poly.points]
    size = max(float(np.hypot(*e)) for e in exacts if e is not None)
    checked = 0
    for lab, xy in poly.points.items():
        exact = _exact(an, mech, lab, diagram)
        if exact is None:
            continue                              # slot-definition points
        drawn = (np.asarray(xy) - np.asarray(poly.pole)) * per
        # SVG coordinates carry 6 decimals of a point (1/72 in): 1e-6 of the polygon's size
        np.testing.assert_allclose(drawn, exact, atol=1e-6 * size)
        checked += 1
    assert checked >= 1
    # and the command agrees: every image point within tolerance, exit 0
    assert main(["check", str(src), "--drawing", str(out)]) == 0
    text = capsys.readouterr().out
    assert f"{checked} of {checked} within tolerance" in text
    assert "WRONG" not in text and "ignored" not in text


@pytest.mark.parametrize("name", ["ex3_1_fourbar", "ex3_3_inverted_slider"])
def test_the_whole_sheet_is_read_panel_by_panel(examples: Path, tmp_path: Path, name: str,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    """``draw`` without ``-d``: every panel on one sheet; only the two polygons are read."""
    src = examples / f"{name}.toml"
    out = tmp_path / "sheet.svg"
    assert main(["draw", str(src), "-o", str(out)]) == 0
    polys = read_polygons(out)
    assert sorted(p.diagram for p in polys) == ["acceleration", "velocity"]
    assert all(p.scale for p in polys)            # each panel's own scale, not a fit
    capsys.readouterr()
    assert main(["check", str(src), "--drawing", str(out)]) == 0
    text = capsys.readouterr().out
    assert "not turned" in text and "WRONG" not in text
