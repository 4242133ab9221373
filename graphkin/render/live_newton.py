"""The live page of a mechanism only Newton's method solves (``graphkin live``).

A mechanism the construction cannot solve one group at a time (two sliders
that close one loop, a cam's equivalent linkage, a rolling contact whose
roller turns with its travel) has no recorded construction to write out.
Its page solves instead the analytic solver's loop-closure equations
(Sec. 2.7): the rows are written out as JavaScript from the one table both
writers read (:mod:`graphkin.kinematics.analytic.jsrows`), and the script
below runs Newton's method on them from the previous posture on every
pointer move, the drive (and a dragged pivot) moved in steps of at most
2° (or 2 % of the mechanism's size) so that the branch stays the one drawn;
the velocities and accelerations are then one linear solve each (Secs.
3.9 and 4.9).  A posture where Newton's method does not converge, jumps to
another branch or finds a rank-deficient Jacobian is shown as one that
cannot be assembled (``null``), never as NaN.

The script defines the ``construction(I, K)`` the page calls (the same
signature as a written-out construction), plus ``mark``/``restore`` (the
cycle's coupler curves start from the current posture and leave it as it
was), ``reset`` and ``edit`` (the saved file places each rolling contact's
link at its angle of the posture shown, and gives every moving point as an
assembly hint, so that ``graphkin solve`` of the saved file finds this
posture).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.7 (loop-closure equations), Sec. 2.19 (the rolling constraint),
Secs. 3.9 and 4.9 (algebraic velocity and acceleration analysis).
"""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np

from graphkin.errors import GraphkinError, InputError
from graphkin.mechanisms.model import FRAME, Mechanism

__all__ = ["NEWTON_JS", "ROLL_EDIT_JS", "newton_data", "roll_edit_js"]

#: Largest drive step of the march between two postures (rad, and fraction of the size).
MARCH_ANGLE = math.radians(2.0)

MARCH_LENGTH = 0.02

#: A step of the march that moves a link's origin by more than this fraction of the size has
#: jumped to another branch (a 2° step moves a link by far less).
JUMP = 0.5


def _json(value: Any) -> str:
    return (json.dumps(value, ensure_ascii=False, allow_nan=False)
            .replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")
            .replace("\u2028", "\\u2028").replace("\u2029", "\\u2029"))


def newton_data(mech: Mechanism, source: str) -> tuple[dict[str, Any], str]:
    """What the page needs to solve ``mech`` by Newton's method: its data and JavaScript.

    Returns
    -------
    data : dict
        Merged into the page's data: ``K`` (the frame pivots' coordinates and
        the rolling constants), the drive, the links' points, ``rates``,
        ``newton`` (the posture the page starts from and the solver's
        numbers), ``refused`` (panel -> why it is not drawn) and ``curvature``
        (where the polygons are constructed at Newton's posture, the curvature
        panel of :func:`graphkin.render.live_curvature.curvature_data`, re-done
        from the page's posture and polygons; else why not, in one line).
    js : str
        The rows and the solver (``construction(I, K)``).

    Raises
    ------
    InputError
        The file's posture cannot be solved (the message of the solver).
    """
    from graphkin.kinematics.analytic.jsrows import JS_RUNTIME, write_rows
    from graphkin.kinematics.analytic.newton import _Search
    from graphkin.kinematics.analytic.phase import rolling_phases
    from graphkin.kinematics.analytic.rates import _singular_threshold
    from graphkin.kinematics.analytic.rolling import _RollingCircle
    from graphkin.kinematics.analytic.system import _System
    from graphkin.render.live_newton_polygons import POLYGONS_JS, newton_polygons
    from graphkin.tolerance import DEFAULT_TOL

    eqs0 = _System(mech, DEFAULT_TOL)
    values = np.array([d.value for d in mech.drives], dtype=float)
    try:
        q0 = _Search(eqs0).solve(values)
    except GraphkinError as exc:
        raise InputError(f"no live page: {exc}", file=source) from None
    eqs = eqs0.integrated(q0)
    eqs.follow(q0)
    frame = mech.links[FRAME].points
    rows = write_rows(eqs, "js", dict(frame))
    anchors = [float(c.anchor) for c in eqs.cons
               if isinstance(c, _RollingCircle) and c.anchor is not None]
    # every point of every link, from its link's state (the frame's from K when dragged)
    slot_of = {n: k for k, (n, _) in enumerate(rows.slots)}
    points: list[list[Any]] = []
    seen: set[str] = set()
    for lid, lk in mech.links.items():
        k = eqs.index[lid]
        for n, (x, y) in lk.points.items():
            if n in seen:
                continue
            seen.add(n)
            fs = [slot_of[f"{n}.0"], slot_of[f"{n}.1"]] if f"{n}.0" in slot_of else None
            points.append([n, k, float(x), float(y), fs])
    # the paths' points (a slider's or slot's line, a circle's center), which the instant
    # centers' construction reads from the posture (Sec. 3.13)
    for lab, lid, (x, y) in _path_points(mech):
        points.append([lab, eqs.index[lid], float(x), float(y), None])
    drives = [{"label": d.label, "angle": d.kind in ("angle", "relative")}
              for d in mech.drives]
    phases = [{"rolling": int(p.key[len("rolling["):-1]), "link": p.link}
              for p in (rolling_phases(mech) if mech.rolling else ()) if p.kind == "angle"]
    rated = eqs.rate_values is not None
    row_scale = [float(v) for v in eqs.row_scale]
    rate_scale = [1.0 if g.kinds[0] == "A" else 1.0 / eqs.size
                  for g in eqs.rate_functions or []]
    gkn = {
        "m": rows.m, "n": rows.n, "ncons": rows.ncons, "ndrives": rows.ndrives,
        "rateRows": rows.rate_rows, "rowScale": row_scale + rate_scale,
        "colScale": [float(v) for v in eqs.col_scale], "q0": [float(v) for v in q0],
        "A0": anchors, "values": [float(v) for v in values], "drives": drives,
        "rates": [[float(v), float(a)] for v, a in (eqs.rate_values or [])] if rated else None,
        "points": points, "links": {lid: eqs.index[lid] for lid in mech.links},
        "size": float(eqs.size), "march": [MARCH_ANGLE, MARCH_LENGTH], "jump": JUMP,
        "singular": _singular_threshold(DEFAULT_TOL), "phases": phases,
    }
    why = _refused(mech)
    extra = ""
    got = newton_polygons(mech) if rated else None
    pitch: list[dict[str, str]] = []
    if got is not None:  # constructed at Newton's posture: drawn, not refused
        poly, extra = got
        pitch = poly.pop("pitch")
        gkn["polygons"] = {**poly, "why": POLYGONS_WHY}
        why.pop("velocity", None)
        why.pop("acceleration", None)
    js = (JS_RUNTIME + rows.source + extra + POLYGONS_JS * bool(extra)
          + f"const GKN = {_json(gkn)};\n" + NEWTON_JS)
    hidden = set(frame)
    data: dict[str, Any] = {
        "K": [v for _, v in rows.slots],
        "links": {lid: list(lk.points) for lid, lk in mech.links.items()},
        "frame": {n: [slot_of[f"{n}.0"], slot_of[f"{n}.1"]] for n in frame
                  if f"{n}.0" in slot_of},
        "coupler": {},
        "branches": {},
        "rates": rated,
        "inputs": {dr["label"]: float(v) for dr, v in zip(drives[1:], values[1:])},
        "assembly": [n for lid, lk in mech.links.items() if lid != FRAME
                     for n in lk.points if n not in hidden],
        "newton": True,
        # the curvature panel says why, in one line, as on every other page without one
        "curvature": {"why": "the curvature constructions start from the velocity and "
                             "acceleration polygons, which this page does not redraw (Newton's "
                             "method solves the mechanism, not a construction)"},
    }
    if got is not None:
        # the polygons are constructed at Newton's posture: so is the curvature of the link
        # draw -d curvature draws, from the page's posture and polygons (Secs. 4.13-4.17)
        from graphkin.render.live_curvature import curvature_data

        names = list(dict.fromkeys(n for lk in mech.links.values() for n in lk.points))
        made = {*names, "o_v", "o_a"} | {f"{p}({n})" for p in ("v", "a") for n in names} | {
            f"{w}{lid}" for w in ("θ", "ω", "α") for lid in mech.links}
        data["curvature"], cjs = curvature_data(mech, names, made)
        js += cjs
    if why:
        data["refused"] = why
    if pitch:
        data["pitch"] = pitch
    return data, js


#: The one line of a posture Newton's method finds whose polygons have no construction.
POLYGONS_WHY = ("This posture is found (Newton's method) but its velocity and acceleration "
                "polygons have no clean construction here (two of their lines are parallel: "
                "a toggle of the coupler and the wheel): drag back.")


def _path_points(mech: Mechanism) -> list[tuple[str, str, tuple[float, float]]]:
    """The points of the paths (label, the link that carries the path, local coordinates)."""
    out: list[tuple[str, str, tuple[float, float]]] = []
    paths: tuple[Any, ...] = (*mech.sliders, *mech.slots, *mech.rolling)
    for path in paths:
        p0, p1 = getattr(path, "p0", None), getattr(path, "p1", None)
        if p0 is not None and p1 is not None:
            out += [(f"{path.key}:L0", path.on, p0), (f"{path.key}:L1", path.on, p1)]
        c = getattr(path, "on_center", None) if hasattr(path, "on_center") else \
            getattr(path, "center", None)
        if isinstance(c, (tuple, list)):
            out.append((f"{path.key}:O", path.on, (float(c[0]), float(c[1]))))
    return out


def _refused(mech: Mechanism) -> dict[str, str]:
    """Panel -> the one line saying why the page does not draw it."""
    out: dict[str, str] = {}
    for d in ("velocity", "acceleration"):
        if not mech.has_rates:
            out[d] = (f"no {d} polygon: the file gives no rates (add omega to [drive] or a "
                      "[rates] table)")
        elif mech.rolling:
            out[d] = (f"no {d} polygon on the live page: a rolling contact's polygon is "
                      f"constructed at the file's posture only (graphkin draw -d {d}); here "
                      "Newton's method re-solves the posture and the rates (the table)")
        else:
            out[d] = (f"no {d} polygon: the mechanism was solved analytically (it cannot be "
                      "constructed one group at a time)")
    return out


ROLL_EDIT_JS = r"""
// the saved file: each rolling contact's link at its angle of the posture shown (degrees), so
// that graphkin solve places it there (the roller has rolled, not slipped back)
// (and, with ``hints``, every moving point as an assembly hint: a tangent's branch has none)
function gkRollEdit(phases, f, r, hints) {
  if (!r) return;
  for (const p of phases) {
    if (Array.isArray(f.rolling) && f.rolling[p.rolling]) {
      f.rolling[p.rolling].angle = r["\u03b8" + p.link] * 180 / Math.PI;
    }
  }
  if (hints && hints.length) {
    if (f.assembly === null || typeof f.assembly !== "object" || Array.isArray(f.assembly)) {
      f.assembly = {};
    }
    for (const n of hints) if (r[n]) f.assembly[n] = [r[n][0], r[n][1]];
  }
}
"""


def roll_edit_js(mech: Mechanism, made: set[str]) -> str:
    """For a construction page whose rollers turn with their travel (``roll_angle``).

    The saved file then gives each such contact's ``angle`` at the posture
    shown; empty when the mechanism has no rolling contact.
    """
    from graphkin.kinematics.analytic.phase import rolling_phases

    if not mech.rolling:
        return ""
    phases = [{"rolling": int(p.key[len("rolling["):-1]), "link": p.link}
              for p in rolling_phases(mech) if p.kind == "angle" and f"θ{p.link}" in made]
    frame = set(mech.links[FRAME].points)
    hints = [n for lid, lk in mech.links.items() if lid != FRAME for n in lk.points
             if n in made and n not in frame]
    return (ROLL_EDIT_JS + f"construction.edit = (f, r) => gkRollEdit({_json(phases)}, f, r, "
            f"{_json(list(dict.fromkeys(hints)))});\n" if phases else "")


NEWTON_JS = ROLL_EDIT_JS + r"""
// Newton's method on the rows above, from the posture before (render/live_newton.py)
// least squares by Householder QR: x minimising |A x - b|, and min |R_ii| / max |R_ii|
function gkLstsq(A0, b0) {
  const m = A0.length, n = A0[0].length, A = A0.map((r) => r.slice()), b = b0.slice();
  const d = new Array(n).fill(0);
  for (let j = 0; j < n; j++) {
    let s = 0;
    for (let i = j; i < m; i++) s += A[i][j] * A[i][j];
    const a = Math.sqrt(s);
    d[j] = A[j][j] > 0 ? -a : a;
    if (a === 0) continue;
    const v0 = A[j][j] - d[j];
    const vn = s - A[j][j] * A[j][j] + v0 * v0;
    A[j][j] = v0;
    for (let k = j + 1; k < n; k++) {
      let t = 0;
      for (let i = j; i < m; i++) t += A[i][j] * A[i][k];
      t = 2 * t / vn;
      for (let i = j; i < m; i++) A[i][k] -= t * A[i][j];
    }
    let t = 0;
    for (let i = j; i < m; i++) t += A[i][j] * b[i];
    t = 2 * t / vn;
    for (let i = j; i < m; i++) b[i] -= t * A[i][j];
  }
  let lo = Infinity, hi = 0;
  for (const v of d) { lo = Math.min(lo, Math.abs(v)); hi = Math.max(hi, Math.abs(v)); }
  const x = new Array(n).fill(0);
  for (let j = n - 1; j >= 0; j--) {
    let s = b[j];
    for (let k = j + 1; k < n; k++) s -= A[j][k] * x[k];
    x[j] = s / d[j];
  }
  return [x, hi > 0 ? lo / hi : 0];
}
// the scaled rows of the posture system at q
function gkScaled(q, K, V, A) {
  const [r, J] = gkRowsPhi(q, K, V, A), m = GKN.m, n = GKN.n, rs = [], Js = [];
  for (let i = 0; i < m; i++) {
    rs.push(r[i] * GKN.rowScale[i]);
    Js.push(J[i].slice(0, n).map((v, j) => v * GKN.rowScale[i] * GKN.colScale[j]));
  }
  return [rs, Js];
}
const gkNorm = (r) => { let s = 0; for (const v of r) s += v * v; return Math.sqrt(s); };
// Newton-Raphson from q (halving a step that does not reduce the residual); null: no posture
function gkNewton(q0, K, V, A) {
  let q = q0.slice(), [r, J] = gkScaled(q, K, V, A), f = gkNorm(r), polish = 0;
  for (let it = 0; it < 40; it++) {
    if (!Number.isFinite(f)) return null;
    // converged: one more step polishes it (none needed below 1e-13, far under 1e-9)
    if (f < 1e-13 || (f < 1e-11 && ++polish > 1)) return q;
    const [dx] = gkLstsq(J, r.map((v) => -v));
    let lam = 1, qn = null, rn = null, Jn = null, fn = Infinity;
    for (let h = 0; h < 12; h++, lam /= 2) {
      qn = q.map((v, j) => v + lam * dx[j] * GKN.colScale[j]);
      [rn, Jn] = gkScaled(qn, K, V, A);
      fn = gkNorm(rn);
      if (fn < f || f < 1e-11) break;
    }
    if (!(fn < f) && f >= 1e-11) return null;
    q = qn; r = rn; J = Jn; f = fn;
  }
  return f < 1e-11 ? q : null;
}
let gkNState = {q: GKN.q0.slice(), A: GKN.A0.slice(), V: GKN.values.slice(), K: null};
// march from the state s to the drive values V and numbers K: [the posture or null, the last
// posture reached on the way]
function gkMarch(s, V, K) {
  const K0 = s.K || K, dV = V.map((v, i) => GKN.drives[i].angle ?
    _wrap(v - s.V[i]) : v - s.V[i]);
  let steps = 1;
  for (let i = 0; i < dV.length; i++) {
    steps = Math.max(steps, Math.ceil(Math.abs(dV[i]) / (GKN.drives[i].angle ? GKN.march[0] :
                                                         GKN.march[1] * GKN.size)));
  }
  for (let i = 0; i < K.length; i++) {
    steps = Math.max(steps, Math.ceil(Math.abs(K[i] - K0[i]) / (GKN.march[1] * GKN.size)));
  }
  if (steps > 2000) return [null, s];
  let last = s;
  for (let k = 1; k <= steps; k++) {
    const t = k / steps, Vk = s.V.map((v, i) => v + t * dV[i]);
    const Kk = K.map((v, i) => K0[i] + t * (v - K0[i]));
    const qn = gkNewton(last.q, Kk, Vk, last.A);
    if (qn === null) return [null, last];
    // a jump of a link's origin (a roller's angle may turn fast: k = R/ρ times the arm's)
    for (let j = 0; j < qn.length; j++) {
      if (j % 3 !== 2 && Math.abs(qn[j] - last.q[j]) / GKN.colScale[j] > GKN.jump) {
        return [null, last];
      }
    }
    last = {q: qn, A: gkRowsAnchors(qn, Kk, last.A), V: Vk, K: Kk};
  }
  if (gkCycle) return [last, last];  // a curve's point needs no verdict on the toggle
  const [, J] = gkScaled(last.q, K, last.V, last.A);
  if (gkLstsq(J, new Array(J.length).fill(0))[1] <= GKN.singular) return [null, last];
  return [last, last];
}
// the coupler curves (drive + k°, k = 0..359, in order): a forward chain from the posture
// shown until it cannot be assembled, then a backward chain from the posture shown, so
// each curve is the branch the posture is on, each posture one step from the one before
let gkCycle = null;
function gkCycleState(V, K) {
  const c = gkCycle, d = _wrap(V[0] - c.mark.V[0]);
  if (c.fwd !== null) {
    const [s] = gkMarch(c.fwd, V, K);
    if (s !== null) { c.fwd = s; return s; }
    c.fwd = null;
    return null;
  }
  if (d >= 0 || d < c.floor) return null;
  const [s, last] = gkMarch(c.back, V, K);
  if (s === null) { c.back = last; c.floor = _wrap(last.V[0] - c.mark.V[0]); return null; }
  c.back = s;
  return s;
}
// q̇ and q̈ (Secs. 3.9, 4.9): the constraint rows and the known rates, one solve each
function gkRates(s) {
  if (!GKN.rates) return [null, null];
  const [, J] = gkRowsPhi(s.q, s.K, s.V, s.A), m = GKN.m, c = GKN.ncons, n = GKN.n;
  const rows = [], scale = [];
  for (let i = 0; i < c; i++) { rows.push(J[i]); scale.push(GKN.rowScale[i]); }
  for (let i = 0; i < GKN.rateRows; i++) { rows.push(J[m + i]); scale.push(GKN.rowScale[m + i]); }
  if (rows.length !== n) return null;
  const As = rows.map((r, i) => r.map((v, j) => v * scale[i] * GKN.colScale[j]));
  const b = new Array(c).fill(0).concat(GKN.rates.map((x) => x[0]));
  const [xv, ratio] = gkLstsq(As, b.map((v, i) => v * scale[i]));
  if (ratio <= GKN.singular) return null;
  const qd = xv.map((v, j) => v * GKN.colScale[j]);
  const g = gkRowsGam(s.q, qd, s.K, s.A);
  const rhs = g.map((v, i) => i < c ? -v : GKN.rates[i - c][1] - v);
  const [xa] = gkLstsq(As, rhs.map((v, i) => v * scale[i]));
  return [qd, xa.map((v, j) => v * GKN.colScale[j])];
}
// the page's values of a state: points, angles, and the rates when the file gives them
function gkNewtonValues(s, qd, qdd) {
  const out = {}, q = s.q;
  for (const lid of Object.keys(GKN.links)) {
    const k = GKN.links[lid];
    out["\u03b8" + lid] = k < 0 ? 0 : q[3 * k + 2];
    if (qd) {
      out["\u03c9" + lid] = k < 0 ? 0 : qd[3 * k + 2];
      out["\u03b1" + lid] = k < 0 ? 0 : qdd[3 * k + 2];
    }
  }
  for (const [name, k, x, y, fs] of GKN.points) {
    if (k < 0) {
      out[name] = fs ? [s.K[fs[0]], s.K[fs[1]]] : [x, y];
      if (qd) { out["v(" + name + ")"] = [0, 0]; out["a(" + name + ")"] = [0, 0]; }
      continue;
    }
    const c = Math.cos(q[3 * k + 2]), sn = Math.sin(q[3 * k + 2]);
    const rx = c * x - sn * y, ry = sn * x + c * y;
    out[name] = [q[3 * k] + rx, q[3 * k + 1] + ry];
    if (qd) {
      const w = qd[3 * k + 2], al = qdd[3 * k + 2];
      out["v(" + name + ")"] = [qd[3 * k] - w * ry, qd[3 * k + 1] + w * rx];
      out["a(" + name + ")"] = [qdd[3 * k] - al * ry - w * w * rx,
                                qdd[3 * k + 1] + al * rx - w * w * ry];
    }
  }
  if (qd) { out.o_v = [0, 0]; out.o_a = [0, 0]; }
  return out;
}
function construction(I, K) {
  gkWhy = "";
  const V = GKN.drives.map((d, i) => (I[d.label] !== undefined ? I[d.label] : GKN.values[i]));
  const s = gkCycle ? gkCycleState(V, K) : gkMarch(gkNState, V, K)[0];
  if (s === null) return null;
  let qd = null, qdd = null;
  if (GKN.rates && !gkCycle) {  // the coupler curves need the positions only
    const got = gkRates(s);
    if (got === null) return null;
    [qd, qdd] = got;
  }
  if (!gkCycle) gkNState = s;
  const out = gkNewtonValues(s, qd, qdd);
  // the polygons constructed at Newton's posture (render/live_newton_polygons.py)
  if (qd && GKN.polygons) {
    const got = gkNewtonPolygons(GKN.polygons, out);
    if (got === null) gkWhy = GKN.polygons.why;
    return got;
  }
  return out;
}
let gkWhy = "";
// why the last call returned null, when the posture was found but not its polygons
construction.why = () => gkWhy;
construction.mark = () => {
  gkCycle = {mark: gkNState, fwd: gkNState, back: gkNState, floor: -Infinity};
  return gkNState;
};
construction.restore = (s) => { gkNState = s; gkCycle = null; };
construction.reset = () => {
  gkNState = {q: GKN.q0.slice(), A: GKN.A0.slice(), V: GKN.values.slice(), K: null};
};
construction.edit = (f, r) => gkRollEdit(GKN.phases, f, r, null);
"""
