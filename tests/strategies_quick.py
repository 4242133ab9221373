"""Hypothesis strategies for quick-return mechanisms (issue 24), beside ``strategies.py``.

Built with the same world-first builder as the families of
:mod:`strategies` (a posture chosen in the world, each link written in a
random local frame), so the generating posture and the angular velocities
solved by hand are the exact answers.
"""

from __future__ import annotations

from typing import Any

from hypothesis import assume
from hypothesis import strategies as st
from strategies import (
    RandomMechanism,
    _add,
    _Build,
    _dir,
    _dot,
    _e,
    _Field,
    _neg,
    _norm,
    _perp,
    _rrp,
    _solve2,
    _sub,
)

__all__ = ["quick_returns"]


@st.composite
def _quick_return(draw: Any, with_rates: bool) -> RandomMechanism:
    through = draw(st.booleans())
    b = _Build(draw, f"quick-return{', ram guide through O4' if through else ''}", with_rates)
    o2 = b.add("1", "O2", b.point())
    b.add("2", "O2", o2)
    a = b.add("2", "A", _add(o2, _e(b.angle()), b.length(0.2, 0.8)))
    o4 = b.add("1", "O4", b.point(o2, 0.6))
    assume(_norm(_sub(o4, o2)) > 0.1 * b.size and _norm(_sub(a, o4)) > 0.1 * b.size)
    b.add("4", "O4", o4)
    u = _e(_dir(_sub(a, o4)))  # the slot of the lever 4 runs from O4 through the crank pin A
    c = b.add("4", "C", _add(o4, u, b.length(0.3, 1.5) * b.sign()))
    b.add("5", "C", c)
    b.slots.append({"link": 2, "on": 4, "point": "A", "line": ["O4", "C"]})
    # the rod 5 from C to the ram's pin D, at most 65° from the ram's line
    psi = b.angle()
    phi = psi + b.along()
    u6 = _e(phi)
    if through:  # the ram's guide passes through O4 (Whitworth): D where C's ray meets it
        s, _t = _solve2(_e(psi), _neg(u6), _sub(o4, c))
        assume(0.5 * b.size < s < 2.0 * b.size)
        dd = _add(c, _e(psi), s)
        p0 = o4
    else:
        dd = _add(c, _e(psi), b.length(0.5, 2.0))
        p0 = _add(dd, u6, -b.length(-1.0, 1.0))
    b.add("5", "D", dd)
    b.add("6", "D", dd)
    b.slider("6", "1", "D", p0, _add(p0, u6, b.length(0.3, 2.0)))
    b.drive_angle("2")
    f2 = _Field(b.rate_of["2"], o2)
    # A slides along the slot: perp(u)·(V_A2 - ω4 k×(A - O4)) = 0, and k×(A - O4) = |AO4| perp(u)
    f4 = _Field(_dot(_perp(u), f2.at(a)) / _norm(_sub(a, o4)), o4)
    f5, f6 = _rrp(f4, c, dd, u6)
    b.generic_motion({"2": f2, "4": f4, "5": f5, "6": f6}, {frozenset(("1", "6"))})
    return b.finish()


def quick_returns(with_rates: bool = True) -> st.SearchStrategy[RandomMechanism]:
    """Quick-return mechanisms (Sec. 1.7, Fig. 1.15): crank 2, slotted lever 4, rod 5, ram 6.

    The crank pin A runs in the slot O4-C of the lever 4 (pivoted at O4); the
    rod 5 joins C to the ram's pin D, which slides on a frame line at most 65°
    from the rod.  Half of them have the ram's guide through O4 (a Whitworth
    drawn as in the issue 24 report: a guide point on the pivot O4).
    """
    return _quick_return(with_rates)
