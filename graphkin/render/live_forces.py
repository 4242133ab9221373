"""The force-polygon panel of the live page: graphkin's force construction, of the posture.

graphkin records the graphic force analysis of a posture
(:func:`graphkin.forces.solve_forces`, Secs. 11.5-11.8 and 12.4-12.5 of
Uicker, Pennock & Shigley, 5th ed.): the applied forces (loads, couples,
d'Alembert's inertia forces ``-m A_G`` with ``-I_G α``, weights), the two-,
three- and four-force members link by link, one analysis per loaded link and
their superposition.  Its steps are written out here as one more JavaScript
function, from the force operations' templates
(:mod:`graphkin.forces.templates`, in the one table of templates), whose
givens come from the posture function on every pointer move:

* a point of the mechanism (``A``, ``G3``): its position;
* a slider's line direction ``u_<joint>`` and its normal ``n_<joint>``: the
  line's local direction turned by the angle ``θ`` of the link it is on;
* ``A_G``: the acceleration of the center of mass, ``a(G) - o_a``; ``αk``.

The loads, couples, masses and moments are the function's parameters
(``K``).  The order of the analysis (which link is a two- or three-force
member) is the file posture's, which a drag does not change away from the
postures where a line passes through a pin (there the function returns
``null``: the page says equilibrium cannot be held).

Friction at a slider or a straight slot (Sec. 11.10) is done as the book
does it by hand and :func:`~graphkin.forces.solve_forces` does it: a second
function ``forces0``, the construction without friction, gives each rough
joint's normal force's sense ``σ`` (and, without ``impending`` in the file,
the block's impending motion ``ι`` from its velocity); the construction with
friction then starts from each force's line leant by ``φ = atan μ``
(``n_<joint>``, made from the plain normal ``n°_<joint>``) and ends with the
check ``τ`` that the force presses the block; the page's glue turns a sense
over once where it pulls and says self-locking where both fail.  Each act is
an operation of :mod:`graphkin.forces.ops` with its template.

The free bodies (Fig. 11.5b-d) are drawn from the same values: each force
where it acts (the foot of its anchor point on its line of action, or a
slider's crossing of its sliding line).

What the page cannot redo says so in one line (``why``): gear teeth or a
rolling contact (such a mechanism has no live page at all: Newton's method
solves its posture), a pin in a circular slot, and a mechanism the graphic
method finds no order for (the matrix method solves it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, cast

import numpy as np

from graphkin.construction.codegen import Unsupported
from graphkin.construction.jsgen import generate_js
from graphkin.errors import GraphkinError
from graphkin.mechanisms.model import FRAME, Mechanism, Slider, Slot
from graphkin.render.live_bodies import BODIES_JS
from graphkin.tolerance import DEFAULT_TOL

__all__ = ["forces_data", "FORCES_JS"]


@dataclass
class _In:
    """A given of the force construction, as a step the JavaScript writer reads from ``I``."""

    op: str
    outputs: tuple[str, ...]
    inputs: tuple[str, ...] = ()
    params: dict[str, Any] = field(default_factory=dict)


_LINES = ("join", "force_line", "force_line_of")


class _Why(Exception):
    """The page cannot redo this mechanism's forces: the one line saying why."""


def _why(mech: Mechanism) -> str | None:
    """Why the page cannot redo this mechanism's forces (one line), or None."""
    if mech.pressure or mech.rolling:
        return ("gear teeth or a rolling contact: the page does not redo their posture "
                "(Newton's method solves it), so neither their forces")
    if any(isinstance(s, Slot) and not s.is_line for s in mech.slots):
        return "a pin in a circular slot: its force's line is not redrawn live yet"
    return None


def _givens(steps: list[Any], points: list[str], made: set[str],
            sliders: dict[str, Any]) -> tuple[dict[str, dict[str, Any]], list[_In]]:
    """What a force construction reads from the page, each as a given of its function.

    Raises
    ------
    _Why
        It reads something the page does not redraw.
    """
    made_f = {o for st in steps for o in st.outputs}
    read = list(dict.fromkeys(i for st in steps for i in st.inputs if i not in made_f))
    given: dict[str, dict[str, Any]] = {}
    ins: list[_In] = []
    for lab in read:
        spec: dict[str, Any] | None = None
        head, _, key = lab.partition("_")
        if lab in points:
            spec = {"point": lab}
        elif head in ("n", "u", _PLAIN) and key in sliders:
            src = sliders[key]
            p0, p1 = src.p0, src.p1
            if p0 is not None and p1 is not None and f"θ{src.on}" in made:
                d = np.subtract(p1, p0).astype(float)
                spec = {"dir": [float(d[0]), float(d[1])], "link": src.on,
                        "as": "along" if head == "u" else "normal"}
        elif lab.startswith("A_") and f"a({lab[2:]})" in made and "o_a" in made:
            spec = {"accel": lab[2:]}
        elif lab.startswith("α") and lab in made:
            ins.append(_In("input", (lab,)))
            given[lab] = {"alpha": lab}
            continue
        elif head in (_SENSE, _MOVING) or lab == _SCALE0:  # found by the pass without friction
            ins.append(_In("input", (lab,)))
            given[lab] = {"prior": lab}
            continue
        elif head == "V" and key in points and f"v({key})" in made and "o_v" in made:
            spec = {"vel": key}  # a point's velocity V_P = v(P) - o_v
        elif head == f"V{_AT}":  # the frame's velocity at the block's point: none
            spec = {"const": [0.0, 0.0]}
        elif head == f"ω{_AT}" or (lab.startswith("ω") and lab in made):
            ins.append(_In("input", (lab,)))
            given[lab] = {"const": 0.0} if head == f"ω{_AT}" else {"scalar": lab}
            continue
        if spec is None and (lab.startswith("A_") or lab.startswith("α")):
            raise _Why("the inertia forces need the accelerations, which this page does not "
                       "re-solve (rates given for another link than the drive)")
        if spec is None:
            raise _Why(f"the force construction reads {lab}, which the page does not redraw")
        given[lab] = spec
        ins.append(_In("point", (lab,)))
    return given, ins


# the labels of the friction steps (Sec. 11.10), with prefixes a point cannot be named
# with (graphkin.mechanisms.names.LABEL_PREFIXES): no point is read for them
_PLAIN, _SENSE, _TURNED, _SCALE0, _SCALE = "n°", "σ", "τ", "F_‖0", "F_‖"
_MOVING, _AT, _VSCALE = "ι", "°", "V_‖"


def _friction(mech: Mechanism, fs: Any, rough: list[Any], points: list[str],
              made: set[str]) -> tuple[list[_In], list[_In], list[_In], Any]:
    """The friction steps around the force construction, as Sec. 11.10 does it by hand.

    Returns the steps after the frictionless construction (its forces' scale
    and the sense σ of each rough joint's normal force on the block), those
    before the construction with friction (each rough joint's line leant by
    φ = atan μ from the normal against the impending motion: its ``n_``), those
    after it (τ: 1 where the force found pulls the block instead, the sense to
    be turned), and the frictionless construction itself.
    """
    from graphkin.forces.graphic import NotDecomposable, build_forces
    from graphkin.forces.joints import geometry

    sol = fs.solution
    try:  # the frictionless construction: the plain normals (Sec. 11.10, "first without")
        built0 = build_forces(sol, fs.joints, geometry(sol, fs.joints), fs.dynamic, DEFAULT_TOL)
    except (NotDecomposable, GraphkinError) as exc:
        raise _Why(f"friction: no graphic construction without friction here ({exc})") from None
    couples = {o for st in built0.construction.steps if st.op == "force_couple"
               for o in st.outputs}
    applied0 = [lab for labs in built0.applied.values() for lab in labs]
    joints0 = [built0.forces[j.key] for j in fs.joints]
    pre = [_In("force_scale", (_SCALE0,), (*applied0, *joints0),
               {"kinds": tuple("couple" if lab in couples else "force" for lab in applied0)
                + ("force",) * len(joints0), "size": float(mech.size or 1.0)})]
    head: list[_In] = []
    built = fs.built
    tail = [_In("force_scale", (_SCALE,), (_SCALE0, *(built.forces[j.key] for j in fs.joints)),
                {"kinds": ("scale",) + ("force",) * len(fs.joints), "size": 1.0})]
    for j in rough:
        src, key = j.source, j.key
        mu, impending = mech.friction[src.key]
        block = "hi" if src.link == j.hi else "lo"
        sense = f"{_SENSE}_{key}"
        pre.append(_In("force_normal_sense", (sense,),
                       (built0.forces[key], f"n_{key}", _SCALE0), {"block": block}))
        if impending is None:  # the block's motion along its guide, from the velocities
            pre += _impending(mech, src, key, points, made, pre)
            head.append(_In("force_friction_normal", (f"n_{key}",),
                            (f"{_PLAIN}_{key}", f"u_{key}", sense, f"{_MOVING}_{key}"),
                            {"mu": float(mu), "impending": None}))
        else:
            head.append(_In("force_friction_normal", (f"n_{key}",),
                            (f"{_PLAIN}_{key}", f"u_{key}", sense),
                            {"mu": float(mu),
                             "impending": 1.0 if impending == "ahead" else -1.0}))
        tail.append(_In("force_turned", (f"{_TURNED}_{key}",),
                        (built.forces[key], f"n_{key}", _SCALE, sense), {"block": block}))
    return pre, head, tail, built0


def _impending(mech: Mechanism, src: Any, key: str, points: list[str], made: set[str],
               pre: list[_In]) -> list[_In]:
    """The steps finding a block's impending motion from the velocities (ι, Sec. 11.10).

    As :func:`graphkin.forces.solve_forces` does: the block's point's velocity
    less the guide's at that point (``V_Q + ω × (P - Q)``, Q a point of the
    guide; none for the frame), along the guide, its sign taken against the
    velocities' size (every point's |V| and every link's |ω| times the
    mechanism's size, as :meth:`~graphkin.kinematics.Solution.velocity_scale`).
    """
    p = src.point
    if p not in points or f"v({p})" not in made:
        raise _Why(f"friction at {src.key}: the page has no velocity of {p} to find its "
                   "impending motion from (give impending = \"ahead\" or \"behind\")")
    out: list[_In] = []
    if not any(st.outputs == (_VSCALE,) for st in pre):
        vel = [f"V_{n}" for n in points if f"v({n})" in made]
        rates = [f"ω{lid}" for lid in mech.links if f"ω{lid}" in made]
        out.append(_In("force_scale", (_VSCALE,), (*vel, *rates),
                       {"kinds": ("force",) * len(vel) + ("rate",) * len(rates),
                        "size": float(mech.size)}))
    if src.on == FRAME:
        guide = (f"V{_AT}_{key}", p, f"ω{_AT}_{key}")
    else:
        pins = mech.links[FRAME].points  # a pivot of the guide has no velocity
        q = next((n for n in mech.links[src.on].points if n in points and f"v({n})" in made),
                 None) or next((n for n in mech.links[src.on].points
                               if n in points and n in pins), None)
        if q is None or f"ω{src.on}" not in made:
            raise _Why(f"friction at {src.key}: the page has no velocity of link {src.on} "
                       "to find the impending motion from (give impending = \"ahead\" or "
                       "\"behind\")")
        guide = (f"V_{q}" if f"v({q})" in made else f"V{_AT}_{key}", q, f"ω{src.on}")
    out.append(_In("force_impending", (f"{_MOVING}_{key}",),
                   (f"V_{p}", guide[0], guide[1], p, guide[2], f"u_{key}", _VSCALE)))
    return out


def forces_data(mech: Mechanism, points: list[str],
                made: set[str]) -> tuple[dict[str, Any], str] | None:
    """The force panel's data and the JavaScript of its construction, or None (no loads).

    Parameters
    ----------
    mech : Mechanism
    points : list of str
        The points the posture function returns (with ``a(X)`` when it has rates).
    made : set of str
        Every label the posture function can return (``θk``, ``αk`` among them).

    Returns
    -------
    (dict, str) or None
        None when the file has no loads and no mass properties.  Otherwise
        ``({"why": line}, "")`` when the page cannot redo the construction,
        else the panel's data (``given``, ``labels``, ``K``, ``polygons``,
        ``joints``, ``drives``; with friction ``given0``, ``K0`` and
        ``rough``) and the source of ``forces(I, K)`` (and ``forces0(I, K)``,
        the frictionless pass).
    """
    try:
        return _forces_data(mech, points, made)
    except _Why as why:
        return {"why": str(why)}, ""


def _forces_data(mech: Mechanism, points: list[str],
                 made: set[str]) -> tuple[dict[str, Any], str] | None:
    import graphkin.forces.templates  # noqa: F401  (registers the force templates)
    from graphkin.forces import solve_forces
    from graphkin.render.forces_sheet import DRIVE, GREY_INK, INERTIA, JOINT, LOAD

    if not mech.loads and not mech.inertia:
        return None
    why = _why(mech)
    if why is not None:
        raise _Why(why)
    try:
        fs = solve_forces(mech.solve())
    except GraphkinError as exc:
        raise _Why(f"no force analysis at the file's posture ({exc})") from None
    built = fs.built
    if built is None:
        raise _Why("the graphic method finds no link-by-link order here (the matrix "
                   "method solves it): graphkin draw -d forces draws it")
    steps = list(built.construction.steps)
    sliders: dict[str, Any] = {j.key: j.source for j in fs.joints
                               if isinstance(j.source, (Slider, Slot))}
    rough = [j for j in fs.joints if j.key in sliders and sliders[j.key].key in mech.friction]
    extra: dict[str, Any] = {}
    source0 = ""
    head: list[_In] = []
    tail: list[_In] = []
    if rough:
        pre, head, tail, built0 = _friction(mech, fs, rough, points, made)
        steps0 = [*built0.construction.steps, *pre]
        given0, ins0 = _givens(steps0, points, made, sliders)
        moving = [f"{_MOVING}_{j.key}" for j in rough if mech.friction[sliders[j.key].key][1]
                  is None]
        try:
            fn0 = generate_js(cast(Any, [*ins0, *steps0]),
                              requests=[_SCALE0, *(f"{_SENSE}_{j.key}" for j in rough),
                                        *moving],
                              tol=DEFAULT_TOL, name="forces0",
                              given=[i.outputs[0] for i in ins0 if i.op == "point"],
                              homogeneous=False)
        except Unsupported as exc:
            raise _Why(f"the frictionless construction cannot be written for the page "
                       f"({exc})") from None
        source0 = fn0.source
        extra = {"given0": given0, "K0": fn0.values,
                 "rough": [{"key": j.key, "link": sliders[j.key].link,
                            "phi": math.degrees(math.atan(mech.friction[sliders[j.key].key][0]))}
                           for j in rough]}
    made_f = {o for st in [*head, *steps] for o in cast(Any, st).outputs}
    given, ins = _givens([*head, *steps, *tail], points, made, sliders)
    labels = [o for st in steps if st.op not in _LINES for o in st.outputs]
    # a slider drive's input force after superposition is its size along the line only
    # (F_C·u = F_C′·u + F_C″·u, Sec. 12.5): the polygon draws it along the given u
    along: dict[str, str] = {}
    for lid, lab in built.drive_forces.items():
        d = next(x for x in mech.drives if x.link == lid)
        key = next((j.key for j in fs.joints if j.source is d.slider), None)
        if lab not in made_f and key is not None and f"u_{key}" in given:
            along[lid] = f"u_{key}"
            labels.append(f"u_{key}")
    try:
        fn = generate_js(cast(Any, [*ins, *head, *steps, *tail]),
                         requests=[*labels, *(f"{_TURNED}_{j.key}" for j in rough)],
                         tol=DEFAULT_TOL, name="forces",
                         given=[i.outputs[0] for i in ins if i.op == "point"],
                         homogeneous=False)
    except Unsupported as exc:
        raise _Why(f"the force construction cannot be written for the page ({exc})") from None
    kinds = {o: s.kind for s in steps for o in s.outputs}
    # each moving link's force polygon: the forces ON it, head to tail (they close, Σ F = 0)
    colour = {"load": LOAD, "couple": LOAD, "weight": LOAD, "inertia": INERTIA}
    from graphkin.forces.graphic import applied_labels

    applied = applied_labels(mech, fs.dynamic)
    rough_keys = {j.key for j in rough}
    # a link solved as a three-force member: its concurrency point (Fig. 11.5e), one analysis
    concurrency = {lid: f"X_{lid}" for lid in mech.moving
                   if len(fs.partials) == 1 and f"X_{lid}" in made_f}
    polygons: dict[str, list[dict[str, Any]]] = {}
    couples: dict[str, list[dict[str, Any]]] = {}
    acting: list[dict[str, Any]] = []  # the applied forces where they act (the free bodies)
    frame_angle = float(np.asarray(fs.solution.links[FRAME].angle, dtype=float))
    for lid in mech.moving:
        poly: list[dict[str, Any]] = []
        for lab, kind, src in applied.get(lid, []):
            if kind == "couple":
                couples.setdefault(lid, []).append({"label": lab, "text": _text(lab),
                                                    "color": colour[kind]})
                continue
            at = src.point if kind == "load" else src.center
            poly.append({"label": lab, "name": lab, "sign": 1, "color": colour[kind],
                         "text": _text(lab), "at": at if at in points else None})
            if at in points:
                acting.append({"label": lab, "at": at, "color": colour[kind],
                               "text": _text(lab)})
        for j in fs.joints:
            if lid in (j.lo, j.hi):
                entry: dict[str, Any] = {"label": built.forces[j.key], "name": j.label(lid),
                         "sign": 1 if lid == j.hi else -1, "color": JOINT,
                         "text": _text(j.label(lid)),
                         "at": j.point if j.point in points else None}
                slide = _sliding(j.source, made, frame_angle)
                if j.kind == "slide" and slide is not None:
                    entry["slide"] = slide  # acts where its line crosses the sliding line
                if j.key in rough_keys and slide is not None:
                    # drawn with its normal and friction components (Sec. 11.9, Fig. 11.11b)
                    by, at = j.other(lid), j.key.partition("@")[2]
                    where = f" at {at}" if at else ""
                    sub = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")
                    entry.update(rough=slide, parts=[f"Fⁿ{by}{lid}".translate(sub) + where,
                                                     f"Fᵗ{by}{lid}".translate(sub) + where])
                poly.append(entry)
        if lid in built.drive_forces:
            lab = built.drive_forces[lid]
            d = next(x for x in mech.drives if x.link == lid)
            at = d.slider.point if d.slider is not None else None
            entry = {"label": lab, "name": lab, "sign": 1, "color": DRIVE, "text": _text(lab),
                     "at": at if at in points else None}
            if lid in along:
                poly.append({**entry, "label": built.drives[lid], "along": along[lid]})
            elif lab in made_f:
                poly.append(entry)
        polygons[lid] = poly
    drives: dict[str, dict[str, Any]] = {}
    for lid, lab in built.drives.items():
        d = next(x for x in mech.drives if x.link == lid)
        drives[lid] = {"label": lab, "kind": "torque" if lab.startswith("T_") else "force",
                       "text": _text(lab), "at": d.pivot if d.pivot in points else None}
    return ({**extra, "given": given, "labels": labels, "K": fn.values,
             "kinds": {lab: kinds.get(lab, "force") for lab in labels},
             "polygons": polygons, "couples": couples, "acting": acting, "drives": drives,
             "drive_color": DRIVE, "joints": {j.key: built.forces[j.key] for j in fs.joints},
             "jointText": {j.key: _text(built.forces[j.key]) for j in fs.joints},
             "concurrency": concurrency, "grey": GREY_INK, "inertia_color": INERTIA,
             "frame": FRAME, "notes": list(fs.notes)}, source0 + fn.source)


def _text(label: str) -> str:
    """A force's name as ``draw -d forces`` prints it (``F_34′`` -> ``F₃₄′``), for the page."""
    from graphkin.render.forces import force_name

    return force_name(label).replace("\\$", "$")  # mathtext's escape: not on a web page


def _sliding(src: Any, made: set[str], frame_angle: float) -> dict[str, Any] | None:
    """A slider's line direction (local, its link, the frame's angle), or None."""
    if not isinstance(src, (Slider, Slot)) or src.p0 is None or src.p1 is None:
        return None
    if src.on != FRAME and f"θ{src.on}" not in made:
        return None
    d = np.subtract(src.p1, src.p0).astype(float)
    return {"dir": [float(d[0]), float(d[1])], "link": src.on, "angle0": frame_angle}


FORCES_JS = r"""
// the givens of the force construction (Secs. 11.5-12.5) from the posture r: points, a
// slider's line direction (or its normal) turned by its link's angle, A_G = a(G) - o_a, α;
// with friction, what the frictionless pass found (prior: the senses σ, the forces' scale)
function gkForceInputs(F, r, given, prior) {
  const J = {}, G = given || F.given;
  for (const lab of Object.keys(G)) {
    const g = G[lab];
    if (g.point !== undefined) { if (!r[g.point]) return null; J[lab] = r[g.point]; }
    else if (g.dir !== undefined) {
      const t = r["\u03b8" + g.link];
      if (!Number.isFinite(t)) return null;
      const c = Math.cos(t), s = Math.sin(t);
      let x = c * g.dir[0] - s * g.dir[1], y = s * g.dir[0] + c * g.dir[1];
      const n = Math.hypot(x, y);
      x /= n; y /= n;
      J[lab] = g.as === "normal" ? [-y, x] : [x, y];  // the normal: turned 90° ccw
    } else if (g.accel !== undefined) {
      const a = r["a(" + g.accel + ")"], o = r.o_a;
      if (!a || !o) return null;
      J[lab] = [a[0] - o[0], a[1] - o[1]];
    } else if (g.alpha !== undefined) J[lab] = r[g.alpha];
    else if (g.prior !== undefined) J[lab] = prior ? prior[g.prior] : undefined;
    else if (g.vel !== undefined) {  // a point's velocity, V_P = v(P) - o_v
      const v = r["v(" + g.vel + ")"], o = r.o_v;
      if (!v || !o) return null;
      J[lab] = [v[0] - o[0], v[1] - o[1]];
    } else if (g.scalar !== undefined) J[lab] = r[g.scalar];
    else if (g.const !== undefined) J[lab] = g.const;
  }
  return J;
}
// the force construction of the posture r (null where equilibrium cannot be held cleanly).
// With friction (Sec. 11.10), as the book does it: first without friction (forces0) for the
// sense σ of each rough joint's normal force, then with each force leant by φ from the
// normal against the impending motion; where the force found pulls the block instead (τ),
// that sense is turned and the analysis redone, once; turned twice, the posture is
// self-locking: {selfLocking: joint} (graphkin.forces.solve's verdict)
function gkForces(F, r) {
  if (F.why) return null;
  if (!F.rough) {
    const J = gkForceInputs(F, r);
    return J === null ? null : forces(J, F.K);
  }
  const J0 = gkForceInputs(F, r, F.given0);
  const r0 = J0 === null ? null : forces0(J0, F.K0);
  if (r0 === null) return null;
  // a block at rest on its guide has no impending motion to oppose: graphkin asks for it
  for (const j of F.rough) if (r0["\u03b9_" + j.key] === 0) return {atRest: j};
  const prior = Object.assign({}, r0), tried = {};
  for (;;) {
    const J = gkForceInputs(F, r, F.given, prior);
    const out = J === null ? null : forces(J, F.K);
    if (out === null) return null;
    const turned = F.rough.filter((j) => out["\u03c4_" + j.key] > 0);
    if (!turned.length) return out;
    for (const j of turned) {
      if (tried[j.key]) return {selfLocking: j};
      tried[j.key] = true;
      prior["\u03c3_" + j.key] = -prior["\u03c3_" + j.key];
    }
  }
}
"""
"""The page's glue of the force construction (in the page's library, beside the centers')."""

FORCES_APP_JS = r"""
// the force polygons (Secs. 11.6-11.8, 12.5): each moving link's forces head to tail, in the
// colours of `draw -d forces` (loads blue, inertia forces red, the drive green, joints black)
let frc = null;
const fsvg = byId("gk-forces"), fnote = byId("gk-forces-note");
fsvg.setAttribute("viewBox", "0 0 " + W + " " + H);
if (!D.forces) fsvg.parentNode.style.display = "none";
function forceVec(f) {
  const w = frc[f.label];
  if (f.along !== undefined) {  // a size along a given direction (a slider drive's force)
    const u = frc[f.along];
    return Number.isFinite(w) && u ? [w * u[0], w * u[1]] : null;
  }
  return w ? [f.sign * w[0], f.sign * w[1]] : null;
}
function drawForces(r, stale) {
  drawForcePolygons(r, stale);
  drawBodies(r, stale);
}
function drawForcePolygons(r, stale) {
  const F = D.forces;
  fsvg.textContent = "";
  frc = F.why ? null : gkForces(F, r);
  if (F.why) { fnote.textContent = "No live force polygons: " + F.why + "."; return; }
  if (frc && frc.atRest) {  // graphkin solve: "say impending = ahead or behind"
    const j = frc.atRest;
    frc = null;
    fnote.textContent = "The block at " + j.key + " is at rest relative to its guide at this " +
      "posture: its impending motion is not known (give impending = \"ahead\" or " +
      "\"behind\" in the file).";
    return;
  }
  if (frc && frc.selfLocking) {  // Sec. 11.10: no drive moves it (graphkin solve says so)
    const j = frc.selfLocking;
    frc = null;
    fnote.textContent = "Self-locking at this posture: the force on link " + j.link +
      " lies within the friction angle \u03c6 = " + j.phi.toFixed(2) + "\u00b0 of its " +
      "guide's normal, so no drive moves it (Sec. 11.10).";
    return;
  }
  if (frc === null) {
    fnote.textContent = "Equilibrium cannot be held cleanly at this posture (a dead center " +
      "of the force construction): no force polygon.";
    return;
  }
  let big = 0;
  for (const lid of Object.keys(F.polygons)) {
    for (const f of F.polygons[lid]) {
      const v = forceVec(f);
      if (v) big = Math.max(big, Math.hypot(v[0], v[1]));
    }
  }
  fnote.textContent = big > 0 ? "" : "No force acts at this posture.";
  if (!(big > 0)) return;
  const chains = [], pts = [];
  let x0 = 0;
  for (const lid of Object.keys(F.polygons)) {
    const chain = [];
    let p = [x0, 0], right = x0;
    for (const f of F.polygons[lid]) {
      const v = forceVec(f);
      if (!v || Math.hypot(v[0], v[1]) <= 1e-9 * big) continue;
      const q = [p[0] + v[0], p[1] + v[1]];
      chain.push([p, q, f]);
      pts.push(p, q);
      right = Math.max(right, p[0], q[0]);
      p = q;
    }
    if (!chain.length) continue;
    chains.push([lid, chain]);
    let left = x0;
    for (const [a, b] of chain) left = Math.min(left, a[0], b[0]);
    x0 += (right - left) + 0.35 * big;
  }
  fitPoints("forces", pts);
  const d = el(fsvg, "defs", {});
  const marks = {};
  const g = el(fsvg, "g", stale ? {class: "gk-stale"} : {});
  for (const [lid, chain] of chains) {
    for (const [a, b, f] of chain) {
      if (!marks[f.color]) {
        const id = UID + "gk-forces-arrow-" + Object.keys(marks).length;
        const m = el(d, "marker", {id: id, viewBox: "0 0 10 10", refX: "10", refY: "5",
                                   markerWidth: "7", markerHeight: "7",
                                   orient: "auto-start-reverse"});
        el(m, "path", {d: "M0,1 L10,5 L0,9 z", fill: f.color});
        marks[f.color] = id;
      }
      el(g, "line", {x1: X("forces", a), y1: Y("forces", a), x2: X("forces", b),
                     y2: Y("forces", b), stroke: f.color,
                     "stroke-width": px(ink("result-line", "lw")),
                     "marker-end": "url(#" + marks[f.color] + ")", class: "gk-force",
                     "data-name": f.name});
      // two thirds along: a two-force member's F_12 and F_32 (out and back) apart
      label(g, "forces", [a[0] + 0.65 * (b[0] - a[0]), a[1] + 0.65 * (b[1] - a[1])],
            f.text || f.name, "vector");
    }
    // the link's name under its polygon
    let lo = Infinity, sx = 0;
    for (const [a, b] of chain) { lo = Math.min(lo, a[1], b[1]); sx += a[0] + b[0]; }
    const o = [sx / (2 * chain.length), lo];
    el(g, "text", {x: X("forces", o), y: Y("forces", o) + 18, "font-size": "11",
                   "text-anchor": "middle"}, "link " + lid);
  }
}
// the applied forces on the posture, where they act (an inertia force offset from G by h so
// that its moment about G is -I_G α, Eq. 12.18), the largest a quarter of the panel long
function drawActing(r, stale) {
  const F = D.forces, v = views.posture;
  if (!frc || !v || !F.acting.length) return;
  let big = 0;
  for (const a of F.acting) { const w = frc[a.label]; big = Math.max(big, Math.hypot(w[0], w[1])); }
  if (!(big > 0)) return;
  const k = 0.25 * (W - 2 * M) / v.s / big;
  const g = el(svgs.posture, "g", stale ? {class: "gk-stale"} : {});
  const d = el(g, "defs", {});
  const marks = {};
  for (const a of F.acting) {
    const w = frc[a.label], p = r[a.at], f2 = w[0] * w[0] + w[1] * w[1];
    if (!p || !(f2 > 1e-18 * big * big)) continue;
    const h = (w[2] - (p[0] * w[1] - p[1] * w[0])) / f2;
    const tip = [p[0] + h * w[1], p[1] - h * w[0]], tail = [tip[0] - k * w[0], tip[1] - k * w[1]];
    if (!marks[a.color]) {
      const id = UID + "gk-acting-arrow-" + Object.keys(marks).length;
      const m = el(d, "marker", {id: id, viewBox: "0 0 10 10", refX: "10", refY: "5",
                                 markerWidth: "7", markerHeight: "7", orient: "auto"});
      el(m, "path", {d: "M0,1 L10,5 L0,9 z", fill: a.color});
      marks[a.color] = id;
    }
    el(g, "line", {x1: X("posture", tail), y1: Y("posture", tail), x2: X("posture", tip),
                   y2: Y("posture", tip), stroke: a.color, "stroke-width": "1.6",
                   "marker-end": "url(#" + marks[a.color] + ")", class: "gk-acting",
                   "data-name": a.label});
    label(g, "posture", tail, a.text || a.label, "vector");  // as draw -d forces names it (P₄)
  }
}
function forceTable() {
  const t = byId("gk-force-table");
  t.textContent = "";
  if (!D.forces || !frc) return;
  const head = el0(t, "tr");
  for (const h of ["force", "x", "y", "|F|"]) el0(head, "th", h);
  const keys = Object.keys(D.forces.joints).filter((k) => frc[D.forces.joints[k]]);
  // the scale of the column: the largest joint force (round-off of it reads 0)
  const sf = colScale(keys.map((k) => Math.hypot(...frc[D.forces.joints[k]])));
  for (const key of keys) {
    const lab = D.forces.joints[key], w = frc[lab];
    const row = el0(t, "tr");
    // named as draw -d forces names it (F_12 -> F₁₂)
    el0(row, "th", (D.forces.jointText || {})[key] || lab);
    el0(row, "td", fmt(w[0], sf)); el0(row, "td", fmt(w[1], sf));
    el0(row, "td", fmt(Math.hypot(w[0], w[1]), sf));
  }
  for (const lid of Object.keys(D.forces.drives)) {
    const dv = D.forces.drives[lid], v = frc[dv.label];
    const row = el0(t, "tr");
    el0(row, "th", (dv.text || dv.label) + (dv.kind === "torque" ? " (ccw)" : ""));
    el0(row, "td", fmt(v)); el0(row, "td", ""); el0(row, "td", "");
  }
}
"""
"""The panel's part of the page's script, inside ``gkLiveApp`` (``frc``: the forces shown)."""

FORCES_APP_JS += BODIES_JS

