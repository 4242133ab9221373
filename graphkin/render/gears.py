"""The drawing of a pair of spur gears in mesh, laid out as Figs. 7.8-7.9, 7.17, 7.18 and 7.21.

Every step of the layout's construction (:func:`graphkin.gears.mesh_construction`)
is one group whose gid is the step's id (``step-03-P``, ``step-14-C``): the
centers, the pitch point P, the pitch circles (dash-dot, as center lines),
the common tangent, the base circles, the line of action touching them at A
and B, the addendum circles with the ends of the path of contact C and D,
the dedendum circles.  Beside them: the teeth of both gears (``teeth-2``,
``teeth-3``: involute flanks, top and bottom lands, one tooth of each
touching at P), the path of contact CD drawn bold (``path-of-contact``),
the angles of approach and recess at each center (``approach-2``,
``recess-2``, ``approach-3``, ``recess-3``, Eqs. 7.7-7.8) and, when the
teeth interfere, the overshoot AC or BD marked (``interference``,
Fig. 7.18).  Letters are placed by :mod:`graphkin.render.labels`; a results
table sets each value measured on the construction beside the book's
closed form.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.5, 7.7-7.9; Figs. 7.8, 7.9,
7.17, 7.18, 7.21.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.gears import analytic
from graphkin.gears.mesh import Contact, MeshLayout
from graphkin.gears.profile import gear_teeth, mesh_phases, rack_teeth
from graphkin.render.labels import place_labels
from graphkin.render.results import Row
from graphkin.render.scene import Item, LabelRequest, Panel, clip_segment, inside_spans
from graphkin.render.sheet import Sheet, _frame, _layout, box_panel
from graphkin.render.stepper import PAGER_JS, frame_section
from graphkin.text import fmt

__all__ = ["gear_sheet", "draw_gears", "gear_frames", "gear_steps_html", "CIRCLE_STYLE"]

#: How each circle of the layout is drawn: pitch circles as center lines (dash-dot).
CIRCLE_STYLE = {"pitch": "ref-line", "base": "angle-arc", "addendum": "arc",
                "dedendum": "datum"}
_CIRCLE_WORDS = {"pitch": "pitch circle", "base": "base circle", "addendum": "addendum circle",
                 "dedendum": "dedendum circle"}
#: A rack's circles are lines (Sec. 7.5): the step label -> the circle it stands for.
_RACK_LINES = {"tangent": "pitch", "addendum3": "addendum", "dedendum3": "dedendum"}


def _xy(v: Any) -> np.ndarray:
    a = np.asarray(v, dtype=float)
    return a[:2] / a[2]


def _near(lay: MeshLayout) -> list[str]:
    """The points of the layout near the mesh.

    C, D, P, and the interference points A and B unless they lie far along
    the line of action (a gear much larger than its pinion).
    """
    p = np.array(lay.points["P"])
    reach = max(3.0 * abs(lay.path), 6.0 * lay.pair.driver.module)
    keys = [k for k in ("A", "B", "C", "D", "P") if k in lay.points]   # a rack has no B
    far = [k for k in ("A", "B") if k in lay.points
           and np.hypot(*(np.array(lay.points[k]) - p)) > reach]
    return [k for k in keys if k not in far]


def _extent(lay: MeshLayout) -> tuple[np.ndarray, np.ndarray, bool]:
    """The box of the drawing's content; whether gear 3 is drawn whole."""
    pair = lay.pair
    ra2, ra3 = pair.outside_radii
    if pair.driven.rack:   # the pinion whole and the rack below it, as deep as its teeth
        pts = np.array([lay.points[k] for k in _near(lay)])
        o2 = np.array(lay.points["O2"])
        g3 = pair.driven
        lo = np.minimum(pts.min(axis=0), [o2[0] - 1.3 * ra2, -g3.dedendum - 2.0 * g3.module])
        hi = np.maximum(pts.max(axis=0), [o2[0] + 1.3 * ra2, o2[1] + ra2])
        return lo, hi, False
    o2, o3 = np.array(lay.points["O2"]), np.array(lay.points["O3"])
    r2p, r3p = pair.operating_pitch_radii
    whole = r3p <= 2.6 * r2p
    keys = ["A", "B", "C", "D", "P"] if whole else _near(lay)
    pts = np.array([lay.points[k] for k in keys])
    lo = np.minimum(pts.min(axis=0), o2 - ra2)
    hi = np.maximum(pts.max(axis=0), o2 + ra2)
    if whole:
        lo, hi = np.minimum(lo, o3 - ra3), np.maximum(hi, o3 + ra3)
    else:   # the gear near the mesh, as deep below P as the pinion is tall
        lo = np.array([lo[0], min(lo[1], -1.1 * ra2)])
    return lo, hi, whole


def _zone(lay: MeshLayout) -> tuple[np.ndarray, np.ndarray]:
    """The box of the zone of action: A, B, C, D and P with room around them (Fig. 7.9)."""
    keys = _near(lay)
    pts = np.array([lay.points[k] for k in keys])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    ab = float(np.hypot(*(pts.max(axis=0) - pts.min(axis=0))))
    m = lay.pair.driver.module
    pad = np.array([0.12 * ab + 1.5 * m, 3.0 * m])
    return lo - pad, hi + pad


def _panel(lay: MeshLayout, name: str, title: str, lo: np.ndarray, hi: np.ndarray,
           max_inches: float) -> Panel:
    return box_panel(name, "gears", title, lay.pair.units, lo, hi, max_inches)


def gear_sheet(lay: MeshLayout, *, table: bool = True, max_inches: float = 6.5,
               title: str | None = None, skip: frozenset[str] = frozenset(),
               upto: int | None = None) -> Sheet:
    """Lay out the drawing of a pair in mesh on a sheet (pure data, no matplotlib).

    Two panels: ``pair``, the two gears with their circles, the line of action
    and the angles of approach and recess at the centers (Figs. 7.8, 7.17),
    and ``action``, the zone of action enlarged with every letter (Figs. 7.9,
    7.18, 7.21b).  The names of circles and lines whose label gids are in
    ``skip`` are left out (a crowded zone: see :func:`draw_gears`).  With
    ``upto`` only the construction's steps ``0..upto`` are drawn, the newest
    highlighted, and no teeth (the book's Steps 1-5 before Steps 6-8).
    """
    pair = lay.pair
    g2, g3 = pair.driver, pair.driven
    lo, hi, _ = _extent(lay)
    if pair.center > pair.tight_center_distance * (1 + 1e-9):
        fig = "increased center distance, Fig. 7.21b"
    elif lay.interference:
        fig = "interference, Fig. 7.18"
    else:
        fig = "Fig. 7.10" if g3.rack else "Fig. 7.9"
    what = (f"(a) a pinion of {g2.teeth} teeth and a rack" if g3.rack
            else f"(a) gears {g2.teeth} and {g3.teeth} teeth in mesh")
    panels = [_panel(lay, "pair", what, lo, hi, 0.62 * max_inches)]
    zlo, zhi = _zone(lay)
    panels.append(_panel(lay, "action", f"(b) the zone of action ({fig})", zlo, zhi,
                         1.2 * max_inches))
    recut = _recut(lay) if upto is None else {}
    for p in panels:
        _paint(lay, p, zoom=p.name == "action", upto=upto, recut=recut)
    if upto is None:
        panels.append(_involute_panel(lay, 0.9 * max_inches))
    for p in panels:
        p.labels = [r for r in p.labels if r.gid not in skip]
        _frame(p)
        place_labels(p)
    rows = _rows(lay) if table else []
    mate = f"{g2.teeth} teeth and a rack" if g3.rack else f"{g2.teeth} and {g3.teeth} teeth"
    default = (f"Spur gears, {mate}, module {fmt(g2.module)} "
               f"{pair.units}, {fmt(math.degrees(g2.pressure_angle))}°")
    sheet = Sheet(panels, (0.0, 0.0), title if title is not None else (pair.title or default),
                  "gears", rows)
    _layout(sheet, legend=False)
    return sheet


def draw_gears(lay: MeshLayout, *, table: bool = True, max_inches: float = 6.5,
               upto: int | None = None) -> Any:
    """The matplotlib drawing (:class:`~graphkin.render.mpl.Drawing`) of a pair in mesh.

    Where the zone of action is too crowded for the name of a circle or a line
    to stand clear of every other line (two equal gears with long teeth,
    Fig. 7.18), that name is left out: its circle keeps its line style and
    its gid, and the letters always stay.
    """
    from graphkin.render.labels import collisions
    from graphkin.render.mpl import render_sheet

    skip: frozenset[str] = frozenset()
    for _ in range(4):
        drawing = render_sheet(gear_sheet(lay, table=table, max_inches=max_inches, skip=skip,
                                          upto=upto))
        bad = {gid for _, gid, _ in collisions(drawing)
               if gid.endswith(("-circle", "-line", "-words"))}
        if not bad:
            break
        skip = skip | bad
    return drawing


def _label(p: Panel, g: Any, text: str, at: np.ndarray, key: str, style: str = "label",
           prefer: tuple[float, float] | None = None) -> None:
    p.labels.append(LabelRequest(text, np.asarray(at, dtype=float), style,
                                 f"label-{g.gid}-{key}", g, key=key, prefer=prefer))


def _recut(lay: MeshLayout) -> dict[str, np.ndarray]:
    """The teeth re-cut where they interfere (Fig. 7.18): gear 2 before A, gear 3 after B."""
    from graphkin.render.gears_recut import recut_template

    out = {}
    for link, end in (("2", lay.start), ("3", lay.end)):
        if end == Contact.INTERFERENCE:
            tpl = recut_template(lay, int(link))
            if tpl is not None:
                out[link] = tpl
    return out


def _paint(lay: MeshLayout, p: Panel, zoom: bool, upto: int | None = None,
           recut: dict[str, np.ndarray] | None = None) -> None:
    """Draw the layout in a panel; ``zoom``: the zone of action, every element lettered.

    ``upto``: the construction's steps up to that one only (the newest highlighted);
    ``recut``: a tooth outline re-cut by the mate (:func:`_recut`) for gear ``"2"`` or ``"3"``.
    """
    pair = lay.pair
    cx = lay.construction
    ev = cx.evaluate()
    box = p.inner
    assert box is not None
    diag = p.diag()
    teeth_z, circle_z, line_z, point_z = 2.0, 1.0, 3.0, 5.0
    # the teeth of both gears, one tooth of each touching at P (Fig. 7.9)
    psi2, psi3 = mesh_phases(pair)
    ra2, ra3 = pair.outside_radii
    for gear, ra, psi, center, link in ((pair.driver, ra2, psi2, "O2", "2"),
                                        (pair.driven, ra3, psi3, "O3", "3")
                                        ) if upto is None else ():
        g = p.group(f"{p.prefix}teeth-{link}", teeth_z, key=f"teeth {link}")
        if gear.circular_pitch / p.k < MIN_PITCH:   # teeth too fine to see: the circles only
            continue
        x0, y0, x1, y1 = box
        if gear.rack:
            side = 1.0 if lay.points["A"][0] >= lay.points["P"][0] else -1.0
            outline = rack_teeth(gear, (x0, x1), side)
        else:
            outline = gear_teeth(gear, ra, lay.points[center], psi,
                                 template=(recut or {}).get(link))
        inside = ((outline[..., 0] >= x0) & (outline[..., 0] <= x1)
                  & (outline[..., 1] >= y0) & (outline[..., 1] <= y1))
        for i in np.flatnonzero(inside.any(axis=1)):
            # the runs of the tooth inside the drawing area (none into the title strip)
            edges = np.flatnonzero(np.diff(np.concatenate([[0], inside[i].astype(int), [0]])))
            for j, (a, b) in enumerate(zip(edges[::2], edges[1::2])):
                if b - a >= 2:
                    g.items.append(Item("path", outline[i, a:b], "given-line",
                                        gid=f"{p.prefix}teeth-{link}-{i}"
                                        + (f"-{j}" if j else "")))
        if g.items:
            g.items[0].key = f"teeth {link}"
    # the construction's steps
    for step in cx.steps[: None if upto is None else upto + 1]:
        g = p.group(p.prefix + step.step_id, circle_z if step.kind == "circle" else line_z,
                    step=step, diagram="gears", key=step.label,
                    highlight=upto is not None and step.index == upto)
        value = ev[step.outputs[0]]
        if step.kind == "circle":
            c = np.asarray(value, dtype=float)
            which, link = step.label[:-1], step.label[-1]
            style = CIRCLE_STYLE.get(which, "arc")
            spans = inside_spans(c[:2], float(c[2]), box)
            if spans is None:
                g.items.append(Item("circle", np.array([c[:2]]), style, radius=float(c[2]),
                                    key=step.label))
            else:
                for t1, t2 in spans:
                    g.items.append(Item("arc", np.array([c[:2]]), style, radius=float(c[2]),
                                        theta1=t1, theta2=t2, key=step.label))
            anchor = _on_edge(c, box, link) if zoom else None
            if which in _CIRCLE_WORDS and anchor is not None:
                _label(p, g, f"{_CIRCLE_WORDS[which]} {link}", anchor, "circle", "label-aux")
        elif step.kind == "line":
            line = np.asarray(value, dtype=float)
            d = np.array([line[1], -line[0]])
            pp = np.array(lay.points["P"])
            nn = float(line[0] ** 2 + line[1] ** 2)   # through the foot of P on the line
            through = pp - (float(line[0] * pp[0] + line[1] * pp[1] + line[2]) / nn) * line[:2]
            seg = clip_segment(through - diag * d, through + diag * d, box)
            if seg is not None:
                rack_line = step.label in _RACK_LINES and pair.driven.rack
                style = ("result-line" if step.label == "AB" else
                         CIRCLE_STYLE.get(_RACK_LINES.get(step.label, ""), "aux-line")
                         if rack_line else "aux-line")
                g.items.append(Item("path", np.array(seg), style, key=step.label))
                if zoom and rack_line and step.label != "tangent":
                    _label(p, g, f"{_RACK_LINES[step.label]} line 3",
                           through + 0.7 * (seg[1] - through), "line", "label-aux")
                if zoom and step.label in ("AB", "tangent"):
                    words = "line of action" if step.label == "AB" else (
                        "pitch line 3" if pair.driven.rack else "common tangent")
                    end = seg[1] if step.label == "AB" else seg[0]
                    _label(p, g, words, through + 0.82 * (end - through), "line", "label-aux")
        elif step.kind == "point":
            xy = _xy(value)
            g.z = point_z
            style = "point" if step.label in ("P", "C", "D") else "aux-point"
            if step.label in ("O2", "O3"):
                style = "pin"
            if _in(xy, box):
                g.items.append(Item("marker", np.array([xy]), style, key=step.label))
                if zoom or step.label in ("O2", "O3", "P"):
                    _label(p, g, _letters(step.label), xy, "letter")
    if upto is not None:
        return
    _path_of_contact(lay, p)
    if zoom:
        _interference(lay, p)
    else:
        _angles(lay, p)


def gear_frames(lay: MeshLayout) -> list[tuple[str, str, str]]:
    """One drawing per step of the layout, then the teeth: ``(title, note, svg)`` each."""
    from graphkin.render.svg import to_svg

    frames = []
    for step in lay.construction:
        d = draw_gears(lay, table=False, upto=step.index)
        frames.append((step.label, step.note, to_svg(d.figure)))
    d = draw_gears(lay, table=True)
    frames.append(("the teeth", "Steps 6-8: the involute teeth of both gears, one tooth of each "
                   "touching at P; the path of contact CD, the angles of approach and recess "
                   "(Eqs. 7.7-7.8) and the contact ratio CD/p_b (Eq. 7.9).", to_svg(d.figure)))
    return frames


def gear_steps_html(lay: MeshLayout) -> str:
    """The layout of Sec. 7.5 step by step as one self-contained HTML page (``steps -d gears``).

    Each step: its number, one sentence in the book's words, and the drawing
    up to it with the newest element highlighted; previous/next buttons and
    the arrow keys walk through it.
    """
    import html

    frames = gear_frames(lay)
    head = html.escape(lay.pair.title or lay.construction.title)
    n = len(frames)
    parts = []
    for k, (label, note, svg) in enumerate(frames):
        parts.append(frame_section(k, n, label, f"<p>{html.escape(note)}</p>", svg))
    script = PAGER_JS
    return ("<!DOCTYPE html><html><head><meta charset='utf-8'>"
            f"<title>Gears: {head}</title><style>body{{font-family:sans-serif;margin:1em}}"
            ".fig svg{max-width:100%;height:auto}</style></head>"
            f"<body><h1>Spur gears in mesh (Sec. 7.5): {head}</h1><p><button id='prev'>"
            "◀ previous</button> <button id='next'>next ▶</button> (or the arrow keys)</p>"
            + "".join(parts) + f"<script>{script}</script></body></html>\n")


MIN_PITCH = 0.04
"""The smallest circular pitch on paper (inches) at which teeth are drawn one by one."""

INVOLUTE_PARTS = 6
"""How many equal parts of the base circle the drawn involute construction uses (Step 6)."""


def _involute_panel(lay: MeshLayout, max_inches: float) -> Panel:
    """(c) The involute of gear 3 struck on its tangents, as in Fig. 7.8 (Sec. 7.5, Step 6).

    The recorded steps of :func:`graphkin.gears.involute.involute_construction`
    about O3 (off the panel): the points A0..A6 dividing the base circle, the
    radial lines and the tangents at them, the arcs of radius A0A_k, the
    points T_k, and the involute itself in closed form up to the addendum
    circle.
    """
    from graphkin.gears.involute import Unwind, involute_construction, involute_xy

    which = 2 if lay.pair.driven.rack else 3   # a rack's flanks are straight: the pinion's
    g3 = lay.pair.driver if which == 2 else lay.pair.driven
    rb, ra = g3.base_radius, lay.pair.outside_radii[which - 2]
    # tan ϕ at the addendum circle (the construction stops at 1.5 rad for a very steep one)
    roll = min(math.sqrt(max((ra / rb) ** 2 - 1.0, 1e-12)), 1.5)
    origin = math.pi / 2 - 0.5 * roll
    cx = involute_construction(rb, parts=INVOLUTE_PARTS, roll=roll, origin=origin,
                               sense=Unwind.CCW)
    ev = cx.evaluate()
    pts = {s.outputs[0]: _xy(ev[s.outputs[0]]) for s in cx.steps if s.kind == "point"}
    near = np.array([v for k, v in pts.items() if k != "O"])
    lo, hi = near.min(axis=0), near.max(axis=0)
    pad = 0.25 * float(max(hi - lo))
    lo, hi = lo - pad, hi + pad
    p = _panel(lay, "involute", f"(c) the involute of gear {which} (Step 6)", lo, hi,
               max_inches)
    box = p.inner
    assert box is not None
    o = pts["O"]
    for step in cx.steps:
        if step.op in ("point", "scalar", "copy_point"):
            continue
        g = p.group(p.prefix + step.step_id, 3.0, step=step, diagram="gears", key=step.label)
        value = np.asarray(ev[step.outputs[0]], dtype=float)
        if step.kind == "circle":   # the arc struck about A_k: near the tangent only
            k = step.label[1:]
            t = pts[f"T{k}"]
            a = math.degrees(math.atan2(t[1] - value[1], t[0] - value[0]))
            g.items.append(Item("arc", np.array([value[:2]]), "arc", radius=float(value[2]),
                                theta1=a - 12.0, theta2=a + 12.0, key=step.label))
        elif step.kind == "line":
            anchor = pts["A" + step.label[len("OA"):]] if step.label.startswith("OA") \
                else pts["A" + step.label[1:]]
            d = np.array([value[1], -value[0]])
            reach = 0.45 * float(max(hi - lo))
            if step.label.startswith("OA"):   # the radius O A_k, from inside the panel
                seg = clip_segment(anchor - reach * d, anchor + 0.1 * reach * d, box)
            else:
                seg = clip_segment(anchor - reach * d, anchor + 0.25 * reach * d, box)
            if seg is not None:
                g.items.append(Item("path", np.array(seg), "aux-line", key=step.label))
        else:
            xy = pts[step.outputs[0]]
            style = "point" if step.label.startswith("T") else "aux-point"
            g.items.append(Item("marker", np.array([xy]), style, key=step.label))
            if step.label.startswith("A"):
                _label(p, g, _letters(step.label), xy, "letter", "label-small",
                       prefer=tuple((xy - o) / np.hypot(*(xy - o)) * -1))
    for name, r, style in ((f"base circle {which}", rb, "angle-arc"),
                           (f"addendum circle {which}", ra, "arc")):
        g = p.group(f"{p.prefix}{name.replace(' ', '-')}", 1.0, key=name)
        for t1, t2 in inside_spans(o, r, box) or [(0.0, 360.0)]:
            g.items.append(Item("arc", np.array([o]), style, radius=r, theta1=t1, theta2=t2))
        at = math.radians(90.0 + math.degrees(0.5 * roll) + 4.0)
        _label(p, g, name, o + r * np.array([math.cos(at), math.sin(at)]), "circle",
               "label-aux")
    g = p.group(f"{p.prefix}involute-curve", 4.0, key="involute")
    curve = involute_xy(rb, np.linspace(rb, ra, 60), origin=origin, sense=Unwind.CCW)
    g.items.append(Item("path", curve, "result-line", key="involute"))
    _label(p, g, "involute", curve[40], "words", "label-aux")
    return p


def _letters(label: str) -> str:
    return label.translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))


def _on_edge(c: np.ndarray, box: tuple[float, float, float, float], link: str
             ) -> np.ndarray | None:
    """The place for a circle's name, away from the mesh.

    Where a circle of the pinion (2) crosses the left of the zone, or of the
    gear (3) the right.
    """
    x0, y0, x1, y1 = box
    for f in (0.08, 0.16, 0.26, 0.36):
        x = x0 + f * (x1 - x0) if link == "2" else x1 - f * (x1 - x0)
        dx = x - c[0]
        if abs(dx) >= c[2]:
            continue
        dy = math.sqrt(c[2] ** 2 - dx * dx)
        y = c[1] - dy if link == "2" else c[1] + dy
        if y0 + 0.05 * (y1 - y0) <= y <= y1 - 0.05 * (y1 - y0):
            return np.array([x, y])
    return None


def _in(xy: np.ndarray, box: tuple[float, float, float, float]) -> bool:
    return bool(box[0] <= xy[0] <= box[2] and box[1] <= xy[1] <= box[3])


def _path_of_contact(lay: MeshLayout, p: Panel) -> None:
    g = p.group(f"{p.prefix}path-of-contact", 4.0, key="path of contact")
    c, d = np.array(lay.points["C"]), np.array(lay.points["D"])
    g.items.append(Item("path", np.array([c, d]), "vector-abs", key="path of contact"))


def _angles(lay: MeshLayout, p: Panel) -> None:
    """The angles of approach α and recess β at each center (Eqs. 7.7-7.8, Fig. 7.17)."""
    pair = lay.pair
    box = p.inner
    assert box is not None
    P = np.array(lay.points["P"])
    for link, center, rp, sense in (("2", "O2", pair.operating_pitch_radii[0], -1.0),
                                    ("3", "O3", pair.operating_pitch_radii[1], 1.0)):
        if center not in lay.points:   # a rack's center is at infinity: it does not turn
            continue
        o = np.array(lay.points[center])
        if not _in(o, box):
            continue
        i = int(link) - 2
        base = math.degrees(math.atan2(*(P - o)[::-1]))
        radius = 0.5 * min(rp, pair.operating_pitch_radii[0] * 1.2)
        # a gear turning cw (sense −1) reached P from the ccw side: approach on that side
        spans = {"approach": (base, base - sense * math.degrees(lay.approach_angles[i])),
                 "recess": (base, base + sense * math.degrees(lay.recess_angles[i]))}
        for name, (t_from, t_to) in spans.items():
            g = p.group(f"{p.prefix}{name}-{link}", 4.0, key=f"{name} {link}")
            t1, t2 = sorted((t_from, t_to))
            g.items.append(Item("arc", np.array([o]), "angle-arc", radius=radius, theta1=t1,
                                theta2=t2, key=f"{name} {link}"))
            for t in (t1, t2):
                ray = o + radius * 1.08 * np.array([math.cos(math.radians(t)),
                                                     math.sin(math.radians(t))])
                g.items.append(Item("path", np.array([o + 0.85 * (ray - o), ray]),
                                    "angle-arc"))
            mid = math.radians((t1 + t2) / 2)
            at = o + radius * np.array([math.cos(mid), math.sin(mid)])
            letter = ("α" if name == "approach" else "β") + _letters(link)
            _label(p, g, letter, at, "angle", "label-small",
                   prefer=(math.cos(mid), math.sin(mid)))


def _interference(lay: MeshLayout, p: Panel) -> None:
    """Fig. 7.18: the part of the path of contact beyond A or B, where the tips dig in."""
    spans = []
    if lay.start == Contact.INTERFERENCE:
        spans.append(("A", "C"))
    if lay.end == Contact.INTERFERENCE:
        spans.append(("B", "D"))
    if not spans:
        return
    g = p.group(f"{p.prefix}interference", 4.5, key="interference")
    for a, b in spans:
        xa, xb = np.array(lay.points[a]), np.array(lay.points[b])
        g.items.append(Item("path", np.array([xa, xb]), "vector-c", key=f"interference {a}{b}"))
        g.items.append(Item("marker", np.array([xa]), "ball", key=f"interference {a}"))
    mid = 0.5 * (np.array(lay.points[spans[0][0]]) + np.array(lay.points[spans[0][1]]))
    _label(p, g, "interference", mid, "words", "label-aux")
    _undercut(lay, p, spans)


def _undercut(lay: MeshLayout, p: Panel, spans: list[tuple[str, str]]) -> None:
    """The tip's path through the other gear's flank (Fig. 7.18): what a generator cuts away.

    Drawn where it runs inside the cut gear's tooth (between its flanks, above
    its root circle): the new, undercut flank (``undercut-2`` for gear 2 cut
    by 3's tip, ``undercut-3``); the tooth's own flank there is cut away.
    """
    from graphkin.gears.profile import tip_path

    pair = lay.pair
    box = p.inner
    assert box is not None
    for a, _ in spans:
        cut, cutter = ("2", 3) if a == "A" else ("3", 2)
        gear = pair.driver if cut == "2" else pair.driven
        center = np.array(lay.points[f"O{cut}"])
        path = tip_path(pair, lay.points, cutter)
        rel = path - center
        r = np.hypot(*rel.T)
        psi = mesh_phases(pair)[0 if cut == "2" else 1]
        half = np.asarray(gear.half_angle(np.maximum(r, gear.base_radius)), dtype=float)
        off = (np.arctan2(rel[:, 1], rel[:, 0]) - psi + np.pi) % (2 * np.pi) - np.pi
        keep = (r >= gear.root_radius) & (np.abs(off) < half)
        keep = keep | np.roll(keep, 1) | np.roll(keep, -1)   # to the flank on either side
        keep &= (path[:, 0] >= box[0]) & (path[:, 0] <= box[2]) \
            & (path[:, 1] >= box[1]) & (path[:, 1] <= box[3])
        edges = np.flatnonzero(np.diff(np.concatenate([[0], keep.astype(int), [0]])))
        runs = [(i, j) for i, j in zip(edges[::2], edges[1::2]) if j - i >= 2]
        if not runs:
            continue
        g = p.group(f"{p.prefix}undercut-{cut}", 4.6, key=f"undercut {cut}")
        for n, (i, j) in enumerate(runs):
            g.items.append(Item("path", path[i:j], "result-line",
                                gid=f"{p.prefix}undercut-{cut}-{n}", key=f"undercut {cut}"))
        i, j = max(runs, key=lambda ij: ij[1] - ij[0])
        _label(p, g, f"undercut {cut}", path[(i + j) // 2], "words", "label-aux")


def _rows(lay: MeshLayout) -> list[Row]:
    """Each value measured on the construction beside the book's closed form."""
    pair = lay.pair
    g2, g3 = pair.driver, pair.driven
    ra2, ra3 = pair.outside_radii
    if g3.rack:
        return _rack_rows(lay)
    phi = analytic.operating_pressure_angle(pair.standard_center_distance, pair.center,
                                            g2.pressure_angle)
    if g3.internal:
        r2p, r3p = pair.operating_pitch_radii
        cp, pd = analytic.approach_recess_internal(ra2, ra3, g2.base_radius, g3.base_radius,
                                                   r2p, r3p, phi)
    else:
        cp, pd = analytic.approach_recess(ra2, ra3, g2.base_radius, g3.base_radius,
                                          pair.center, phi)
    mc = analytic.contact_ratio(cp, pd, g2.base_pitch)
    u = pair.units
    deg = math.degrees
    values = [
        ("phi", "pressure angle φ'", "°", deg(lay.operating_pressure_angle), deg(phi)),
        ("CP", "approach CP (7.10)", u, lay.approach, cp),
        ("PD", "recess PD (7.11)", u, lay.recess, pd),
        ("CD", "path of contact CD", u, lay.path, cp + pd),
        ("m_c", "contact ratio m_c (7.9)", "", lay.contact_ratio, mc),
        ("alpha2", "approach α₂ (7.7)", "°", deg(lay.approach_angles[0]),
         deg(cp / g2.base_radius)),
        ("alpha3", "approach α₃ (7.7)", "°", deg(lay.approach_angles[1]),
         deg(cp / g3.base_radius)),
        ("beta2", "recess β₂ (7.8)", "°", deg(lay.recess_angles[0]), deg(pd / g2.base_radius)),
        ("beta3", "recess β₃ (7.8)", "°", deg(lay.recess_angles[1]), deg(pd / g3.base_radius)),
    ]
    return _compare(values)


def _rack_rows(lay: MeshLayout) -> list[Row]:
    """:func:`_rows` for a pinion and a rack: CP = a / sin φ, Eq. (7.10) as R3 → ∞."""
    g2, g3 = lay.pair.driver, lay.pair.driven
    phi = g2.pressure_angle
    cp, pd = analytic.approach_recess_rack(lay.pair.outside_radii[0], g2.base_radius,
                                           g2.pitch_radius, g3.addendum, phi)
    u, deg = lay.pair.units, math.degrees
    return _compare([
        ("phi", "pressure angle φ", "°", deg(lay.operating_pressure_angle), deg(phi)),
        ("CP", "approach CP = a/sin φ", u, lay.approach, cp),
        ("PD", "recess PD (7.11)", u, lay.recess, pd),
        ("CD", "path of contact CD", u, lay.path, cp + pd),
        ("m_c", "contact ratio m_c (7.9)", "", lay.contact_ratio,
         analytic.contact_ratio(cp, pd, g2.base_pitch)),
        ("alpha2", "approach α₂ (7.7)", "°", deg(lay.approach_angles[0]),
         deg(cp / g2.base_radius)),
        ("beta2", "recess β₂ (7.8)", "°", deg(lay.recess_angles[0]), deg(pd / g2.base_radius)),
    ])


def _compare(values: list[tuple[str, str, str, float, float]]) -> list[Row]:
    rows = []
    for key, q, unit, drawn, exact in values:
        diff = abs(drawn - exact) / max(abs(exact), 1e-300)
        rows.append(Row(key, q, unit, fmt(drawn, 6), fmt(exact, 6), diff, (drawn,), (exact,)))
    return rows
