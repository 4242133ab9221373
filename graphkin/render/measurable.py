"""Polygons a reader can measure: the shortest drawn component at least 3 mm, or said in words.

A velocity or acceleration polygon is read with a rule: a vector drawn
0.7 mm long cannot be measured, nor its label set beside it.  The polygon's
scale is chosen so that its shortest component is at least :data:`MIN_MM`
long where the sheet has room; where it has not (a component a thousandth of
the largest), the panel says which components are too short to draw to scale
and gives their values, as a student would write beside the figure.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 3.4 and 4.2 (polygons drawn to a
stated scale).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.render.scale import fmt
from graphkin.render.scene import Panel

__all__ = ["MIN_MM", "component_magnitudes", "room_for", "short_components", "short_note"]

MIN_MM = 3.0
"""The shortest measurable component, in millimetres of paper."""

MM_PER_IN = 25.4
ROUND_OFF = 1e-9
"""A component below this fraction of the polygon's largest is zero (not drawn)."""


def component_magnitudes(painter: Any, plane: str) -> list[float]:
    """The magnitudes of the vectors a polygon draws (its components), in data units."""
    out: list[float] = []
    for s in painter.cx.steps:
        if s.kind != "vector" or s.diagram != plane:
            continue
        v = painter.raw(s.outputs[0])
        if v is None or np.shape(v) != (2,) or not np.all(np.isfinite(v)):
            continue
        out.append(float(np.hypot(*v)))
    big = max(out, default=0.0)
    return [m for m in out if m > ROUND_OFF * big]


def room_for(extent: float, mags: list[float], room: float, cap: float) -> float:
    """The room (inches) a polygon needs for its shortest component to be measurable.

    ``room`` is the usual room, ``cap`` the most the sheet gives; a polygon
    whose shortest component is measurable in ``room`` keeps it, one that
    needs more than ``cap`` keeps ``room`` (its short components are named in
    words instead of growing the sheet for nothing).

    Examples
    --------
    >>> room_for(100.0, [100.0, 10.0], 3.0, 6.0)       # 10 of 100 in 3 in: 7.6 mm
    3.0
    >>> round(room_for(100.0, [100.0, 2.0], 3.0, 6.0), 3)   # 2 of 100 needs 5.9 in
    5.906
    >>> room_for(100.0, [100.0, 0.1], 3.0, 6.0)         # would need 118 in: kept
    3.0
    """
    if not mags or extent <= 0:
        return room
    short = min(mags)
    # the round scale chosen may be up to 2.5 times coarser than extent/room: allow for it
    need = extent * MIN_MM / MM_PER_IN / short
    if need <= room:
        return room
    return need if need <= cap else room


def short_components(panel: Panel) -> list[tuple[str, float, float]]:
    """The arrows of a drawn polygon panel shorter than :data:`MIN_MM`: (name, value, mm)."""
    out: list[tuple[str, float, float]] = []
    seen: set[str] = set()
    for g in panel.groups:
        for it in g.items:
            if it.kind != "arrow" or not it.key or it.key in seen or ":" in it.key:
                continue
            length = float(np.hypot(*(it.xy[-1] - it.xy[0])))
            mm = length / panel.k * MM_PER_IN
            if math.isfinite(mm) and mm < MIN_MM:
                seen.add(it.key)
                out.append((it.key, length, mm))
    return out


def short_note(panel: Panel, shorts: list[tuple[str, float, float]]) -> str:
    """One sentence naming the components too short to draw to scale, with their values.

    Examples
    --------
    >>> p = Panel("acceleration", "acceleration", "", "mm/s²")
    >>> short_note(p, [("A_DC^t", 29.1, 0.58)])
    'Too short to draw to scale (under 3 mm): $A^{t}_{DC}$ = 29.1 mm/s² (0.6 mm).'

    The components are named as on the polygon (``A^t_DC``, Sec. 4.3), not in the
    ASCII of the files.
    """
    from graphkin.render.paint import vector_math

    if not shorts:
        return ""
    unit = f" {panel.unit}" if panel.unit else ""
    items = [f"{vector_math(name)} = {fmt(value, 3)}{unit} ({mm:.1f} mm)"
             for name, value, mm in shorts]
    return f"Too short to draw to scale (under {MIN_MM:g} mm): " + "; ".join(items) + "."
