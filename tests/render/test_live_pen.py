"""Pen mode of the live page: the student's own polygon, exported, marked by `graphkin check`.

Headless Chromium draws a polygon by script, as a student would with the
mouse (the pole, then each image point, clicked on the velocity panel), the
page exports it as an SVG, and `graphkin check FILE --drawing` (the Python
checker, the one authority on marks; docs/checking.md) marks it: a correct
polygon within the drawing tolerance, a planted mistake (C's image drawn
drawn 40 % short) named wrong.
"""

from __future__ import annotations

from pathlib import Path

from spec_data import EXAMPLES

import graphkin
from graphkin.cli import main
from graphkin.files import load_toml
from graphkin.render.live import live_html


def _click(browser, xy) -> None:
    x, y = xy
    browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
    browser.send("Input.dispatchMouseEvent", type="mousePressed", x=x, y=y, button="left",
                 clickCount=1)
    browser.send("Input.dispatchMouseEvent", type="mouseReleased", x=x, y=y, button="left",
                 clickCount=1)


def _draw(browser, tmp_path: Path, wrong: str | None = None) -> tuple[Path, Path]:
    """Draw Example 3.1's velocity polygon with the pen; returns (saved file, drawing)."""
    path = EXAMPLES / "ex3_1_fourbar.toml"
    page = tmp_path / "live.html"
    page.write_text(live_html(graphkin.load(path), load_toml(path), path.name),
                    encoding="utf-8")
    browser.open(page)
    browser.js("document.getElementById('gk-pen').click()")
    r = browser.js("window.graphkinLive.state().result")
    o = r["o_v"]
    to = "(function (p) { return window.graphkinLive.toClient('velocity', p); })"
    _click(browser, browser.js(f"{to}({o})"))
    for n in ("B", "C", "E"):
        p = r[f"v({n})"]
        if n == wrong:  # drawn 40 % short: V_C's magnitude wrong, its direction right
            p = [o[0] + 0.6 * (p[0] - o[0]), o[1] + 0.6 * (p[1] - o[1])]
        label = browser.js("document.getElementById('gk-pen-label').value")
        assert label == n.lower()  # the page offers the next point's letter
        _click(browser, browser.js(f"{to}({p})"))
    drawing = tmp_path / "mine.svg"
    drawing.write_text(browser.js("window.graphkinLive.penSVG()"), encoding="utf-8")
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    assert browser.errors() == []
    return saved, drawing


def test_a_correct_polygon_drawn_with_the_pen_is_marked_right(browser, tmp_path, capsys):
    saved, drawing = _draw(browser, tmp_path)
    assert browser.js("document.querySelectorAll('.gk-pen line').length") == 3
    capsys.readouterr()
    rc = main(["check", str(saved), "--drawing", str(drawing)])
    out = capsys.readouterr().out
    assert rc == 0, out
    assert "not turned" in out  # the drawing's own scale was read
    for key in ("V_B", "V_C", "V_E"):
        row = next(line for line in out.splitlines() if line.startswith(key))
        assert " ok " in row, row
    assert "3 of 3 within tolerance" in out


def test_a_planted_mistake_is_named(browser, tmp_path, capsys):
    saved, drawing = _draw(browser, tmp_path, wrong="C")
    capsys.readouterr()
    rc = main(["check", str(saved), "--drawing", str(drawing)])
    out = capsys.readouterr().out
    assert rc != 0 or "2 of 3" in out, out
    rows = {line.split()[0]: line for line in out.splitlines() if line.startswith("V_")}
    assert " ok " in rows["V_B"] and " ok " in rows["V_E"], out
    assert " ok " not in rows["V_C"] and "WRONG" in rows["V_C"], out
    assert "-40.00 %" in rows["V_C"], out  # the error the checker measured is the planted one
