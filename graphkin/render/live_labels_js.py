"""The live page's full placement of its letters, when the pointer stops (issue 29).

While a point is dragged the live page (:mod:`graphkin.render.live_app`) sets
each letter at the offset it last had, a cheap placement.  When the pointer
stops (the end of a drag, the slider let go, the first drawing, reset, undo,
a branch switched) every panel's letters are placed again by ``draw``'s rule
(:mod:`graphkin.render.labels`, Sec. 1.6 of Uicker, Pennock & Shigley, 5th
ed.: the lettering must be read as written): each letter tries the ring of
places around its point in ``draw``'s order of directions and distances, and
takes the first clean one (no drawn line, marker or other letter under its
box, inside the panel, nearer its own point than any other lettered point,
:mod:`graphkin.render.label_points`), else the best by ``draw``'s score, else
the best of a grid about its point.  Its numbers are ``draw``'s own, written
into the page from Python (:data:`RULES`), in the page's pixels: the page's
12 px letters are ``draw``'s 9 pt labels, so an inch of ``draw``'s paper is
96 px.

The live page holds some rules harder than ``draw`` (a letter on a line is
the lesser evil there too): a place where its box would overlap another
letter or a fixed text, cover another point's marker, leave the panel or
stand nearer another lettered point loses to every place that does none of
these.  The drawn lines are rasterised into a grid of 2 px cells, as
``draw``'s ink map (with its summed-area table for a crowded place's many
boxes), and every panel is measured before any letter moves (one layout), so
a page's letters are placed within a frame (``benchmarks/bench_live.py``).
"""

from __future__ import annotations

import dataclasses
import json

from graphkin.render.label_points import PRIORITY
from graphkin.render.labels import (
    _DIRS,
    _FAR_RINGS,
    _GAPS,
    _PAD,
    GRID,
    INK_WIDTH,
    RING_SPREAD,
    SCORE,
)
from graphkin.render.scene import LabelRequest
from graphkin.render.style import FONT_PT

__all__ = ["LABELS_JS", "LIVE_FONT_PX", "PX_PER_INCH", "RULES"]

LIVE_FONT_PX = 12.0
"""The size of the live page's letters (its ``label`` function), in CSS px."""
PX_PER_INCH = LIVE_FONT_PX / (FONT_PT / 72.0)
"""The page's pixels per inch of ``draw``'s paper: its letters are ``draw``'s, 12 px = 9 pt."""

_GAP = next(f.default for f in dataclasses.fields(LabelRequest) if f.name == "gap")


def _rules() -> dict[str, object]:
    """``draw``'s rules of placement in the page's pixels (screen y grows downward)."""
    px = PX_PER_INCH
    return {
        # draw's eight directions in its order, y turned down for the screen
        "dirs": [[float(dx), float(-dy)] for dx, dy in _DIRS],
        # the ring's distances from the point to the box's nearest corner or side
        "gaps": [float(_GAP * g + (RING_SPREAD * g if g > 1 else 0.0)) * px for g in _GAPS]
        + [float(r) * px for r in _FAR_RINGS],
        "pad": _PAD * px,
        "inkWidth": INK_WIDTH * px,
        "score": {"ink": SCORE["ink"], "onInk": SCORE["on_ink"], "label": SCORE["label"],
                  "out": SCORE["out"], "rank": SCORE["rank"], "astray": SCORE["astray"],
                  "grid": SCORE["grid"], "gridDistance": SCORE["grid_distance"] / px},
        "grid": {"step": GRID["step"] * px, "reach": GRID["reach"] * px,
                 "clear": GRID["clear"] * px},
        "priority": {"point": PRIORITY["label"], "vector": PRIORITY["label-vector"]},
        # anchors closer than this (px) are one point (an image at its pole), as draw's
        # coincident points are lettered together
        "same": 0.5,
        # a circle of this radius (px) or less is a point's marker, not an outline
        "marker": 6.0,
        # the ink map's cells (px): two pixels, a line counted a little wide (draw counts
        # a line INK_WIDTH, three pixels, wide), the map's table four times quicker to build
        "cell": 2.0,
    }


RULES = _rules()
"""The numbers of the placement, all from ``draw`` (:mod:`graphkin.render.labels`)."""

LABELS_JS = "const GK_LABEL_RULES = " + json.dumps(RULES) + ";\n" + r"""
// the drawn ink of a panel (its lines, outlines, markers, arrowheads and fixed texts) on a
// grid of cells (GK_LABEL_RULES.cell px), counted under a box cell by cell or, for many
// boxes, by its summed-area table; markers and fixed texts also as shapes
function gkLabelInk(svg, W, H) {
  const R = GK_LABEL_RULES, C = R.cell, nx = Math.ceil(W / C), ny = Math.ceil(H / C);
  const ink = new Uint8Array(nx * ny), markers = [], fixed = [];
  const cell = (x, y) => {
    const i = Math.floor(x / C), j = Math.floor(y / C);
    if (i >= 0 && i < nx && j >= 0 && j < ny) ink[j * nx + i] = 1;
  };
  // the range of t in [t0, t1] where a + t d lies in [lo, hi] (Liang-Barsky), or null
  const slab = (a, d, lo, hi, t0, t1) => {
    if (d === 0) return a < lo || a > hi ? null : [t0, t1];
    let u = (lo - a) / d, v = (hi - a) / d;
    if (u > v) { const w = u; u = v; v = w; }
    u = Math.max(u, t0); v = Math.min(v, t1);
    return u <= v ? [u, v] : null;
  };
  const seg = (x0, y0, x1, y1) => {
    // clipped to the panel: a Kennedy line runs far beyond it
    const dx = x1 - x0, dy = y1 - y0;
    const tx = slab(x0, dx, -1, W + 1, 0, 1), t = tx && slab(y0, dy, -1, H + 1, tx[0], tx[1]);
    if (!t) return;
    const ax = (x0 + t[0] * dx) / C, ay = (y0 + t[0] * dy) / C;
    const n = Math.max(1, Math.ceil(2 * (t[1] - t[0]) * Math.hypot(dx, dy) / C));
    const sx = (t[1] - t[0]) * dx / C / n, sy = (t[1] - t[0]) * dy / C / n;
    for (let k = 0; k <= n; k++) {
      const i = Math.floor(ax + sx * k), j = Math.floor(ay + sy * k);
      if (i >= 0 && i < nx && j >= 0 && j < ny) ink[j * nx + i] = 1;
    }
  };
  const fill = (x0, y0, x1, y1) => {
    const i0 = Math.max(Math.floor(x0 / C), 0), i1 = Math.min(Math.ceil(x1 / C), nx);
    const j0 = Math.max(Math.floor(y0 / C), 0), j1 = Math.min(Math.ceil(y1 / C), ny);
    for (let j = j0; j < j1; j++) for (let i = i0; i < i1; i++) ink[j * nx + i] = 1;
  };
  const head = (x0, y0, x1, y1, sw) => {  // an arrowhead at (x1, y1): a filled triangle
    const d = Math.hypot(x1 - x0, y1 - y0);
    if (!(d > 0)) return;
    const L = 7 * sw, ux = (x1 - x0) / d, uy = (y1 - y0) / d;
    for (let k = 0; k <= 4; k++) {
      const t = k / 4, cx = x1 - ux * L * t, cy = y1 - uy * L * t, hw = 0.4 * L * t;
      seg(cx - uy * hw, cy + ux * hw, cx + uy * hw, cy - ux * hw);
    }
  };
  const num = (e, a, d) => { const v = parseFloat(e.getAttribute(a)); return isFinite(v) ? v : d; };
  const drawn = "line, polyline, polygon, circle, path, rect, ellipse, text";
  for (const e of svg.querySelectorAll(drawn)) {
    if (e.closest("defs, marker, clipPath")) continue;
    const tag = e.tagName.toLowerCase(), cls = e.classList;
    if (cls.contains("gk-label") || cls.contains("gk-handle")) continue;
    const sw = num(e, "stroke-width", 1);
    if (tag === "text") {
      const b = e.getBBox();
      if (b.width > 0) {
        fixed.push([b.x - 1, b.y - 1, b.x + b.width + 1, b.y + b.height + 1]);
        fill(b.x, b.y, b.x + b.width, b.y + b.height);
      }
    } else if (tag === "line") {
      const x0 = num(e, "x1", 0), y0 = num(e, "y1", 0), x1 = num(e, "x2", 0), y1 = num(e, "y2", 0);
      seg(x0, y0, x1, y1);
      if (e.getAttribute("marker-end")) head(x0, y0, x1, y1, sw);
      if (e.getAttribute("marker-start")) head(x1, y1, x0, y0, sw);
    } else if (tag === "polyline" || tag === "polygon") {
      const v = (e.getAttribute("points") || "").trim().split(/[\s,]+/).map(Number);
      const n = Math.floor(v.length / 2);
      for (let k = 1; k < n; k++) seg(v[2 * k - 2], v[2 * k - 1], v[2 * k], v[2 * k + 1]);
      if (tag === "polygon" && n > 2) seg(v[2 * n - 2], v[2 * n - 1], v[0], v[1]);
    } else if (tag === "circle") {
      const x = num(e, "cx", 0), y = num(e, "cy", 0), r = num(e, "r", 0);
      if (r <= R.marker) {  // a point's marker: a disc
        const rr = r + sw / 2;
        markers.push([x, y, rr]);
        for (let j = Math.floor((y - rr) / C); j * C <= y + rr; j++) {
          for (let i = Math.floor((x - rr) / C); i * C <= x + rr; i++) {
            // the cell touches the disc
            const qx = Math.min(Math.max(x, i * C), (i + 1) * C);
            const qy = Math.min(Math.max(y, j * C), (j + 1) * C);
            if ((qx - x) ** 2 + (qy - y) ** 2 <= rr * rr) cell((i + 0.5) * C, (j + 0.5) * C);
          }
        }
      } else {
        const n = Math.min(720, Math.max(16, Math.ceil(2 * Math.PI * r / 3)));
        for (let k = 0; k < n; k++) {
          const a = 2 * Math.PI * k / n, b = 2 * Math.PI * (k + 1) / n;
          seg(x + r * Math.cos(a), y + r * Math.sin(a), x + r * Math.cos(b), y + r * Math.sin(b));
        }
      }
    } else {  // a frame's ground triangle, a body's outline: its box
      const b = e.getBBox();
      fill(b.x - sw / 2, b.y - sw / 2, b.x + b.width + sw / 2, b.y + b.height + sw / 2);
    }
  }
  // the summed-area table, built only for a crowded place's grid (many boxes): a few boxes
  // are quicker counted cell by cell
  let S = null, boxes = 0;
  const table = () => {
    S = new Int32Array((nx + 1) * (ny + 1));
    for (let j = 0; j < ny; j++) {
      let row = 0;
      for (let i = 0; i < nx; i++) {
        row += ink[j * nx + i];
        S[(j + 1) * (nx + 1) + i + 1] = S[j * (nx + 1) + i + 1] + row;
      }
    }
  };
  const clamp = (v, hi) => (v < 0 ? 0 : (v > hi ? hi : v));
  // the length (px) of ink under a box: its inked cells, each a cell's width of line
  const under = (x0, y0, x1, y1) => {
    const i0 = clamp(Math.floor(x0 / C), nx), i1 = clamp(Math.ceil(x1 / C), nx);
    const j0 = clamp(Math.floor(y0 / C), ny), j1 = clamp(Math.ceil(y1 / C), ny);
    if (i1 <= i0 || j1 <= j0) return 0;
    if (S === null && ++boxes > 300) table();
    if (S === null) {
      let c = 0;
      for (let j = j0; j < j1; j++) for (let i = i0; i < i1; i++) c += ink[j * nx + i];
      return C * c;
    }
    const w = nx + 1;
    return C * (S[j1 * w + i1] - S[j0 * w + i1] - S[j1 * w + i0] + S[j0 * w + i0]);
  };
  return {under: under, markers: markers, fixed: fixed};
}

// every letter of the panels (name -> svg; text.gk-label, data-ax/-ay its point, data-point
// "1" a lettered point) placed by draw's rule; returns, by panel, each letter's offset from
// its point and its text-anchor, by its text (the cheap placement while dragging); a panel
// not laid out (hidden)
// is left out. Every panel is measured before any letter moves: one layout, not one a panel
function gkPlaceLabels(svgs, W, H) {
  const got = {}, out = {};
  for (const k of Object.keys(svgs)) got[k] = gkMeasureLabels(svgs[k], W, H);
  for (const k of Object.keys(got)) if (got[k]) out[k] = gkPlaceMeasured(got[k], W, H);
  return out;
}

// a panel's letters' boxes (the browser's getBBox) and its ink, or null
function gkMeasureLabels(svg, W, H) {
  const R = GK_LABEL_RULES;
  const texts = svg.querySelectorAll("text.gk-label");
  if (!texts.length) return null;
  const labs = [];
  for (const t of texts) {
    const b = t.getBBox();
    if (!(b.width > 0 && b.height > 0)) return null;  // a hidden panel: not laid out
    const x = parseFloat(t.getAttribute("x")), y = parseFloat(t.getAttribute("y"));
    const point = t.getAttribute("data-point") === "1";
    labs.push({t: t, ax: parseFloat(t.getAttribute("data-ax")),
               ay: parseFloat(t.getAttribute("data-ay")), point: point,
               dx: b.x - x, dy: b.y - y, bw: b.width, bh: b.height,
               w: b.width + 2 * R.pad, h: b.height + 2 * R.pad,
               pri: point ? R.priority.point : R.priority.vector, i: labs.length});
  }
  return {labs: labs, ink: gkLabelInk(svg, W, H)};
}

// the letters of a measured panel placed, as draw places its labels (render/labels.py _spot)
function gkPlaceMeasured(m, W, H) {
  const R = GK_LABEL_RULES, S = R.score, labs = m.labs, ink = m.ink;
  // the lettered points, coincident ones once
  const pts = [];
  for (const L of labs) {
    if (!L.point || !isFinite(L.ax) || !isFinite(L.ay)) continue;
    if (!pts.some((p) => Math.hypot(p[0] - L.ax, p[1] - L.ay) <= R.same)) pts.push([L.ax, L.ay]);
  }
  const placed = ink.fixed.slice(), out = {};
  labs.sort((a, b) => a.pri - b.pri || a.i - b.i);
  for (const L of labs) {
    if (!isFinite(L.ax) || !isFinite(L.ay)) continue;
    // a point off the panel (an axis's tip, a far center): its letter placed about the
    // panel's nearest point to it, as near it as the panel lets it be, and no other point's
    const on = L.ax >= 0 && L.ax <= W && L.ay >= 0 && L.ay <= H;
    const ax = Math.min(Math.max(L.ax, 0), W), ay = Math.min(Math.max(L.ay, 0), H);
    const w = L.w, h = L.h, area = w * h;
    const others = L.point && on ?
      pts.filter((p) => Math.hypot(p[0] - ax, p[1] - ay) > R.same) : [];
    // a box attached to its point: nearer it, edge to point, than to any other (draw's
    // fallback where no clear place has its centre nearer its point)
    const gapTo = (cx, cy, p) => Math.hypot(Math.max(Math.abs(cx - p[0]) - w / 2, 0),
                                            Math.max(Math.abs(cy - p[1]) - h / 2, 0));
    // a place's score by draw's weights, under each reading of "nearer its own point": by
    // the box's centre ([0]) and, where no place has that, by the box's edge ([1]); a place
    // that breaks a hard rule loses to every place that breaks none (level 2: on a letter,
    // another point's marker or off the panel; level 1: nearer another point, which points a
    // few pixels apart cannot help)
    const evaluate = (cx, cy, extra) => {
      const x0 = cx - w / 2, y0 = cy - h / 2, x1 = cx + w / 2, y1 = cy + h / 2;
      let inked = ink.under(x0, y0, x1, y1), other = false;
      for (const m of ink.markers) {
        const qx = Math.min(Math.max(m[0], x0), x1), qy = Math.min(Math.max(m[1], y0), y1);
        if ((qx - m[0]) ** 2 + (qy - m[1]) ** 2 < m[2] * m[2]) {
          if (!inked) inked = 1;
          if (Math.hypot(m[0] - ax, m[1] - ay) > R.same) other = true;
        }
      }
      let lab = 0;
      for (const q of placed) {
        const ox = Math.min(x1, q[2]) - Math.max(x0, q[0]);
        const oy = Math.min(y1, q[3]) - Math.max(y0, q[1]);
        if (ox > 0 && oy > 0) lab += ox * oy;
      }
      lab /= area;
      const ix = Math.max(Math.min(x1, W) - Math.max(x0, 0), 0);
      const iy = Math.max(Math.min(y1, H) - Math.max(y0, 0), 0);
      const off = 1 - ix * iy / area;
      let byCentre = false, byBox = false;
      if (others.length) {
        const own = Math.hypot(cx - ax, cy - ay), ownBox = gapTo(cx, cy, [ax, ay]);
        for (const p of others) {
          if (!byCentre && Math.hypot(cx - p[0], cy - p[1]) < own) byCentre = true;
          if (!byBox && gapTo(cx, cy, p) < ownBox) byBox = true;
          if (byCentre && byBox) break;
        }
      }
      const base = S.ink * inked * R.inkWidth / area + (inked ? S.onInk : 0) + S.label * lab +
        S.out * off + extra;
      const hard = lab > 0 || off > 1e-12 || other;
      return [byCentre, byBox].map((astray) => {
        const level = hard ? 2 : (astray ? 1 : 0);
        return {score: base + (astray ? S.astray : 0) + 1000 * level, level: level,
                clean: !level && !inked};
      });
    };
    // draw's ring: its directions at its distances, box corner or side that far from the point
    const ring = [];
    for (const g of R.gaps) {
      for (const d of R.dirs) {
        const n = Math.hypot(d[0], d[1]);
        ring.push([ax + d[0] / n * g + d[0] * w / 2, ay + d[1] / n * g + d[1] * h / 2]);
      }
    }
    // the ring in rank order up to its first clean place: the best score of that prefix
    const sc = [];
    for (let k = 0; k < ring.length; k++) {
      sc.push(evaluate(ring[k][0], ring[k][1], S.rank * k));
      if (sc[k][0].clean) break;
    }
    const cand = [0, 1].map((r) => {
      let j = 0, first = sc.findIndex((e) => e[r].clean);
      if (first < 0) first = sc.length - 1;
      for (let k = 1; k <= first; k++) if (sc[k][r].score < sc[j][r].score - 1e-12) j = k;
      return {c: ring[j], e: sc[j][r]};
    });
    if (!cand[0].e.clean) {
      // a crowded place: a grid about the point, wider until a place breaks no hard rule
      let inner = -1;
      for (let wide = 1; wide <= (on ? 2 : 1); wide *= 2) {
        const reach = wide * (R.grid.reach + Math.max(w, h)), st = R.grid.step;
        for (let gy = -reach; gy <= reach + 1e-9; gy += st) {
          for (let gx = -reach; gx <= reach + 1e-9; gx += st) {
            const dist = Math.hypot(gx, gy);
            if (dist > reach || dist <= inner || (Math.abs(gx) < w / 2 + R.grid.clear &&
                                                   Math.abs(gy) < h / 2 + R.grid.clear)) {
              continue;
            }
            const e = evaluate(ax + gx, ay + gy, S.grid + S.gridDistance * dist);
            for (const r of [0, 1]) {
              if (e[r].score < cand[r].e.score - 1e-12) cand[r] = {c: [ax + gx, ay + gy], e: e[r]};
            }
          }
        }
        if (!cand[0].e.level || !cand[1].e.level) break;
        inner = reach;
      }
    }
    const best = cand[1].e.level < cand[0].e.level ? cand[1] : cand[0];
    const c = best.c;
    const x = c[0] - L.bw / 2 - L.dx, y = c[1] - L.bh / 2 - L.dy;
    L.t.setAttribute("x", x.toFixed(2));
    L.t.setAttribute("y", y.toFixed(2));
    placed.push([c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2]);
    out[L.t.textContent] = [x - L.ax, y - L.ay, L.t.getAttribute("text-anchor")];
  }
  return out;
}
"""
