"""Angles drawn at their pivot: the drive's θ2 from the x axis, a joint angle θi/j between links.

References
----------
Uicker, Pennock & Shigley, 5th ed., Fig. 3.1 (the input angle θ2), Problems
5.7-5.11 (joint angles of a robot arm, θ3/2).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphkin.render.scale import fmt
from graphkin.render.scene import Group, Item, Panel, sub_digits

if TYPE_CHECKING:
    from graphkin.render.paint import StepPainter

__all__ = ["angle_arc", "joint_arc"]


def angle_arc(painter: StepPainter, g: Group, panel: Panel, pivot: np.ndarray, base: float,
              theta: float, label: str, text: str) -> None:
    """A datum line at ``base`` (rad) through ``pivot`` and an arc of ``theta`` from it, lettered.

    The input angle (θ2 = 120° from the x axis, ``base`` 0) or a joint angle
    (θ3/2 from link 2's axis).
    """
    k = panel.k
    r = 0.32 * k
    d = np.array([math.cos(base), math.sin(base)])
    g.items.append(Item("path", np.array([pivot, pivot + 0.5 * k * d]), "datum",
                        key=f"{label}:datum"))
    t = math.remainder(theta, 2 * math.pi)
    # a sample every 3° (a round angle, 30°, is 10 samples on every machine)
    ts = base + np.linspace(0.0, t, max(int(abs(math.degrees(t)) / 3 + 1e-6), 2) + 1)
    pts = pivot + r * np.stack([np.cos(ts), np.sin(ts)], axis=-1)
    g.items.append(Item("path", pts, "angle-arc", key=label))
    if len(pts) >= 3:
        head = min(0.07 * k, 0.5 * r * abs(t))
        g.items.append(Item("arrow", np.array([pts[-3], pts[-1]]), "angle-arc",
                            key=f"{label}:head", head=head, width=head * 0.35))
    mid = base + t / 2
    at = pivot + (r + 0.02 * k) * np.array([math.cos(mid), math.sin(mid)])
    painter.label(panel, g, text, at, label, style="label-small", gap=0.04,
                  prefer=(math.cos(mid), math.sin(mid)))


def joint_arc(painter: StepPainter, g: Group, panel: Panel, pair: str, theta: float,
              label: str) -> None:
    """A joint angle θi/j (a robot's elbow, P5.7): an arc at their pin from link j's axis."""
    mech, sol = painter.src.mechanism, painter.src.solution
    assert mech is not None and sol is not None
    i, _, j = pair.partition("/")
    pin = next((p.name for p in mech.pins if i in p.links and j in p.links), None)
    if pin is None or j not in sol.links:
        return
    t = math.remainder(theta, 2 * math.pi)
    text = f"θ{sub_digits('x' + i)[1:]}/{sub_digits('x' + j)[1:]} = {fmt(math.degrees(t), 5)}°"
    angle_arc(painter, g, panel, np.asarray(sol.position(pin), dtype=float),
              float(sol.links[j].angle), theta, label, text)
