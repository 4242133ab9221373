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


def test_steps_verb_takes_a_synthesis_file(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    """``graphkin steps SYNTHFILE`` is ``synthesize --steps``: the same frames, and --frames."""
    f = tmp_path / "two.toml"
    f.write_text(TWO, encoding="utf-8")
    out, frames = tmp_path / "page.html", tmp_path / "frames"
    assert main(["steps", str(f), "-o", str(out), "--frames", str(frames)]) == 0
    n = len(teaching_steps(synthesize(load_spec(f)))) + 1   # each step, then the result
    page = out.read_text(encoding="utf-8")
    assert len(re.findall(r"<section class='frame'", page)) == n
    assert sorted(p.name for p in frames.iterdir()) == [f"synthesis-{k:02d}.svg"
                                                       for k in range(n)]
    # another diagram of a synthesis file is refused in one line
    capsys.readouterr()
    assert main(["steps", str(f), "-d", "velocity", "-o", str(tmp_path / "c.html")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "--diagram" in err[0] and "-d synthesis" in err[0]


def test_steps_verb_refuses_synthesis_diagram_of_a_mechanism(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    m = tmp_path / "m.toml"
    m.write_text('title = "m"\n[links.1]\nO2 = [0, 0]\nO4 = [3, 0]\n[links.2]\nO2 = [0, 0]\n'
                 'A = [1, 0]\n', encoding="utf-8")
    assert main(["steps", str(m), "-d", "synthesis", "-o", str(tmp_path / "x.html")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "synthesis file" in err[0]
