"""graphkin.live(mech) in a real JupyterLab: rendered, dragged, and read back by the kernel.

Skipped unless ``jupyterlab`` and ``anywidget`` are importable and Chromium is
installed (CI has no JupyterLab: it skips).  The scenario (tests/jupyter_live.py):
JupyterLab headless on localhost, the notebook opened in headless Chromium, the
widget rendered by its first cell, the crank dragged with pointer events, the
edited mechanism printed by a second cell in the same kernel and the widget
shown again by a third; the drive the kernel reads is the page's, and B is the
crank's tip at that angle, ``A + AB (cos θ₂, sin θ₂)`` (Example 3.1, AB = 4 in,
Uicker Sec. 3.6).  Set GK_JLAB_SHOTS=dir to keep the screenshots.
"""

from __future__ import annotations

import pytest
from jupyter_live import check_widget, server

pytest.importorskip("jupyterlab")
pytest.importorskip("anywidget")
pytest.importorskip("websocket")  # websocket-client: tests/cdp.py's DevTools client


def test_the_widget_renders_in_jupyterlab_and_the_kernel_reads_the_drag(tmp_path):
    with server(tmp_path, "lab") as url:
        check_widget(url, "jlab")
