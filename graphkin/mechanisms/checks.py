"""Checks of a mechanism read from a file beyond its keys: zero lengths, rates half given.

Zero lengths (Sec. 1.4)
-----------------------

A link is a rigid body that carries its joints at fixed distances (Sec. 1.4,
"links"); a binary link whose two pins stand at one place has no length: it
transmits no motion (a crank of zero length turns, by its drive, and nothing
moves), and it is the same as one pin joining the links it would join.  Typed
by hand it is most often a slip (``B = [0, 0]`` for ``B = [4, 0]``), but it is
also the book's equivalent linkage of a cam in a dwell (Sec. 4.7), which
``graphkin cam`` writes; so it is solved and the report notes it in one line
naming the key (:func:`zero_length_notes`).

What is not noted, because a zero length there means something to the book's
user (docs/formats/mechanism.md, "Zero lengths"):

* two **frame** pivots at one place: coaxial bearings (an arm turning about the
  sun's shaft, Sec. 10.5);
* a point of a link at a pin that is not itself a joint (a coupler point at
  ``B``, a slider's block point at its pin): a point, not a length;
* a slider's line through its crank's pivot: the in-line slider-crank (offset 0);
* a rolling circle's center at its link's pivot: a gear on its shaft.

Rates half given (Secs. 4.2-4.4)
--------------------------------
An angular acceleration without the angular velocity (``alpha`` without
``omega``) cannot be used: every normal component of the acceleration polygon
needs ω.  It was silently left out (no accelerations reported); it is refused.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

from graphkin.errors import InputError
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import is_zero


def _names_of(data: Mapping[str, Any]) -> set[str]:
    links = data.get("links")
    if not isinstance(links, Mapping):
        return set()
    return {str(n) for lk in links.values() if isinstance(lk, Mapping) for n in lk}


def added_points(data: Mapping[str, Any], expanded: Mapping[str, Any]) -> frozenset[str]:
    """The points a ``[[cams]]`` expansion added (its equivalent linkage's pins, Sec. 4.7).

    A cam's center of curvature may stand on its pivot (a circular arc about it, in
    a dwell): a crank of zero length the user never wrote, so not a slip to refuse.
    """
    if expanded is data:
        return frozenset()
    return frozenset(_names_of(expanded) - _names_of(data))


def zero_length_notes(mech: Mechanism, added: frozenset[str] = frozenset()) -> tuple[str, ...]:
    """A note for each moving link with two pins at one place (a zero length).

    Such a link moves nothing: a crank of zero length turns by its drive and
    every other link stands still.  That is what the book's equivalent linkage
    of a cam in a dwell is (Sec. 4.7: the profile's arc about the cam's pivot,
    its center of curvature on the pivot), and what ``graphkin cam`` writes for
    it; typed by hand it is more often a slip (``B = [0, 0]`` for ``B = [4, 0]``).
    So it is solved, and the report says so in one line naming the key.

    Parameters
    ----------
    mech : Mechanism
        The mechanism as read from the file, its ``[[cams]]`` replaced by their
        equivalent linkages.
    added : frozenset of str, optional
        Points a ``[[cams]]`` expansion added (the equivalent linkage's pins): the
        user never wrote them, and their zero length in a dwell is exact.

    Returns
    -------
    tuple of str
        ``links.<k>.<P>: pins <Q> and <P> of link <k> are at one place ...``.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 1.4 (links and joints), Sec. 4.7.
    """
    scale = mech.size
    out: list[str] = []
    for lid, link in mech.links.items():
        if lid == FRAME:
            continue
        joints = [p.name for p in mech.pins
                  if lid in p.links and p.name in link.points and p.name not in added]
        for i, a in enumerate(joints):
            for b in joints[i + 1:]:
                (xa, ya), (xb, yb) = link.points[a], link.points[b]
                if is_zero(math.hypot(xb - xa, yb - ya), scale):
                    out.append(f"links.{lid}.{b}: pins {a} and {b} of link {lid} are at one "
                               f"place: a link of zero length between its joints moves "
                               f"nothing (a cam's dwell; if not meant, give {b} its place "
                               f"on link {lid})")
    return tuple(out)


#: The names of a drive's first and second rates in the file, by the drive's kind.
_RATE_KEYS = {"angle": ("omega", "alpha"), "relative": ("omega", "alpha"),
              "position": ("velocity", "acceleration"), "x": ("vx", "ax"), "y": ("vy", "ay")}


def check_rates_given(mech: Mechanism, fail: Callable[[str | None, str], InputError]) -> None:
    """Refuse a drive (or ``[rates]``) that gives the second rate without the first.

    Parameters
    ----------
    mech : Mechanism
    fail : callable
        The parser's ``fail(key, message)``.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.2-4.4 (the acceleration polygon needs ω).
    """
    for d in mech.drives:
        first, second = _RATE_KEYS.get(d.kind, ("omega", "alpha"))
        if d.rate is None and d.rate2 is not None:
            raise fail(f"{d.key}.{second}", f"{second} is given without {first}: the "
                       f"accelerations need {first} too (write {first} = 0 for a drive "
                       "momentarily at rest)")
    r = mech.rates
    if r is not None and r.rate is None and r.rate2 is not None:
        first, second = ("velocity", "acceleration") if r.kind == "position" \
            else ("omega", "alpha")
        raise fail(f"rates.{second}", f"{second} is given without {first}: the "
                   f"accelerations need {first} too")
