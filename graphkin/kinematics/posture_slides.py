"""Posture steps of a translating link held by two slides (Sec. 2.8, case 3).

A link whose angle is known (it slides on a link whose angle is known) but
none of whose points is yet: each slide that carries it on a placed link
gives one of its points a straight path, parallel to the slide.  Two such
paths of one point meet at that point (two lines, case 3), and the link is
then placed from it.  This is the yoke of the Scotch yoke (Sec. 3.14,
Fig. 3.27): it slides on the frame's guide and the block pinned to the crank
slides in its slot.

These are free functions on the posture builder
(:class:`graphkin.kinematics.posture._Builder`), kept apart so the builder's
module stays small.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (case 3), Sec. 3.14, Fig. 3.27.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphkin.construction import Mark, Role, Term, VectorEquation
from graphkin.errors import AssemblyError
from graphkin.geometry import ops as g
from graphkin.mechanisms.model import XY, Slider, Slot

if TYPE_CHECKING:
    from graphkin.kinematics.posture import _Builder, _Group

__all__ = ["slides", "slide_locus", "two_slides_groups", "do_two_slides", "pins_in_line_groups",
           "do_pins_in_line"]

K, U = Mark.KNOWN, Mark.UNKNOWN


def _direction(s: Slider | Slot) -> float:
    """Angle of a straight path in its carrier's (``on``'s) coordinates (rad)."""
    assert s.p0 is not None and s.p1 is not None
    return math.atan2(s.p1[1] - s.p0[1], s.p1[0] - s.p0[0])


def _turn_together(b: _Builder, i: str, j: str) -> bool:
    """Whether links ``i`` and ``j`` were found to keep their angle to each other."""
    return ("same_angle", i, j) in b.events or ("same_angle", j, i) in b.events


def slides(b: _Builder, lid: str, name: str | None = None) -> list[Slider | Slot]:
    """The straight paths that carry the link ``lid`` (angle known) on a placed link.

    Every slider; a straight slot of a placed link in which the point ``name``
    of ``lid`` runs (the pin itself: its velocity relative to the slot's link
    is along the slot however the two turn); a straight slot of ``lid`` whose
    pin is placed (the slot's line passes through the pin, whatever turns the
    pin's link: the cam's center of curvature K in the translating flat face's
    slot, Sec. 4.7, Example 4.7).
    """
    out: list[Slider | Slot] = [
        s for s in b.mech.sliders
        if (s.link == lid and s.on in b.placed) or (s.on == lid and s.link in b.placed)]
    rolls = {r.slot_key for r in b.mech.rolling}
    for t in b.mech.slots:
        if not t.is_line or t.key in rolls:  # a rolling center's path: its link also turns
            continue
        if t.link == lid and t.on in b.placed and (name is None or t.point == name):
            out.append(t)
        elif t.on == lid and t.link in b.placed and t.point in b.env:
            out.append(t)
    return out


def slide_locus(b: _Builder, lid: str, name: str, loc: XY,
                s: Slider | Slot) -> tuple[str, str, str, tuple[str, ...]]:
    """The line on which the point ``name`` of link ``lid`` (angle known) runs by slide ``s``.

    The link keeps its angle, so each of its points runs parallel to the slide:
    the path of ``name`` is drawn through where ``name`` would be with the
    slide's point at the line's start.  Returns (label, "line", vector name,
    motion) as :meth:`_Builder.locus` does.  A slot of ``lid`` whose pin's
    link turns otherwise gives the motion ("slot_pin", lid, slot key, line):
    the pin's apparent velocity is then relative to ``lid`` (Sec. 3.6).
    """
    th = b.angle[lid]
    x = b.fresh(f"{name}'")
    lab = f"l_{name}({s.key})"
    if s.link == lid:
        sloc = b.mech.links[lid].points[s.point]
        b.add("rigid", (f"{s.key}:L0", th), (x,), local_p=sloc, local_q=loc,
              note=f"Where {name} would be with {s.point} at the line's start.")
        b.add("parallel", (f"{s.key}:line", x), (lab,),
              note=f"Through it draw the path of {name}, parallel to the slide.")
        return lab, "line", f"R_{name}", ("slide", lid, s.on, lab)
    assert s.p0 is not None
    b.add("rigid", (s.point, th), (x,), local_p=s.p0, local_q=loc,
          note=f"Where {name} would be with the slide's start at {s.point}.")
    b.add("line_at_angle", (x, th), (lab,), offset=_direction(s),
          note=f"Through it draw the path of {name}, parallel to the slide.")
    if _turn_together(b, lid, s.link):
        return lab, "line", f"R_{name}", ("slide", lid, s.link, lab)
    return lab, "line", f"R_{name}", ("slot_pin", lid, s.key, lab)


def _parallel(b: _Builder, s1: Slider | Slot, s2: Slider | Slot) -> bool:
    """Whether two slides' paths run parallel: the sine of their angle within round-off.

    A slide's line is drawn on its carrier ``on`` at ``direction_angle`` in the
    carrier's axes; both carriers' angles are known here.  The slides keep
    their angles, so the verdict is the same in every posture.
    """
    t1, t2 = (float(np.asarray(b.env[b.angle[s.on]])) + _direction(s) for s in (s1, s2))
    return abs(math.sin(t1 - t2)) <= b.tol.angle


def two_slides_groups(b: _Builder) -> list[_Group]:
    """Translating links (angle known, no point yet) held by two slides that are not parallel.

    The point found is the first slide's own point of the link (the yoke's foot
    F, Fig. 3.27), else the link's first point.
    """
    from graphkin.kinematics.posture import _Group

    out = []
    for lid, link in b.mech.links.items():
        if lid in b.placed or lid not in b.angle or b.distinct_known(lid):
            continue
        own = [s.point for s in slides(b, lid) if s.link == lid]
        name = own[0] if own else next(iter(link.points))
        sl = slides(b, lid, name)
        pair = next(((s1, s2) for i, s1 in enumerate(sl) for s2 in sl[i + 1:]
                     if not _parallel(b, s1, s2)), None)
        if pair is None:
            continue
        out.append(_Group("two_slides", pin=name, links=(lid, lid), slides=pair))
    return out


def do_two_slides(b: _Builder, lid: str, name: str,
                  pair: tuple[Slider | Slot, ...]) -> list[str]:
    """The two paths of the point ``name`` meet at it (case 3); one way only."""
    s1, s2 = pair
    loc = b.mech.links[lid].points[name]
    la, _, va, ma = slide_locus(b, lid, name, loc, s1)
    lb, _, vb, mb = slide_locus(b, lid, name, loc, s2)
    b.events.append(("dyad", name, ma, mb))
    b.add("meet", (la, lb), (name,), role=Role.RESULT,
          equation=VectorEquation((Term(va, U, K),), (Term(vb, U, K),), case=3),
          note=f"Link {lid} keeps its angle: the two paths of {name} meet at {name} "
               "(case 3).")
    if not np.isfinite(g.xy(b.env[name])).all():
        raise AssemblyError(f"cannot assemble: the paths of {name} are parallel", step=name)
    return [""]


def _collinear(b: _Builder, s1: Slot, s2: Slot) -> bool:
    """Whether two straight slots of one link lie on one line of it (within round-off)."""
    assert s1.p0 is not None and s1.p1 is not None and s2.p0 is not None and s2.p1 is not None
    u = np.subtract(s1.p1, s1.p0)
    u = u / float(np.hypot(*u))
    ends = (np.subtract(s2.p0, s1.p0), np.subtract(s2.p1, s1.p0))
    return all(abs(float(u[0] * d[1] - u[1] * d[0])) <= b.tol.length(b.mech.scale)
               for d in ends)


def pins_in_line_groups(b: _Builder) -> list[_Group]:
    """A link with two pins of one known link in one straight slot line of it.

    The follower of Example 11.3 (Fig. 11.10) slides in the frame's bearings at
    B and D: its slot line passes through both pins, so it is the line BD, and
    the follower keeps its angle to the link that holds both pins.  Only when
    the link has no known point nor angle yet, and the pins stand apart.
    """
    from graphkin.kinematics.posture import _Group

    out = []
    for lid in b.mech.links:
        if lid in b.placed or lid in b.angle or b.distinct_known(lid):
            continue
        slots = [t for t in b.mech.slots if t.is_line and t.on == lid and t.link in b.placed
                 and t.link in b.angle and t.point in b.env]
        pair = next(((t1, t2) for i, t1 in enumerate(slots) for t2 in slots[i + 1:]
                     if t1.link == t2.link and _collinear(b, t1, t2)
                     and float(np.hypot(*(g.xy(b.env[t1.point]) - g.xy(b.env[t2.point]))))
                     > b.tol.length(b.mech.scale)), None)
        if pair is not None:
            out.append(_Group("pins_in_line", pin=pair[0].point, links=(lid, pair[0].link),
                              slides=pair))
    return out


def do_pins_in_line(b: _Builder, lid: str, pair: tuple[Slider | Slot, ...],
                    branch: str | None) -> list[str]:
    """The slot line is the line through the two pins: it gives the link's angle.

    Which way the slot runs along it (from P toward Q or back) is the branch,
    ``ahead`` or ``behind`` (the assembly hints choose); the link then keeps
    its angle to the pins' link, whose ω and α it shares.
    """
    t1, t2 = pair
    p, q = t1.point, t2.point
    key = t1.key
    r = float(b.mech.scale)
    b.add("join", (p, q), (f"{key}:PQ",),
          note=f"The slot of link {lid} passes through both pins: draw the line "
               f"{p}{q}.")
    b.add("circle", (p,), (f"{key}:u",), radius=r, note=f"About {p} mark a length on it.")
    names = ["ahead", "behind"]
    lab = f"{key}:T"
    b.add("intersect_line_circle", (f"{key}:PQ", f"{key}:u"), (lab,), branch=branch or names[0],
          role=Role.AUXILIARY, note=f"The slot of link {lid} runs along {p}{q}.")
    th = f"θ{lid}"
    b.add("angle_along", (p, lab), (th,), local_angle=_direction(t1), sign=1.0,
          role=Role.RESULT, note=f"The slot's direction gives θ{lid}.")
    b.angle[lid] = th
    b.events.append(("same_angle", lid, t1.link))
    # its point on the cam's face (or on any other straight path) at once, so that the
    # assembly hints of the link's points choose the branch
    now = next((grp for grp in two_slides_groups(b) if grp.links[0] == lid), None)
    if now is not None:
        do_two_slides(b, lid, now.pin, now.slides)
    return names
