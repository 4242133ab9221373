"""The scalars of a posture drawing: a drive's input angle and the links' angular rates.

An angle is an arc from the link's reference direction; an angular rate a
curved arrow about the link's frame pivot (or its centroid) turning in the
rate's sense, with its value, as the book letters ω2 and α2 on a figure.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.6 (kinematic diagrams), Sec. 3.2
(angular velocity and its sense).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphkin.construction import Step
from graphkin.mechanisms.model import FRAME
from graphkin.render.joint_angle import angle_arc, joint_arc
from graphkin.render.scale import fmt
from graphkin.render.scene import Group, Item, Panel, sub_digits
from graphkin.render.sources import Source
from graphkin.tolerance import is_zero

if TYPE_CHECKING:
    from graphkin.render.paint import StepPainter

__all__ = ["paint_scalar"]


def paint_scalar(self: StepPainter, step: Step, g: Group, panel: Panel) -> None:
    """An input angle or an angular rate, drawn on its link.

    ``self`` is the :class:`~graphkin.render.paint.StepPainter` of the diagram.
    """
    label = step.outputs[0]
    mech = self.src.mechanism
    sol = self.src.solution
    if mech is None or sol is None or panel.plane != "posture":
        return
    v = self.raw(label)
    if v is None or v.shape != () or not math.isfinite(float(v)):
        return
    value = float(v)
    sym, lid = label[:1], label[1:]
    if sym == "θ" and step.op == "input" and "/" in lid:
        joint_arc(self, g, panel, lid, value, label)
        return
    if sym in ("ω", "α"):
        rates = [abs(float(self.values[f"{sym}{x}"])) for x in mech.links
                 if f"{sym}{x}" in self.values
                 and np.shape(self.values[f"{sym}{x}"]) == ()]
        if abs(value) <= 1e-9 * max([1.0, *rates]):
            value = 0.0  # zero but for round-off: say so
    if lid not in mech.links or lid == FRAME:
        return
    center, direction = _link_center(self.src, lid)
    if center is None:
        return
    k = panel.k
    if sym == "θ" and step.op == "input":
        lid = label[1:]
        angle_arc(self, g, panel, center, 0.0, value, label,
                  f"θ{sub_digits('x' + lid)[1:]} = {fmt(math.degrees(value), 5)}°")
    elif sym in ("ω", "α") and not self.quiet_rates and not (
            value == 0 and step.op in ("add_angle", "scalar")):
        unit = "rad/s" if sym == "ω" else "rad/s²"
        text = f"{sym}{sub_digits('x' + lid)[1:]} = {fmt(abs(value), 4)} {unit}"
        if value != 0:
            text += " ccw" if value > 0 else " cw"
        radius = (0.2 if sym == "ω" else 0.3) * k
        start = direction + math.radians(60 if sym == "ω" else 100)
        if value == 0:
            self.label(panel, g, text, center, label, style="label-small", gap=0.25)
            return
        sweep = math.radians(250) * (1 if value > 0 else -1)
        ts = np.linspace(start, start + sweep, 41)
        pts = center + radius * np.stack([np.cos(ts), np.sin(ts)], axis=-1)
        g.items.append(Item("path", pts[:-3], "rate", key=label))
        tan = pts[-1] - pts[-4]
        self.arrow(panel, g, pts[-1] - tan * 0.01, pts[-1], "rate", key=f"{label}:head")
        # make the head a fixed size pointing along the arc's end
        g.items[-1].xy = np.array([pts[-4], pts[-1]])
        g.items[-1].head = min(0.08 * k, float(np.hypot(*tan)) * 1.5)
        g.items[-1].width = g.items[-1].head * 0.35
        mid = center + (radius + 0.02 * k) * np.array([math.cos(start + sweep / 2),
                                                        math.sin(start + sweep / 2)])
        # where one line finds no room: the value over its unit and sense
        two = (text.replace(" = ", " =\n", 1),)
        self.label(panel, g, text, mid, label, style="label-small", gap=0.05,
                   prefer=(math.cos(start + sweep / 2), math.sin(start + sweep / 2)),
                   fallback=two)


def _link_center(src: Source, lid: str) -> tuple[np.ndarray | None, float]:
    """Where a link's rate is drawn: its frame pivot if it has one, else its centroid.

    Returns the point and the direction (rad) of the link's body from there.
    """
    sol = src.solution
    mech = src.mechanism
    if sol is None or mech is None:
        return None, 0.0
    names = list(mech.links[lid].points)
    if not names:
        return None, 0.0
    pts = {n: np.asarray(sol.position(n, lid), dtype=float) for n in names}
    frame = mech.links[FRAME].points
    pivots = [n for n in names if n in frame]
    c = pts[pivots[0]] if pivots else np.mean(list(pts.values()), axis=0)
    size = max(float(np.hypot(*(p - c))) for p in pts.values())
    # the points away from the centre; their mean direction, else (a floating link, whose
    # points' mean offset from their centroid is zero but for round-off, or a lever with
    # its pivot at the middle) the first point's: a direction of round-off would turn the
    # rate's arrow differently on another machine
    others = [pts[n] - c for n in names if not is_zero(float(np.hypot(*(pts[n] - c))), size)]
    ang = 0.0
    if others:
        m = np.mean(others, axis=0)
        if pivots and not is_zero(float(np.hypot(*m)), size, rel=1e-6):
            ang = math.atan2(m[1], m[0])
        else:
            ang = math.atan2(others[0][1], others[0][0])
    return c, ang
