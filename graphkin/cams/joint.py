"""A disk cam as a joint of a mechanism file (``[[cams]]``): its equivalent linkage at the posture.

A ``[[cams]]`` entry of a mechanism file puts the cam of a cam file
(docs/formats/cam.md) on a link pinned to the frame and its follower on
another link.  At the file's drive (the cam's angle) the direct contact is
replaced by the equivalent linkage through the centers of curvature of the
two surfaces in contact (Sec. 4.7, Examples 4.7-4.8; Sec. 6.10), which has
the cam mechanism's posture, velocity *and* acceleration at that instant
(:func:`graphkin.cams.equivalent.equivalent_linkage`):

* a knife edge or roller: a coupler (the next free link number) pinned to the
  cam at ``K<f>``, the pitch curve's center of curvature, and to the follower
  at its trace point ``T<f>`` (the roller's center; ``<f>`` is the follower's
  link id) — the contact force then acts along the coupler, the common normal;
* a flat face: the cam's center of curvature ``K<f>`` runs in a straight slot
  of the follower, parallel to the face at the profile's radius of curvature
  (Example 4.7) — the slot's force is normal to the face, the common normal.

Coulomb friction at a translating follower's guide (``guide_friction``, the
``F_μ sgn Ẏ`` of Sec. 6.13) is the generated slider's friction.  Friction at
the contact itself is not modelled: the equivalent slot slides at another
speed than the contact does.

A translating follower slides on the frame along the guide ``G<f>a → G<f>b``
(the direction of rise; its own x axis runs along it, its origin at the trace
point); an oscillating follower turns about its pivot (``pivot``, default
``O4``; its own x axis along the arm at the cam file's θ4).  The cam's own
coordinates are the cam file's ``u, v`` from its center.  The rest of the
mechanism (links driven by the follower) is read as written.  The cam is
also drawn: its profile as an outline body, the roller or the face.

This module is reached from :mod:`graphkin.mechanisms.cam_joint` (a lazy
import: the cam layer sits above the mechanism layer).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 4.7 (Figs. 4.18, 4.20), 6.9-6.10, 6.13.
"""

from __future__ import annotations

import cmath
import copy
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.cams.analytic import profile
from graphkin.cams.equivalent import equivalent_linkage
from graphkin.cams.model import Cam
from graphkin.cams.parse import load_cam
from graphkin.errors import InputError
from graphkin.keys import read_units
from graphkin.units import length_factor, parse_quantity

__all__ = ["CamJoint", "expand", "OUTLINE_POINTS"]

#: Points of the cam's drawn outline (a body: drawing only).
OUTLINE_POINTS = 144


@dataclass(frozen=True)
class CamJoint:
    """One ``[[cams]]`` entry at the file's posture.

    Attributes
    ----------
    key : str
        ``cams[i]``.
    cam : Cam
        The cam file's cam (its own length unit).
    link, follower, coupler : str
        The cam's link, the follower's, and the equivalent coupler's (roller and
        knife edge; ``""`` for a flat face).
    theta : float
        Θ, the cam angle (rad) at the drive, turned in the cam's sense.
    center : tuple of float
        The cam's center O2 in the frame.
    axis : float
        The direction of the cam file's +y axis in the frame (rad).
    scale : float
        Mechanism length units per cam-file length unit.
    Y, pressure : float
        The follower's lift and the pressure angle (rad) at Θ.
    contact, normal : tuple of float
        The contact point in the frame and the common normal's unit vector
        (pointing into the cam).
    data : mapping or None
        The mechanism file's data as written (with its ``[[cams]]``): what a
        sweep over the cycle is rebuilt from (:mod:`graphkin.cams.cycle`).
    """

    key: str
    cam: Cam
    link: str
    follower: str
    coupler: str
    theta: float
    center: tuple[float, float]
    axis: float
    scale: float
    Y: float
    pressure: float
    contact: tuple[float, float]
    normal: tuple[float, float]
    data: Mapping[str, Any] | None = field(default=None, compare=False, repr=False)


def _fail(key: str, message: str, source: str) -> InputError:
    return InputError(message, key=key, file=source)


def _link_id(value: Any, key: str, source: str) -> str:
    if isinstance(value, bool) or not isinstance(value, (int, str)):
        raise _fail(key, f"a link id is a number or a name, not {value!r}", source)
    return str(value)


def _drive_angle(data: Mapping[str, Any], cam_link: str, key: str, source: str,
                 unit: str) -> float | None:
    """The cam link's angle (rad) from the file's drive of it; None where none drives it.

    Without a drive of its own (an absolute angle, or a law following the first
    drive) the cam's angle is its link's in the linkage (:mod:`graphkin.cams.linkage`).
    """
    raw = data.get("drive", [])
    drives = [raw] if isinstance(raw, Mapping) else raw if isinstance(raw, list) else []
    for d in drives:
        if isinstance(d, Mapping) and str(d.get("link")) == cam_link and "angle" in d \
                and "relative_to" not in d:
            try:
                deg, sense = parse_quantity(d["angle"], "angle", unit)
            except ValueError as exc:
                raise _fail("drive.angle", str(exc)[:200], source) from None
            if sense is not None or not math.isfinite(deg):
                raise _fail("drive.angle", "an angle in degrees (counterclockwise)", source)
            return math.radians(deg)
        if isinstance(d, Mapping) and str(d.get("link")) == cam_link and \
                isinstance(d.get("follows"), Mapping):
            where = f"drive[{drives.index(d)}].follows" if len(drives) > 1 else "drive.follows"
            return _follows_angle(drives, d["follows"], where, unit, source)
    return None


def _follows_angle(drives: list[Any], law: Mapping[str, Any], key: str, unit: str,
                   source: str) -> float:
    """The cam link's angle (rad) where its drive follows the first by a linear law.

    ``θ = ratio θ_first + offset`` (degrees, :mod:`graphkin.mechanisms.laws`),
    the first drive an angle: the cam turns with the crank that drives it
    (a belt, a gear pair written as the law).  The rest of the law (its link,
    its numbers) is checked where the drive is read.
    """
    first = drives[0] if drives else None
    if not isinstance(first, Mapping) or "angle" not in first or "relative_to" in first:
        raise _fail(key, "a cam's link follows the first drive by its angle only (the first "
                    "drive an absolute angle)", source)
    if "table" in law:
        raise _fail(key, "a cam's link follows the first drive by a ratio and an offset, not "
                    "a table", source)
    vals = []
    for raw, what in ((first["angle"], "drive.angle"), (law.get("offset", 0.0), key)):
        try:
            deg, sense = parse_quantity(raw, "angle", unit)
        except ValueError as exc:
            raise _fail(what, str(exc)[:200], source) from None
        if sense is not None or not math.isfinite(deg):
            raise _fail(what, "an angle in degrees (counterclockwise)", source)
        vals.append(deg)
    ratio = law.get("ratio", 1.0)
    if isinstance(ratio, bool) or not isinstance(ratio, (int, float)) or \
            not math.isfinite(float(ratio)):
        raise _fail(f"{key}.ratio", "the ratio is a finite number", source)
    return math.radians(float(ratio) * vals[0] + vals[1])


def expand(data: Mapping[str, Any], source: str) -> tuple[dict[str, Any], tuple[CamJoint, ...]]:
    """The mechanism-file data with every ``[[cams]]`` entry replaced by its equivalent linkage.

    Parameters
    ----------
    data : mapping
        The parsed TOML of a mechanism file (its keys already checked).
    source : str
        The file's name: a cam file's relative path is read from its folder.

    Returns
    -------
    data : dict
        Ordinary mechanism-file data (no ``cams`` key) for :mod:`graphkin.mechanisms.parse`.
    joints : tuple of CamJoint

    Raises
    ------
    InputError
        One line naming ``cams[i]``'s key (or the cam file's own key).

    Examples
    --------
    Ex 6.6's cam (a radial roller follower) at Θ = 30°: the follower's lift is
    Y = 15(1 − cos 60°) = 7.5 mm and the pressure angle 28.68°.

    >>> import math
    >>> from graphkin.mechanisms import from_dict
    >>> m = from_dict({"links": {"1": {"O2": [0, 0]}},
    ...     "cams": {"link": 2, "follower": 4, "file": "examples/cams/ex6_6_roller.toml"},
    ...     "drive": {"link": 2, "angle": 30, "omega": 1}})
    >>> j = m.cams[0]
    >>> round(j.Y, 6), round(math.degrees(j.pressure), 2), m.links["4"].points["T4"]
    (7.5, 28.68, (0.0, 0.0))
    >>> j.coupler, round(m.links["5"].points["T4"][0], 3)    # |ρ| of the pitch curve
    ('5', 72.757)
    """
    written = copy.deepcopy(dict(data))
    data = dict(data)
    raw = data.pop("cams")
    entries = [raw] if isinstance(raw, Mapping) else raw
    if not isinstance(entries, list) or not entries:
        raise _fail("cams", "expected [[cams]] tables", source)
    unit = read_units(data.get("units", {}), "units", source).get("length", "mm")
    try:
        mech_factor = length_factor(unit)
    except ValueError as exc:
        raise _fail("units.length", str(exc), source) from None
    links_in = data.get("links")
    if not isinstance(links_in, Mapping) or not isinstance(links_in.get("1"), Mapping):
        raise _fail("links", "a mechanism needs [links.1] (the frame) and moving links", source)
    links: dict[str, dict[str, Any]] = {str(k): dict(v) if isinstance(v, Mapping) else v
                                         for k, v in links_in.items()}
    sliders = _entries(data, "sliders", source)
    slots = _entries(data, "slots", source)
    bodies = _entries(data, "bodies", source)
    assembly = dict(data.get("assembly", {})) if isinstance(data.get("assembly", {}),
                                                            Mapping) else {}
    joints = []
    for i, e in enumerate(entries):
        key = f"cams[{i}]"
        if not isinstance(e, Mapping):
            raise _fail(key, f"expected a table, not {e!r}", source)
        for need in ("link", "follower", "file"):
            if need not in e:
                raise _fail(f"{key}.{need}", "missing: a cam names its link, its follower's "
                            "link and its cam file", source)
        cl = _link_id(e["link"], f"{key}.link", source)
        fl = _link_id(e["follower"], f"{key}.follower", source)
        if "1" in (cl, fl):
            raise _fail(f"{key}.link" if cl == "1" else f"{key}.follower",
                        "the cam and its follower are moving links (1 is the frame)", source)
        if cl == fl:
            raise _fail(f"{key}.follower", "the follower is another link than the cam", source)
        fv = e["file"]
        if not isinstance(fv, str) or not fv:
            raise _fail(f"{key}.file", "the cam file's path, a string", source)
        path = Path(fv)
        if not path.is_absolute() and not source.startswith("<"):
            path = Path(source).parent / path
        if not path.is_file():
            raise _fail(f"{key}.file", f"no cam file {fv!r}", source)
        cam = load_cam(path).cam
        scale = length_factor(cam.unit) / mech_factor
        center = e.get("center", "O2")
        if not isinstance(center, str) or center not in links["1"]:
            raise _fail(f"{key}.center", f"the frame has no point {center!r} (the cam's "
                        "center: a point of [links.1])", source)
        pivot = e.get("pivot", "O4")
        if not isinstance(pivot, str) or not pivot:
            raise _fail(f"{key}.pivot", "the follower's pivot is named by a string", source)
        axis = math.radians(_number(e.get("axis", 90.0), f"{key}.axis", source))
        rot = cmath.exp(1j * (axis - math.pi / 2))
        o2 = complex(*_xy(links["1"][center], f"links.1.{center}", source))
        theta2 = _drive_angle(data, cl, key, source, unit)
        if theta2 is None:      # a link the linkage moves: its angle from the linkage solved
            theta2 = _linkage_angle(data, links, sliders, slots, assembly, entries[i:], cl,
                                    center, key, source)
        theta = cam.s * (theta2 - (axis - math.pi / 2))
        try:
            eq = equivalent_linkage(cam, theta)
        except InputError as exc:
            raise _fail(key, exc.message, source) from None
        if cl not in links:          # a cam written nowhere else: listed after the frame
            links = {"1": links["1"], cl: {}, **{k: v for k, v in links.items() if k != "1"}}
        for lid in (cl, fl):
            if not isinstance(links.setdefault(lid, {}), dict):
                raise _fail(f"links.{lid}", "expected a table", source)
        # past every link the entries name: a later cam's follower is not yet in links
        coupler = "" if cam.follower.kind.flat else _free_id(links, entries)
        names = {"O2": center, "O4": pivot, "K": f"K{fl}", "T": f"T{fl}", "S1": f"G{fl}a",
                 "S2": f"G{fl}b", "L1": f"F{fl}a", "L2": f"F{fl}b"}

        cam_links = links[cl]
        c_local = complex(*_xy(cam_links.get(center, [0.0, 0.0]), f"links.{cl}.{center}",
                               source))
        cam_links.setdefault(center, [c_local.real, c_local.imag])
        ids = {"1": "1", "2": cl, "3": coupler, "4": fl}
        for lid, pts in eq["links"].items():
            target = links.setdefault(ids[lid], {})
            if not isinstance(target, dict):
                raise _fail(f"links.{ids[lid]}", "expected a table", source)
            for name, xy in pts.items():
                n = names[name]
                if lid == "2" and name == "O2":
                    continue
                new = _place(lid, xy, o2, rot, scale, c_local)
                if n in target:
                    old = complex(*_xy(target[n], f"links.{ids[lid]}.{n}", source))
                    if abs(old - complex(*new)) > 1e-9 * max(1.0, abs(old)):
                        raise _fail(f"links.{ids[lid]}.{n}", f"graphkin names the cam's "
                                    f"{'pivot' if name == 'O4' else 'point'} {n} (at "
                                    f"[{new[0]:.6g}, {new[1]:.6g}]): rename yours", source)
                target[n] = new
        for s in eq.get("sliders", []):
            sliders.append({"link": fl, "on": "1", "point": names[s["point"]],
                            "line": [names[x] for x in s["line"]],
                            **_friction(e)})
        for s in eq.get("slots", []):
            slots.append({"link": cl, "on": fl, "point": names[s["point"]],
                          "line": [names[x] for x in s["line"]]})
        for k in ("guide_friction", "impending"):
            if k in e and cam.follower.kind.oscillating:
                raise _fail(f"{key}.{k}", "an oscillating follower has no guide (it turns "
                            "on a pin at its pivot)", source)
        for name, xy in eq["assembly"].items():
            assembly[names[name]] = _place("1", xy, o2, rot, scale, c_local)
        pr = profile(cam, np.array([theta]))
        bodies += _bodies(cam, cl, fl, names, c_local, scale)
        contact = o2 + rot * cmath.exp(1j * cam.s * theta) * complex(pr.contact[0]) * scale
        assert pr.normal is not None
        normal = rot * cmath.exp(1j * cam.s * theta) * complex(pr.normal[0])
        Y = float(cam.program.evaluate([theta]).Y[0])
        joints.append(CamJoint(key, cam, cl, fl, coupler, theta % (2 * math.pi),
                               (o2.real, o2.imag), axis, scale, Y * (1.0 if
                                                                     cam.follower.kind.oscillating
                                                                     else scale),
                               float(pr.pressure[0]), _tuple(contact), _tuple(normal),
                               written))
    data["links"] = links
    for name, rows in (("sliders", sliders), ("slots", slots), ("bodies", bodies)):
        if rows:
            data[name] = rows
    data["assembly"] = assembly
    return data, tuple(joints)


def _linkage_angle(data: Mapping[str, Any], links: Mapping[str, Any], sliders: list[Any],
                   slots: list[Any], assembly: Mapping[str, Any], rest: list[Any], cl: str,
                   center: str, key: str, source: str) -> float:
    """The angle of a cam's link that no drive turns: the linkage's (Sec. 2.8).

    The file as read so far (the earlier cams' equivalent linkages in place)
    without this cam's and the later ones' followers' sides is solved
    (:func:`graphkin.cams.linkage.linkage_angle`).  The cam's link turns about
    its pin with the frame at the cam's center, which it must hold.
    """
    from graphkin.cams.linkage import linkage_angle

    pts = links.get(cl)
    if not isinstance(pts, Mapping) or not pts:
        raise _fail(f"{key}.link", f"the cam's link {cl} must be the drive, by its angle "
                    f"([drive] link = {cl}, angle = ...), or a link of this file that the "
                    "linkage turns about its pin with the frame at the cam's center", source)
    frame = links.get("1")
    pivots = [n for n in pts if isinstance(frame, Mapping) and n in frame]
    if center not in pts and not pivots:
        raise _fail(f"{key}.link", f"the cam's link {cl} has no drive and no pin with the "
                    "frame (no point of it in [links.1]): a cam turns about a frame pivot, "
                    "so it must sit on the drive's link or on a link pinned to the frame",
                    source)
    if center not in pts:
        raise _fail(f"{key}.center", f"the cam's link {cl} has no drive, so the linkage turns "
                    f"it, about its pin with the frame: the cam's center {center!r} must be "
                    f"that pin, a point of [links.{cl}] (name it with center = ...)", source)
    rolls = any(isinstance(r, Mapping) and cl in (str(r.get("link")), str(r.get("on")))
                for r in _entries(data, "rolling", source))
    c0 = _xy(pts[center], f"links.{cl}.{center}", source)
    if not rolls and all(_xy(xy, f"links.{cl}.{n}", source) == c0 for n, xy in pts.items()):
        raise _fail(f"{key}.link", f"the cam's link {cl} has no drive and no point but its "
                    f"center {center}: its angle is not defined by two of its points (give it "
                    "the pin by which the linkage turns it)", source)
    now = dict(data, links=links, assembly=dict(assembly))
    for name, rows in (("sliders", sliders), ("slots", slots)):
        if rows:
            now[name] = rows
    followers = [str(e.get("follower")) for e in rest if isinstance(e, Mapping)]
    return linkage_angle(now, cl, followers, key, source)


def _place(lid: str, p: list[float], o2: complex, rot: complex, scale: float,
           c_local: complex) -> list[float]:
    """A point of the equivalent linkage (cam-file units and frames) in the mechanism's.

    ``lid`` is the equivalent linkage's link: 1 the frame (turned by the cam's axis about
    O2), 2 the cam (its own u, v from its center), any other its own coordinates.
    """
    z = complex(*p) * scale
    if lid == "1":
        z = o2 + rot * z
    elif lid == "2":
        z = c_local + z
    return _pt(z)


def _friction(e: Mapping[str, Any]) -> dict[str, Any]:
    """Coulomb friction at the follower's guide, F_μ sgn Ẏ (Sec. 6.13): the slider's."""
    out: dict[str, Any] = {}
    if "guide_friction" in e:
        out["friction"] = e["guide_friction"]
    if "impending" in e:
        out["impending"] = e["impending"]
    return out


def _bodies(cam: Cam, cl: str, fl: str, names: dict[str, str], c_local: complex,
            scale: float) -> list[dict[str, Any]]:
    """The cam's profile (an outline), the roller (a circle) or the face: drawing only."""
    th = np.linspace(0.0, 2 * np.pi, OUTLINE_POINTS, endpoint=False)
    u = profile(cam, th).contact
    u = u[np.isfinite(u)]
    out: list[dict[str, Any]] = []
    if len(u) >= 3:
        out.append({"link": cl, "outline": [_pt(c_local + z * scale) for z in u]})
    f = cam.follower
    if f.kind.roller:
        out.append({"link": fl, "circle": {"center": names["T"], "radius": f.roller * scale}})
    elif f.kind.flat:
        half = (f.face / 2 if f.face else 0.6 * (cam.prime + abs(cam.program.lift))) * scale
        if f.kind.oscillating:
            y = -f.rise.sign * f.face_offset * scale      # the face, in the arm's frame
            reach = float(np.abs(complex(*f.pivot))) * scale
            out.append({"link": fl, "face": [[reach - 2 * half, y], [reach + half, y]]})
        else:
            out.append({"link": fl, "face": [[0.0, -half], [0.0, half]]})
    return out


def _entries(data: Mapping[str, Any], name: str, source: str) -> list[Any]:
    raw = data.get(name, [])
    if isinstance(raw, Mapping):
        return [raw]
    if not isinstance(raw, list):
        raise _fail(name, f"expected [[{name}]] tables", source)
    return list(raw)


def _free_id(links: Mapping[str, Any], entries: list[Any]) -> str:
    named = [str(e.get(k)) for e in entries if isinstance(e, Mapping)
             for k in ("link", "follower")]
    nums = [int(k) for k in [*links, *named] if k.isdigit()]
    return str(max(nums, default=1) + 1)


def _xy(v: Any, key: str, source: str) -> tuple[float, float]:
    if (isinstance(v, list) and len(v) == 2 and all(isinstance(c, (int, float))
                                                    and not isinstance(c, bool) for c in v)
            and all(math.isfinite(c) for c in v)):
        return float(v[0]), float(v[1])
    raise _fail(key, f"a point must be two numbers [x, y], not {v!r}", source)


def _number(v: Any, key: str, source: str) -> float:
    if isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) \
            and abs(v) < 1e6:
        return float(v)
    raise _fail(key, f"an angle in degrees, not {v!r}", source)


def _pt(z: complex) -> list[float]:
    return [float(z.real), float(z.imag)]


def _tuple(z: complex) -> tuple[float, float]:
    return (float(z.real), float(z.imag))
