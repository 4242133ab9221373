"""How each kind of element is drawn: the textbook's draftsman conventions as data.

Construction lines are thin, results bold; normal components of an
acceleration are dashed, tangential ones solid and the Coriolis component
dash-dotted (Fig. 4.11); the frame is hatched, pins are small circles and
sliders blocks.  Styles are plain dictionaries so that the scene (which knows
no matplotlib) can name them and the matplotlib layer can apply them.

References
----------
Uicker, Pennock & Shigley, 5th ed., Figs. 3.5, 4.4 and 4.11 (the look of
polygons and their components), Sec. 1.6 (the symbols of links and pairs).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any

from graphkin.construction import Role

if TYPE_CHECKING:  # matplotlib is imported only when something is drawn
    from matplotlib.typing import RcKeyType

    from graphkin.render.scene import Item

__all__ = ["STYLES", "HIGHLIGHT", "RC", "rc_context", "IMAGE_FILLS", "style_for_role",
           "FONT_PT", "SMALL_PT", "item_style"]

HIGHLIGHT = "#c62828"
"""Colour of the newest step on a teaching page."""

FONT_PT = 9.0
"""Size of point letters (points)."""
SMALL_PT = 7.0
"""Size of secondary labels (components, scale text)."""

INK = "#000000"
GREY = "#5a5a5a"

STYLES: dict[str, dict[str, Any]] = {
    # the mechanism
    "link": {"ec": INK, "fc": "#ffffff", "lw": 1.0},
    "plate": {"ec": INK, "fc": "#e9e9e9", "lw": 1.0},
    "ground": {"ec": INK, "fc": "none", "lw": 0.0, "hatch": "////"},
    "ground-line": {"color": INK, "lw": 1.0},
    "hatch": {"color": INK, "lw": 0.5},
    "bearing": {"ec": INK, "fc": "#ffffff", "lw": 0.9},
    "block": {"ec": INK, "fc": "#ffffff", "lw": 1.0},
    "slot": {"ec": INK, "fc": "#ffffff", "lw": 0.8},
    "pin": {"marker": "o", "ms": 5.0, "mfc": "#ffffff", "mec": INK, "mew": 0.9},
    "point": {"marker": "o", "ms": 3.2, "mfc": INK, "mec": INK, "mew": 0.5},
    "aux-point": {"marker": "o", "ms": 2.4, "mfc": GREY, "mec": GREY, "mew": 0.4},
    "pole": {"marker": "o", "ms": 4.2, "mfc": INK, "mec": INK, "mew": 0.5},
    "image-point": {"marker": "o", "ms": 2.6, "mfc": INK, "mec": INK, "mew": 0.4},
    # construction
    "given-line": {"color": INK, "lw": 1.0},
    "aux-line": {"color": GREY, "lw": 0.5},
    "ref-line": {"color": GREY, "lw": 0.5, "ls": (0, (6, 2, 1, 2))},
    "result-line": {"color": INK, "lw": 1.3},
    "arc": {"color": GREY, "lw": 0.5},
    "result-arc": {"color": INK, "lw": 0.9},
    "right-angle": {"color": GREY, "lw": 0.5},
    "angle-arc": {"color": INK, "lw": 0.6},
    "datum": {"color": GREY, "lw": 0.5, "ls": (0, (3, 2))},
    # vectors
    "vector-abs": {"color": INK, "lw": 1.5},
    "vector-rel": {"color": INK, "lw": 1.1},
    "vector-n": {"color": INK, "lw": 1.0, "ls": (0, (4, 2))},
    "vector-t": {"color": INK, "lw": 1.0},
    "vector-c": {"color": INK, "lw": 1.0, "ls": (0, (6, 2, 1.5, 2))},
    "vector-aux": {"color": GREY, "lw": 0.8},
    "rate": {"color": INK, "lw": 0.8},
    "infinity": {"color": INK, "lw": 1.0},
    # text
    "label": {"size": FONT_PT},
    "label-aux": {"size": SMALL_PT, "color": GREY},
    "label-small": {"size": SMALL_PT},
    "label-vector": {"size": FONT_PT},
    "number": {"size": FONT_PT + 1, "style": "italic"},
    "title": {"size": FONT_PT + 1, "weight": "bold"},
    "caption": {"size": SMALL_PT + 0.5},
    "table": {"size": SMALL_PT},
    "table-head": {"size": SMALL_PT, "weight": "bold"},
    "scale-bar": {"color": INK, "lw": 0.8},
    "cubic": {"color": INK, "lw": 1.1, "ls": (0, (8, 2))},
    "ball": {"marker": "o", "ms": 5.5, "mfc": "none", "mec": INK, "mew": 1.0},
    # the Kennedy circle (Fig. 3.22b)
    "kennedy-circle": {"color": GREY, "lw": 0.6},
    "kennedy-known": {"color": INK, "lw": 1.0},
    "kennedy-unknown": {"color": GREY, "lw": 0.6, "ls": (0, (3, 2))},
    "label-order": {"size": SMALL_PT, "color": INK},
}

IMAGE_FILLS = ("#fee6ce", "#9ecae1", "#c7e9c0", "#74c476", "#dadaeb", "#fdae6b")
"""Light fills for the images of links (one per link, in link order).

The first four print as distinct greys (luminance 0.92, 0.75, 0.86, 0.64): a
handout photocopied in black and white still tells the images apart.
"""

RC: dict[RcKeyType, Any] = {
    "svg.fonttype": "none",
    "svg.hashsalt": "graphkin",
    "font.family": "sans-serif",
    "font.sans-serif": ["DejaVu Sans"],
    "font.monospace": ["DejaVu Sans Mono"],
    "mathtext.fontset": "dejavusans",
    "hatch.linewidth": 0.5,
    "hatch.color": INK,
    "lines.solid_capstyle": "butt",
    "lines.dash_capstyle": "butt",
    "axes.unicode_minus": True,
    "pdf.fonttype": 42,
    # glyphs at their outline widths at every resolution: hinted, a line of digits set 9 %
    # narrower at 72 dpi and 9 % wider at 90 than in the SVG, so label boxes measured once
    # did not fit the PNG (two table columns ran together at 90 dpi)
    "text.hinting": "no_hinting",
}
"""Matplotlib settings of every graphkin drawing (deterministic SVG with real text)."""


_DEPTH = [0]
"""How many :func:`rc_context` are open (matplotlib's copies every setting on each entry)."""


@contextmanager
def rc_context() -> Iterator[None]:
    """Apply :data:`RC` for the duration of a drawing or a save.

    Inside another one it does nothing (graphkin never changes a setting
    between): measuring 1000 labels entered it 1000 times, 1.5 s of copying.
    """
    import matplotlib as mpl

    if _DEPTH[0]:
        yield
        return
    with mpl.rc_context(RC):
        _DEPTH[0] += 1
        try:
            yield
        finally:
            _DEPTH[0] -= 1


def style_for_role(role: Role | str, kind: str) -> str:
    """The style name of a construction element of ``kind`` with ``role``.

    Examples
    --------
    >>> style_for_role("auxiliary", "line"), style_for_role("result", "line")
    ('aux-line', 'result-line')
    """
    role = Role(role)
    if kind == "line":
        return {Role.GIVEN: "given-line", Role.RESULT: "result-line"}.get(role, "aux-line")
    if kind == "circle":
        return "result-arc" if role == Role.RESULT else "arc"
    return "aux-point" if role == Role.AUXILIARY else "point"


def item_style(it: Item, highlight: bool) -> dict[str, Any]:
    """An item's drawing style: its style's entry, its overrides, and the highlight.

    The one reading of :data:`STYLES` for every writer of a scene (matplotlib in
    :mod:`graphkin.render.mpl`, TikZ in :mod:`graphkin.render.tikz`), so both draw
    a step the same way.
    """
    st = dict(STYLES.get(it.style, {}))
    if it.style == "image":
        st = {"ec": "none", "fc": "#dddddd", "lw": 0.0}
    st.update(it.overrides)
    if highlight:
        for key in ("color", "ec", "mec"):
            if key in st and st[key] not in ("none",):
                st[key] = HIGHLIGHT
        if st.get("mfc", "#ffffff") not in ("#ffffff", "none"):
            st["mfc"] = HIGHLIGHT
        if "lw" in st and st.get("lw", 0) > 0:
            st["lw"] = st["lw"] + 0.5
        if it.kind == "text":
            st["color"] = HIGHLIGHT
    return st
