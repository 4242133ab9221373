"""Which letters belong to which point: a point's letters stand nearer it than any other.

The label engine (:mod:`graphkin.render.labels`) keeps a point's letters off
every other lettered point's side: a place whose centre is nearer another
lettered point of the panel is never clean, so the letters read as their own
point's (Sec. 1.6: the lettering must be read as written).
:func:`astray_labels` measures a placed panel the same way.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.6 (lettering a kinematic diagram).
"""

from __future__ import annotations

import numpy as np

from graphkin.render.scene import LabelRequest, Panel
from graphkin.render.style import STYLES

__all__ = ["labelled_points", "nearer_another", "astray_labels", "PRIORITY"]

PRIORITY = {"label": 0, "number": 1, "label-vector": 2, "label-aux": 3, "label-small": 4}
"""The order labels are placed in, by style (points first)."""


def _is_point_label(panel: Panel, req: LabelRequest, markers: np.ndarray) -> bool:
    """A point's letters: a near anchor (no far arrow) on a marker of the panel."""
    if req.arrow is not None or req.center or req.parts or not len(markers):
        return False
    a = panel.to_paper(np.asarray([req.anchor], dtype=float))[0]
    return bool(np.any(np.hypot(markers[:, 0] - a[0], markers[:, 1] - a[1]) <= _SAME_POINT))


def labelled_points(panel: Panel) -> np.ndarray:
    """The paper places (inches) of the panel's lettered points: markers with a label.

    A point's letters must stand nearer their own point than any other lettered
    point, or a reader takes them for the other's (Sec. 1.6: the lettering must be
    read as written); :func:`graphkin.render.labels._spot` holds every point label to that.
    """
    ms = [panel.to_paper(it.xy)[0] for g in panel.groups for it in g.items
          if it.kind == "marker" and len(it.xy)]
    markers = np.asarray(ms, dtype=float).reshape(-1, 2)
    pts = [panel.to_paper(np.asarray([r.anchor], dtype=float))[0] for r in panel.labels
           if _is_point_label(panel, r, markers)]
    return np.asarray(pts, dtype=float).reshape(-1, 2)


def nearer_another(pts: np.ndarray, a: np.ndarray, cx: np.ndarray,
                   cy: np.ndarray, half: tuple[float, float] | None = None
                   ) -> np.ndarray | None:
    """Which candidate centres stand nearer another lettered point than their own at ``a``.

    With ``half`` (the box's half width and height) the distances are the
    box's own, from its nearest edge: a box that touches its point is still
    attached to it where a crowded place has no other clear spot.  None when
    ``a`` is no lettered point (a vector's or a rate's label).
    """
    if not len(pts):
        return None
    own = np.hypot(pts[:, 0] - a[0], pts[:, 1] - a[1]) <= _SAME_POINT
    if not np.any(own):
        return None
    others = pts[~own]
    if not len(others):
        return np.zeros(cx.shape, dtype=bool)
    hw, hh = half if half is not None else (0.0, 0.0)

    def gap(px: np.ndarray, py: np.ndarray) -> np.ndarray:
        return np.hypot(np.maximum(np.abs(cx[:, None] - px[None, :]) - hw, 0.0),
                        np.maximum(np.abs(cy[:, None] - py[None, :]) - hh, 0.0))

    d_own = gap(np.array([a[0]]), np.array([a[1]]))[:, 0]
    d_other = np.min(gap(others[:, 0], others[:, 1]), axis=1)
    # nearer by a clear margin: a box as near both but for round-off is its own point's
    return d_other < d_own - _NEARER  # type: ignore[no-any-return]


_SAME_POINT = 1e-6
"""Anchors closer than this (inches) are one point (coincident points lettered together)."""
_NEARER = 1e-9
"""A box is nearer another point only when nearer by more than this (inches)."""


def astray_labels(panel: Panel) -> list[tuple[str, str]]:
    """The point labels of a placed panel that stand nearer another lettered point.

    Returns ``(gid, text)`` of each point label whose box centre is nearer some
    other lettered point of the panel than its own, and whose box is not nearer
    its own point than any other either (not attached to it): a reader would
    take it for the other's.  Empty when every letter reads as its point's.
    """
    ms = [panel.to_paper(it.xy)[0] for g in panel.groups for it in g.items
          if it.kind == "marker" and len(it.xy)]
    markers = np.asarray(ms, dtype=float).reshape(-1, 2)
    points = labelled_points(panel)
    out = []
    seen: dict[tuple[int, str | None], int] = {}
    # labels were placed in this order, each appending its text to its group: the k-th
    # request of a gid in a group is the k-th text of that gid there
    for i in sorted(range(len(panel.labels)),
                    key=lambda i: (PRIORITY.get(panel.labels[i].style, 4), i)):
        r = panel.labels[i]
        k = seen.get((id(r.group), r.gid), 0)
        seen[(id(r.group), r.gid)] = k + 1
        if not _is_point_label(panel, r, markers):
            continue
        texts = [it for it in r.group.items if it.kind == "text" and it.gid == r.gid]
        if k >= len(texts):
            continue
        put = texts[k]
        a = panel.to_paper(np.asarray([r.anchor], dtype=float))[0]
        c = panel.to_paper(put.xy)[0]
        from graphkin.render.labels import text_size

        w, h = text_size(put.text, float(STYLES.get(put.style, {}).get("size", 8.0)), put.style)
        cx, cy = np.array([c[0]]), np.array([c[1]])
        astray = nearer_another(points, a, cx, cy)
        attached = nearer_another(points, a, cx, cy, (w / 2, h / 2))
        if astray is not None and bool(astray[0]) and attached is not None and \
                bool(attached[0]):
            out.append((r.gid, put.text))
    return out
