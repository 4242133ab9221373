"""The design chapters' drawings state their scales on the paper of the file's units.

A gear pair in millimetres (Problem 7.16: m = 5 mm) was drawn at "1 in =
100 mm", while every mechanism drawing of a metric file reads "1 cm = ...":
the panels of gears and synthesis chose their scale on inch paper whatever
the unit.  Expected: centimetres for a metric file, inches for an inch file
(graphkin.render.scale.paper_unit, as the mechanism sheets do).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from graphkin.cli import main

DATA = Path(__file__).resolve().parents[1] / "data" / "audit7"
SCALE = re.compile(r"1 (cm|in) = [0-9.]+ ([a-z]+)")


def _scales(svg: Path) -> set[tuple[str, str]]:
    return set(SCALE.findall(svg.read_text()))


@pytest.mark.parametrize(("name", "paper", "unit"),
                         [("p7_16_metric.toml", "cm", "mm"), ("p7_36_inch.toml", "in", "in")])
def test_gear_drawing_scales_on_the_files_paper(tmp_path: Path, name: str, paper: str,
                                                unit: str) -> None:
    out = tmp_path / "mesh.svg"
    assert main(["draw", str(DATA / name), "-d", "gears", "-o", str(out)]) == 0
    found = _scales(out)
    assert found and found == {(paper, unit)}


def test_synthesis_drawing_of_a_metric_file_scales_in_cm(tmp_path: Path) -> None:
    out = tmp_path / "s.svg"
    assert main(["synthesize", str(DATA / "three_postures_mm.toml"), "--draw", str(out)]) == 0
    found = _scales(out)
    assert found and {p for p, _ in found} == {"cm"}
