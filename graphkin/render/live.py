"""The live page: drag the crank or a frame pivot and the polygons redraw (``graphkin live``).

One self-contained HTML file (no network): the mechanism's recorded
posture, velocity and acceleration constructions are written out as one
JavaScript function (:func:`graphkin.construction.jsgen.generate_js`) whose
parameters are the mechanism's dimensions, and a small script
(:mod:`graphkin.render.live_app`) calls it on every pointer move and redraws
the three panels.  Nothing is computed in Python at run time; the values the
page shows are the construction's own (tested against ``graphkin solve`` of
the file the page saves, tests/render/test_live.py).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (the posture constructions), Secs. 3.4-3.6 (velocity polygon and
images), Secs. 4.2-4.6 (acceleration polygon).
"""

from __future__ import annotations

import html
import json
import math
import re
from typing import Any

from graphkin.construction.codegen import Unsupported
from graphkin.construction.jsgen import RUNTIME, generate_js, js_string
from graphkin.errors import InputError
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.render.contact_letters import contact_acceleration_letters, contact_velocity_letters
from graphkin.render.live_app import APP_JS, LIVE_LIB, PAGE_CSS
from graphkin.render.style import STYLES
from graphkin.tolerance import DEFAULT_TOL

__all__ = ["drag_hint", "live_body", "live_data", "live_html", "script_json"]

_BRANCH_OPS = ("intersect_circles", "intersect_line_circle", "tangent_foot")


def script_json(value: Any) -> str:
    """``value`` as JSON safe inside ``<script>`` (``<``, ``>``, ``&``, line separators escaped)."""
    return (json.dumps(value, ensure_ascii=False, allow_nan=False)
            .replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")
            .replace("\u2028", "\\u2028").replace("\u2029", "\\u2029"))


def live_data(mech: Mechanism, file_data: dict[str, Any], source: str, *,
              turn: bool = True) -> tuple[dict[str, Any], str]:
    """What the page needs: its data (JSON-able) and the JavaScript of the construction.

    The page of :func:`_live_data`, with the pitch circles of its rolling contacts
    (``circles``, :func:`graphkin.render.live_pitch.pitch_circles`), which the posture
    panel draws as ``graphkin draw`` does, whichever way the page solves the posture.

    Parameters and Raises: see :func:`_live_data`.
    """
    from graphkin.render.live_pitch import pitch_circles

    data, js = _live_data(mech, file_data, source, turn=turn)
    data["circles"] = pitch_circles(mech)
    data["hint"] = drag_hint(mech, data)
    return data, js


def _names(xs: list[str]) -> str:
    """``A``, ``A or B``, ``A, B or C``."""
    return xs[0] if len(xs) == 1 else f"{', '.join(xs[:-1])} or {xs[-1]}"


def _driver(mech: Mechanism, drive: dict[str, Any]) -> str:
    """What turns the mechanism on this page, named for its kind, with its handle."""
    lid, tip, pivot = str(drive.get("link")), drive.get("tip"), drive.get("pivot")
    if not tip:  # no handle on the driving link (a slider's travel, a cam held): the control
        return f"Set the drive {drive.get('label', '')} with the drive control"
    by = f"about {pivot} by its handle {tip}"
    if drive.get("relative") or lid in {str(j.link) for j in mech.cams}:
        return f"Turn the cam {by}"
    rolls = [r for r in mech.rolling if lid in (str(r.link), str(r.on))]
    if any(str(r.link) == lid and r.p0 is not None for r in rolls):
        return f"Turn the pinion {lid} {by} (the rack slides under it)"
    if rolls:
        return f"Turn the driving gear {lid} {by}"
    points = mech.links[lid].points if lid in mech.links else {}
    if any(r.center in points for r in mech.rolling):
        return f"Turn the arm {lid}, which carries the planets, {by}"
    return f"Drag the crank's moving pin {tip}"


def drag_hint(mech: Mechanism, data: dict[str, Any]) -> str:
    """The page's first line: what its user drags, named for this kind of page.

    The driving link's handle (a linkage's crank pin, a gear pair's or train's
    driving gear or arm, a pinion on its rack, a cam; the drive's control where
    the driving link has no handle: a slider's travel), then the frame pivots
    and the points of links the page lets the user drag, by name.  (A vector
    file's page says its own: :mod:`graphkin.render.live_vector`.)

    Examples
    --------
    >>> import tomllib
    >>> import graphkin
    >>> text = graphkin.examples.text("fourbar")  # Example 3.1
    >>> data, _ = live_data(graphkin.loads(text), tomllib.loads(text), "fourbar.toml")
    >>> data["hint"].split(" (filled")[0]
    "Drag the crank's moving pin B, a frame pivot A or D, or a point of a link E or F"
    """
    drive = data.get("drive", {})
    first = _driver(mech, drive)
    tip = drive.get("tip")
    frame = list(data.get("frame", {}))
    moving = {n for lid, lk in mech.links.items() if lid != FRAME for n in lk.points}
    items = []
    if frame:
        what = "a frame pivot" if all(n in moving for n in frame) else "a frame point"
        items.append(f"{what} {_names(frame)}")
    points = [n for n in data.get("coupler", {}) if n != tip]
    if points:
        items.append(f"a point of a link {_names(points)}")
    drag = first.startswith("Drag")
    rest = ""
    if len(items) == 2:
        rest = f", {'' if drag else 'drag '}{items[0]}, or {items[1]}"
    elif items:
        rest = f" or {items[0]}" if drag else f", or drag {items[0]}"
    handles = " (filled handles)" if tip or items else ""
    return (f"{first}{rest}{handles}; every panel is the recorded construction, re-solved in "
            "the page.")



def _live_data(mech: Mechanism, file_data: dict[str, Any], source: str, *,
               turn: bool = True) -> tuple[dict[str, Any], str]:
    """What the page needs: its data (JSON-able) and the JavaScript of the construction.

    Parameters
    ----------
    mech : Mechanism
        The loaded file.
    file_data : dict
        The file's parsed TOML (the page saves it back with the edits).
    source : str
        The file's name, for messages.
    turn : bool
        Let a cam mechanism's cams turn on the page (:mod:`.live_cam_turn`);
        False holds them at the file's angle (:mod:`.live_cams`).

    Raises
    ------
    InputError
        The mechanism is not solved by a construction (the page has nothing to
        write out), or its construction uses an operation with no template.
    """
    from graphkin.kinematics.posture import NotDecomposable
    from graphkin.kinematics.sweep.engine import _Engine

    try:
        eng = _Engine(mech, DEFAULT_TOL)
    except NotDecomposable:  # not one group at a time: Newton's method on the page
        return _newton_page(mech, file_data, source)
    if eng.method != "construction" or eng.pc is None:
        return _newton_page(mech, file_data, source)
    cx = eng.combined if eng.combined is not None else eng.pc.construction
    consts: dict[str, float] = {k: float(v) for k, v in eng.held.items()}
    if eng.combined is not None:
        consts.update({k: float(v) for k, v in eng.rate_given.items()})
    made = {o for s in cx.steps for o in s.outputs}
    points = [n for lk in mech.links.values() for n in lk.points if n in made]
    points = list(dict.fromkeys(points))
    requests = list(points)
    requests += [f"θ{lid}" for lid in mech.links if f"θ{lid}" in made]
    rates = eng.combined is not None
    if rates:
        for pre in ("v", "a"):
            requests += [f"{pre}({n})" for n in points if f"{pre}({n})" in made]
        requests += [f"{w}{lid}" for w in ("ω", "α") for lid in mech.links if f"{w}{lid}" in made]
        requests += [p for p in ("o_v", "o_a") if p in made]
        pitch = _pitch_images(mech, made)
        requests += [e["label"] for e in pitch if e["label"] not in requests]
    try:
        fn = generate_js(cx.steps, requests=requests, tol=DEFAULT_TOL, name="construction")
    except Unsupported as exc:
        raise InputError(f"no live page: {exc}", file=source) from None
    drive = _drive_data(mech, eng.label, made)
    # a gear rolling on a circle turns with its arm on the covering (roll_circle_angle): the
    # crank dragged round is counted on continuously, past a whole turn
    drive["covering"] = any(s.op == "roll_circle_angle" for s in cx.steps)
    names = [n for n, _ in fn.slots]
    # a frame point where a path of the frame passes (a slider's line, a slot's center) is
    # part of that path, whose direction other steps carry: not draggable
    all_paths: tuple[Any, ...] = (*mech.sliders, *mech.slots, *mech.rolling)
    fixed = {tuple(map(float, q)) for path in all_paths
             if path.on == FRAME
             for q in (getattr(path, a, None) for a in ("p0", "p1", "center", "on_center"))
             if isinstance(q, (tuple, list))}
    frame_pts = {n: [names.index(f"{n}.0"), names.index(f"{n}.1")]
                 for n, xy in mech.links[FRAME].points.items()
                 if f"{n}.0" in names and tuple(map(float, xy)) not in fixed}
    coupler = _coupler_points(mech, cx.steps, names, made)
    branch_pts = [s.outputs[0] for s in cx.steps if s.op in _BRANCH_OPS and
                  s.outputs[0] in points]
    hints = dict(file_data.get("assembly", {})) if isinstance(file_data.get("assembly"),
                                                              dict) else {}
    data = {
        "title": mech.title or source,
        "unit": mech.length_unit,
        "links": {lid: [n for n in lk.points if n in made] for lid, lk in mech.links.items()},
        "frame": frame_pts,
        "coupler": coupler,
        "branches": {n[:-len(".branch")]: k for k, n in enumerate(names)
                     if n.endswith(".branch") and n[:-len(".branch")] in points},
        "drive": drive,
        "inputs": consts,
        "K": fn.values,
        "rates": rates,
        "pitch": pitch if rates else [],
        "assembly": sorted(set(hints) | set(branch_pts)),
        "file": file_data,
        "style": {k: STYLES[k] for k in ("link", "plate", "pin", "result-line", "aux-line")
                  if k in STYLES},
    }
    from graphkin.render.live_cam_turn import turn_cams, turn_handle
    from graphkin.render.live_cams import hold_cams

    # a cam turns: its linkage rebuilt at every angle (Sec. 4.7); else held at the file's
    tjs = turn_cams(data, mech, file_data, source, cx.steps, names, eng.label) if turn else ""
    hold_cams(data, mech, source)
    turn_handle(data)
    cam = data.get("cam")
    if data.get("turnWhy") and isinstance(cam, dict):
        cam["why"] += f" (not turned on the page: {data.pop('turnWhy')})"
    from graphkin.render.live_centers import centers_data
    from graphkin.render.live_newton import roll_edit_js

    js = RUNTIME + fn.source + tjs + roll_edit_js(mech, made)
    js += _follow(data, mech, {d.label: list(w) for w, d in eng.coupled_rates.items()}
                  if rates else None)

    data["centers"], cjs = centers_data(mech, points, made, avoid=coupler)
    js += cjs
    from graphkin.render.live_curvature import curvature_data

    data["curvature"], vjs = curvature_data(mech, points, made)
    js += vjs
    from graphkin.render.live_forces import forces_data

    fd = forces_data(mech, points, made)
    if fd is not None:
        data["forces"], fjs = fd
        js += fjs
    if turn:
        from graphkin.render.live_cam_turn import check_turn

        check_turn(data, mech, file_data, source)  # the same page at another cam angle
    return data, js


def _pitch_images(mech: Mechanism, made: set[str]) -> list[dict[str, str]]:
    """The images of the points of contact of rolling contact, as the book letters them.

    The contact point of each link of a contact has one velocity (no slip,
    Eq. 3.13: ``c₄`` and ``c₂`` are one image; on the frame, ``V_C = 0``: the
    image is the pole) and accelerations that differ by the rolling component
    ``A^r`` (Eq. 4.19; ``c′₄``).  Each entry: the polygon (``"v"`` or ``"a"``),
    the image's label in the construction (the pole ``o_v`` for a contact
    point of a link rolling on the frame) and its letters (Sec. 3.7, Fig. 3.14b).
    """
    out: list[dict[str, str]] = []
    count: dict[str, int] = {}
    for r in mech.rolling:
        for lid in (r.link, r.on):
            count[lid] = count.get(lid, 0) + 1
    for r in mech.rolling:
        pair = (r.link, r.on)
        links = [lid for lid in pair if lid != FRAME]
        # velocity: one image for the contact points of both links (no slip); on the frame
        # the pole, c₄ = c₁ (V_C = 0)
        c, name = r.contact_label, r.contact_name
        v = next((f"v({c}@{lid})" for lid in links if f"v({c}@{lid})" in made),
                 "o_v" if FRAME in pair and "o_v" in made else "")
        if v:  # the letters are draw's (render/contact_letters.py): one rule for both
            out.append({"pre": "v", "label": v, "text": contact_velocity_letters(name, pair)})
        # acceleration: each link's own contact image (they differ by A^r); a link in two
        # contacts (a planet on a sun and in a ring) names the contact by the other link
        for lid in links:
            a = next((lab for lab in (f"a({c}@{lid})", f"a({c}@{lid}):r")
                      if lab in made), "")
            other = pair[1] if lid == pair[0] else pair[0]
            if a:
                out.append({"pre": "a", "label": a,
                            "text": contact_acceleration_letters(name, lid, other,
                                                                 count[lid] > 1)})
    return out


def _drive_data(mech: Mechanism, label: str, made: set[str]) -> dict[str, Any]:
    """The page's drive: its input's label, kind, value, and the crank's pin to drag."""
    d = mech.drives[0]
    m = re.fullmatch(r"drive\[(\d+)\]", d.key)
    # where the file gives the drive's value: its table (or its place in [[drive]]) and key
    drive: dict[str, Any] = {"label": label, "kind": d.kind, "link": d.link,
                             "value": float(d.value), "index": int(m.group(1)) if m else 0,
                             "key": {"relative": "angle"}.get(d.kind, d.kind),
                             "degrees": d.kind in ("angle", "relative")}
    link = mech.links.get(d.link)
    if d.kind == "angle" and link is not None:
        frame = mech.links[FRAME].points
        pivot = next((n for n in link.points if n in frame), None)
        tip = next((n for n in link.points if n != pivot and n in made), None)
        if pivot is not None and tip is not None:
            (px, py), (tx, ty) = link.points[pivot], link.points[tip]
            drive.update(pivot=pivot, tip=tip, phi=math.atan2(ty - py, tx - px))
    return drive


def _newton_page(mech: Mechanism, file_data: dict[str, Any],
                 source: str) -> tuple[dict[str, Any], str]:
    """The page of a mechanism only Newton's method solves (:mod:`.live_newton`).

    Not a cam's: Newton's method would turn its equivalent linkage, which holds at
    the file's cam angle only (Sec. 4.7), not the cam.
    """
    from graphkin.render.live_newton import newton_data

    if mech.cams:
        raise InputError("no live page: this cam mechanism's equivalent linkage is solved by "
                         "Newton's method, which would turn the linkage, not the cam "
                         "(Sec. 4.7); see the cycle with graphkin plot or animate", file=source)

    data, js = newton_data(mech, source)
    # Newton's page has no table law's rates: _Engine refuses a table with rates unswept by
    # the constructions, so a follower's rates here are a linear law's constants
    js += _follow(data, mech, None)
    made = {n for lk in mech.links.values() for n in lk.points}
    data.update(title=mech.title or source, unit=mech.length_unit,
                drive=_drive_data(mech, mech.drives[0].label, made), file=file_data,
                style={k: STYLES[k] for k in ("link", "plate", "pin", "result-line", "aux-line")
                       if k in STYLES})
    js = RUNTIME + js
    from graphkin.render.live_centers import centers_data

    names = list(made)   # every named point is on the Newton page's posture
    data["centers"], cjs = centers_data(mech, names, made)
    return data, js + cjs


def _follow(data: dict[str, Any], mech: Mechanism, rates: dict[str, list[str]] | None) -> str:
    """The page's followers (``data["follow"]``) and the JavaScript that moves them; "" if none.

    A drive that follows the first by a law moves with it on every drag, as in a
    sweep (Sec. 5.4; :mod:`graphkin.render.live_laws`).
    """
    from graphkin.render.live_laws import LAWS_JS, follow_data

    follow = follow_data(mech, rates)
    if follow is None:
        return ""
    data["follow"] = follow
    return LAWS_JS


_DIMENSIONS = ("local_a", "local_b", "local_p", "local_q", "radius", "distance", "offset")


def _coupler_points(mech: Mechanism, steps: Any, names: list[str],
                    made: set[str]) -> dict[str, dict[str, Any]]:
    """The points of one moving link that can be dragged: where their numbers sit in ``K``.

    A point of one link only, laid off by a ``rigid`` step (case 1), whose
    velocity and acceleration images are ``similar`` to the link (Sec. 3.5,
    Mehmke) or found by a difference (no dimension), and whose local
    coordinates no other step carries.  Dragging it changes the link's shape:
    the ``rigid`` step's ``q - p`` and the images' complex ratios.
    """
    owners: dict[str, list[str]] = {}
    for lid, lk in mech.links.items():
        for n in lk.points:
            owners.setdefault(n, []).append(lid)
    # a point of a path (a slider's or slot's point, a line's points, a rolling center) is
    # read by the path's own steps through their numbers: not draggable
    paths: tuple[Any, ...] = (*mech.sliders, *mech.slots, *mech.rolling)
    on_path = {getattr(p, a) for p in paths for a in ("point", "center")
               if isinstance(getattr(p, a, None), str)}
    path_xy = {(p.on, tuple(map(float, q))) for p in paths
               for q in (getattr(p, a, None) for a in ("p0", "p1", "center", "on_center"))
               if isinstance(q, (tuple, list))}
    out: dict[str, dict[str, Any]] = {}
    for n, lids in owners.items():
        if len(lids) != 1 or lids[0] == FRAME or n not in made or n in on_path:
            continue
        lid = lids[0]
        local = mech.links[lid].points[n]
        if (lid, tuple(map(float, local))) in path_xy:
            continue
        mine = {n, f"v({n})", f"a({n})"}
        rigid = [s for s in steps if s.outputs == (n,) and s.op == "rigid"]
        readers = [s for s in steps if mine & set(s.inputs)
                   and any(k in s.params for k in _DIMENSIONS)]
        if len(rigid) != 1 or readers or f"{n}.0" not in names:
            continue
        images = []
        ok = True
        for s in steps:
            if not (mine & set(s.outputs)) or s.outputs == (n,):
                continue
            if s.op == "similar" and f"{s.outputs[0]}.0" in names and \
                    tuple(s.params["local_p"]) == tuple(local):
                images.append({"slots": [names.index(f"{s.outputs[0]}.0"),
                                         names.index(f"{s.outputs[0]}.1")],
                               "a": list(s.params["local_a"]), "b": list(s.params["local_b"])})
            elif s.op not in ("velocity_difference", "acceleration_difference"):
                ok = False
        if not ok:
            continue
        r = rigid[0]
        out[n] = {"link": lid, "anchor": r.inputs[0], "angle": r.inputs[1],
                  "offset": float(r.params.get("offset", 0.0)),
                  "p": [float(v) for v in r.params["local_p"]],
                  "slots": [names.index(f"{n}.0"), names.index(f"{n}.1")], "images": images}
    return out


def live_body(title: str, hint: str | None = None) -> str:
    """The page's markup inside ``<body>`` (the page and the notebook widget share it).

    ``hint``: the first line, what the user drags (:func:`drag_hint`, ``data["hint"]``).
    """
    t = html.escape(title)
    h = html.escape(hint or "Drag the crank's moving pin or a frame pivot (filled handles); "
                    "every panel is the recorded construction, re-solved in the page.")
    return f"""<header><h1>{t}</h1>
<p class="hint">{h}</p>
<div class="controls"><label>drive <input id="gk-drive" type="range"></label>
<output id="gk-drive-val"></output>
<label>branch at <select id="gk-branch"></select></label>
<button id="gk-switch" type="button">Switch the branch</button>
<button id="gk-undo" type="button">Undo</button>
<button id="gk-reset" type="button">Reset</button>
<button id="gk-save" type="button">Save the edited mechanism</button></div>
<div class="controls" id="gk-pen-bar"><button id="gk-pen" type="button" aria-pressed="false">Pen:
draw my velocity polygon</button>
<label>polygon <select id="gk-pen-panel"><option value="velocity">velocity</option>
<option value="acceleration">acceleration</option></select></label>
<label>next point <input id="gk-pen-label" size="4"></label>
<button id="gk-pen-clear" type="button">Clear my drawing</button>
<button id="gk-pen-export" type="button">Export my drawing (SVG)</button></div>
<p id="gk-status" role="status"></p></header>
<main><figure><figcaption>Posture</figcaption><svg id="gk-posture"></svg></figure>
<figure><figcaption>Velocity polygon</figcaption><svg id="gk-velocity"></svg></figure>
<figure><figcaption>Acceleration polygon</figcaption><svg id="gk-acceleration"></svg></figure>
<figure><figcaption>Kennedy circle</figcaption><svg id="gk-kennedy"></svg>
<p id="gk-centers-note"></p></figure>
<figure><figcaption>Curvature</figcaption><svg id="gk-curvature"></svg>
<p id="gk-curvature-note"></p></figure>
<figure><figcaption>Force polygons</figcaption><svg id="gk-forces"></svg>
<p id="gk-forces-note"></p></figure>
<figure><figcaption>Free bodies</figcaption><svg id="gk-bodies"></svg></figure>
</main>
<table id="gk-table"></table>
<table id="gk-force-table"></table>
"""


def live_html(mech: Mechanism, file_data: dict[str, Any], source: str, *,
              turn: bool = True) -> str:
    """The whole page, self-contained (one file, no network); ``turn``: see :func:`live_data`."""
    data, js = live_data(mech, file_data, source, turn=turn)
    title = html.escape(str(data["title"]))
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title} (live)</title>
<style>{PAGE_CSS}</style></head>
<body>
{live_body(str(data["title"]), data.get("hint"))}<script id="gk-data" type="application/json">
{script_json(data)}</script>
<script>
{js}
{LIVE_LIB}
{APP_JS}
window.graphkinLive = gkLiveApp(document,
  JSON.parse(document.getElementById("gk-data").textContent), {js_string(source)}, null);
</script>
</body></html>
"""
