"""``graphkin synthesize FILE --steps OUT.html``: the construction one step per frame."""

from __future__ import annotations

import re

from graphkin.cli import main
from graphkin.render.style import HIGHLIGHT
from graphkin.render.synthesis_steps import teaching_steps
from graphkin.synthesis import load_spec, synthesize

TWO = """title = "Two postures"
units = "in"
[[postures]]
point = [0, 0]
angle = 0
[[postures]]
point = [1.5, 0.6]
angle = 40
[pivots]
circle_points = [[0.5, -1], [1.8, -0.8]]
center_points = [[0, -3], [3, -3]]
"""


def test_two_postures_step_by_step(tmp_path) -> None:  # type: ignore[no-untyped-def]
    f = tmp_path / "two.toml"
    f.write_text(TWO, encoding="utf-8")
    out = tmp_path / "two.html"
    assert main(["synthesize", str(f), "--steps", str(out)]) == 0
    page = out.read_text(encoding="utf-8")
    res = synthesize(load_spec(f))
    steps = teaching_steps(res)
    # Sec. 9.3 in order: the pole P12 first, then for each dyad the moving pivot, its
    # second position, the bisector through P12, and the fixed pivot on it
    labels = [s.label for _, s in steps]
    assert labels[0] == "P12"
    for name in ("A", "B"):
        order = [labels.index(x) for x in (f"{name}1", f"{name}2", f"b_{name}12", f"O_{name}")]
        assert order == sorted(order), order
    frames = re.findall(r"<section class='frame'.*?</section>", page, flags=re.S)
    assert len(frames) == len(steps) + 1                  # one per step, then the result
    for (_, step), frame in zip(steps, frames):
        assert "Step " in frame and step.step_id in frame
        assert HIGHLIGHT.lower() in frame.lower()         # the newest step is highlighted
    assert HIGHLIGHT.lower() not in frames[-1].lower()
    assert "synthesis-linkage-1" in frames[-1] and "synthesis-linkage-1" not in frames[0]
