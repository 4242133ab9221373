"""The cam profile in closed form: the independent check of the graphic layout (Secs. 6.9-6.10).

Nothing here uses a construction step.  The trace point (the pitch curve) is
written in the fixed frame with its derivatives, turned into the cam's frame
by ``e^{-isΘ}`` (complex numbers, ``s`` = +1 for a counterclockwise cam), and:

* a knife edge or roller: the contact point lies a roller radius inside the
  pitch curve along its normal (Eq. 6.36), the pitch curve's radius of
  curvature is Eq. (6.37), the profile's Eq. (6.38), the pressure angle the
  angle between that normal and the follower's direction of motion
  (Eqs. 6.32, 6.39);
* a flat face: the profile is the envelope of the face's lines
  ``Re(N̄ X) = p``: the contact point ``(p + i p_α) N`` and the radius of
  curvature ``p + p_αα`` (for the translating face these are Eqs. 6.26, 6.27,
  6.30).

Radii of curvature are positive where the profile is convex (the book's
Eqs. 6.37-6.38 give a counterclockwise cam's convex profile a negative one).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 6.9 (Eqs. 6.26-6.31), 6.10
(Eqs. 6.32-6.39, Ex 6.6, Ex 6.7), 4.17 (Eq. 4.57).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphkin.cams.model import Cam, FollowerKind
from graphkin.cams.program import Kinematics

__all__ = ["Profile", "profile", "pitch"]

Array = np.ndarray


@dataclass(frozen=True)
class Profile:
    """The analytic profile at an array of cam angles.

    Attributes
    ----------
    theta : array
        Cam angle Θ (rad).
    contact : array, complex
        The contact point in the cam's frame ``u + iv`` (Eqs. 6.30, 6.36).
    pitch : array, complex or None
        The trace point in the cam's frame (the pitch curve); None for a flat face.
    rho : array
        Radius of curvature of the profile, positive where convex (Eqs. 6.27, 6.38).
    rho_pitch : array or None
        Radius of curvature of the pitch curve, positive where convex (Eq. 6.37).
    pressure : array
        Pressure angle φ (rad), positive when the normal leans as in Fig. 6.27
        during a rise (Eqs. 6.32, 6.39); zero for a translating flat face.
    face : array or None
        Flat faces: where the contact lies along the face, measured from the
        foot of the perpendicular from O2 (translating, Eq. 6.26: ``y'``) or
        from the pivot's foot (oscillating).
    normal : array, complex
        The profile's unit normal at the contact, pointing into the cam (cam frame).
    """

    theta: Array
    contact: Array
    pitch: Array | None
    rho: Array
    rho_pitch: Array | None
    pressure: Array
    face: Array | None
    normal: Array | None = None


def pitch(cam: Cam, k: Kinematics) -> tuple[Array, Array, Array, Array]:
    """The trace point (fixed frame), its Θ-derivatives, the follower's direction of motion.

    All complex arrays.

    Translating: ``P = ε + i(Y0 + Y)`` (Fig. 6.27); oscillating: ``P = O4 + r4 e^{iθ4}``
    with ``θ4 = θ4₀ + σY`` (Ex 6.7, Eqs. 2, 5-6).
    """
    f = cam.follower
    if f.kind.oscillating:
        sig = f.rise.sign
        th4 = cam.arm0 + sig * k.Y
        e = np.exp(1j * th4)
        o4 = complex(*f.pivot)
        p = o4 + f.arm * e
        p1 = 1j * f.arm * sig * k.y1 * e
        p2 = f.arm * e * (1j * sig * k.y2 - k.y1**2)
        return p, p1, p2, sig * 1j * e
    p = f.offset + 1j * (cam.y0 + k.Y)
    return p, 1j * k.y1, 1j * k.y2, np.full_like(p, 1j)


def _to_cam(cam: Cam, theta: Array, p: Array, p1: Array, p2: Array) -> tuple[Array, Array, Array]:
    """The same point in the cam's rotating frame, with derivatives (chain rule)."""
    s = cam.s
    r = np.exp(-1j * s * theta)
    return r * p, r * (p1 - 1j * s * p), r * (p2 - 2j * s * p1 - p)


def _roller(cam: Cam, k: Kinematics) -> Profile:
    s = cam.s
    pf, pf1, pf2, d = pitch(cam, k)
    p, p1, p2 = _to_cam(cam, k.theta, pf, pf1, pf2)
    w = np.abs(p1)
    inward = -s * 1j * p1 / w
    rr = cam.follower.roller if cam.follower.kind.roller else 0.0
    contact = p + rr * inward
    curl = (np.conj(p1) * p2).imag
    with np.errstate(divide="ignore"):
        rho_book = w**3 / curl          # Eq. (6.37)
    rho_pitch = -s * rho_book
    normal_fixed = np.exp(1j * s * k.theta) * (-inward)
    phi = s * np.angle(normal_fixed / d)
    return Profile(k.theta, contact, p, rho_pitch - rr, rho_pitch, phi, None, inward)


def _flat(cam: Cam, k: Kinematics) -> Profile:
    f = cam.follower
    s = cam.s
    if f.kind is FollowerKind.FLAT_FACE:
        nf = np.full(k.Y.shape, 1j)
        p, p1, p2 = cam.prime + k.Y, k.y1, k.y2
        a1, a2 = -s + 0 * k.Y, 0 * k.Y
    else:
        sig = f.rise.sign
        th4 = cam.arm0 + sig * k.Y
        n = 1j * np.exp(1j * th4)             # the arm's left normal
        o4 = complex(*f.pivot)

        def dot(a: Array, b: complex) -> Array:
            return (np.conj(a) * b).real

        t1, t2 = sig * k.y1, sig * k.y2        # θ4', θ4''
        p = sig * dot(n, o4) - f.face_offset
        p1 = sig * dot(1j * n, o4) * t1
        p2 = sig * (dot(1j * n, o4) * t2 - dot(n, o4) * t1**2)
        nf = sig * n
        a1, a2 = t1 - s, t2
    N = np.exp(-1j * s * k.theta) * nf
    pa = p1 / a1
    contact = (p + 1j * pa) * N
    rho = p + (p2 * a1 - p1 * a2) / a1**3
    cf = np.exp(1j * s * k.theta) * contact     # the contact point in the fixed frame
    if f.kind is FollowerKind.FLAT_FACE:
        phi = np.zeros_like(k.Y)
        along = (cf - 1j * cf.imag).real            # u along the face from O2's foot: Eq. 6.26
    else:
        sig = f.rise.sign
        o4 = complex(*f.pivot)
        dv = sig * 1j * (cf - o4)
        phi = s * np.angle(nf / (dv / np.abs(dv)))
        arm = np.exp(1j * (cam.arm0 + sig * k.Y))
        along = (np.conj(arm) * (cf - o4)).real
    return Profile(k.theta, contact, None, rho, None, phi, along, -N)


def profile(cam: Cam, theta: Array) -> Profile:
    """The analytic profile of ``cam`` at cam angles ``theta`` (rad).

    Examples
    --------
    Ex 6.6: Y = 15(1 − cos 2Θ) mm, R0 = 40 mm, roller 12 mm, Θ = 30°.

    >>> import math
    >>> from graphkin.cams.examples import example_6_6
    >>> pr = profile(example_6_6(), [math.radians(30)])
    >>> round(float(pr.contact[0].real), 3), round(float(pr.contact[0].imag), 3)
    (23.473, 29.139)
    >>> round(float(pr.rho[0]), 3), round(math.degrees(pr.pressure[0]), 2)
    (60.757, 28.68)

    The book prints u = 23.413 mm and ρ_cam = −60.775 mm: slips of its
    arithmetic (its own numbers give 23.750 − 12·1.250/54.141 = 23.473 and
    54.141³/2181.3 = 72.757; see docs/cams.md).
    """
    k = cam.program.evaluate(np.atleast_1d(np.asarray(theta, dtype=float)))
    # where the follower turns with the cam the envelope has no point (NaN), said by undercuts()
    with np.errstate(divide="ignore", invalid="ignore"):
        if cam.follower.kind.flat:
            return _flat(cam, k)
        return _roller(cam, k)
