"""Conjugate points known by inspection: frame pivots and frame-fixed lines (Sec. 4.13)."""

from __future__ import annotations

import numpy as np

from graphkin.geometry import ops as g
from graphkin.mechanisms.model import FRAME, Mechanism

__all__ = ["known_conjugates"]

Array = np.ndarray

# ---------------------------------------------------------------------------
# the conjugates known by inspection
# ---------------------------------------------------------------------------

def _frame_pins(mech: Mechanism, lid: str) -> list[str]:
    frame = mech.links[FRAME].points
    return [n for n in mech.links[lid].points if n in frame]


def _ideal_normal(p0: tuple[float, float], p1: tuple[float, float]) -> Array:
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    return g.ideal_point(-dy, dx)


def known_conjugates(mech: Mechanism, link: str) -> dict[str, tuple[Array, str]]:
    """The points of a link whose paths have a constant curvature known by inspection.

    A pin ``A`` of the link shared with a link that turns about a frame pivot
    ``O`` has its center of curvature at ``O``; a point held on a frame-fixed
    straight line (a pin to a slider on the frame, a pin in a straight slot of
    the frame) has it at infinity, normal to the line; a pin in a circular
    slot of the frame has it at the slot's center.  These are the pairs of
    conjugate points "found by inspection" of Sec. 4.13 (Examples 4.12-4.14).

    Parameters
    ----------
    mech : Mechanism
    link : str

    Returns
    -------
    dict
        Point name -> (homogeneous conjugate point, shape (3,), the reason in words).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.13.

    Examples
    --------
    The offset slider-crank of Example 3.2: the rod's pin B turns about the crank's pivot A (its
    center of curvature), its pin C slides on a horizontal line (the center at infinity).

    >>> import graphkin
    >>> mech = graphkin.examples.slider_crank()
    >>> {n: (h + 0.0).tolist() for n, (h, why) in known_conjugates(mech, "3").items()}
    {'B': [0.0, 0.0, 1.0], 'C': [0.0, 1.0, 0.0]}
    """
    out: dict[str, tuple[Array, str]] = {}
    frame = mech.links[FRAME].points
    for name in mech.links[link].points:
        if name in frame:
            continue
        for m in mech.point_links[name]:
            if m in (link, FRAME):
                continue
            pins = _frame_pins(mech, m)
            if len(pins) == 1:
                o = pins[0]
                out[name] = (g.point(*frame[o]),
                             f"{name} is a pin of link {m}, which turns about the frame pivot "
                             f"{o}: the path of {name} is a circle about {o}, so {name}' = {o}")
                break
            for s in mech.sliders:
                if s.link == m and s.on == FRAME:
                    out[name] = (_ideal_normal(s.p0, s.p1),
                                 f"{name} is a pin of the slider {m}, which moves on a "
                                 f"frame-fixed line: the path of {name} is straight, so its "
                                 f"conjugate {name}' is at infinity, normal to the line")
                    break
            if name in out:
                break
        if name in out:
            continue
        for sl in mech.slots:
            if sl.point == name and sl.on == FRAME:
                if sl.is_line:
                    assert sl.p0 is not None and sl.p1 is not None
                    out[name] = (_ideal_normal(sl.p0, sl.p1),
                                 f"{name} moves in a straight slot of the frame: its conjugate "
                                 f"{name}' is at infinity, normal to the slot")
                else:
                    assert sl.center is not None
                    out[name] = (g.point(*sl.center),
                                 f"{name} moves in a circular slot of the frame: {name}' is "
                                 "the slot's center")
                break
    return out
