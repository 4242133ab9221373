"""A cam mechanism at one cam angle as its equivalent linkage, written as a mechanism file.

Direct contact is replaced, for velocities and accelerations, by a linkage
through the centers of curvature of the two surfaces in contact (Sec. 4.7,
Examples 4.7-4.8; Sec. 6.10):

* a roller or knife edge: a coupler 3 pinned to the cam at K, the pitch
  curve's center of curvature, and to the follower at the roller's center
  T, |ρ| long (Eq. 6.37): a slider-crank or a four-bar (Fig. 4.18b);
* a flat face: the cam's center of curvature K (a point of the cam) runs in
  a straight slot of the follower, parallel to the face at the profile's
  radius of curvature ρ (Eq. 6.27) — Example 4.7 with a circle of that radius.

The linkage has the cam's posture, velocity and acceleration at that cam
angle, so ``graphkin solve`` works on it as on any mechanism (``graphkin
cam FILE --equivalent ANGLE -o eq.toml``), and ``draw -d
velocity|acceleration|centers`` and ``steps`` wherever the posture is
constructed one group at a time (the translating flat face's follower keeps
its angle and is held by the guide and the slot through K: Sec. 2.8, case 3).
The follower's velocity and acceleration it gives equal
``y'ω`` and ``y''ω²`` (tested through :mod:`graphkin.kinematics`).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 4.7 (Fig. 4.18), 6.9-6.10.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.cams.analytic import profile
from graphkin.cams.model import Cam, FollowerKind
from graphkin.errors import InputError

__all__ = ["equivalent_linkage", "equivalent_toml"]


def _pt(z: complex) -> list[float]:
    return [float(z.real), float(z.imag)]


def equivalent_linkage(cam: Cam, theta: float) -> dict[str, Any]:
    """The equivalent linkage of ``cam`` at cam angle Θ (rad), as mechanism-file data.

    Links: 1 the frame (O2, the follower's guide or pivot O4), 2 the cam
    (its own frame: the profile's u, v), 3 the coupler K-T (roller and knife
    edge), 4 the follower.  The drive turns the cam to Θ at the cam's speed
    (1 rad/s when the file gives none).

    Raises
    ------
    InputError
        At a posture where the surface in contact is straight (an infinite
        radius of curvature): there is no center of curvature to pin.

    Examples
    --------
    Ex 6.6 at Θ = 30°: the coupler is the pitch curve's radius of curvature.

    >>> import math
    >>> from graphkin.cams.examples import example_6_6
    >>> d = equivalent_linkage(example_6_6(), math.radians(30))
    >>> round(d["links"]["3"]["T"][0], 3), d["assembly"]["T"]
    (72.757, [0.0, 47.5])
    """
    f = cam.follower
    s = cam.s
    pr = profile(cam, np.array([theta]))
    rot = complex(math.cos(s * theta), math.sin(s * theta))       # cam frame -> fixed
    c = complex(pr.contact[0])
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    omega = (cam.omega or 1.0) * s
    assert pr.normal is not None
    n_in = complex(pr.normal[0])                  # into the cam, at the contact
    if f.kind.flat:
        rho = float(pr.rho[0])
        centre = c + rho * n_in
    else:
        assert pr.pitch is not None and pr.rho_pitch is not None
        rho = float(pr.rho_pitch[0])
        centre = complex(pr.pitch[0]) + rho * n_in
    if not math.isfinite(rho) or abs(rho) > 1e6 * size:
        raise InputError(f"at Θ = {math.degrees(theta):g}° the surface in contact is "
                         "straight (no center of curvature): choose another cam angle",
                         key="--equivalent", file=cam.source or None)
    kf = centre * rot                                   # K in the fixed frame
    data: dict[str, Any] = {
        "title": f"{cam.title or 'cam'}: equivalent linkage at Θ = {math.degrees(theta):g}°",
        "units": cam.unit,
        "links": {"1": {"O2": [0.0, 0.0]}, "2": {"O2": [0.0, 0.0], "K": _pt(centre)},
                  "4": {}},
        "drive": {"link": 2, "angle": math.degrees(s * theta), "omega": omega, "alpha": 0.0},
        "assembly": {"K": _pt(kf)},
    }
    links = data["links"]
    if f.kind.oscillating:
        sig = f.rise.sign
        th4 = cam.arm0 + sig * float(cam.program.evaluate([theta]).Y[0])
        links["1"]["O4"] = list(f.pivot)
        links["4"]["O4"] = [0.0, 0.0]
        data["assembly"]["O4"] = list(f.pivot)
        if f.kind is FollowerKind.OSCILLATING_ROLLER:
            links["4"]["T"] = [f.arm, 0.0]
            data["assembly"]["T"] = _pt(complex(*f.pivot) + f.arm * complex(math.cos(th4),
                                                                            math.sin(th4)))
        else:
            e = -sig * f.face_offset
            y = e - sig * rho
            links["4"]["L1"], links["4"]["L2"] = [0.0, y], [size, y]
            data["assembly"]["L1"] = _pt(complex(*f.pivot) + 1j * y * complex(math.cos(th4),
                                                                              math.sin(th4)))
    else:
        links["1"]["S1"], links["1"]["S2"] = [f.offset, 0.0], [f.offset, size]
        Y = float(cam.program.evaluate([theta]).Y[0])
        t = complex(f.offset, cam.y0 + Y)
        links["4"]["T"] = [0.0, 0.0]
        data["assembly"]["T"] = _pt(t)
        data["sliders"] = [{"link": 4, "on": 1, "point": "T", "line": ["S1", "S2"]}]
        if f.kind.flat:
            # a slider's own x axis runs along its line (S1 -> S2, up): the face's parallel
            # at ρ below T, (a, −ρ) from T in the frame, is (−ρ, −a) in the follower's own
            links["4"]["L1"], links["4"]["L2"] = [-rho, size], [-rho, -size]
    if f.kind.flat:
        data["slots"] = [{"link": 2, "on": 4, "point": "K", "line": ["L1", "L2"]}]
    else:
        # the coupler 3 from K to the roller's center T, |ρ| long (Fig. 4.18b)
        links["3"] = {"K": [0.0, 0.0], "T": [abs(rho), 0.0]}
        data["links"] = {k: links[k] for k in ("1", "2", "3", "4")}
    return data


def equivalent_toml(cam: Cam, theta: float) -> str:
    """:func:`equivalent_linkage` written as a mechanism file (docs/formats/mechanism.md)."""
    d = equivalent_linkage(cam, theta)

    def v(x: Any) -> str:
        if isinstance(x, str):
            return '"' + x.replace("\\", "\\\\").replace('"', '\\"') + '"'
        if isinstance(x, list):
            return "[" + ", ".join(v(y) for y in x) + "]"
        if isinstance(x, dict):
            return "{ " + ", ".join(f"{k} = {v(y)}" for k, y in x.items()) + " }"
        if isinstance(x, float):
            return repr(x)
        return str(x)

    lines = [f"# {d['title']}", "# written by graphkin cam --equivalent (Sec. 4.7: the "
             "equivalent linkage through the centers of curvature)",
             f"title = {v(d['title'])}", f"units = {v(d['units'])}", ""]
    for lid, pts in d["links"].items():
        lines.append(f"[links.{lid}]")
        lines += [f"{name} = {v(xy)}" for name, xy in pts.items()]
        lines.append("")
    for table in ("sliders", "slots"):
        for entry in d.get(table, []):
            lines.append(f"[[{table}]]")
            lines += [f"{k} = {v(x)}" for k, x in entry.items()]
            lines.append("")
    for table in ("drive", "assembly"):
        lines.append(f"[{table}]")
        lines += [f"{k} = {v(x)}" for k, x in d[table].items()]
        lines.append("")
    return "\n".join(lines)
