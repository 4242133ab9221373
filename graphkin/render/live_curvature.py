"""The curvature panel of the live page: graphkin's curvature construction, of the posture.

graphkin records, for each moving link, the curvature construction of its
motion (:func:`graphkin.kinematics.curvature.link.curvature_constructions`,
Secs. 4.12-4.17 of Uicker, Pennock & Shigley, 5th ed.): the velocity pole
``I``, the inflection pole ``J`` by Bobillier's construction, by the
Euler-Savary lay-off (Eq. 4.43) or from the acceleration image of the point
at ``I`` (Sec. 4.15: inverted slider-cranks, Rapson's slide, five-bars), the
inflection circle, ``Γ`` by the four circles of Fig. 4.33, the conjugates of
Hartmann/Euler-Savary, Hain's construction of the cubic of stationary
curvature (``G_N``, ``G_T``) and Ball's point ``U``.  Here those steps are
written out as a third JavaScript function whose given points are taken
from the posture function's results on every pointer move:

* a point of the mechanism: its position;
* ``A_X`` (the acceleration of X drawn from X to the scale ``1/ω²``):
  ``X + (a(X) - o_a) / ω_k²``; ``V_X`` likewise ``X + (v(X) - o_v) / |ω_k|``;
* an auxiliary point of the link (and its ``A_``, ``V_``): from two points of
  the link by their complex ratio (Mehmke), or from a block's one pin and
  the link's angle;
* a center of curvature at infinity: normal to a slider's line.

Which given is which is found by value at the file's posture (to 1e-9 of the
mechanism's size), what its label says first.  The link is the one ``graphkin
draw -d curvature`` draws when the page can redo it.

The Bresse circle and Γ are not replayed: the recorded steps hold at the
file's posture only (the diameter laid off with the file's ``ω²/α``, or
``Γ = J`` copied where α = 0 there), so they are replaced by
``bresse_circle`` and ``acceleration_center``
(:mod:`graphkin.construction.ops.bresse`), which take ω, α and the scale of
the accelerations from the page at each posture and decide there whether α
is zero (Sec. 4.15, Eq. 4.48), as graphkin's construction of the saved file
does (:func:`_posture_bresse`).

Ball's point ``U`` is replayed like any step: where the file's ``N`` is
infinite (Example 4.16: ``U = J`` there) the construction makes it with
``ball_point`` (:mod:`graphkin.construction.ops.ball`), from ``I``, ``J``
and the two points of the cubic, continuous through ``N = ∞``, so the page
finds ``U`` after any drag.

Other steps the page cannot redo are left out with everything that depends
on them: a step whose numbers were fixed by the file's rates (a ``similar``
step other than the pole velocity's, whose sense the page gives), an
identity of the file's posture (``copy_point``), a given that is none of the
above, an operation with no template.  The function is written
``soft``: a result with no clean answer at a posture is ``null`` on its own.
Where no link is left, the panel's data is one line saying why (``why``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.construction import Role
from graphkin.construction.codegen import TEMPLATES, Unsupported
from graphkin.construction.jsgen import generate_js
from graphkin.construction.step import Step
from graphkin.errors import GraphkinError
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import DEFAULT_TOL

__all__ = ["curvature_data"]

# steps whose numbers are the file posture's rates, not geometry: not redone in the page
# (but the pole velocity's, its sense given by the page: see _bresse; the Bresse diameter's
# is replaced by a step of any posture: _posture_bresse)
_FIXED_BY_RATES = ("similar",)
# steps that take ω, α and the scale of the accelerations from the page at each posture
_POSTURE_RATES = ("bresse_circle", "acceleration_center")
# an identity of the file's posture, not a construction (Γ = J where α = 0, Sec. 4.15, when
# _posture_bresse cannot replace it); a drag parts them
_AT_THIS_POSTURE = ("copy_point",)


def _bresse(step: Any, st: Any) -> str | None:
    """A ``similar`` step on I, J the page can redo: ``"sign"``, ``"ratio"`` or None.

    The curvature construction lays off along the centrode tangent from I
    ``(J - I)`` turned 90°, times the sign of ω (the pole velocity ``v``, drawn
    to the scale ``1/|ω|``, Eq. 4.47) or times ``ω²/α`` (the Bresse diameter,
    Eq. 4.48: ``local_p = (0, ω²/α)``); the page gives that sign or ratio from
    the posture's ω and α on every move.  (The Bresse diameter's step is
    replaced before, :func:`_posture_bresse`; a ratio step is kept for a
    construction whose Bresse circle is not found there.)
    """
    la, lb, lp = (tuple(float(v) for v in step.params[k])
                  for k in ("local_a", "local_b", "local_p"))
    if la != (0.0, 0.0) or lb != (1.0, 0.0) or lp[0] != 0.0:
        return None
    w, a = float(st.omega), float(st.alpha)
    if step.outputs[0].endswith("v") and lp[1] == (1.0 if w > 0 else -1.0):
        return "sign"
    if a != 0.0 and abs(lp[1] - w * w / a) <= 1e-9 * abs(lp[1]):
        return "ratio"
    return None


def _posture_bresse(sol: Any, lid: str, steps: list[Step]) -> list[Step]:
    """The steps with the Bresse circle and Γ made for whatever α the posture has.

    The recorded construction lays off the Bresse diameter with the file's
    ratio ``ω²/α`` (Eq. 4.48) and meets the circle with the inflection circle
    (Fig. 4.34), or, where ``α = 0`` in the file, copies ``J`` to ``Γ``
    (Sec. 4.15): each holds at the file's posture only.  They are replaced by
    ``bresse_circle`` and ``acceleration_center``
    (:mod:`graphkin.construction.ops.bresse`) on the same ``I`` and ``J``,
    which take ``ω``, ``α`` and the scale of the accelerations from the page
    at each posture and decide there whether ``α`` is zero (then no circle and
    ``Γ = J``), as graphkin's construction of the saved file does.
    """
    ic = next((s for s in steps if s.op == "circle_on_diameter"
               and s.outputs[0].startswith("inflection circle")), None)
    made = next((s for s in steps if s.outputs and s.outputs[0].rstrip("*") == "Γ"
                 and s.op in ("copy_point", "other_intersection")), None)
    if ic is None or made is None:
        return steps
    gamma = made.outputs[0]
    bresse = made.inputs[1] if made.op == "other_intersection" else "Bresse circle"
    if any(bresse in s.outputs for s in steps if s.op != "circle_on_diameter"):
        return steps  # (a label of the file's own: not this construction's circle)
    st = sol.links[lid]
    rates = {"omega": float(st.omega), "alpha": float(st.alpha),
             "ref": max(float(s.omega or 0.0) ** 2 + abs(float(s.alpha or 0.0))
                        for s in sol.links.values())}
    ij = tuple(ic.inputs)
    circle = Step(made.index, bresse, "bresse_circle", ij, (bresse,), dict(rates),
                  Role.RESULT, note="The Bresse circle on the diameter IE, "
                  "E = I + (ω²/α) k × R_JI (Eq. 4.48); none where α = 0.", kind="circle")
    center = Step(made.index, gamma, "acceleration_center", ij, (gamma,), dict(rates),
                  Role.RESULT, note="Γ, where the Bresse circle meets the inflection "
                  "circle again (Fig. 4.34); J where α = 0 (Sec. 4.15).", kind="point")
    e = next((s.inputs[1] for s in steps if bresse in s.outputs
              and s.op == "circle_on_diameter"), None)
    out: list[Step] = []
    for s in steps:
        if s is made:
            out.extend([circle, center] if made.op == "copy_point" else [center])
        elif bresse in s.outputs:
            out.append(circle)
        elif not (e is not None and e in s.outputs and s.op == "similar"):
            out.append(s)
    return out


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
    # two points nearly coincident (a block's pin and slider point, apart by round-off) give
    # the complex ratio of Sec. 4.15 no conditioning: the link's angle does instead
    return best if far > 1e-6 * (1.0 + float(sol.mechanism.scale)) else None


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


@dataclass
class _Plan:
    """What the page can redo of one link's curvature construction."""

    lid: str
    cx: Any
    steps: list[Step]
    given: dict[str, dict[str, Any]]
    ok: set[str]
    results: list[str]
    ratios: list[str]
    signs: list[str]


def _plan(sol: Any, lid: str, cx: Any, points: list[str], made: set[str],
          size: float) -> _Plan | str:
    """The steps of link ``lid``'s construction the page can redo, or why it has no panel."""
    if f"ω{lid}" not in made or f"α{lid}" not in made:
        return f"the page does not find ω{lid} and α{lid}"
    steps = _posture_bresse(sol, lid, list(cx.steps))
    cands = _candidates(sol, lid, points)
    given: dict[str, dict[str, Any]] = {}
    ok: set[str] = set()
    why: dict[str, str] = {}  # a label the page cannot redo: the first reason
    ratios: list[str] = []
    signs: list[str] = []
    pq = _two_points(sol, lid, points)
    # a block (one point): its other points from that point and the link's angle
    one = next((n for n in points if n in sol.mechanism.links[lid].points), None) \
        if pq is None and f"θ{lid}" in made else None
    for s in steps:
        blocked = next((why.get(i, f"{i} is not made") for i in s.inputs if i not in ok), None)
        hit: dict[str, Any] | None = None
        if s.op == "point" and not s.inputs:
            lab = s.outputs[0]
            xy = np.asarray(s.params["xy"], dtype=float)
            # what the label says first (the point X, V_X from X, A_X from X): another point
            # may coincide with it at the file's posture only (a slider's C on the frame's
            # L1a, A_A on the rod's end R) and part on a drag
            pre = lab[:2] if lab[:2] in ("A_", "V_") else ""
            want = {"A_": "atip", "V_": "vtip", "": "point"}[pre]
            same = [g for g, v in cands if float(np.hypot(*(v - xy))) <= 1e-9 * size]
            hit = next((g for g in same if g.get(want) == lab[len(pre):]), None)
            aux = given.get(lab[len(pre):], {}) if pre else {}
            if hit is None and not ("z" in aux or "d" in aux):
                hit = same[0] if same else None
            if hit is None and pq is not None:
                hit = _body_given(sol, lid, pq, lab, xy, given, size)
            elif hit is None and one is not None:
                hit = _turn_given(sol, lid, one, lab, xy, given, size)
            blocked = None if hit is not None else (
                f"its given point {s.outputs[0]} is not one the page finds from the posture")
        elif s.op == "ideal_point":
            hit = _slider_normal(sol, s.params["direction"])
            blocked = None if hit is not None else (
                f"its given {s.outputs[0]} at infinity is not normal to a slider's line")
        elif blocked is not None:
            pass
        elif s.op == "similar":
            kind = _bresse(s, sol.links[lid])
            if kind == "ratio":
                ratios.append(s.outputs[0])
            elif kind == "sign":
                signs.append(s.outputs[0])
            elif kind is None:
                blocked = f"the step making {s.outputs[0]} carries the file posture's rates"
        elif s.op in _AT_THIS_POSTURE:
            blocked = f"{s.outputs[0]} = {s.inputs[0]} holds at the file's posture only"
        elif s.op not in TEMPLATES or s.op == "point":
            blocked = f"the operation {s.op!r} has no template"
        if hit is not None:
            given[s.outputs[0]] = dict(hit, link=lid)
        if blocked is None:
            ok.update(s.outputs)
        else:
            why.update({o: blocked for o in s.outputs})
    results = [s.outputs[0] for s in steps if s.role.name == "RESULT"
               and s.outputs and s.outputs[0] in ok]
    if "J" not in results and "inflection circle" not in results:
        return why.get("J", why.get("inflection circle", "it has no inflection pole J"))
    return _Plan(lid, cx, steps, given, ok, results, ratios, signs)


def _why_none(sol: Any, tol: Any) -> str:
    """Why no link has a curvature construction (each turns about a pivot, or none turns)."""
    from graphkin.kinematics.curvature.link import _turning

    mech = sol.mechanism
    turning = [lid for lid in mech.moving if _turning(sol, lid, tol)]
    if not turning:
        return "no link turns at the file's posture (ω = 0): every velocity pole is at infinity"
    if len(turning) == 1:
        return (f"link {turning[0]} turns about a frame pivot: its velocity pole I is the "
                "pivot, and its inflection circle shrinks to that point (Sec. 4.13)")
    return (f"links {', '.join(turning[:-1])} and {turning[-1]} each turn about a frame "
            "pivot: the velocity pole I of each is its pivot, and its inflection circle "
            "shrinks to that point (Sec. 4.13)")


def _left_out(lid: str, steps: list[Step]) -> dict[str, str]:
    """``{"note": line}`` saying what of draw's panel the page leaves out, or ``{}``.

    An identity of the file's posture (``copy_point``) is not carried into a
    drag: Γ = J where α = 0 (then the file's construction has no Bresse circle
    either, its diameter ``ω²/α`` infinite, Eq. 4.48).  (U = J where the cubic
    contains the centrode normal, Example 4.16, is the step ``ball_point`` of
    any posture: carried.)
    """
    copied = {s.outputs[0] for s in steps if s.op in _AT_THIS_POSTURE}
    lines = []
    if "Γ" in copied:
        lines.append(f"Γ and the Bresse circle are not drawn: α{lid} = 0 in the file (so Γ = J "
                     "there) and the page redoes the file's construction; graphkin draw -d "
                     "curvature of the saved file draws them")
    return {"note": "; ".join(lines)} if lines else {}


def curvature_data(mech: Mechanism, points: list[str],
                   made: set[str]) -> tuple[dict[str, Any], str]:
    """The curvature panel's data and the JavaScript of its construction.

    The link is the one ``graphkin draw -d curvature`` draws (the first coupler
    with a curvature construction) when the page can redo its construction,
    else the link whose construction it redoes most of.

    Parameters
    ----------
    mech : Mechanism
    points : list of str
        The points the posture function returns (with their ``v(X)``, ``a(X)``).
    made : set of str
        Every label the posture function can return (``ωk`` among them).

    Returns
    -------
    (dict, str)
        ``{"link", "given", "labels", "results", "K"}`` (and ``"note"``: one line
        naming what of draw's panel the page leaves out, :func:`_left_out`) and the source of
        ``curvature(I, K)``; or ``({"why": line}, "")`` when the page has no
        curvature panel, ``line`` saying why in the user's words.
    """
    from graphkin.construction.ops import templates  # noqa: F401  (registers the templates)
    from graphkin.kinematics.curvature.link import curvature_constructions

    try:
        sol = mech.solve()
        if mech.has_rates and not (sol.has_rates and sol.has_accelerations):
            return {"why": "the velocities and accelerations are undetermined at the file's "
                           "posture (a toggle or dead center, Sec. 3.5), and the inflection "
                           "circle needs them"}, ""
        if not sol.has_rates or not sol.has_accelerations:
            return {"why": "the file gives no rates (the inflection circle needs the angular "
                           "velocity and acceleration)"}, ""
        if not any(f"ω{lid}" in made for lid in mech.links if lid != FRAME):
            rates = getattr(mech, "rates", None)
            return {"why": (f"the file gives the rates of link {rates.link} ([rates]), not the "
                            "drive's, and the page redoes the polygons from the drive's"
                            if rates is not None else
                            "the page does not construct this mechanism's velocity and "
                            "acceleration polygons, which the curvature construction reads")}, ""
        ccs = {lid: cx for lid, cx in curvature_constructions(sol).items()
               if lid != FRAME and any(s.op != "point" for s in cx.steps)}
    except GraphkinError as exc:
        return {"why": f"no curvature construction at the file's posture ({exc})"}, ""
    if not ccs:
        return {"why": _why_none(sol, DEFAULT_TOL)}, ""
    size = 1.0 + float(mech.scale)
    frame_points = set(mech.links[FRAME].points)
    couplers = [k for k in ccs if not frame_points & set(mech.links[k].points)]
    first = (couplers or list(ccs))[0]
    plans = {lid: _plan(sol, lid, cx, points, made, size) for lid, cx in ccs.items()}
    good = [p for p in plans.values() if isinstance(p, _Plan)]
    if not good:
        return {"why": f"the curvature construction of link {first} cannot be redone on the "
                       f"page: {plans[first]}"}, ""
    first_plan = plans[first]
    plan = first_plan if isinstance(first_plan, _Plan) else max(
        good, key=lambda p: len(p.results))
    ok = plan.ok
    # Γ by the four circles (Fig. 4.33) is Γ again, from auxiliary points the construction
    # chose at the file's posture (another pair at another cam angle): where Γ is made at
    # every posture (acceleration_center) the page does not carry it
    if any(s.op == "acceleration_center" and s.outputs[0] in ok for s in plan.steps):
        plan.results = [lab for lab in plan.results if not lab.startswith("Γ (four circles)")]
    extra = [lab for lab in ("N", "T") if any(lab in s.outputs for s in plan.steps)]
    requests = plan.results + [lab for lab in extra if lab in ok and lab not in plan.results]
    steps = _needed([s for s in plan.steps if s.outputs and all(o in ok for o in s.outputs)],
                    requests)
    read = {o for s in steps for o in s.outputs}
    given = {lab: g for lab, g in plan.given.items() if lab in read}
    try:
        fn = generate_js(steps, requests=requests, tol=DEFAULT_TOL, name="curvature",
                         given=given, homogeneous=False,
                         ideal=[lab for lab, g in given.items() if "slider" in g], soft=True)
    except Unsupported as exc:
        return {"why": f"the curvature construction cannot be written for the page ({exc})"}, ""
    kinds = {o: s.kind for s in plan.steps for o in s.outputs}
    names = [n for n, _ in fn.slots]
    note = _left_out(plan.lid, plan.steps)
    # ω, α and the scale of the accelerations of each posture (set by the page, Eq. 4.48)
    rates = [[names.index(f"{s.outputs[0]}.{k}") for k in range(3)] for s in steps
             if s.op in _POSTURE_RATES and f"{s.outputs[0]}.2" in names]
    moving = [k for k in mech.links if k != FRAME and f"ω{k}" in made and f"α{k}" in made]
    return ({"link": plan.lid, "given": given, "labels": list(requests), **note,
             "results": plan.results, "kinds": {lab: kinds[lab] for lab in requests},
             "K": fn.values,
             "ratios": [names.index(f"{lab}.1") for lab in plan.ratios if f"{lab}.1" in names],
             "signs": [names.index(f"{lab}.1") for lab in plan.signs if f"{lab}.1" in names],
             "rates": rates, "rateLinks": moving,
             # whether the link turns at a posture: |ω| L beyond tol.angle of the largest
             # speed (kinematics/curvature/link.py's _turning)
             "scale": float(mech.scale), "turning": DEFAULT_TOL.angle},
            fn.source)
