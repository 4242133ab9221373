"""The script and style sheet of the live page (:mod:`graphkin.render.live`), as strings.

The script reads the page's data (``#gk-data``), calls the written-out
construction ``construction(I, K)`` on every pointer move and redraws the
posture and the velocity and acceleration polygons (Secs. 3.4-3.6 and
4.2-4.6 of Uicker, Pennock & Shigley, 5th ed.) in the colours of ``draw``
(render/style.py, passed in the data).  Every text it writes goes through
``textContent`` (never parsed as HTML).  The script is one function,
``gkLiveApp(root, data, name, onEdit)``, run on the page's document (which
sets ``window.graphkinLive``: the tests and the benchmark read the page's
state, its drive setter and its TOML there) or inside a notebook widget's
element (:mod:`graphkin.render.live_widget`, whose ``onEdit`` sends the
edited file back to Python).
"""

from __future__ import annotations

from graphkin.render.live_cam_turn import CAMS_APP_JS
from graphkin.render.live_centers import CENTERS_CSS, CENTERS_JS
from graphkin.render.live_curvature_js import CURVATURE_APP_JS, CURVATURE_CSS, CURVATURE_JS
from graphkin.render.live_forces import FORCES_APP_JS, FORCES_JS
from graphkin.render.live_labels_js import LABELS_JS
from graphkin.render.live_pen import PEN_JS
from graphkin.render.live_pitch import PITCH_APP_JS
from graphkin.render.live_toml_js import TOML_JS

__all__ = ["APP_JS", "LIVE_LIB", "PAGE_CSS"]

LIVE_LIB = TOML_JS + r"""
// the labels as graphkin draw prints them (render/scene.py, render/paint.py,
// render/kennedy.py): a point's trailing digits subscript (O2 -> O₂), an image's letter
// lowercase and primed in the acceleration polygon (a(B) -> b′, O2 -> o₂), an instant
// center's digits subscript (I13 -> I₁₃), a construction label's part after "_" a subscript
// (O_V, G_N: [head, subscript, what follows])
const GK_SUB = "₀₁₂₃₄₅₆₇₈₉";
const gkSub = (d) => d.replace(/[0-9]/g, (c) => GK_SUB[+c]);
function gkPointText(lab) {
  const base = String(lab).split("#")[0].split(":").pop();
  const m = /^(.*\D)(\d+)$/.exec(base);
  return m ? m[1] + gkSub(m[2]) : base;
}
function gkImageText(lab, prime) {
  const [name, link] = String(lab).split("@");
  const base = name.split("#")[0].split(":").pop();
  const m = /^(.*?)(\d*)$/.exec(base);
  const letters = m[1] || base, digits = m[1] ? m[2] : "";
  return letters.toLowerCase() + (prime ? "\u2032" : "") + gkSub(digits + (link || ""));
}
function gkCenterText(lab) {
  return /^I[0-9-]+$/.test(lab) ? "I" + gkSub(lab.slice(1)) : lab;
}
function gkParts(lab) {
  const base = String(lab).split("#")[0].split(":").pop(), k = base.indexOf("_");
  if (k <= 0 || k === base.length - 1) return [gkPointText(lab), "", ""];
  let lo = base.slice(k + 1).replace(/_/g, ""), prime = "";
  while (lo.endsWith("'")) { lo = lo.slice(0, -1); prime += "'"; }
  return [base.slice(0, k), lo, prime];
}
// a center farther than graphkin's FAR_AS_INFINITY sizes from the frame is at infinity, as
// graphkin's report says (kinematics/instant_centers/primary.py): drawn as a direction
function gkAtInfinity(C, p) {
  const dx = p[0] - C.origin[0] * p[2], dy = p[1] - C.origin[1] * p[2];
  return !(Math.abs(p[2]) * C.far > Math.hypot(dx, dy));
}
"""

PAGE_CSS = """
body { font-family: system-ui, sans-serif; margin: 1em; color: #000; }
h1 { font-size: 1.2em; margin: 0 0 .3em; }
.hint { margin: 0 0 .5em; color: #444; font-size: .9em; }
.controls { display: flex; gap: .6em; align-items: center; flex-wrap: wrap; }
#gk-drive { width: 22em; }
/* two lines reserved, never more: a message coming or going must not move the panels
   under the pointer while dragging */
#gk-status { min-height: 2.6em; max-height: 2.6em; overflow-y: auto;
             color: #c62828; font-weight: 600; margin: .4em 0; }
#gk-status.gk-note { color: #37474f; font-weight: 400; }
main { display: flex; flex-wrap: wrap; gap: .8em; }
figure { margin: 0; border: 1px solid #ccc; }
figcaption { font-size: .85em; padding: .2em .4em; background: #f4f4f4; }
svg { display: block; width: 420px; height: 360px; touch-action: none; }
.gk-handle { cursor: grab; }
.gk-stale { opacity: .35; }
table { border-collapse: collapse; margin-top: .8em; font-size: .85em; }
td, th { border: 1px solid #ccc; padding: .15em .5em; text-align: right; }
th { background: #f4f4f4; }
"""

APP_JS = r"""
// a panel not drawn: its figure keeps its caption and says why
function gkRefuse(svg, why) {
  const f = svg.parentNode, p = document.createElement("p");
  svg.style.display = "none"; f.style.display = "";
  p.className = "gk-refused"; p.textContent = why;
  f.appendChild(p);
}
// the page's script, run inside ``root`` (the document, or a notebook widget's element):
// D is the page's data, GK_NAME the file's name, onEdit(toml) is told every edit (or null);
// returns the page's API (state, setDrive, toml, redraw)
function gkLiveApp(root, D, GK_NAME, onEdit) {
"use strict";
const byId = (id) => root.querySelector("#" + id);
// markers referenced by url(#...) must be unique in the document (several widgets)
const UID = "gk" + Math.random().toString(36).slice(2, 9) + "-";
const NS = "http://www.w3.org/2000/svg";
const W = 420, H = 360, M = 30;
const K0 = D.K.slice();
let K = D.K.slice();
const drive0 = D.drive.value;
let drive = drive0;
const I = Object.assign({}, D.inputs);
const history = [];
let res = null, good = null, dragging = null;
const st = D.style;
const ink = (k, p) => (st[k] && st[k][p] !== undefined) ? st[k][p] : "#000";
const px = (lw) => 1.4 * lw;
const views = {};
const placed = {};  // each panel's letters' offsets from their points, by text (label)
const panels = ["posture"].concat(D.rates && !D.refused ? ["velocity", "acceleration"] : []);
const svgs = {};
for (const name of ["posture", "velocity", "acceleration", "kennedy", "curvature"]) {
  const svg = byId("gk-" + name);
  svg.setAttribute("viewBox", "0 0 " + W + " " + H);
  if (panels.indexOf(name) < 0 && !(name === "kennedy" && D.centers) &&
      !(name === "curvature" && D.curvature)) {
    svg.parentNode.style.display = "none";
  }
  svgs[name] = svg;
}
// a panel Python itself does not draw says why, in its one line (render/live_newton.py)
for (const name of Object.keys(D.refused || {})) gkRefuse(svgs[name], D.refused[name]);
const moving = [];
for (const lid of Object.keys(D.links)) {
  if (lid === "1") continue;
  for (const n of D.links[lid]) if (moving.indexOf(n) < 0) moving.push(n);
}
const owners = {};
for (const lid of Object.keys(D.links)) {
  for (const n of D.links[lid]) owners[n] = (owners[n] || 0) + 1;
}

// a drive that follows the first by a law moves with it (render/live_laws.py, Sec. 5.4)
const follow = (J) => (D.follow ? gkFollow(D.follow, J) : J);
// a cam turns: its equivalent linkage's numbers set in K for the angle (live_cam_turn.py)
let turned = null;
function solve() {
  I[D.drive.label] = drive;
  if (!D.turn) return construction(follow(I), K);
  const s = gkTurnSolve(D.turn, follow(I), K, construction);
  turned = s.t;
  return s.r;
}

// the instant centers (Aronhold-Kennedy, Sec. 3.15) from the primary centers of the posture
// (a cam's dwell: none, its follower and coupler at rest, said so: live_cam_turn.py)
function centersOf(r) {
  if (D.turn && gkTurnDwell(D.turn, turned)) return null;
  return D.centers ? gkCenters(D.centers, r) : null;
}
let ics = null, curv = null;

// the coupler curves of the whole cycle: the points of the links not pinned to the frame,
// at 360 drive angles from the current one (null where the posture cannot be assembled)
const traced = [];
for (const lid of Object.keys(D.links)) {
  if (lid === "1" || D.links[lid].some((n) => D.frame[n])) continue;
  for (const n of D.links[lid]) if (traced.indexOf(n) < 0 && owners[n] === 1) traced.push(n);
}
let curves = {};
function cycle() {
  curves = {};
  if (D.drive.kind !== "angle" || (D.cam && !D.turn) || !traced.length) return curves;
  const J = Object.assign({}, I), mark = construction.mark ? construction.mark() : null;
  for (const n of traced) curves[n] = [];
  for (let k = 0; k < 360; k++) {
    J[D.drive.label] = drive + 2 * Math.PI * k / 360;
    const r = D.turn ? gkTurnSolve(D.turn, follow(J), K.slice(), construction).r
      : construction(follow(J), K);
    for (const n of traced) curves[n].push(r ? r[n] : null);
  }
  if (mark) construction.restore(mark);
  return curves;
}

function pointsOf(panel, r) {
  const out = [];
  const pre = panel === "posture" ? "" : (panel === "velocity" ? "v" : "a");
  if (pre) { const o = r["o_" + pre]; if (o) out.push(o); }
  for (const lid of Object.keys(D.links)) for (const n of D.links[lid]) {
    const p = pre ? r[pre + "(" + n + ")"] : r[n];
    if (p) out.push(p);
  }
  for (const e of D.pitch || []) if (e.pre === pre && r[e.label]) out.push(r[e.label]);
  return out;
}

function fit(panel, r) {
  const pts = pointsOf(panel, r);
  if (panel === "posture") {
    for (const n of Object.keys(curves)) for (const p of curves[n]) if (p) pts.push(p);
    for (const o of camOutlines(r)) for (const p of o) pts.push(p);  // a turning cam's outline
    for (const p of pitchExtent(r)) pts.push(p);  // the pitch circles (render/live_pitch.py)
    // the instant centers too, unless one is far (near parallel lines): within 3 sizes
    const c = centersOf(r);
    if (c) {
      let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
      for (const p of pts) {
        x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
        y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
      }
      const size = Math.hypot(x1 - x0, y1 - y0), o = [(x0 + x1) / 2, (y0 + y1) / 2];
      for (const lab of D.centers.labels) {
        const h = c[lab];
        if (!h || gkAtInfinity(D.centers, h)) continue;
        const p = [h[0] / h[2], h[1] / h[2]];
        if (Math.hypot(p[0] - o[0], p[1] - o[1]) < 3 * size) pts.push(p);
      }
    }
  }
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const p of pts) {
    x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
    y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
  }
  let w = x1 - x0, h = y1 - y0;
  const big = Math.max(w, h) || 1;
  w = Math.max(w, 0.05 * big); h = Math.max(h, 0.05 * big);
  // a subnormal extent (ω = 1e-313: every image at the pole) overflows the scale: fit a unit
  const s0 = Math.min((W - 2 * M) / w, (H - 2 * M) / h);
  const s = Number.isFinite(s0) && s0 > 0 ? s0 : Math.min(W - 2 * M, H - 2 * M);
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  views[panel] = {s: s, left: cx - W / (2 * s), top: cy + H / (2 * s)};
}

// fit a panel to a list of points (the curvature panel's own scale)
function fitPoints(panel, pts) {
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const p of pts) {
    x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
    y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
  }
  if (!pts.length) { x0 = y0 = -1; x1 = y1 = 1; }
  let w = x1 - x0, h = y1 - y0;
  const big = Math.max(w, h) || 1;
  w = Math.max(w, 0.05 * big); h = Math.max(h, 0.05 * big);
  // a subnormal extent (ω = 1e-313: every image at the pole) overflows the scale: fit a unit
  const s0 = Math.min((W - 2 * M) / w, (H - 2 * M) / h);
  const s = Number.isFinite(s0) && s0 > 0 ? s0 : Math.min(W - 2 * M, H - 2 * M);
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  views[panel] = {s: s, left: cx - W / (2 * s), top: cy + H / (2 * s)};
}

function X(panel, p) { const v = views[panel]; return (p[0] - v.left) * v.s; }
function Y(panel, p) { const v = views[panel]; return (v.top - p[1]) * v.s; }

function el(parent, tag, attrs, text) {
  const e = document.createElementNS(NS, tag);
  for (const k of Object.keys(attrs)) e.setAttribute(k, attrs[k]);
  if (text !== undefined) e.textContent = text;
  parent.appendChild(e);
  return e;
}

function defs(svg) {
  const d = el(svg, "defs", {});
  const m = el(d, "marker", {id: UID + svg.id + "-arrow", viewBox: "0 0 10 10", refX: "10",
                             refY: "5", markerWidth: "7", markerHeight: "7",
                             orient: "auto-start-reverse"});
  el(m, "path", {d: "M0,1 L10,5 L0,9 z", fill: ink("result-line", "color")});
}

function outline(g, panel, pts, plate) {
  if (pts.length < 2) return;
  const xy = pts.map((p) => X(panel, p).toFixed(2) + "," + Y(panel, p).toFixed(2)).join(" ");
  if (pts.length >= 3) {
    el(g, "polygon", {points: xy, fill: ink(plate, "fc"), stroke: ink(plate, "ec"),
                      "stroke-width": px(ink(plate, "lw"))});
  } else {
    el(g, "polyline", {points: xy, fill: "none", stroke: ink("link", "ec"),
                       "stroke-width": 2 * px(ink("link", "lw"))});
  }
}

// a label beside p: a text, or [head, subscript, what follows] (gkParts: O_V is O with V
// below, as draw's mathtext $O_V$; dy, which every browser honours, not baseline-shift);
// kind "vector" for a force's name (not a lettered point). While dragging, at the offset
// the letter had when the pointer last stopped (placed by draw's rule then: gkPlaceLabels,
// render/live_labels_js.py), else up and to the right, or to the left near the right edge
function label(g, panel, p, text, kind) {
  const x = X(panel, p), y = Y(panel, p);
  const s = Array.isArray(text) ? text.join("") : text;
  const o = (placed[panel] || {})[s];
  const left = !o && x + 6 + 7 * s.length > W;
  const t = el(g, "text", {x: o ? x + o[0] : x + (left ? -6 : 6), y: o ? y + o[1] : y - 6,
                           "font-size": "12", "font-style": "italic", class: "gk-label",
                           "data-ax": x.toFixed(2), "data-ay": y.toFixed(2),
                           "data-point": kind === "vector" ? "0" : "1"},
               Array.isArray(text) ? text[0] : text);
  if (left || (o && o[2])) t.setAttribute("text-anchor", left ? "end" : o[2]);
  if (Array.isArray(text) && text[1]) {
    el(t, "tspan", {dy: "0.3em", "font-size": "70%", class: "gk-sub"}, text[1]);
    if (text[2]) el(t, "tspan", {dy: "-0.3em"}, text[2]);
  }
  return t;
}

function drawPosture(r, stale) {
  const svg = svgs.posture;
  svg.textContent = "";
  defs(svg);
  const g = el(svg, "g", stale ? {class: "gk-stale"} : {});
  for (const n of Object.keys(curves)) {
    let run = [];
    const flush = () => {
      if (run.length > 1) {
        el(g, "polyline", {points: run.join(" "), fill: "none", class: "gk-curve",
                           stroke: ink("aux-line", "color"), "stroke-width": "1"});
      }
      run = [];
    };
    // closed over one turn, but not on the covering: a train's planets are not back
    for (const p of curves[n].concat(D.drive.covering ? [] : [curves[n][0]])) {
      if (p) run.push(X("posture", p).toFixed(1) + "," + Y("posture", p).toFixed(1));
      else flush();
    }
    flush();
  }
  drawCams(g, r);
  drawPitchCircles(g, r);
  for (const lid of Object.keys(D.links)) {
    if (lid === "1") continue;
    outline(g, "posture", D.links[lid].map((n) => r[n]).filter(Boolean), "plate");
  }
  if (ics) drawCenters(g);
  for (const n of Object.keys(D.frame)) {
    const p = r[n] || [K[D.frame[n][0]], K[D.frame[n][1]]];
    const x = X("posture", p), y = Y("posture", p);
    el(g, "path", {d: "M" + x + "," + y + " l-9,14 h18 z", fill: "#fff", stroke: "#000",
                   "stroke-width": "1"});
  }
  // a frame pivot of a moving link (O2 of link 2) drawn and lettered once
  for (const n of new Set(moving.concat(Object.keys(D.frame)))) {
    const p = r[n]; if (!p) continue;
    const pin = (owners[n] || 0) > 1;
    el(g, "circle", {cx: X("posture", p), cy: Y("posture", p), r: pin ? 4 : 2.5,
                     fill: pin ? "#fff" : "#000", stroke: "#000", "stroke-width": "1.2"});
    label(g, "posture", p, gkPointText(n));
  }
  const handles = [];
  for (const n of Object.keys(D.frame)) handles.push(["frame", n]);
  for (const n of Object.keys(D.coupler)) handles.push(["point", n]);
  if (D.drive.tip) handles.push(["drive", D.drive.tip]);
  for (const [kind, n] of handles) {
    const p = r[n]; if (!p) continue;
    el(g, "circle", {cx: X("posture", p), cy: Y("posture", p), r: 11, fill: "#c62828",
                     "fill-opacity": "0.18", class: "gk-handle", "data-kind": kind,
                     "data-name": n});
  }
}

function drawCenters(g) {
  // Kennedy's lines: through their finite centers, to the panel's edge when a center on the
  // line is at infinity (the line is then the parallel to its direction); a center at
  // infinity is drawn as its direction, a double arrow with its name (Sec. 3.13)
  const C = D.centers, v = views.posture;
  const fin = (h) => !gkAtInfinity(C, h);
  const xy = (h) => [h[0] / h[2], h[1] / h[2]];
  const on = {};
  for (const [lab, p, q] of C.joins) on[lab] = [p, q];
  for (const [lab, l1, l2] of C.meets) { on[l1].push(lab); on[l2].push(lab); }
  // a center on the best pair of its lines at this posture (kennedy_center): the two it used
  const seen = {};
  for (const lab of Object.keys(C.kennedy || {})) {
    const kc = C.kennedy[lab], pr = kc.pairs[ics[lab + "|k"]];
    if (!ics[lab] || !pr) continue;
    [["a", pr[0]], ["b", pr[pr.length - 1]]].forEach(([x, i]) => {
      const key = kc.lines[i].slice().sort().join(" ");
      if (!seen[key]) { seen[key] = lab + "|" + x; on[seen[key]] = kc.lines[i].slice(); }
      if (on[seen[key]].indexOf(lab) < 0) on[seen[key]].push(lab);
    });
  }
  const reach = 2 * Math.hypot(W, H) / v.s;
  for (const lab of Object.keys(on)) {
    const ln = ics[lab];
    const hs = on[lab].map((c) => ics[c]).filter(Boolean);
    const finite = hs.filter(fin).map(xy);
    if (!ln || !finite.length) continue;
    const d = [ln[1], -ln[0]], o = finite[0];
    let t0 = 0, t1 = 0;
    for (const p of finite) {
      const t = (p[0] - o[0]) * d[0] + (p[1] - o[1]) * d[1];
      t0 = Math.min(t0, t); t1 = Math.max(t1, t);
    }
    if (hs.some((h) => !fin(h))) { t0 -= reach; t1 += reach; }
    const pad = 0.08 * (t1 - t0) + 8 / v.s;
    const a = [o[0] + (t0 - pad) * d[0], o[1] + (t0 - pad) * d[1]];
    const b = [o[0] + (t1 + pad) * d[0], o[1] + (t1 + pad) * d[1]];
    el(g, "line", {x1: X("posture", a), y1: Y("posture", a), x2: X("posture", b),
                   y2: Y("posture", b), stroke: ink("aux-line", "color"),
                   "stroke-width": "0.8", "stroke-dasharray": "5 3", class: "gk-kennedy"});
  }
  let k = 0;
  for (const lab of C.labels) {
    const h = ics[lab];
    if (!h) continue;
    if (fin(h)) {
      if (C.given[lab] && C.given[lab].pin !== undefined) continue;  // the pin is drawn
      const p = xy(h);
      el(g, "circle", {cx: X("posture", p), cy: Y("posture", p), r: 3, fill: "#fff",
                       stroke: "#000", "stroke-width": "1.2", class: "gk-center"});
      label(g, "posture", p, gkCenterText(lab));
      continue;
    }
    // at infinity: its direction, screen y down, in the panel's lower left corner
    const n = Math.hypot(h[0], h[1]) || 1, ux = h[0] / n, uy = -h[1] / n;
    const cx = 42 + 60 * k, cy = H - 40;
    k++;
    el(g, "line", {x1: cx - 18 * ux, y1: cy - 18 * uy, x2: cx + 18 * ux, y2: cy + 18 * uy,
                   stroke: "#000", "stroke-width": "1.2", class: "gk-center-infinity",
                   "data-name": lab, "marker-start": "url(#" + UID + "gk-posture-arrow)",
                   "marker-end": "url(#" + UID + "gk-posture-arrow)"});
    el(g, "text", {x: cx - 16, y: cy + 30, "font-size": "11", "font-style": "italic"},
       gkCenterText(lab) + " \u2192 \u221e");
  }
}

// the Kennedy circle (Sec. 3.15): the links on a circle, a line for every center: primary
// centers black, those Kennedy's theorem found in the result colour, none where the page
// cannot find it at this posture (dashed)
function drawKennedyCircle() {
  const svg = svgs.kennedy, C = D.centers;
  svg.textContent = "";
  const n = C.links.length, R = 0.36 * Math.min(W, H), ox = W / 2, oy = H / 2;
  const at = {};
  C.links.forEach((lid, i) => {
    const t = Math.PI / 2 - 2 * Math.PI * i / n;
    at[lid] = [ox + R * Math.cos(t), oy - R * Math.sin(t)];
  });
  for (const lab of Object.keys(C.pairs)) {
    const [i, j] = C.pairs[lab], p = at[i], q = at[j];
    if (!p || !q) continue;
    const found = ics && ics[lab];
    const e = el(svg, "line", {x1: p[0], y1: p[1], x2: q[0], y2: q[1],
                               stroke: C.given[lab] ? "#000" : ink("result-line", "color"),
                               "stroke-width": found ? "1.6" : "0.8",
                               "stroke-dasharray": found ? "none" : "4 3",
                               class: "gk-kennedy-pair", "data-name": lab});
    el(e, "title", {}, gkCenterText(lab));
    const m = [p[0] + 0.38 * (q[0] - p[0]), p[1] + 0.38 * (q[1] - p[1])];  // chords cross at 1/2
    el(svg, "text", {x: m[0] + 3, y: m[1] - 3, "font-size": "10", fill: "#555"},
       gkCenterText(lab));
  }
  for (const lid of C.links) {
    const p = at[lid];
    el(svg, "circle", {cx: p[0], cy: p[1], r: 11, fill: "#fff", stroke: "#000"});
    el(svg, "text", {x: p[0], y: p[1] + 4, "font-size": "12", "text-anchor": "middle"}, lid);
  }
}

/*CURVATURE*/

function drawPolygon(panel, pre, r, stale) {
  const svg = svgs[panel];
  svg.textContent = "";
  defs(svg);
  const g = el(svg, "g", stale ? {class: "gk-stale"} : {});
  const o = r["o_" + pre];
  if (!o) return;
  const img = (n) => r[pre + "(" + n + ")"];
  for (const lid of Object.keys(D.links)) {
    if (lid === "1") continue;
    outline(g, panel, D.links[lid].map(img).filter(Boolean), "plate");
  }
  for (const n of moving) {
    const p = img(n); if (!p) continue;
    if (Math.hypot(p[0] - o[0], p[1] - o[1]) * views[panel].s > 1) {
      el(g, "line", {x1: X(panel, o), y1: Y(panel, o), x2: X(panel, p), y2: Y(panel, p),
                     stroke: ink("result-line", "color"),
                     "stroke-width": px(ink("result-line", "lw")),
                     "marker-end": "url(#" + UID + svg.id + "-arrow)"});
    }
    label(g, panel, p, gkImageText(n, pre === "a"));
  }
  // the points of contact of rolling contact (Sec. 3.7): one velocity image for both
  // links, the pole on the frame (V_C = 0); accelerations apart by A^r (live.py)
  for (const e of D.pitch || []) {
    const p = e.pre === pre ? r[e.label] : null; if (!p) continue;
    el(g, "circle", {cx: X(panel, p), cy: Y(panel, p), r: 3, fill: "#fff", stroke: "#000"});
    label(g, panel, p, e.text).classList.add("gk-pitch");
  }
  el(g, "circle", {cx: X(panel, o), cy: Y(panel, o), r: 3, fill: "#000"});
  label(g, panel, o, gkParts(pre === "v" ? "O_V" : "O_A")).classList.add("gk-pole");
  if (pen.panel === panel) drawPen(svg, panel);
}

// A value within VERDICT_REL (graphkin/tolerance.py) of its column's scale is round-off: "0",
// never "6.12323e-16" (the x of a pin straight above its pivot).
function fmt(v, scale) {
  if (!Number.isFinite(v)) return "\u2014";
  if (scale !== undefined && Math.abs(v) <= 1e-9 * scale) v = 0;
  return Number(v.toPrecision(6)).toString();
}
function colScale(vals) {
  return vals.reduce((m, x) => (Number.isFinite(x) ? Math.max(m, Math.abs(x)) : m), 0);
}

function table(r) {
  const t = byId("gk-table");
  t.textContent = "";
  const head = el0(t, "tr");
  for (const h of ["point", "x", "y"].concat(D.rates ? ["|V|", "|A|"] : [])) el0(head, "th", h);
  const ov = r.o_v, oa = r.o_a;
  const rel = (q, o) => (q && o ? Math.hypot(q[0] - o[0], q[1] - o[1]) : NaN);
  const shown = moving.filter((n) => r[n]);
  // each column's scale: the largest of its kind on the page (the size of the mechanism)
  const sx = colScale(shown.flatMap((n) => [r[n][0], r[n][1]]));
  const sv = colScale(shown.map((n) => rel(r["v(" + n + ")"], ov)));
  const sa = colScale(shown.map((n) => rel(r["a(" + n + ")"], oa)));
  for (const n of shown) {
    const p = r[n];
    const row = el0(t, "tr");
    el0(row, "th", gkPointText(n)); el0(row, "td", fmt(p[0], sx)); el0(row, "td", fmt(p[1], sx));
    if (D.rates) {
      const v = rel(r["v(" + n + ")"], ov), a = rel(r["a(" + n + ")"], oa);
      el0(row, "td", fmt(v, sv));
      el0(row, "td", fmt(a, sa));
    }
  }
}
function el0(parent, tag, text) {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  parent.appendChild(e);
  return e;
}

const slider = byId("gk-drive");
const sval = byId("gk-drive-val");
const status = byId("gk-status");
const isAngle = D.drive.degrees;
function showDrive() {
  const v = isAngle ? drive * 180 / Math.PI : drive;
  // the drive as draw writes it: θ₂, θ₃/₂, s₄, and a point's coordinate x_C as x with the
  // subscript C (render/joint_angle.py)
  const lab = D.drive.label;
  const [h, lo] = lab.indexOf("_") > 0 ? gkParts(lab) : [gkSub(lab), ""];
  sval.textContent = h;
  if (lo) el0(sval, "sub", lo);
  sval.append(" = " + fmt(v) + (isAngle ? "\u00b0" : " " + D.unit));
  if (isAngle) slider.value = String(((v + 180) % 360 + 360) % 360 - 180);
  else slider.value = String(v);
}

const DEAD = "This posture cannot be assembled (or is at a dead center, " +
  "where the construction has no clean answer): drag back.";
function redraw(refit) {
  // a cam's equivalent linkage holds at the file's cam angle only (Sec. 4.7; live_cams.py)
  const held = D.cam && !D.turn && drive !== drive0;
  if (held) drive = drive0;
  res = solve();
  const ok = res !== null;
  if (ok) good = res;
  const r = ok ? res : good;
  if (r === null) {  // not even the file's posture (a dead point): said so, drawn nothing
    status.textContent = (construction.why && construction.why()) || DEAD;
    return;
  }
  cycle();
  ics = centersOf(r);
  curv = D.curvature ? gkCurvature(D.curvature, r) : null;
  if (refit || !views.posture) for (const p of panels) fit(p, r);
  drawPosture(r, !ok);
  if (D.rates && !D.refused) {
    drawPolygon("velocity", "v", r, !ok); drawPolygon("acceleration", "a", r, !ok);
  }
  if (D.centers) drawKennedyCircle();
  byId("gk-centers-note").textContent = (D.turn && gkTurnDwell(D.turn, turned)) ||
    gkCentersWhy(D.centers, ics);
  if (D.curvature) drawCurvature(r, !ok, refit);
  if (D.forces) { drawForces(r, !ok); drawActing(r, !ok); }
  if (ok) { table(r); forceTable(); }
  if (refit) placeLabels();
  // a drive that follows by a table has no value beyond its rows (render/live_laws.py)
  const why = ok || !D.follow ? "" : gkFollowWhy(D.follow, drive);
  const camSays = D.turn ? gkTurnNote(D.turn, turned, drive) : "";
  // a cam's angle and curvature: a note; an undercut profile stays a warning
  status.classList.toggle("gk-note", ok && !held && camSays.indexOf("undercut") < 0);
  status.textContent = (held ? D.cam.why + (ok ? "" : " ") : "") + (ok ? camSays : why ||
    (turned && turned.why) || (construction.why && construction.why()) ||
    ((camSays ? camSays + " " : "") + DEAD));
  showDrive();
}

// the pointer stopped: every panel's letters placed by draw's rule (live_labels_js.py)
function placeLabels() {
  const shown = {};
  for (const name of ["posture", "velocity", "acceleration", "curvature", "forces"]) {
    const svg = byId("gk-" + name);
    if (svg && svg.getBoundingClientRect().width > 0) shown[name] = svg;
  }
  Object.assign(placed, gkPlaceLabels(shown, W, H));
}

function snapshot() { history.push([K.slice(), drive]); if (history.length > 200) history.shift(); }

function world(svg, ev) {
  const pt = svg.createSVGPoint();
  pt.x = ev.clientX; pt.y = ev.clientY;
  const q = pt.matrixTransform(svg.getScreenCTM().inverse());
  const v = views.posture;
  return [v.left + q.x / v.s, v.top - q.y / v.s];
}

svgs.posture.addEventListener("pointerdown", (ev) => {
  const t = ev.target;
  if (!t.classList || !t.classList.contains("gk-handle")) return;
  snapshot();
  dragging = {kind: t.getAttribute("data-kind"), name: t.getAttribute("data-name")};
  if (dragging.kind === "drive" && D.drive.relative) {  // a cam: turned from where it is held
    const w = world(svgs.posture, ev), piv = (res || good)[D.drive.pivot];
    dragging.a0 = Math.atan2(w[1] - piv[1], w[0] - piv[0]);
    dragging.d0 = drive;
  }
  svgs.posture.setPointerCapture(ev.pointerId);
  ev.preventDefault();
});
svgs.posture.addEventListener("pointermove", (ev) => {
  if (!dragging) return;
  const w = world(svgs.posture, ev);
  if (dragging.kind === "frame") {
    const i = D.frame[dragging.name];
    K[i[0]] = w[0]; K[i[1]] = w[1];
  } else if (dragging.kind === "point") {
    dragPoint(D.coupler[dragging.name], w);
  } else {
    const piv = (res || good)[D.drive.pivot];
    const a = Math.atan2(w[1] - piv[1], w[0] - piv[0]);
    if (D.drive.relative) {  // a cam turns by the angle the pointer turns about its center
      drive = dragging.d0 + a - dragging.a0;
    } else {
      const b = a - D.drive.phi;
      // on a covering (a planet turning with its arm) the drive is counted on continuously
      drive = D.drive.covering ? drive + Math.atan2(Math.sin(b - drive), Math.cos(b - drive)) : b;
    }
  }
  redraw(false);
});
function localOf(c) { return [c.p[0] + K[c.slots[0]], c.p[1] + K[c.slots[1]]]; }
function dragPoint(c, w) {
  // Q = P + R(θ + offset)(q - p): the link's new local q of the dragged point, and the
  // complex ratio (q - a)/(b - a) of each image similar to the link (Mehmke, Sec. 3.5)
  const r = res || good, P = r[c.anchor], t = r[c.angle] + c.offset;
  const dx = w[0] - P[0], dy = w[1] - P[1], ct = Math.cos(t), sn = Math.sin(t);
  K[c.slots[0]] = ct * dx + sn * dy;
  K[c.slots[1]] = -sn * dx + ct * dy;
  const q = localOf(c);
  for (const im of c.images) {
    const zr0 = im.b[0] - im.a[0], zr1 = im.b[1] - im.a[1];
    const zp0 = q[0] - im.a[0], zp1 = q[1] - im.a[1];
    const den = zr0 ** 2 + zr1 ** 2;
    K[im.slots[0]] = (zp0 * zr0 + zp1 * zr1) / den;
    K[im.slots[1]] = (zp1 * zr0 - zp0 * zr1) / den;
  }
}
/*PEN*/
/*FORCES*/
/*CAMS*/
// the edited mechanism, told to the notebook (its widget.mechanism) after every edit
function notify() { if (onEdit) onEdit(edited()); }
const stop = () => { if (dragging) { dragging = null; redraw(true); notify(); } };
svgs.posture.addEventListener("pointerup", stop);
svgs.posture.addEventListener("pointercancel", stop);

if (isAngle) { slider.min = "-180"; slider.max = "180"; slider.step = "0.1"; }
else {
  const span = Math.max(Math.abs(drive0), 1);
  slider.min = String(drive0 - 2 * span); slider.max = String(drive0 + 2 * span);
  slider.step = String(span / 500);
}
slider.addEventListener("pointerdown", snapshot);
// the slider let go: every panel refitted to the posture reached, as when a drag stops
slider.addEventListener("change", () => { redraw(true); notify(); });
slider.addEventListener("input", () => {
  const v = Number(slider.value);
  drive = isAngle ? v * Math.PI / 180 : v;
  redraw(false);
});
// the two-way steps (Sec. 2.8, cases 2-4): switch the chosen point's branch
const branchSel = byId("gk-branch");
for (const n of Object.keys(D.branches)) {
  const o = document.createElement("option");
  o.value = n; o.textContent = gkPointText(n);
  branchSel.appendChild(o);
}
if (!branchSel.options.length) {
  branchSel.parentNode.style.display = "none";
  byId("gk-switch").style.display = "none";
}
byId("gk-switch").addEventListener("click", () => {
  const k = D.branches[branchSel.value];
  if (k === undefined) return;
  snapshot(); K[k] = -K[k]; redraw(true); notify();
});
byId("gk-undo").addEventListener("click", () => {
  const s = history.pop(); if (!s) return;
  K = s[0]; drive = s[1]; redraw(true); notify();
});
byId("gk-reset").addEventListener("click", () => {
  snapshot(); K = K0.slice(); drive = drive0;
  if (construction.reset) construction.reset();
  redraw(true); notify();
});

// the edited file as TOML (render/live_toml_js.py, shared with the vector page)
const tomlKey = gkTomlKey, tomlVal = gkTomlVal, isTable = gkIsTable, tomlTable = gkTomlTable;

function edited() {
  const f = JSON.parse(JSON.stringify(D.file));
  const r = res || good;
  for (const n of Object.keys(D.frame)) f.links["1"][n] = [K[D.frame[n][0]], K[D.frame[n][1]]];
  for (const n of Object.keys(D.coupler)) f.links[D.coupler[n].link][n] = localOf(D.coupler[n]);
  const dr = Array.isArray(f.drive) ? f.drive[D.drive.index] : f.drive;
  dr[D.drive.key] = D.drive.degrees ? drive * 180 / Math.PI : drive;
  // within a table's rows, read back within them (render/live_laws.py)
  if (D.follow) dr[D.drive.key] = gkFollowSaved(D.follow, dr[D.drive.key], drive);
  if (r && D.assembly.length) {
    f.assembly = isTable(f.assembly) ? f.assembly : {};
    for (const n of D.assembly) if (r[n]) f.assembly[n] = [r[n][0], r[n][1]];
  }
  if (construction.edit) construction.edit(f, r);
  const out = [];
  tomlTable(out, f, []);
  return out.join("\n").replace(/^\n+/, "") + "\n";
}

byId("gk-save").addEventListener("click", () => gkDownload(edited(), GK_NAME));

redraw(true);
return {
  state: () => ({drive: drive, K: K.slice(), result: res, curves: curves,
                 centers: gkCentersState(D.centers, ics),
                 curvature: curv, forces: frc}),
  setDrive: (v) => { drive = v; redraw(false); return res; },
  pen: pen,
  penSVG: penSVG,
  // client coordinates of a point of a panel (the tests click there)
  toClient: (panel, p) => {
    const r = svgs[panel].getBoundingClientRect();
    return [r.x + X(panel, p) * r.width / W, r.y + Y(panel, p) * r.height / H];
  },
  toml: edited,
  redraw: redraw,
  // the edit (K and the drive), kept by the notebook's model and restored in a new view
  edit: () => ({K: K.slice(), drive: drive}),
  load: (s) => { if (s.K.length === K.length) { K = s.K.slice(); drive = s.drive; redraw(true); } },
};
}
"""

# the pen mode's part of the script (render/live_pen.py), inside gkLiveApp, the curvature
# panel's drawing (render/live_curvature_js.py) and the pitch circles' (render/live_pitch.py)
APP_JS = (APP_JS.replace("/*PEN*/\n", PEN_JS).replace("/*FORCES*/\n", FORCES_APP_JS)
          .replace("/*CURVATURE*/\n", CURVATURE_APP_JS)
          .replace("/*CAMS*/\n", CAMS_APP_JS + PITCH_APP_JS))
# the curvature, force and centers' constructions' glue (render/live_curvature_js.py,
# render/live_forces.py, render/live_centers.py)
LIVE_LIB += CURVATURE_JS + FORCES_JS + CENTERS_JS + LABELS_JS
PAGE_CSS += CENTERS_CSS + CURVATURE_CSS
