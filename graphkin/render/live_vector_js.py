"""The script and style sheet of a vector file's live page (:mod:`graphkin.render.live_vector`).

``gkVectorApp(root, data, name)`` keeps what is given of ``C = A + B`` (each
vector's magnitude and direction, ``null`` where unknown), writes it into the
construction's numbers (``K``: the laid-off vectors and the arcs' radii) and
inputs (``I``: the known directions), calls the written-out construction
``vectorConstruction(I, K)`` on every pointer move and redraws it: the given
vectors in ink, the lines and arcs thin and grey, the chosen solution's
vectors in ink and the other's in grey, in the colours of ``draw``
(render/style.py, passed in the data).  Each solution is reported as
``graphkin vector`` reports it (:meth:`VectorEquationResult.polar`): a known
part kept, a found magnitude signed along its known direction, a found
direction in (-180°, 180°].  Where the intersections have no answer the page
says why, in ``graphkin vector``'s words.  Every text goes through
``textContent``.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (Table 2.2, Figs. 2.10-2.13), Sec. 2.10 (polar notation ``R∠θ``).
"""

from __future__ import annotations

__all__ = ["VECTOR_APP_JS", "VECTOR_CSS"]

VECTOR_CSS = """
body { font-family: system-ui, sans-serif; margin: 1em; color: #000; }
h1 { font-size: 1.2em; margin: 0 0 .3em; }
.gk-case { margin: 0 0 .4em; }
.gk-eq { font-family: "DejaVu Sans", system-ui, sans-serif; font-size: 1.1em; }
.hint { margin: 0 0 .5em; color: #444; font-size: .9em; max-width: 60em; }
.controls { display: flex; gap: .6em; align-items: center; flex-wrap: wrap; margin-bottom: .7em; }
#gk-status { min-height: 1.3em; color: #c62828; font-weight: 600; margin: .3em .5em;
             max-width: 700px; }
main { display: flex; flex-wrap: wrap; gap: 1em; align-items: flex-start; }
figure { margin: 0; border: 1px solid #ccc; }
figcaption { font-size: .85em; padding: .2em .4em; background: #f4f4f4; }
svg { display: block; width: 720px; height: 520px; touch-action: none; }
.gk-handle { cursor: grab; }
table { border-collapse: collapse; font-size: .9em; }
td, th { border: 1px solid #ccc; padding: .2em .6em; text-align: right; }
th { background: #f4f4f4; }
tr.gk-chosen td { font-weight: 700; }
td.gk-none { text-align: left; color: #c62828; }
#gk-steps { font-size: .85em; color: #333; max-width: 34em; padding-left: 1.6em; }
"""

VECTOR_APP_JS = r"""
function gkVectorApp(root, D, GK_NAME) {
"use strict";
const byId = (id) => root.querySelector("#" + id);
const NS = "http://www.w3.org/2000/svg";
const W = 720, H = 520, M = 40;
const NAMES = ["A", "B", "C"];
const ENDS = {A: ["O", "P"], B: ["P", "T"], C: ["O", "T"]};
const UID = "gk" + Math.random().toString(36).slice(2, 9) + "-";
const st = D.style;
const ink = (k, p) => (st[k] && st[k][p] !== undefined) ? st[k][p] : "#000";
const px = (lw) => 1.4 * lw;
const svg = byId("gk-vector");
svg.setAttribute("viewBox", "0 0 " + W + " " + H);
const status = byId("gk-status");
const K = D.K.slice();
const I = Object.assign({}, D.inputs);
// what is given of each vector (magnitude, angle in radians; null where unknown)
const given0 = {};
for (const n of NAMES) given0[n] = {m: D.known[n].magnitude, a: D.known[n].angle};
const copy = (g) => JSON.parse(JSON.stringify(g));
let given = copy(given0), chosen = D.chosen, res = null, sols = [], why = "";
let view = null, dragging = null;
const history = [];
// where the knobs of a line (distance from its point) and of an arc (angle) sit: display only
const knob = {};

function apply() {
  for (const h of D.handles) {
    const g = given[h.name];
    if (h.kind === "vector") { K[h.slot] = h.sign * g.m; K[h.slot + 1] = 0; I[h.theta] = g.a; }
    else if (h.kind === "direction") I[h.theta] = g.a;
    else K[h.slot] = Math.abs(g.m);
  }
}

const deg = (a) => a * (180 / Math.PI) + 0;
function wrap(a) {  // (-π, π], as graphkin's _wrap
  const t = 2 * Math.PI;
  let r = a - t * Math.round(a / t);
  if (r <= -Math.PI) r += t;
  if (r > Math.PI) r -= t;
  return r;
}
// a solution's vector in polar form, as graphkin vector reports it (VectorEquationResult.polar)
function polar(n, v) {
  const g = given[n];
  if (g.m !== null && g.a !== null) return [g.m, g.a];
  if (g.a !== null) return [v[0] * Math.cos(g.a) + v[1] * Math.sin(g.a), g.a];
  const th = Math.atan2(v[1], v[0]);
  if (g.m !== null) return [g.m, g.m >= 0 ? th : wrap(th + Math.PI)];
  return [Math.hypot(v[0], v[1]), th];
}

function solutionsOf(r) {
  return D.results.map((e, k) => {
    const p = {O: r.O || null, P: r.P || null, T: r.T || null};
    if (e.vertex) p[D.found] = r[e.vertex] || null;
    if (!p.O || !p.P || !p.T) return null;
    const out = {branch: D.branches[k] || null, vertex: e.vertex || null, points: p};
    for (const n of NAMES) {
      const a = p[ENDS[n][0]], b = p[ENDS[n][1]];
      const v = [b[0] - a[0], b[1] - a[1]], q = polar(n, v);
      out[n] = {x: v[0], y: v[1], magnitude: q[0], angle_deg: deg(q[1])};
    }
    return out;
  });
}

function fmt(v) { return Number.isFinite(v) ? Number(v.toPrecision(6)).toString() : "\u2014"; }
const known = () => NAMES.find((n) => given[n].m !== null && given[n].a !== null);
const unit = D.unit ? " " + D.unit : "";
const mag = (n) => "|" + n + "| = " + fmt(Math.abs(given[n].m));
// why an intersection has no answer, in graphkin vector's words (vector_equation._no_solution)
function whyNot(r, e) {
  const head = "case " + D.case + " has no solution: ";
  const z = known(), tol = (x) => D.tol.abs + D.tol.rel * Math.abs(x);
  if (e.op === "intersect_circles") {
    const [k1, k2] = e.inputs.map((l) => r[l]);
    const [n1, n2] = e.inputs.map((l) => D.arcs[l].name);
    const d = Math.hypot(k2[0] - k1[0], k2[1] - k1[1]), r1 = k1[2], r2 = k2[2];
    if (d <= tol(Math.max(r1, r2))) {
      return head + z + " is zero, so the arcs are concentric and the directions of " + n1 +
        " and " + n2 + " are indeterminate";
    }
    if (r1 + r2 < d) {
      return head + "the arcs do not meet: |" + n1 + "| + |" + n2 + "| = " + fmt(r1 + r2) +
        " < |" + z + "| = " + fmt(d) + " (a real solution needs |" + n1 + "| + |" + n2 +
        "| \u2265 |" + z + "|, Sec. 2.8)";
    }
    return head + "the arcs do not meet: one lies inside the other, ||" + n1 + "| - |" + n2 +
      "|| = " + fmt(Math.abs(r1 - r2)) + " > |" + z + "| = " + fmt(d);
  }
  if (e.op === "intersect_line_circle") {
    const l = r[e.inputs[0]], k = r[e.inputs[1]];
    const nl = D.lines[e.inputs[0]].name, nk = D.arcs[e.inputs[1]].name;
    if (!l) return head + "the direction of " + nl + " is not a direction";
    const dist = Math.abs(l[0] * k[0] + l[1] * k[1] + l[2]);
    return head + "the line with the direction of " + nl + " passes " + fmt(dist) +
      " from the center of the arc of radius |" + nk + "| = " + fmt(k[2]) +
      ", so they do not meet";
  }
  const [x, y] = e.inputs.map((l) => D.lines[l].name);
  const zg = given[z], ux = [Math.cos(given[x].a), Math.sin(given[x].a)];
  const zv = [zg.m * Math.cos(zg.a), zg.m * Math.sin(zg.a)];
  const off = Math.abs(zv[0] * ux[1] - zv[1] * ux[0]);
  const what = off <= tol(Math.abs(zg.m))
    ? "the lines coincide, so the magnitudes " + x + " and " + y + " are indeterminate (Sec. 2.8)"
    : "the lines are parallel but distinct, so the magnitudes " + x + " and " + y +
      " are infinite (Sec. 2.8)";
  return head + "the directions of " + x + " (" + fmt(deg(wrap(given[x].a))) + "\u00b0) and " +
    y + " (" + fmt(deg(wrap(given[y].a))) + "\u00b0) are parallel; " + what;
}

function solve() {
  apply();
  res = vectorConstruction(I, K);
  sols = res ? solutionsOf(res) : D.results.map(() => null);
  const k = sols.findIndex((s) => s === null);
  why = !res ? "the given values cannot be drawn" : (k < 0 ? "" : whyNot(res, D.results[k]));
}

// ---- drawing ----------------------------------------------------------------------------
const X = (p) => (p[0] - view.left) * view.s;
const Y = (p) => (view.top - p[1]) * view.s;
function el(parent, tag, attrs, text) {
  const e = document.createElementNS(NS, tag);
  for (const k of Object.keys(attrs)) e.setAttribute(k, attrs[k]);
  if (text !== undefined) e.textContent = text;
  parent.appendChild(e);
  return e;
}
function knobAt(h) {
  const r = res;
  if (!r || !r[h.anchor]) return null;
  const c = r[h.anchor];
  if (h.kind === "direction") {
    const a = given[h.name].a, rho = knob[h.name];
    return [c[0] + rho * Math.cos(a), c[1] + rho * Math.sin(a)];
  }
  const R = Math.abs(given[h.name].m), psi = knob[h.name];
  return [c[0] + R * Math.cos(psi), c[1] + R * Math.sin(psi)];
}
function place() {  // the knobs' first places: beyond the solutions, off the triangle
  const verts = sols.filter(Boolean).map((s) => s.points[D.found] || s.points.P);
  for (const h of D.handles) {
    if (knob[h.name] !== undefined || h.kind === "vector" || !res) continue;
    const c = res[h.anchor];
    if (h.kind === "direction") {
      let far = 0;
      for (const v of verts) far = Math.max(far, Math.hypot(v[0] - c[0], v[1] - c[1]));
      knob[h.name] = Math.max(1.15 * far, 0.6 * D.size);
    } else {
      let mx = 0, my = 0;
      for (const v of verts) { mx += v[0] / verts.length; my += v[1] / verts.length; }
      const d = [c[0] - mx, c[1] - my];
      knob[h.name] = verts.length && Math.hypot(d[0], d[1]) > 1e-9 * D.size
        ? Math.atan2(d[1], d[0]) : Math.PI / 2;
    }
  }
}
function fit() {
  const pts = [];
  for (const q of ["O", "P", "T"]) if (res && res[q]) pts.push(res[q]);
  for (const s of sols) if (s) for (const q of ["O", "P", "T"]) pts.push(s.points[q]);
  for (const h of D.handles) {
    const k = h.kind === "vector" ? null : knobAt(h);
    if (k) pts.push(k);
  }
  for (const l of Object.keys(D.arcs)) {
    const k = res && res[l];
    if (k) { pts.push([k[0] - k[2], k[1] - k[2]]); pts.push([k[0] + k[2], k[1] + k[2]]); }
  }
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const p of pts) {
    x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
    y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
  }
  if (!pts.length) { x0 = y0 = -1; x1 = y1 = 1; }
  let w = x1 - x0, h = y1 - y0;
  const big = Math.max(w, h) || 1;
  w = Math.max(w, 0.05 * big); h = Math.max(h, 0.05 * big);
  const s0 = Math.min((W - 2 * M) / w, (H - 2 * M) / h);
  const s = Number.isFinite(s0) && s0 > 0 ? s0 : 1;
  view = {s: s, left: (x0 + x1) / 2 - W / (2 * s), top: (y0 + y1) / 2 + H / (2 * s)};
}
function arrowDefs() {
  const d = el(svg, "defs", {});
  for (const [id, colour] of [["ink", ink("vector-abs", "color")],
                              ["grey", ink("vector-aux", "color")]]) {
    const m = el(d, "marker", {id: UID + id, viewBox: "0 0 10 10", refX: "10", refY: "5",
                               markerWidth: "12", markerHeight: "12", orient: "auto",
                               markerUnits: "userSpaceOnUse"});
    el(m, "path", {d: "M0,1 L10,5 L0,9 z", fill: colour});
  }
}
function vector(g, a, b, style, arrow, name, dash) {
  const attrs = {x1: X(a), y1: Y(a), x2: X(b), y2: Y(b), stroke: ink(style, "color"),
                 "stroke-width": px(ink(style, "lw")) * 1.4,
                 "marker-end": "url(#" + UID + arrow + ")"};
  if (dash) attrs["stroke-dasharray"] = "6 3";
  el(g, "line", attrs);
  // the name beside the middle, on the left of the vector
  const dx = X(b) - X(a), dy = Y(b) - Y(a), n = Math.hypot(dx, dy) || 1;
  el(g, "text", {x: (X(a) + X(b)) / 2 + 12 * dy / n - 5, y: (Y(a) + Y(b)) / 2 - 12 * dx / n + 5,
                 "font-size": "14", "font-weight": "700", fill: ink(style, "color")}, name);
}
function point(g, p, name, grey) {
  el(g, "circle", {cx: X(p), cy: Y(p), r: 3, fill: grey ? ink("aux-point", "mfc") : "#000"});
  el(g, "text", {x: X(p) + 6, y: Y(p) - 6, "font-size": "13", "font-style": "italic",
                 fill: grey ? ink("aux-point", "mfc") : "#000"}, name);
}
function draw() {
  svg.textContent = "";
  arrowDefs();
  const g = el(svg, "g", {});
  const r = res;
  if (!r) return;
  const reach = 2 * Math.hypot(W, H) / view.s;
  for (const l of Object.keys(D.lines)) {  // a line of known direction, through its point
    const ln = r[l], c = r[D.lines[l].anchor];
    if (!ln || !c) continue;
    const d = [ln[1], -ln[0]];
    el(g, "line", {x1: X([c[0] - reach * d[0], c[1] - reach * d[1]]),
                   y1: Y([c[0] - reach * d[0], c[1] - reach * d[1]]),
                   x2: X([c[0] + reach * d[0], c[1] + reach * d[1]]),
                   y2: Y([c[0] + reach * d[0], c[1] + reach * d[1]]),
                   stroke: ink("aux-line", "color"),
                   "stroke-width": px(ink("aux-line", "lw")) * 1.5});
  }
  for (const l of Object.keys(D.arcs)) {  // an arc of known magnitude, about its point
    const k = r[l];
    el(g, "circle", {cx: X(k), cy: Y(k), r: Math.max(k[2] * view.s, 0), fill: "none",
                     stroke: ink("arc", "color"), "stroke-width": px(ink("arc", "lw")) * 1.5});
  }
  // the solutions: the other one first, grey and dashed, the chosen one in ink over it
  const order = sols.map((s, k) => k).filter((k) => k !== chosen).concat([chosen]);
  for (const k of order) {
    const s = sols[k];
    if (!s) continue;
    const prime = k ? "\u2032" : "", mine = k === chosen;
    for (const n of NAMES) {
      if (given[n].m !== null && given[n].a !== null) continue;
      vector(g, s.points[ENDS[n][0]], s.points[ENDS[n][1]], mine ? "result-line" : "vector-aux",
             mine ? "ink" : "grey", n + prime, !mine);
    }
    if (D.found) point(g, s.points[D.found], D.found + prime, !mine);
  }
  for (const h of D.handles) {  // the vectors known whole
    if (h.kind !== "vector") continue;
    const [a, b] = ENDS[h.name];
    if (r[a] && r[b]) vector(g, r[a], r[b], "vector-abs", "ink", h.name, false);
  }
  for (const q of ["O", "P", "T"]) if (q !== D.found && r[q]) point(g, r[q], q, false);
  for (const h of D.handles) {
    const p = h.kind === "vector" ? r[h.end] : knobAt(h);
    if (!p) continue;
    if (h.kind !== "vector") {
      el(g, "text", {x: X(p) + 9, y: Y(p) + 16, "font-size": "12", fill: ink("aux-line", "color")},
         h.kind === "direction" ? "\u03b8_" + h.name : "|" + h.name + "|");
    }
    el(g, "circle", {cx: X(p), cy: Y(p), r: 11, fill: D.highlight, "fill-opacity": "0.18",
                     stroke: D.highlight, "stroke-opacity": "0.5", class: "gk-handle",
                     "data-handle": String(D.handles.indexOf(h))});
  }
}

// ---- the table, the choice, the status ---------------------------------------------------
const sel = byId("gk-solution");
D.branches.forEach((b, k) => {
  const o = document.createElement("option");
  o.value = String(k); o.textContent = "solution " + (k + 1) + " (" + b + ")";
  sel.appendChild(o);
});
if (!D.branches.length) sel.parentNode.style.display = "none";
function el0(parent, tag, text, cls) {
  const e = document.createElement(tag);
  if (text !== undefined) e.textContent = text;
  if (cls) e.className = cls;
  parent.appendChild(e);
  return e;
}
function table() {
  const t = byId("gk-table");
  t.textContent = "";
  const head = el0(t, "tr");
  for (const h of ["", "A", "B", "C"]) el0(head, "th", h);
  sols.forEach((s, k) => {
    const row = el0(t, "tr", undefined, k === chosen && sols.length > 1 ? "gk-chosen" : "");
    el0(row, "td", "solution " + (k + 1) + (D.branches[k] ? " (" + D.branches[k] + ")" : ""));
    if (!s) { el0(row, "td", "no solution", "gk-none").colSpan = 3; return; }
    for (const n of NAMES) {
      el0(row, "td", fmt(s[n].magnitude) + unit + " \u2220" + fmt(s[n].angle_deg) + "\u00b0");
    }
  });
}
function redraw(refit) {
  solve();
  place();
  if (refit || !view) fit();
  draw();
  table();
  sel.value = String(chosen);
  status.textContent = why;
}
const steps = byId("gk-steps");
for (const s of D.steps) el0(steps, "li", s);

// ---- dragging -------------------------------------------------------------------------------
function snapshot() {
  history.push([copy(given), chosen, Object.assign({}, knob)]);
  if (history.length > 200) history.shift();
}
function world(ev) {
  const pt = svg.createSVGPoint();
  pt.x = ev.clientX; pt.y = ev.clientY;
  const q = pt.matrixTransform(svg.getScreenCTM().inverse());
  return [view.left + q.x / view.s, view.top - q.y / view.s];
}
function dragTo(h, w) {
  const g = given[h.name];
  if (h.kind === "vector") {  // the tip: magnitude and direction from where its step starts
    const a = res[h.start];
    const d = [h.sign * (w[0] - a[0]), h.sign * (w[1] - a[1])];
    g.m = Math.hypot(d[0], d[1]);
    g.a = Math.atan2(d[1], d[0]);
    return;
  }
  const c = res[h.anchor], d = [w[0] - c[0], w[1] - c[1]], n = Math.hypot(d[0], d[1]);
  if (h.kind === "direction") {
    if (n > 1e-9 * D.size) { g.a = Math.atan2(d[1], d[0]); knob[h.name] = n; }
    return;
  }
  // an arc keeps a radius (a zero magnitude of unknown direction has no arc)
  const sign = D.known[h.name].magnitude < 0 ? -1 : 1;
  g.m = sign * Math.max(n, 1e-3 * D.size);
  if (n > 0) knob[h.name] = Math.atan2(d[1], d[0]);
}
svg.addEventListener("pointerdown", (ev) => {
  const t = ev.target;
  if (!t.classList || !t.classList.contains("gk-handle") || !res) return;
  snapshot();
  dragging = D.handles[Number(t.getAttribute("data-handle"))];
  svg.setPointerCapture(ev.pointerId);
  ev.preventDefault();
});
svg.addEventListener("pointermove", (ev) => {
  if (!dragging || !res) return;
  dragTo(dragging, world(ev));
  redraw(false);
});
const stop = () => { if (dragging) { dragging = null; redraw(true); } };
svg.addEventListener("pointerup", stop);
svg.addEventListener("pointercancel", stop);
sel.addEventListener("change", () => { snapshot(); chosen = Number(sel.value); redraw(false); });
byId("gk-undo").addEventListener("click", () => {
  const s = history.pop(); if (!s) return;
  given = s[0]; chosen = s[1];
  for (const k of Object.keys(knob)) delete knob[k];
  Object.assign(knob, s[2]);
  redraw(true);
});
byId("gk-reset").addEventListener("click", () => {
  snapshot(); given = copy(given0); chosen = D.chosen;
  for (const k of Object.keys(knob)) delete knob[k];
  redraw(true);
});

// ---- the edited file ------------------------------------------------------------------------
const tomlKey = gkTomlKey, tomlVal = gkTomlVal, isTable = gkIsTable;  // render/live_toml_js.py
function edited() {
  const f = JSON.parse(JSON.stringify(D.file));
  for (const n of NAMES) {
    const g = given[n];
    const t = isTable(f[n]) ? f[n] : (f[n] = {});
    // a part not edited is kept as the file writes it ("76.2 mm", "0.5 rad")
    if (g.m !== null && g.m !== given0[n].m) t.magnitude = g.m;
    if (g.a !== null && g.a !== given0[n].a) t.angle = deg(g.a);
  }
  if (D.branches.length && (D.fileBranch || chosen !== D.chosen)) f.branch = D.branches[chosen];
  const out = [], tables = [];
  for (const k of Object.keys(f)) {
    if (isTable(f[k]) && NAMES.indexOf(k) >= 0) tables.push(k);
    else out.push(tomlKey(k) + " = " + tomlVal(f[k]));
  }
  for (const k of tables) {
    out.push("", "[" + k + "]");
    for (const kk of Object.keys(f[k])) out.push(tomlKey(kk) + " = " + tomlVal(f[k][kk]));
  }
  return out.join("\n").replace(/^\n+/, "") + "\n";
}
byId("gk-save").addEventListener("click", () => gkDownload(edited(), GK_NAME));

redraw(true);
return {
  state: () => ({given: copy(given), chosen: chosen, result: res, solutions: sols, why: why}),
  // each handle's kind, vector and place on the screen (client coordinates: the tests drag)
  handles: () => D.handles.map((h) => {
    const p = h.kind === "vector" ? (res && res[h.end]) : knobAt(h);
    const b = svg.getBoundingClientRect();
    return {kind: h.kind, name: h.name,
            client: p ? [b.x + X(p) * b.width / W, b.y + Y(p) * b.height / H] : null};
  }),
  toClient: (p) => {
    const b = svg.getBoundingClientRect();
    return [b.x + X(p) * b.width / W, b.y + Y(p) * b.height / H];
  },
  choose: (k) => { chosen = k; redraw(false); return sols[k]; },
  toml: edited,
};
}
"""
