"""A cam on a link the linkage moves: the cam's angle from the linkage solved without the cam.

A ``[[cams]]`` cam usually sits on a drive's link, so its angle is the
drive's.  It may instead sit on any link pinned to the frame that the rest of
the mechanism moves: the rocker of a four-bar, a gear turned through a
rolling contact, the follower of an earlier cam.  Its angle at the file's
posture is then the one the linkage gives that link, and the linkage that
moves it does not depend on the cam (the follower is driven *by* the cam,
never the other way): so the file is read in two passes,

1. the file without the cam's follower and every link the follower reaches
   without passing the frame or the cam's link (the follower's side: a rod, a
   slider it drives), and without the later cams' followers' sides, is solved
   as any mechanism (Sec. 2.8); the cam link's angle θ is read off that
   posture (:meth:`~graphkin.kinematics.solution.Solution.angle_rad`);
2. the cam is replaced by its equivalent linkage at Θ = s(θ − (axis − 90°))
   (Sec. 4.7, :func:`graphkin.cams.joint.expand`) and the whole file solved.

The first pass's posture is the second's up to the cam link: the same
groups, the same assembly hints.  Where the linkage does not place the cam's
link on its own (the cam's link moved by its own follower, a drive on the
follower's side) the file is refused in one line naming the cam's key.

On the live page the cam turns with its link's angle at every posture, read
from two of the link's points as solved (:mod:`graphkin.render.live_cam_turn`);
over a cycle (:mod:`graphkin.cams.cycle`) the follower moves by its program at
the link's angle swept by the linkage.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 2.8 (the posture), 4.7 (the
equivalent linkage), 6.3 (the follower's displacement).
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

from graphkin.errors import GraphkinError, InputError

__all__ = ["follower_side", "driving_data", "linkage_angle", "link_turning"]


#: A drive's rates: not needed for the angle, and not read in the first pass.
_RATES = ("omega", "alpha", "velocity", "acceleration", "vx", "vy", "ax", "ay")


def _rows(data: Mapping[str, Any], name: str) -> list[Mapping[str, Any]]:
    raw = data.get(name, [])
    rows = [raw] if isinstance(raw, Mapping) else raw if isinstance(raw, list) else []
    return [r for r in rows if isinstance(r, Mapping)]


def _pairs(data: Mapping[str, Any]) -> Iterable[tuple[str, str]]:
    """Every pair of links a joint of ``data`` holds together (pins, sliders, slots, rolling)."""
    links = data.get("links", {})
    owners: dict[str, list[str]] = {}
    for lid, pts in links.items():
        if isinstance(pts, Mapping):
            for n in pts:
                owners.setdefault(str(n), []).append(str(lid))
    for ids in owners.values():
        for a in ids:
            for b in ids:
                if a != b:
                    yield a, b
    for name in ("sliders", "slots", "rolling"):
        for r in _rows(data, name):
            yield str(r.get("link")), str(r.get("on"))
    for d in _rows(data, "drive"):
        if "relative_to" in d:
            yield str(d.get("link")), str(d.get("relative_to"))


def follower_side(data: Mapping[str, Any], followers: Iterable[str],
                  barrier: Iterable[str]) -> set[str]:
    """The followers and every link they reach by joints without passing ``barrier``.

    ``barrier`` holds the frame and the cam's link: what lies beyond them is the
    linkage that moves the cam, which the followers do not move.
    """
    adj: dict[str, set[str]] = {}
    for a, b in _pairs(data):
        adj.setdefault(a, set()).add(b)
        adj.setdefault(b, set()).add(a)
    stop = set(barrier) | {"1"}
    out = {str(f) for f in followers} - stop
    todo = list(out)
    while todo:
        for b in adj.get(todo.pop(), ()):
            if b not in out and b not in stop:
                out.add(b)
                todo.append(b)
    return out


def driving_data(data: Mapping[str, Any], side: set[str]) -> dict[str, Any]:
    """``data`` without the links of ``side`` and every joint, drive or hint that names them.

    Only the tables the posture needs are kept (no forces, bodies or rates).
    """
    links = {str(k): v for k, v in data.get("links", {}).items() if str(k) not in side}
    out: dict[str, Any] = {k: data[k] for k in ("title", "units") if k in data}
    out["links"] = links
    for name in ("sliders", "slots", "rolling"):
        rows = [dict(r) for r in _rows(data, name)
                if str(r.get("link")) not in side and str(r.get("on")) not in side]
        if rows:
            out[name] = rows
    drives = []
    for d in _rows(data, "drive"):
        follows = d.get("follows")
        if str(d.get("link")) in side or str(d.get("relative_to", "1")) in side or (
                isinstance(follows, Mapping) and str(follows.get("link")) in side):
            continue
        drives.append({k: v for k, v in d.items() if k not in _RATES})
    if drives:
        out["drive"] = drives
    names = {str(n) for pts in links.values() if isinstance(pts, Mapping) for n in pts}
    hints = data.get("assembly", {})
    if isinstance(hints, Mapping):
        out["assembly"] = {k: v for k, v in hints.items() if str(k) in names}
    return out


def linkage_angle(data: Mapping[str, Any], cam_link: str, followers: Iterable[str],
                  key: str, source: str) -> float:
    """The cam link's angle θ (rad) at the file's posture, solved without the cams.

    Parameters
    ----------
    data : mapping
        The mechanism file's data, the earlier cams already replaced by their
        equivalent linkages (:func:`graphkin.cams.joint.expand`), this cam and
        the later ones not.
    cam_link : str
    followers : iterable of str
        The followers of this cam and the later ones.
    key : str
        ``cams[i]``.
    source : str

    Raises
    ------
    InputError
        One line naming ``cams[i].link``, when the linkage without the cam does
        not place the cam's link.
    """
    from graphkin.mechanisms import from_dict

    side = follower_side(data, followers, [cam_link])
    first = driving_data(data, side)
    why = ""
    if cam_link not in first["links"]:
        why = "no link holds it"
    elif "drive" not in first:
        why = "every drive is on the follower's side"
    if not why:
        try:
            return float(from_dict(first, source).solve().angle_rad(cam_link))
        except GraphkinError as exc:
            lines = exc.message.splitlines()
            why = lines[0] if lines else type(exc).__name__
    raise InputError(
        f"the cam's link {cam_link} is not a drive by its angle, so its angle is the "
        f"linkage's (the file without the follower's side: link(s) {', '.join(sorted(side))}), "
        f"which does not place it: {why}", key=f"{key}.link", file=source)


def link_turning(mech: Any, link: str, center: str) -> Any:
    """θ, dθ/dx and d²θ/dx² of ``link`` at arrays of the first drive's value ``x`` (Sec. 3.11).

    ``mech`` is the linkage that moves the cam's link (:func:`driving_data`,
    its first drive at unit speed): its posture and polygons are evaluated on
    the whole array at once (the same recorded steps as a sweep, no loop over
    postures).  With the drive at unit speed and at rest in acceleration, the
    link's ω and α are the kinematic coefficients θ' and θ'' (Sec. 3.11),
    read from two of its points: the cam's center ``P`` (on the frame) and
    another ``Q``, ``θ = arg(Q − P) − arg(q − p)`` (their own coordinates),
    ``ω = (r × v_Q)/|r|²`` and ``α = (r × a_Q)/|r|²`` with ``r = Q − P``.

    Returns
    -------
    callable
        ``x -> (θ, θ', θ'')``, arrays of ``x``'s shape (NaN where the linkage
        cannot be assembled).
    """
    import math

    import numpy as np

    from graphkin.kinematics.sweep.engine import _engine
    from graphkin.tolerance import DEFAULT_TOL

    pts = mech.links[link].points
    p = pts[center]
    far = max((n for n in pts if n != center),
              key=lambda n: math.hypot(pts[n][0] - p[0], pts[n][1] - p[1]), default=None)
    if far is None or math.hypot(pts[far][0] - p[0], pts[far][1] - p[1]) == 0.0:
        raise InputError(f"the cam's link {link} has no point but its center {center}: its "
                         "angle is not defined by two of its points", key="links." + link,
                         file=mech.source)
    phi = math.atan2(pts[far][1] - p[1], pts[far][0] - p[0])
    eng = _engine(mech, DEFAULT_TOL)
    if eng.method != "construction" or eng.pc is None or eng.pol is None:
        raise InputError(f"the linkage that moves the cam's link {link} is not swept by the "
                         f"constructions here ({eng.reason or eng.method})", key="links." + link,
                         file=mech.source)

    def turning(x: Any) -> Any:
        xs = np.atleast_1d(np.asarray(x, dtype=float))
        ev = eng.posture(xs)
        evv, eva = eng.rates(ev, unit=True)
        P = np.asarray(ev[center], dtype=float)
        Q = np.asarray(ev[far], dtype=float)
        r = Q[..., :2] / Q[..., 2:3] - P[..., :2] / P[..., 2:3]
        vq = np.asarray(evv[f"v({far})"], dtype=float)
        aq = np.asarray(eva[f"a({far})"], dtype=float)
        rr = r[..., 0] ** 2 + r[..., 1] ** 2
        th = np.arctan2(r[..., 1], r[..., 0]) - phi
        w = (r[..., 0] * vq[..., 1] - r[..., 1] * vq[..., 0]) / rr
        a = (r[..., 0] * aq[..., 1] - r[..., 1] * aq[..., 0]) / rr
        shape = np.shape(x)
        return th.reshape(shape), w.reshape(shape), a.reshape(shape)

    return turning
