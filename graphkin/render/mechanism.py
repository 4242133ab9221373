"""The mechanism itself, drawn as the book draws it: bars, plates, pins, blocks and a hatched frame.

Each moving link is the outline of its points (shapely's buffer of their
convex hull: a bar for two points, a shaded plate for more), numbered; a pin
is a small circle; a slider is a block on its line; a pin in a slot runs in
a slot cut in its link; the frame shows a bearing at every fixed pivot and a
hatched guide under every slider on it.  Sizes are given in inches of paper
and turned into data units by the panel's scale, so every drawing looks the
same whatever its scale.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.6-1.7 (kinematic diagrams: the
symbols of links, pins, sliders and the frame), Figs. 2.14 and 3.5.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import shapely
import shapely.ops
from shapely.geometry import LineString, MultiPoint, Point, Polygon

from graphkin.mechanisms.model import FRAME, Body, Mechanism, Rolling, Slider, Slot
from graphkin.render.scene import Group, Item, LabelRequest, Panel, point_text, safe_id
from graphkin.render.sources import Source
from graphkin.tolerance import DEFAULT_TOL, VERDICT_REL, is_zero

__all__ = ["paint_mechanism", "paint_bodies", "body_world", "link_points", "mechanism_extent",
           "BAR_HALF"]

BAR_HALF = 0.045
"""Half the width of a bar, in inches."""
BLOCK = (0.17, 0.10)
"""Half length and half height of a slider block, in inches."""
BEARING = (0.1, 0.15)
"""Half width and height of a frame bearing, in inches."""
HATCH = (0.045, 0.065)
"""Spacing and length of the hatch strokes of the frame, in inches."""


def link_points(src: Source, lid: str) -> dict[str, np.ndarray]:
    """World positions of a link's named points."""
    sol = src.solution
    mech = src.mechanism
    assert sol is not None and mech is not None
    return {n: np.asarray(sol.position(n, lid), dtype=float) for n in mech.links[lid].points}


def slide_bars(src: Source, lid: str, k: float) -> list[LineString]:
    """The part of a link along each straight slide it carries, out to the block that runs on it.

    A rod that guides a block (an inverted slider-crank, Fig. 3.9) is drawn
    along its line as far as the block, whatever points the file names on it.
    """
    mech, sol = src.mechanism, src.solution
    assert mech is not None and sol is not None
    bars: list[LineString] = []
    equivalent = {r.slot_key for r in mech.rolling}
    guides: tuple[Slider | Slot, ...] = (*mech.sliders, *mech.slots)
    for s in guides:
        if s.on != lid or s.link == lid or s.key in equivalent:
            continue
        bar = _bar(src, lid, s, s.point, s.link, 1.6 * BLOCK[0] * k)
        if bar is not None:
            bars.append(bar)
    # a moving link's straight face that a roller rolls on (a follower's face, Fig. 4.20):
    # along its line, past the contact point by the roller's radius
    for r in mech.rolling:
        if r.on != lid or r.on == FRAME or r.link == lid:
            continue
        bar = _bar(src, lid, r, r.center, r.link, max(r.radius, 1.6 * BLOCK[0] * k))
        if bar is not None:
            bars.append(bar)
    return bars


def _bar(src: Source, lid: str, guide: Slider | Slot | Rolling, point: str, on: str,
         reach: float) -> LineString | None:
    """The bar of ``guide``'s line on link ``lid``: its two points, and ``reach`` past ``point``.

    ``point`` (of link ``on``) is the block or the roller's center that runs
    along the line; None when the line cannot be placed.
    """
    lw = _line_world(src, guide)
    if lw is None:
        return None
    sol = src.solution
    assert sol is not None
    p0, u = lw
    st = sol.links[lid]
    ts = [float(u @ (np.asarray(st.position(e), dtype=float) - p0))
          for e in (guide.p0, guide.p1)]
    tq = float(u @ (np.asarray(sol.position(point, on), dtype=float) - p0))
    lo, hi = min(*ts, tq - reach), max(*ts, tq + reach)
    return LineString([tuple(p0 + lo * u), tuple(p0 + hi * u)])


def _is_rod(mech: Mechanism, lid: str, pts: dict[str, np.ndarray]) -> bool:
    """A one-point link sliding on the frame drawn as a rod through its guides.

    A rod pushed along its guides (the drive of Rapson's slide, Fig. 4.23, or
    of a trammel) or carrying a block that slides on another link is drawn as
    a rod; a plain piston pinned to a connecting rod is only its block, as
    Fig. 1.15 draws it (a rod would run off the panel for nothing).
    """
    if not any(len(mech.point_links[n]) > 1 for n in pts):
        return False
    if any(d.link == lid and d.kind == "position" for d in mech.drives):
        return True
    blocks = {s.link for s in mech.sliders if s.on != FRAME}
    return any(other in blocks and len(mech.links[other].points) <= 1
               for n in pts for other in mech.point_links[n] if other != lid)


def _ring(geom: shapely.Geometry) -> np.ndarray:
    """A polygon's outline without the vertices that are round-off of its edges.

    GEOS's union of a bar's buffers whose flat sides coincide (a slide along an edge of
    the link's hull) splits a straight side at points that come and go with the last
    digits: 30 vertices on one machine, 97 on another.  The same line, but the labels'
    ink map samples each edge from its ends, and counted a cell more or less.  Points
    within 1e-9 of the outline's size of the line through their neighbours go.

    Examples
    --------
    >>> sq = Polygon([(0, 0), (1, 0), (2, 1e-12), (3, 0), (3, 3), (0, 3)])
    >>> len(_ring(sq))
    4
    """
    if not isinstance(geom, Polygon):  # pragma: no cover
        geom = geom.convex_hull
    x0, y0, x1, y1 = geom.bounds
    size = max(x1 - x0, y1 - y0, 1e-300)
    return np.asarray(geom.simplify(VERDICT_REL * size).exterior.coords)[:-1]


def _line_world(src: Source, s: Slider | Slot | Rolling) -> tuple[np.ndarray, np.ndarray] | None:
    """A straight slider or slot line in world coordinates: a point and a unit direction."""
    sol = src.solution
    if s.p0 is None or s.p1 is None or sol is None:
        return None
    st = sol.links[s.on]
    p0 = np.asarray(st.position(s.p0), dtype=float)
    p1 = np.asarray(st.position(s.p1), dtype=float)
    d = p1 - p0
    n = float(np.hypot(*d))
    if n == 0:
        return None
    return p0, d / n


def _rect(center: np.ndarray, u: np.ndarray, hl: float, hh: float) -> np.ndarray:
    n = np.array([-u[1], u[0]])
    return np.array([center - hl * u - hh * n, center + hl * u - hh * n,
                     center + hl * u + hh * n, center - hl * u + hh * n])


def paint_mechanism(src: Source, panel: Panel, known: set[str] | None,
                    drawn: set[str]) -> None:
    """Draw the mechanism into ``panel``.

    Parameters
    ----------
    src : Source
    panel : Panel
        A posture-plane panel with its scale set.
    known : set of str or None
        Points already constructed (a link is drawn once all its points are);
        None: everything.
    drawn : set of str
        Points already marked by construction steps (their pins and letters).
    """
    mech, sol = src.mechanism, src.solution
    if mech is None or sol is None:
        return
    k = panel.k
    pre = panel.prefix

    def is_known(name: str) -> bool:
        return known is None or name in known

    centroid = np.mean([np.asarray(sol.position(n), dtype=float) for n in mech.point_names],
                       axis=0)

    # the rollers' discs drawn over the links (a roller on a link): each link's number is
    # set where the others' discs leave its bar seen
    discs = _other_discs(mech, sol, is_known)

    # ---- moving links ------------------------------------------------
    rods: set[str] = set()
    for lid in mech.moving:
        link = mech.links[lid]
        if not all(is_known(n) for n in link.points):
            continue
        pts = link_points(src, lid)
        body = {n: q for n, q in pts.items() if n not in mech.helper_points}
        if body:  # a slot's helper points are drawn as the slot, not as the body's corners
            pts = body
        arr = np.array(list(pts.values()))
        g = panel.group(f"{pre}link-{lid}", 1.0 + 0.01 * mech.moving.index(lid), key=f"link {lid}")
        distinct = _hull(arr, mech.scale)
        bars = slide_bars(src, lid, k)
        if distinct.geom_type == "Point" and not bars:
            rod = [sl for sl in mech.sliders if sl.link == lid and sl.on == FRAME]
            lw = _line_world(src, rod[0]) if rod else None
            if lw is not None and _is_rod(mech, lid, pts):
                # a rod sliding in frame guides, carrying a pin (Rapson's slide, Fig. 4.23)
                u = lw[1]
                # 1.3 in of paper each way, but never longer than half the mechanism: on a
                # small handout panel the rod would run through the title (Ex. 12.3's trammel)
                ext = np.array(mechanism_extent(src))
                size = float(np.max(np.ptp(ext, axis=0))) if len(ext) > 1 else 0.0
                half = min(1.3 * k, max(0.5 * size, 0.4 * k))
                bar = LineString([tuple(arr[0] - half * u), tuple(arr[0] + half * u)])
                g.items.append(Item("polygon", _ring(bar.buffer(BAR_HALF * k, quad_segs=6)),
                                    "link", key=f"link {lid}"))
                _number(panel, g, lid, arr[0] + 0.7 * half * u, pre, gap=BAR_HALF + 0.03)
                rods.add(lid)
                continue
            if not any(s.link == lid for s in mech.sliders):
                g.items.append(Item("circle", arr[:1], "link", radius=2.2 * BAR_HALF * k,
                                    key=f"link {lid}"))
                _number(panel, g, lid, arr[0], pre)
            continue
        # a slide the body does not reach (a follower's face; a rod whose only other
        # point defines its slide, Example 4.4) is joined to it by a bar (a follower's face)
        joins = [_join(distinct, b) for b in bars if distinct.distance(b) > 2 * BAR_HALF * k]
        shape = shapely.union_all([distinct.buffer(BAR_HALF * k, quad_segs=6),
                                   *(b.buffer(BAR_HALF * k, quad_segs=6) for b in bars),
                                   *(j.buffer(BAR_HALF * k, quad_segs=6) for j in joins)])
        plate = distinct.geom_type == "Polygon" and distinct.area > (3 * BAR_HALF * k) ** 2
        parts = list(shape.geoms) if hasattr(shape, "geoms") else [shape]
        for j, part in enumerate(parts):
            g.items.append(Item("polygon", _ring(part), "plate" if plate else "link",
                                key=f"link {lid}" if j == 0 else f"link {lid}:{j}"))
        # the number beside the bar, or inside the plate
        if plate:
            # the middle of the plate (a convex hull: its centroid is inside), not GEOS's
            # representative point, which jumps across the plate with the last digits
            rp = distinct.buffer(-1.2 * BAR_HALF * k)
            anchor = np.asarray((rp if not rp.is_empty else distinct).centroid.coords[0])
            panel.labels.append(LabelRequest(lid, anchor, "number", f"{pre}number-{lid}", g,
                                             key=f"link {lid}", gap=0.0, center=True))
        else:
            line = (LineString([tuple(p) for p in arr]).convex_hull if len(arr) > 1
                    else shapely.union_all([distinct, *bars]).convex_hull)
            # a hull's ring, not its area: collinear points (a pantograph's arm O2-A-B) give
            # a hull of zero area whose area centroid is round-off over round-off
            c = np.asarray((line.exterior if line.geom_type == "Polygon" else line)
                           .centroid.coords[0])
            _number(panel, g, lid, _beside_discs(line, c, discs.get(lid)), pre,
                    gap=BAR_HALF + 0.03)

    paint_bodies(src, panel, known)

    # ---- slots: a slot cut in the link that carries the path ------------
    rolling = mech.rolling
    equivalent = {r.slot_key for r in rolling}
    for s in mech.slots:
        if s.key in equivalent:
            continue  # a rolling contact's equivalent slot: the roller is drawn instead
        if not (is_known(s.point) and all(is_known(n) for n in mech.links[s.on].points)):
            continue
        p = np.asarray(sol.position(s.point, s.link), dtype=float)
        g = panel.group(f"{pre}slot-{safe_id(s.key)}", 1.5, key=s.key)
        if s.is_line:
            lw = _line_world(src, s)
            if lw is None:
                continue
            u = lw[1]
            shape = LineString([tuple(p - 0.32 * k * u), tuple(p + 0.32 * k * u)]).buffer(
                1.3 * BAR_HALF * k, quad_segs=6)
        else:
            st = sol.links[s.on]
            c = np.asarray(st.position(s.center), dtype=float)
            rad = float(s.radius or 0.0)
            phi = math.atan2(p[1] - c[1], p[0] - c[0])
            span = min(0.32 * k / max(rad, 1e-300), math.pi)
            ts = np.linspace(phi - span, phi + span, 25)
            arc = LineString([tuple(c + rad * np.array([math.cos(t), math.sin(t)])) for t in ts])
            shape = arc.buffer(1.3 * BAR_HALF * k, quad_segs=6)
        if isinstance(shape, Polygon):
            g.items.append(Item("polygon", _ring(shape), "slot", key=s.key))

    # ---- sliders: blocks, and a hatched guide when they run on the frame -----
    frame_group = panel.group(f"{pre}frame", 0.8, key="frame")
    numbered_frame = False

    # ---- rolling contact: the circle it rolls on (a sun, a ring), as an outline ----
    circles: set[tuple[str, object, float]] = {(r.link, r.center, round(r.radius, 12))
                                               for r in rolling}
    for r in rolling:
        if r.on_center is None or r.on_radius is None:
            continue
        oc = r.on_center_point or r.on_center
        if (r.on, oc, round(r.on_radius, 12)) in circles:
            continue                      # the same circle rolls on something else too
        if isinstance(oc, str) and not is_known(oc):
            continue
        circles.add((r.on, oc, round(r.on_radius, 12)))
        c = np.asarray(sol.links[r.on].position(r.on_center), dtype=float)
        ts = np.linspace(0.0, 2.0 * math.pi, 97)
        rim = c + r.on_radius * np.column_stack([np.cos(ts), np.sin(ts)])
        g = panel.group(f"{pre}rolls-on-{safe_id(r.key)}", 1.55, key=f"link {r.on}")
        g.items.append(Item("path", rim, "link", key=f"circle of link {r.on}"))

    # ---- rolling contact: the roller itself, and the ground it rolls on ------
    seen_rollers: dict[str, int] = {}
    for r in rolling:
        if not is_known(r.center):
            continue
        c = np.asarray(sol.position(r.center, r.link), dtype=float)
        whole = _whole_disc(mech, sol, r)
        # a planet meshing with a sun and a ring is one disc, drawn once; a compound gear
        # (two pitch circles on one link, Example 11.7's planet 4-5) draws its second disc
        # as roller-4-2, so that no two elements share a gid
        disc_key = f"{r.link} {r.center} {r.radius!r}"
        if disc_key not in seen_rollers:
            seen_rollers[disc_key] = sum(k.split()[0] == r.link for k in seen_rollers) + 1
            nth = "" if seen_rollers[disc_key] == 1 else f"-{seen_rollers[disc_key]}"
            # a gear (a roller that is its whole link: a planet, its center and a point of
            # its rim) is drawn under the links, the frame and the pins, as the arm that
            # carries it is drawn over it; a roller on a link (a follower's) over its bar
            g = panel.group(f"{pre}roller-{r.link}{nth}", GEAR_Z if whole else 1.6,
                            key=f"link {r.link}")
            disc = Point(float(c[0]), float(c[1])).buffer(r.radius, quad_segs=24)
            g.items.append(Item("polygon", _ring(disc), "link", key=f"roller {r.link}"))
            if whole:   # numbered on its disc, not beside its bar inside it
                _number(panel, g, r.link, c + np.array([0.0, 0.6 * r.radius]), pre,
                        gap=0.02)
        lw = _line_world(src, r)
        if lw is not None and r.on == FRAME:
            p0, u = lw
            foot = p0 + float(u @ (c - p0)) * u
            away = foot - c
            n = away / max(float(np.hypot(*away)), 1e-300)
            half = max(1.3 * r.radius, 0.4 * k)
            frame_group.items.extend(_ground(foot - half * u, foot + half * u, n, k))
            if not numbered_frame:
                panel.labels.append(LabelRequest("1", foot + half * u + 0.1 * k * n, "number",
                                                 f"{pre}number-1", frame_group, key="link 1",
                                                 gap=0.04))
                numbered_frame = True
    for sl in mech.sliders:
        if not is_known(sl.point):
            continue
        lw = _line_world(src, sl)
        if lw is None:
            continue
        u = lw[1]
        p = np.asarray(sol.position(sl.point, sl.link), dtype=float)
        hl, hh = BLOCK[0] * k, BLOCK[1] * k
        if sl.on == FRAME:
            nrm = np.array([-u[1], u[0]])
            sgn = -1.0 if float(nrm @ (centroid - p)) > 0 else 1.0
            base = p + sgn * hh * nrm
            a, b = base - 2.6 * hl * u, base + 2.6 * hl * u
            frame_group.items.extend(_ground(a, b, sgn * nrm, k))
            if not numbered_frame:
                panel.labels.append(LabelRequest("1", a + 0.3 * (b - a) + sgn * nrm * 0.08 * k,
                                                 "number", f"{pre}number-1", frame_group,
                                                 key="link 1", gap=0.04))
                numbered_frame = True
        g = panel.group(f"{pre}slider-{sl.link}", 2.5, key=f"link {sl.link}")
        g.items.append(Item("polygon", _rect(p, u, hl, hh), "block", key=f"link {sl.link}"))
        if sl.link not in rods and (len(mech.links[sl.link].points) <= 1 or sl.link not in [
                x for x in mech.moving if _has_outline(src, x)]):
            _number(panel, g, sl.link, p, pre, gap=BLOCK[1] + 0.05)

    # ---- frame bearings at fixed pivots ------------------------------
    frame_pts = mech.links[FRAME].points
    for name in frame_pts:
        if len(mech.point_links.get(name, [])) < 2:
            continue
        p = np.asarray(sol.position(name, FRAME), dtype=float)
        others = []
        for lid in mech.point_links[name]:
            if lid == FRAME:
                continue
            for q in link_points(src, lid).values():
                # a point on the pivot but for round-off leaves it in no direction
                if not is_zero(float(np.hypot(*(q - p))), mech.scale):
                    others.append((q - p) / float(np.hypot(*(q - p))))
        down = _free_direction(others)
        side = np.array([-down[1], down[0]])
        w, h = BEARING[0] * k, BEARING[1] * k
        b0, b1 = p + h * down - w * side, p + h * down + w * side
        frame_group.items.append(Item("polygon", np.array([p, b0, b1]), "bearing"))
        g0, g1 = p + h * down - 1.6 * w * side, p + h * down + 1.6 * w * side
        frame_group.items.extend(_ground(g0, g1, down, k))
        if not numbered_frame:
            panel.labels.append(LabelRequest("1", g1 + 0.06 * k * down, "number",
                                             f"{pre}number-1", frame_group, key="link 1",
                                             gap=0.04))
            numbered_frame = True

    # ---- points not marked by a construction step --------------------
    for name in mech.point_names:
        if name in drawn or not is_known(name) or name in mech.helper_points:
            continue
        from graphkin.render.paint import _is_joint_or_named_point

        p = np.asarray(sol.position(name), dtype=float)
        main = _is_joint_or_named_point(mech, name)
        style = ("pin" if len(mech.point_links[name]) >= 2 else "point") if main \
            else "aux-point"
        g = panel.group(f"{pre}point-{safe_id(name)}", 4.0, key=name)
        g.items.append(Item("marker", np.array([p]), style, key=name))
        panel.labels.append(LabelRequest(point_text(name), p, "label" if main else "label-aux",
                                         f"{pre}label-{safe_id(name)}", g, key=name))


def body_world(src: Source, body: Body) -> shapely.Geometry | None:
    """A ``[[bodies]]`` shape at the solved posture (world coordinates), or None if unsolved.

    A circle is a polygon of 96 sides; a face a line; an outline the polygon
    through its corners in the order written (its convex hull if it crosses
    itself).
    """
    sol = src.solution
    if sol is None or body.link not in sol.links:
        return None
    st = sol.links[body.link]
    if body.kind == "circle":
        assert body.center is not None and body.radius is not None
        c = np.asarray(st.position(body.center), dtype=float)
        return Point(float(c[0]), float(c[1])).buffer(body.radius, quad_segs=24)
    pts = [tuple(np.asarray(st.position(p), dtype=float)) for p in body.points]
    if body.kind == "face":
        return LineString(pts)
    poly = Polygon(pts)
    return poly if poly.is_valid and poly.area > 0 else MultiPoint(pts).convex_hull


def paint_bodies(src: Source, panel: Panel, known: set[str] | None) -> None:
    """Draw the ``[[bodies]]`` of the file: cam discs, rollers, faces, plates (Fig. 4.18).

    A disc or plate is shaded behind the links (the book's cam, Figs. 4.18 and
    4.20); a face is a bar of the link's width.  A body is drawn once every
    point of its link is constructed.
    """
    mech = src.mechanism
    if mech is None or src.solution is None:
        return
    k = panel.k
    for body in mech.bodies:
        if known is not None and not all(n in known for n in mech.links[body.link].points):
            continue
        geom = body_world(src, body)
        if geom is None:
            continue
        g = panel.group(f"{panel.prefix}body-{body.index}", 0.9, key=f"link {body.link}")
        if body.kind == "face":
            geom = geom.buffer(BAR_HALF * k, quad_segs=6)
        if isinstance(geom, Polygon) and not geom.is_empty:
            g.items.append(Item("polygon", _ring(geom),
                                "link" if body.kind == "face" else "plate",
                                key=f"link {body.link}"))


def _ground(a: np.ndarray, b: np.ndarray, out: np.ndarray, k: float) -> list[Item]:
    """A ground line from ``a`` to ``b`` with short slanted hatch strokes on the ``out`` side."""
    items = [Item("path", np.array([a, b]), "ground-line")]
    d = b - a
    length = float(np.hypot(*d))
    if length == 0:
        return items
    u = d / length
    step = HATCH[0] * k
    n = max(int(length / step), 1)
    stroke = HATCH[1] * k * (np.asarray(out) * 0.7071 - u * 0.7071)
    for i in range(n + 1):
        q = a + u * (i * length / n)
        items.append(Item("path", np.array([q, q + stroke]), "hatch"))
    return items


def _free_direction(dirs: list[np.ndarray]) -> np.ndarray:
    """The side of a pivot for its bearing: straight down unless a link is there.

    Of the four compass directions (down first), the one farthest from every
    link that leaves the pivot.
    """
    best, score = np.array([0.0, -1.0]), -2.0
    for cand in ((0.0, -1.0), (-1.0, 0.0), (1.0, 0.0), (0.0, 1.0)):
        c = np.array(cand)
        clearance = -max((float(c @ v) for v in dirs), default=-1.0)
        # by a clear margin: two sides as clear but for round-off keep the order above
        if clearance >= 0.35 - 1e-9:
            return c
        if clearance > score + 1e-9:
            best, score = c, clearance
    return best


def _has_outline(src: Source, lid: str) -> bool:
    """True when a link is drawn as a bar or plate (two or more distinct points)."""
    pts = link_points(src, lid)
    mech = src.mechanism
    hull = _hull(np.array(list(pts.values())), mech.scale if mech is not None else 1.0)
    return hull.geom_type != "Point"


def _hull(arr: np.ndarray, scale: float) -> Any:
    """The convex hull of a link's points; one point when they coincide but for round-off.

    Examples
    --------
    >>> _hull(np.array([[1.0, 2.0], [1.0 + 1e-15, 2.0]]), 1.0).geom_type
    'Point'
    """
    if len(arr) and np.all(np.hypot(*(arr - arr[0]).T) <= DEFAULT_TOL.length(scale)):
        return Point(*arr[0])
    return MultiPoint([tuple(p) for p in arr]).convex_hull


GEAR_Z = 0.75
"""Where a gear's disc is drawn: under the frame (0.8), the links (1.0) and the pins (4.0)."""


def _whole_disc(mech: Mechanism, sol: Any, r: Rolling) -> bool:
    """True when every point of the rolling link lies on or inside its circle (a gear)."""
    c = np.asarray(sol.position(r.center, r.link), dtype=float)
    return all(float(np.hypot(*(np.asarray(sol.position(n, r.link), dtype=float) - c)))
               - r.radius <= DEFAULT_TOL.length(r.radius) for n in mech.links[r.link].points)


def _other_discs(mech: Mechanism, sol: Any, is_known: Any) -> dict[str, Any]:
    """For each link, the union of the rollers' discs drawn over it (world coordinates).

    A gear's disc is drawn under the links (:data:`GEAR_Z`); a roller on a link over them.
    """
    rollers = [(r.link, Point(*np.asarray(sol.position(r.center, r.link), dtype=float)[:2])
                .buffer(r.radius, quad_segs=24)) for r in mech.rolling
               if is_known(r.center) and not _whole_disc(mech, sol, r)]
    return {lid: shapely.union_all([d for k, d in rollers if k != lid])
            for lid in mech.moving if any(k != lid for k, _ in rollers)}


def _join(body: Any, bar: Any) -> LineString:
    """The shortest bar from a link's body to a slide it does not reach.

    The shortest distance between two segments or polygons is reached at a
    vertex of one of them; between a body and a slide parallel to it, at every
    point of their overlap, where GEOS's nearest points fall as the last digits
    go.  Of the joins as short as the shortest but for round-off, the one
    nearest the body's middle.

    Examples
    --------
    >>> _join(LineString([(0, 0), (4, 0)]), LineString([(1, 2), (9, 2)])).coords[:]
    [(1.0, 0.0), (1.0, 2.0)]
    """
    def verts(g: Any) -> list[Point]:
        return [Point(c) for c in shapely.get_coordinates(g)]

    near = shapely.ops.nearest_points
    cands = [(v, near(v, bar)[1]) for v in verts(body)] + \
        [(near(w, body)[1], w) for w in verts(bar)]
    d = np.array([a.distance(b) for a, b in cands])
    size = max(float(np.ptp(np.asarray(body.bounds).reshape(2, 2), axis=0).max()),
               float(d.min()), 1e-300)
    mid = body.centroid
    best = min((i for i in range(len(cands)) if is_zero(d[i] - d.min(), size)),
               key=lambda i: round(cands[i][0].distance(mid) / size, 9))
    a, b = cands[best]
    return LineString([a, b])


def _beside_discs(line: Any, c: np.ndarray, discs: Any) -> np.ndarray:
    """The middle of a bar, else (under another link's disc) the middle of its longest part seen.

    Examples
    --------
    >>> bar = LineString([(0, 0), (7, 0)])          # an arm O-P, the planet's disc r = 4 at P
    >>> _beside_discs(bar, np.array([3.5, 0.0]), Point(7, 0).buffer(4.0)).round(6).tolist()
    [1.5, 0.0]
    """
    if discs is None or discs.is_empty or not discs.contains(Point(*c)):
        return c
    seen = line.difference(discs)
    parts = list(getattr(seen, "geoms", [seen]))
    parts = [q for q in parts if not q.is_empty and q.length > 0]
    if not parts:
        return c
    longest = max(parts, key=lambda q: q.length)
    return np.asarray(longest.interpolate(0.5, normalized=True).coords[0], dtype=float)


def _number(panel: Panel, g: Group, lid: str, anchor: np.ndarray, pre: str,
            gap: float = 0.05) -> None:
    gid = f"{pre}number-{lid}"
    # a link is numbered once: a planet's pin and its circles give one "4", at the last asked
    panel.labels[:] = [lab for lab in panel.labels if lab.gid != gid]
    panel.labels.append(LabelRequest(lid, np.asarray(anchor, dtype=float), "number",
                                     f"{pre}number-{lid}", g, key=f"link {lid}",
                                     gap=gap))


def mechanism_extent(src: Source) -> list[np.ndarray]:
    """Every point the mechanism drawing covers (world coordinates), for the panel's bounds."""
    mech, sol = src.mechanism, src.solution
    if mech is None or sol is None:
        return []
    out: list[np.ndarray] = []
    for lid in mech.links:
        out.extend(link_points(src, lid).values())
    guides: tuple[Slider | Slot, ...] = (*mech.sliders, *mech.slots)
    for s in guides:
        out.append(np.asarray(sol.position(s.point, s.link), dtype=float))
    for r in mech.rolling:
        c = np.asarray(sol.position(r.center, r.link), dtype=float)
        out.extend([c - r.radius, c + r.radius])
        if r.on_center is not None and r.on_radius is not None:   # the sun, the ring
            oc = np.asarray(sol.links[r.on].position(r.on_center), dtype=float)
            if np.all(np.isfinite(oc)):
                out.extend([oc - r.on_radius, oc + r.on_radius])
    for body in mech.bodies:
        geom = body_world(src, body)
        if geom is not None:
            x0, y0, x1, y1 = geom.bounds
            out.extend([np.array([x0, y0]), np.array([x1, y1])])
    return out
