"""The curvature panel's part of the live page's script (:mod:`graphkin.render.live_app`).

Two strings, as the pen's (:mod:`graphkin.render.live_pen`) and the forces'
(:mod:`graphkin.render.live_forces`): :data:`CURVATURE_JS`, in the page's
library, makes the given points of the written-out curvature construction
(:mod:`graphkin.render.live_curvature`) from the posture and calls it;
:data:`CURVATURE_APP_JS`, inside ``gkLiveApp`` (at its ``/*CURVATURE*/``
mark), draws the panel: the inflection circle on IJ, the centrode normal
and tangent, the Bresse circle, the conjugates, Hain's points and Ball's
point of Secs. 4.13-4.17 of Uicker, Pennock & Shigley, 5th ed.
"""

from __future__ import annotations

__all__ = ["CURVATURE_APP_JS", "CURVATURE_CSS", "CURVATURE_JS"]

CURVATURE_CSS = """
#gk-curvature-note { max-width: 400px; margin: .3em .5em; font-size: .85em; color: #37474f; }
#gk-curvature-note:empty { display: none; }
"""
"""The style of the one line under the curvature panel (as wide as the panel)."""

CURVATURE_JS = r"""// the given points of the curvature construction
// (Secs. 4.13-4.17) from the posture r: a point's position, or its velocity (acceleration)
// drawn from it to the scale 1/|ω| (1/ω²)
function gkCurvatureInputs(V, r) {
  const J = {}, w = r["\u03c9" + V.link];
  for (const lab of Object.keys(V.given)) {
    const g = V.given[lab];
    if (g.slider !== undefined) {
      // a center of curvature at infinity, normal to a slider's line (Sec. 4.13)
      let t = r["\u03b8" + g.slider];
      if (t === undefined) t = g.slider === "1" ? g.frameAngle : NaN;
      t += g.angle;
      J[lab] = [-Math.sin(t) * g.sign, Math.cos(t) * g.sign, 0];
      continue;
    }
    if (g.turn !== undefined) {
      // a point H = P + R(θ) d of a link with one point P (a block), or its velocity
      // (acceleration) drawn from it: V_P + ω k × R_HP, A_P + α k × R_HP - ω² R_HP
      const P = r[g.turn], t = r["\u03b8" + V.link], a = r["\u03b1" + V.link];
      if (!P || !Number.isFinite(t) || w === undefined) return null;
      const c = Math.cos(t), s = Math.sin(t);
      const hx = c * g.d[0] - s * g.d[1], hy = s * g.d[0] + c * g.d[1];
      const H = [P[0] + hx, P[1] + hy];
      if (!g.atip && !g.vtip) { J[lab] = H; continue; }
      const pre = g.vtip ? "v" : "a", p = r[pre + "(" + g.turn + ")"], o = r["o_" + pre];
      if (!p || !o || (g.atip && a === undefined)) return null;
      const rx = g.vtip ? -w * hy : -a * hy - w * w * hx;
      const ry = g.vtip ? w * hx : a * hx - w * w * hy;
      const k = g.vtip ? Math.abs(w) : w * w;
      J[lab] = [H[0] + (p[0] - o[0] + rx) / k, H[1] + (p[1] - o[1] + ry) / k];
      continue;
    }
    if (g.body !== undefined) {
      // a body point H = P + (Q - P) z of the link, or its velocity (acceleration) drawn
      // from it: V_H = V_P + (V_Q - V_P) z (Mehmke: the images are similar to the link)
      const P = r[g.body[0]], Q = r[g.body[1]], z = g.z;
      if (!P || !Q || w === undefined) return null;
      const H = [P[0] + (Q[0] - P[0]) * z[0] - (Q[1] - P[1]) * z[1],
                 P[1] + (Q[0] - P[0]) * z[1] + (Q[1] - P[1]) * z[0]];
      if (!g.atip && !g.vtip) { J[lab] = H; continue; }
      const pre = g.vtip ? "v" : "a", k = g.vtip ? Math.abs(w) : w * w;
      const p = r[pre + "(" + g.body[0] + ")"], q = r[pre + "(" + g.body[1] + ")"];
      const o = r["o_" + pre];
      if (!p || !q || !o) return null;
      const ax = p[0] - o[0] + (q[0] - p[0]) * z[0] - (q[1] - p[1]) * z[1];
      const ay = p[1] - o[1] + (q[0] - p[0]) * z[1] + (q[1] - p[1]) * z[0];
      J[lab] = [H[0] + ax / k, H[1] + ay / k];
      continue;
    }
    const n = g.point !== undefined ? g.point : (g.vtip !== undefined ? g.vtip : g.atip);
    const p = r[n];
    if (!p || w === undefined) return null;
    if (g.point !== undefined) { J[lab] = p; continue; }
    const pre = g.vtip !== undefined ? "v" : "a", k = pre === "v" ? Math.abs(w) : w * w;
    const q = r[pre + "(" + n + ")"], o = r["o_" + pre];
    if (!q || !o) return null;
    J[lab] = [p[0] + (q[0] - o[0]) / k, p[1] + (q[1] - o[1]) / k];
  }
  return J;
}
// the curvature construction of the posture r (null where it has no clean answer)
function gkCurvature(V, r) {
  if (!V || !r || V.why) return null;
  // the link turns at this posture: |ω| L beyond round-off of the posture's speeds (as
  // graphkin's curvature does; in a cam's dwell the coupler stands still, ω = 0)
  if (V.scale !== undefined) {
    const wl = r["\u03c9" + V.link];
    let ref = 0;
    for (const key of Object.keys(r)) {
      const v = r[key];
      if (key.startsWith("v(") && v && r.o_v) {
        ref = Math.max(ref, Math.hypot(v[0] - r.o_v[0], v[1] - r.o_v[1]));
      } else if (key.startsWith("\u03c9") && Number.isFinite(v)) {
        ref = Math.max(ref, Math.abs(v) * V.scale);
      }
    }
    if (!(Number.isFinite(wl) && Math.abs(wl) * V.scale > V.turning * Math.max(ref, 1e-300))) {
      return null;
    }
  }
  const J = gkCurvatureInputs(V, r);
  if (J === null) return null;
  // the Bresse diameter's ratio ω²/α of this posture (Eq. 4.48)
  const K = V.K.slice(), w = r["\u03c9" + V.link], a = r["\u03b1" + V.link];
  for (const k of V.ratios) {
    K[k] = w * w / a;
    if (!Number.isFinite(K[k])) return null;  // α = 0: the Bresse circle is a line
  }
  // the Bresse circle and Γ of this posture: ω, α and the scale of the accelerations
  // (max ω² + |α| over the links), whether α is zero decided on it (Eq. 4.48, Sec. 4.15)
  if (V.rates && V.rates.length) {
    let ref = 0;
    for (const lid of V.rateLinks) {
      const wk = r["\u03c9" + lid], ak = r["\u03b1" + lid];
      if (Number.isFinite(wk) && Number.isFinite(ak)) ref = Math.max(ref, wk * wk + Math.abs(ak));
    }
    for (const [kw, ka, kr] of V.rates) { K[kw] = w; K[ka] = a; K[kr] = ref; }
  }
  // the pole velocity's sense, v = ω k × R_JI drawn to the scale 1/|ω| (Eq. 4.47)
  for (const k of V.signs) K[k] = w > 0 ? 1 : -1;
  // a result with no clean answer here (Hain's G_T at infinity, Example 4.16) is null, the
  // others drawn; without the poles I and J there is no panel (said so)
  const v = curvature(J, K);
  if (v === null || ["I", "J"].some((lab) => V.labels.indexOf(lab) >= 0 && v[lab] === null)) {
    return null;
  }
  return v;
}
"""
"""The curvature construction's glue (in the page's library, beside the centers')."""

CURVATURE_APP_JS = r"""// the curvature of the motion of one link
// (Secs. 4.13-4.17): its inflection circle on IJ, the centrode normal N and tangent T at I,
// the conjugates, Hain's G_N and G_T, Ball's point U
function drawCurvature(r, stale, refit) {
  const svg = svgs.curvature, V = D.curvature, note = byId("gk-curvature-note");
  svg.textContent = "";
  if (V.why) {  // no panel: why, in one line (as the force polygons say theirs)
    svg.style.display = "none";
    note.textContent = "No live curvature: " + V.why + ".";
    return;
  }
  // what of draw's panel the page leaves out (an identity of the file's posture), or nothing
  note.textContent = V.note ? V.note + "." : "";
  defs(svg);
  const cap = svg.parentNode.querySelector("figcaption");
  if (cap) {
    cap.textContent = "Curvature of " + V.link + "/1: inflection circle" +
      (V.labels.indexOf("Bresse circle") >= 0 ? ", Bresse circle (dashed)" : "");
  }
  if (!curv) {
    el(svg, "text", {x: 12, y: 24, "font-size": "12", fill: "#c62828"},
       "No clean construction at this posture (\u03c9" + V.link + " = 0 or a degenerate case).");
    return;
  }
  const g = el(svg, "g", stale ? {class: "gk-stale"} : {});
  const pts = [];
  for (const lid of Object.keys(D.links)) for (const n of D.links[lid]) if (r[n]) pts.push(r[n]);
  const ic = curv["inflection circle"];
  let size = 1;
  if (pts.length) {
    let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
    for (const p of pts) {
      x0 = Math.min(x0, p[0]); x1 = Math.max(x1, p[0]); y0 = Math.min(y0, p[1]);
      y1 = Math.max(y1, p[1]);
    }
    size = Math.hypot(x1 - x0, y1 - y0) || 1;
  }
  const near = (p) => p && pts.length && Math.hypot(p[0] - pts[0][0], p[1] - pts[0][1]) < 3 * size;
  for (const c of [ic, curv["Bresse circle"]]) {
    if (c && c[2] < 3 * size) pts.push([c[0] - c[2], c[1] - c[2]], [c[0] + c[2], c[1] + c[2]]);
  }
  for (const lab of V.labels) {
    if (V.kinds[lab] === "point" && near(curv[lab])) pts.push(curv[lab]);
  }
  if (refit || !views.curvature) fitPoints("curvature", pts);
  for (const lid of Object.keys(D.links)) {
    if (lid === "1") continue;
    outline(g, "curvature", D.links[lid].map((n) => r[n]).filter(Boolean), "plate");
  }
  if (ic) {
    el(g, "circle", {cx: X("curvature", ic), cy: Y("curvature", ic),
                     r: ic[2] * views.curvature.s, fill: "none",
                     stroke: ink("result-line", "color"), "stroke-width": "1.4",
                     class: "gk-inflection-circle"});
  }
  const bc = curv["Bresse circle"];
  if (bc) {  // drawn however large (the panel clips it), fitted only when near
    el(g, "circle", {cx: X("curvature", bc), cy: Y("curvature", bc),
                     r: bc[2] * views.curvature.s, fill: "none",
                     stroke: ink("aux-line", "color"), "stroke-width": "1.2",
                     "stroke-dasharray": "6 3", class: "gk-bresse-circle"});
  }
  const I = curv.I, Jp = curv.J;
  if (I && Jp) {
    // N from I toward J, T 90° clockwise from N (Sec. 4.12)
    const d = Math.hypot(Jp[0] - I[0], Jp[1] - I[1]) || 1, u = [(Jp[0] - I[0]) / d,
                                                                 (Jp[1] - I[1]) / d];
    const L = Math.max(d, 0.25 * size);
    for (const [name, e] of [["N", u], ["T", [u[1], -u[0]]]]) {
      const q = [I[0] + 1.3 * L * e[0], I[1] + 1.3 * L * e[1]];
      el(g, "line", {x1: X("curvature", I), y1: Y("curvature", I), x2: X("curvature", q),
                     y2: Y("curvature", q), stroke: ink("aux-line", "color"),
                     "stroke-width": "1", "marker-end": "url(#" + UID + "gk-curvature-arrow)"});
      label(g, "curvature", q, name);
    }
  }
  for (const lab of V.labels) {
    const p = curv[lab];
    if (V.kinds[lab] !== "point" || !p || !near(p)) continue;
    if (lab === "\u0393 (four circles)" && curv["\u0393"]) continue;  // the same point
    el(g, "circle", {cx: X("curvature", p), cy: Y("curvature", p), r: 3,
                     fill: lab === "I" || lab === "J" ? "#000" : "#fff", stroke: "#000",
                     "stroke-width": "1.2", class: "gk-curvature-point", "data-name": lab});
    label(g, "curvature", p, gkParts(lab.replace(" (four circles)", "")));
  }
}
"""
"""The panel's drawing, inside ``gkLiveApp`` (``curv``: the construction's values shown)."""
