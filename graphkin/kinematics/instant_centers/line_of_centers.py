"""Velocities by the line-of-centers method (Sec. 3.16)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from graphkin.errors import DegenerateError, InputError
from graphkin.geometry import ops as g
from graphkin.kinematics.instant_centers.centers import InstantCenters
from graphkin.kinematics.instant_centers.kennedy import _centers, _perp, _world_origin_velocity
from graphkin.kinematics.instant_centers.labels import center_label
from graphkin.kinematics.instant_centers.ratios import _unbounded
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME

__all__ = ["LineOfCentersVelocity", "line_of_centers_velocity"]

Array = np.ndarray


@dataclass
class LineOfCentersVelocity:
    """The result of the line-of-centers method (Sec. 3.15).

    Attributes
    ----------
    velocity : ndarray, shape (..., 2)
        Velocity of the point, relative to the reference link.
    omega : ndarray
        ω of the point's link relative to the reference (0 when it translates).
    common : str
        Label of the common center (``I24``), whose velocity carries the motion over.
    common_velocity : ndarray, shape (..., 2)
        Its velocity, found as a point of the given link.
    line : tuple of str
        The three centers on the line of centers.
    """

    velocity: Array
    omega: Array
    common: str
    common_velocity: Array
    line: tuple[str, str, str]


def line_of_centers_velocity(sol: Solution | InstantCenters, point: str | ArrayLike,
                             link: object, *, given: object,
                             reference: object = FRAME) -> LineOfCentersVelocity:
    """Velocity of a point of ``link`` from the known motion of link ``given`` (Sec. 3.15).

    The book's four steps: (1) the three links are ``given``, ``link`` and the
    reference; (2) their three centers lie on the line of centers; (3) the
    common center ``I(given, link)`` gets its velocity as a point of ``given``
    (turning about ``I(ref, given)`` at ω_given, or translating with it);
    (4) as a point of ``link`` it fixes ω_link about ``I(ref, link)``, and so
    the velocity of any point of ``link``.  Only ω_given (and, when ``given``
    translates, the velocity of its points) is read from the solution.

    Parameters
    ----------
    sol : Solution or InstantCenters
    point : str or (x, y)
        A named point of ``link``, or world coordinates of a point of it.
    link : link id
    given : link id
        The link whose motion is known.
    reference : link id
        The frame by default.

    Returns
    -------
    LineOfCentersVelocity

    Raises
    ------
    DegenerateError
        When the common center coincides with ``I(ref, link)`` (the motion
        cannot be carried over), or all three centers are at infinity.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.15, Figs. 3.29-3.31, Example 3.12.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.examples.fourbar().solve()
    >>> r = line_of_centers_velocity(sol, "C", 4, given=2)
    >>> r.common, bool(np.allclose(r.velocity, sol.velocity("C")))
    ('I24', True)
    """
    ic = _centers(sol)
    s = ic.solution
    lid, gid, rid = str(link), str(given), str(reference)
    if isinstance(point, str):
        where = s.position(point, lid)
    else:
        where = np.asarray(point, dtype=float)
    if lid == rid:
        z = np.zeros(np.shape(where))
        return LineOfCentersVelocity(z, np.zeros(z.shape[:-1]), "", z, ("", "", ""))
    if lid == gid:
        raise InputError("the given link and the point's link must differ")
    a = ic[(rid, gid)].point          # the given link's center
    b = ic[(rid, lid)].point          # the point's link's center
    c = ic[(gid, lid)].point          # the common center
    labels = (center_label(rid, gid), center_label(gid, lid), center_label(rid, lid))
    ug, wg = _world_origin_velocity(s, gid)
    ur, wr = _world_origin_velocity(s, rid)
    w_given = wg - wr
    ca, cb, cc = g.is_ideal(a), g.is_ideal(b), g.is_ideal(c)
    with np.errstate(invalid="ignore", divide="ignore"):
        # (3) velocity of the common center as a point of the given link
        cxy = np.where(cc[..., None], 0.0, g.xy(c))
        v_trans = ug - ur  # a translating link: every point moves alike
        v_rot = w_given[..., None] * _perp(cxy - g.xy(a))
        v_c = np.where(ca[..., None], v_trans, v_rot)
        # (4) as a point of the wanted link, about its own center b
        rb = cxy - g.xy(b)
        w_link = g.dot2(v_c, _perp(rb)) / g.dot2(rb, rb)
        # the common center at infinity: the two links turn alike (ω_link = ω_given)
        w_link = np.where(cc, w_given, w_link)
        w_link = np.where(cb, 0.0, w_link)
        v_rot_b = w_link[..., None] * _perp(where - g.xy(b))
        # the wanted link translates: every point has the velocity of the common center
        vel = np.where(cb[..., None], v_c, v_rot_b)
    if _unbounded(ic, vel[..., 0] + vel[..., 1] + w_link):
        raise DegenerateError(
            f"the line-of-centers method fails here: {labels[1]} and {labels[2]} coincide, or "
            "the centers are all at infinity", centers=labels)
    return LineOfCentersVelocity(vel, w_link, labels[1], v_c, labels)
