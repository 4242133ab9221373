"""The keys every input file may hold, in one place, and the check that nothing else is there.

A misspelt key is worse than a syntax error: ``alfa = 50`` in ``[drive]``
would silently leave α = 0.  So every table of every file kind is checked
against the schema below before anything is read, and an unknown key ends
with one line naming the file, the key and the nearest valid key.

To add a key (a new extension, a new file kind), add it here, to the table
it belongs in; the parser that reads it is then the only other place to
touch.  Schemas are nested dicts:

* a key mapped to ``None`` holds a value (a number, string, list...);
* a key mapped to a dict holds a table with those keys; the same dict
  applies to every table of an array of tables (``[[sliders]]``) and to a
  key written as a single table or as an array (``[drive]`` or ``[[drive]]``);
* the key ``"*"`` stands for any name the user chooses (link ids, point
  names);
* a value that may be either a string or a table (``units = "mm"`` or
  ``units = { length = "mm" }``) is checked only when it is a table.

Examples
--------
>>> check_keys({"drive": {"link": 2, "alfa": 0}}, MECHANISM, "mech.toml")
Traceback (most recent call last):
    ...
graphkin.errors.InputError: unknown key 'alfa' (did you mean 'alpha'?)
>>> read_units("in", "units", "mech.toml")
{'length': 'in'}
>>> read_units({"length": "mm", "force": "N"}, "units", "mech.toml")
{'length': 'mm', 'force': 'N'}
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Mapping
from typing import Any

from graphkin.errors import InputError

__all__ = ["Schema", "UNITS", "MECHANISM", "VECTOR", "GEARS", "TRAIN", "GALLERY", "CAM",
           "SYNTHESIS", "check_keys", "read_units", "nearest", "design_file"]

Schema = Mapping[str, Any]

UNITS: Schema = {
    "length": None,   # any length unit pint knows; default mm
    "force": None,    # forces (docs/formats/mechanism.md#forces): a force unit; default N
}
"""``units = { ... }``: the same in every file kind (``units = "in"`` means the length)."""

_CIRCLE: Schema = {"center": None, "radius": None}

GALLERY: Schema = {
    "figure": None, "examples": None, "section": None, "diagrams": None, "note": None,
    "link": None,
    "book": {"quantity": None, "path": None, "value": None, "unit": None, "source": None,
             "why": None, "tolerance": None},
}
"""``[gallery]``: what a gallery file says of the textbook figure it reproduces
(:mod:`graphkin.render.gallery`)."""

MECHANISM: Schema = {
    "title": None,
    "units": UNITS,
    "links": {"*": {"*": None}},          # [links.<id>] <point> = [x, y]
    "sliders": {"link": None, "on": None, "point": None, "line": None,
                "friction": None, "impending": None},   # Coulomb friction (forces, Sec. 11.10)
    "slots": {"link": None, "on": None, "point": None, "line": None, "circle": _CIRCLE,
              "friction": None, "impending": None},     # Coulomb friction (forces, Ex 11.5)
    "rolling": {"link": None, "on": None, "circle": _CIRCLE, "line": None, "side": None,
                "angle": None, "on_circle": _CIRCLE, "contact": None,
                "pressure_angle": None},   # gear teeth (forces, Sec. 11.11)
    "drive": {"link": None, "angle": None, "position": None, "omega": None, "alpha": None,
              "velocity": None, "acceleration": None,
              # a joint angle between two moving links (Problems 5.7-5.11)
              "relative_to": None,
              # a point's coordinates in the frame (Problem 5.13)
              "point": None, "x": None, "y": None, "vx": None, "vy": None, "ax": None,
              "ay": None,
              # an input coupled to the first by a law: θ5 = 3 θ2 + 30° (a swept parameter)
              "follows": {"link": None, "ratio": None, "offset": None, "table": None}},
    "rates": {"link": None, "omega": None, "alpha": None, "velocity": None,
              "acceleration": None},
    "assembly": {"*": None},              # <point> = [x, y]
    # forces (docs/formats/mechanism.md#forces, Ch. 11-12)
    "loads": {"link": None, "point": None, "force": None, "torque": None},
    "inertia": {"*": {"center": None, "mass": None, "weight": None, "moment": None}},
    "gravity": {"acceleration": None},
    # gallery files (graphkin.render.gallery)
    "gallery": GALLERY,
    # drawing only (docs/formats/mechanism.md#bodies): a cam's disc, a follower's face
    "bodies": {"link": None, "circle": _CIRCLE, "face": None, "outline": None},
    # a disk cam and its follower (docs/formats/mechanism.md#cams, Ch. 6)
    "cams": {"link": None, "follower": None, "file": None, "center": None, "pivot": None,
             "axis": None, "guide_friction": None, "impending": None},
}
"""Every key of a mechanism file (the format reference: ``docs/formats/mechanism.md``)."""

SYNTHESIS: Schema = {
    "title": None,
    "units": UNITS,
    "body": {"points": None},
    "postures": None,     # [[postures]]: point and angle, or the body's two points by name
    "pivots": {"circle_points": None, "center_points": None},
    "function": {"expression": None, "range": None, "points": None, "input": None,
                 "output": None, "ground": None},
    "path": {"points": None, "crank": None, "coupler": None, "rocker_pin": None},
    "cognates": {"O_A": None, "A": None, "B": None, "O_B": None, "P": None, "write": None},
    "dwell": {"O_A": None, "A": None, "B": None, "O_B": None, "C": None, "span": None,
              "slider": None},   # slider: a straight stretch and a slotted link (Fig. 9.44)
    "overlay": {"points": None, "closed": None},   # the overlay method (Sec. 9.8)
    "coupler_curve": {"points": None, "O4": None, "O2": None, "R": None, "r": None},  # 9.9
    # a crank-rocker from the rocker's two limit postures and Q (Sec. 9.3, Fig. 9.3)
    "crank_rocker": {"O4": None, "B1": None, "swing": None, "Q": None, "x_angle": None},
    # gallery files (graphkin.render.gallery_synthesis)
    "gallery": GALLERY,
}
"""Every key of a synthesis file (``graphkin synthesize``, ``docs/formats/synthesis.md``);
the keys of each ``[[postures]]`` entry depend on ``body.points`` and are checked by
:mod:`graphkin.synthesis.spec`."""

VECTOR: Schema = {
    "title": None,
    "units": {"length": None},
    "branch": None,
    **{name: {"magnitude": None, "angle": None} for name in ("A", "B", "C")},
    "gallery": GALLERY,
}
"""Every key of a vector file (``graphkin vector``, ``docs/formats/vector.md``)."""

_GEAR_SIZE: Schema = {"module": None, "diametral_pitch": None, "pressure_angle": None,
                      "system": None}

GEARS: Schema = {
    "title": None,
    "units": {"length": None},
    **_GEAR_SIZE,
    "center_distance": None,
    # [gears.<name>]: the first is the driver (link 2), the second the driven gear (link 3)
    "gears": {"*": {"teeth": None, "link": None, "addendum": None, "dedendum": None,
                    "offset": None, "kind": None, **_GEAR_SIZE}},   # kind: external/internal
    "gallery": GALLERY,
}
"""Every key of a gear file (``graphkin gears``, ``docs/formats/gears.md``)."""

TRAIN: Schema = {
    "title": None,
    "units": {"length": None},     # of [radii] and the module (default mm)
    "module": None,                # or diametral_pitch: with [teeth], R = N m / 2
    "diametral_pitch": None,
    "teeth": {"*": None},          # <gear> = N
    "radii": {"*": None},          # <gear> = R (instead of teeth: only ratios count)
    "mesh": {"gears": None, "contact": None, "arm": None},
    "joined": {"members": None},
    "speeds": {"*": None},         # <member> = "100 rev/min ccw"
    "turns": {"*": None},          # <member> = "1 rev" (angular displacements)
    "gallery": GALLERY,
}
"""Every key of a gear-train file (``graphkin gears``, ``docs/formats/gears.md#gear-trains``)."""

CAM: Schema = {
    "title": None,
    "units": {"length": None},
    "cam": {"prime": None, "rotation": None, "speed": None},
    "follower": {"kind": None, "offset": None, "roller": None, "face": None, "pivot": None,
                 "arm": None, "face_offset": None, "rise": None},
    "segment": {"motion": None, "lift": None, "angle": None, "rest": None, "name": None,
                "points": None},
    "limits": {"pressure_angle": None, "radius": None},
    "dynamics": {"spring": None, "preload": None, "mass": None},   # jump speed (Ex 6.8)
    "gallery": GALLERY,
}
"""Every key of a cam file (``graphkin cam``, ``docs/formats/cam.md``)."""

#: What to say besides the nearest key, for keys people expect to exist.
HINTS: Mapping[str, str] = {
    "units.angle": "angles in a file are always degrees; write a unit on a value "
                   "instead, e.g. angle = \"2.1 rad\"",
    "units.time": "time is always seconds; write a rate with its unit instead, "
                  "e.g. omega = \"900 rev/min\"",
    "units.omega": "write a rate with its unit instead, e.g. omega = \"900 rev/min\"",
    "units.velocity": "velocities are in units.length per second; write a unit on a value "
                      "instead, e.g. velocity = \"10 ft/s\"",
}


def nearest(key: str, valid: list[str]) -> str | None:
    """The valid key nearest to ``key`` (by :func:`difflib.get_close_matches`), or None.

    Case is ignored: ``Omega`` finds ``omega``.

    Examples
    --------
    >>> nearest("titel", ["title", "units", "links"])
    'title'
    >>> nearest("omgea", ["link", "angle", "omega", "alpha"])
    'omega'
    >>> nearest("moment_of_inertia", ["center", "mass", "moment"])
    'moment'
    >>> nearest("zzz", ["link", "angle"]) is None
    True
    """
    lower = {v.lower(): v for v in valid}
    close = difflib.get_close_matches(key.lower(), list(lower), n=1, cutoff=0.6)
    if close:
        return lower[close[0]]
    # a valid key with more written around it: moment_of_inertia, omega_2, alpha2
    inside = [v for v in lower if len(v) > 2 and v in key.lower()]
    return lower[max(inside, key=len)] if inside else None


def check_keys(data: Any, schema: Schema, source: str, path: str = "") -> None:
    """Raise :class:`~graphkin.errors.InputError` at the first key ``schema`` does not know.

    Parameters
    ----------
    data : Mapping or list
        Parsed TOML (a table, or an array of tables).
    schema : Mapping
        What may be there (see the module's docstring).
    source : str
        The file name, for the message.
    path : str
        The dotted key of ``data`` in the file ("" at the top).

    Raises
    ------
    InputError
        Naming the file, the dotted key, and the nearest valid key (or every
        valid key when none is near).
    """
    if isinstance(data, list):
        for i, item in enumerate(data):
            check_keys(item, schema, source, f"{path}[{i}]")
        return
    if not isinstance(data, Mapping):
        return
    for key, value in data.items():
        key = str(key)
        if key in schema:
            sub = schema[key]
        elif "*" in schema:
            sub = schema["*"]
        else:
            raise _unknown(key, schema, source, path)
        if isinstance(sub, Mapping):
            check_keys(value, sub, source, f"{path}.{key}" if path else key)


def _unknown(key: str, schema: Schema, source: str, path: str) -> InputError:
    valid = [k for k in schema if k != "*"]
    guess = nearest(key, valid)
    hint = HINTS.get(f"{_table(path)}.{key}")
    if guess is not None:
        message = f"unknown key {key!r} (did you mean {guess!r}?)"
    else:
        message = f"unknown key {key!r} (valid keys: {', '.join(valid)})"
    if hint:
        message += f"; {hint}"
    dotted = f"{path}.{key}" if path else key
    return InputError(message, key=dotted, file=source, suggestion=guess)


def _table(path: str) -> str:
    """``sliders[0].line`` -> ``sliders.line`` (the schema's name of a table)."""
    return re.sub(r"\[\d+\]", "", path)


def read_units(value: Any, key: str, source: str, schema: Schema = UNITS) -> dict[str, str]:
    """The ``units`` of a file, in either spelling, as ``{"length": "in", ...}``.

    ``units = "in"`` is short for ``units = { length = "in" }``; every file
    kind accepts both.  Values are only checked to be strings here; the
    parser that uses a unit checks that pint knows it.

    Raises
    ------
    InputError
        Neither a string nor a table, a key not in ``schema``, or a value
        that is not a non-empty string.
    """
    if isinstance(value, str):
        value = {"length": value}
    if not isinstance(value, Mapping):
        raise InputError(f"expected units = \"mm\" or units = {{ length = \"mm\" }}, "
                         f"not {value!r}", key=key, file=source)
    check_keys(value, schema, source, key)
    out = {}
    for k, v in value.items():
        if not isinstance(v, str) or not v.strip():
            raise InputError(f"a unit is a string such as \"mm\", not {v!r}",
                             key=f"{key}.{k}", file=source)
        out[str(k)] = v.strip()
    return out


#: The top-level keys that make a file one of the design chapters' files, not a
#: mechanism file (docs/formats/): what it is, the command that reads it.
_DESIGN_KEYS: tuple[tuple[tuple[str, ...], str, str], ...] = (
    (("cam", "segment"), "a cam file (docs/formats/cam.md)", "cam"),
    (("gears", "mesh"), "a gear file (docs/formats/gears.md)", "gears"),
    (("postures", "function", "path", "cognates", "dwell", "overlay", "coupler_curve",
      "crank_rocker"), "a synthesis file (docs/formats/synthesis.md)", "synthesize"),
    # (case 1 may leave out the unknown vector's table: [A] and [B] only)
    (("C", "A", "B"), "a vector file (docs/formats/vector.md)", "vector"),
)


def design_file(data: Mapping[str, Any]) -> tuple[str, str, str] | None:
    """What a file without links is, when its keys say a design chapter's file.

    Returns ``(what, command, key)``, or None for anything else (a mechanism
    file, or a file too broken to tell: the mechanism parser names its keys).

    >>> design_file({"title": "Ex 6.1", "cam": {}, "segment": []})[1]
    'cam'
    >>> design_file({"links": {}, "cams": []}) is None
    True
    """
    if "links" in data:
        return None
    for keys, what, verb in _DESIGN_KEYS:
        found = [k for k in keys if k in data]
        if found:
            return what, verb, found[0]
    return None
