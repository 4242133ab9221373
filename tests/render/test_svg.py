"""Layer 3: the saved SVG parsed as XML, looked up by id; determinism; the other formats."""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest

from graphkin.construction import Role
from graphkin.render import draw, save, to_bytes
from graphkin.render.scene import safe_id

SVG = "{http://www.w3.org/2000/svg}"
FOURBAR = "ex3_1_fourbar"


def parse(data: bytes) -> tuple[ET.Element, dict[str, ET.Element]]:
    root = ET.fromstring(data)
    ids: dict[str, ET.Element] = {}
    for el in root.iter():
        i = el.get("id")
        if i is not None:
            assert i not in ids, f"duplicate id {i}"
            ids[i] = el
    return root, ids


def text_of(el: ET.Element) -> str:
    return "".join(t.text or "" for t in el.iter(f"{SVG}text")) + "".join(
        t.text or "" for t in el.iter(f"{SVG}tspan"))


@pytest.mark.parametrize("diagram", ["posture", "velocity", "acceleration"])
def test_every_step_is_a_group_with_its_id(gk, diagram):
    _, ids = parse(gk.svg(FOURBAR, diagram))
    for step in gk.solved(FOURBAR).constructions[diagram]:
        assert step.step_id in ids, step.step_id
        assert ids[step.step_id].tag == f"{SVG}g"


def test_point_letters_are_real_text(gk):
    _, ids = parse(gk.svg(FOURBAR, "posture"))
    for name in ("A", "B", "C", "D", "E", "F"):
        el = ids[f"label-{name}"]
        texts = list(el.iter(f"{SVG}text"))
        assert texts and texts[0].text == name
    _, ids = parse(gk.svg(FOURBAR, "velocity"))
    assert text_of(ids["label-" + safe_id("v(C)")]) == "c"
    # mathtext splits O_V into tspans: the label is found by its id, not by its text
    assert "".join(text_of(ids["label-o_v"]).split()) == "OV"


def test_counts_per_role(gk):
    """One letter per image found (result) and one group per step, whatever the role."""
    _, ids = parse(gk.svg(FOURBAR, "velocity"))
    cx = gk.solved(FOURBAR).constructions["velocity"]
    for role in Role:
        steps = [s for s in cx if s.role == role]
        assert sum(s.step_id in ids for s in steps) == len(steps)
    images = [s for s in cx if s.role == Role.RESULT and s.kind == "point"]
    # the four images b, c, e, f of Example 3.1 (Fig. 3.5 of the book)
    assert sorted(s.label for s in images) == ["v(B)", "v(C)", "v(E)", "v(F)"]
    assert all("label-" + safe_id(s.label) in ids for s in images)


def test_panels_and_results_are_named(gk):
    _, ids = parse(gk.svg(FOURBAR, "velocity"))
    assert {"panel-posture", "panel-velocity", "results", "sheet-title"} <= set(ids)
    assert "agrees with the analytic solution" in text_of(ids["results-agreement"])
    assert "1 in = " in text_of(ids["scale-text-velocity"])


def test_same_drawing_twice_gives_the_same_bytes(gk):
    sol = gk.solved(FOURBAR)
    a = to_bytes(draw(sol, "acceleration").figure)
    b = to_bytes(draw(sol, "acceleration").figure)
    assert a == b
    assert b"nan" not in a.lower()


def test_pdf_and_png(gk, tmp_path):
    fig = gk.drawn("ex2_5_open", "posture").figure
    pdf = save(fig, tmp_path / "x.pdf").read_bytes()
    png = save(fig, tmp_path / "x.png").read_bytes()
    assert pdf.startswith(b"%PDF")
    assert png.startswith(b"\x89PNG")
    assert save(fig, tmp_path / "x.pdf").read_bytes() == pdf


def test_all_sheet_has_unique_prefixed_ids(gk):
    root, ids = parse(gk.svg(FOURBAR, "all"))
    sol = gk.solved(FOURBAR)
    for step in sol.constructions["posture"]:
        assert step.step_id in ids
    for d in ("velocity", "acceleration"):
        for step in sol.constructions[d]:
            assert f"{d}-{step.step_id}" in ids
