"""How two branches of a posture group are told apart: assembly hints, else the file's drawing.

Measures used by :func:`graphkin.kinematics.posture._choose` on two forks of
the posture builder, one per branch of a two-way group (Sec. 2.8, Table 2.2:
two arcs meet twice, an arc cuts a line twice).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from graphkin.geometry import ops as g
from graphkin.mechanisms.model import FRAME

if TYPE_CHECKING:
    from graphkin.kinematics.posture import _Builder

__all__ = ["_new_points", "_hint_distance", "_layout_distance", "_differ_tolerance"]


def _new_points(b: _Builder, t: _Builder) -> list[str]:
    """Labels of the points ``t`` constructed beyond ``b`` (its new steps' outputs)."""
    return [o for st in t.cx.steps[len(b.cx.steps):] if st.kind == "point" for o in st.outputs]


def _hint_distance(t: _Builder, names: list[str], origin: np.ndarray) -> float:
    """Mean distance of the named points from their assembly hints.

    Both are taken relative to ``origin`` (a point of the mechanism), so that
    a mechanism far from the origin loses no digits to its offset.
    """
    hints = t.mech.assembly
    return float(np.mean([np.hypot(*((g.xy(t.env[n]) - origin)
                                     - (np.asarray(hints[n]) - origin))) for n in names]))


def _layout_distance(b: _Builder, t: _Builder) -> float:
    """How far the links ``t`` placed beyond ``b`` are turned from their own drawing in the file.

    Each link's points are compared with where they would be if the link kept
    the orientation of its own coordinates (its x axis along the frame's).
    """
    total = 0.0
    for lid in t.placed - b.placed:
        if lid == FRAME or lid not in t.anchor:
            continue
        anchor, aloc = t.anchor[lid]
        pa = g.xy(t.env[anchor])
        for name, loc in t.mech.links[lid].points.items():
            if name in t.env:
                drawn = pa + np.subtract(loc, aloc)
                total += float(np.hypot(*(g.xy(t.env[name]) - drawn)))
    return total


def _differ_tolerance(b: _Builder, at: np.ndarray) -> float:
    """When two branches' positions of a point count as different.

    Relative to the mechanism's own size (not to its distance from the
    origin), with a floor of the round-off of coordinates as large as ``at``:
    a slider-crank scaled by 1e-12 or moved 1e9 from the origin takes the
    branch its hints ask for.
    """
    eps = float(np.finfo(float).eps)
    return max(1e-6 * b.mech.size, 1e3 * eps * float(np.max(np.abs(at), initial=0.0)))
