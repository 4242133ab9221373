"""The matplotlib side: a sheet becomes a Figure, each group one SVG ``<g>`` with the step's id.

No pyplot: figures are made with :class:`matplotlib.figure.Figure` directly,
so the library keeps no global state.  Every group of the scene becomes a
:class:`StepGroup` artist that writes ``<g id="step-07-C">`` around its
children; every label is a real ``<text>`` with its own id (``label-C``).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, 3.4, 4.3.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from matplotlib import patches
from matplotlib.artist import Artist
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.text import Text
from matplotlib.transforms import Bbox, TransformedBbox

from graphkin.render.scene import Group, Item, Panel
from graphkin.render.sheet import Sheet, build_sheet
from graphkin.render.sources import CURVATURE_PANELS, DIAGRAMS, as_source, optional_modules
from graphkin.render.style import STYLES, item_style, rc_context
from graphkin.render.text import plain, shown_size

__all__ = ["StepGroup", "Vector", "Drawing", "draw", "sheet_figure", "render_sheet"]


class StepGroup(Artist):
    """An artist that draws its children inside one SVG group with a stable id.

    Parameters
    ----------
    gid : str
        The group's id (a step's :attr:`~graphkin.construction.Step.step_id`).
    children : list of Artist
    """

    def __init__(self, gid: str, children: list[Artist], zorder: float = 2.0) -> None:
        super().__init__()
        self.set_gid(gid)
        self.set_zorder(zorder)
        self.children = list(children)
        self.step: Any = None

    def get_children(self) -> list[Artist]:
        """The artists of the group."""
        return list(self.children)

    def draw(self, renderer: Any) -> None:
        """Draw the children inside ``<g id=gid>``."""
        if not self.get_visible():
            return
        renderer.open_group("graphkin", gid=self.get_gid())
        for c in self.children:
            c.draw(renderer)
        renderer.close_group("graphkin")
        self.stale = False


class Vector(Line2D):
    """A vector drawn as a shaft and a filled head; its data are exactly ``[tail, tip]``.

    The shaft stops inside the head so that the point of the arrow is the
    vector's true tip at any line width.
    """

    def __init__(self, tail: np.ndarray, tip: np.ndarray, head: float, half: float,
                 **kw: Any) -> None:
        super().__init__([tail[0], tip[0]], [tail[1], tip[1]], **kw)
        d = np.asarray(tip, dtype=float) - np.asarray(tail, dtype=float)
        n = float(np.hypot(*d))
        u = d / n if n else np.array([1.0, 0.0])
        nrm = np.array([-u[1], u[0]])
        end = np.asarray(tip) - u * min(head * 0.7, n)
        style = {k: v for k, v in kw.items() if k in ("color", "lw", "ls", "zorder")}
        self._shaft = Line2D([tail[0], end[0]], [tail[1], end[1]], **style)
        base = np.asarray(tip) - u * head
        color = kw.get("color", "k")
        self._head = patches.Polygon(np.array([tip, base + half * nrm, base - half * nrm]),
                                     closed=True, fc=color, ec=color, lw=0.3)

    def set_figure(self, fig: Any) -> None:  # noqa: D102
        super().set_figure(fig)
        for a in getattr(self, "_shaft", None), getattr(self, "_head", None):
            if a is not None:
                a.set_figure(fig)

    def set_transform(self, t: Any) -> None:  # noqa: D102
        super().set_transform(t)
        for a in getattr(self, "_shaft", None), getattr(self, "_head", None):
            if a is not None:
                a.set_transform(t)

    def set_clip_path(self, path: Any, transform: Any = None) -> None:  # noqa: D102
        super().set_clip_path(path, transform)
        for a in getattr(self, "_shaft", None), getattr(self, "_head", None):
            if a is not None:
                a.set_clip_path(path, transform)

    @property
    def tip(self) -> np.ndarray:
        """The point of the arrow (data)."""
        return np.asarray(self.get_xydata())[-1]

    @property
    def tail(self) -> np.ndarray:
        """The start of the arrow (data)."""
        return np.asarray(self.get_xydata())[0]

    def draw(self, renderer: Any) -> None:
        """Draw the shaft and the head in one group."""
        if not self.get_visible():
            return
        renderer.open_group("vector", gid=self.get_gid())
        self._shaft.draw(renderer)
        self._head.draw(renderer)
        renderer.close_group("vector")
        self.stale = False


class Drawing(dict[str, Artist]):
    """What :func:`draw` returns: construction label -> its main artist.

    Attributes
    ----------
    figure : Figure
    texts : dict
        Label -> the :class:`~matplotlib.text.Text` of its letter.
    groups : dict
        Group id -> :class:`StepGroup`.
    sheet : Sheet or None
    """

    def __init__(self) -> None:
        super().__init__()
        self.figure: Figure | None = None
        self.texts: dict[str, Text] = {}
        self.groups: dict[str, StepGroup] = {}
        self.sheet: Sheet | None = None
        self.own_figure = False  # True when draw() made the figure (no ``ax`` given)

    def __repr__(self) -> str:
        """A short summary instead of every artist (never raises)."""
        try:
            panels = " ".join(p.name for p in self.sheet.panels) if self.sheet else "?"
            return f"<Drawing {panels}: {len(self)} labelled artists, {len(self.groups)} steps>"
        except Exception:
            return f"<Drawing at {id(self):#x}>"

    def save(self, path: Any, dpi: float = 150.0) -> Any:
        """Write the drawing; the suffix chooses the format: ``.svg``, ``.pdf``, ``.png``, ``.tex``.

        ``.tex`` is a TikZ picture that compiles with pdflatex
        (:mod:`graphkin.render.tikz`).  Returns the path written.

        Raises
        ------
        GraphkinError
            An unknown suffix, a drawing into axes of one's own as TikZ, or a handout
            page as TikZ.
        """
        from pathlib import Path

        from graphkin.render.svg import save

        p = Path(path)
        if p.suffix.lower() == ".tex":
            from graphkin.errors import GraphkinError
            from graphkin.render.tikz import drawing_tikz

            if not self.own_figure:
                raise GraphkinError("a drawing into axes of your own is saved with its figure "
                                    "(fig.savefig); TikZ writes a whole sheet")
            p.write_text(drawing_tikz(self), encoding="utf-8")
            return p
        if self.figure is None:
            from graphkin.errors import GraphkinError

            raise GraphkinError("this drawing has no figure to save")
        return save(self.figure, p, dpi=dpi)

    def _repr_svg_(self) -> str | None:
        """Jupyter: ``sol.draw("velocity")`` shows itself (a figure of your own shows itself)."""
        if not self.own_figure or self.figure is None:
            return None
        from graphkin.render.svg import to_bytes

        return to_bytes(self.figure).decode("utf-8")


_style = item_style


def _artists(it: Item, highlight: bool) -> list[Artist]:
    st = _style(it, highlight)
    xy = np.asarray(it.xy, dtype=float)
    out: list[Artist] = []
    if it.kind == "path":
        out.append(Line2D(xy[:, 0], xy[:, 1], color=st.get("color", "k"), lw=st.get("lw", 1.0),
                          ls=st.get("ls", "-"), solid_joinstyle="miter"))
    elif it.kind == "marker":
        out.append(Line2D(xy[:, 0], xy[:, 1], ls="none", marker=st.get("marker", "o"),
                          ms=st.get("ms", 3.0), mfc=st.get("mfc", "k"), mec=st.get("mec", "k"),
                          mew=st.get("mew", 0.5)))
    elif it.kind == "polygon":
        kw: dict[str, Any] = {"closed": True, "fc": st.get("fc", "none"),
                              "ec": st.get("ec", "k"), "lw": st.get("lw", 1.0),
                              "joinstyle": "miter"}
        if "hatch" in st:
            kw["hatch"] = st["hatch"]
            kw["ec"] = st.get("ec", "k")
        if "alpha" in st:
            kw["alpha"] = st["alpha"]
        out.append(patches.Polygon(xy, **kw))
    elif it.kind == "circle":
        out.append(patches.Circle(tuple(xy[0]), it.radius, fill=False,
                                  ec=st.get("color", "k"), lw=st.get("lw", 0.5),
                                  ls=st.get("ls", "-")))
    elif it.kind == "arc" and abs(it.theta2 - it.theta1) < 1.0:
        # a sliver of a huge circle (an inflection circle far larger than the panel):
        # its chord points, so no transform sees the far centre
        t = np.radians(np.linspace(it.theta1, it.theta2, 17))
        out.append(Line2D(xy[0, 0] + it.radius * np.cos(t), xy[0, 1] + it.radius * np.sin(t),
                          color=st.get("color", "k"), lw=st.get("lw", 0.5),
                          ls=st.get("ls", "-")))
    elif it.kind == "arc":
        out.append(patches.Arc(tuple(xy[0]), 2 * it.radius, 2 * it.radius,
                               theta1=it.theta1, theta2=it.theta2, ec=st.get("color", "k"),
                               lw=st.get("lw", 0.5), ls=st.get("ls", "-")))
    elif it.kind == "arrow":
        out.append(Vector(xy[0], xy[-1], it.head, it.width, color=st.get("color", "k"),
                          lw=st.get("lw", 1.0), ls=st.get("ls", "-")))
    elif it.kind == "text":
        kw = {"fontsize": shown_size(it.text, st.get("size", 8.0)),
              "color": st.get("color", "k"),
              "ha": it.ha, "va": it.va}
        if "family" in st:
            kw["family"] = st["family"]
        if "weight" in st:
            kw["fontweight"] = st["weight"]
        if "style" in st:
            kw["fontstyle"] = st["style"]
        out.append(Text(xy[0, 0], xy[0, 1], it.text, **kw))
    for a in out:
        if it.gid:
            a.set_gid(it.gid)
    return out


def _add_group(ax: Axes, g: Group, drawing: Drawing,
               inner: patches.Patch | None = None) -> StepGroup:
    """Add a group's artists; lines and shapes are clipped to ``inner`` (when given).

    ``inner`` is the panel less its title and scale-bar strips: a construction
    line or a large circle stops short of the panel's title.
    """
    children: list[Artist] = []
    # one clip box per rectangle, not one per artist (300 lettered points made 10 000)
    clips: dict[int, tuple[Any, Any]] = ax.__dict__.setdefault("_graphkin_clips", {})
    for it in g.items:
        arts = _artists(it, g.highlight)
        clip = inner if inner is not None and it.kind != "text" else ax.patch
        if id(clip) not in clips:  # what Artist.set_clip_path makes of a Rectangle
            clips[id(clip)] = (clip, TransformedBbox(Bbox.unit(), clip.get_transform()))
        for a in arts:
            a.set_transform(ax.transData)
            a.set_figure(ax.figure)
            a.axes = ax
            if isinstance(a, Vector) or not isinstance(clip, patches.Rectangle):
                a.set_clip_path(clip)
            else:
                a.set_clip_path(None)
                a.set_clip_box(clips[id(clip)][1])
            children.append(a)
        if it.key is not None and arts:
            main = arts[0]
            if it.kind == "text":
                assert isinstance(main, Text)  # _artists makes one Text of a text item
                drawing.texts.setdefault(_key(g, it.key), main)
                for alias in it.aliases:  # far points listed in one label
                    drawing.texts.setdefault(_key(g, alias), main)
            else:
                drawing.setdefault(_key(g, it.key), main)
                for alias in it.aliases:
                    drawing.setdefault(_key(g, alias), main)
    sg = StepGroup(g.gid, children, g.z)
    sg.step = g.step
    ax.add_artist(sg)
    drawing.groups[g.gid] = sg
    return sg


def _key(g: Group, key: str) -> str:
    pre = g.gid.split("step-")[0] if "step-" in g.gid else ""
    return pre + key if pre and not key.startswith(pre) else key


def _panel_axes(fig: Figure, sheet: Sheet, p: Panel) -> Axes:
    W, H = sheet.size
    x, y = p.origin
    w, h = p.size
    ax = fig.add_axes((x / W, y / H, w / W, h / H))
    _setup_axes(ax, p)
    return ax


def _setup_axes(ax: Axes, p: Panel) -> None:
    ax.set_axis_off()
    ax.set_xlim(p.view[0], p.view[2])
    ax.set_ylim(p.view[1], p.view[3])
    ax.set_gid(f"panel-{p.prefix}{p.name}" if not p.prefix.startswith(p.name) else
               f"panel-{p.name}")


def render_sheet(sheet: Sheet) -> Drawing:
    """Make the figure of a laid-out sheet (a handout page draws its band too)."""
    with rc_context():
        fig = Figure(figsize=sheet.size)
        drawing = Drawing()
        drawing.figure = fig
        drawing.own_figure = True
        drawing.sheet = sheet
        if sheet.title and sheet.page is None:  # a handout's title is in its title block
            left, top = sheet.title_offset or (0.0, sheet.size[1])
            t = fig.text((left + 0.12) / sheet.size[0], (top - 0.22) / sheet.size[1],
                         plain(sheet.title),
                         ha="left", va="center", fontsize=STYLES["title"]["size"] + 1,
                         fontweight="bold")
            t.set_gid("sheet-title")
        for p in sheet.panels:
            ax = _panel_axes(fig, sheet, p)
            inner = None
            if p.inner is not None:
                x0, y0, x1, y1 = p.inner
                inner = patches.Rectangle((x0, y0), x1 - x0, y1 - y0, transform=ax.transData)
            for g in p.groups:
                frame = g.gid.startswith(f"{p.prefix}title-") \
                    or g.gid.startswith(f"{p.prefix}scale-")
                _add_group(ax, g, drawing, None if frame else inner)
        if sheet.page is not None:
            from graphkin.render.handout import render_page

            render_page(fig, sheet)
        elif sheet.rows:
            from graphkin.render.results import full_table
            from graphkin.render.table import add_table, table_size

            tab = full_table(sheet.rows)
            add_table(fig, tab, sheet.table_origin, table_size(tab), sheet.size)
        if sheet.page is None and sheet.legend:
            from graphkin.render.legend import box_axes, draw_legend

            ax = box_axes(fig, sheet.size, sheet.legend_box, "legend")
            draw_legend(ax, sheet.legend, sheet.legend_cols, sheet.legend_box[3])
    return drawing


def sheet_figure(obj: Any, diagram: str = "all", **kw: Any) -> Figure:
    """The figure of a whole sheet (see :func:`draw`)."""
    d = draw(obj, diagram, **kw)
    assert d.figure is not None
    return d.figure


def draw(obj: Any, diagram: str = "posture", ax: Axes | None = None, upto: int | None = None,
         *, highlight: int | None = None, table: bool | None = None,
         values: dict[str, Any] | None = None, max_inches: float | None = None,
         link: str | None = None, sheet: str | None = None) -> Drawing:
    """Draw a diagram of a mechanism, a solution or a construction.

    Parameters
    ----------
    obj : Mechanism, Solution or Construction
        A mechanism is solved first.  A bare construction is drawn alone (no
        mechanism), evaluated by itself or with ``values``.
    diagram : str
        ``posture``, ``velocity``, ``acceleration``, ``centers``,
        ``curvature``, several joined by ``+`` (``"posture+velocity"``), or
        ``all`` (a sheet with every diagram).
    ax : matplotlib Axes, optional
        Draw only the diagram's own panel into these axes (their limits are
        set to the panel's view; the aspect is made equal).  Without ``ax`` a
        new Figure holds the whole sheet, each panel to a round scale.
    upto : int, optional
        Draw the construction only up to step ``upto`` (inclusive):
        "step k of n".
    highlight : int, optional
        A step to draw in the highlight colour.
    table : bool, optional
        Add the results table (default: yes for a sheet, no into ``ax``).
    values : dict, optional
        Values for a bare construction's inputs.
    max_inches : float, optional
        The largest side of a panel.
    link : str, optional
        The link whose curvature construction is drawn (default: the first
        coupler that turns).
    sheet : str, optional
        ``a4`` or ``letter``: a handout page of that paper at round scales,
        with a title block and a compact results table.

    Returns
    -------
    Drawing
        A dict of construction label -> main artist (a marker, a line, an
        arc, a :class:`Vector`), with ``.texts`` (label -> Text),
        ``.groups`` (id -> :class:`StepGroup`) and ``.figure``.

    Raises
    ------
    DiagramUnavailable
        No such diagram for this object (no rates, or its module is missing).

    Examples
    --------
    >>> import graphkin
    >>> from graphkin.render import draw
    >>> mech = graphkin.examples.fourbar()
    >>> d = draw(mech, "posture")
    >>> d["B"].get_xydata().round(4).tolist()     # B = A + 4 (cos 120°, sin 120°)
    [[-2.0, 3.4641]]
    >>> d.groups["step-07-C"].get_gid()
    'step-07-C'

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Fig. 2.14), 3.4 (Fig. 3.5),
    4.3 (Fig. 4.4).
    """
    if diagram == "forces":  # free bodies and force polygons (graphkin.render.forces)
        from graphkin.render.forces import draw_forces

        return draw_forces(obj, table=table is not False, upto=upto, sheet=sheet)
    wanted = tuple(dict.fromkeys(
        "curvature" if d in CURVATURE_PANELS else d
        for d in (DIAGRAMS if diagram == "all" else diagram.split("+"))
        if d in optional_modules or d in CURVATURE_PANELS))
    src = as_source(obj, values=values, diagrams=wanted, link=link)
    if ax is None and sheet is not None:
        from graphkin.render.handout import build_paper_sheet

        return render_sheet(build_paper_sheet(src, diagram, sheet, upto=upto,
                                              highlight=highlight,
                                              table=True if table is None else table))
    if ax is None:
        laid = build_sheet(src, diagram, upto=upto, highlight=highlight,
                           table=True if table is None else table, max_inches=max_inches)
        return render_sheet(laid)
    fig = ax.figure
    bb = ax.get_position()  # relative to the (sub)figure that holds the axes
    if isinstance(fig, Figure):
        fw, fh = fig.get_size_inches()
    else:  # a subfigure
        fw, fh = fig.bbox.width / fig.dpi, fig.bbox.height / fig.dpi
    room = max(min(bb.width * fw, bb.height * fh) - 1.0, 0.8)
    into = build_sheet(src, diagram, upto=upto, highlight=highlight, table=False,
                       max_inches=max_inches or room, title="")
    name = diagram if diagram in [p.name for p in into.panels] else into.panels[0].name
    if diagram == "all":
        name = into.panels[0].name
    panel = into.panel(name)
    drawing = Drawing()
    drawing.figure = fig if isinstance(fig, Figure) else fig.figure
    drawing.sheet = into
    with rc_context():
        _setup_axes(ax, panel)
        ax.set_aspect("equal", adjustable="datalim")
        for g in panel.groups:
            _add_group(ax, g, drawing)
    return drawing
