"""The JSON and text report of instant centers."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.kinematics.instant_centers.centers import How
from graphkin.kinematics.instant_centers.kennedy import _is_batch, instant_centers
from graphkin.kinematics.instant_centers.labels import _id_key, center_label
from graphkin.kinematics.solution import Solution

__all__ = ["instant_centers_json", "instant_centers_text"]

Array = np.ndarray

# ---------------------------------------------------------------------------
# output
# ---------------------------------------------------------------------------

def _canonical(d: Array) -> list[float]:
    """A unit direction with its first nonzero component positive (either sense is valid)."""
    dx, dy = float(d[0]), float(d[1])
    n = math.hypot(dx, dy)
    dx, dy = dx / n, dy / n
    if dx < 0 or (dx == 0 and dy < 0):
        dx, dy = -dx, -dy
    return [dx + 0.0, dy + 0.0]


def instant_centers_json(sol: Solution) -> dict[str, Any] | None:
    """The ``instant_centers`` section of ``graphkin solve --json`` (``docs/formats/json.md``).

    Keys ``"i-j"`` (lower id first); ``{"position": [x, y]}``, or
    ``{"direction": [dx, dy]}`` (a unit vector) for a center at infinity; plus
    ``label``, ``how`` (``primary``, ``kennedy``, ``velocities``), ``order`` of
    discovery, ``source``, the ``lines`` it was found on and, for a center that
    depends on the input speeds, ``speed_ratio_dependent: true``.  ``None``
    for a batch.  A center that cannot be found (several degrees of freedom
    and no velocities in the file) is left out.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 3.12-3.14.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 30
    ... ''').solve()
    >>> instant_centers_json(sol)["1-2"]["position"]
    [0.0, 0.0]
    """
    if _is_batch(sol):
        return None
    ic = instant_centers(sol)
    out: dict[str, Any] = {}
    for c in sorted(ic.centers.values(), key=lambda c: (_id_key(c.pair[0]), _id_key(c.pair[1]))):
        entry: dict[str, Any] = {}
        if c.point[2] == 0.0:
            entry["direction"] = _canonical(c.point[:2])
        else:
            entry["position"] = [float(c.point[0]) + 0.0, float(c.point[1]) + 0.0]
        entry.update({"label": c.label, "how": c.how.value, "order": c.order,
                      "source": c.source})
        if c.lines:
            entry["lines"] = list(c.lines)
        if c.speed_dependent:
            entry["speed_ratio_dependent"] = True
        out[f"{c.pair[0]}-{c.pair[1]}"] = entry
    return out


def instant_centers_text(sol: Solution) -> str | None:
    """A short textbook-style table of the instant centers, for the text report.

    ``None`` for a batch.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 30
    ... ''').solve()
    >>> print(instant_centers_text(sol))
      n = 2 links, N = n(n-1)/2 = 1 instant center (Eq. 3.20)
      #  center  found by        location
      1  I12     pin A           (0, 0) mm
    """
    if _is_batch(sol):
        return None
    ic = instant_centers(sol)
    unit = sol.mechanism.length_unit
    n, count = len(ic.links), ic.count
    lines = [f"  n = {n} links, N = n(n-1)/2 = {count} instant "
             f"center{'s' if count != 1 else ''} (Eq. 3.20)"]
    rows = [("#", "center", "found by", "location", "")]
    for c in ic.centers.values():
        if c.point[2] == 0.0:
            dx, dy = _canonical(c.point[:2])
            where = f"at infinity ∠{round(math.degrees(math.atan2(dy, dx)), 2) + 0.0:.2f}°"
        else:
            where = f"({float(c.point[0]) + 0.0:.6g}, {float(c.point[1]) + 0.0:.6g}) {unit}"
        if c.how is How.KENNEDY:
            by = "Kennedy"
            extra = "on " + " and ".join(c.lines)
        elif c.how is How.VELOCITIES:
            by = "velocities"
            extra = "depends on the speed ratio (Sec. 5.4)" if c.speed_dependent else ""
        else:
            by, extra = c.source, ""
        rows.append((str(c.order), c.label, by, where, extra))
    widths = [max(len(r[k]) for r in rows) for k in range(4)]
    for r in rows:
        lines.append(("  " + "  ".join(x.ljust(w) for x, w in zip(r[:4], widths))
                      + ("  " + r[4] if r[4] else "")).rstrip())
    for p in ic.missing:
        lines.append(f"  {center_label(*p)}: not found")
    for note in ic.notes:
        lines.append(f"  note: {note}")
    return "\n".join(lines)
