"""Layer 2: the artists themselves, their gids and coordinates, against independent values.

The exact values come from the analytic solver (Newton-Raphson on the
loop-closure equations, graphkin.kinematics.analytic) or from a hand
derivation given in the comment; never from the drawing code's own output.
"""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest
from matplotlib.figure import Figure
from numpy.testing import assert_allclose

from graphkin.render import DiagramUnavailable, draw
from graphkin.render.style import HIGHLIGHT

FOURBAR = "ex3_1_fourbar"


def xy(artist) -> np.ndarray:
    return np.asarray(artist.get_xydata(), dtype=float)


def test_posture_points_sit_at_their_exact_positions(gk):
    d = gk.drawn(FOURBAR, "posture")
    # Example 3.1: B = A + 4 in (cos 120°, sin 120°) = (-2, 2√3) by hand
    assert_allclose(xy(d["B"])[0], [-2.0, 2 * math.sqrt(3)], atol=1e-12)
    ex = gk.exact(FOURBAR)
    for name in ("C", "E", "F"):
        assert_allclose(xy(d[name])[0], ex.position(name), atol=1e-9)


def test_case4_arcs_are_swung_about_the_known_points_through_C(gk):
    d = gk.drawn(FOURBAR, "posture")
    arc = d["k_C(B)"]
    assert_allclose(arc.center, [-2.0, 2 * math.sqrt(3)], atol=1e-12)
    assert arc.width / 2 == pytest.approx(18.0)  # BC = 18 in (Example 3.1)
    c = gk.exact(FOURBAR).position("C")
    phi = math.degrees(math.atan2(c[1] - arc.center[1], c[0] - arc.center[0]))
    assert arc.theta1 < phi < arc.theta2
    assert d["k_C(D)"].width / 2 == pytest.approx(11.0)  # DC = 11 in


def test_velocity_vectors_equal_the_analytic_velocities(gk):
    d = gk.drawn(FOURBAR, "velocity")
    ex = gk.exact(FOURBAR)
    pole = xy(d["o_v"])[0]
    # V_B = ω2 k × R_BA with ω2 = 900 rev/min = 30π rad/s, R_BA = (-2, 2√3): by hand
    vb = 30 * math.pi * np.array([-2 * math.sqrt(3), -2.0])
    assert_allclose(xy(d["v(B)"])[0] - pole, vb, rtol=1e-12)
    for name in ("C", "E", "F"):
        arrow = d[f"v({name}):abs"]
        assert_allclose(arrow.tail, pole, atol=1e-9)
        assert_allclose(arrow.tip - arrow.tail, ex.velocity(name), rtol=1e-9)


def test_velocity_construction_lines_are_perpendicular_to_the_links(gk):
    d = gk.drawn(FOURBAR, "velocity")
    sol = gk.solved(FOURBAR)
    b, c, dd = (np.asarray(sol.position(n)) for n in "BCD")
    for key, link in (("⊥CB:v", c - b), ("⊥CD:v", c - dd)):
        p = xy(d[key])
        direction = p[-1] - p[0]
        assert abs(direction @ link) <= 1e-9 * np.linalg.norm(direction) * np.linalg.norm(link)


def test_acceleration_normal_component_is_V_squared_over_R_toward_B(gk):
    d = gk.drawn(FOURBAR, "acceleration")
    ex = gk.exact(FOURBAR)
    r_cb = ex.position("C") - ex.position("B")
    v_cb = ex.velocity("C") - ex.velocity("B")
    # A_CB^n = -(V_CB² / R_CB) R̂_CB (Eq. 4.7): from C toward B
    want = -(v_cb @ v_cb) / (r_cb @ r_cb) * r_cb
    arrow = d["A_CB^n"]
    assert_allclose(arrow.tip - arrow.tail, want, rtol=1e-9)
    # it starts at the image b' and the total gives A_C
    pole = xy(d["o_a"])[0]
    assert_allclose(arrow.tail - pole, ex.acceleration("B"), rtol=1e-9)
    assert_allclose(xy(d["a(C)"])[0] - pole, ex.acceleration("C"), rtol=1e-9)


def test_right_angle_mark_where_the_tangential_direction_was_drawn(gk):
    d = gk.drawn(FOURBAR, "acceleration")
    group = next(g for gid, g in d.groups.items() if gid.endswith("CB_a"))
    tip = d["A_CB^n"].tip
    marks = [c for c in group.children if hasattr(c, "get_xydata") and len(c.get_xydata()) == 3]
    assert marks, "no right-angle mark"
    corner_dist = min(np.linalg.norm(m.get_xydata() - tip, axis=1).min() for m in marks)
    assert corner_dist < np.linalg.norm(d["A_CB^n"].tip - d["A_CB^n"].tail)


def test_image_letters_follow_the_book(gk):
    v = gk.drawn(FOURBAR, "velocity")
    a = gk.drawn(FOURBAR, "acceleration")
    assert v.texts["v(C)"].get_text() == "c"
    assert a.texts["a(C)"].get_text() == "c′"
    assert v.texts["o_v"].get_text() == "$O_V$"
    cam = gk.drawn("ex4_7_cam_follower", "velocity")
    assert cam.texts["v(B@3)"].get_text() == "b₃"  # the point of link 3 at B


def test_every_step_of_each_construction_has_its_group(gk):
    sol = gk.solved(FOURBAR)
    for diagram in ("posture", "velocity", "acceleration"):
        d = gk.drawn(FOURBAR, diagram)
        ids = {s.step_id for s in sol.constructions[diagram]}
        assert ids <= set(d.groups)


def test_upto_draws_only_the_first_steps_and_the_links_already_found(gk):
    sol = gk.solved(FOURBAR)
    cx = sol.constructions["posture"]
    k = next(s.index for s in cx if s.label == "C")
    d = draw(sol, "posture", upto=k, table=False)
    ids = {s.step_id for s in cx}
    assert {s.step_id for s in cx.steps[: k + 1]} <= set(d.groups)
    assert not (ids - {s.step_id for s in cx.steps[: k + 1]}) & set(d.groups)
    # link 3 carries E, which is laid off later: not drawn yet; link 2 is
    assert "link-3" not in d.groups and "link-2" in d.groups
    full = gk.drawn(FOURBAR, "posture")
    assert "link-3" in full.groups


def test_highlighted_step_is_drawn_in_the_highlight_colour(gk):
    sol = gk.solved(FOURBAR)
    cx = sol.constructions["velocity"]
    k = next(s.index for s in cx if s.label == "v(C)")
    d = draw(sol, "velocity", upto=k, highlight=k, table=False)
    group = d.groups[cx[k].step_id]
    colours = {c.get_color() for c in group.children if hasattr(c, "get_color")}
    assert HIGHLIGHT in colours
    other = d.groups[cx[k - 1].step_id]
    assert HIGHLIGHT not in {c.get_color() for c in other.children if hasattr(c, "get_color")}


def test_point_at_infinity_is_an_arrow_at_the_panel_edge_marked_infinity(gk):
    d = gk.drawn("ex3_2_slider_driven", "centers")
    arrow = d["I14"]  # the slider on the frame: I14 at infinity, perpendicular to the slide
    direction = arrow.tip - arrow.tail
    assert abs(direction[0]) <= 1e-9 * abs(direction[1])  # the slide is horizontal
    ax = arrow.axes
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    assert x0 <= arrow.tip[0] <= x1 and y0 <= arrow.tip[1] <= y1
    assert min(arrow.tip[1] - y0, y1 - arrow.tip[1]) < 0.25 * (y1 - y0)
    assert "∞" in d.texts["I14"].get_text()


def test_panels_are_drawn_to_their_stated_scale(gk):
    d = gk.drawn(FOURBAR, "velocity")
    for panel in d.sheet.panels:
        ax = next(a for a in d.figure.axes if a.get_gid() == f"panel-{panel.name}")
        w_in = ax.get_position().width * d.figure.get_size_inches()[0]
        x0, x1 = ax.get_xlim()
        assert (x1 - x0) / w_in == pytest.approx(panel.scale.per_inch, rel=1e-9)
    # a round scale: 1 in = 200 in/s would be 2.5 × 80...; what is stated is a 1-2-2.5-5 number
    vel = d.sheet.panel("velocity").scale
    mantissa = vel.value / 10 ** math.floor(math.log10(vel.value))
    assert mantissa in (1.0, 2.0, 2.5, 5.0)


def test_results_table_lists_the_analytic_values(gk):
    d = gk.drawn(FOURBAR, "velocity")
    rows = {r.key: r for r in d.sheet.rows}
    # Example 3.1: ω3 = 25.382 rad/s ccw, ω4 = 49.501 rad/s ccw (analytic, p. 123 of the book)
    assert rows["omega3"].exact_value[0] == pytest.approx(25.382, abs=1e-3)
    assert rows["omega4"].exact_value[0] == pytest.approx(49.501, abs=1e-3)
    assert all(r.diff is not None and r.diff < 1e-9 for r in d.sheet.rows)


def test_draw_into_given_axes_and_no_rates_is_refused(gk):
    fig = Figure(figsize=(5, 5))
    ax = fig.add_subplot()
    d = draw(gk.solved(FOURBAR), "velocity", ax=ax)
    assert d["v(C)"].axes is ax
    assert_allclose(xy(d["v(C)"])[0] - xy(d["o_v"])[0], gk.exact(FOURBAR).velocity("C"),
                    rtol=1e-9)
    with pytest.raises(DiagramUnavailable, match="no rates"):
        draw(gk.solved("ex2_5_open"), "velocity")


def test_library_uses_no_pyplot_and_graphkin_does_not_import_matplotlib(gk):
    code = (
        "import sys, graphkin\n"
        "assert 'matplotlib' not in sys.modules\n"
        "import graphkin.kinematics\n"
        "assert 'matplotlib' not in sys.modules\n"
        "from graphkin.render import draw, to_bytes\n"
        "m = graphkin.loads('[links.1]\\nA=[0,0]\\nD=[3,0]\\n[links.2]\\nA=[0,0]\\nB=[1,0]\\n"
        "[links.3]\\nB=[0,0]\\nC=[3,0]\\n[links.4]\\nD=[0,0]\\nC=[2,0]\\n[drive]\\nlink=2\\n"
        "angle=60\\n')\n"
        "to_bytes(draw(m, 'posture').figure)\n"
        "assert 'matplotlib.pyplot' not in sys.modules\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_a_rod_whose_other_point_only_defines_its_slide_is_drawn_along_the_slide(gk):
    # Example 4.4: rod 2 turns about O2 and carries the slide of block 3 (A at 500 mm along
    # it); its only other point, X, defines the slide and is no body corner.  The rod must
    # still be drawn, from its pivot out past the block: its outline reaches at least |O2A|
    from matplotlib.patches import Polygon as MplPolygon

    sol = gk.solved("ex4_4_coriolis_block")
    d = draw(sol, "posture", table=False)
    rod = d.groups["link-2"]
    polys = [a for a in rod.get_children() if isinstance(a, MplPolygon)]
    assert polys, "rod 2 is drawn as a body"
    xy = np.vstack([p.get_xy() for p in polys])
    o2 = np.asarray(sol.position("O2"), dtype=float)
    a = np.asarray(sol.position("A", "3"), dtype=float)
    reach = np.max(np.hypot(*(xy - o2).T))
    assert reach >= 0.95 * float(np.hypot(*(a - o2)))
