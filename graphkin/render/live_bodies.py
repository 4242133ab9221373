"""The free bodies of the live page: each link cut free with its forces where they act.

Fig. 11.5b-d of Uicker, Pennock & Shigley, *Theory of Machines and
Mechanisms*, 5th ed. (Sec. 11.5), drawn as ``graphkin draw -d forces`` draws
them (:mod:`graphkin.render.forces_sheet`): each moving link cut free, all to
one length scale; every force on it an arrow of one length whose head is at
its point of action, over its line of action (dashed), named and coloured as
there (joint forces ``F₂₃`` black, loads and weights blue, inertia forces
``−m₃A_G₃`` red with their offset h, Eq. 12.18, the drive green); a rough
joint's force with its normal and friction components (Fig. 11.11b, grey);
a couple or the drive's torque a turning arrow; a three-force member's
concurrency point X (Fig. 11.5e).  The script is part of the force panel's
(:data:`graphkin.render.live_forces.FORCES_APP_JS`), inside ``gkLiveApp``:
it reads the forces the page has just found (``frc``) and the panel's data
(``D.forces``: each force's anchor point ``at``, a slider's line ``slide``,
its printed name ``text``), and is redrawn on every pointer move.
"""

from __future__ import annotations

__all__ = ["BODIES_JS"]

BODIES_JS = r"""
// the free bodies (Sec. 11.5, Fig. 11.5b-d), as `draw -d forces` draws them: each moving link
// cut free, all to one length scale; every force on it an arrow of one length whose head is
// at its point of action, over its line of action (dashed), labelled in its colour; a couple
// or the drive's torque a turning arrow
const bsvg = byId("gk-bodies");
if (!D.forces || D.forces.why) bsvg.parentNode.style.display = "none";
const CW = 280, CH = 240, AL = 40, PAD = 14;  // a body's cell, an arrow's length (px)
const INERTIA_INK = D.forces && D.forces.inertia_color;
function gkSlideDir(g, r) {  // a slider's line direction, turned by its link's angle
  let t = r["\u03b8" + g.link];
  if (!Number.isFinite(t)) t = g.angle0;
  const c = Math.cos(t), s = Math.sin(t);
  const x = c * g.dir[0] - s * g.dir[1], y = s * g.dir[0] + c * g.dir[1], n = Math.hypot(x, y);
  return [x / n, y / n];
}
// where a force on a link acts: the foot of its anchor point on the line of action (a pin's
// force passes through the pin; an inertia force is offset from G by h, Eq. 12.18), or, for
// a slider, where its line of action crosses the sliding line through the slider's point
function actsAt(f, p, r) {
  const w = frc[f.label];
  if (f.along !== undefined || !Array.isArray(w) || w.length < 3) return p;
  const fx = f.sign * w[0], fy = f.sign * w[1], m = f.sign * w[2], f2 = fx * fx + fy * fy;
  const rest = m - (p[0] * fy - p[1] * fx);
  if (f.slide) {
    const u = gkSlideDir(f.slide, r), den = u[0] * fy - u[1] * fx;
    if (Math.abs(den) > 1e-9 * Math.sqrt(f2)) return [p[0] + rest / den * u[0],
                                                      p[1] + rest / den * u[1]];
  }
  return [p[0] + rest / f2 * fy, p[1] - rest / f2 * fx];
}
function turning(g, x, y, t, color, text, name, marks, d) {
  // a turning arrow of radius 13 px about (x, y), ccw for t > 0 (y is down on the screen)
  const id = arrowMark(d, marks, color), R = 13, a0 = -0.75 * Math.PI, a1 = 0.75 * Math.PI;
  const p0 = [x + R * Math.cos(a0), y - R * Math.sin(a0)];
  const p1 = [x + R * Math.cos(a1), y - R * Math.sin(a1)];
  const [s, e] = t > 0 ? [p0, p1] : [p1, p0];
  el(g, "path", {d: "M" + s[0].toFixed(2) + "," + s[1].toFixed(2) + " A" + R + "," + R +
                 " 0 1 " + (t > 0 ? 0 : 1) + " " + e[0].toFixed(2) + "," + e[1].toFixed(2),
                 fill: "none", stroke: color, "stroke-width": "1.4",
                 "marker-end": "url(#" + id + ")", class: "gk-body-torque",
                 "data-name": name, "data-sense": t > 0 ? "ccw" : "cw"});
  el(g, "text", {x: x + R + 3, y: y - R, "font-size": "12", fill: color}, text);
}
function arrowMark(d, marks, color) {
  if (!marks[color]) {
    const id = UID + "gk-body-arrow-" + Object.keys(marks).length;
    const m = el(d, "marker", {id: id, viewBox: "0 0 10 10", refX: "10", refY: "5",
                               markerWidth: "7", markerHeight: "7", orient: "auto"});
    el(m, "path", {d: "M0,1 L10,5 L0,9 z", fill: color});
    marks[color] = id;
  }
  return marks[color];
}
function drawBodies(r, stale) {
  const F = D.forces;
  bsvg.textContent = "";
  if (F.why || !frc) return;
  const lids = Object.keys(F.polygons);
  if (!lids.length) return;
  const cols = Math.min(lids.length, 3), rows = Math.ceil(lids.length / cols);
  bsvg.setAttribute("viewBox", "0 0 " + cols * CW + " " + rows * CH);
  bsvg.style.width = cols * CW + "px"; bsvg.style.height = rows * CH + "px";
  let big = 0;
  for (const lid of lids) for (const f of F.polygons[lid]) {
    const v = forceVec(f);
    if (v) big = Math.max(big, Math.hypot(v[0], v[1]));
  }
  // each body: its points, and its forces with their points of action
  const bodies = [];
  let s = Infinity;
  for (const lid of lids) {
    const pts = (D.links[lid] || []).map((n) => [n, r[n]]).filter((q) => q[1]);
    const forces = [];
    for (const f of F.polygons[lid]) {
      const v = forceVec(f), p = f.at ? r[f.at] : null;
      if (!v || !p || !(Math.hypot(v[0], v[1]) > 1e-9 * big)) continue;
      const q = actsAt(f, p, r);
      if (Number.isFinite(q[0]) && Number.isFinite(q[1])) forces.push([f, v, q]);
    }
    const all = pts.map((q) => q[1]).concat(forces.map((x) => x[2]));
    if (!all.length) continue;
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const p of all) {
      x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]);
      y0 = Math.min(y0, p[1]); y1 = Math.max(y1, p[1]);
    }
    // one length scale: every body fits its cell, with room for the arrows around it
    const room = 2 * (AL + PAD);
    if (x1 > x0) s = Math.min(s, (CW - room) / (x1 - x0));
    if (y1 > y0) s = Math.min(s, (CH - room - 16) / (y1 - y0));
    bodies.push({lid: lid, pts: pts, forces: forces, c: [(x0 + x1) / 2, (y0 + y1) / 2]});
  }
  if (!Number.isFinite(s)) s = 1;
  const d = el(bsvg, "defs", {}), marks = {};
  bodies.forEach((b, k) => {
    const ox = (k % cols) * CW, oy = Math.floor(k / cols) * CH;
    const clip = UID + "gk-body-clip-" + k;
    el(el(d, "clipPath", {id: clip}), "rect", {x: ox, y: oy, width: CW, height: CH});
    const g = el(bsvg, "g", Object.assign({class: "gk-body" + (stale ? " gk-stale" : ""),
                                           "data-link": b.lid, "clip-path": "url(#" + clip +
                                           ")"}));
    const cx = ox + CW / 2, cy = oy + (CH + 16) / 2;
    const sx = (p) => cx + (p[0] - b.c[0]) * s, sy = (p) => cy - (p[1] - b.c[1]) * s;
    el(g, "rect", {x: ox + 0.5, y: oy + 0.5, width: CW - 1, height: CH - 1, fill: "none",
                   stroke: "#ddd"});
    el(g, "text", {x: ox + 6, y: oy + 14, "font-size": "11"}, "free body of link " + b.lid);
    const xy = b.pts.map((q) => sx(q[1]).toFixed(2) + "," + sy(q[1]).toFixed(2)).join(" ");
    if (b.pts.length >= 3) {
      el(g, "polygon", {points: xy, fill: ink("plate", "fc"), stroke: ink("plate", "ec"),
                        "stroke-width": px(ink("plate", "lw"))});
    } else if (b.pts.length === 2) {
      el(g, "polyline", {points: xy, fill: "none", stroke: ink("link", "ec"),
                         "stroke-width": 2 * px(ink("link", "lw"))});
    }
    for (const [n, p] of b.pts) {
      el(g, "circle", {cx: sx(p), cy: sy(p), r: 3, fill: "#fff", stroke: "#000",
                       "stroke-width": "1.1", class: "gk-body-point", "data-name": n});
      el(g, "text", {x: sx(p) + 5, y: sy(p) + 13, "font-size": "10",
                     "font-style": "italic"}, gkPointText(n));
    }
    const X = F.concurrency[b.lid] ? frc[F.concurrency[b.lid]] : null;
    if (X && Math.abs(X[2]) > 1e-12) {  // the concurrency point of a three-force member
      const p = [X[0] / X[2], X[1] / X[2]], x = sx(p), y = sy(p);
      if (x > ox && x < ox + CW && y > oy && y < oy + CH) {
        el(g, "circle", {cx: x, cy: y, r: 2.5, fill: "#000", class: "gk-body-concurrency"});
        el(g, "text", {x: x + 5, y: y - 5, "font-size": "11", "font-style": "italic"}, "X");
      }
    }
    for (const [f, v, q] of b.forces) {
      const n = Math.hypot(v[0], v[1]), ux = v[0] / n, uy = v[1] / n;
      const hx = sx(q), hy = sy(q), tx = hx - AL * ux, ty = hy + AL * uy;
      if (f.rough) {  // a rough joint: its normal and friction components (Fig. 11.11b)
        const u = gkSlideDir(f.rough, r), t = v[0] * u[0] + v[1] * u[1];
        const comps = [[v[0] - t * u[0], v[1] - t * u[1]], [t * u[0], t * u[1]]];
        comps.forEach((c, i) => {
          if (!(Math.hypot(c[0], c[1]) > 1e-9 * n)) return;
          const x0 = hx - AL * c[0] / n, y0 = hy + AL * c[1] / n;
          el(g, "line", {x1: x0, y1: y0, x2: hx, y2: hy, stroke: F.grey, "stroke-width": "0.9",
                         "marker-end": "url(#" + arrowMark(d, marks, F.grey) + ")",
                         class: "gk-body-component", "data-name": f.name + (i ? "t" : "n")});
          el(g, "text", {x: (x0 + hx) / 2 + 4, y: (y0 + hy) / 2 - 4, "font-size": "10",
                         fill: F.grey}, f.parts[i]);
        });
      }
      if (f.color === INERTIA_INK && Math.hypot(q[0] - r[f.at][0], q[1] - r[f.at][1]) > 0) {
        // the offset h of the inertia force from G (Eq. 12.18, Fig. 12.8c)
        const G = r[f.at];
        el(g, "line", {x1: sx(G), y1: sy(G), x2: hx, y2: hy, stroke: f.color,
                       "stroke-width": "0.8", class: "gk-body-h"});
        el(g, "text", {x: (sx(G) + hx) / 2 + 3, y: (sy(G) + hy) / 2 - 3, "font-size": "10",
                       fill: f.color, "font-style": "italic"}, "h");
      }
      el(g, "line", {x1: hx - 2 * CW * ux, y1: hy + 2 * CW * uy, x2: hx + 2 * CW * ux,
                     y2: hy - 2 * CW * uy, stroke: "#7a7a7a", "stroke-width": "0.5",
                     "stroke-dasharray": "4 3", class: "gk-body-line"});
      el(g, "line", {x1: tx, y1: ty, x2: hx, y2: hy, stroke: f.color, "stroke-width": "1.6",
                     "marker-end": "url(#" + arrowMark(d, marks, f.color) + ")",
                     class: "gk-body-force", "data-name": f.name});
      // the label beside the arrow's tail, on its left
      el(g, "text", {x: tx - 12 * uy - 4, y: ty - 12 * ux + 4, "font-size": "12",
                     fill: f.color, class: "gk-body-label"}, f.text || f.name);
    }
    const torques = (F.couples[b.lid] || []).map((c) => [c, frc[c.label], null]);
    const dv = F.drives[b.lid];
    if (dv && dv.kind === "torque") torques.push([dv, frc[dv.label], dv.at ? r[dv.at] : null]);
    torques.forEach(([c, w, at], i) => {
      const t = Array.isArray(w) ? w[2] : w;
      if (!Number.isFinite(t) || t === 0) return;
      const p = at || b.c;
      turning(g, sx(p) + 30 * i, sy(p), t, c.color || F.drive_color, c.text || c.label,
              c.label, marks, d);
    });
  });
}
"""
"""The free bodies' part of the page's script (``drawBodies(r, stale)``, inside ``gkLiveApp``)."""
