"""A gear train read off a mechanism file: its rolling circles as gears, their carriers as arms.

A mechanism file describes a planetary train by its links: gears are the
circles of its ``[[rolling]]`` contacts (circle on circle), and the member
that carries both axes of a mesh is the link holding both centers (the
frame for fixed axes, else an arm).  :func:`train_of` builds the
:class:`~graphkin.gears.train.Train` of Secs. 7.12-7.16 from it, so that the
book's formula method (Eq. 7.25) and tabular method (Sec. 7.16) can be
printed for the same mechanism the rolling constructions solve, and checked
against them.

Naming: a gear is named by its link (``3``); a second circle on the same
link (a compound planet) by the link and its order (``4'``), joined to the
first on one shaft.  A gear of the frame (a fixed ring or sun) is ``1``,
given at rest.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.12-7.16, Eqs. (7.24)-(7.25).
"""

from __future__ import annotations

from collections.abc import Mapping
from fractions import Fraction

from graphkin.gears.train import FRAME, Contact, Mesh, Train
from graphkin.mechanisms.model import Mechanism, Rolling

__all__ = ["train_of", "gear_names"]

_FRAME_LINK = "1"


def gear_names(mech: Mechanism) -> dict[tuple[str, str, float], str]:
    """Each gear circle ``(link, center, radius)`` of the rolling contacts -> its name.

    Only circle-on-circle contacts whose centers are named points count.
    """
    names: dict[tuple[str, str, float], str] = {}
    count: dict[str, int] = {}
    for r in _meshing(mech):
        assert r.on_center_point is not None and r.on_radius is not None
        for key in ((r.on, r.on_center_point, float(r.on_radius)),
                    (r.link, r.center, float(r.radius))):
            if key not in names:
                n = count.get(key[0], 0)
                names[key] = key[0] + "'" * n
                count[key[0]] = n + 1
    return names


def _meshing(mech: Mechanism) -> list[Rolling]:
    return [r for r in mech.rolling if not r.on_line and r.on_center_point is not None
            and r.on_radius is not None]


def _carrier(mech: Mechanism, r: Rolling) -> str | None:
    """The link (other than the two gears) that holds both centers; the frame first."""
    both = [lid for lid, link in mech.links.items() if lid not in (r.link, r.on)
            and r.center in link.points and r.on_center_point in link.points]
    if _FRAME_LINK in both:
        return FRAME
    return both[0] if len(both) == 1 else None


def train_of(mech: Mechanism, given: Mapping[str, float], unit: str = "rad/s") -> Train | None:
    """The gear train of a mechanism's rolling circles, or None when it is not one.

    Parameters
    ----------
    mech : Mechanism
    given : mapping
        Link -> its angular velocity (the drives' ω, in ``unit``).
    unit : str
        The unit of ``given`` and of the train's answers (``rad/s``, ``rev/min``).

    Returns
    -------
    Train or None
        None when the file has no circle-on-circle contact, a contact whose
        centers no single link carries, a line (rack) contact, or a given
        member that is neither a gear nor an arm of the train.
    """
    meshing = _meshing(mech)
    if not meshing or len(meshing) != len(mech.rolling):
        return None
    names = gear_names(mech)
    size = {name: Fraction(key[2]).limit_denominator(10**9) for key, name in names.items()}
    meshes = []
    for r in meshing:
        arm = _carrier(mech, r)
        if arm is None:
            return None
        assert r.on_center_point is not None and r.on_radius is not None
        driver = names[(r.on, r.on_center_point, float(r.on_radius))]
        driven = names[(r.link, r.center, float(r.radius))]
        contact = Contact.INTERNAL if r.contact == "inside" else Contact.EXTERNAL
        meshes.append(Mesh(driver, driven, contact, arm))
    joined = []
    by_link: dict[str, list[str]] = {}
    for (lid, _, _), name in names.items():
        by_link.setdefault(lid, []).append(name)
    for group in by_link.values():
        if len(group) > 1:
            joined.append(tuple(group))
    speeds = {str(k): float(v) for k, v in given.items()}
    if _FRAME_LINK in by_link:
        speeds.setdefault(_FRAME_LINK, 0.0)
    train = Train(size, meshes, joined, speeds, unit, mech.title, mech.source,
                  by_teeth=False)
    members = set(train.members)
    if any(m not in members for m in speeds):
        return None
    return train
