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
from graphkin.mechanisms.model import XY, Slider

if TYPE_CHECKING:
    from graphkin.kinematics.posture import _Builder, _Group

__all__ = ["slides", "slide_locus", "two_slides_groups", "do_two_slides"]

K, U = Mark.KNOWN, Mark.UNKNOWN


def slides(b: _Builder, lid: str) -> list[Slider]:
    """The sliders that carry the translating link ``lid`` on a placed link."""
    return [s for s in b.mech.sliders
            if (s.link == lid and s.on in b.placed) or (s.on == lid and s.link in b.placed)]


def slide_locus(b: _Builder, lid: str, name: str, loc: XY,
                s: Slider) -> tuple[str, str, str, tuple[str, ...]]:
    """The line on which the point ``name`` of link ``lid`` (angle known) runs by slide ``s``.

    The link keeps its angle, so each of its points runs parallel to the slide:
    the path of ``name`` is drawn through where ``name`` would be with the
    slide's point at the line's start.  Returns (label, "line", vector name,
    motion) as :meth:`_Builder.locus` does.
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
    b.add("line_at_angle", (x, th), (lab,), offset=s.direction_angle,
          note=f"Through it draw the path of {name}, parallel to the slide.")
    return lab, "line", f"R_{name}", ("slide", lid, s.link, lab)


def _parallel(b: _Builder, s1: Slider, s2: Slider) -> bool:
    """Whether two slides' paths run parallel: the sine of their angle within round-off.

    A slide's line is drawn on its carrier ``on`` at ``direction_angle`` in the
    carrier's axes; both carriers' angles are known here.  The slides keep
    their angles, so the verdict is the same in every posture.
    """
    t1, t2 = (float(np.asarray(b.env[b.angle[s.on]])) + s.direction_angle for s in (s1, s2))
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
        sl = slides(b, lid)
        pair = next(((s1, s2) for i, s1 in enumerate(sl) for s2 in sl[i + 1:]
                     if not _parallel(b, s1, s2)), None)
        if pair is None:
            continue
        own = [s.point for s in pair if s.link == lid]
        name = own[0] if own else next(iter(link.points))
        out.append(_Group("two_slides", pin=name, links=(lid, lid), slides=pair))
    return out


def do_two_slides(b: _Builder, lid: str, name: str, pair: tuple[Slider, ...]) -> list[str]:
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
