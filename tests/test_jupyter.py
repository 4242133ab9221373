"""Jupyter (issue 31): short reprs, rich reprs, Drawing.save, and docs/notebook.ipynb run.

The notebook is executed the way a kernel runs it, without a kernel: each
code cell in order in one namespace, the value of a cell's last expression
shown as Jupyter would (``_repr_html_``, else ``_repr_svg_``, else ``repr``).
"""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path
from typing import Any

import pytest

import graphkin

NOTEBOOK = Path(__file__).parents[1] / "docs" / "notebook.ipynb"


def _shown(value: Any) -> tuple[str, str]:
    """What Jupyter shows for ``value``: (mime kind, text)."""
    for kind, name in (("html", "_repr_html_"), ("svg", "_repr_svg_")):
        f = getattr(value, name, None)
        if f is not None:
            out = f()
            if out is not None:
                return kind, out
    return "text", repr(value)


def _run_notebook(path: Path) -> list[tuple[str, str]]:
    nb = json.loads(path.read_text(encoding="utf-8"))
    ns: dict[str, Any] = {"__name__": "__notebook__"}
    shown = []
    for cell in nb["cells"]:
        if cell["cell_type"] != "code":
            continue
        tree = ast.parse("".join(cell["source"]))
        last = tree.body.pop() if tree.body and isinstance(tree.body[-1], ast.Expr) else None
        exec(compile(tree, str(path), "exec"), ns)  # noqa: S102 - the project's own notebook
        if last is not None:
            value = eval(compile(ast.Expression(last.value), str(path), "eval"), ns)  # noqa: S307
            if value is not None:
                shown.append(_shown(value))
    return shown


def test_the_documented_notebook_runs() -> None:
    shown = _run_notebook(NOTEBOOK)
    kinds = [k for k, _ in shown]
    # mech (its sketch), sol (its posture), v (the polygon), the files, the sweep, a column
    assert kinds == ["svg", "svg", "svg", "text", "html", "text"]
    assert "'velocity.svg', 'velocity.tex'" in shown[3][1]
    assert "72 postures" in shown[4][1]


def test_a_sweep_is_short_and_a_small_table() -> None:
    sw = graphkin.examples.crank_rocker().sweep(count=50)
    text = repr(sw)
    assert len(text) < 400 and "50 postures" in text and "\n" not in text
    html = sw._repr_html_()
    assert len(html) < 20_000
    # every column heading, and 6 rows shown of 50 (3 first, 2 last, one "... 45 more")
    assert html.count("<th>") == len(sw.columns)
    assert html.count("<tr>") == 1 + 6 and "45 more" in html


def test_a_mechanism_shows_a_sketch_and_a_solution_its_posture_only() -> None:
    mech = graphkin.examples.fourbar()
    assert "\n" not in repr(mech) and len(repr(mech)) < 400
    sol = mech.solve()
    svg = sol._repr_svg_()
    assert svg is not None and mech._repr_svg_() == svg
    assert all(f'id="{s.step_id}"' in svg for s in sol.constructions["posture"])
    assert 'id="panel-velocity"' not in svg and 'id="results"' not in svg  # posture only


def test_a_mechanism_that_does_not_assemble_shows_its_summary(tmp_path: Path) -> None:
    text = graphkin.examples.text("fourbar")
    # the coupler BC 0.1 in long: at θ2 = 120°, |BD| = |(12, -3.46)| = 12.5 in exceeds
    # |BC| + |CD| = 11.1 in, so the loop cannot close (Sec. 2.8)
    short = re.sub(r"(?m)^(\s*C\s*=\s*)\[.*\]", r"\1[0.1, 0.0]", text, count=1)
    assert short != text
    mech = graphkin.loads(short)
    assert mech._repr_svg_() is None
    assert repr(mech).startswith("<Mechanism")


@pytest.mark.parametrize(("suffix", "magic"), [
    (".svg", b"<?xml"), (".pdf", b"%PDF"), (".png", b"\x89PNG"), (".tex", b"% graphkin"),
])
def test_drawing_save_writes_the_suffixs_format(tmp_path: Path, suffix: str,
                                                magic: bytes) -> None:
    d = graphkin.examples.fourbar().solve().draw("velocity")
    out = d.save(tmp_path / f"v{suffix}")
    assert Path(out).read_bytes().startswith(magic)


def test_drawing_save_refuses_an_unknown_suffix(tmp_path: Path) -> None:
    d = graphkin.examples.fourbar().solve().draw("posture")
    with pytest.raises(graphkin.GraphkinError, match="suffix"):
        d.save(tmp_path / "v.jpeg")
