"""The hook by which a mechanism file's ``[[cams]]`` reach the cam layer (Sec. 4.7).

A disk cam in a mechanism is a higher pair; for the posture, the velocities
and the accelerations at the file's drive it is replaced by its equivalent
linkage through the centers of curvature at the contact, which
:mod:`graphkin.cams.joint` writes as ordinary mechanism-file data.  The cam
layer sits above this one, so it is imported inside the function (as
``Solution.draw`` reaches ``render``): a file without ``[[cams]]`` never
loads it.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 4.7; Ch. 6.
"""

from __future__ import annotations

import dataclasses
import weakref
from collections.abc import Callable, Mapping
from typing import TYPE_CHECKING, Any

from graphkin.keys import MECHANISM, check_keys

if TYPE_CHECKING:
    from graphkin.mechanisms.model import Mechanism

__all__ = ["expand_cams", "for_sweep", "with_cams"]


def expand_cams(data: Mapping[str, Any], source: str) -> tuple[Mapping[str, Any], tuple[Any, ...]]:
    """``data`` with its ``[[cams]]`` replaced by their equivalent linkages, and the cam joints.

    Returns ``(data, ())`` unchanged for a file without cams.
    """
    if "cams" not in data:
        return data, ()
    from graphkin.cams.joint import expand  # the cam layer, above this one

    return expand(data, source)


def with_cams(data: Mapping[str, Any], source: str,
              build: Callable[[Mapping[str, Any]], Mechanism]) -> Mechanism:
    """``build(data)``, its ``[[cams]]`` first replaced by their equivalent linkages.

    The mechanism remembers its cams (:attr:`Mechanism.cams`).
    """
    if "cams" not in data:
        return build(data)
    check_keys(data, MECHANISM, source)     # a misspelt key first, before anything is read
    expanded, cams = expand_cams(data, source)
    return dataclasses.replace(build(expanded), cams=cams)


def for_sweep(mech: Mechanism) -> Mechanism:
    """The mechanism a sweep turns: ``mech``, or its cams' followers driven by their programs.

    For a cam mechanism: :func:`graphkin.cams.cycle.swept_mechanism`.  The
    equivalent linkage holds at the file's cam angle only (Sec. 4.7); over
    the cycle each follower moves as its cam's displacement diagram says (Sec. 6.3).
    """
    if not mech.cams:
        return mech
    hit = _SWEPT.get(id(mech))
    if hit is not None and hit[0]() is mech:   # once per mechanism: its sweeps reuse the engine
        return hit[1]
    from graphkin.cams.cycle import swept_mechanism  # the cam layer, above this one

    twin = swept_mechanism(mech)
    for k in [k for k, v in _SWEPT.items() if v[0]() is None]:
        del _SWEPT[k]
    _SWEPT[id(mech)] = (weakref.ref(mech), twin)
    return twin


_SWEPT: dict[int, tuple[weakref.ref[Mechanism], Mechanism]] = {}
"""Cam mechanism (by id, while it lives) -> the mechanism its sweeps turn."""
