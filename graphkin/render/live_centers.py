"""The instant centers of the live page: graphkin's Kennedy search, redone from each posture.

graphkin finds the instant centers of the file's posture the way the book
teaches (:func:`graphkin.kinematics.instant_centers.instant_centers`, Secs.
3.12-3.15 of Uicker, Pennock & Shigley, 5th ed.) and records every step: the
primary centers by inspection, the common normal of a pin in a slot, the
meets of two lines of centers (Aronhold-Kennedy) and, where no two lines
reach a center (two inputs, Sec. 5.4: the five-bar's I23), the point where
the two links have the same velocity.  Those steps are written out here as
one JavaScript function, in homogeneous coordinates (a center at infinity
is a direction), from the one table of templates
(:mod:`graphkin.construction.ops.templates`); its given points are read from
the posture function's results on every pointer move:

* a pin's center is the pin (``{"pin": name}``); a slider's is the point at
  infinity normal to its line (``{"slider": link, "angle": ...}``);
* a point of the posture, or of the velocity polygon (``{"at": name}``:
  a slot's pin, a point of a link and its image ``v(X)``, the pole ``o_v``);
* a point fixed in a moving link that the posture does not name (a slot's or
  a rolling path's points, ``{"body": X, "theta": "θk", "d": [dx, dy]}``:
  ``X + R(θk) d``); a point fixed in the frame keeps its recorded numbers;
* a link's ω (``{"scalar": "ωk"}``).

A center found from the velocities is recorded by graphkin as its value
(``homogeneous_point``); here it is the step ``equal_velocity_point`` of each
link's point, image and ω, so it moves with the page's velocities.

Whatever the page cannot redo says so in one line (``why``): centers graphkin
does not find either (two inputs and no rates), a center found from the
velocities on a page without them, a given the posture does not carry; they
are left out with every step that depends on them, and drawn dashed on the
Kennedy circle.  A posture where the recorded route has no clean answer (two
lines of centers coincide there) is said so by the page.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Secs. 3.12-3.15 (primary centers, the Aronhold-Kennedy theorem, the Kennedy
circle), Sec. 3.14 (direct contact: the common normal), Sec. 5.4 (centers
that depend on the input speeds).
"""

from __future__ import annotations

from collections.abc import Iterable
from itertools import combinations
from typing import Any

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.codegen import Unsupported
from graphkin.construction.jsgen import generate_js
from graphkin.errors import GraphkinError
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import DEFAULT_TOL

__all__ = ["CENTERS_CSS", "CENTERS_JS", "centers_data", "live_centers_construction"]

#: the steps that make a center from lines of centers (the lines drawn on the posture)
_CENTER_OPS = ("meet", "at_infinity_on")


class _Drop(Exception):
    """A given or step the page cannot redo; the message says why, in the user's words."""


def _body(mech: Mechanism, lid: str, local: Any, name: str | None, points: list[str],
          avoid: set[str]) -> dict[str, Any] | None:
    """How the page finds the point ``local`` of link ``lid`` from a posture (None: fixed).

    The point itself when the posture names it; else laid off from a point
    of the link the posture has (not a draggable one, whose local
    coordinates change): ``X + R(θ) (local - local_X)``, θ the link's angle.
    """
    if lid == FRAME:
        return None  # the frame's points stay where the file puts them
    if name is not None and name in points:
        return {"at": name}
    own = mech.links[lid].points
    anchor = next((n for n in own if n in points and n not in avoid), None)
    if anchor is None:
        raise _Drop(f"no point of link {lid} on the page to lay off its path from")
    d = np.subtract(np.asarray(local, dtype=float), np.asarray(own[anchor], dtype=float))
    return {"body": anchor, "theta": f"θ{lid}", "d": [float(d[0]), float(d[1])]}


def _paths(mech: Mechanism, steps: Iterable[Any]) -> dict[str, tuple[str, Any, str | None]]:
    """Label of each given point of a slot or rolling contact -> (link, local coords, name)."""
    steps = list(steps)
    out: dict[str, tuple[str, Any, str | None]] = {}

    def reader(label: str) -> Any:
        return next((s for s in steps if label in s.inputs), None)

    for s in mech.slots:
        stem = f"slots[{s.index}]"
        out[f"{stem}:L0"] = (s.on, s.p0, None)
        out[f"{stem}:L1"] = (s.on, s.p1, None)
        out[f"{stem}:center"] = (s.on, s.center, None)
        for ref in (f"{stem}:line", f"{stem}:center"):
            st = reader(ref)
            if st is not None and st.op in ("perpendicular", "join"):
                pin = next(i for i in st.inputs if i != ref)
                out[pin] = (s.link, mech.links[s.link].points[s.point], s.point)
    for r in mech.rolling:
        stem = r.key
        out[f"{stem}:O"] = (r.on, r.on_center, None)
        out[f"{stem}:L0"] = (r.on, r.p0, None)
        out[f"{stem}:L1"] = (r.on, r.p1, None)
        for ref in (f"{stem}:O", f"{stem}:line"):
            st = reader(ref)
            if st is not None and st.op in ("along_ray", "perpendicular"):
                c = next(i for i in st.inputs if i != ref)
                out[c] = (r.link, mech.links[r.link].points[r.center], r.center)
    return out


def _rates_of(mech: Mechanism, lid: str, points: list[str],
              made: set[str]) -> tuple[str, str, str | None]:
    """A point of link ``lid``, its velocity image and its ω, as the posture names them.

    The frame: the pole ``o_v`` for both (its velocity is zero everywhere) and
    ω = 0 (None).
    """
    if lid == FRAME:
        if "o_v" not in made:
            raise _Drop("the page has no velocity polygon")
        return "o_v", "o_v", None
    n = next((n for n in mech.links[lid].points if n in points and f"v({n})" in made), None)
    if n is None or f"ω{lid}" not in made:
        raise _Drop(f"the page has no velocity of link {lid}")
    return n, f"v({n})", f"ω{lid}"


def live_centers_construction(mech: Mechanism, ic: Any, points: list[str], made: set[str],
                              avoid: Iterable[str] = (), steps: Iterable[Any] | None = None
                              ) -> tuple[Construction,
                                                                  dict[str, dict[str, Any]],
                                                                  dict[str, str]]:
    """The centers' construction as the page redoes it, its given points, and what it leaves out.

    Parameters
    ----------
    mech : Mechanism
    ic : InstantCenters
        graphkin's centers of the file's posture.
    points, made : the page's points and every label its posture function makes.
    avoid : the draggable points (their local coordinates change).
    steps : the route's steps (default: the search's, ``ic.construction.steps``;
        the page's is :func:`~graphkin.kinematics.instant_centers.route.every_posture_route`).

    Returns
    -------
    (Construction, dict, dict)
        The steps (a center found from velocities as ``equal_velocity_point``),
        label -> how the page gives it (see the module's docstring), and label
        -> why a step is left out (with everything that depends on it).
    """
    from graphkin.kinematics.instant_centers import center_label

    avoid = set(avoid)
    prim: dict[str, dict[str, Any]] = {}
    for p in mech.pins:
        for i, j in combinations(p.links, 2):
            prim.setdefault(center_label(i, j), {"pin": p.name})
    for sl in mech.sliders:
        prim.setdefault(center_label(sl.link, sl.on), {"slider": sl.on,
                                                       "angle": float(sl.direction_angle)})
    route = list(ic.construction.steps if steps is None else steps)
    paths = _paths(mech, route)
    pair_of = {c.label: c.pair for c in ic.centers.values()}
    cx = Construction(title=ic.construction.title)
    given: dict[str, dict[str, Any]] = {}
    dropped: dict[str, str] = {}
    for st in route:
        lab = st.outputs[0] if st.outputs else ""
        gone = [i for i in st.inputs if i in dropped]
        if gone:
            dropped[lab] = dropped[gone[0]]
            continue
        try:
            if st.op in ("point", "ideal_point") and not st.inputs and lab in prim:
                given[lab] = prim[lab]
            elif st.op == "point" and not st.inputs and lab in paths:
                lid, local, name = paths[lab]
                how = _body(mech, lid, local, name, points, avoid)
                if how is not None:
                    given[lab] = how
            elif st.op == "homogeneous_point" and lab in pair_of:
                _from_velocities(cx, given, mech, lab, pair_of[lab], points, made)
                continue
            elif st.op in ("point", "ideal_point", "homogeneous_point") and not st.inputs:
                raise _Drop(f"the page does not know where {lab} is from the posture")
        except _Drop as exc:
            dropped[lab] = str(exc)
            continue
        cx.add(st.op, st.inputs, st.outputs, role=st.role, note=st.note, diagram="centers",
               **st.params)
    return cx, given, dropped


def _from_velocities(cx: Construction, given: dict[str, dict[str, Any]], mech: Mechanism,
                     lab: str, pair: tuple[str, str], points: list[str], made: set[str]) -> None:
    """``Iij`` where links i and j have the same velocity, from the posture's velocities."""
    try:
        rates = [_rates_of(mech, lid, points, made) for lid in pair]
    except _Drop as exc:
        raise _Drop(f"{lab} is found from the velocities, and {exc}") from None
    ins: list[str] = []
    # the points are given from the posture on every move (their recorded xy is not read)
    for lid, (p, v, w) in zip(pair, rates):
        given[f"{lab}:{lid}:P"] = {"at": p}
        given[f"{lab}:{lid}:v"] = {"at": v}
        cx.add("point", (), (f"{lab}:{lid}:P",), xy=(0.0, 0.0), diagram="centers")
        cx.add("point", (), (f"{lab}:{lid}:v",), xy=(0.0, 0.0), diagram="centers")
        if w is None:
            cx.add("scalar", (), (f"{lab}:{lid}:ω",), value=0.0, diagram="centers")
        else:
            given[f"{lab}:{lid}:ω"] = {"scalar": w}
            cx.add("input", (), (f"{lab}:{lid}:ω",), name=f"{lab}:{lid}:ω", diagram="centers")
        ins += [f"{lab}:{lid}:P", f"{lab}:{lid}:v", f"{lab}:{lid}:ω"]
    cx.add("equal_velocity_point", tuple(ins), (lab,), diagram="centers",
           note=f"{lab}: where links {pair[0]} and {pair[1]} have the same velocity "
                "(Sec. 3.12).", scale=float(mech.scale))


def centers_data(mech: Mechanism, points: list[str], made: set[str],
                 avoid: Iterable[str] = ()) -> tuple[dict[str, Any], str]:
    """The centers' data for the page and the JavaScript of their construction.

    Returns
    -------
    (dict, str)
        ``fn`` (the function's name, None when nothing can be written),
        ``given``, ``K``, ``labels`` (the centers the page computes, in the
        order of discovery), ``lines``, ``joins`` (each line of centers with
        the points known on it), ``meets``, ``links``, ``pairs`` (every pair,
        found or not: the Kennedy circle), ``why`` (one line, or ``""``); and
        the source of ``function centers(I, K)``.
    """
    from graphkin.kinematics.instant_centers import center_label, instant_centers
    from graphkin.kinematics.instant_centers.labels import sort_links
    from graphkin.kinematics.instant_centers.primary import FAR_AS_INFINITY
    from graphkin.kinematics.instant_centers.route import every_posture_route

    frame = list(mech.links[FRAME].points.values()) or [(0.0, 0.0)]
    origin = [sum(float(q[0]) for q in frame) / len(frame),
              sum(float(q[1]) for q in frame) / len(frame)]
    links = sort_links(mech.links)
    base: dict[str, Any] = {
        "fn": None, "given": {}, "K": [], "labels": [], "lines": [], "joins": [], "meets": [],
        "links": links, "pairs": {center_label(i, j): [i, j] for i, j in combinations(links, 2)},
        "kennedy": {},
        "frameAngle": 0.0, "far": FAR_AS_INFINITY * mech.scale, "origin": origin, "why": ""}
    try:
        sol = mech.solve()
        ic = instant_centers(sol)
    except GraphkinError as exc:
        base["why"] = f"graphkin finds no instant centers at the file's posture ({exc})"
        return base, ""
    base["frameAngle"] = float(np.asarray(sol.links[FRAME].angle, dtype=float))
    # the route for every posture: each center on the best of its lines where the page is
    route = every_posture_route(sol, ic)
    centers = route.centers
    missing = [c for c in base["pairs"] if c not in centers]
    why = list(ic.notes) if sorted(center_label(*p) for p in ic.missing) == sorted(missing) \
        else ([f"{', '.join(missing)}: not found (no two lines of centers reach them)"]
              if missing else [])
    cx, given, dropped = live_centers_construction(mech, ic, points, made, avoid,
                                                   steps=route.construction.steps)
    labels = [c for c in centers if c not in dropped]
    lost = [c for c in centers if c in dropped]
    if lost:
        reasons = list(dict.fromkeys(dropped[c] for c in lost))
        why.append(f"{', '.join(lost)} not redone on the page: {'; '.join(reasons)}")
    made_here = {o for s in cx.steps for o in s.outputs}
    lines = list(dict.fromkeys(i for s in cx.steps if s.op in _CENTER_OPS
                               and s.outputs[0] in labels for i in s.inputs))
    joins = []
    for s in cx.steps:
        if s.outputs and s.outputs[0] in lines:
            joins.append([s.outputs[0], *(i for i in s.inputs if i in made_here
                                          and _kind(cx, i) == "point")])
    meets = [[s.outputs[0], *s.inputs] for s in cx.steps
             if s.op == "meet" and s.outputs[0] in labels]
    # a center on the best pair of its lines at each posture: the lines it meets are its
    # outputs 'Iij|a', 'Iij|b', the pair's index 'Iij|k' says which points they pass through
    kennedy = {s.outputs[0]: {"lines": route.lines[s.outputs[0]],
                              "pairs": route.pairs[s.outputs[0]]}
               for s in cx.steps if s.op == "kennedy_center" and s.outputs[0] in labels}
    on_lines = [p for j in joins for p in j[1:]]
    on_lines += [p for lab in kennedy for ln in route.lines[lab] for p in ln]
    outs = [f"{lab}|{x}" for lab in kennedy for x in "abk"]
    requests = list(dict.fromkeys(labels + lines + on_lines + outs))
    base["why"] = "; ".join(why)
    if not labels:
        return base, ""
    try:
        # the points are read from the inputs; the ω's too, as numbers (``input`` steps)
        fn = generate_js(cx.steps, requests=requests, tol=DEFAULT_TOL, name="centers",
                         given=[k for k, v in given.items() if "scalar" not in v])
    except Unsupported as exc:
        base["why"] = "; ".join([*why, f"the centers cannot be written for the page ({exc})"])
        return base, ""
    base.update(fn="centers", given=given, K=fn.values, labels=labels, lines=lines,
                joins=joins, meets=meets, kennedy=kennedy)
    return base, fn.source


def _kind(cx: Construction, label: str) -> str:
    return next(s.kind for s in cx.steps if label in s.outputs)


CENTERS_JS = r"""
// The inputs of the written-out centers (Secs. 3.12-3.14) from the posture r, homogeneous:
// a pin is [x, y, 1]; a slider's center is at infinity normal to its line, [-sin θ, cos θ, 0],
// θ the angle of the link it slides on plus the line's own (Eq. 3.21); a point of the posture
// or of the velocity polygon; a point fixed in a link, X + R(θ) d; a link's ω
function gkCenterInputs(C, r) {
  const J = {};
  for (const lab of Object.keys(C.given)) {
    const g = C.given[lab];
    if (g.pin !== undefined || g.at !== undefined) {
      const p = r[g.pin !== undefined ? g.pin : g.at];
      if (!p) return null;
      J[lab] = [p[0], p[1], 1];
    } else if (g.scalar !== undefined) {
      const w = r[g.scalar];
      if (w === undefined) return null;
      J[lab] = w;
    } else if (g.body !== undefined) {
      const p = r[g.body], t = r[g.theta];
      if (!p || t === undefined) return null;
      const c = Math.cos(t), s = Math.sin(t);
      J[lab] = [p[0] + c * g.d[0] - s * g.d[1], p[1] + s * g.d[0] + c * g.d[1], 1];
    } else {
      let t = r["\u03b8" + g.slider];
      if (t === undefined) t = g.slider === "1" ? C.frameAngle : NaN;
      t += g.angle;
      J[lab] = [-Math.sin(t), Math.cos(t), 0];
    }
  }
  return J;
}
// every center and line of centers of the posture r (null where the recorded route has no
// clean answer: two lines of centers coincide, or two links have no relative motion)
function gkCenters(C, r) {
  if (!C || !r || !C.fn) return null;
  const J = gkCenterInputs(C, r);
  return J === null ? null : centers(J, C.K);
}
// the centers as graphkin's JSON gives them (docs/formats/json.md, spec/output.md):
// {position: [x, y]}, or {direction: [dx, dy]} (a unit vector, its first nonzero component
// positive) for a center at infinity by the page's own rule (gkAtInfinity), never a raw
// homogeneous point with w at round-off; null where the page cannot show that center
function gkCentersState(C, ics) {
  if (!ics || !C || !C.labels) return null;
  const out = {};
  for (const lab of C.labels) {
    const p = ics[lab];
    if (!p) { out[lab] = null; continue; }
    if (gkAtInfinity(C, p)) {
      const n = Math.hypot(p[0], p[1]);
      let dx = p[0] / n, dy = p[1] / n;
      if ((Math.abs(dx) <= 1e-9 && dy < 0) || dx < -1e-9) { dx = -dx; dy = -dy; }
      out[lab] = {direction: [dx + 0, dy + 0]};
    } else {
      out[lab] = {position: [p[0] / p[2], p[1] / p[2]]};
    }
  }
  return out;
}
// what the Kennedy panel cannot show, in one line (empty when it shows every center)
function gkCentersWhy(C, c) {
  if (!C.fn) return "No instant centers on this page: " + C.why + ".";
  if (c === null) {
    return "No instant centers at this posture: the recorded Kennedy construction has no " +
      "clean answer here (two lines of centers coincide, or two links move alike).";
  }
  return C.why ? "Not shown: " + C.why + "." : "";
}
"""
"""The page's glue of the centers: their inputs from the posture, the function, the note."""

CENTERS_CSS = """
#gk-centers-note { max-width: 400px; margin: .3em .5em; font-size: .85em; color: #c62828; }
#gk-centers-note:empty { display: none; }
"""
"""The style of the one line under the Kennedy circle (as wide as the panel)."""
