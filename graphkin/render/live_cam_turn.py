"""The live page of a cam mechanism turns the cam: its equivalent linkage rebuilt at every angle.

A ``[[cams]]`` joint is solved through the equivalent linkage through the
centers of curvature at the file's cam angle (Sec. 4.7,
:mod:`graphkin.cams.joint`): the pin ``K<f>`` on the cam at the pitch curve's
center of curvature and a coupler ``|ρ|`` long to the roller's center
``T<f>``.  Those numbers are the only ones of the page's construction that
change with the cam angle.  So when the user drags the cam (its contact
point) or the drive's slider, the page

1. evaluates the cam at the new angle with the two operations of the one
   table (``cam_program``, ``cam_center``: :mod:`graphkin.cams.turning`,
   written out as JavaScript by :func:`~graphkin.construction.jsgen.generate_js`),
2. writes ``K<f>``'s coordinates on the cam and ``|ρ|`` into the
   construction's numbers ``K`` (the slots found here, by name), and the
   branch of ``T<f>`` that puts the roller's center where the program puts
   it (as ``graphkin solve`` picks it from its assembly hint),
3. runs the construction, then every panel, as for any page.

So every value equals ``graphkin solve`` of the file saved with the new angle
(tests/render/test_live_cam_turn.py).  Where the pitch curve is straight at
the contact (ρ infinite: no center, no linkage, as ``solve`` refuses it) the
page says so in one line and keeps the last posture, dimmed; where the roller
is larger than the convex pitch curve's radius (the profile undercut, Sec.
6.10) it says that the follower leaves the profile.  Every posture shows the
cam angle Θ, the lift and the pitch curve's ρ with its sense (convex,
concave).

An oscillating flat face turns the same way: its slot ``F<f>a``-``F<f>b`` lies
at the offset ``y`` the cam gives, so ``y`` goes into the slot's points, the
tangent's offset ``|y|`` from the pivot, and the complex ratios of their
velocity and acceleration images; its branch is checked on ``F<f>a`` (the
program's foot of the pivot on the face's slot).  A translating flat face's
slot lies at ``x = −ρ`` along its guide: that goes into the slot's points' first
coordinates (it has no branch: its two straight paths meet once).

A cam on another drive's link turns with that drive's input (a law following
the first, or held).  A cam on a link the linkage moves (a four-bar's rocker, no
drive of its own: :mod:`graphkin.cams.linkage`) turns with its link's angle
``θ<link>`` as the page's posture solves it: the page's construction, written
out once more with only ``θ<link>`` requested (``gkCamLinkFns``: the steps up
to that link, none of the cam's), is run on the page's numbers first; the cam
is then evaluated at that angle and the posture run as for any turning cam.
``K<f>``'s images by its link's complex ratio (``similar`` from two other pins of
a rocker, Sec. 3.5) are rewritten with ``K<f>``.  A link whose angle the
construction does not give from two solved points is held, said so.

Not turned (the page is held at the file's angle, :mod:`graphkin.render.live_cams`,
and says why): a construction whose other numbers change with the angle
(checked here by building the page at other angles; the branches the page
keeps itself are not counted) is held.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 4.7 (the equivalent linkage),
Secs. 6.3-6.10 (the program, the pitch curve's curvature, Eq. 6.37; undercutting).
"""

from __future__ import annotations

import copy
import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from graphkin.cams.analytic import profile
from graphkin.cams.turning import NotTurned, turn_steps
from graphkin.construction.codegen import Unsupported
from graphkin.construction.jsgen import generate_js
from graphkin.construction.step import Step
from graphkin.errors import GraphkinError
from graphkin.mechanisms.model import Mechanism

__all__ = ["TURN_JS", "CAMS_APP_JS", "check_turn", "turn_cams", "turn_handle"]

#: The operations that lay off a rolling contact's angle from its phase at the file's drive.
_PHASED = ("roll_angle", "roll_circle_angle", "planetary_arm")

#: Points of the cam's outline drawn on the page.
OUTLINE = 120

TURN_JS = r"""// the cams turned to the drive's angle x (render/live_cam_turn.py): each cam
// evaluated by its operations (cam_program, cam_center), its linkage's numbers in Kc
// the angle x of each cam's link is its drive's input in J (the first drive's, or another's;
// a number J: every cam's link at that angle)
// a cam on a link the linkage moves (c.via): its link's angle θ as the posture's construction
// solves it, up to that link only (gkCamLinkFns, the page's numbers at c.via.slots)
function gkTurnVia(c, J, Kc) {
  const v = gkCamLinkFns[c.via.fn](J, c.via.slots.map((k) => Kc[k]));
  const x = v === null ? null : v[c.via.theta];
  return Number.isFinite(x) ? x : null;
}
function gkTurn(T, J, Kc) {
  const got = [], xs = [];
  for (const [i, c] of T.cams.entries()) {
    // (a link an earlier cam's follower moves: read after that cam's numbers are set)
    xs.push(typeof J === "number" ? J : c.via ? gkTurnVia(c, J, Kc) : J[c.input]);
    // the linkage cannot place a cam's link here: no posture (said as any unassembled one)
    if (xs[i] === null) return {why: "", none: true, cams: got, xs: xs};
    const x = xs[i], I = {}; I[c.input] = x;
    const v = gkCamFns[c.fn](I, c.K);
    if (v === null) return {why: gkTurnStraight(c, x), cams: got, xs: xs};
    Kc[c.kx] = v[c.center][0]; Kc[c.ky] = v[c.center][1];
    // the images of K on its link by the link's complex ratio (K − A)/(B − A) (Sec. 3.5)
    for (const [i, j, ax, ay, bx, by, cx, cy] of c.ksim) {
      const r0 = bx - ax, r1 = by - ay, p0 = cx + Kc[c.kx] - ax, p1 = cy + Kc[c.ky] - ay;
      const dd = r0 * r0 + r1 * r1;
      Kc[i] = (p0 * r0 + p1 * r1) / dd; Kc[j] = (p1 * r0 - p0 * r1) / dd;
    }
    for (const k of c.r) Kc[k] = v[c.length];
    if (c.ysign) {      // a flat face: its slot's line at y in the follower's coordinates
      // (its coordinate c.axis: 1 an oscillating face's, 0 a translating face's)
      const y = v[c.length];
      if (c.axis === 1 && !(y * c.ysign > 1e-9 * c.reach)) {
        return {why: gkTurnFace(c, x), cams: got, xs: xs};
      }
      for (const [k, a, b] of c.y) Kc[k] = a * y + b;
      for (const k of c.d) Kc[k] = Math.abs(y);
      for (const [i, j, ax, ay, bx, by, px] of c.sim) {
        const q0 = c.axis === 0 ? y : px, q1 = c.axis === 0 ? px : y;
        const r0 = bx - ax, r1 = by - ay, p0 = q0 - ax, p1 = q1 - ay, dd = r0 * r0 + r1 * r1;
        Kc[i] = (p0 * r0 + p1 * r1) / dd; Kc[j] = (p1 * r0 - p0 * r1) / dd;
      }
    }
    got.push(v);
  }
  return {why: "", cams: got, xs: xs};
}
// Θ (degrees, 0 to 360) of cam c at the drive's angle x
function gkTurnTheta(c, x) {
  const t = c.s * (x - c.shift), tp = 2 * Math.PI;
  return (t - tp * Math.floor(t / tp)) * 180 / Math.PI;
}
function gkTurnNum(v) { return Number(v.toPrecision(5)).toString(); }
// the lift: a length, or an oscillating follower's swing (radians, shown in degrees)
function gkTurnLift(c, v) {
  return c.swing ? gkTurnNum(v[c.lift] * 180 / Math.PI) + "\u00b0" :
    gkTurnNum(v[c.lift]) + " " + c.unit;
}
function gkTurnFace(c, x) {
  return c.key + ": at \u0398 = " + gkTurnNum(gkTurnTheta(c, x)) + "\u00b0 the face's slot " +
    "would pass through the follower's pivot or beyond it (the profile's radius of curvature " +
    "is the face's offset, or less: a cusp, Sec. 6.9): the page's linkage is not the cam's " +
    "there: drag on.";
}
function gkTurnStraight(c, x) {
  return c.key + ": at \u0398 = " + gkTurnNum(gkTurnTheta(c, x)) + "\u00b0 the pitch curve is " +
    "straight at the contact (its radius of curvature is infinite, Eq. 6.37): no center of " +
    "curvature, no equivalent linkage (Sec. 4.7), and graphkin solve refuses that angle: drag on.";
}
// the posture at the inputs J: the cams' linkages, then the construction; the roller's
// center on the side where the cam's program puts it (the branch solve's hint picks)
function gkTurnSolve(T, J, Kc, fn) {
  const t = gkTurn(T, J, Kc);
  if (t.why || t.none) return {r: null, t: t};
  let r = fn(J, Kc);
  T.cams.forEach((c, i) => {
    if (c.branch === null) return;
    // the right branch puts T where the program does, to round-off; the other 2h away, or
    // nowhere when the rest of the mechanism cannot be assembled from it
    const want = t.cams[i][c.trace];
    const near = (q) => q && q[c.point] &&
      Math.hypot(q[c.point][0] - want[0], q[c.point][1] - want[1]) <= 1e-6 * c.reach;
    if (near(r)) return;
    Kc[c.branch] = -Kc[c.branch];
    const other = fn(J, Kc);
    if (near(other)) { r = other; return; }
    Kc[c.branch] = -Kc[c.branch];
    r = null;
  });
  if (r) T.cams.forEach((c, i) => { r[c.contact] = t.cams[i][c.contact]; });
  return {r: r, t: t};
}
// why the page draws no instant centers where a cam dwells ("" elsewhere): its center of
// curvature is the cam's center (cam_center puts it there), the follower and the coupler K-T
// stand still, and a center of links at rest relative to each other is anywhere
function gkTurnDwell(T, t) {
  if (!t || t.why || t.none) return "";
  for (let i = 0; i < T.cams.length; i++) {
    const k = t.cams[i][T.cams[i].center];
    if (k[0] === 0 && k[1] === 0) {
      return "No instant centers at this posture: " + T.cams[i].key + " dwells here (its " +
        "pitch curve is a circle about the cam's center), so the follower and the coupler " +
        T.cams[i].center + "-" + T.cams[i].point + " stand still, and the center of two " +
        "links at rest relative to each other is anywhere (Sec. 3.13).";
    }
  }
  return "";
}
// one line per posture: each cam's angle, lift and pitch curve's curvature, and an undercut
function gkTurnNote(T, t, x) {
  if (!t || t.why || t.none) return t ? t.why : "";
  return T.cams.map((c, i) => {
    const v = t.cams[i], rho = v[c.rho], th = gkTurnTheta(c, t.xs ? t.xs[i] : x);
    const tol = 1e-9 * c.size;
    if (c.ysign) {      // a flat face: the profile's own radius (Sec. 6.9), positive or a cusp
      return c.key + ": \u0398 = " + gkTurnNum(th) + "\u00b0, Y = " + gkTurnLift(c, v) +
        ", profile \u03c1 = " + gkTurnNum(rho) + " " + c.unit +
        (rho > tol ? " (convex)." : " (not positive: the profile has a cusp here, Sec. 6.9; " +
         "the values are the program's, as graphkin solve gives them).");
    }
    let s = c.key + ": \u0398 = " + gkTurnNum(th) + "\u00b0, Y = " + gkTurnLift(c, v) +
      ", pitch curve \u03c1 = " + gkTurnNum(rho) + " " + c.unit +
      (rho > tol ? " (convex)" : " (concave: K on the follower's side)");
    if (c.roller > 0 && rho > tol && rho < c.roller - tol) {
      s += "; the roller (" + gkTurnNum(c.roller) + " " + c.unit + ") is larger than " +
        "the pitch curve's radius here: the profile is undercut (Sec. 6.10) and the follower " +
        "leaves it; the values are the program's, as graphkin solve gives them";
    }
    return s + ".";
  }).join(" ");
}
"""

CAMS_APP_JS = r"""// the cams' outlines turned to the drive's angle, the roller and the contact
// (render/live_cam_turn.py)
function camOutlines(r) {
  if (!D.turn) return [];
  // the posture's own angle of each cam's link (a dimmed, earlier posture keeps its own)
  return D.turn.cams.map((c) => {
    const a = r["\u03b8" + c.link], th = Number.isFinite(a) ? a : drive;
    const c0 = Math.cos(th), s0 = Math.sin(th);
    const o = r[c.at];
    return o ? c.outline.map((q) => [o[0] + c0 * q[0] - s0 * q[1], o[1] + s0 * q[0] + c0 * q[1]])
      : [];
  });
}
function drawCams(g, r) {
  if (!D.turn) return;
  const outlines = camOutlines(r);
  D.turn.cams.forEach((c, i) => {
    const pts = outlines[i];
    if (!pts.length) return;
    el(g, "polygon", {points: pts.map((p) => X("posture", p).toFixed(1) + "," +
                                          Y("posture", p).toFixed(1)).join(" "),
                      fill: "#eceff1", stroke: ink("link", "color"), "stroke-width": "1",
                      class: "gk-cam"});
    const t = r[c.point];
    if (t && c.roller > 0) {
      const v = views.posture;
      el(g, "circle", {cx: X("posture", t), cy: Y("posture", t), r: c.roller * c.scale * v.s,
                       fill: "none", stroke: ink("link", "color"), "stroke-width": "1",
                       class: "gk-roller"});
    }
  });
}
"""


def turn_handle(data: dict[str, Any]) -> None:
    """The drive's handle of a turning page: the contact point of a cam it turns (in place).

    Dragged, the cam turns by the angle the pointer turns about the cam's center.
    """
    turn = data.get("turn")
    if turn is None:
        return
    c = next((c for c in turn["cams"] if c["input"] == turn["label"]), None)
    if c is not None:       # (a cam on another drive's link: the first drive keeps its pin)
        data["drive"].update(pivot=c["at"], tip=c["contact"], phi=0.0, relative=True)


def _fail(why: str) -> NotTurned:
    return NotTurned(why)


def _slots(steps: Sequence[Step], names: list[str], fl: str) -> tuple[int, int, list[int]]:
    """Where ``K<f>``'s coordinates on the cam and ``|ρ|`` sit in the construction's ``K``."""
    k = f"K{fl}"
    if f"{k}.0" not in names or f"{k}.1" not in names:
        raise _fail(f"the construction does not lay off {k} on the cam by its coordinates")
    radius = [names.index(f"{s.outputs[0]}.0") for s in steps
              if s.op == "circle" and s.inputs == (k,) and f"{s.outputs[0]}.0" in names]
    if not radius:
        raise _fail(f"the construction draws no arc about {k}")
    return names.index(f"{k}.0"), names.index(f"{k}.1"), radius


def _face_slots(steps: Sequence[Step], names: list[str],
                fl: str) -> tuple[int, int, dict[str, Any]]:
    """Where a flat face's linkage sits in ``K``: ``K<f>``, the slot's offset ``y``.

    The slot's line ``F<f>a``-``F<f>b`` lies at ``y`` in the follower's own
    coordinates (:func:`graphkin.cams.equivalent.equivalent_linkage`): its
    points' second coordinates (``rigid`` from the pivot), the tangent's
    offset ``|y|`` from the pivot (``tangent_foot``, Sec. 2.8 case 4) and the
    complex ratios of their velocity and acceleration images (``similar``)
    all move with ``y``; the branch is the tangent's side.
    """
    k = f"K{fl}"
    if f"{k}.0" not in names or f"{k}.1" not in names:
        raise _fail(f"the construction does not lay off {k} on the cam by its coordinates")
    feet = [s for s in steps if s.op == "tangent_foot" and s.inputs[1:] == (k,)]
    if len(feet) != 1 or f"{feet[0].outputs[0]}.0" not in names:
        raise _fail(f"the construction does not draw the face's slot through {k} as a tangent "
                    "from the follower's pivot")
    foot = feet[0]
    y0 = None
    ys: list[list[float]] = []
    locs = set()
    for s in steps:
        if s.op == "rigid" and s.outputs[0] in (f"F{fl}a", f"F{fl}b"):
            lp, lq = s.params["local_p"], s.params["local_q"]
            y0 = float(lq[1])
            locs.add(tuple(map(float, lq)))
            if f"{s.outputs[0]}.1" in names:
                ys.append([names.index(f"{s.outputs[0]}.1"), 1.0, -float(lp[1])])
    if y0 is None or len(locs) != 2:
        raise _fail(f"the construction does not place the face's slot F{fl}a-F{fl}b")
    for s in steps:       # the slot's own copies of its line's points
        if s.op == "rigid" and s.outputs[0] not in (f"F{fl}a", f"F{fl}b") and \
                tuple(map(float, s.params["local_q"])) in locs and f"{s.outputs[0]}.1" in names:
            ys.append([names.index(f"{s.outputs[0]}.1"), 1.0, -float(s.params["local_p"][1])])
    sims = []
    for s in steps:       # the images of the slot's points: q = (P − A)/(B − A) moves with y
        lab = f"{s.outputs[0]}.0"
        if s.op == "similar" and lab in names and \
                tuple(map(float, s.params["local_p"])) in locs:
            (ax, ay), (bx, by) = s.params["local_a"], s.params["local_b"]
            sims.append([names.index(lab), names.index(f"{s.outputs[0]}.1"), float(ax),
                         float(ay), float(bx), float(by), float(s.params["local_p"][0])])
    d = [names.index(f"{foot.outputs[0]}.0")]
    d += [names.index(f"{s.outputs[0]}.0") for s in steps
          if s.op == "circle" and s.inputs == foot.inputs[:1] and
          f"{s.outputs[0]}.0" in names and s.outputs[0].endswith(":offset")]
    branch = f"{foot.outputs[0]}.branch"
    return names.index(f"{k}.0"), names.index(f"{k}.1"), {
        "y": ys, "d": d, "sim": sims, "ysign": math.copysign(1.0, y0), "axis": 1,
        "branch": names.index(branch) if branch in names else None}


def _translating_face_slots(steps: Sequence[Step], names: list[str],
                            fl: str) -> tuple[int, int, dict[str, Any]]:
    """Where a translating flat face's linkage sits in ``K``: ``K<f>``, the slot's offset.

    The slot ``F<f>a``-``F<f>b`` lies at ``x = −ρ`` in the follower's own
    coordinates (x along its guide, :func:`graphkin.cams.equivalent.equivalent_linkage`):
    the first coordinates of its points (``rigid`` from the follower's point,
    or to it from ``K<f>`` in the two-slides group, Sec. 2.8 case 3) and the
    complex ratios of their images (``similar``) move with it; no branch.
    """
    k = f"K{fl}"
    if f"{k}.0" not in names or f"{k}.1" not in names:
        raise _fail(f"the construction does not lay off {k} on the cam by its coordinates")
    locs = {tuple(map(float, s.params["local_q"])) for s in steps
            if s.op == "rigid" and s.outputs[0] in (f"F{fl}a", f"F{fl}b")}
    if len(locs) != 2:
        raise _fail(f"the construction does not place the face's slot F{fl}a-F{fl}b")
    ys: list[list[float]] = []
    sims = []
    for s in steps:
        lab = f"{s.outputs[0]}.0"
        if lab not in names or s.op not in ("rigid", "similar"):
            continue
        lq = tuple(map(float, s.params.get("local_q", ())))
        lp = tuple(map(float, s.params["local_p"]))
        if s.op == "rigid" and lq in locs:          # Q − P = (y − p0, …)
            ys.append([names.index(lab), 1.0, -lp[0]])
        elif s.op == "rigid" and lp in locs:        # Q − P = (q0 − y, …)
            ys.append([names.index(lab), -1.0, lq[0]])
        elif s.op == "similar" and lp in locs:
            (ax, ay), (bx, by) = s.params["local_a"], s.params["local_b"]
            sims.append([names.index(lab), names.index(f"{s.outputs[0]}.1"), float(ax),
                         float(ay), float(bx), float(by), lp[1]])
    return names.index(f"{k}.0"), names.index(f"{k}.1"), {
        "y": ys, "d": [], "sim": sims, "ysign": -1.0, "axis": 0, "branch": None}


def turn_cams(data: dict[str, Any], mech: Mechanism, file_data: Mapping[str, Any], source: str,
              steps: Sequence[Step], names: list[str], label: str) -> str:
    """The page's turning cams (``data["turn"]``) and their JavaScript; "" when held.

    Where the cams cannot turn, sets ``data["turnWhy"]`` (why, in the user's
    words) and returns "".

    Parameters
    ----------
    data : dict
        The page's data (its ``K`` is the construction's numbers).
    mech : Mechanism
    file_data : mapping
        The file as written (a copy at another angle checks the slots).
    source : str
    steps : sequence of Step
        The page's construction.
    names : list of str
        The names of its numbers (``JSFunction.slots``).
    label : str
        The drive's input (``θ2``).
    """
    if not mech.cams:
        return ""
    try:
        cams, js = _cams(mech, steps, names, data["K"], label)
    except NotTurned as exc:
        data["turnWhy"] = str(exc)
        return ""
    # a rolling contact's phase at the file's drive (its "as drawn" constant) is the page's
    # own, as its branches are: a page built at another drive angle lays it off afresh there
    rolled = {o for s in steps if s.op in _PHASED for o in s.outputs}
    phases = [k for k, n in enumerate(names) if n.rsplit(".", 1)[0] in rolled]
    data["turn"] = {"label": label, "cams": cams, "phases": phases}
    names_js = ", ".join(f"gkCam{i}" for i in range(len(cams)))
    # (by the cam's place: null for a cam its own drive turns)
    links_js = ", ".join("null" if c["via"] is None else f"gkCamLink{c['via']['fn']}"
                         for c in cams)
    return (js + f"const gkCamFns = [{names_js}];\nconst gkCamLinkFns = [{links_js}];\n"
            + TURN_JS)


def _cams(mech: Mechanism, steps: Sequence[Step], names: list[str], page_k: Sequence[float],
          label: str) -> tuple[list[dict[str, Any]], str]:
    d0 = mech.drives[0]
    out: list[dict[str, Any]] = []
    js = ""
    for i, j in enumerate(mech.cams):
        # the cam turns with its link's angle in the posture: its drive's input (the first
        # drive's, dragged; or another drive's, moved by its law or held at its value)
        dj = next((d for d in mech.drives if d.link == j.link and d.kind == "angle"), None)
        via = None
        if dj is None:      # a link the linkage moves: its angle as the posture solves it
            cam_input = f"θ{j.link}"
            via = _via(steps, names, page_k, cam_input, i)
            js += via.pop("source")
        else:
            cam_input = label if dj is d0 else dj.label
        ts = turn_steps(j, cam_input)
        fl = j.follower
        flat = j.cam.follower.kind.flat
        if j.cam.follower.kind.flat and not j.cam.follower.kind.oscillating:
            kx, ky, face = _translating_face_slots(steps, names, fl)
            radius: list[int] = []
        elif flat:
            kx, ky, face = _face_slots(steps, names, fl)
            radius = []
        else:
            kx, ky, radius = _slots(steps, names, fl)
            face = {"y": [], "d": [], "sim": [], "branch": None, "ysign": 0.0, "axis": 1}
        req = [ts.theta, ts.lift, ts.center, ts.length, ts.trace, ts.contact, ts.rho]
        try:
            fn = generate_js(ts.steps, requests=req, name=f"gkCam{i}")
        except Unsupported as exc:
            raise _fail(f"{j.key}: {exc}") from None
        js += fn.source
        cam = j.cam
        f = cam.follower
        size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
        th = np.linspace(0.0, 2 * np.pi, OUTLINE, endpoint=False)
        u = profile(cam, th).contact * j.scale
        u = u[np.isfinite(u)]
        center = next((n for n, xy in mech.links["1"].points.items()
                       if tuple(map(float, xy)) == tuple(map(float, j.center))
                       and n in mech.links[j.link].points), None)
        if center is None:
            raise _fail(f"{j.key}: the cam's center is not a pin of the frame")
        out.append({
            "fn": i, "key": j.key, "K": fn.values, "kx": kx, "ky": ky, "r": radius,
            "input": cam_input, "link": j.link, "via": via, "ksim": _k_images(mech, j, steps,
                                                                              names),
            "branch": face["branch"] if flat else (
                names.index(f"T{fl}.branch") if f"T{fl}.branch" in names else None),
            "y": face["y"], "d": face["d"], "sim": face["sim"], "ysign": face["ysign"],
            "axis": face["axis"],
            "point": f"F{fl}a" if flat else f"T{fl}", "trace": ts.trace,
            "contact": ts.contact, "center": ts.center,
            "length": ts.length, "lift": ts.lift, "rho": ts.rho, "at": center,
            "s": float(cam.s), "shift": float(j.axis - math.pi / 2),
            "roller": float(f.roller) if f.kind.roller else 0.0, "scale": float(j.scale),
            "size": float(size), "reach": float(size * j.scale), "unit": cam.unit,
            "swing": bool(f.kind.oscillating),
            "outline": [[round(float(z.real), 6), round(float(z.imag), 6)] for z in u]})
    return out, js


def _k_images(mech: Mechanism, j: Any, steps: Sequence[Step],
              names: list[str]) -> list[list[float]]:
    """Where the images of ``K<f>`` by its link's complex ratio sit in ``K`` (Sec. 3.5).

    A cam link with two pins besides ``K<f>`` (a four-bar's rocker) gives
    ``K<f>``'s velocity and acceleration images from two of them
    (``similar``): their ratio ``(K − A)/(B − A)`` moves with ``K<f>``.  Rows
    ``[i, j, a, b, center]``: the slots, the link's points A and B and the
    cam's center in the link's own coordinates.
    """
    pts = mech.links[j.link].points
    k = pts.get(f"K{j.follower}")
    center = next((xy for n, xy in pts.items() if n in mech.links["1"].points and
                   tuple(map(float, mech.links["1"].points[n])) == tuple(map(float, j.center))),
                  None)
    if k is None or center is None:
        return []
    rows = []
    for s in steps:
        lab = f"{s.outputs[0]}.0"
        if s.op == "similar" and lab in names and \
                tuple(map(float, s.params["local_p"])) == tuple(map(float, k)):
            (ax, ay), (bx, by) = s.params["local_a"], s.params["local_b"]
            rows.append([names.index(lab), names.index(f"{s.outputs[0]}.1"), float(ax),
                         float(ay), float(bx), float(by), float(center[0]), float(center[1])])
    return rows


def _via(steps: Sequence[Step], names: list[str], page_k: Sequence[float], theta: str,
         i: int) -> dict[str, Any]:
    """How the page finds the angle ``θ<link>`` of a cam's link the linkage moves.

    The posture's construction up to that link only (the steps the link's
    angle needs: none of the cam's), written out as JavaScript; its numbers are
    the page's at the slots found here by name, so a dragged pivot or a switched
    branch moves it as it moves the page.  The cam's angle is then that link's
    (:mod:`graphkin.cams.linkage`), as ``graphkin solve`` reads it.

    Raises
    ------
    NotTurned
        The construction gives that link no angle from its solved points.
    """
    if not any(theta in s.outputs for s in steps):
        raise _fail(f"the posture's construction gives the cam's link no angle {theta} from "
                    "two of its solved points")
    # only the steps θ<link> reads (the writer keeps every step that can fail, and the
    # follower's steps fail where the cam's numbers are not yet this posture's)
    live = {theta}
    mine = []
    for s in reversed(steps):
        if not live.isdisjoint(s.outputs):
            mine.append(s)
            live.update(s.inputs)
    try:
        fn = generate_js(mine[::-1], requests=[theta], name=f"gkCamLink{i}")
    except Unsupported as exc:
        raise _fail(str(exc)) from None
    slots = []
    where = {n: k for k, n in enumerate(names)}
    for n, v in fn.slots:
        # the page's number of that name: the same step's, recorded once
        if n not in where or page_k[where[n]] != v:
            raise _fail(f"the construction of {theta} reads a number the page has not ({n})")
        slots.append(where[n])
    return {"fn": i, "slots": slots, "theta": theta, "source": fn.source}


def check_turn(data: dict[str, Any], mech: Mechanism, file_data: Mapping[str, Any],
               source: str) -> None:
    """The whole page at another cam angle differs only where the cams' numbers say (in place).

    The page is built again, held (``turn=False``), from the file with the
    drive turned 11°, −13°, 37° and 101° (where the cam has an equivalent
    linkage).  Every number of the construction's ``K`` but
    the cams' and the branches the page keeps itself (``data["branches"]``: picked
    there from the file's assembly hints, which the follower's travel may bring
    nearer the other branch) must be the same and the force construction too, else the page
    is held at the file's angle (``data["turn"]`` removed, said in the
    drive's line).  An instant centers' route or a curvature construction
    found at the file's angle that is another one there (the file's angle in a
    dwell, where the coupler's pin is the cam's center: Kennedy's route then
    takes them as one) is not drawn while the cam turns, said in its panel.
    """
    turn = data.get("turn")
    if turn is None:
        return
    try:
        others = _elsewhere(mech, file_data, source)
        mine = {k for c in turn["cams"] for k in (c["kx"], c["ky"], *c["r"], *c["d"])}
        mine |= {row[0] for c in turn["cams"] for row in c["y"]}
        mine |= {k for c in turn["cams"] for row in c["sim"] + c["ksim"] for k in row[:2]}
        mine |= {c["branch"] for c in turn["cams"] if c["branch"] is not None}
        # a branch of the rest of the mechanism is the page's own: kept while the cam turns,
        # switchable, and saved as the point's assembly hint; the page built at another angle
        # picks it afresh from the file's fixed hint, which a point moved far enough (the
        # follower's lift) lies nearer the other branch of: not a change of construction
        mine |= set(data.get("branches", {}).values())
        mine |= set(turn.get("phases", ()))
        for other in others:
            k1, k2 = data["K"], other["K"]
            if len(k1) != len(k2):
                raise _fail("the page's construction changes its steps with the cam angle")
            for k, (a, b) in enumerate(zip(k1, k2)):
                if k not in mine and abs(a - b) > 1e-12 * (1.0 + abs(a)):
                    raise _fail("the page's construction changes other numbers than the "
                                "cam's with the cam angle")
            if _json(data.get("forces")) != _json(other.get("forces")):
                raise _fail("the force construction changes with the cam angle")
    except NotTurned as exc:
        from graphkin.render.live_cams import cam_hold

        del data["turn"]
        hold = cam_hold(mech, source)
        assert hold is not None
        data["cam"]["why"] = f"{hold['why']} (not turned on the page: {exc})"
        for key in ("pivot", "tip", "phi", "relative"):
            data["drive"].pop(key, None)
        return
    # the cam's own angle Θ at the file's posture (its link's angle; the crank's when on it)
    deg = f"Θ = {math.degrees(mech.cams[0].theta):g}°"
    # (an angle where the rest of the mechanism cannot be assembled has no centers to compare)
    if any(_route(data.get("centers")) != _route(other.get("centers")) for other in others
           if (other.get("centers") or {}).get("fn")):
        data["centers"] = dict(data["centers"], fn=None, why=(
            f"the Kennedy route found at the file's cam angle ({deg}) is another one at other "
            "angles (Kennedy's lines are chosen where they meet best at that posture, and "
            "two centers coincide in a dwell); change the file's angle"))
    cvs = [dict(d.get("curvature") or {}) for d in (data, *others)]
    for cv in cvs:
        # (the numbers, and the mechanism's size the link's ω = 0 verdict measures by: the
        # cam's equivalent linkage is another size at another angle)
        cv.pop("K", None)
        cv.pop("scale", None)
    if any(_json(cv) != _json(cvs[0]) for cv in cvs[1:]):
        data["curvature"] = {"why": f"the curvature construction found at the file's cam angle "
                                    f"({deg}) is another one at other angles; change the "
                                    "file's angle"}


def _route(centers: Any) -> str:
    """The centers' route without the numbers the cam's angle changes, as JSON.

    The route (:func:`~graphkin.kinematics.instant_centers.route.every_posture_route`)
    chooses its lines at each posture, so it is the same at every cam angle but for
    numbers that only measure: the mechanism's size (``far``, and in ``K`` the
    scale of each center's measure of conditioning) and where a flat face's slot
    points lie along the slot (``d``), whose common normal through the pin takes
    only the slot's direction (Sec. 3.14).
    """
    if not isinstance(centers, dict):
        return _json(centers)
    c = {k: v for k, v in centers.items() if k not in ("K", "far")}
    c["given"] = {lab: {k: v for k, v in g.items() if k != "d"}
                  for lab, g in (c.get("given") or {}).items()}
    return _json(c)


def _json(v: Any) -> str:
    import json

    return json.dumps(v, sort_keys=True, default=str)


def _elsewhere(mech: Mechanism, file_data: Mapping[str, Any],
               source: str) -> list[dict[str, Any]]:
    """The held page's data with the drive turned 11°, −13°, 37° and 101° (where it has one).

    Several angles: an angle in the same dwell as the file's would have the
    same (degenerate) routes.  NotTurned where none has an equivalent linkage.
    """
    from graphkin.mechanisms import from_dict
    from graphkin.render.live import live_data

    d0 = mech.drives[0]
    out = []
    for step in (11.0, -13.0, 37.0, 101.0):
        other = copy.deepcopy(dict(file_data))
        raw = other.get("drive")
        drives = raw if isinstance(raw, list) else [raw]
        entry = drives[int(d0.key[6:-1]) if d0.key.startswith("drive[") else 0]
        assert isinstance(entry, dict)
        entry["angle"] = math.degrees(d0.value) + step
        try:   # the cam file's path is relative to the file read (mech.source)
            m2 = from_dict(other, mech.source or source)
            d2, _ = live_data(m2, other, source, turn=False)
        except GraphkinError:
            continue
        out.append(d2)
    if not out:
        raise _fail("the cam has no equivalent linkage near the file's angle to check the "
                    "page by")
    return out
