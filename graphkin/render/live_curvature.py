"""The curvature panel of the live page: graphkin's curvature construction, of the posture.

graphkin records, for each moving link, the curvature construction of its
motion (:func:`graphkin.kinematics.curvature.link.curvature_constructions`,
Secs. 4.12-4.17 of Uicker, Pennock & Shigley, 5th ed.): the velocity pole
``I`` from two pairs of conjugate points, Bobillier's construction of the
inflection pole ``J`` and the inflection circle, ``Γ`` by the four circles of
Fig. 4.33, the conjugates of Hartmann/Euler-Savary, Hain's construction of
the cubic of stationary curvature (``G_N``, ``G_T``) and Ball's point ``U``.
Here those steps are written out as a third JavaScript function whose given
points are taken from the posture function's results on every pointer move:

* a point of the mechanism: its position;
* ``A_X`` (the acceleration of X drawn from X to the scale ``1/ω²``):
  ``X + (a(X) - o_a) / ω_k²``; ``V_X`` likewise ``X + (v(X) - o_v) / |ω_k|``.

Which given is which is found by value at the file's posture (each given
point must be one of those, to 1e-9 of the mechanism's size).  Steps the page
cannot redo from the posture are left out with everything that depends on
them: a step whose numbers were fixed by the file's rates (the Bresse
circle's ``similar`` steps carry ``ω²/α`` of the file's posture; the
closed-form Euler-Savary step), a given that is not one of the above (an
auxiliary point, a center of curvature at infinity), an operation with no
template.  A link that turns about a frame pivot (its inflection circle is
the point ``I``) has no panel.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphkin.construction.codegen import TEMPLATES, Unsupported
from graphkin.construction.jsgen import generate_js
from graphkin.errors import GraphkinError
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import DEFAULT_TOL

__all__ = ["curvature_data"]

# steps whose numbers are the file posture's rates, not geometry: not redone in the page
# (the Bresse circle's similar step is, its ratio ω²/α given by the page: see _bresse)
_FIXED_BY_RATES = ("similar",)
# an identity of the file's posture, not a construction: Γ = J where α = 0 (Sec. 4.15), U = J
# where the cubic contains the centrode normal (Example 4.16); a drag parts them
_AT_THIS_POSTURE = ("copy_point",)


def _bresse(step: Any, st: Any) -> str | None:
    """A ``similar`` step on I, J the page can redo: ``"turn"``, ``"ratio"`` or None.

    The curvature construction lays off along the centrode tangent from I
    ``(J - I)`` turned 90°, times 1 (the pole velocity's direction) or times
    ``ω²/α`` (the Bresse diameter, Eq. 4.48: ``local_p = (0, ω²/α)``); the page
    gives that ratio from the posture's ω and α on every move.
    """
    la, lb, lp = (tuple(float(v) for v in step.params[k])
                  for k in ("local_a", "local_b", "local_p"))
    if la != (0.0, 0.0) or lb != (1.0, 0.0) or lp[0] != 0.0:
        return None
    if lp[1] == 1.0:
        return "turn"
    w, a = float(st.omega), float(st.alpha)
    if a != 0.0 and abs(lp[1] - w * w / a) <= 1e-9 * abs(lp[1]):
        return "ratio"
    return None


def _candidates(sol: Any, lid: str, points: list[str]) -> list[tuple[dict[str, Any], np.ndarray]]:
    """Every given the page can make from a posture, with its value at the file's posture."""
    st = sol.links[lid]
    w = float(st.omega)
    out: list[tuple[dict[str, Any], np.ndarray]] = []
    for n in points:
        p = np.asarray(sol.position(n), dtype=float)
        out.append(({"point": n}, p))
        if w != 0.0 and n in sol.mechanism.links[lid].points:
            out.append(({"vtip": n}, p + np.asarray(sol.velocity(n), dtype=float) / abs(w)))
            out.append(({"atip": n}, p + np.asarray(sol.acceleration(n), dtype=float) / w**2))
    return out


def _slider_normal(sol: Any, direction: Any) -> dict[str, Any] | None:
    """A center of curvature at infinity: normal to a slider's line (Sec. 4.13), or None.

    A point held on a straight line of another link moves, relative to it,
    on that line: its center of curvature is the point at infinity of the
    line's normal ``±(-sin θ, cos θ)``, ``θ`` the line's angle (the angle of
    the link it is on plus the line's own).
    """
    d = np.asarray(direction, dtype=float)
    for sl in sol.mechanism.sliders:
        t = float(np.asarray(sol.links[sl.on].angle, dtype=float)) + float(sl.direction_angle)
        n = np.array([-np.sin(t), np.cos(t)])
        for sign in (1.0, -1.0):
            if float(np.hypot(*(d - sign * n))) <= 1e-9:
                return {"slider": sl.on, "angle": float(sl.direction_angle), "sign": sign,
                        "frameAngle": float(np.asarray(sol.links[FRAME].angle, dtype=float))}
    return None


def _two_points(sol: Any, lid: str, points: list[str]) -> tuple[str, str] | None:
    """Two points of the link the posture gives, far apart: the frame of its body points."""
    mine = [n for n in points if n in sol.mechanism.links[lid].points]
    best, far = None, 0.0
    for i, p in enumerate(mine):
        for q in mine[i + 1:]:
            d = float(np.hypot(*(np.asarray(sol.position(q)) - np.asarray(sol.position(p)))))
            if d > far:
                best, far = (p, q), d
    return best if far > 0.0 else None


def _body_given(sol: Any, lid: str, pq: tuple[str, str], label: str, xy: np.ndarray,
                given: dict[str, dict[str, Any]], size: float) -> dict[str, Any] | None:
    """An auxiliary point of the link, or its acceleration (velocity) drawn from it.

    Sec. 4.15 ("any point will do"): ``H = P + (Q - P) z`` with the complex
    ratio ``z`` of the link, and by Mehmke's theorem ``A_H = A_P + (A_Q - A_P) z``
    (the images are similar to the link).
    """
    p, q = (np.asarray(sol.position(n), dtype=float) for n in pq)
    w = float(sol.links[lid].omega)
    for pre, key, k in (("A_", "atip", w * w), ("V_", "vtip", abs(w))):
        body = given.get(label[len(pre):]) if label.startswith(pre) else None
        if body is not None and "z" in body and "pos" in body and k != 0.0:
            z = complex(*body["z"])
            get = sol.acceleration if key == "atip" else sol.velocity
            ap, aq = (complex(*np.asarray(get(n), dtype=float)) for n in pq)
            h = complex(*body["pos"]) + (ap + (aq - ap) * z) / k
            if abs(h - complex(*xy)) <= 1e-9 * size:
                return {"body": list(pq), "z": body["z"], key: True}
            return None
    d = complex(*(q - p))
    z = complex(*(xy - p)) / d
    return {"body": list(pq), "z": [z.real, z.imag], "pos": [float(xy[0]), float(xy[1])]}


def _turn_given(sol: Any, lid: str, anchor: str, label: str, xy: np.ndarray,
                given: dict[str, dict[str, Any]], size: float) -> dict[str, Any] | None:
    """An auxiliary point of a link with one point only, or its acceleration (velocity) drawn.

    A block has one named point ``P`` (its pin); the link's other points are
    ``H = P + R(θ) d`` with ``θ`` the link's angle and ``d`` fixed in the link,
    and, as for any two points of one link (Eqs. 3.4 and 4.5),
    ``V_H = V_P + ω k × R_HP`` and ``A_H = A_P + α k × R_HP - ω² R_HP``.
    Each is checked against the construction's own given at the file's posture.
    """
    st = sol.links[lid]
    p = np.asarray(sol.position(anchor), dtype=float)
    t = float(np.asarray(st.angle, dtype=float))
    w, al = float(st.omega), float(st.alpha)
    c, sn = np.cos(t), np.sin(t)

    def turned(d: np.ndarray) -> np.ndarray:
        return np.array([c * d[0] - sn * d[1], sn * d[0] + c * d[1]])

    for pre, key, k in (("A_", "atip", w * w), ("V_", "vtip", abs(w))):
        body = given.get(label[len(pre):]) if label.startswith(pre) else None
        if body is not None and "d" in body and k != 0.0:
            r = turned(np.asarray(body["d"], dtype=float))
            if key == "atip":
                rel = al * np.array([-r[1], r[0]]) - w * w * r
                base = np.asarray(sol.acceleration(anchor), dtype=float)
            else:
                rel = w * np.array([-r[1], r[0]])
                base = np.asarray(sol.velocity(anchor), dtype=float)
            h = p + r + (base + rel) / k
            if float(np.hypot(*(h - xy))) <= 1e-9 * size:
                return {"turn": anchor, "d": body["d"], key: True}
            return None
    d = xy - p
    return {"turn": anchor, "d": [float(c * d[0] + sn * d[1]), float(-sn * d[0] + c * d[1])]}


def _needed(steps: list[Any], requests: list[str]) -> list[Any]:
    """The steps the requested labels read, directly or not (no other step can fail the page).

    A line drawn for the figure only (the collineation axis IQ, through Q at
    infinity at Example 4.16's posture) would make the whole function return
    ``null`` where its meet has no clean answer.
    """
    live = set(requests)
    keep: list[Any] = []
    for s in reversed(steps):
        if live & set(s.outputs):
            keep.append(s)
            live.update(s.inputs)
    return keep[::-1]


def curvature_data(mech: Mechanism, points: list[str],
                   made: set[str]) -> tuple[dict[str, Any], str] | None:
    """The curvature panel's data and the JavaScript of its construction, or None.

    Parameters
    ----------
    mech : Mechanism
    points : list of str
        The points the posture function returns (with their ``v(X)``, ``a(X)``).
    made : set of str
        Every label the posture function can return (``ωk`` among them).

    Returns
    -------
    (dict, str) or None
        ``{"link", "given", "labels", "results", "K"}`` and the source of
        ``curvature(I, K)``; None when no link has a curvature construction the
        page can redo.
    """
    from graphkin.construction.ops import templates  # noqa: F401  (registers the templates)
    from graphkin.kinematics.curvature.link import curvature_constructions

    try:
        sol = mech.solve()
        ccs = curvature_constructions(sol)
    except GraphkinError:
        return None
    size = 1.0 + float(mech.scale)
    best: tuple[int, str, Any, dict[str, dict[str, Any]], list[str], set[str],
                list[str]] | None = None
    for lid, cx in ccs.items():
        if lid == FRAME or f"ω{lid}" not in made:
            continue
        cands = _candidates(sol, lid, points)
        given: dict[str, dict[str, Any]] = {}
        ok: set[str] = set()
        ratios: list[str] = []
        pq = _two_points(sol, lid, points)
        # a block (one point): its other points from that point and the link's angle
        one = next((n for n in points if n in sol.mechanism.links[lid].points), None) \
            if pq is None and f"θ{lid}" in made and f"α{lid}" in made else None
        for s in cx.steps:
            if s.op == "point" and not s.inputs:
                xy = np.asarray(s.params["xy"], dtype=float)
                # the point of that name first: another point may coincide with it at the
                # file's posture only (a slider's C on the frame's L1a) and part on a drag
                same = [g for g, v in cands if float(np.hypot(*(v - xy))) <= 1e-9 * size]
                hit = next((g for g in same if g.get("point") == s.outputs[0]),
                           same[0] if same else None)
                if hit is None and pq is not None:
                    hit = _body_given(sol, lid, pq, s.outputs[0], xy, given, size)
                elif hit is None and one is not None:
                    hit = _turn_given(sol, lid, one, s.outputs[0], xy, given, size)
                if hit is not None:
                    given[s.outputs[0]] = dict(hit, link=lid)
                    ok.add(s.outputs[0])
            elif s.op == "ideal_point":
                hit = _slider_normal(sol, s.params["direction"])
                if hit is not None:
                    given[s.outputs[0]] = dict(hit, link=lid)
                    ok.add(s.outputs[0])
            elif s.op == "similar" and all(i in ok for i in s.inputs):
                kind = _bresse(s, sol.links[lid])
                if kind is not None:
                    ok.update(s.outputs)
                    if kind == "ratio":
                        ratios.append(s.outputs[0])
            elif (s.op in TEMPLATES and s.op not in _FIXED_BY_RATES + _AT_THIS_POSTURE
                  and s.op != "point"
                  and all(i in ok for i in s.inputs)):
                ok.update(s.outputs)
        results = [s.outputs[0] for s in cx.steps if s.role.name == "RESULT"
                   and s.outputs and s.outputs[0] in ok]
        if "J" not in results and "inflection circle" not in results:
            continue
        if best is None or len(results) > best[0]:
            best = (len(results), lid, cx, given, results, ok, ratios)
    if best is None:
        return None
    _, lid, cx, given, results, ok, ratios = best
    extra = [lab for lab in ("N", "T") if any(lab in s.outputs for s in cx.steps)]
    requests = results + [lab for lab in extra if lab in ok and lab not in results]
    steps = _needed([s for s in cx.steps if s.outputs and all(o in ok for o in s.outputs)],
                    requests)
    try:
        fn = generate_js(steps, requests=requests, tol=DEFAULT_TOL, name="curvature",
                         given=given, homogeneous=False,
                         ideal=[lab for lab, g in given.items() if "slider" in g], soft=True)
    except Unsupported:
        return None
    kinds = {o: s.kind for s in cx.steps for o in s.outputs}
    names = [n for n, _ in fn.slots]
    return ({"link": lid, "given": given, "labels": list(requests), "results": results,
             "kinds": {lab: kinds[lab] for lab in requests}, "K": fn.values,
             "ratios": [names.index(f"{lab}.1") for lab in ratios if f"{lab}.1" in names]},
            fn.source)
