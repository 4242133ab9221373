"""The instant centers in the JSON and in the text report (``docs/formats/json.md``).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 3.12-3.14.
"""

from __future__ import annotations

import math
import re
from typing import Any

import numpy as np

from graphkin.kinematics.instant_centers import How, center_label, instant_centers
from graphkin.kinematics.instant_centers.labels import _id_key
from graphkin.kinematics.solution import Solution
from graphkin.output.units import OutputUnits
from graphkin.text import clean, g6, table
from graphkin.tolerance import VERDICT_REL

__all__ = ["instant_centers_json", "instant_centers_text", "is_batch"]

Array = np.ndarray


def _line_words(label: str) -> str:
    """A line of centers as the report names it: ``n(B):I23`` is the slot's normal at B.

    Examples
    --------
    >>> print(_line_words("n(B):I23"), "|", _line_words("n(A):I24#3"), "|",
    ...       _line_words("I12-I23"))
    the slot's normal at B | the slot's normal at A | I12-I23
    >>> _line_words("rolling[0]:normal")
    'the common normal at the rolling contact'
    """
    m = re.match(r"^n\((?P<p>[^()]+)\):I[\w-]+(#\d+)?$", label)
    if m:
        return f"the slot's normal at {m.group('p')}"
    if re.match(r"^rolling\[\d+\]:normal(#\d+)?$", label):
        return "the common normal at the rolling contact"
    return label.split("#")[0]

def is_batch(sol: Solution) -> bool:
    """Whether ``sol`` holds many postures (a sweep): the reports describe one."""
    return bool(np.ndim(next(iter(sol.links.values())).angle) > 0)


def _canonical(d: Array) -> list[float]:
    """A unit direction with its first nonzero component positive (either sense is valid)."""
    dx, dy = float(d[0]), float(d[1])
    n = math.hypot(dx, dy)
    dx, dy = dx / n, dy / n
    # a direction within round-off of the y axis is taken upward: the sense of its x
    # component is round-off (it differs between machines), never a verdict
    if (abs(dx) <= VERDICT_REL and dy < 0) or dx < -VERDICT_REL:
        dx, dy = -dx, -dy
    return [dx + 0.0, dy + 0.0]


def instant_centers_json(sol: Solution, units: OutputUnits | None = None
                         ) -> dict[str, Any] | None:
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
    >>> instant_centers_json(graphkin.examples.fourbar().solve())["1-2"]["position"]
    [0.0, 0.0]
    """
    if is_batch(sol):
        return None
    k = 1.0 if units is None else units.k_length
    if _large(sol):
        return _direct_json(sol, k)
    ic = instant_centers(sol)
    out: dict[str, Any] = {}
    for c in sorted(ic.centers.values(), key=lambda c: (_id_key(c.pair[0]), _id_key(c.pair[1]))):
        entry: dict[str, Any] = {}
        if c.point[2] == 0.0:
            entry["direction"] = _canonical(c.point[:2])
        else:
            entry["position"] = [float(c.point[0]) * k + 0.0, float(c.point[1]) * k + 0.0]
        entry.update({"label": c.label, "how": c.how.value, "order": c.order,
                      "source": c.source})
        if c.lines:
            entry["lines"] = list(c.lines)
        if c.speed_dependent:
            entry["speed_ratio_dependent"] = True
        out[f"{c.pair[0]}-{c.pair[1]}"] = entry
    return out


def instant_centers_text(sol: Solution, units: OutputUnits | None = None) -> str | None:
    """A short textbook-style table of the instant centers, for the text report.

    ``None`` for a batch.

    Examples
    --------
    >>> import graphkin
    >>> print(instant_centers_text(graphkin.examples.fourbar().solve()))
      n = 4 links, N = n(n-1)/2 = 6 instant centers (Eq. 3.20)
      #  center  found by  location
      1  I12     pin A     (0, 0) in
      2  I14     pin D     (10, 0) in
      3  I23     pin B     (-2, 3.4641) in
      4  I34     pin C     (14.8136, 9.89088) in
      5  I13     Kennedy   (5.42613, -9.39833) in  on I12-I23 and I14-I34
      6  I24     Kennedy   (-11.0627, 0) in        on I12-I14 and I23-I34
    """
    if is_batch(sol):
        return None
    k = 1.0 if units is None else units.k_length
    unit = sol.mechanism.length_unit if units is None else units.text("length")
    if _large(sol):
        return _direct_text(sol, k, unit)
    ic = instant_centers(sol)
    n, count = len(ic.links), ic.count
    lines = [f"  n = {n} links, N = n(n-1)/2 = {count} instant "
             f"center{'s' if count != 1 else ''} (Eq. 3.20)"]
    rows = [("#", "center", "found by", "location", "")]
    for c in ic.centers.values():
        if c.point[2] == 0.0:
            dx, dy = _canonical(c.point[:2])
            where = f"at infinity ∠{round(math.degrees(math.atan2(dy, dx)), 2) + 0.0:.2f}°"
        else:
            # a coordinate that is zero but for the intersections' round-off prints as 0
            tiny = VERDICT_REL * sol.mechanism.scale * k
            where = (f"({g6(clean(float(c.point[0]) * k, tiny) + 0.0)}, "
                     f"{g6(clean(float(c.point[1]) * k, tiny) + 0.0)}) {unit}")
        if c.how is How.KENNEDY:
            by = "Kennedy"
            extra = "on " + " and ".join(_line_words(x) for x in c.lines)
        elif c.how is How.VELOCITIES:
            by = "velocities"
            extra = "depends on the speed ratio (Sec. 5.4)" if c.speed_dependent else ""
        else:
            by, extra = c.source, ""
        rows.append((str(c.order), c.label, by, where, extra))
    lines += table(rows, "  ")
    for p in ic.missing:
        lines.append(f"  {center_label(*p)}: not found")
    for note in ic.notes:
        lines.append(f"  note: {note}")
    return "\n".join(lines)


# ---- a large mechanism: every center at once (graphkin.kinematics.instant_centers.direct) ----

def _large(sol: Solution) -> bool:
    """More centers than the step-by-step Kennedy search is meant for."""
    from graphkin.kinematics.instant_centers.direct import DIRECT_ABOVE

    n = len(sol.mechanism.links)
    return n * (n - 1) // 2 > DIRECT_ABOVE


def _direct_json(sol: Solution, k: float) -> dict[str, Any]:
    """Every pair found at once: ``position`` or ``direction``, and ``how``."""
    from graphkin.kinematics.instant_centers.direct import direct_centers

    dc = direct_centers(sol)
    out: dict[str, Any] = {}
    ia, ib = dc.pairs
    pts = dc.points
    finite = np.all(np.isfinite(pts), axis=1)
    primary, by_velocities = How.PRIMARY.value, How.VELOCITIES.value
    xs, ys, ws = (pts[:, 0] * k + 0.0).tolist(), (pts[:, 1] * k + 0.0).tolist(), \
        pts[:, 2].tolist()
    la, lb = ia.tolist(), ib.tolist()
    links = dc.links
    for m in np.flatnonzero(finite).tolist():
        i, j = links[la[m]], links[lb[m]]
        entry: dict[str, Any] = (
            {"position": [xs[m], ys[m]]} if ws[m] != 0.0
            else {"direction": _canonical(pts[m, :2])})
        entry["how"] = primary if m in dc.primary else by_velocities
        out[f"{i}-{j}"] = entry
    return out


def _direct_text(sol: Solution, k: float, unit: str) -> str:
    """The count, the centers at the pins, and where the others are listed."""
    from graphkin.kinematics.instant_centers.direct import direct_centers

    dc = direct_centers(sol)
    n, count = len(dc.links), dc.count
    lines = [f"  n = {n} links, N = n(n-1)/2 = {count} instant centers (Eq. 3.20)"]
    rows = [("center", "found by", "location")]
    ia, ib = dc.pairs
    for m, pin in dc.primary.items():
        x, y = float(dc.points[m, 0]) * k + 0.0, float(dc.points[m, 1]) * k + 0.0
        rows.append((center_label(dc.links[ia[m]], dc.links[ib[m]]), f"pin {pin}",
                     f"({g6(x)}, {g6(y)}) {unit}"))
    lines += table(rows, "  ")
    known = int(np.sum(np.all(np.isfinite(dc.points), axis=1)))
    lines.append(f"  the other {known - len(dc.primary)} centers are found at once from the "
                 "velocities (the points of equal velocity, Sec. 3.12) and listed by "
                 "graphkin solve --json; too many to list here")
    for note in dc.notes:
        lines.append(f"  note: {note}")
    return "\n".join(lines)
