"""Hypothesis strategies: random rolling-contact arrangements whose true posture is known.

As in :mod:`strategies`, each strategy first chooses the posture in the world
(every link's pose, the contact where the circles touch), then writes each
link's points in that link's own frame, so ``truth`` is the exact answer.
Each kind of Secs. 3.7, 4.7 and 7.12-7.16 has its own strategy:

* a circle on a line on the frame: a wheel driven by a crank and coupler
  (Example 3.9); a wheel on a driven carriage;
* a circle on a line of a moving link: a pinion on a crank or on a driven
  slider rolling on a rack pivoted to the frame (the rack's line may start
  at its pivot);
* a rack sliding on the frame under a pinion on a fixed pivot, the pinion or
  the rack driven;
* a circle on a circle, outside or inside: gears on fixed centers (either as
  the rolling ``link``), three gears in a row, a planet on a driven arm round
  a fixed sun or in a fixed ring, a planet on an arm between a driven sun and
  a fixed ring (the arm the output), a planet on a driven arm and a driven sun
  (two inputs), a ring driven by a planet round a fixed or a driven sun.

At the file's drive a contact places one link (the rolling link, or the one
it rolls on, or the arm: :mod:`graphkin.kinematics.analytic.phase`); its
``angle`` is written as that link's true angle.  A rack whose travel the
contact sets stands as drawn: its origin on the line through the frame's
origin across the slide.  Assembly hints are the true world positions.
"""

from __future__ import annotations

import math
from typing import Any

from hypothesis import strategies as st
from strategies import RandomMechanism, _add, _e, _sub, _to_local

XY = tuple[float, float]
Pose = tuple[float, float, float]

__all__ = ["rolling_arrangements", "ROLLING_KINDS"]

_ANG = st.floats(-math.pi, math.pi)


def _rate(draw: Any) -> float:
    """A rate of either sense, not small."""
    return draw(st.sampled_from([-1.0, 1.0])) * draw(st.floats(1.0, 20.0))


def _pose(draw: Any, near: XY) -> Pose:
    """A random local frame for a link near the world point ``near``."""
    return (near[0] + draw(st.floats(-5, 5)), near[1] + draw(st.floats(-5, 5)), draw(_ANG))


def _perp(v: XY) -> XY:
    return (-v[1], v[0])


def _build(kind: str, frame: dict[str, XY], links: dict[str, tuple[Pose, dict[str, XY]]],
           extra: dict[str, Any]) -> RandomMechanism:
    data: dict[str, Any] = {"title": kind, "links": {"1": {n: list(p)
                                                         for n, p in frame.items()}}}
    for lid, (pose, pts) in links.items():
        data["links"][lid] = {n: list(_to_local(pose, p)) for n, p in pts.items()}
    data.update(extra)
    return RandomMechanism(kind, data, {lid: pose for lid, (pose, _) in links.items()})


def _deg(t: float) -> float:
    return math.degrees(t)


def _angle_drive(link: str, pose: Pose, draw: Any) -> dict[str, Any]:
    return {"link": link, "angle": _deg(pose[2]), "omega": _rate(draw),
            "alpha": draw(st.floats(-20, 20))}


def _slide_drive(link: str, travel: float, draw: Any) -> dict[str, Any]:
    return {"link": link, "position": travel, "velocity": _rate(draw),
            "acceleration": draw(st.floats(-20, 20))}


@st.composite
def _wheel_by_coupler(draw: Any) -> RandomMechanism:
    """Example 3.9: crank 2, coupler 3, wheel 4 rolling on the ground (a line of the frame)."""
    psi = draw(st.floats(-0.5, 0.5))
    u = _e(psi)
    r = draw(st.floats(2, 6))
    side = draw(st.sampled_from(["left", "right"]))
    sg = 1.0 if side == "left" else -1.0
    base = (draw(st.floats(-5, 5)), -8.0)
    g = _add(_add(base, u, draw(st.floats(4, 16))), _perp(u), sg * r)
    a = _e(draw(_ANG))
    a = (4 * a[0], 4 * a[1])
    b = _add(g, _e(draw(_ANG)), draw(st.floats(0.3, 0.9)) * r)
    ab = _sub(b, a)
    # away from the toggles: the coupler crosses the line of B's path, and A, B and the
    # contact C are not in line
    c = _add(g, _perp(u), -sg * r)
    cb = _sub(b, c)
    for v, w in ((ab, u), (ab, cb)):
        sine = abs(v[0] * w[1] - v[1] * w[0]) / (math.hypot(*v) * math.hypot(*w))
        if sine < 0.35:
            raise _Reject
    p2, p3, p4 = _pose(draw, (0, 0)), _pose(draw, a), _pose(draw, g)
    frame = {"O2": (0.0, 0.0), "G1": base, "G2": _add(base, u, 10.0)}
    links = {"2": (p2, {"O2": (0.0, 0.0), "A": a}), "3": (p3, {"A": a, "B": b}),
             "4": (p4, {"G": g, "B": b})}
    extra = {"rolling": [{"link": 4, "on": 1, "circle": {"center": "G", "radius": r},
                          "line": ["G1", "G2"], "side": side, "angle": _deg(p4[2])}],
             "drive": _angle_drive("2", p2, draw), "assembly": {"B": list(b), "G": list(g)}}
    return _build("wheel by coupler", frame, links, extra)


@st.composite
def _wheel_on_carriage(draw: Any) -> RandomMechanism:
    """A wheel 3 pinned to a driven carriage 2 that slides parallel to the ground."""
    psi = draw(_ANG)
    u = _e(psi)
    r = draw(st.floats(1, 8))
    side = draw(st.sampled_from(["left", "right"]))
    sg = 1.0 if side == "left" else -1.0
    s0 = (draw(st.floats(-5, 5)), draw(st.floats(-5, 5)))
    t = draw(st.floats(1, 15))
    p = _add(s0, u, t)
    g0 = _add(s0, _perp(u), -sg * r)
    off = draw(st.floats(-5, 5))  # the carriage's x axis runs along its slide
    p2 = (p[0] - off * u[0], p[1] - off * u[1], psi)
    p3 = _pose(draw, p)
    frame = {"S0": s0, "S1": _add(s0, u, 10.0), "G1": g0, "G2": _add(g0, u, 10.0)}
    links = {"2": (p2, {"P": p}), "3": (p3, {"P": p, "Q": _add(p, _e(draw(_ANG)), r)})}
    extra = {"sliders": [{"link": 2, "on": 1, "point": "P", "line": ["S0", "S1"]}],
             "rolling": [{"link": 3, "on": 1, "circle": {"center": "P", "radius": r},
                          "line": ["G1", "G2"], "side": side, "angle": _deg(p3[2])}],
             "drive": _slide_drive("2", t, draw)}
    return _build("wheel on a carriage", frame, links, extra)


@st.composite
def _pinion_on_pivoted_rack(draw: Any) -> RandomMechanism:
    """A pinion 3 on a crank 2 or on a driven slider 2, rolling on a rack 4 pivoted at O4."""
    carrier = draw(st.sampled_from(["crank", "slider"]))
    r = draw(st.floats(1, 6))
    side = draw(st.sampled_from(["left", "right"]))
    sg = 1.0 if side == "left" else -1.0
    frame: dict[str, XY] = {}
    if carrier == "crank":
        p = _e(draw(_ANG))
        p = (8 * p[0], 8 * p[1])
        p2 = _pose(draw, (0, 0))
        frame["O2"] = (0.0, 0.0)
        two = (p2, {"O2": (0.0, 0.0), "P": p})
        drive = _angle_drive("2", p2, draw)
        sliders: list[dict[str, Any]] = []
    else:
        sl = draw(_ANG)
        s0 = (draw(st.floats(-5, 5)), draw(st.floats(-5, 5)))
        t = draw(st.floats(1, 12))
        p = _add(s0, _e(sl), t)
        frame.update({"S0": s0, "S1": _add(s0, _e(sl), 10.0)})
        p2 = (p[0], p[1], sl)
        two = (p2, {"P": p})
        drive = _slide_drive("2", t, draw)
        sliders = [{"link": 2, "on": 1, "point": "P", "line": ["S0", "S1"]}]
    u = _e(draw(_ANG))
    c = _add(p, _perp(u), -sg * r)  # the contact: the rack's line runs through it
    at_pivot = draw(st.booleans())
    o4 = _add(c, u, draw(st.sampled_from([-1.0, 1.0])) * draw(st.floats(4, 12)))
    if not at_pivot:
        o4 = _add(o4, _perp(u), draw(st.floats(-8, 8)))
    # the pinion's center runs on the line offset by r: its tangent from O4 must exist
    # well apart from its toggle (the center not near the circle of the path's offset)
    n = _perp(u)
    d = abs((o4[0] - p[0]) * n[0] + (o4[1] - p[1]) * n[1])
    if math.hypot(*_sub(p, o4)) < d + 1.0:
        raise _Reject
    f1 = o4 if at_pivot else _add(c, u, -6.0)
    frame["O4"] = o4
    p4, p3 = _pose(draw, o4), _pose(draw, p)
    links = {"2": two, "3": (p3, {"P": p, "Q": _add(p, _e(draw(_ANG)), r / 2)}),
             "4": (p4, {"O4": o4, "F1": f1, "F2": _add(f1, u, 12.0)})}
    extra = {"sliders": sliders,
             "rolling": [{"link": 3, "on": 4, "circle": {"center": "P", "radius": r},
                          "line": ["F1", "F2"], "side": side, "angle": _deg(p3[2])}],
             "drive": drive, "assembly": {"F2": list(links["4"][1]["F2"])}}
    return _build(f"pinion on a {carrier}, pivoted rack", frame, links, extra)


@st.composite
def _sliding_rack(draw: Any) -> RandomMechanism:
    """A rack 3 sliding on the frame under a pinion 2 on the fixed pivot O2; either driven."""
    driven = draw(st.sampled_from(["pinion", "rack"]))
    psi = draw(_ANG)
    u, n = _e(psi), _perp(_e(psi))
    r = draw(st.floats(1, 8))
    side = draw(st.sampled_from(["left", "right"]))
    sg = 1.0 if side == "left" else -1.0
    o2 = (draw(st.floats(-5, 5)), draw(st.floats(-5, 5)))
    c = _add(o2, n, -sg * r)
    h = -sg * draw(st.floats(0.5, 5))  # the slide runs beyond the rack's line
    w = _add(_add(c, n, h), u, draw(st.floats(-8, 8)))  # the rack's slider point R
    if driven == "pinion":
        # as drawn: the rack's origin on the line through the frame's origin across the slide
        k = n[0] * w[0] + n[1] * w[1]
        p3 = (k * n[0], k * n[1], psi)
    else:
        off = draw(st.floats(-5, 5))
        p3 = (w[0] - off * u[0], w[1] - off * u[1], psi)
    p2 = _pose(draw, o2)
    s0 = _add(w, u, -draw(st.floats(1, 10)))
    frame = {"O2": o2, "S0": s0, "S1": _add(s0, u, 10.0)}
    links = {"2": (p2, {"O2": o2, "A": _add(o2, _e(draw(_ANG)), r)}),
             "3": (p3, {"R": w, "L0": _add(c, u, -5.0), "L1": _add(c, u, 5.0)})}
    travel = (w[0] - s0[0]) * u[0] + (w[1] - s0[1]) * u[1]
    extra = {"sliders": [{"link": 3, "on": 1, "point": "R", "line": ["S0", "S1"]}],
             "rolling": [{"link": 2, "on": 3, "circle": {"center": "O2", "radius": r},
                          "line": ["L0", "L1"], "side": side}],
             "drive": (_angle_drive("2", p2, draw) if driven == "pinion"
                       else _slide_drive("3", travel, draw))}
    if driven == "rack":  # the contact places the pinion (else the rack's travel: no angle)
        extra["rolling"][0]["angle"] = _deg(p2[2])
    return _build(f"sliding rack, {driven} driven", frame, links, extra)


@st.composite
def _gears(draw: Any) -> RandomMechanism:
    """Gears 2 and 3 on the fixed pivots O2, O3, outside or inside; the pinion 2 driven."""
    contact = draw(st.sampled_from(["outside", "inside"]))
    order = draw(st.sampled_from(["pinion rolls", "gear rolls"]))
    if contact == "inside":
        order = "pinion rolls"  # the smaller circle rolls inside the larger
    r2 = draw(st.floats(2, 10))
    r3 = r2 * draw(st.floats(1.3, 4.0)) if contact == "inside" else draw(st.floats(2, 20))
    dist = r2 + r3 if contact == "outside" else r3 - r2
    o2 = (0.0, 0.0)
    o3 = _add(o2, _e(draw(_ANG)), dist)
    p2, p3 = _pose(draw, o2), _pose(draw, o3)
    frame = {"O2": o2, "O3": o3}
    links = {"2": (p2, {"O2": o2, "A": _add(o2, _e(draw(_ANG)), r2)}),
             "3": (p3, {"O3": o3, "B": _add(o3, _e(draw(_ANG)), r3)})}
    if order == "pinion rolls":
        roll = {"link": 2, "on": 3, "circle": {"center": "O2", "radius": r2},
                "on_circle": {"center": "O3", "radius": r3}}
    else:
        roll = {"link": 3, "on": 2, "circle": {"center": "O3", "radius": r3},
                "on_circle": {"center": "O2", "radius": r2}}
    roll.update({"contact": contact, "angle": _deg(p3[2])})  # the gear 3 is the one placed
    extra = {"rolling": [roll], "drive": _angle_drive("2", p2, draw)}
    return _build(f"gears {contact}, {order}", frame, links, extra)


@st.composite
def _planet(draw: Any) -> RandomMechanism:
    """A planet 3 on the arm 2 about O: round a fixed sun or ring, or with driven sun 4."""
    kind = draw(st.sampled_from(["fixed sun", "fixed ring", "driven sun", "sun and ring",
                                 "ring output", "two inputs, ring output"]))
    rs = draw(st.floats(3, 15))
    rp = draw(st.floats(1, 10)) if kind != "fixed ring" else rs * draw(st.floats(0.15, 0.7))
    arm = rs + rp if kind != "fixed ring" else rs - rp
    p = _add((0.0, 0.0), _e(draw(_ANG)), arm)
    p2, p3, p4 = _pose(draw, (0, 0)), _pose(draw, p), _pose(draw, (0, 0))
    frame = {"O": (0.0, 0.0)}
    links: dict[str, tuple[Pose, dict[str, XY]]] = {
        "2": (p2, {"O": (0.0, 0.0), "P": p}),
        "3": (p3, {"P": p, "Q": _add(p, _e(draw(_ANG)), rp / 2)})}
    planet = {"link": 3, "circle": {"center": "P", "radius": rp}, "angle": _deg(p3[2])}
    if kind in ("fixed sun", "fixed ring"):
        rolling = [{**planet, "on": 1, "on_circle": {"center": "O", "radius": rs},
                    "contact": "outside" if kind == "fixed sun" else "inside"}]
        drive: Any = _angle_drive("2", p2, draw)
    else:
        links["4"] = (p4, {"O": (0.0, 0.0), "S": _add((0.0, 0.0), _e(draw(_ANG)), rs)})
        rolling = [{**planet, "on": 4, "on_circle": {"center": "O", "radius": rs},
                    "contact": "outside"}]
        if kind in ("ring output", "two inputs, ring output"):
            # the ring 5 about O meshes with the planet inside; fixed sun: the frame's circle
            ring = rs + 2 * rp
            p5 = _pose(draw, (0, 0))
            links["5"] = (p5, {"O": (0.0, 0.0), "R": _add((0.0, 0.0), _e(draw(_ANG)), ring)})
            if kind == "ring output":
                del links["4"]
                rolling[0]["on"] = 1
                drive = _angle_drive("2", p2, draw)
            else:
                drive = [_angle_drive("2", p2, draw), _angle_drive("4", p4, draw)]
            rolling.append({"link": 3, "on": 5, "circle": {"center": "P", "radius": rp},
                            "on_circle": {"center": "O", "radius": ring}, "contact": "inside",
                            "angle": _deg(p5[2])})  # this contact places the ring
        elif kind == "driven sun":
            if draw(st.booleans()):  # the sun as the rolling link, on the planet
                rolling = [{"link": 4, "on": 3, "circle": {"center": "O", "radius": rs},
                            "on_circle": {"center": "P", "radius": rp},
                            "contact": "outside", "angle": _deg(p3[2])}]
            drive = [_angle_drive("2", p2, draw), _angle_drive("4", p4, draw)]
        else:
            ring = rs + 2 * rp
            rolling.append({"link": 3, "on": 1, "circle": {"center": "P", "radius": rp},
                            "on_circle": {"center": "O", "radius": ring}, "contact": "inside",
                            "angle": _deg(p2[2])})  # this contact places the arm
            drive = _angle_drive("4", p4, draw)
    return _build(f"planet, {kind}", frame, links, {"rolling": rolling, "drive": drive})


@st.composite
def _gear_chain(draw: Any) -> RandomMechanism:
    """Three gears in a row on fixed pivots (a simple train, Sec. 7.12); gear 2 driven."""
    r = [draw(st.floats(2, 10)) for _ in range(3)]
    o = [(0.0, 0.0)]
    o.append(_add(o[0], _e(draw(_ANG)), r[0] + r[1]))
    t = draw(st.floats(0.4, 2 * math.pi - 0.4))  # the third gear clear of the first
    if math.hypot(*_sub(_add(o[1], _e(math.atan2(-o[1][1], -o[1][0]) + t), r[1] + r[2]),
                        o[0])) < r[0] + r[2] + 0.5:
        raise _Reject
    o.append(_add(o[1], _e(math.atan2(-o[1][1], -o[1][0]) + t), r[1] + r[2]))
    names = ["O2", "O3", "O4"]
    poses = [_pose(draw, c) for c in o]
    links = {str(k + 2): (poses[k], {names[k]: o[k]}) for k in range(3)}
    rolling = []
    for k in range(2):
        a, b = (k, k + 1) if draw(st.booleans()) else (k + 1, k)
        rolling.append({"link": a + 2, "on": b + 2,
                        "circle": {"center": names[a], "radius": r[a]},
                        "on_circle": {"center": names[b], "radius": r[b]},
                        "angle": _deg(poses[k + 1][2])})  # the contact places the next gear
    extra = {"rolling": rolling, "drive": _angle_drive("2", poses[0], draw)}
    return _build("gear chain", dict(zip(names, o)), links, extra)


class _Reject(Exception):
    """A drawn arrangement too near a toggle: drawn again."""


ROLLING_KINDS = {
    "wheel by coupler": _wheel_by_coupler,
    "wheel on a carriage": _wheel_on_carriage,
    "pinion on a pivoted rack": _pinion_on_pivoted_rack,
    "sliding rack": _sliding_rack,
    "gears": _gears,
    "gear chain": _gear_chain,
    "planet": _planet,
}


@st.composite
def _retry(draw: Any, kind: str) -> RandomMechanism:
    for _ in range(20):
        try:
            return draw(ROLLING_KINDS[kind]())  # type: ignore[no-any-return]
        except _Reject:
            continue
    from hypothesis import assume

    assume(False)
    raise AssertionError  # pragma: no cover


def rolling_arrangements(kind: str | None = None) -> st.SearchStrategy[RandomMechanism]:
    """Random rolling arrangements of one kind (a key of ``ROLLING_KINDS``) or of any."""
    if kind is not None:
        return _retry(kind)
    return st.one_of(*[_retry(k) for k in ROLLING_KINDS])
