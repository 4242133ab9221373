"""The live page as a notebook widget: ``graphkin.live(mech)`` (JupyterLab, Notebook, VS Code).

The widget is the page of ``graphkin live`` (:mod:`graphkin.render.live`)
run inside the cell's output by anywidget, which all three front ends load:
its ``_esm`` is the same written-out construction and the same script
(``gkLiveApp``, :mod:`graphkin.render.live_app`) run in the widget's element,
its ``_css`` the page's style sheet scoped to the widget (``.gk-live``), so
nothing of the notebook is restyled.  Every edit (a drag released, the
slider let go, a branch switched, undo, reset) sends the edited mechanism
file back to Python (the ``toml`` trait, the same TOML the page saves), and
``widget.mechanism`` parses it: the edited mechanism, readable back.  The
edit itself (the page's parameters and drive, the ``edit`` trait) is kept in
the model too, so a view made later (the widget shown again, the browser's
page reloaded) and every other view of the widget show the edited
mechanism, not the file's.

anywidget is an optional extra (``pip install 'graphkin[jupyter]'``),
imported only when a widget is made.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (the posture constructions), Secs. 3.4-3.6, 3.13-3.15 and 4.2-4.6
(the polygons, instant centers and Kennedy circle the page draws).
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

from graphkin.construction.jsgen import js_string
from graphkin.errors import GraphkinError, InputError
from graphkin.mechanisms.model import Mechanism
from graphkin.render.live import live_body, live_data, script_json
from graphkin.render.live_app import APP_JS, LIVE_LIB, PAGE_CSS

__all__ = ["live", "widget_css", "widget_esm"]

MISSING = ("graphkin.live needs anywidget, an optional extra: "
           "pip install 'graphkin[jupyter]' (or pip install anywidget)")


def widget_css() -> str:
    """The page's style sheet with every rule scoped to the widget's element (``.gk-live``)."""
    out = []
    for line in PAGE_CSS.strip().splitlines():
        sel, sep, rest = line.partition("{")
        if not sep:
            out.append(line)
            continue
        scoped = [".gk-live" if s.strip() == "body" else f".gk-live {s.strip()}"
                  for s in sel.split(",")]
        out.append(", ".join(scoped) + " {" + rest)
    return "\n".join(out) + "\n"


def widget_esm(data: dict[str, Any], js: str) -> str:
    """The widget's ES module: the construction, the page's script and ``render``."""
    return (js + LIVE_LIB + APP_JS
            + f"\nconst GK_DATA = {script_json(data)};"
            + f"\nconst GK_BODY = {js_string(live_body(str(data['title']), data.get('hint')))};\n"
            + """
function render({ model, el }) {
  const root = document.createElement("div");
  root.className = "gk-live";
  root.innerHTML = GK_BODY;  // graphkin's own markup, the title escaped (live_body)
  el.appendChild(root);
  const app = gkLiveApp(root, GK_DATA, model.get("source"), (toml) => {
    model.set("toml", toml);
    model.set("edit", JSON.stringify(app.edit()));
    model.save_changes();
  });
  el.graphkinLive = app;
  // a view made after an edit (the cell shown again, the browser's page reloaded) and every
  // other view of the same widget show the edited mechanism, not the file's
  const follow = () => {
    const s = model.get("edit");
    if (s && s !== JSON.stringify(app.edit())) app.load(JSON.parse(s));
  };
  follow();
  model.on("change:edit", follow);
}
export default { render };
""")


def _file_text(obj: Mechanism | str | Path) -> tuple[str, str]:
    """The mechanism file's text and name, from a path or a mechanism loaded from a file."""
    from graphkin import examples
    from graphkin.files import read_text

    if isinstance(obj, (str, Path)):
        return read_text(obj), str(obj)
    if isinstance(obj, Mechanism):
        m = re.fullmatch(r"<example (\w+)>", obj.source or "")
        if m:
            return examples.text(m.group(1)), f"{m.group(1)}.toml"
        if obj.source and Path(obj.source).is_file():
            return read_text(obj.source), obj.source
        raise InputError("graphkin.live needs the mechanism's file: pass its path, or a "
                         "mechanism from graphkin.load(path) or graphkin.examples",
                         file=obj.source or "<mechanism>")
    raise InputError(f"graphkin.live takes a Mechanism or a file's path, not "
                     f"{type(obj).__name__}")


def _widget_class() -> Any:
    """The widget class (anywidget imported here, when a widget is first made)."""
    try:
        import anywidget
        import traitlets
    except ImportError:
        raise GraphkinError(MISSING) from None

    class LiveWidget(anywidget.AnyWidget):  # type: ignore[misc]
        """The live page in a notebook; ``mechanism`` is the edited mechanism."""

        _esm = traitlets.Unicode("").tag(sync=True)
        _css = traitlets.Unicode("").tag(sync=True)
        toml = traitlets.Unicode("").tag(sync=True)
        source = traitlets.Unicode("").tag(sync=True)
        edit = traitlets.Unicode("").tag(sync=True)  # the page's edit: {K, drive}, JSON

        @property
        def mechanism(self) -> Mechanism:
            """The mechanism as edited on the widget (its file: :attr:`toml`)."""
            from graphkin.mechanisms import loads

            return loads(self.toml, source=self.source)

    return LiveWidget


_CLASS: list[Any] = []


def live(obj: Mechanism | str | Path) -> Any:
    """The live page of a mechanism as a notebook widget.

    Parameters
    ----------
    obj : Mechanism, str or Path
        A mechanism loaded from a file (``graphkin.load``) or shipped
        (``graphkin.examples.fourbar()``), or the file's path.

    Returns
    -------
    LiveWidget
        An ``anywidget.AnyWidget``: displayed, it is the page of ``graphkin
        live``; ``widget.toml`` is the edited file and ``widget.mechanism``
        the edited mechanism.

    Raises
    ------
    GraphkinError
        anywidget is not installed (one line: how to install it).
    InputError
        No file for the mechanism, or a mechanism that is not solved by a
        construction (as ``graphkin live`` says).
    """
    if not _CLASS:
        _CLASS.append(_widget_class())
    from graphkin.files import parse_toml
    from graphkin.mechanisms import loads

    text, source = _file_text(obj)
    mech = loads(text, source=source)
    data, js = live_data(mech, parse_toml(text, source), source)
    return _CLASS[0](_esm=widget_esm(data, js), _css=widget_css(), toml=text, source=source)
