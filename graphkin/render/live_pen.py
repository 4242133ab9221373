"""Pen mode of the live page: the student draws his own polygon and exports it (as a string).

Part of the page's script (:data:`graphkin.render.live_app.APP_JS`, inside
``gkLiveApp``): with the pen on, a click on the velocity (or acceleration)
panel places the pole, then each image point, labelled with the next point's
letter (``b``, ``c``, ...; ``b'`` for accelerations), drawn in blue over
graphkin's polygon.  ``penSVG()`` writes the drawing as an SVG on paper
(:data:`PEN_MM` mm a pixel of the panel, a root ``width`` in mm with a
``viewBox``) with the pole ``O_V``/``O_A``, one line from the pole to each image
point, the letters, and the scale in the drawing's own words (``Scale: 1 mm
= 6.3 in/s``): what ``graphkin check --drawing`` reads (docs/checking.md), so
that the marks are the Python checker's (Sec. 3.4: a polygon drawn to scale).
"""

from __future__ import annotations

__all__ = ["PEN_JS", "PEN_MM"]

PEN_MM = 0.25
"""mm of the exported drawing per pixel of the panel (a click is within 0.1 mm)."""

PEN_JS = r"""
// ---- pen mode: the student draws his own polygon over the panel (click the pole, then each
// image point) and exports it as an SVG that `graphkin check --drawing` marks (the marks are
// the Python checker's: docs/checking.md) ----
const pen = {on: false, panel: "velocity", pole: null, pts: []};
const penBtn = byId("gk-pen"), penLabel = byId("gk-pen-label"), penPanel = byId("gk-pen-panel");
const PEN_MM = %PEN_MM%;  // mm of the exported drawing per pixel of the panel
if (!D.rates || D.refused) byId("gk-pen-bar").style.display = "none";
function penNext() {
  // the next letter: the first moving point not drawn yet (b, c, ...; b' in the acceleration)
  const used = pen.pts.map((q) => q[0]);
  const tick = pen.panel === "acceleration" ? "'" : "";
  for (const n of moving) {
    const lab = n.toLowerCase() + tick;
    if (used.indexOf(lab) < 0 && D.links["1"].indexOf(n) < 0) return lab;
  }
  return "";
}
function penReset() { pen.pole = null; pen.pts = []; penLabel.value = ""; }
function drawPen(svg, panel) {
  if (!pen.pole) return;
  const g = el(svg, "g", {class: "gk-pen"});
  const blue = "#1565c0";
  el(g, "circle", {cx: X(panel, pen.pole), cy: Y(panel, pen.pole), r: 3.5, fill: blue});
  for (const [lab, p] of pen.pts) {
    el(g, "line", {x1: X(panel, pen.pole), y1: Y(panel, pen.pole), x2: X(panel, p),
                   y2: Y(panel, p), stroke: blue, "stroke-width": "1.6"});
    el(g, "text", {x: X(panel, p) + 5, y: Y(panel, p) + 14, "font-size": "12", fill: blue},
       lab);
  }
}
function penSVG() {
  // the drawing on paper: PEN_MM mm per pixel of the panel, y down as in every SVG; the
  // scale stated in the drawing's own words (Scale: 1 mm = ... in/s), so the checker does
  // not turn or stretch it to fit
  const panel = pen.panel, v = views[panel];
  const u = D.unit + (panel === "velocity" ? "/s" : "/s^2");
  const mm = (q) => [(X(panel, q) * PEN_MM).toFixed(4), (Y(panel, q) * PEN_MM).toFixed(4)];
  const esc = (t) => t.replace(/&/g, "&amp;").replace(/</g, "&lt;").replace(/>/g, "&gt;");
  const out = ['<svg xmlns="http://www.w3.org/2000/svg" width="' + (W * PEN_MM) + 'mm" ' +
               'height="' + (H * PEN_MM) + 'mm" viewBox="0 0 ' + (W * PEN_MM) + " " +
               (H * PEN_MM) + '">'];
  if (pen.pole) {
    const o = mm(pen.pole);
    out.push('<text x="' + o[0] + '" y="' + o[1] + '" font-size="3">' +
             (panel === "velocity" ? "O_V" : "O_A") + "</text>");
    for (const [lab, p] of pen.pts) {
      const q = mm(p);
      out.push('<line x1="' + o[0] + '" y1="' + o[1] + '" x2="' + q[0] + '" y2="' + q[1] +
               '" stroke="black" stroke-width="0.3"/>');
      out.push('<text x="' + q[0] + '" y="' + q[1] + '" font-size="3">' + esc(lab) +
               "</text>");
    }
  }
  const per = 1 / (v.s * PEN_MM);
  out.push('<text x="2" y="' + (H * PEN_MM - 2) + '" font-size="3">Scale: 1 mm = ' +
           Number(per.toPrecision(12)) + " " + esc(u) + "</text>");
  out.push("</svg>");
  return out.join("\n") + "\n";
}
function panelWorld(panel, ev) {
  const svg = svgs[panel];
  const pt = svg.createSVGPoint();
  pt.x = ev.clientX; pt.y = ev.clientY;
  const q = pt.matrixTransform(svg.getScreenCTM().inverse());
  const v = views[panel];
  return [v.left + q.x / v.s, v.top - q.y / v.s];
}
penBtn.addEventListener("click", () => {
  pen.on = !pen.on;
  penBtn.setAttribute("aria-pressed", String(pen.on));
  penBtn.textContent = pen.on ? "Pen on: click the pole, then each image point" :
    "Pen: draw my " + pen.panel + " polygon";
});
penPanel.addEventListener("change", () => {
  pen.panel = penPanel.value; penReset(); redraw(false);
  penBtn.textContent = pen.on ? penBtn.textContent : "Pen: draw my " + pen.panel + " polygon";
});
for (const panel of ["velocity", "acceleration"]) {
  svgs[panel].addEventListener("pointerdown", (ev) => {
    if (!pen.on || pen.panel !== panel || !views[panel]) return;
    const w = panelWorld(panel, ev);
    if (!pen.pole) pen.pole = w;
    else pen.pts.push([penLabel.value.trim() || "?", w]);
    penLabel.value = penNext();
    redraw(false);
    ev.preventDefault();
  });
}
byId("gk-pen-clear").addEventListener("click", () => { penReset(); redraw(false); });
byId("gk-pen-export").addEventListener("click", () => {
  const blob = new Blob([penSVG()], {type: "image/svg+xml"});
  const a = document.createElement("a");
  a.href = URL.createObjectURL(blob);
  a.download = GK_NAME.replace(/\.toml$/i, "").replace(/^.*[\\/]/, "") + "-" + pen.panel +
    "-drawing.svg";
  document.body.appendChild(a); a.click(); a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
});

"""
PEN_JS = PEN_JS.replace("%PEN_MM%", repr(PEN_MM))
