"""The live page of a cam mechanism: held at the file's cam angle, where its linkage holds.

A mechanism file's disk cam (``[[cams]]``) is solved through its equivalent
linkage through the centers of curvature at the file's cam angle (Sec. 4.7,
:mod:`graphkin.cams.joint`): a coupler ``K<f>``-``T<f>`` (roller, knife edge)
or a slot (flat face) whose length and pins are the cam's at *that* angle
only.  The page's construction is that linkage's, so re-solving it at
another drive angle would turn the linkage, not the cam: the follower would
leave the cam's displacement program (Example 6.6's follower point 5° away:
y = 49.882 where the cam's program says 49.870).

So the page of a cam mechanism

* keeps the drive at the file's cam angle: a drag of the slider (or a call of
  ``setDrive``) returns to it and the page says why in one line, naming the
  file and the drive's key (:func:`cam_hold`);
* lets nothing move that the cam's linkage places (the cam's center, an
  oscillating follower's pivot, the guide, ``K<f>``, ``T<f>``, the face's slot):
  they are the cam file's, rebuilt from it by ``graphkin solve``
  (:func:`cam_points`); the rest of the mechanism is dragged as usual;
* draws no coupler curves (the linkage turned through a cycle is not the cam
  mechanism; ``graphkin plot`` and ``animate`` follow the cam's program).

Every value the page shows is then the one ``graphkin solve`` gives for the
file the page saves (tests/render/test_live_cams.py).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 4.7 (the equivalent linkage),
Secs. 6.3 and 6.9-6.10 (the follower's motion from the cam's program).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from graphkin.errors import InputError
from graphkin.mechanisms.model import Mechanism

__all__ = ["cam_hold", "cam_points", "hold_cams"]


def _entries(mech: Mechanism) -> list[Mapping[str, Any]]:
    """The file's ``[[cams]]`` tables, as written (one per :attr:`Mechanism.cams`)."""
    written = mech.cams[0].data if mech.cams else None
    raw = written.get("cams") if written is not None else None
    entries = [raw] if isinstance(raw, Mapping) else raw if isinstance(raw, list) else []
    return [e if isinstance(e, Mapping) else {} for e in entries]


def cam_points(mech: Mechanism) -> set[str]:
    """The points the cams' equivalent linkages place, from the cam files (Sec. 4.7).

    The cam's center (``center``, default ``O2``), an oscillating follower's
    pivot (``pivot``, default ``O4``), the translating follower's guide
    ``G<f>a``, ``G<f>b``, the center of curvature ``K<f>``, the trace point
    ``T<f>`` and the flat face's slot ``F<f>a``, ``F<f>b``.  ``graphkin solve``
    rebuilds them from the cam file at the file's cam angle, so the page does
    not move them.
    """
    out: set[str] = set()
    entries = _entries(mech)
    for i, j in enumerate(mech.cams):
        e = entries[i] if i < len(entries) else {}
        fl = j.follower
        out |= {str(e.get("center", "O2")), f"K{fl}", f"T{fl}", f"G{fl}a", f"G{fl}b",
                f"F{fl}a", f"F{fl}b"}
        if j.cam.follower.kind.oscillating:
            out.add(str(e.get("pivot", "O4")))
    return out


def cam_hold(mech: Mechanism, source: str) -> dict[str, Any] | None:
    """What the page says when the drive is moved off the file's cam angle; None without cams.

    Returns
    -------
    dict or None
        ``{"why": one line naming the file and the drive's key, "cams": the
        cams' keys, "angle": the file's cam angle (degrees)}``.
    """
    if not mech.cams:
        return None
    d = mech.drives[0]
    deg = math.degrees(d.value)
    keys = [j.key for j in mech.cams]
    # (a cam on another link: the drive's angle is not the cam's, but holds it there)
    what = "cam angle" if all(j.link == d.link for j in mech.cams) else "drive's angle"
    why = InputError(
        f"the page keeps the {what} at the file's {deg:.6g}°: the cam ({', '.join(keys)}) is "
        "replaced by its equivalent linkage through the centers of curvature, which holds at "
        "that angle only (Sec. 4.7); change the angle in the file, or see the cycle with "
        "graphkin plot or animate", key=f"{d.key}.angle", file=source).one_line()
    return {"why": why, "cams": keys, "angle": deg}


def hold_cams(data: dict[str, Any], mech: Mechanism, source: str) -> None:
    """The page's data of a cam mechanism held at the file's cam angle (in place).

    Adds ``data["cam"]`` (:func:`cam_hold`), and takes out of the page's
    handles, branches and assembly hints every point of :func:`cam_points`
    and the drive's handle (the drive is held; on a turning page, only where the
    drive turns a cam: a crank elsewhere keeps its pin).  No-op without cams.  A page
    whose cams turn (``data["turn"]``, :mod:`graphkin.render.live_cam_turn`)
    keeps ``data["cam"]`` for the cam's points but says nothing of a hold:
    its drive's handle is the cam's contact point.
    """
    hold = cam_hold(mech, source)
    if hold is None:
        return
    mine = cam_points(mech)
    data["cam"] = hold
    if data.get("turn") is not None:
        hold["why"] = ""
    data["frame"] = {n: v for n, v in data["frame"].items() if n not in mine}
    data["coupler"] = {n: v for n, v in data["coupler"].items() if n not in mine}
    data["branches"] = {n: v for n, v in data["branches"].items() if n not in mine}
    data["assembly"] = [n for n in data["assembly"] if n not in mine]
    # the drive's pin is a handle unless the drive turns a cam (or the pin is a cam's point)
    drv = data["drive"]
    if drv.get("link") in {j.link for j in mech.cams} or drv.get("pivot") in mine or \
            drv.get("tip") in mine or data.get("turn") is None:
        for k in ("pivot", "tip", "phi"):
            drv.pop(k, None)
