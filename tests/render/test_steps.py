"""The teaching page: steps told in the book's words, with their numbers, equations and drawings.

The numbers are checked against hand derivations from the textbook's data
(Example 3.1: ω2 = 900 rev/min, R_BA = 4 in, R_CB = 18 in; Example 4.4:
ω2 = 50 rad/s, V_A3/2 = 30 m/s) and against the independent analytic solver.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from spec_data import EXAMPLES

import graphkin
from graphkin.cli import main
from graphkin.render.narrate import PageStep, narrate, plain
from graphkin.render.sources import as_source
from graphkin.render.teach import FRAME_INCHES, _scale_of, steps_html, write_frames

NAME = "ex2_5_open"  # the smallest construction (Example 2.5: two arcs, case 4)

#: what a step label looks like inside graphkin, never in a heading
INTERNAL = re.compile(r"\S:\S|[>⊥∥@\[\]]|\b[va]\(|\bdds?\d|\bo_[va]\b|\bk_|\^[ntcr]\b(?!_)")

RATED = sorted(p.stem for p in EXAMPLES.glob("*.toml")
               if p.stem != "expected" and graphkin.load(p).has_rates)


def _told(gk, name: str, diagram: str) -> list[PageStep]:
    """The page's narration, at the scale the page draws at."""
    src = as_source(gk.solved(name))
    return narrate(src, diagram, _scale_of(src, diagram, FRAME_INCHES))


def _numbers(text: str) -> list[float]:
    return [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", plain(text))]


@pytest.mark.parametrize("name", RATED)
@pytest.mark.parametrize("diagram", ["velocity", "acceleration"])
def test_every_step_reads_like_the_book(gk, name, diagram):
    told = _told(gk, name, diagram)
    assert told
    for ps in told:
        title = plain(ps.title)
        # a title in words, never an internal id ("R_CD:D>C", "a(C):nB", "dds3")
        assert not INTERNAL.search(title.replace("^n_", "_").replace("^t_", "_")
                                   .replace("^c_", "_").replace("^r_", "_")), title
        assert re.match(r"[A-Z]", title), title
        assert ps.text and ps.refs.startswith("Sec."), (title, ps.refs)
        if ps.vector:
            # every step that finds or uses a vector shows its equation (or formula) ...
            assert ps.equation_text(), title
            # ... and the numbers
            assert ps.numbers, title
        if ps.sides and len(ps.sides) == 3:
            # two lines meet: the left side is there, both unknown (??)
            (lhs,) = ps.sides[0]
            assert (str(lhs.magnitude), str(lhs.direction)) == ("?", "?")


def test_helper_points_get_no_step(gk):
    for name, helpers in (("ex4_4_coriolis_block", {"X"}), ("ex3_3_inverted_slider",
                                                            {"L1", "L2"}),
                          ("ex4_7_cam_follower", {"S1", "S2"})):
        sol = gk.solved(name)
        assert sol.mechanism.helper_points == helpers
        for diagram in ("velocity", "acceleration"):
            told = _told(gk, name, diagram)
            cx = sol.constructions[diagram]
            covered = {i for ps in told for i in ps.steps}
            for s in cx:
                for o in s.outputs:
                    if o[:2] in ("v(", "a(") and o[2:-1] in helpers:
                        assert s.index not in covered, (name, o)
            for ps in told:
                assert not any(re.search(rf"\b{h}\b", plain(ps.title)) for h in helpers)


def test_fourbar_numbers_are_the_books(gk):
    """Example 3.1 / 4.2: the numbers of the velocity and acceleration pages."""
    exact = gk.exact("ex3_1_fourbar")
    told = {plain(ps.title): ps for ps in _told(gk, "ex3_1_fourbar", "velocity")}
    # V_B = ω2 R_BA = (900·2π/60 rad/s)(4/12 ft) = 31.42 ft/s (the book: 31.4 ft/s)
    vb = told["Velocity of B: V_B = V_A + V_BA"]
    w2 = 900 * 2 * math.pi / 60
    assert any(abs(x - w2 * 4 / 12) < 0.01 for x in _numbers(" ".join(vb.numbers)))
    assert "4/12 ft" in " ".join(vb.numbers)
    # ω3 as the analytic solver finds it
    w3 = float(exact.omega(3))
    step = next(ps for t, ps in told.items() if t.startswith("Angular velocity of link 3"))
    assert any(abs(x - abs(w3)) < 0.01 for x in _numbers(step.numbers[-1]))
    # A^n_CB = V_CB²/R_CB with V_CB from the analytic solver and R_CB = 18 in = 1.5 ft
    vcb = float(np.hypot(*(exact.velocity("C") - exact.velocity("B")))) / 12
    acc = {plain(ps.title): ps for ps in _told(gk, "ex3_1_fourbar", "acceleration")}
    an = acc["Normal component A^n_CB = V_CB²/R_CB"]
    line = plain(an.numbers[0])
    assert "18/12 ft" in line
    assert abs(_numbers(line.split("=")[-1])[0] - vcb**2 / 1.5) < 0.5
    # and the length laid off on the drawing, at the scale stated
    src = as_source(gk.solved("ex3_1_fourbar"))
    from graphkin.render.sheet import build_sheet

    scale = build_sheet(src, "acceleration", table=False).panel("acceleration").scale
    an2 = next(ps for ps in narrate(src, "acceleration", scale)
               if plain(ps.title).startswith("Normal component A^n_CB"))
    inches = _numbers(plain(an2.numbers[1]).split("lay off")[1])[0]
    assert inches == pytest.approx(vcb**2 / 1.5 / (scale.value * scale.factor / 12), rel=2e-3)


def test_coriolis_gets_its_own_step_and_says_which_omega(gk):
    """Example 4.4: A^c = 2 ω2 V_A3/2 = 2 (50 rad/s)(30 m/s) = 3000 m/s² (the book: 3000)."""
    sol = gk.solved("ex4_4_coriolis_block")
    told = _told(gk, "ex4_4_coriolis_block", "acceleration")
    (cor,) = [ps for ps in told if plain(ps.title).startswith("Coriolis")]
    assert plain(cor.title) == "Coriolis component A^c_A3A2 = 2ω2 × V_A3/2"
    assert "ω2, the angular velocity of the link that carries the path" in plain(cor.text)
    assert abs(_numbers(plain(cor.numbers[1]).split("=")[-1].split(";")[0])[0] - 3000) < 0.5
    # its own drawing element: the step that lays the component off is part of it
    cx = sol.constructions["acceleration"]
    ops = {cx[i].op for i in cor.steps}
    assert ops == {"coriolis", "translate"}
    # the inverted slider-crank (Example 4.6): ω4 of the rod that carries the path
    told = _told(gk, "ex3_3_inverted_slider", "acceleration")
    (cor,) = [ps for ps in told if plain(ps.title).startswith("Coriolis")]
    assert plain(cor.title) == "Coriolis component A^c_A3A4 = 2ω4 × V_A3/4"


def test_rolling_contact_gets_its_own_step():
    told = narrate(as_source(graphkin.examples.rolling_wheel().solve()), "acceleration")
    (roll,) = [ps for ps in told if plain(ps.title).startswith("Rolling contact")]
    assert "Eq. 4.19" in roll.refs and roll.sides is not None


@pytest.fixture(scope="module")
def fourbar_page(gk) -> str:
    return steps_html(gk.solved("ex3_1_fourbar"), "acceleration")


def test_page_marks_answers_and_works_without_js(gk, fourbar_page):
    page = fourbar_page
    told = _told(gk, "ex3_1_fourbar", "acceleration")
    sections = re.findall(r'<section class="step[^"]*"[^>]*>', page)
    assert len(sections) == len(told) + 1  # and the results table
    assert not any(" hidden" in s for s in sections)  # all shown without JavaScript
    assert "⟦" not in page and page.count('<span class="answer">') >= len(
        [n for ps in told for n in ps.numbers if "⟦" in n])
    assert "@media print" in page
    assert not re.search(r'\b(src|href)="(https?:)?//', page)
    assert "<script src" not in page and "<link " not in page
    # the drawing's found rates hide with the answers
    assert '.hide-answers [id$="label-α3"]' in page


def test_one_section_per_step_with_its_drawing(gk):
    page = steps_html(gk.solved(NAME), "posture")
    told = narrate(as_source(gk.solved(NAME)), "posture")
    assert len(re.findall(r"<svg[\s>]", page)) == len(told)
    cx = gk.solved(NAME).constructions["posture"]
    last = len(told) - 1
    for s in cx:
        assert f'id="f{last:02d}-{s.step_id}"' in page


def test_frames_are_numbered_svgs(gk, tmp_path):
    paths = write_frames(gk.solved(NAME), "posture", tmp_path / "frames")
    cx = gk.solved(NAME).constructions["posture"]
    assert [p.name for p in paths] == [f"step-{k:02d}.svg" for k in range(len(cx))]
    last = ET.parse(paths[-1]).getroot()
    ids = {el.get("id") for el in last.iter()}
    assert {s.step_id for s in cx} <= ids
    first = {el.get("id") for el in ET.parse(paths[0]).getroot().iter()}
    assert cx[0].step_id in first and cx[-1].step_id not in first


def test_cli_steps_writes_the_page(tmp_path, gk):
    out = tmp_path / "p.html"
    assert main(["steps", str(EXAMPLES / "ex4_4_coriolis_block.toml"), "-d", "acceleration",
                 "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "Coriolis component" in text
    # the helper point X (it only defines the slide) is neither told nor drawn
    cx = gk.solved("ex4_4_coriolis_block").constructions["acceleration"]
    (ax,) = [s for s in cx if s.outputs == ("a(X)",)]
    assert ax.step_id not in text and "x′" not in text


def test_posture_steps_are_told_with_the_arcs_lengths(gk):
    """Example 3.1's posture: C is R_CB = 18 in from B and R_CD = 11 in from D (case 4)."""
    told = _told(gk, "ex3_1_fourbar", "posture")
    (c,) = [ps for ps in told if plain(ps.title).startswith("Position of C")]
    assert plain(c.title) == "Position of C: R_C = R_B + R_CB = R_D + R_CD"
    assert c.case == 4 and len(c.sides) == 3 and "BC = 18 in" in c.text
    exact = gk.exact("ex3_1_fourbar")
    x, y = (float(v) for v in exact.position("C"))
    assert _numbers(plain(c.numbers[-1]))[:2] == pytest.approx([x, y], abs=0.01)
    for ps in told:
        assert not INTERNAL.search(plain(ps.title)), ps.title


def test_vector_names_are_typeset_with_their_subscripts():
    from graphkin.render.narrate import answer_html

    html = answer_html("α4 = A^t_A4D/R_AD; V_A3/2 = ⟦30 m/s⟧ from O_V")
    assert "<i>O</i><sub>V</sub>" in html
    assert "<i>A</i><sup>t</sup><sub>A4D</sub>/<i>R</i><sub>AD</sub>" in html
    assert "<i>V</i><sub>A3/2</sub>" in html and "α<sub>4</sub>" in html
    assert '<span class="answer"><span class="val">30 m/s</span></span>' in html


ALL = sorted(p.stem for p in EXAMPLES.glob("ex[0-9]*.toml"))


@pytest.mark.parametrize("name", ALL)
def test_posture_centers_and_curvature_steps_have_titles_in_words(gk, name):
    sol = gk.solved(name)
    for diagram in ("posture", "centers", "curvature"):
        src = as_source(sol, diagrams=(diagram,) if diagram != "posture" else ())
        if diagram not in src.constructions:
            continue
        for ps in narrate(src, diagram):
            title = plain(ps.title)
            assert title and not INTERNAL.search(title), (diagram, title)


# ---- the figures of the curvature sheet, one page each (Secs. 4.12-4.17) ---------------

PANELS = ("inflection", "bobillier", "hartmann", "cubic")


@pytest.fixture(scope="module")
def fourbar_panels(gk):
    """Example 3.1's coupler: each figure's page, its narration and its steps."""
    from graphkin.render.teach import _construction

    out = {}
    for panel in PANELS:
        src, cx = _construction(gk.solved("ex3_1_fourbar"), panel, None)
        told = narrate(src, panel, _scale_of(src, panel, FRAME_INCHES))
        out[panel] = (cx, told, steps_html(gk.solved("ex3_1_fourbar"), panel))
    return out


@pytest.mark.parametrize("panel", PANELS)
def test_a_curvature_figure_is_walked_step_by_step(fourbar_panels, panel):
    cx, told, page = fourbar_panels[panel]
    own = cx.own
    given = [s.index for s in cx.steps if s.index not in own]
    # every step of the figure is told once, in order; what earlier figures made comes first
    covered = [i for ps in told for i in ps.steps]
    assert sorted(covered) == sorted(s.index for s in cx.steps)
    assert len(covered) == len(set(covered))
    if given:
        assert list(told[0].steps) == given
        assert plain(told[0].title).startswith("Given from the figures before")
    for ps in told:
        title = plain(ps.title)
        assert re.match(r"[A-Z]", title) and not INTERNAL.search(title), title
        assert ps.text, title  # what is drawn and why, for every step
        assert ps.refs.startswith("Sec. 4.1"), ps.refs
    # one section a step (and the results), each drawing the figure up to its step,
    # with its own steps in the drawing and none of the figure's later steps
    sections = re.findall(r'<section class="step[^"]*"[^>]*>', page)
    assert len(sections) == len(told) + 1
    for k, ps in enumerate(told):
        drawn = set(re.findall(rf'id="f{k:02d}-(step-[^"]+?)"', page))
        for s in cx.steps:
            if s.index in ps.steps and s.kind in ("point", "line", "circle"):
                assert s.step_id in drawn, (k, s.step_id)
            if s.index > ps.main:
                assert s.step_id not in drawn, (k, s.step_id)


def test_the_figures_open_with_what_they_are_for(fourbar_panels):
    """Each figure says first what it constructs, in the book's words (Secs. 4.13, 4.17)."""
    assert "Bobillier's theorem" in fourbar_panels["bobillier"][1][0].text
    assert "Ball's point" in fourbar_panels["cubic"][1][0].text
    assert "instantaneous center of acceleration" in fourbar_panels["inflection"][1][0].text
    hart = fourbar_panels["hartmann"][1]
    assert plain(hart[0].title) == ("Given from the figures before: I, J, the inflection "
                                    "circle, the centrode normal N")


def test_the_radius_of_curvature_read_off_is_the_analytic_one(gk, fourbar_panels):
    """ρ_E = R_EE′ on the conjugate-points page equals |V_E|³/|V_E × A_E| (Sec. 4.16),
    with V_E and A_E from the independent analytic solver."""
    _, told, _ = fourbar_panels["hartmann"]
    (line,) = [n for ps in told for n in ps.numbers if "ρ_E" in n]
    rho = _numbers(line.split("=")[-1])[0]
    exact = gk.exact("ex3_1_fourbar")
    v = np.asarray(exact.velocity("E"), dtype=float)[:2]
    a = np.asarray(exact.acceleration("E"), dtype=float)[:2]
    expected = np.linalg.norm(v) ** 3 / abs(v[0] * a[1] - v[1] * a[0])
    assert rho == pytest.approx(expected, rel=1e-3)


def test_cli_steps_walks_a_curvature_figure(tmp_path, capsys):
    out = tmp_path / "cubic.html"
    assert main(["steps", str(EXAMPLES / "ex3_1_fourbar.toml"), "-d", "cubic",
                 "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "Ball" in text and "cubic of stationary curvature" in text
    capsys.readouterr()
    # a figure the link's curvature does not use: one line naming the key, exit 2
    assert main(["steps", str(EXAMPLES / "ex3_3_inverted_slider.toml"), "-d", "bobillier",
                 "-o", str(tmp_path / "b.html")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--diagram" in err[0] and "bobillier" in err[0]


def test_the_last_frame_draws_every_step_told(gk):
    """Leaving out a helper point's steps leaves the others' numbers: the last frame of
    Example 4.4's acceleration page draws every step that is not a helper's."""
    from graphkin.render.narrate import helper_steps

    sol = gk.solved("ex4_4_coriolis_block")
    page = steps_html(sol, "acceleration")
    last = len(re.findall(r"<svg[\s>]", page)) - 1
    skip = helper_steps(as_source(sol), "acceleration")
    assert skip
    for s in sol.constructions["acceleration"]:
        if s.index not in skip:
            assert f'id="f{last:02d}-{s.step_id}"' in page, s.step_id


def test_a_slider_drive_is_given_as_the_book_gives_it(tmp_path):
    """Example 3.2: "driven by slider 4 at a constant velocity V_C = -10 î m/s"; the line
    S -> T runs along +x, so the signed rate along it is -10 m/s (audit 8: the page said
    "ṡ = -10 m/s").  Example 4.4's block slides on the turning link 2 at 30 m/s: V_A3/2."""
    out = tmp_path / "p.html"
    assert main(["steps", str(EXAMPLES / "ex3_2_slider_driven.toml"), "-d", "velocity",
                 "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    assert "Given: <i>V</i><sub>C</sub> = -10 m/s along the line of slider 4" in text
    assert "ṡ" not in text
    assert main(["steps", str(EXAMPLES / "ex4_4_coriolis_block.toml"), "-d", "velocity",
                 "-o", str(out)]) == 0
    assert "<sub>A3/2</sub> = 30 m/s along the line of slider 3" in out.read_text(
        encoding="utf-8")
