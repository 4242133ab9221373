"""Free-body diagrams and force polygons, laid out as the book's Fig. 11.5.

(a) the mechanism with its loads, to a length scale; (b-d) the free-body
diagram of each moving link, to the same length scale, every force drawn on
its line of action (dashed), with the concurrency point of a three-force
member (Fig. 11.5e) and the drive's torque; then the force polygon of each
link, to one stated force scale, each closing (Σ F = 0, Fig. 11.5f).  With
several loaded links the polygons of each partial analysis (Sec. 12.5) come
first, then those of the totals.

Every artist has a gid: ``forces-mechanism``, ``fbd-3``, ``fbd-3-F_23``,
``polygon-3``, ``polygon-3-F_23`` (the arrow, tail to head at the force scale),
``concurrency-3``, ``force-scale``.

References
----------
Uicker, Pennock & Shigley, 5th ed., Figs. 11.5, 11.8, 12.8, 12.10.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from graphkin.render.scale import choose_scale, fmt
from graphkin.render.style import FONT_PT, GREY, HIGHLIGHT, INK, SMALL_PT, rc_context

if TYPE_CHECKING:
    from graphkin.forces.solve import ForceSolution
    from graphkin.render.mpl import Drawing

__all__ = ["draw_forces", "force_name"]

PANEL_IN = 3.1
"""Side of one panel (inches)."""
_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
_LOAD = "#1f4e9c"
_INERTIA = "#9c2f1f"
_DRIVE = "#2e7d32"


def force_name(label: str) -> str:
    """A construction label as the book writes it: ``F_34′`` -> ``F₃₄′``.

    Examples
    --------
    >>> force_name("F_34′"), force_name("-m3A_G3"), force_name("T_12")
    ('F₃₄′', '−m₃A_G₃', 'T₁₂')
    """
    head, sep, rest = label.partition("_")
    if label.startswith("-m"):
        body = label[2:]
        k = body.index("A_")
        return "−m" + body[:k].translate(_SUB) + "A_" + body[k + 2:].translate(_SUB)
    if not sep:
        return label.replace("$", r"\$")
    digits = "".join(ch for ch in rest if ch.isdigit())
    tail = rest[len(digits):]
    return (head + digits.translate(_SUB) + tail).replace("$", r"\$")


def _unit(v: np.ndarray) -> np.ndarray:
    n = float(np.hypot(*v))
    return v / n if n > 0 else np.array([1.0, 0.0])


class _Panel:
    """An axes placed on the figure so that one inch of paper is ``per_inch`` data units."""

    def __init__(self, fig: Any, col: int, row: int, nrows: int, center: np.ndarray,
                 per_inch: float, title: str, gid: str) -> None:
        fw, fh = fig.get_size_inches()
        x0 = 0.25 + col * (PANEL_IN + 0.2)
        y0 = fh - 0.75 - (row + 1) * (PANEL_IN + 0.45)
        self.ax = fig.add_axes((x0 / fw, y0 / fh, PANEL_IN / fw, PANEL_IN / fh))
        half = PANEL_IN * per_inch / 2
        self.ax.set_xlim(center[0] - half, center[0] + half)
        self.ax.set_ylim(center[1] - half, center[1] + half)
        self.ax.set_aspect("equal")
        self.ax.set_axis_off()
        self.ax.set_gid(gid)
        self.ax.set_title(title, fontsize=FONT_PT, loc="left")
        self.per_inch = per_inch

    def arrow(self, tail: np.ndarray, head: np.ndarray, color: str, gid: str,
              lw: float = 1.3) -> Any:
        from matplotlib.patches import FancyArrowPatch

        a = FancyArrowPatch(tuple(tail), tuple(head), arrowstyle="-|>", mutation_scale=9,
                            color=color, lw=lw, shrinkA=0, shrinkB=0)
        a.set_gid(gid)
        self.ax.add_patch(a)
        return a

    def text(self, at: np.ndarray, s: str, gid: str, color: str = INK,
             size: float = FONT_PT, offset: tuple[float, float] = (3, 3)) -> Any:
        t = self.ax.annotate(s, tuple(at), xytext=offset, textcoords="offset points",
                             fontsize=size, color=color)
        t.set_gid(gid)
        return t


def _links(ax: Any, fs: ForceSolution, only: str | None, gid: str) -> None:
    """The links as lines (a plate for three or more points), pins as small circles."""
    from matplotlib.patches import Polygon

    sol = fs.solution
    mech = fs.mechanism
    for lid in mech.moving if only is None else [only]:
        names = [n for n in mech.links[lid].points if n not in mech.helper_points]
        pts = np.array([sol.position(n, lid) for n in names]) if names else np.zeros((0, 2))
        if len(pts) >= 3:
            c = pts.mean(axis=0)
            order = np.argsort(np.arctan2(pts[:, 1] - c[1], pts[:, 0] - c[0]))
            poly = Polygon(pts[order], closed=True, ec=INK, fc="#eeeeee", lw=1.0)
            poly.set_gid(f"{gid}-link-{lid}")
            ax.add_patch(poly)
        elif len(pts) == 2:
            (ln,) = ax.plot(pts[:, 0], pts[:, 1], color=INK, lw=2.0, solid_capstyle="round")
            ln.set_gid(f"{gid}-link-{lid}")
        for j in fs.joints:
            if lid in (j.lo, j.hi) and j.kind != "pin":
                p = fs.geometry.points[j.point]
                (b,) = ax.plot([p[0]], [p[1]], marker="s", ms=9, mfc="white", mec=INK,
                               mew=0.9)
                b.set_gid(f"{gid}-block-{j.key}")
        for n, p in zip(names, pts):
            (m,) = ax.plot([p[0]], [p[1]], marker="o", ms=4, mfc="white", mec=INK, mew=0.8)
            m.set_gid(f"{gid}-point-{n}")
            t = ax.annotate(n, tuple(p), xytext=(-4, -11), textcoords="offset points",
                            fontsize=SMALL_PT)
            t.set_gid(f"{gid}-label-{n}")
    if only is None:
        span = float(mech.scale)
        for j in fs.joints:  # the guides of the sliders (Fig. 11.8a)
            if j.key in fs.geometry.along and j.key in fs.geometry.base:
                b, u = fs.geometry.base[j.key], fs.geometry.along[j.key]
                pt = fs.geometry.points[j.point]
                t0 = float((pt - b) @ u)
                ends = np.array([b + (t0 - span) * u, b + (t0 + span) * u])
                (gl,) = ax.plot(ends[:, 0], ends[:, 1], color=GREY, lw=0.8, zorder=0)
                gl.set_gid(f"{gid}-guide-{j.key}")
        for p in mech.pins:
            if "1" in p.links:
                xy = sol.position(p.name)
                (g,) = ax.plot([xy[0]], [xy[1]], marker="^", ms=9, mfc="none", mec=INK,
                               mew=0.8, zorder=0)
                g.set_gid(f"{gid}-ground-{p.name}")


_Force = tuple[str, np.ndarray, np.ndarray, str, tuple[str, ...]]
_Item = tuple[str, np.ndarray, str, tuple[str, ...]]


def _forces_on(fs: ForceSolution, lid: str) -> list[_Force]:
    """Every force on a link, loads first.

    Each as (label, force, point of application, colour, the construction
    labels that find it); a given load has no construction label.
    """
    sol = fs.solution
    mech = fs.mechanism
    out: list[_Force] = []
    for ld in mech.loads:
        if ld.link == lid and ld.force is not None and ld.point is not None:
            out.append((_load_name(fs, ld), np.asarray(ld.force, float),
                        np.asarray(sol.position(ld.point, lid)), _LOAD, ()))
    if lid in fs.inertia:
        f = fs.inertia[lid]
        g = mech.inertia[lid].center
        out.append((f"−m{lid}A_{g}".translate(_SUB), f.force, f.point, _INERTIA, ()))
    if mech.gravity is not None and lid in mech.inertia:
        inr = mech.inertia[lid]
        out.append((f"W{lid}".translate(_SUB), inr.mass * np.asarray(mech.gravity),
                    np.asarray(sol.position(inr.center, lid)), _LOAD, ()))
    for j in fs.joints:
        if lid in (j.lo, j.hi):
            w = fs.forces[j.key][:2]
            out.append((force_name(j.label(lid)), w if lid == j.hi else -w,
                        fs.point(j.key), INK, (j.label(lid), j.label(j.other(lid)))))
    for d in mech.drives:
        if d.link == lid and d.kind == "position" and d.slider is not None:
            key = next(j.key for j in fs.joints if j.source is d.slider)
            u = fs.geometry.along[key]
            out.append((f"F_{d.slider.point}", fs.drives[lid][1] * u,
                        fs.geometry.points[d.slider.point], _DRIVE,
                        (f"F_{d.slider.point}·u",)))
    return out


def _load_name(fs: ForceSolution, ld: Any) -> str:
    from graphkin.forces.graphic import applied_labels

    for label, _, src in applied_labels(fs.mechanism, fs.dynamic).get(ld.link, []):
        if src is ld:
            return force_name(label)
    return "P"


def _extent(points: list[np.ndarray]) -> tuple[np.ndarray, float]:
    a = np.array(points)
    lo, hi = a.min(axis=0), a.max(axis=0)
    return (lo + hi) / 2, float(max(hi - lo))


def draw_forces(obj: Any, *, table: bool = True, upto: int | None = None) -> Drawing:
    """Draw the mechanism with its loads, each link's free body and force polygon.

    Parameters
    ----------
    obj : Mechanism, Solution or ForceSolution
    table : bool
        Write the results (joint forces, the drive's torque) under the title.
    upto : int, optional
        Draw only what the force construction has found up to step ``upto``
        (inclusive), the newest step's forces in the highlight colour: a
        started drawing to hand out, or one frame of ``graphkin steps -d forces``.

    Returns
    -------
    Drawing
        Label -> artist (``fbd-3-F₂₃``-style gids), with ``.figure``.

    Raises
    ------
    DiagramUnavailable
        The file has no loads and no mass properties.
    """
    import matplotlib.pyplot as plt  # noqa: F401  (the backend)
    from matplotlib.figure import Figure
    from matplotlib.patches import Arc

    from graphkin.forces.report import forces_report
    from graphkin.forces.solve import ForceSolution
    from graphkin.render.mpl import Drawing
    from graphkin.render.sources import DiagramUnavailable

    if isinstance(obj, ForceSolution):
        fs = obj
    else:
        sol = obj.solve() if hasattr(obj, "pins") else obj
        got = forces_report(sol)
        if got is None:
            raise DiagramUnavailable("no forces diagram: the file has no [[loads]] and no "
                                     "[inertia.N] (docs/forces.md)", diagram="forces")
        fs = got
    mech = fs.mechanism
    sol = fs.solution
    moving = list(mech.moving)
    polys: list[tuple[str, str, list[_Item]]] = []
    known: set[str] | None = None
    newest: set[str] = set()
    if upto is not None and fs.construction is not None:
        steps = fs.construction.steps[: upto + 1]
        known = {o for st_ in steps for o in st_.outputs}
        newest = set(steps[-1].outputs) if steps else set()

    def seen(raw: tuple[str, ...]) -> bool:
        return known is None or not raw or any(r in known for r in raw)

    def hue(raw: tuple[str, ...], color: str) -> str:
        return HIGHLIGHT if any(r in newest for r in raw) else color

    for p in fs.partials if len(fs.partials) > 1 else []:
        env = fs.built.values if fs.built is not None else {}
        for lid in moving:
            items: list[_Item] = []
            for label, kind, _src in _applied(fs, lid) if lid == p.link else []:
                items.append((force_name(label), env[label][:2], kind, ()))
            for j in fs.joints:
                if lid in (j.lo, j.hi):
                    w = env[p.forces[j.key]][:2]
                    items.append((force_name(j.label(lid, p.suffix)),
                                  w if lid == j.hi else -w, INK, (p.forces[j.key],)))
            if _is_polygon(items):
                polys.append((lid, f"{p.suffix} loads of link {p.link}", items))
    for lid in moving:
        items = [(lab, f, c, raw) for lab, f, _, c, raw in _forces_on(fs, lid)]  # noqa: C416
        if _is_polygon(items):
            polys.append((lid, "", items))
    # the scales: one length scale for (a)-(d), one force scale for every polygon
    pts = [np.asarray(sol.position(n)) for n in mech.point_names
           if n not in mech.helper_points]
    center, span = _extent(pts)
    lscale = choose_scale(span * 1.35, PANEL_IN, "in", mech.length_unit)
    # the loads' arrows (a fixed length on paper) must fit in panel (a) too
    tails = [at - _unit(f) * 0.55 * lscale.per_inch for lid in moving
             for _, f, at, color, _ in _forces_on(fs, lid) if color != INK]
    if tails:
        center, span = _extent(pts + tails)
        lscale = choose_scale(span * 1.35, PANEL_IN, "in", mech.length_unit)
    fmax = 0.0
    for _, _, items in polys:
        acc = np.zeros(2)
        path = [acc.copy()]
        for _, v, _, _ in items:
            acc = acc + v
            path.append(acc.copy())
        fmax = max(fmax, _extent(path)[1])
    fscale = choose_scale(max(fmax, 1e-300) * 1.3, PANEL_IN, "in", mech.force_unit)
    ncols = 4
    n_top = 1 + len(moving)
    rows_top = math.ceil(n_top / ncols)
    rows = rows_top + math.ceil(len(polys) / ncols)
    width = 0.25 + ncols * (PANEL_IN + 0.2)
    height = 0.75 + rows * (PANEL_IN + 0.45) + 0.3
    fig = Figure(figsize=(width, height))
    drawing = Drawing()
    drawing.figure = fig
    # polygon name -> [(label, tail, head)] in force units, as drawn (for tests and readers)
    vectors: dict[str, list[tuple[str, np.ndarray, np.ndarray]]] = {}
    drawing.vectors = vectors  # type: ignore[attr-defined]
    with rc_context():
        kind = "Dynamic" if fs.dynamic else "Static"
        head = fig.text(0.25 / width, 1 - 0.3 / height,
                         f"{kind} force analysis: {mech.title or mech.source}",
                         fontsize=FONT_PT + 1, weight="bold")
        head.set_gid("forces-title")
        drawing.texts["title"] = head
        sub = (f"lengths 1 in = {fmt(lscale.value, 4)} {lscale.unit};  forces 1 in = "
               f"{fmt(fscale.value, 4)} {fscale.unit}")
        if table and upto is None:
            bits = []
            for lid, (what, val) in fs.drives.items():
                if what == "torque":
                    sense = "ccw" if val > 0 else "cw" if val < 0 else ""
                    bits.append(f"T{'1' + lid}".translate(_SUB) + f" = {fmt(abs(val), 4)} "
                                f"{mech.force_unit}·{mech.length_unit} {sense}")
                else:
                    bits.append(f"input force on {lid} = {fmt(val, 4)} {mech.force_unit}")
            sub += "   " + ";  ".join(bits)
        st = fig.text(0.25 / width, 1 - 0.55 / height, sub, fontsize=SMALL_PT + 1)
        st.set_gid("force-scale")
        drawing.texts["force-scale"] = st
        # (a) the mechanism with its loads
        pa = _Panel(fig, 0, 0, rows, center, lscale.per_inch, "(a) mechanism and loads",
                    "forces-mechanism")
        _links(pa.ax, fs, None, "forces-mechanism")
        arrow_len = 0.55 * lscale.per_inch
        for lid in moving:
            for lab, f, at, color, _ in _forces_on(fs, lid):
                if color == INK:
                    continue
                u = _unit(f)
                drawing[f"load-{lab}"] = pa.arrow(at - u * arrow_len, at, color,
                                                  f"forces-mechanism-{lab}")
                pa.text(at - u * arrow_len, lab, f"forces-mechanism-label-{lab}", color)
        # (b...) free bodies
        for k, lid in enumerate(moving, start=1):
            names = [n for n in mech.links[lid].points if n not in mech.helper_points]
            lpts = [np.asarray(sol.position(n, lid)) for n in names] or [center]
            c, _ = _extent(lpts)
            letter = "bcdefghijklmnop"[(k - 1) % 15]
            pb = _Panel(fig, k % ncols, k // ncols, rows, c, lscale.per_inch,
                        f"({letter}) free body of link {lid}", f"fbd-{lid}")
            _links(pb.ax, fs, lid, f"fbd-{lid}")
            half = PANEL_IN * lscale.per_inch
            if known is not None and f"l_{lid}" in known:  # a two-force member's line
                ln_ = fs.built.values[f"l_{lid}"] if fs.built is not None else None
                if ln_ is not None:
                    d_ = np.array([ln_[1], -ln_[0]])
                    p_ = -ln_[2] * np.array([ln_[0], ln_[1]])
                    (two,) = pb.ax.plot([p_[0] - d_[0] * 1e3 * half, p_[0] + d_[0] * 1e3 * half],
                                        [p_[1] - d_[1] * 1e3 * half, p_[1] + d_[1] * 1e3 * half],
                                        color=hue((f"l_{lid}",), GREY), lw=0.7,
                                        ls=(0, (6, 2, 1, 2)))
                    two.set_gid(f"fbd-{lid}-two-force-line")
            for lab, f, at, color, raw in _forces_on(fs, lid):
                if np.hypot(*f) == 0 or not seen(raw):
                    continue
                color = hue(raw, color)
                u = _unit(f)
                (ln,) = pb.ax.plot([at[0] - u[0] * half, at[0] + u[0] * half],
                                   [at[1] - u[1] * half, at[1] + u[1] * half], color=GREY,
                                   lw=0.5, ls=(0, (4, 3)))
                ln.set_gid(f"fbd-{lid}-line-{lab}")
                drawing[f"fbd-{lid}-{lab}"] = pb.arrow(at - u * arrow_len, at, color,
                                                        f"fbd-{lid}-{lab}")
                drawing.texts[f"fbd-{lid}-{lab}"] = pb.text(
                    at - u * arrow_len, lab, f"fbd-{lid}-label-{lab}", color)
            x = _concurrency(fs, lid)
            if x is not None and seen((f"X_{lid}",)):
                (m,) = pb.ax.plot([x[0]], [x[1]], marker="o", ms=4, color=INK)
                m.set_gid(f"concurrency-{lid}")
                pb.text(x, "X", f"concurrency-{lid}-label", size=SMALL_PT)
            for d in mech.drives:
                if d.link == lid and d.kind == "angle" and d.pivot is not None \
                        and seen((f"T_1{lid}",)):
                    tq = fs.drives[lid][1]
                    o = sol.position(d.pivot)
                    r = 0.25 * lscale.per_inch
                    arc = Arc(tuple(o), 2 * r, 2 * r, theta1=30, theta2=300, color=_DRIVE,
                              lw=1.2)
                    arc.set_gid(f"fbd-{lid}-torque")
                    pb.ax.add_patch(arc)
                    tip = 300 if tq >= 0 else 30
                    a = math.radians(tip)
                    e = np.asarray(o) + r * np.array([math.cos(a), math.sin(a)])
                    tang = np.array([-math.sin(a), math.cos(a)]) * (1 if tq >= 0 else -1)
                    pb.arrow(e - tang * 0.05 * lscale.per_inch, e, _DRIVE,
                             f"fbd-{lid}-torque-head")
                    sense = "ccw" if tq > 0 else "cw" if tq < 0 else ""
                    pb.text(np.asarray(o) + np.array([r, r]),
                            f"T{'1' + lid}".translate(_SUB) + f" {sense}",
                            f"fbd-{lid}-torque-label", _DRIVE)
        # force polygons
        for k, (lid, tag, items) in enumerate(polys):
            if not all(seen(raw) for *_, raw in items):
                continue
            path = [np.zeros(2)]
            for _, v, _, _ in items:
                path.append(path[-1] + v)
            c, _ = _extent(path)
            pos = rows_top * ncols + k
            name = f"polygon-{lid}" + (f"-{tag.split()[0]}" if tag else "")
            title = (f"force polygon of link {lid}: ΣF = 0" if not tag
                     else f"{tag}: polygon of link {lid}")
            pp = _Panel(fig, pos % ncols, pos // ncols, rows, c, fscale.per_inch, title, name)
            vectors[name] = [(lab, tail, tail + v) for (lab, v, _, _), tail in zip(items, path)]
            turn = sum(float(a[0] * b[1] - a[1] * b[0]) for a, b in zip(path, path[1:]))
            for (lab, v, color, raw), tail in zip(items, path):
                if np.hypot(*v) == 0:
                    continue
                color = hue(raw, color)
                drawing[f"{name}-{lab}"] = pp.arrow(tail, tail + v, color, f"{name}-{lab}")
                # the label beside the middle of its vector, outside the polygon (the
                # interior is on the left of each side of a counterclockwise polygon)
                u = _unit(v) * (1.0 if turn > 0 else -1.0)
                t = pp.text(tail + v / 2, lab, f"{name}-label-{lab}", color, size=SMALL_PT,
                            offset=(8 * float(u[1]), -8 * float(u[0])))
                t.set_ha("center")
                t.set_va("center")
                drawing.texts[f"{name}-{lab}"] = t
            (o,) = pp.ax.plot([0], [0], marker="o", ms=3, color=INK)
            o.set_gid(f"{name}-start")
    return drawing


def _is_polygon(items: list[_Item]) -> bool:
    """Three or more forces: a polygon worth drawing (two are just equal and opposite)."""
    return sum(1 for _, v, _, _ in items if float(np.hypot(*v)) > 0) >= 3


def _applied(fs: ForceSolution, lid: str) -> list[tuple[str, str, Any]]:
    from graphkin.forces.graphic import applied_labels

    out = []
    for label, kind, src in applied_labels(fs.mechanism, fs.dynamic).get(lid, []):
        if kind == "couple":
            continue
        out.append((label, _INERTIA if kind == "inertia" else _LOAD, src))
    return out


def _concurrency(fs: ForceSolution, lid: str) -> np.ndarray | None:
    """The concurrency point of a link that was solved as a three-force member."""
    if fs.built is None or len(fs.partials) != 1:
        return None
    x = fs.built.values.get(f"X_{lid}")
    if x is None or abs(float(x[2])) < 1e-12:
        return None
    return np.asarray(x[:2] / x[2])


def forces_frames(obj: Any) -> list[tuple[Any, str]]:
    """One drawing per step of the force construction: (step, SVG text).

    Raises
    ------
    DiagramUnavailable
        No loads and no masses, or the forces were solved by the matrix method.
    """
    from graphkin.forces.report import forces_report
    from graphkin.render.sources import DiagramUnavailable
    from graphkin.render.svg import to_svg

    sol = obj.solve() if hasattr(obj, "pins") else obj
    fs = forces_report(sol)
    if fs is None or fs.construction is None:
        why = ("the file has no [[loads]] and no [inertia.N]" if fs is None else
               "the forces were solved by the matrix method (no graphic order)")
        raise DiagramUnavailable(f"no force construction: {why}", diagram="forces")
    out = []
    for k, step in enumerate(fs.construction):
        d = draw_forces(fs, upto=k)
        out.append((step, to_svg(d.figure)))
    return out


def forces_steps_html(obj: Any, title: str | None = None) -> str:
    """The force construction step by step as one self-contained HTML page.

    Each step: its number, the vector equation with its ✓/? marks, one
    sentence in the book's words, and the drawing with what the construction
    has found so far (the newest step in the highlight colour).  Previous/next
    buttons and the arrow keys walk through it.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 11.6-11.8, 12.5.
    """
    import html

    frames = forces_frames(obj)
    sol = obj.solve() if hasattr(obj, "pins") else obj
    head = html.escape(title or sol.mechanism.title or sol.mechanism.source)
    parts = []
    n = len(frames)
    for k, (step, svg) in enumerate(frames):
        eq = "" if step.equation is None else \
            f"<p class='eq'>{html.escape(str(step.equation))}</p>"
        body = svg[svg.index("<svg"):]
        parts.append(f"<section class='frame' id='step-{k}' style='display:"
                     f"{'block' if k == 0 else 'none'}'><h2>Step {k + 1} of {n}: "
                     f"{html.escape(step.label)}</h2>{eq}<p>{html.escape(step.note)}</p>"
                     f"<div class='fig'>{body}</div></section>")
    script = ("let k=0;const f=[...document.querySelectorAll('.frame')];"
              "function show(i){k=Math.max(0,Math.min(f.length-1,i));"
              "f.forEach((e,j)=>e.style.display=j===k?'block':'none');}"
              "document.getElementById('prev').onclick=()=>show(k-1);"
              "document.getElementById('next').onclick=()=>show(k+1);"
              "document.addEventListener('keydown',e=>{if(e.key==='ArrowLeft')show(k-1);"
              "if(e.key==='ArrowRight')show(k+1);});")
    return ("<!DOCTYPE html><html><head><meta charset='utf-8'>"
            f"<title>Forces: {head}</title><style>body{{font-family:sans-serif;margin:1em}}"
            ".eq{font-family:monospace}.fig svg{max-width:100%;height:auto}</style></head>"
            f"<body><h1>Force analysis: {head}</h1><p><button id='prev'>◀ previous</button> "
            "<button id='next'>next ▶</button> (or the arrow keys)</p>"
            + "".join(parts) + f"<script>{script}</script></body></html>\n")
