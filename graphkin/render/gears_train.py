"""A gear train drawn as the book prints its analysis: the members' speeds and Table 7.3's layout.

A gear train has no layout to construct; the book gives its answer as tables
(Sec. 7.16, Tables 7.3-7.5).  :func:`train_figure` sets two of them on one
sheet with the one table writer of every figure (:mod:`graphkin.render.table`):

* ``members``: every gear and arm, its teeth (or radius), its angular
  velocity (or turn) and sense, the given ones marked, and the train value
  of each gear seen from its arm (the formula method, Eq. 7.25);
* ``tabular``: the book's three steps (gears fixed to the arm, the arm
  fixed, the total) with the factors as the book prints them,
  ``(20/80)(-40/20)ω2/3``, when the train has one arm and two given motions.

Group ids read back by tests: ``members-table`` and ``tabular-table`` with
their cells ``row-KEY-C``.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.15-7.16, Tables 7.3-7.5.
"""

from __future__ import annotations

from typing import Any

from graphkin.gears.train import FRAME, Train
from graphkin.render.table import Table, add_table, table_size
from graphkin.text import g6

__all__ = ["train_tables", "train_figure"]

_GAP = 0.25
"""Inches between the two tables and around them."""


def train_tables(train: Train, data: dict[str, Any]) -> list[tuple[str, Table]]:
    """The tables of a train's report (``data`` is :func:`graphkin.output.trains.train_json`)."""
    u = data["unit"]
    w = "Δθ" if train.turns else "ω"
    train_value = {f["last"]: f for f in data["formula"]}
    rows, keys = [], []
    for m, d in data["members"].items():
        f = train_value.get(m)
        seen = "" if f is None else (
            f"θ'{f['last']}{f['first']}/{f['arm']} = {f['fraction']}" if f["arm"] != FRAME
            else f"θ'{f['last']}{f['first']} = {f['fraction']}")
        rows.append((m, d["kind"], "" if d["size"] is None else g6(d["size"]),
                     f"{g6(d['omega'])} {u} {d['sense']}".rstrip(),
                     "given" if m in train.given else "", seen))
        keys.append(f"member-{m}")
    size = "teeth" if data["size"] == "teeth" else "radius"
    out = [("members", Table(("member", "", size, w, "", "formula, Eq. (7.25)"), rows, keys,
                             ("left", "left", "right", "right", "left", "left"),
                             title=f"{data['title'] or 'Gear train'}: counterclockwise "
                                   "positive"))]
    tab = data["table"]
    if tab is not None:
        head = ("Step", *[("Arm " if m == tab["arm"] else "Gear ") + m for m in tab["columns"]])
        body = [(r["step"], *r["cells"]) for r in tab["rows"]]
        foot = (f"{w}{tab['arm']} = {g6(tab['omega_arm'])} {u}, {w}{tab['turned']}/"
                f"{tab['arm']} = {g6(tab['omega_turned_relative'])} {u}")
        out.append(("tabular", Table(head, body, [f"step-{i + 1}" for i in range(len(body))],
                                     ("left",) * len(head),
                                     title="Tabular analysis (Sec. 7.16)", foot=foot)))
    return out


def train_figure(train: Train, data: dict[str, Any]) -> Any:
    """A matplotlib figure holding :func:`train_tables`, one under the other."""
    from matplotlib.figure import Figure

    tables = train_tables(train, data)
    sizes = [table_size(t) for _, t in tables]
    width = max(s[0] for s in sizes) + 2 * _GAP
    height = sum(s[1] for s in sizes) + _GAP * (len(sizes) + 1)
    fig = Figure(figsize=(width, height))
    y = height
    for (gid, t), s in zip(tables, sizes):
        y -= _GAP + s[1]
        add_table(fig, t, (_GAP, y), s, (width, height), gid=gid)
    return fig
