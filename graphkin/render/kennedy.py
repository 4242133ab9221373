"""The Kennedy circle (Fig. 3.22b) drawn beside the instant centers of a mechanism.

The links are numbered around a circle; each pair of links is a chord.  A
chord is drawn solid once its instant center is known (by inspection or by
Kennedy's theorem), dashed while it is not; the small number on each solid
chord is the order in which its center was found.  Its data come from
:meth:`graphkin.kinematics.instant_centers.InstantCenters.kennedy_circle`.

Group ids (stable, read back by tests): ``kennedy-circle`` (the circle and the
link numbers, ``kennedy-link-K``), ``kennedy-I13`` (each chord), and
``kennedy-order-I13`` (the order of discovery on a chord).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.13, Fig. 3.22b (the Kennedy circle
of a four-bar) and Fig. 3.23.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphkin.render.scene import Item, LabelRequest, Panel, safe_id

__all__ = ["kennedy_panel", "RADIUS"]

RADIUS = 0.85
"""Radius of the Kennedy circle, in inches of paper."""

_CHAR = 0.1
"""A link name's width per letter, in inches (the 11 pt italic of ``number``)."""


def kennedy_panel(ic: Any, prefix: str = "") -> Panel:
    """A panel with the Kennedy circle of ``ic`` (an InstantCenters), drawn in inches.

    Parameters
    ----------
    ic : InstantCenters
    prefix : str
        Prepended to every group id (sheets with several diagrams).
    """
    data = ic.kennedy_circle()
    links = [str(x) for x in data["links"]]
    pos = {str(k): np.asarray(v, dtype=float) * RADIUS for k, v in data["positions"].items()}
    p = Panel("kennedy", "kennedy", "Kennedy circle", "in", prefix=prefix)
    r = RADIUS
    # a link named by a word ("crank") reaches out sideways from its vertex: room for it
    side = max(0.45, 0.1 + _CHAR * max((len(x) for x in links), default=1))
    p.view = (-r - side, -r - 0.45, r + side, r + 0.7)
    p.bbox = (-r, -r, r, r)
    g = p.group(f"{prefix}kennedy-circle", 1.0, key="Kennedy circle")
    g.items.append(Item("circle", np.array([[0.0, 0.0]]), "kennedy-circle", radius=r,
                        key="Kennedy circle", gid=f"{prefix}kennedy-circle-line"))
    for lid in links:
        q = pos[lid]
        g.items.append(Item("marker", np.array([q]), "point", key=f"kennedy {lid}"))
        u = q / max(float(np.hypot(*q)), 1e-12)
        at, ha, va = q + 0.16 * u, "center", "center"
        if len(lid) > 2:
            # a name longer than a link number ("crank") is set outward from its
            # vertex, by its near side 0.1 in off the circle: centred, it ran back
            # over the vertex's dot and the chords
            at = q + 0.1 * u
            ha = "left" if u[0] > 0.3 else "right" if u[0] < -0.3 else "center"
            va = "bottom" if u[1] > 0.3 else "top" if u[1] < -0.3 else "center"
        g.items.append(Item("text", np.array([at]), "number",
                            gid=f"{prefix}kennedy-link-{safe_id(lid)}", text=lid,
                            key=f"kennedy link {lid}", ha=ha, va=va))
    edges = sorted(data["edges"], key=lambda e: (e["order"] is None, e["order"] or 0))
    for e in edges:
        a, b = (str(x) for x in e["pair"])
        if a not in pos or b not in pos:
            continue
        lab = str(e["label"])
        cg = p.group(f"{prefix}kennedy-{safe_id(lab)}", 2.0, key=f"kennedy {lab}")
        style = "kennedy-known" if e["known"] else "kennedy-unknown"
        cg.items.append(Item("path", np.array([pos[a], pos[b]]), style, key=f"kennedy {lab}"))
        if e["order"] is not None:
            # the order of discovery, on the chord a little off its middle (diagonals cross)
            t = 0.5 if len(links) == 2 else 0.32
            at = pos[a] + t * (pos[b] - pos[a])
            p.labels.append(LabelRequest(f"{e['order']}", at, "label-order",
                                         f"{prefix}kennedy-order-{safe_id(lab)}", cg,
                                         key=f"order {lab}", gap=0.02))
    found = [e for e in edges if e["order"] is not None]
    entries = [f"{e['order']}. {_pretty(str(e['label']))}" for e in found]
    rows = ["   ".join(entries[i:i + 4]) for i in range(0, len(entries), 4)]
    if rows:
        depth = 0.3 + 0.14 * (len(rows) - 1)
        x0, y0, x1, y1 = p.view
        p.view = (x0, y0 - 0.14 * (len(rows) - 1), x1, y1)
        g.items.append(Item("text", np.array([[0.0, -r - depth + 0.07 * (len(rows) - 1)]]),
                            "caption", gid=f"{prefix}kennedy-order", text="\n".join(rows),
                            key="kennedy order"))
    return p


def _pretty(label: str) -> str:
    """``I13`` -> ``I₁₃`` (both digits subscript)."""
    if label.startswith("I") and label[1:].replace("-", "").isdigit():
        return "I" + label[1:].translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
    return label
