"""Read and validate a cam file (``docs/formats/cam.md``).

Every problem is one :class:`~graphkin.errors.InputError` naming the file,
the dotted key and the reason (the CLI prints one line and exits 2); an
unknown or misspelt key is refused with the nearest valid one
(:data:`graphkin.keys.CAM`).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 6.3-6.10.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from graphkin.cams.model import Cam, Follower, FollowerKind, Sense
from graphkin.cams.motions import Motion, Rest
from graphkin.cams.program import Program, Segment
from graphkin.errors import InputError
from graphkin.files import parse_toml, read_text
from graphkin.keys import CAM, check_keys, nearest, read_units
from graphkin.units import length_factor, parse_quantity

__all__ = ["CamFile", "load_cam", "loads_cam"]

MAX_MAGNITUDE = 1e12
"""The largest length or angle accepted (lengths in the file's unit)."""
MAX_SEGMENTS = 1000
MAX_POINTS = 100_000


@dataclass(frozen=True)
class CamFile:
    """A cam file read: the cam and the limits asked for.

    Attributes
    ----------
    cam : Cam
    pressure_angle : float or None
        ``[limits] pressure_angle`` (rad): report the least prime circle for it.
    radius : float or None
        ``[limits] radius``: the least radius of curvature wanted of the profile.
    """

    cam: Cam
    pressure_angle: float | None = None
    radius: float | None = None
    dynamics: tuple[float, float, float] | None = None
    """``[dynamics]``: the retaining spring's rate (N/m), its preload (N) and the follower's
    mass (kg), for the jump speed (Sec. 6.12, Ex 6.8)."""


def load_cam(path: str | Path) -> CamFile:
    """Read a cam file.

    Raises
    ------
    InputError
        One line naming the file, the key and the reason.
    """
    return loads_cam(read_text(path), str(path))


def loads_cam(text: str, source: str = "<cam>") -> CamFile:
    r"""Parse cam-file text (see :func:`load_cam`).

    Examples
    --------
    >>> f = loads_cam('''
    ... units = "mm"
    ... [cam]
    ... prime = 40
    ... [follower]
    ... kind = "roller"
    ... roller = 12
    ... [[segment]]
    ... motion = "cycloidal"
    ... lift = 30
    ... angle = 180
    ... [[segment]]
    ... motion = "cycloidal"
    ... lift = -30
    ... angle = 180
    ... ''')
    >>> f.cam.follower.kind.value, f.cam.prime, len(f.cam.program.segments)
    ('roller', 40.0, 2)
    >>> loads_cam('[cam]\nprime = 40\nrotaton = "cw"', "c.toml")
    Traceback (most recent call last):
        ...
    graphkin.errors.InputError: unknown key 'rotaton' (did you mean 'rotation'?)
    """
    data = parse_toml(text, source)
    check_keys(data, CAM, source)
    return _Reader(data, source).read()


class _Reader:
    def __init__(self, data: Mapping[str, Any], source: str) -> None:
        self.data = data
        self.source = source
        self.unit = "mm"

    def fail(self, key: str | None, message: str) -> InputError:
        return InputError(message, key=key, file=self.source)

    def table(self, name: str, required: bool = True) -> Mapping[str, Any]:
        value = self.data.get(name)
        if value is None:
            if required:
                raise self.fail(name, f"missing: a cam file needs a [{name}] table")
            return {}
        if not isinstance(value, Mapping):
            raise self.fail(name, f"expected a table [{name}], not {value!r}")
        return value

    def length(self, value: Any, key: str) -> float:
        try:
            v, sense = parse_quantity(value, "length", self.unit)
        except ValueError as exc:
            raise self.fail(key, str(exc)[:200]) from None
        if sense is not None:
            raise self.fail(key, "a length has no sense (cw/ccw)")
        return self.bounded(v, key)

    def angle(self, value: Any, key: str) -> float:
        """Degrees when plain; any angle unit when written (``"1.5 rad"``); returns radians."""
        try:
            v, sense = parse_quantity(value, "angle", self.unit)
        except ValueError as exc:
            raise self.fail(key, str(exc)[:200]) from None
        if sense is not None:
            raise self.fail(key, "write the sense in its own key, not on the angle")
        return math.radians(self.bounded(v, key))

    def bounded(self, v: float, key: str) -> float:
        if not math.isfinite(v) or abs(v) > MAX_MAGNITUDE:
            raise self.fail(key, f"values beyond ±{MAX_MAGNITUDE:g} are not supported")
        return v

    def choice(self, value: Any, key: str, enum: Any) -> Any:
        valid = [e.value for e in enum]
        if isinstance(value, str) and value.strip().lower() in valid:
            return enum(value.strip().lower())
        guess = nearest(str(value), valid)
        hint = f" (did you mean {guess!r}?)" if guess else ""
        raise self.fail(key, f"{value!r} is not one of {', '.join(valid)}{hint}")

    # ---- the tables ------------------------------------------------------
    def read(self) -> CamFile:
        if "units" in self.data:
            self.unit = read_units(self.data["units"], "units", self.source).get("length", "mm")
            try:
                length_factor(self.unit)
            except ValueError as exc:
                raise self.fail("units.length", str(exc)) from None
        cam_t = self.table("cam")
        if "prime" not in cam_t:
            raise self.fail("cam.prime", "missing: the prime circle's radius R0")
        prime = self.length(cam_t["prime"], "cam.prime")
        if prime <= 0:
            raise self.fail("cam.prime", f"the prime circle's radius must be positive, not "
                            f"{prime:g}")
        rotation = self.choice(cam_t.get("rotation", "ccw"), "cam.rotation", Sense)
        omega = None
        if "speed" in cam_t:
            try:
                omega, sense = parse_quantity(cam_t["speed"], "omega", self.unit)
            except ValueError as exc:
                raise self.fail("cam.speed", str(exc)[:200]) from None
            if sense is not None:
                raise self.fail("cam.speed", "write the sense as cam.rotation, not on the speed")
            if not omega > 0:
                raise self.fail("cam.speed", f"the cam's speed must be positive, not {omega:g}")
            omega = self.bounded(omega, "cam.speed")
        follower = self.follower()
        program = self.program(follower.kind.oscillating)
        title = self.data.get("title", "")
        if not isinstance(title, str):
            raise self.fail("title", "the title is a string")
        cam = Cam(program, prime, follower, rotation, omega, self.unit, title, self.source)
        limits = self.table("limits", required=False)
        pa = self.angle(limits["pressure_angle"], "limits.pressure_angle") \
            if "pressure_angle" in limits else None
        if pa is not None and not 0 < pa < math.pi / 2:
            raise self.fail("limits.pressure_angle", "a pressure angle between 0° and 90°")
        radius = self.length(limits["radius"], "limits.radius") if "radius" in limits else None
        if radius is not None and radius < 0:
            raise self.fail("limits.radius", "a radius of curvature is not negative")
        return CamFile(cam, pa, radius, self.dynamics())

    def dynamics(self) -> tuple[float, float, float] | None:
        """``[dynamics]`` in SI: spring rate (N/m), preload (N), mass (kg) (Ex 6.8)."""
        t = self.table("dynamics", required=False)
        if not t:
            return None
        out = []
        for name, unit in (("spring", "N/m"), ("preload", "N"), ("mass", "kg")):
            key = f"dynamics.{name}"
            if name not in t:
                raise self.fail(key, "missing: [dynamics] needs spring, preload and mass")
            v = t[name]
            if isinstance(v, str):
                try:
                    from graphkin.units import check_unit, registry

                    num, _, u = v.strip().partition(" ")
                    q = registry().Quantity(float(num), check_unit(u.strip() or unit))
                    val = float(q.to(unit).magnitude)
                except Exception:  # pint raises several unrelated types
                    raise self.fail(key, f"{v!r} is not a number in {unit} or a value with "
                                    f"a unit of that kind") from None
            elif isinstance(v, (int, float)) and not isinstance(v, bool):
                val = float(v)
            else:
                raise self.fail(key, f"a number in {unit}, not {v!r}")
            if not (math.isfinite(val) and 0 <= val <= MAX_MAGNITUDE) or \
                    (name != "preload" and val == 0):
                raise self.fail(key, f"{'a positive' if name != 'preload' else 'a'} "
                                f"finite {name}, not {v!r}")
            out.append(val)
        return out[0], out[1], out[2]

    def follower(self) -> Follower:
        t = self.table("follower")
        if "kind" not in t:
            raise self.fail("follower.kind", "missing: one of " +
                            ", ".join(k.value for k in FollowerKind))
        kind = self.choice(t["kind"], "follower.kind", FollowerKind)
        allowed = {"kind", "offset", "roller", "face"} if not kind.oscillating else \
            {"kind", "roller", "face", "pivot", "arm", "face_offset", "rise"}
        if not kind.roller:
            allowed.discard("roller")
        if not kind.flat:
            allowed.discard("face")
        if kind is not FollowerKind.OSCILLATING_ROLLER:
            allowed.discard("arm")
        if kind is not FollowerKind.OSCILLATING_FLAT_FACE:
            allowed.discard("face_offset")
        for key in t:
            if key not in allowed:
                raise self.fail(f"follower.{key}", f"a {kind.value} follower has no {key} "
                                f"(its keys: {', '.join(sorted(allowed))})")
        for key in ({"roller"} if kind.roller else set()) | \
                ({"pivot", "rise"} if kind.oscillating else set()) | \
                ({"arm"} if kind is FollowerKind.OSCILLATING_ROLLER else set()):
            if key not in t:
                raise self.fail(f"follower.{key}", f"missing: a {kind.value} follower needs "
                                f"its {key}")
        pivot = (0.0, 0.0)
        if "pivot" in t:
            v = t["pivot"]
            if not isinstance(v, list) or len(v) != 2:
                raise self.fail("follower.pivot", f"the pivot is [x, y] from the cam's shaft, "
                                f"not {v!r}")
            pivot = (self.length(v[0], "follower.pivot"), self.length(v[1], "follower.pivot"))
        face = self.length(t["face"], "follower.face") if "face" in t else None
        if face is not None and face <= 0:
            raise self.fail("follower.face", "the face's width must be positive")
        return Follower(
            kind,
            offset=self.length(t.get("offset", 0), "follower.offset"),
            roller=self.length(t.get("roller", 0), "follower.roller"),
            face=face, pivot=pivot,
            arm=self.length(t.get("arm", 0), "follower.arm"),
            face_offset=self.length(t.get("face_offset", 0), "follower.face_offset"),
            rise=self.choice(t.get("rise", "ccw"), "follower.rise", Sense),
        )

    def program(self, angular: bool) -> Program:
        raw = self.data.get("segment")
        if raw is None:
            raise self.fail("segment", "missing: the follower's program, one [[segment]] "
                            "per rise, dwell or return")
        if not isinstance(raw, list) or not all(isinstance(s, Mapping) for s in raw):
            raise self.fail("segment", "write each segment as a [[segment]] table")
        if len(raw) > MAX_SEGMENTS:
            raise self.fail("segment", f"more than {MAX_SEGMENTS} segments")
        return Program(tuple(self.segment(s, i, angular) for i, s in enumerate(raw)),
                       source=self.source)

    def segment(self, t: Mapping[str, Any], i: int, angular: bool) -> Segment:
        key = f"segment[{i}]"
        if "motion" not in t:
            raise self.fail(f"{key}.motion", "missing: one of " + ", ".join(m.value
                                                                              for m in Motion))
        motion = self.choice(t["motion"], f"{key}.motion", Motion)
        if "angle" not in t:
            raise self.fail(f"{key}.angle", "missing: the segment's cam angle β (degrees)")
        beta = self.angle(t["angle"], f"{key}.angle")
        rest = None
        if motion in (Motion.HALF_HARMONIC, Motion.HALF_CYCLOIDAL):
            if "rest" not in t:
                raise self.fail(f"{key}.rest", "missing: \"start\" or \"end\", the end at "
                                "which the half motion has zero slope (Figs. 6.20-6.23)")
            rest = self.choice(t["rest"], f"{key}.rest", Rest)
        elif "rest" in t:
            raise self.fail(f"{key}.rest", "only half-harmonic and half-cycloidal motions "
                            "have a resting end")
        name = t.get("name", "")
        if not isinstance(name, str):
            raise self.fail(f"{key}.name", "a segment's name is a string")
        if motion is Motion.TABLE:
            if "lift" in t:
                raise self.fail(f"{key}.lift", "a table's lift is given by its points")
            table = self.points(t, key, beta, angular)
            # its lift is the change of displacement over it, as for the other motions
            # (the report's lift column; the points themselves are absolute)
            return Segment(motion, table[1][-1] - table[1][0], beta, None, name, table)
        if "points" in t:
            raise self.fail(f"{key}.points", "points belong to motion = \"table\"")
        if motion is Motion.DWELL:
            lift = 0.0
            if "lift" in t and t["lift"] not in (0, 0.0):
                raise self.fail(f"{key}.lift", "a dwell has no lift")
        else:
            if "lift" not in t:
                raise self.fail(f"{key}.lift", "missing: the lift (negative for a return)")
            lift = self.angle(t["lift"], f"{key}.lift") if angular else \
                self.length(t["lift"], f"{key}.lift")
        return Segment(motion, lift, beta, rest, name)

    def points(self, t: Mapping[str, Any], key: str, beta: float,
               angular: bool) -> tuple[tuple[float, ...], tuple[float, ...]]:
        pts = t.get("points")
        if not isinstance(pts, list) or not 3 <= len(pts) <= MAX_POINTS:
            raise self.fail(f"{key}.points", "a table needs at least 3 points [angle, "
                            "displacement], the angle in degrees from the segment's start")
        th, ys = [], []
        for j, p in enumerate(pts):
            if not isinstance(p, list) or len(p) != 2:
                raise self.fail(f"{key}.points[{j}]", f"a point is [angle, displacement], "
                                f"not {p!r}")
            th.append(self.angle(p[0], f"{key}.points[{j}]"))
            ys.append(self.angle(p[1], f"{key}.points[{j}]") if angular
                      else self.length(p[1], f"{key}.points[{j}]"))
        if abs(th[0]) > 1e-12 or abs(th[-1] - beta) > 1e-9 * beta:
            raise self.fail(f"{key}.points", "the points run from angle 0 to the segment's "
                            f"angle {math.degrees(beta):g}°")
        if any(b <= a for a, b in zip(th, th[1:])):
            raise self.fail(f"{key}.points", "the points' angles must increase")
        return tuple(th), tuple(ys)
