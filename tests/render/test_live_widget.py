"""graphkin.live(mech): the live page as a notebook widget (anywidget), read back in Python.

Without a Jupyter server: the widget's traits (``_esm``, ``_css``, ``toml``)
are checked and round-tripped in plain Python (``get_state``/``set_state``,
what the front end sends), and the widget's ES module is run in headless
Chromium with a stand-in for anywidget's model (``get``, ``set``,
``save_changes``): a drag there sends the edited file to the model, and
``widget.mechanism`` made from it solves to what the page shows.
"""

from __future__ import annotations

import json
import sys

import numpy as np
import pytest
from spec_data import EXAMPLES

import graphkin
from graphkin.errors import GraphkinError, InputError

pytest.importorskip("anywidget")


def test_the_widget_holds_the_page_and_the_file():
    w = graphkin.live(graphkin.examples.fourbar())
    assert w.toml == graphkin.examples.text("fourbar")
    assert w.mechanism.title == graphkin.examples.fourbar().title
    assert "export default" in w._esm and "function construction(I, K)" in w._esm
    # the page's style sheet, every rule inside the widget: nothing of the notebook restyled
    rules = [r for r in w._css.splitlines() if "{" in r]
    assert rules and all(r.startswith(".gk-live") for r in rules)
    assert all(not part.strip().startswith(("body", "svg", "table")) for r in rules
               for part in r.split("{")[0].split(","))


def test_the_traits_round_trip_and_mechanism_reads_the_edit(tmp_path):
    # what the front end sends back (the page's TOML with D moved) is the mechanism Python reads
    path = EXAMPLES / "ex3_1_fourbar.toml"
    w = graphkin.live(path)
    state = w.get_state()
    assert {"_esm", "_css", "toml", "source", "edit"} <= set(state)
    text = state["toml"]
    assert text.count("D = [10, 0]") == 1
    w.set_state({"toml": text.replace("D = [10, 0]", "D = [10.5, -0.25]")})
    m = w.mechanism
    assert m.links["1"].points["D"] == (10.5, -0.25)
    # and it is a mechanism like any other: it solves
    assert bool(np.all(m.solve().valid))


def test_without_anywidget_one_line_says_how_to_install(monkeypatch):
    import graphkin.render.live_widget as lw

    monkeypatch.setitem(sys.modules, "anywidget", None)  # import anywidget -> ImportError
    monkeypatch.setattr(lw, "_CLASS", [])
    with pytest.raises(GraphkinError) as e:
        graphkin.live(graphkin.examples.fourbar())
    msg = str(e.value)
    assert "\n" not in msg and "graphkin[jupyter]" in msg and "anywidget" in msg


def test_a_mechanism_without_its_file_is_refused_in_one_line():
    data = graphkin.examples.text("fourbar")
    mech = graphkin.loads(data, source="<made in the notebook>")
    with pytest.raises(InputError, match="needs the mechanism's file") as e:
        graphkin.live(mech)
    assert "\n" not in str(e.value)


HOST = """<!DOCTYPE html><html><head><meta charset="utf-8"><style>{css}</style></head>
<body><div id="cell"></div>
<script type="module">
const esm = {esm};
const state = {{source: {source}, toml: {toml}}};
window.sent = [];
const model = {{
  get: (k) => state[k],
  set: (k, v) => {{ state[k] = v; }},
  save_changes: () => {{ window.sent.push(state.toml); }},
  on: () => {{}},
}};
const url = URL.createObjectURL(new Blob([esm], {{type: "text/javascript"}}));
const mod = await import(url);
mod.default.render({{model: model, el: document.getElementById("cell")}});
window.ready = true;
</script></body></html>
"""


def test_the_widget_runs_in_a_browser_and_sends_the_edited_mechanism(tmp_path):
    from cdp import browser_or_skip

    from graphkin.render.live import script_json

    path = EXAMPLES / "ex3_1_fourbar.toml"
    w = graphkin.live(path)
    page = tmp_path / "host.html"
    page.write_text(HOST.format(css=w._css, esm=script_json(w._esm),
                                source=script_json(w.source), toml=script_json(w.toml)),
                    encoding="utf-8")
    b = browser_or_skip(1300, 1000)
    try:
        b.open(page)
        b.pump(0.5)
        assert b.js("window.ready === true") and b.errors() == []
        # drag D, as a student would (pointer events on the widget's own handle)
        r = b.js("(function () { var h = document.querySelector("
                 "'#cell .gk-handle[data-kind=\"frame\"][data-name=\"D\"]')"
                 ".getBoundingClientRect(); return [h.x + h.width / 2, h.y + h.height / 2]; })()")
        x, y = r
        b.send("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
        b.send("Input.dispatchMouseEvent", type="mousePressed", x=x, y=y, button="left",
               clickCount=1)
        b.send("Input.dispatchMouseEvent", type="mouseMoved", x=x + 20, y=y - 10,
               button="left", buttons=1)
        b.send("Input.dispatchMouseEvent", type="mouseReleased", x=x + 20, y=y - 10,
               button="left", clickCount=1)
        sent = b.js("window.sent")
        state = b.js("document.getElementById('cell').graphkinLive.state()")
    finally:
        b.close()
    assert len(sent) == 1
    w.set_state({"toml": sent[-1]})  # what anywidget's model carries to Python
    m = w.mechanism
    d = m.links["1"].points["D"]
    assert d[0] > 10.2 and d[1] > 0.1  # moved right and up
    sol = m.solve()
    for n in ("B", "C", "E"):
        np.testing.assert_allclose(state["result"][n], sol.position(n), rtol=0, atol=1e-9 * 30,
                                   err_msg=n)
    assert json.loads(json.dumps(state["result"]["D"])) == list(d)
