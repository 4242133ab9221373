"""graphkin.live(mech) in a real Jupyter front-end: the scenario both opt-in tests run.

A Jupyter server (JupyterLab, or Notebook 7, which is built from JupyterLab's
own components and exposes the same application object) is started headless
on localhost (a token, a free port, a temporary root holding one notebook and
Example 3.1's file); the notebook is opened in headless Chromium
(tests/cdp.py); its first cell is run through the front-end's own command
(``notebook:run-all-cells`` would re-make the widget, so the cells are run one
by one with ``notebook:run-cell``); the widget's page is waited for in the
cell's output and the crank's handle dragged with pointer events; a second
cell in the same kernel prints the edited mechanism's drive and its solved B,
and a third shows the widget again (a new view: the dragged posture).  The
drive printed is the one the page shows after the drag, and B is the crank's
tip at that angle: ``A + AB (cos θ₂, sin θ₂)``, AB = 4 in, A = (0, 0)
(Example 3.1's crank, Uicker Sec. 3.6).  ``GK_JLAB_SHOTS=dir`` keeps the
screenshots.
"""

from __future__ import annotations

import json
import math
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

import pytest
from spec_data import EXAMPLES

TOKEN = "gk-live-widget-test"

CELLS = [
    'import graphkin\nw = graphkin.live("ex3_1_fourbar.toml")\nw',
    'import json, math\nm = w.mechanism\nsol = m.solve()\n'
    'print("GK" + json.dumps({"theta2": math.degrees(m.drives[0].value),'
    ' "B": [float(v) for v in sol.position("B")], "valid": bool(sol.valid.all())}))',
    'w',
]

# the notebook's panel (headless, the window has no focus: shell.currentWidget stays null)
NB = ("Array.from(window.jupyterapp.shell.widgets('main'))"
      ".find((w) => w.sessionContext && w.content)")

# the front-ends: the module run with ``python -m``, the option exposing ``window.jupyterapp``
# and the notebook's address
APPS = {
    "lab": ("jupyterlab", "--LabApp.expose_app_in_browser=True", "/lab/tree/live.ipynb"),
    "notebook": ("notebook", "--JupyterNotebookApp.expose_app_in_browser=True",
                 "/notebooks/live.ipynb"),
}


def _notebook() -> str:
    cells = [{"cell_type": "code", "execution_count": None, "metadata": {}, "outputs": [],
              "source": src} for src in CELLS]
    return json.dumps({"cells": cells, "metadata": {"kernelspec": {
        "name": "python3", "display_name": "Python 3", "language": "python"}},
        "nbformat": 4, "nbformat_minor": 5})


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def wait(pred: Any, seconds: float, what: str, b: Any = None) -> Any:
    """Poll ``pred`` until it is truthy (pumping the browser's events), else TimeoutError."""
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        v = pred()
        if v:
            return v
        if b is not None:
            b.pump(0.25)
        else:
            time.sleep(0.25)
    raise TimeoutError(what)


def _up(url: str) -> bool:
    try:
        with urllib.request.urlopen(url, timeout=2) as r:
            return r.status == 200
    except OSError:
        return False


@contextmanager
def server(tmp_path: Path, app: str) -> Iterator[str]:
    """A Jupyter server of ``app`` on localhost, rooted in a temporary folder; stopped after.

    Yields the notebook's URL (with the token).
    """
    from cdp import chromium

    if chromium() is None:
        pytest.skip("chromium is not installed")
    module, expose, where = APPS[app]
    root = tmp_path / "nb"
    root.mkdir()
    shutil.copy(EXAMPLES / "ex3_1_fourbar.toml", root / "ex3_1_fourbar.toml")
    (root / "live.ipynb").write_text(_notebook(), encoding="utf-8")
    port = _free_port()
    runtime = tempfile.mkdtemp(prefix="gk-jupyter-rt-")
    env = dict(os.environ, JUPYTER_RUNTIME_DIR=runtime, JUPYTERLAB_WORKSPACES_DIR=runtime,
               JUPYTERLAB_SETTINGS_DIR=runtime)
    logfile = tmp_path / f"{app}.log"
    log = logfile.open("w")
    proc = subprocess.Popen(
        [sys.executable, "-m", module, "--no-browser", f"--port={port}",
         "--ip=127.0.0.1", f"--IdentityProvider.token={TOKEN}", "--allow-root",
         f"--ServerApp.root_dir={root}", expose, "--ServerApp.open_browser=False"],
        cwd=root, env=env, stdout=log, stderr=subprocess.STDOUT)
    try:
        try:
            wait(lambda: _up(f"http://127.0.0.1:{port}/api/status?token={TOKEN}"), 60,
                 f"jupyter {app} did not start")
        except TimeoutError:
            log.flush()
            raise TimeoutError(f"jupyter {app} did not start: "
                               + logfile.read_text()[-1500:]) from None
        yield f"http://127.0.0.1:{port}{where}?token={TOKEN}"
    finally:
        proc.terminate()  # the server this function started, by its handle
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(timeout=10)
        log.close()
        shutil.rmtree(runtime, ignore_errors=True)


def _run_cell(b: Any, index: int) -> None:
    b.js(f"(async () => {{ const p = {NB}; window.jupyterapp.shell.activateById(p.id);"
         f" p.content.activeCellIndex = {index};"
         " await window.jupyterapp.commands.execute('notebook:run-cell'); return 1; })()")


def _output_text(b: Any, index: int) -> str:
    return str(b.js(f"(function () {{ const c = {NB}.content.widgets[{index}];"
                    " return c.node.querySelector('.jp-OutputArea') ?"
                    " c.node.querySelector('.jp-OutputArea').innerText : ''; })()"))


def check_widget(url: str, tag: str) -> None:
    """Render the widget, drag the crank, read the edit back in the kernel: assert it all."""
    from cdp import Browser

    shots = Path(os.environ["GK_JLAB_SHOTS"]) if os.environ.get("GK_JLAB_SHOTS") else None
    b = Browser(1400, 1000)
    try:
        b.open(url, wait=60)
        # the notebook open and its kernel idle
        wait(lambda: b.js(f"!!(window.jupyterapp && {NB}"
                          f" && {NB}.content.widgets.length === 3"
                          f" && {NB}.sessionContext.session"
                          f" && {NB}.sessionContext.session.kernel"
                          f" && {NB}.sessionContext.session.kernel.status === 'idle')"),
             90, "the notebook or its kernel did not start", b)
        # what the front-end itself logs while opening a notebook, before graphkin runs (Notebook
        # 7.6 throws one TypeError of its settings registry there): not the widget's
        own = len(b.errors())
        _run_cell(b, 0)
        ok = wait(lambda: b.js("!!document.querySelector('.jp-OutputArea .gk-live "
                               ".gk-handle[data-kind=\"drive\"]')")
                  or ("Error" in _output_text(b, 0) and _output_text(b, 0)),
                  90, "the widget did not render", b)
        assert ok is True, f"cell 1 failed: {ok}"
        b.pump(0.5)
        if shots:
            b.screenshot(shots / f"{tag}-1-rendered.png")
        # the widget's style sheet applied (the handles are styled by the scoped rules)
        assert b.js("getComputedStyle(document.querySelector('.gk-live .gk-handle'))"
                    ".cursor") == "grab"
        before = b.js("document.querySelector('.jp-OutputArea .gk-live').parentNode"
                      ".graphkinLive.state()")
        # drag the crank's tip B on the page: pointer events on its handle; A's handle (a
        # frame pivot) gives the crank's pivot on the screen
        sel = "'.jp-OutputArea .gk-live .gk-handle[data-kind=\"drive\"]'"
        b.js(f"document.querySelector({sel}).scrollIntoView({{block: 'center'}})")
        b.pump(0.3)
        xa, ya = b.js("(function () { const r = document.querySelector('.jp-OutputArea "
                      ".gk-live .gk-handle[data-kind=\"frame\"][data-name=\"A\"]')"
                      ".getBoundingClientRect(); return [r.x + r.width / 2,"
                      " r.y + r.height / 2]; })()")
        x, y = b.js(f"(function () {{ const r = document.querySelector({sel})"
                    ".getBoundingClientRect(); return [r.x + r.width / 2,"
                    " r.y + r.height / 2]; })()")
        b.send("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y)
        b.send("Input.dispatchMouseEvent", type="mousePressed", x=x, y=y, button="left",
               clickCount=1)
        for k in range(1, 6):
            b.send("Input.dispatchMouseEvent", type="mouseMoved", x=x + 8 * k, y=y + 6 * k,
                   button="left", buttons=1)
        b.send("Input.dispatchMouseEvent", type="mouseReleased", x=x + 40, y=y + 30,
               button="left", clickCount=1)
        b.pump(1.0)
        after = b.js("document.querySelector('.jp-OutputArea .gk-live').parentNode"
                     ".graphkinLive.state()")
        if shots:
            b.screenshot(shots / f"{tag}-2-dragged.png")
        x1, y1 = x + 40, y + 30  # where the pointer was released
        _run_cell(b, 1)
        text = wait(lambda: "GK{" in _output_text(b, 1) and _output_text(b, 1)
                    or ("Error" in _output_text(b, 1) and _output_text(b, 1)),
                    60, "the second cell printed nothing", b)
        # the widget shown again (a new view of the same model): the edited posture, not the
        # file's; a view's edits are kept in the model, not only in the view that made them
        _run_cell(b, 2)
        views = "document.querySelectorAll('.jp-OutputArea .gk-live')"
        wait(lambda: b.js(f"{views}.length === 2"), 60, "the widget was not shown again", b)
        b.pump(0.3)
        again = b.js(f"{views}[1].parentNode.graphkinLive.state().drive")
        if shots:
            b.js(f"{NB}.content.widgets[1].node.scrollIntoView({{block: 'end'}})")
            b.pump(0.3)
            b.screenshot(shots / f"{tag}-3-read-back.png")
        errors = b.errors()[own:]
    finally:
        b.close()
    assert "GK{" in text, text
    print(text)  # -s shows what the kernel printed
    got = json.loads(text[text.index("GK{") + 2:].splitlines()[0])
    # the drag moved the crank: θ₂ = 120° before (the file); after, the pointer's direction
    # from A on the screen (y down on the screen, up in the drawing; a to-scale panel)
    assert abs(before["drive"] - math.radians(120)) < 1e-12
    want = math.degrees(math.atan2(-(y1 - ya), x1 - xa))
    assert abs(got["theta2"] - want) < 0.5, (got, want)
    assert abs(got["theta2"] - 120) > 30
    # what the kernel read is what the page shows: the page's drive, its B
    assert abs(math.radians(got["theta2"]) - after["drive"]) < 1e-12
    assert got["valid"]
    t = math.radians(got["theta2"])
    ab = 4.0  # Example 3.1: AB = 4 in, A = (0, 0)
    assert math.dist(got["B"], (ab * math.cos(t), ab * math.sin(t))) < 1e-9 * ab
    assert math.dist(got["B"], after["result"]["B"]) < 1e-9 * ab
    assert again == after["drive"]
    assert errors == [], errors
