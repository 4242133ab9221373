"""The polygons of a Newton page, constructed at Newton's posture (``graphkin live``).

A mechanism whose posture only Newton's method finds on the page (Example
3.9's wheel: away from the file's drive, the pin lies on a trochoid, which
no ruler and compass meets) still has its velocity and acceleration polygons
drawn by construction at any one posture (Secs. 3.4-3.7 and 4.2-4.6): their
steps read the posture's points and link angles only.  This module records
those constructions at the file's posture (:func:`build_polygons`), cuts
them from the posture construction there (every named point and every link
angle becomes a given ``point`` or ``scalar`` step, whose numbers are the
function's parameters ``K``), and writes them out with the one JavaScript
writer (:func:`graphkin.construction.jsgen.generate_js`).  On every pointer
move the page copies Newton's posture into those parameters and calls the
written-out polygons (``gkPolygons``): the images, ω and α the page shows are
the construction's, as ``graphkin solve`` constructs them from the saved file.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 3.7 and Example 3.9 (the rolling wheel's velocity polygon), Sec. 4.6
(the rolling contact's acceleration, Eq. 4.19).
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from graphkin.construction.step import Role, Step
from graphkin.errors import GraphkinError
from graphkin.mechanisms.model import Mechanism

__all__ = ["POLYGONS_JS", "newton_polygons"]


def newton_polygons(mech: Mechanism) -> tuple[dict[str, Any], str] | None:
    """The written-out polygons of a posture and where Newton's values go in their ``K``.

    Returns
    -------
    data : dict
        ``K`` (the parameters at the file's posture), ``points`` (name ->
        the slots of its x and y), ``angles`` (the θ labels read as inputs),
        ``inputs`` (the drives' ω and α, by their labels in the polygons) and ``pitch``.
    js : str
        The function ``gkPolygons(I, K)``.

    None when the file's posture has no construction of its polygons (then
    the page says why, as before).
    """
    from graphkin.construction.codegen import Unsupported
    from graphkin.construction.jsgen import generate_js
    from graphkin.kinematics.polygons import build_polygons
    from graphkin.kinematics.posture import build_posture
    from graphkin.render.live import _pitch_images
    from graphkin.tolerance import DEFAULT_TOL

    if not mech.has_rates or mech.rates is not None:
        return None  # superposition over another link's rate is not one construction
    try:
        pc = build_posture(mech, DEFAULT_TOL)
        pol = build_polygons(mech, pc)
    except GraphkinError:
        return None
    from graphkin.render.live_newton import _path_points

    # the posture's named points and the paths' points (a rolling contact's line): the Newton
    # page's own values of them (render/live_newton.py), so a dragged pivot moves both alike
    paths = [lab for lab, _, _ in _path_points(mech)]
    named = {n for lk in mech.links.values() for n in lk.points} | set(paths)
    angles = [f"θ{lid}" for lid in mech.links]
    cut = named | set(angles)
    rate_steps = [*pol.velocity.steps, *pol.acceleration.steps]
    # the posture's steps the polygons read, back from their inputs, stopping at the cut
    by_out = {o: s for s in pc.construction.steps for o in s.outputs}
    made_by_rates = {o for s in rate_steps for o in s.outputs}
    need: set[str] = set()
    todo = [i for s in rate_steps for i in s.inputs if i not in made_by_rates]
    while todo:
        lab = todo.pop()
        if lab in need or lab not in by_out:
            continue
        need.add(lab)
        if lab not in cut:
            todo += list(by_out[lab].inputs)
    values = pc.values
    steps: list[Step] = []
    for s in pc.construction.steps:
        outs = [o for o in s.outputs if o in need]
        if not outs:
            continue
        if any(o in cut for o in outs):
            for o in outs:  # a posture's point (its numbers parameters) or angle (an input)
                v = np.asarray(values[o], dtype=float)
                if v.size == 1:
                    steps.append(Step(len(steps), o, "input", (), (o,),
                                      params={"name": o}, role=Role.GIVEN))
                else:
                    steps.append(Step(len(steps), o, "point", (), (o,),
                                      params={"xy": (float(v[0]), float(v[1]))},
                                      role=Role.GIVEN))
            continue
        steps.append(replace(s, index=len(steps)))
    for s in rate_steps:
        steps.append(replace(s, index=len(steps)))
    made = {o for s in steps for o in s.outputs}
    points = [n for lk in mech.links.values() for n in lk.points]
    points = list(dict.fromkeys(points))
    requests = [f"{p}({n})" for p in ("v", "a") for n in points if f"{p}({n})" in made]
    requests += [f"{w}{lid}" for w in ("ω", "α") for lid in mech.links if f"{w}{lid}" in made]
    requests += [p for p in ("o_v", "o_a") if p in made]
    pitch = _pitch_images(mech, made)
    requests += [e["label"] for e in pitch if e["label"] not in requests]
    try:
        fn = generate_js(steps, requests=requests, tol=DEFAULT_TOL, name="gkPolygons")
    except Unsupported:
        return None
    names = [n for n, _ in fn.slots]
    slots = {n: k for k, n in enumerate(names)}
    data = {
        "K": fn.values,
        "points": {n: [slots[f"{n}.0"], slots[f"{n}.1"]] for n in [*points, *paths]
                   if f"{n}.0" in slots and f"{n}.1" in slots},
        "angles": [a for a in angles if a in need],
        "inputs": {lab: 0.0 if rate is None else float(rate) for d in mech.drives
                   for lab, rate in zip(pol.rate_inputs[d.index], (d.rate, d.rate2))},
        "pitch": pitch,
    }
    return data, fn.source


#: Newton's posture copied into the polygons' parameters (no arithmetic: the values are the
#: posture's own), the polygons called, and their images, ω and α put in the page's values;
#: ``null`` where the construction has no clean answer (said so on the page, never NaN)
POLYGONS_JS = r"""
function gkNewtonPolygons(P, out) {
  const K = P.K.slice(), I = Object.assign({}, P.inputs);
  for (const n of Object.keys(P.points)) {
    const p = out[n], [i, j] = P.points[n];
    if (!p) return null;
    K[i] = p[0]; K[j] = p[1];
  }
  for (const a of P.angles) {
    if (out[a] === undefined) return null;
    I[a] = out[a];
  }
  const r = gkPolygons(I, K);
  if (r === null) return null;
  for (const lab of Object.keys(r)) out[lab] = r[lab];
  return out;
}
"""
