"""The involute constructed as the book constructs it (Sec. 7.5, Step 6; Sec. 7.3, Fig. 7.5).

Divide a portion of the base circle into equal parts A0, A1, A2, ...; draw
the radial lines O A_k and the tangents to the base circle at A_k
(perpendicular to them); with center A_k strike an arc of radius equal to
the arc A0 A_k (the cord unwrapped from the base cylinder) up to the tangent
through A_k: that is the involute's point T_k.  Each act is one recorded
step of a :class:`~graphkin.construction.Construction`; the closed form of
the same points is :func:`involute_polar` (Eqs. 7.14-7.15).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.3, 7.5 (Step 6), 7.10.
"""

from __future__ import annotations

import math
from enum import StrEnum
from typing import Any

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Along
from graphkin.gears.tooth import inv

__all__ = ["Unwind", "involute_construction", "involute_polar", "involute_xy"]


class Unwind(StrEnum):
    """The sense in which the cord unwraps from the base circle, seen from the origin A0.

    ``CCW``: the points A_k follow A0 counterclockwise, and the involute's polar
    angle grows from A0 counterclockwise; ``CW`` is its mirror image.
    """

    CCW = "ccw"
    CW = "cw"


def involute_construction(base: float, *, center: tuple[float, float] = (0.0, 0.0),
                          origin: float = 0.0, parts: int = 6, roll: float = 0.6,
                          sense: Unwind = Unwind.CCW, prefix: str = "") -> Construction:
    """Record the construction of an involute of the base circle ``(center, base)`` (Step 6).

    Parameters
    ----------
    base : float
        The base-circle radius r_b.
    center : (float, float)
        O, the gear's center.
    origin : float
        The polar angle of A0, where the involute begins (radians).
    parts : int
        How many equal parts the roll angle is divided into (points T1..T_parts).
    roll : float
        The angle A0 O A_n rolled off, radians (the involute reaches
        ``r_b √(1 + roll²)``).
    sense : Unwind
        Which way the cord unwraps.
    prefix : str
        Put before every label (two involutes in one construction).

    Returns
    -------
    Construction
        Labels ``O``, ``A0``..``A{n}``, the radii ``OA{k}``, the tangents
        ``t{k}``, the arcs ``k{k}`` and the involute's points ``T0``..``T{n}``.

    Examples
    --------
    >>> cx = involute_construction(1.0, parts=4, roll=0.8)
    >>> ev = cx.evaluate()
    >>> x, y, _ = ev["T4"]
    >>> r, th = involute_polar(1.0, math.atan(0.8))
    >>> bool(np.isclose(math.hypot(x, y), r) and np.isclose(math.atan2(y, x), th))
    True
    """
    if parts < 1 or not math.isfinite(roll) or not 0.0 < roll < 10.0:
        raise ValueError("an involute needs at least one part and a roll angle in (0, 10) rad")
    s = 1.0 if sense == Unwind.CCW else -1.0
    o = f"{prefix}O"
    cx = Construction(title=f"involute of the base circle r_b = {base:g}")
    cx.add("point", (), (o,), xy=tuple(map(float, center)), role="given",
           note="O, the center of the base circle", diagram="gears")
    cx.add("scalar", (), (f"{prefix}theta0",), value=float(origin), role="given",
           note="the direction of O A0, where the involute begins", diagram="gears")
    cx.add("rigid", (o, f"{prefix}theta0"), (f"{prefix}A0",), local_p=(0.0, 0.0),
           local_q=(float(base), 0.0), role="given", diagram="gears",
           note="A0 on the base circle: the involute begins at A0")
    cx.add("copy_point", (f"{prefix}A0",), (f"{prefix}T0",), role="result", diagram="gears",
           note="T0 = A0: the involute leaves the base circle at its origin")
    step = roll / parts
    for k in range(1, parts + 1):
        a, radius, tangent, arc = (f"{prefix}A{k}", f"{prefix}OA{k}", f"{prefix}t{k}",
                                   f"{prefix}k{k}")
        cx.add("rigid", (o, f"{prefix}theta0"), (a,), local_p=(0.0, 0.0),
               local_q=(float(base), 0.0), offset=s * k * step, diagram="gears",
               note=f"A{k}: the base circle divided into equal parts from A0")
        cx.add("join", (o, a), (radius,), diagram="gears", note=f"the radial line O A{k}")
        cx.add("perpendicular", (radius, a), (tangent,), diagram="gears",
               note=f"the tangent to the base circle at A{k}, perpendicular to O A{k}")
        cx.add("circle", (a,), (arc,), radius=float(base * k * step), diagram="gears",
               note=f"with center A{k} an arc of radius equal to the arc A0 A{k}")
        cx.add("intersect_line_circle", (tangent, arc), (f"{prefix}T{k}",),
               branch=Along.BEHIND if s > 0 else Along.AHEAD, role="result", diagram="gears",
               note=f"T{k}, where the arc meets the tangent through A{k}: a point of the involute")
    return cx


def involute_polar(base: float, varphi: Any) -> tuple[Any, Any]:
    """The involute in polar form about its base circle's center, for the involute angle ϕ.

    ``r = r_b / cos ϕ`` (Eq. 7.15) and the polar angle from the origin ``inv ϕ`` (Eq. 7.14).
    """
    varphi = np.asarray(varphi, dtype=float)
    return base / np.cos(varphi), inv(varphi)


def involute_xy(base: float, r: Any, *, origin: float = 0.0, sense: Unwind = Unwind.CCW,
                center: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """Points of the involute at the radii ``r`` (≥ r_b), shape ``(..., 2)``."""
    r = np.asarray(r, dtype=float)
    varphi = np.arccos(np.clip(base / r, -1.0, 1.0))
    th = origin + (1.0 if sense == Unwind.CCW else -1.0) * inv(varphi)
    return np.stack([center[0] + r * np.cos(th), center[1] + r * np.sin(th)], axis=-1)

