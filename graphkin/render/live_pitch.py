"""The pitch circles of rolling contact on the live page's posture panel (``graphkin live``).

``graphkin draw`` draws every circle of a rolling contact (Sec. 2.19): the
rolling circle of the link that rolls (a wheel, a planet's pitch circle, a
follower's roller) and the circle it rolls on (a sun, a ring), each in the
links' ink and numbered with its link, a link once (a compound planet's two
circles give one "4"; :mod:`graphkin.render.mechanism`).  The page draws the
same circles, from the posture it shows on every pointer move:
:func:`pitch_circles` says where each circle's center is (a named point of
the posture, or a point fixed in its link, laid off from a named point of that
link by the link's angle) and its radius; :data:`PITCH_APP_JS`, inside
``gkLiveApp``, draws them (``drawPitchCircles``) and gives the posture panel's
fit their extent (``pitchExtent``).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.19 (rolling contact), Sec. 7.2 (pitch circles), Sec. 7.12 (planetary trains).
"""

from __future__ import annotations

from typing import Any

from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.render.scene import safe_id

__all__ = ["PITCH_APP_JS", "pitch_circles"]


def pitch_circles(mech: Mechanism) -> list[dict[str, Any]]:
    """Every circle of the mechanism's rolling contacts, once each, as the page draws it.

    Each entry: ``id`` (the SVG element's, as ``draw``'s gid: ``roller-<key>``
    for the rolling circle, ``rolls-on-<key>`` for the circle it rolls on),
    ``link``, ``radius``, and the center: ``point`` (a named point of the
    link) or ``local`` (fixed in the link) with ``anchor`` (a named point of
    the link) and ``anchorLocal``, the center being
    ``anchor + R(θ_link) (local - anchorLocal)``, or ``xy`` on the frame (where
    a frame point the page does not move stands); ``number`` is true on the
    link's one numbered circle (the last, as ``draw`` numbers a link once).
    A circle whose center the page cannot place (a link with no named point)
    is left out.
    """
    out: list[dict[str, Any]] = []
    seen: set[tuple[str, Any, float]] = set()

    def add(cid: str, lid: str, center: str | None, local: Any, radius: float) -> None:
        ref: Any = center if center is not None else tuple(float(v) for v in local)
        key = (lid, ref, round(float(radius), 12))
        if key in seen or not radius > 0.0:
            return
        seen.add(key)
        e: dict[str, Any] = {"id": cid, "link": lid, "radius": float(radius)}
        pts = mech.links[lid].points
        if center is not None and center in pts:
            e["point"] = center
            if lid == FRAME:  # a fixed point of a frame path is not on the page's K
                e["xy"] = [float(v) for v in pts[center]]
        elif lid == FRAME:
            e["xy"] = [float(local[0]), float(local[1])]
        else:
            xy = pts.get(center) if center is not None else local
            if xy is None or not pts:
                return
            anchor = next(iter(pts))
            e.update(local=[float(xy[0]), float(xy[1])], anchor=anchor,
                     anchorLocal=[float(v) for v in pts[anchor]])
        out.append(e)

    for r in mech.rolling:
        add(f"roller-{safe_id(r.key)}", r.link, r.center, None, r.radius)
        if r.on_center is not None and r.on_radius is not None:
            add(f"rolls-on-{safe_id(r.key)}", r.on, r.on_center_point, r.on_center,
                r.on_radius)
    last = {e["link"]: k for k, e in enumerate(out)}
    for k, e in enumerate(out):
        e["number"] = last[e["link"]] == k
    return out


PITCH_APP_JS = r"""// the pitch circles of rolling contact (render/live_pitch.py, Sec. 2.19), as
// draw draws them: the rolling circle and the circle it rolls on, in the links' ink, each
// link numbered once
function pitchCenter(r, c) {
  const at = (n) => r[n] || (D.frame[n] ? [K[D.frame[n][0]], K[D.frame[n][1]]] : null);
  if (c.point !== undefined) return at(c.point) || c.xy || null;
  if (c.xy !== undefined) return c.xy;
  const p = at(c.anchor);
  if (!p) return null;
  const t = r["\u03b8" + c.link];
  if (!Number.isFinite(t)) return null;
  const dx = c.local[0] - c.anchorLocal[0], dy = c.local[1] - c.anchorLocal[1];
  return [p[0] + Math.cos(t) * dx - Math.sin(t) * dy, p[1] + Math.sin(t) * dx + Math.cos(t) * dy];
}
// the points the posture panel's fit includes: each circle's box
function pitchExtent(r) {
  const out = [];
  for (const c of D.circles || []) {
    const p = pitchCenter(r, c);
    if (p) out.push([p[0] - c.radius, p[1] - c.radius], [p[0] + c.radius, p[1] + c.radius]);
  }
  return out;
}
function drawPitchCircles(g, r) {
  // the points a number keeps clear of: the links' points and the numbers placed before
  const busy = [];
  for (const lid of Object.keys(D.links)) for (const n of D.links[lid]) if (r[n]) busy.push(r[n]);
  for (const c of D.circles || []) {
    const p = pitchCenter(r, c);
    if (!p) continue;
    el(g, "circle", {cx: X("posture", p), cy: Y("posture", p), r: c.radius * views.posture.s,
                     fill: "none", stroke: ink("link", "ec"),
                     "stroke-width": px(ink("link", "lw")), class: "gk-pitch-circle",
                     id: UID + c.id, "data-link": c.link});
    if (!c.number) continue;
    // the link's number inside its circle, 0.6 R from the center (as draw: above it, or, where
    // a point of the mechanism is, the one of eight directions farthest from every point)
    let at = null, far = -1;
    for (let k = 0; k < 8; k++) {
      const t = Math.PI / 2 + k * Math.PI / 4;
      const q = [p[0] + 0.6 * c.radius * Math.cos(t), p[1] + 0.6 * c.radius * Math.sin(t)];
      let d = Infinity;
      for (const b of busy) d = Math.min(d, Math.hypot(q[0] - b[0], q[1] - b[1]));
      if (d > far + 1e-9 * c.radius) { at = q; far = d; }
      if (far >= 0.3 * c.radius) break;  // clear of every point: the first such direction
    }
    busy.push(at);
    el(g, "text", {x: X("posture", at), y: Y("posture", at) + 5, "font-size": "13",
                   "font-style": "italic", "text-anchor": "middle", class: "gk-link-number",
                   "data-link": c.link}, c.link);
  }
}
"""
"""The posture panel's pitch circles, inside ``gkLiveApp`` (``D.circles``)."""
