"""The whole cycle in motion: one self-contained HTML page drawn from a sweep.

``graphkin animate FILE -o cycle.html`` sweeps the mechanism through its cycle
(:meth:`graphkin.mechanisms.model.Mechanism.sweep`: the same constructions as
one posture, evaluated on arrays) and writes one HTML page where the
mechanism turns, with its velocity and acceleration polygons redrawn at every
posture to scale (and, on request, the instant centers and the inflection
circle).  Play/pause, a slider for the drive, step ±1, speed; the current ω,
α and a chosen point's velocity and acceleration printed beside the drawing;
the ranges where the linkage cannot be assembled and the limit and
dead-center postures marked on the slider (and skipped while playing).

The page is light: the postures are data (JSON of coordinates, each series
stored as integers of a stated quantum), drawn by a small inline script into
SVG — not one picture per frame.  No network is needed.

The polygons are drawn from the pole: the image of each named point is the
tip of its absolute velocity (acceleration) vector, and the image of each
link joins the images of its points — similar to the link (Sec. 3.4, 4.4).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (velocity polygons and images),
Sec. 4.4 (acceleration polygons), Sec. 3.13 (instant centers), Sec. 4.15
(the inflection circle), Sec. 1.10 (limit and dead-center postures).
"""

from __future__ import annotations

import html
from typing import Any

from graphkin.errors import InputError
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.render.cycle_data import QUANTUM, cycle_data
from graphkin.render.style import STYLES
from graphkin.text import script_json

__all__ = ["cycle_data", "animate_html", "QUANTUM"]



_CSS = """
* { box-sizing: border-box; }
body { margin: 0; font: 15px/1.4 "DejaVu Sans", Verdana, sans-serif; color: #111;
       background: #fafafa; }
header { padding: 6px 14px; background: #fff; border-bottom: 1px solid #ddd; }
header h1 { font-size: 16px; margin: 0; }
header .held { margin: 2px 0 0; font-size: 13px; color: #555; }
.controls { display: flex; flex-wrap: wrap; align-items: center; gap: 8px; padding: 6px 14px;
            background: #fff; border-bottom: 1px solid #ddd; }
.controls button, .controls select { font: inherit; padding: 2px 10px; }
#slider-wrap { position: relative; flex: 1 1 320px; min-width: 240px; height: 34px; }
#drive { width: 100%; margin: 0; position: absolute; top: 0; }
#marks { position: absolute; left: 0; right: 0; top: 22px; height: 10px; }
#marks .bad { position: absolute; height: 8px; background: #c62828; opacity: 0.7; }
#marks .tick { position: absolute; width: 2px; height: 10px; background: #1565c0; }
#drive-text { min-width: 9em; font-variant-numeric: tabular-nums; }
#status { color: #c62828; min-width: 12em; }
main { display: grid; grid-template-columns: 1.3fr 1fr 1fr 230px; gap: 8px; padding: 8px;
       align-items: start; }
figure { margin: 0; background: #fff; border: 1px solid #ddd; border-radius: 4px;
         display: flex; flex-direction: column; min-width: 0; }
figcaption { font-weight: bold; font-size: 14px; padding: 4px 8px; }
figure svg { width: 100%; height: calc(100vh - 170px); min-height: 240px; }
#values { font-size: 14px; background: #fff; border: 1px solid #ddd; border-radius: 4px;
          padding: 6px 10px; font-variant-numeric: tabular-nums; }
#values table { border-collapse: collapse; width: 100%; }
#values td { padding: 1px 4px; }
#values td.v { text-align: right; }
.scale { font-size: 12px; color: #444; padding: 2px 8px 6px; }
@media (max-width: 1000px) { main { grid-template-columns: 1fr 1fr; } }
"""

_JS = r"""
(function () {
  var D = JSON.parse(document.getElementById('cycle-data').textContent);
  function esc(s) {  // text of the file's (names, units) as HTML text
    return String(s).replace(/[&<>"']/g, function (c) {
      return {'&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;'}[c];
    });
  }
  var NS = 'http://www.w3.org/2000/svg';
  var errors = [];
  window.addEventListener('error', function (e) { errors.push(String(e.message)); });
  var n = D.n, cur = 0, playing = false, speed = 1, acc = 0, last = null;
  var sense = D.sense === -1 ? -1 : 1;
  var slider = document.getElementById('drive');
  var valid = D.valid, rvalid = D.rated_valid;
  function val(s, q, i) { var v = s[i]; return v === null || v === undefined ? NaN : v * q; }
  function P(name, i) {
    var p = D.points[name];
    return [val(p.x, D.q.L, i), val(p.y, D.q.L, i)];
  }
  function img(name, i, kind) {
    var p = D.points[name];
    if (kind === 'velocity') return [val(p.vx, D.q.V, i), val(p.vy, D.q.V, i)];
    return [val(p.ax, D.q.A, i), val(p.ay, D.q.A, i)];
  }
  function ok(xy) { return isFinite(xy[0]) && isFinite(xy[1]); }
  function el(parent, tag, attrs, text) {
    var e = document.createElementNS(NS, tag);
    for (var k in attrs) { e.setAttribute(k, attrs[k]); }
    if (text !== undefined) e.textContent = text;
    parent.appendChild(e);
    return e;
  }
  function setup(svg, view) {
    var w = view[2] - view[0], h = view[3] - view[1];
    svg.setAttribute('viewBox', view[0] + ' ' + (-view[3]) + ' ' + w + ' ' + h);
    return Math.max(w, h);
  }
  var mechSvg = document.getElementById('mechanism');
  var S = setup(mechSvg, D.view);
  var polys = {};
  ['velocity', 'acceleration'].forEach(function (k) {
    var svg = document.getElementById(k);
    if (svg && D[k]) polys[k] = {svg: svg, size: setup(svg, D[k].view)};
  });
  var layer = {}, kind0 = 'velocity';
  var fit = document.getElementById('fit');
  function clear(svg) { while (svg.lastChild) svg.removeChild(svg.lastChild); }
  function line(g, a, b, cls, w) {
    if (!ok(a) || !ok(b)) return null;
    return el(g, 'line', {x1: a[0], y1: -a[1], x2: b[0], y2: -b[1], 'class': cls,
                          'stroke-width': w});
  }
  // labels at draw's size on the screen (render/style.py), each where it overlaps no label
  // placed before it in the same picture: its usual place first, then around its point
  var placed = [];
  function upp(svg) {  // view units per screen pixel (the picture keeps its aspect)
    var r = svg.getBoundingClientRect(), vb = svg.viewBox && svg.viewBox.baseVal;
    if (!vb || !(r.width > 0) || !(r.height > 0) || !(vb.width > 0)) return null;
    return Math.max(vb.width / r.width, vb.height / r.height);
  }
  function fontFor(svg, fallback, px) {
    var u = upp(svg);
    return u ? (px || D.label_px) * u : fallback;
  }
  var AROUND = [[1, 1], [1, -1], [-1, 1], [-1, -1], [1, 0], [-1, 0], [0, 1], [0, -1]];
  var bounds = null;  // what the picture shows (view units, y up), set before its letters
  function shown(svg) {
    var u = upp(svg), r = svg.getBoundingClientRect(), vb = svg.viewBox.baseVal;
    if (!u) return null;
    var cx = vb.x + vb.width / 2, cy = vb.y + vb.height / 2;
    var hw = r.width * u / 2, hh = r.height * u / 2;
    return [cx - hw, -(cy + hh), cx + hw, -(cy - hh)];
  }
  function overlap(b) {  // how much of the box ``b`` other letters cover (or off the picture)
    var sum = 0;
    if (bounds && (b[0] < bounds[0] || b[1] < bounds[1] || b[2] > bounds[2] ||
                   b[3] > bounds[3])) sum += 1e300;
    placed.forEach(function (q) {
      var ox = Math.min(b[2], q[2]) - Math.max(b[0], q[0]);
      var oy = Math.min(b[3], q[3]) - Math.max(b[1], q[1]);
      if (ox > 0 && oy > 0) sum += ox * oy;
    });
    return sum;
  }
  function label(g, xy, text, size, cls, dx, dy) {
    if (!ok(xy)) return;
    // the box as the browser lays the text out: from the descent below the baseline to the
    // ascent above it (DejaVu Sans: about 0.24 and 0.93 of the size)
    var w = size * 0.66 * String(text).length + size * 0.15, h = size * 1.25;
    var x0 = dx || size * 0.35, y0 = dy || size * 0.35, best = null, least = Infinity;
    // its usual place, then rings around the point, farther out where it is crowded
    var tries = [[x0, y0]];
    [0.45, 1.2, 2.2, 3.4].forEach(function (r) {
      AROUND.forEach(function (d) {
        tries.push([d[0] * size * r + (d[0] < 0 ? -w : d[0] === 0 ? -w / 2 : 0),
                    d[1] * size * r + (d[1] < 0 ? -h : d[1] === 0 ? -h * 0.4 : 0)]);
      });
    });
    for (var k = 0; k < tries.length; k++) {
      var b = [xy[0] + tries[k][0], xy[1] + tries[k][1] - size * 0.27,
               xy[0] + tries[k][0] + w, xy[1] + tries[k][1] + size * 0.98];
      var o = overlap(b);
      if (o < least) { best = b; least = o; }
      if (o === 0) break;
    }
    placed.push(best);
    el(g, 'text', {x: best[0], y: -(best[1] + size * 0.27), 'font-size': size,
                   'class': cls || 'lbl'}, text);
  }
  function arrow(g, a, b, w, color, cls) {
    if (!ok(a) || !ok(b)) return;
    var dx = b[0] - a[0], dy = b[1] - a[1], L = Math.sqrt(dx * dx + dy * dy);
    if (!(L > 0)) return;
    var h = Math.min(w * 7, L * 0.4), ux = dx / L, uy = dy / L;
    var bx = b[0] - ux * h, by = b[1] - uy * h;
    el(g, 'line', {x1: a[0], y1: -a[1], x2: bx, y2: -by, stroke: color,
                   'stroke-width': w, 'class': cls || 'vec'});
    var px = -uy * h * 0.35, py = ux * h * 0.35;
    el(g, 'polygon', {points: b[0] + ',' + (-b[1]) + ' ' + (bx + px) + ',' + (-(by + py)) +
                      ' ' + (bx - px) + ',' + (-(by - py)), fill: color});
  }
  function drawMechanism(i) {
    clear(mechSvg);
    placed = [];
    bounds = shown(mechSvg);
    var w = S / 300, fs = S / 28, fl = fontFor(mechSvg, fs);
    var g = el(mechSvg, 'g', {id: 'mech-layer'});
    D.guides.forEach(function (gd) {
      if (gd.kind === 'line') {
        var a0 = [val(gd.x0, D.q.L, i), val(gd.y0, D.q.L, i)];
        var a1 = [val(gd.x1, D.q.L, i), val(gd.y1, D.q.L, i)];
        line(g, a0, a1, 'guide', w * (gd.surface ? 1.5 : 1));
        (gd.arms || []).forEach(function (p) {
          var q = P(p, i); if (!ok(q) || !ok(a0) || !ok(a1)) return;
          var ux = a1[0] - a0[0], uy = a1[1] - a0[1], L2 = ux * ux + uy * uy;
          var t = ((q[0] - a0[0]) * ux + (q[1] - a0[1]) * uy) / L2;
          var f = [a0[0] + t * ux, a0[1] + t * uy];
          el(g, 'line', {x1: q[0], y1: -q[1], x2: f[0], y2: -f[1], stroke: '#111',
                         'stroke-width': w * 4, 'stroke-linecap': 'round', 'data-arm': p});
        });
      } else {
        var c = [val(gd.cx, D.q.L, i), val(gd.cy, D.q.L, i)];
        if (ok(c)) el(g, 'circle', {cx: c[0], cy: -c[1], r: gd.r * D.q.L, 'class': 'guide',
                                    fill: 'none', 'stroke-width': w});
      }
    });
    D.frame.forEach(function (p) {
      var xy = P(p, i); if (!ok(xy)) return;
      var s = fs * 0.6;
      el(g, 'polygon', {points: xy[0] + ',' + (-xy[1]) + ' ' + (xy[0] - s * 0.6) + ',' +
                        (-xy[1] + s) + ' ' + (xy[0] + s * 0.6) + ',' + (-xy[1] + s),
                        fill: '#fff', stroke: '#111', 'stroke-width': w});
      el(g, 'line', {x1: xy[0] - s, y1: -xy[1] + s, x2: xy[0] + s, y2: -xy[1] + s,
                     stroke: '#111', 'stroke-width': w * 1.5});
    });
    D.wheels.forEach(function (wh) {
      var c = P(wh.point, i); if (!ok(c)) return;
      el(g, 'circle', {cx: c[0], cy: -c[1], r: wh.r * D.q.L, fill: '#eef3fa', stroke: '#111',
                       'stroke-width': w});
    });
    (D.bodies || []).forEach(function (bd) {  // a cam's profile, a roller, a face
      var o = [val(bd.ox, D.q.L, i), val(bd.oy, D.q.L, i)], a = val(bd.angle, 1e-4, i);
      if (!ok(o) || !isFinite(a)) return;
      var c = Math.cos(a * Math.PI / 180), s = Math.sin(a * Math.PI / 180);
      var xy = bd.local.map(function (q) {
        return [o[0] + c * q[0] - s * q[1], o[1] + s * q[0] + c * q[1]]; });
      if (bd.kind === 'circle') {
        el(g, 'circle', {cx: xy[0][0], cy: -xy[0][1], r: bd.r, fill: '#eef3fa',
                         stroke: '#111', 'stroke-width': w, 'data-body': bd.link});
      } else if (bd.kind === 'outline') {
        el(g, 'polygon', {points: xy.map(function (q) { return q[0] + ',' + (-q[1]); })
                          .join(' '), fill: '#eef3fa', stroke: '#111', 'stroke-width': w,
                          'stroke-linejoin': 'round', 'data-body': bd.link});
      } else {
        el(g, 'line', {x1: xy[0][0], y1: -xy[0][1], x2: xy[1][0], y2: -xy[1][1],
                       stroke: '#111', 'stroke-width': w * 3, 'data-body': bd.link});
      }
    });
    D.links.forEach(function (lk) {
      var xy = lk.points.map(function (p) { return P(p, i); });
      if (!xy.every(ok)) return;
      if (lk.shape === 'plate') {
        el(g, 'polygon', {points: xy.map(function (q) { return q[0] + ',' + (-q[1]); }).join(' '),
                          fill: lk.fill, stroke: '#111', 'stroke-width': w * 1.5,
                          'stroke-linejoin': 'round', 'data-link': lk.id});
      } else if (lk.shape === 'bar') {
        el(g, 'line', {x1: xy[0][0], y1: -xy[0][1], x2: xy[1][0], y2: -xy[1][1],
                       stroke: '#111', 'stroke-width': w * 6, 'stroke-linecap': 'round',
                       'data-link': lk.id});
        el(g, 'line', {x1: xy[0][0], y1: -xy[0][1], x2: xy[1][0], y2: -xy[1][1],
                       stroke: lk.fill, 'stroke-width': w * 4, 'stroke-linecap': 'round'});
      }
    });
    D.blocks.forEach(function (b) {
      var c = P(b.point, i); if (!ok(c)) return;
      var a = val(b.angle, 1e-3, i), s = fs * 0.9;
      el(g, 'rect', {x: c[0] - s, y: -c[1] - s * 0.6, width: 2 * s, height: 1.2 * s,
                     fill: '#fff', stroke: '#111', 'stroke-width': w * 1.5,
                     transform: 'rotate(' + (-a) + ' ' + c[0] + ' ' + (-c[1]) + ')'});
    });
    Object.keys(D.points).forEach(function (p) {
      var xy = P(p, i); if (!ok(xy)) return;
      var pin = D.pins.indexOf(p) >= 0;
      el(g, 'circle', {cx: xy[0], cy: -xy[1], r: pin ? fs * 0.22 : fs * 0.14,
                       fill: pin ? '#fff' : '#111', stroke: '#111', 'stroke-width': w,
                       'data-point': p});
      label(g, xy, p, fl, 'lbl');
    });
    if (D.centers && document.getElementById('show-centers') &&
        document.getElementById('show-centers').checked) {
      Object.keys(D.centers).forEach(function (c) {
        var xy = [val(D.centers[c].x, D.q.L, i), val(D.centers[c].y, D.q.L, i)];
        if (!ok(xy)) return;
        el(g, 'circle', {cx: xy[0], cy: -xy[1], r: fs * 0.15, fill: '#1565c0',
                         'data-center': c});
        label(g, xy, c, fontFor(mechSvg, fs * 0.55, D.small_px), 'ic');
      });
    }
    if (D.inflection && document.getElementById('show-inflection') &&
        document.getElementById('show-inflection').checked) {
      Object.keys(D.inflection).forEach(function (k) {
        var ci = D.inflection[k];
        var c = [val(ci.cx, D.q.L, i), val(ci.cy, D.q.L, i)], r = val(ci.r, D.q.L, i);
        if (!ok(c) || !isFinite(r)) return;
        el(g, 'circle', {cx: c[0], cy: -c[1], r: r, fill: 'none', stroke: '#2e7d32',
                         'stroke-width': w, 'stroke-dasharray': (w * 6) + ' ' + (w * 4),
                         'data-inflection': k});
        var j = [val(ci.jx, D.q.L, i), val(ci.jy, D.q.L, i)];
        label(g, j, 'J' + k, fontFor(mechSvg, fs * 0.7, D.small_px), 'inf');
      });
    }
  }
  function drawPolygon(kind, i) {
    var pg = polys[kind]; if (!pg) return;
    var svg = pg.svg; clear(svg);
    placed = [];
    var sc = D[kind].scale, v = D[kind].view;
    var xs = [0], ys = [0];
    Object.keys(D.points).forEach(function (p) {
      var q = img(p, i, kind); if (ok(q)) { xs.push(q[0]); ys.push(q[1]); }
    });
    var x0 = Math.min.apply(null, xs), x1 = Math.max.apply(null, xs);
    var y0 = Math.min.apply(null, ys), y1 = Math.max.apply(null, ys);
    // one scale for the cycle, except where a posture's polygon outgrows it (the cycle's
    // view holds most postures, not the few largest): that posture at its own scale
    var outgrows = x0 < v[0] || x1 > v[2] || y0 < v[1] || y1 > v[3];
    if ((fit && fit.checked) || outgrows) {  // the posture's polygon at a round scale that fits
      var span = Math.max(x1 - x0, y1 - y0, 1e-12), m = span * 0.12;
      v = [x0 - m, y0 - m - span * 0.1, x0 + span + m, y0 + span + m];
      pg.size = setup(svg, v);
      kind0 = kind; sc = nice(span / 4);
    } else {
      pg.size = setup(svg, D[kind].view);
    }
    var S2 = pg.size, w = S2 / 300, fs = S2 / 22, fl = fontFor(svg, fs);
    bounds = shown(svg);
    var g = el(svg, 'g', {id: kind + '-layer'});
    var prime = kind === 'acceleration' ? '′' : '';
    // the scale bar's text and the pole's letter first: the images' letters keep off them
    var y = v[1] + (v[3] - v[1]) * 0.04, x = v[0] + (v[2] - v[0]) * 0.05;
    el(g, 'line', {x1: x, y1: -y, x2: x + sc.bar, y2: -y, stroke: '#111', 'stroke-width': w * 1.5,
                   'class': 'scalebar'});
    var fsc = fontFor(svg, fs * 0.75, D.small_px);  // above the bar, from its left end
    label(g, [x, y], sc.value + ' ' + sc.unit, fsc, 'lbl', fsc * 0.01, fsc * 0.35);
    el(g, 'circle', {cx: 0, cy: 0, r: fs * 0.18, fill: '#c62828'});
    var t = el(g, 'text', {x: -fl * 1.5, y: fl * 0.1, 'font-size': fl, 'class': 'lbl'}, 'O');
    el(t, 'tspan', {'font-size': fl * 0.7, dy: fl * 0.2}, kind === 'velocity' ? 'V' : 'A');
    placed.push([-fl * 1.6, -fl * 0.4, -fl * 0.1, fl * 1.0]);
    var pole = [0, 0];
    D.links.forEach(function (lk) {
      var pts = lk.points.map(function (p) { return img(p, i, kind); });
      if (pts.length < 2 || !pts.every(ok)) return;
      if (pts.length >= 3) {
        el(g, 'polygon', {points: pts.map(function (q) { return q[0] + ',' + (-q[1]); }).join(' '),
                          fill: lk.fill, 'fill-opacity': 0.6, stroke: '#555',
                          'stroke-width': w, 'data-image': lk.id});
      } else {
        line(g, pts[0], pts[1], 'rel', w * 1.5).setAttribute('data-image', lk.id);
      }
    });
    Object.keys(D.points).forEach(function (p) {
      var q = img(p, i, kind); if (!ok(q)) return;
      if (D.frame.indexOf(p) < 0) arrow(g, pole, q, w * 1.6, '#111');
      el(g, 'circle', {cx: q[0], cy: -q[1], r: fs * 0.12, fill: '#111', 'data-point': p,
                       'class': 'image'});
      if (D.frame.indexOf(p) < 0) label(g, q, p.toLowerCase() + prime, fl, 'lbl');
    });
    (D.coincident || []).forEach(function (cp) {
      var q = kind === 'velocity' ? [val(cp.vx, D.q.V, i), val(cp.vy, D.q.V, i)]
                                  : [val(cp.ax, D.q.A, i), val(cp.ay, D.q.A, i)];
      var tip = img(cp.point, i, kind);
      if (!ok(q) || !ok(tip)) return;
      arrow(g, pole, q, w * 1.0, '#777');
      el(g, 'line', {x1: q[0], y1: -q[1], x2: tip[0], y2: -tip[1], stroke: '#1565c0',
                     'stroke-width': w * 1.4, 'stroke-dasharray': (w * 5) + ' ' + (w * 3),
                     'data-apparent': cp.point});
      el(g, 'circle', {cx: q[0], cy: -q[1], r: fs * 0.1, fill: '#1565c0',
                       'data-coincident': cp.point + '@' + cp.on});
      label(g, q, cp.point.toLowerCase() + prime + cp.on, fl, 'lbl');
    });
    var cap = document.getElementById(kind + '-scale');
    if (cap) cap.textContent = 'drawn to scale: bar = ' + sc.value + ' ' + sc.unit;
  }
  function nice(x) {
    var base = D[kind0].scale;
    var f = base.factor, k = Math.pow(10, Math.floor(Math.log10(x / f)));
    var steps = [1, 2, 2.5, 5, 10], v = 10 * k;
    for (var s = 0; s < steps.length; s++) {
      if (steps[s] * k >= x / f) { v = steps[s] * k; break; }
    }
    v = Number(v.toPrecision(3));
    return {value: v, unit: base.unit, factor: f, bar: v * f};
  }
  function fmt(x, d) {
    if (!isFinite(x)) return '—';
    var a = Math.abs(x);
    if (a !== 0 && (a >= 1e6 || a < 1e-3)) return x.toExponential(3);
    var dec = Math.max(0, (d || 4) - 1 - Math.floor(Math.log10(a || 1)));
    return x.toFixed(Math.min(dec, 6));
  }
  function angle(v) {
    var d = Math.atan2(v[1], v[0]) * 180 / Math.PI;
    return '∠' + d.toFixed(1) + '°';
  }
  var choose = document.getElementById('point');
  function values(i) {
    var out = [];
    var dv = D.drive.values[i];
    document.getElementById('drive-text').textContent =
      D.drive.label + ' = ' + fmt(dv, 5) + (D.drive.unit === '°' ? '°' : ' ' + D.drive.unit);
    var good = valid.charAt(i) === '1';
    document.getElementById('status').textContent = good ? '' : 'cannot be assembled here';
    if (D.rates) {
      Object.keys(D.omega).forEach(function (k) {
        var w = val(D.omega[k], 1e-6, i), a = val(D.alpha[k], 1e-5, i);
        out.push('<tr><td>ω' + esc(k) + '</td><td class="v">' + fmt(w) +
                 '</td><td>rad/s</td></tr>');
        out.push('<tr><td>α' + esc(k) + '</td><td class="v">' + fmt(a) +
                 '</td><td>rad/s²</td></tr>');
      });
      var p = choose.value;
      if (p && D.points[p]) {
        var vv = img(p, i, 'velocity'), aa = img(p, i, 'acceleration');
        var vm = Math.sqrt(vv[0] * vv[0] + vv[1] * vv[1]);
        var am = Math.sqrt(aa[0] * aa[0] + aa[1] * aa[1]);
        out.push('<tr><td>V<sub>' + esc(p) + '</sub></td><td class="v">' + fmt(vm) + '</td><td>' +
                 esc(D.unit) + '/s ' + (vm > 0 ? angle(vv) : '') + '</td></tr>');
        out.push('<tr><td>A<sub>' + esc(p) + '</sub></td><td class="v">' + fmt(am) + '</td><td>' +
                 esc(D.unit) + '/s² ' + (am > 0 ? angle(aa) : '') + '</td></tr>');
      }
    }
    var xy = choose.value ? P(choose.value, i) : [NaN, NaN];
    out.push('<tr><td>' + esc(choose.value || '') + '</td><td class="v">(' + fmt(xy[0]) + ', ' +
             fmt(xy[1]) + ')</td><td>' + esc(D.unit) + '</td></tr>');
    document.getElementById('value-rows').innerHTML = out.join('');
  }
  function show(i) {
    i = ((i % n) + n) % n;
    cur = i;
    slider.value = i;
    values(i);  // first: the table's width settles the pictures' sizes the letters are set to
    drawMechanism(i);
    if (D.rates) { drawPolygon('velocity', i); drawPolygon('acceleration', i); }
    document.body.setAttribute('data-posture', String(i));
  }
  function stepBy(d) {
    var i = cur;
    for (var k = 0; k < n; k++) {
      i = ((i + d) % n + n) % n;
      if (valid.charAt(i) === '1') break;
    }
    show(i);
  }
  // slider marks: ranges that cannot be assembled, and limit / dead-center postures
  var marks = document.getElementById('marks');
  function pct(i) { return (100 * i / Math.max(n - 1, 1)) + '%'; }
  for (var i0 = 0; i0 < n; i0++) {
    if (valid.charAt(i0) === '0') {
      var j0 = i0; while (j0 + 1 < n && valid.charAt(j0 + 1) === '0') j0++;
      var bad = document.createElement('div'); bad.className = 'bad';
      bad.style.left = pct(i0); bad.style.width = (100 * (j0 - i0 + 1) / Math.max(n - 1, 1)) + '%';
      bad.title = 'cannot be assembled'; marks.appendChild(bad); i0 = j0;
    }
  }
  D.events.forEach(function (e) {
    if (e.kind === 'cannot-assemble') return;
    var t = document.createElement('div'); t.className = 'tick'; t.style.left = pct(e.i);
    t.title = e.note; marks.appendChild(t);
  });
  slider.max = n - 1;
  slider.addEventListener('input', function () { show(Number(slider.value)); });
  document.getElementById('prev').addEventListener('click', function () { stepBy(-sense); });
  document.getElementById('next').addEventListener('click', function () { stepBy(sense); });
  var play = document.getElementById('play');
  function setPlaying(p) { playing = p; play.textContent = p ? '❚❚ Pause' : '▶ Play'; last = null; }
  play.addEventListener('click', function () { setPlaying(!playing); });
  document.getElementById('speed').addEventListener('change', function (e) {
    speed = Number(e.target.value);
  });
  choose.addEventListener('change', function () { values(cur); });
  window.addEventListener('resize', function () { show(cur); });  // letters stay draw's size
  ['show-centers', 'show-inflection', 'fit'].forEach(function (id) {
    var c = document.getElementById(id);
    if (c) c.addEventListener('change', function () { show(cur); });
  });
  document.addEventListener('keydown', function (e) {
    if (e.target === choose) return;
    if (e.key === ' ') { setPlaying(!playing); e.preventDefault(); }
    else if (e.key === 'ArrowRight') { stepBy(sense); e.preventDefault(); }
    else if (e.key === 'ArrowLeft') { stepBy(-sense); e.preventDefault(); }
  });
  var perSecond = Math.max(n / 6, 1);
  // time runs the way the drive turns: with ω2 cw the crank turns cw (θ2 falls)
  function tick(t) {
    if (playing) {
      if (last !== null) {
        acc += (t - last) / 1000 * perSecond * speed;
        var k = Math.floor(acc);
        if (k >= 1) { acc -= k; for (var s = 0; s < Math.min(k, n); s++) stepBy(sense); }
      }
      last = t;
    }
    requestAnimationFrame(tick);
  }
  requestAnimationFrame(tick);
  var first = D.rates ? rvalid.indexOf('1') : -1;
  if (first < 0) first = valid.indexOf('1');
  show(first < 0 ? 0 : first);
  window.graphkinCycle = {show: show, step: stepBy, current: function () { return cur; },
                          count: n, errors: errors, play: function () { setPlaying(true); },
                          pause: function () { setPlaying(false); },
                          playing: function () { return playing; }};
})();
"""


def animate_html(mech: Mechanism, *, count: int = 360, start: float | None = None,
                 stop: float | None = None, centers: bool = False,
                 inflection: bool = False, polygons: str = "cycle") -> str:
    """The cycle of a mechanism as one self-contained HTML page (no network).

    Parameters
    ----------
    mech : Mechanism
    count : int
        Number of postures (360 by default: one per degree of a crank).
    start, stop : float, optional
        The drive range (as ``graphkin sweep --from/--to``).
    centers : bool
        Offer the instant centers (a checkbox on the page).
    inflection : bool
        Offer each moving link's inflection circle (needs rates).
    polygons : {"cycle", "posture"}
        ``cycle``: each polygon at one scale for the whole cycle (lengths compare
        between postures); ``posture``: each posture's polygon at the round scale
        that fits it (a small acceleration polygon is not a dot).  The page's
        "fit polygons" box switches between them.

    Returns
    -------
    str

    Raises
    ------
    InputError
        ``inflection`` without rates.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.4, 4.4, 3.13, 4.15.
    """
    if inflection and not mech.has_rates:
        raise InputError("the inflection circle needs rates (add omega to [drive])",
                         key="--inflection", file=mech.source)
    if polygons not in ("cycle", "posture"):
        raise InputError(f"the polygons are sized per 'cycle' or per 'posture', not "
                         f"{polygons!r}", key="--polygons", file=mech.source)
    fit_each = polygons == "posture"
    data = cycle_data(mech, count=count, start=start, stop=stop, centers=centers,
                      inflection=inflection)
    # draw's label sizes (points) as CSS pixels on the screen
    data["label_px"] = round(STYLES["label"]["size"] * 96 / 72, 3)
    data["small_px"] = round(STYLES["label-small"]["size"] * 96 / 72, 3)
    title = html.escape(data["title"])
    blob = script_json(data)
    options = "".join(f'<option value="{html.escape(p)}">{html.escape(p)}</option>'
                      for p in _default_order(mech, data))
    toggles = ""
    if centers:
        toggles += ('<label><input type="checkbox" id="show-centers" checked> '
                    "instant centers</label>")
    if inflection:
        toggles += ('<label><input type="checkbox" id="show-inflection" checked> '
                    "inflection circles</label>")
    polygons = ""
    if data["rates"]:
        for key, cap in (("velocity", "Velocity polygon"),
                         ("acceleration", "Acceleration polygon")):
            polygons += (f'<figure><figcaption>{cap}</figcaption>'
                         f'<svg id="{key}" xmlns="http://www.w3.org/2000/svg"></svg>'
                         f'<div class="scale" id="{key}-scale">drawn to scale: bar = '
                         f"{html.escape(data[key]['scale']['value'].__format__('g'))} "
                         f"{html.escape(data[key]['scale']['unit'])}</div></figure>")
    return (
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        f"<title>{title}: the cycle</title>\n<style>{_CSS}"
        ".lbl{fill:#111;font-family:'DejaVu Sans',sans-serif}"
        ".ic{fill:#1565c0}.inf{fill:#2e7d32}.guide{stroke:#777;stroke-dasharray:none}"
        ".rel{stroke:#555}</style>\n</head>\n<body>\n"
        f"<header><h1>{title}: the whole cycle</h1>"
        + (f'<p class="held">{html.escape(data["held"])}</p>' if data["held"] else "")
        + "</header>\n"
        '<div class="controls"><button id="play" type="button">▶ Play</button>'
        '<button id="prev" type="button" title="one posture back">◀ −1</button>'
        '<button id="next" type="button" title="one posture on">+1 ▶</button>'
        '<label>speed <select id="speed"><option value="0.25">¼×</option>'
        '<option value="0.5">½×</option><option value="1" selected>1×</option>'
        '<option value="2">2×</option><option value="4">4×</option></select></label>'
        '<span id="drive-text"></span>'
        '<div id="slider-wrap"><input type="range" id="drive" min="0" max="0" value="0" '
        'aria-label="drive"><div id="marks"></div></div>'
        f'<span id="status"></span>{toggles}'
        + ('<label title="redraw each polygon at a round scale that fits it">'
           f'<input type="checkbox" id="fit"{" checked" if fit_each else ""}>'
           ' fit polygons</label>' if data["rates"] else "")
        + "</div>\n"
        '<main><figure><figcaption>Mechanism</figcaption>'
        '<svg id="mechanism" xmlns="http://www.w3.org/2000/svg"></svg></figure>'
        f'{polygons}<div id="values"><label>point <select id="point">{options}</select>'
        '</label><table><tbody id="value-rows"></tbody></table>'
        '<p style="font-size:12px;color:#555">Red on the slider: cannot be assembled '
        "(skipped while playing); blue ticks: limit and dead-center postures "
        "(Sec. 1.10). Space plays, ← → step.</p></div></main>\n"
        f'<script type="application/json" id="cycle-data">{blob}</script>\n'
        f"<script>{_JS}</script>\n</body>\n</html>\n")


def _default_order(mech: Mechanism, data: dict[str, Any]) -> list[str]:
    """The points offered for the values panel: coupler points first."""
    pts = list(data["points"])
    frame = set(mech.links[FRAME].points)
    moving = [p for p in pts if p not in frame]
    return list(reversed(moving)) + [p for p in pts if p in frame]
