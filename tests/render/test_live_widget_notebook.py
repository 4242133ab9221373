"""graphkin.live(mech) in a real Jupyter Notebook 7: rendered, dragged, read back by the kernel.

Notebook 7 is the classic notebook's interface rebuilt from JupyterLab's
components: the same application object (``window.jupyterapp``), the same
notebook commands and output areas, one document per browser tab.  anywidget
renders there through the same widget manager (``jupyterlab_widgets``).
Skipped unless ``notebook`` (7 or later) and ``anywidget`` are importable and
Chromium is installed (CI has no Jupyter: it skips).  The scenario is
JupyterLab's (tests/jupyter_live.py): the widget rendered by the first cell,
the crank dragged with pointer events, the edited mechanism printed by the
kernel and shown again in a new view; the drive the kernel reads is the
page's, and B is the crank's tip at that angle (Example 3.1, AB = 4 in,
Uicker Sec. 3.6).  Set GK_JLAB_SHOTS=dir to keep the screenshots.
"""

from __future__ import annotations

import pytest
from jupyter_live import check_widget, server

notebook = pytest.importorskip("notebook")
pytest.importorskip("anywidget")
pytest.importorskip("websocket")  # websocket-client: tests/cdp.py's DevTools client

if int(notebook.__version__.split(".")[0]) < 7:
    pytest.skip("the classic notebook (< 7) has no JupyterLab widget manager",
                allow_module_level=True)


def test_the_widget_renders_in_notebook_7_and_the_kernel_reads_the_drag(tmp_path):
    with server(tmp_path, "notebook") as url:
        check_widget(url, "nb7")
