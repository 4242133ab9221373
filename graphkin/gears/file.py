"""Read and validate a gear file (``docs/formats/gears.md``).

A gear file describes one pair of spur gears in mesh::

    title = "Example 7.1"
    units = "in"
    diametral_pitch = 10        # teeth per inch (or module = "2.5 mm")
    pressure_angle = 20         # degrees
    system = "full depth"       # or "stub" (Table 7.2)

    [gears.pinion]              # the first is the driver, link 2
    teeth = 20

    [gears.gear]                # the driven gear, link 3
    teeth = 50

Every problem is one :class:`~graphkin.errors.InputError` naming the file,
the dotted key and the reason (exit status 2 from the CLI); an unknown key
is refused with the nearest valid one (:mod:`graphkin.keys`).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.1, 7.4 (Tables 7.1-7.2), 7.9, 7.11.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from graphkin.errors import InputError
from graphkin.files import parse_toml, read_text
from graphkin.gears.mesh import GearPair
from graphkin.gears.tooth import ADDENDUM, DEDENDUM, Gear, GearKind, ToothSystem
from graphkin.keys import GEARS, check_keys, read_units
from graphkin.units import length_factor, parse_quantity

__all__ = ["load", "loads", "from_dict", "is_gear_file", "gear_kind", "MAX_TEETH",
           "tooth_size"]

#: A gear file's or a gear-train file's table headers, looked for before any TOML is parsed.
_KIND = re.compile(r"^\s*(\[\s*gears\s*\.|\[\[\s*mesh\s*\]\])", re.MULTILINE)

#: A diametral pitch with its unit: "10 teeth/in", "10/in", "10 per in".
_PITCH = re.compile(r"\s*([0-9]+(?:\.[0-9]*)?(?:[eE][+-]?[0-9]+)?)\s*(?:teeth\s*)?(?:/|per\s)"
                    r"\s*([A-Za-z]{1,16})\s*$")

#: The smallest module accepted, in the file's unit: the tolerances' absolute floor is 1e-12.
MIN_MODULE = 1e-6

#: The most teeth a gear may have (a drawing of more is a grey disc).
MAX_TEETH = 10_000


def is_gear_file(data: Mapping[str, Any]) -> bool:
    """Whether parsed TOML is a gear file (it has a ``[gears]`` table and no ``[links]``)."""
    return isinstance(data.get("gears"), Mapping) and "links" not in data


def gear_kind(path: str | Path) -> tuple[str, dict[str, Any]] | None:
    """``("pair", data)`` for a gear file, ``("train", data)`` for a gear-train file, else None.

    The text is looked at first and parsed only when it has a ``[gears.<name>]``
    or ``[[mesh]]`` header, so that a mechanism file is not parsed twice.
    """
    text = read_text(path)
    if not _KIND.search(text):
        return None
    data = parse_toml(text, str(path))
    if is_gear_file(data):
        return "pair", data
    if "mesh" in data and "links" not in data:
        return "train", data
    return None


def load(path: str | Path) -> GearPair:
    """Read a gear file.

    Raises
    ------
    InputError
        One line naming the file, the key and the reason.
    """
    source = str(path)
    return loads(read_text(path), source)


def loads(text: str, source: str = "<string>") -> GearPair:
    """Read a gear file's text."""
    return from_dict(parse_toml(text, source), source)


def from_dict(data: Mapping[str, Any], source: str = "<dict>") -> GearPair:
    """Build the :class:`GearPair` of parsed TOML."""
    return _Reader(source).read(data)


def tooth_size(data: Mapping[str, Any], source: str) -> tuple[str, float | None]:
    """The length unit and the module a file's top level gives; None: no module.

    ``units``, ``module`` or ``diametral_pitch`` (m = 1/P, Sec. 7.1), read as a
    gear file reads them (a train file's ``[teeth]`` take their size from them).

    >>> tooth_size({"units": "in", "diametral_pitch": 10}, "t.toml")
    ('in', 0.1)
    """
    r = _Reader(source)
    r.unit = read_units(data.get("units", "mm"), "units", source,
                        schema={"length": None}).get("length", "mm")
    try:
        length_factor(r.unit)
    except ValueError as exc:
        raise r.error(str(exc), "units.length") from None
    if "module" in data and "diametral_pitch" in data:
        raise r.error("give the module or the diametral pitch, not both", "diametral_pitch")
    if "module" in data:
        module = r.length(data["module"], "module", positive=True)
    elif "diametral_pitch" in data:
        module = r.module(data["diametral_pitch"], "diametral_pitch")
    else:
        return r.unit, None
    if module < MIN_MODULE:
        raise r.error(f"a module too small (below {MIN_MODULE:g} {r.unit})",
                      "module" if "module" in data else "diametral_pitch")
    return r.unit, module


class _Reader:
    def __init__(self, source: str) -> None:
        self.source = source
        self.unit = "mm"

    def error(self, message: str, key: str) -> InputError:
        return InputError(message, key=key, file=self.source)

    def read(self, data: Mapping[str, Any]) -> GearPair:
        check_keys(data, GEARS, self.source)
        units = read_units(data.get("units", "mm"), "units", self.source,
                           schema={"length": None})
        self.unit = units.get("length", "mm")
        try:
            length_factor(self.unit)
        except ValueError as exc:
            raise self.error(str(exc), "units.length") from None
        title = data.get("title", "")
        if not isinstance(title, str):
            raise self.error(f"the title is text, not {title!r}", "title")
        gears = data.get("gears")
        if not isinstance(gears, Mapping) or not all(isinstance(v, Mapping)
                                                     for v in gears.values()):
            raise self.error("expected tables [gears.<name>] (one for each gear of the pair)",
                             "gears")
        if len(gears) != 2:
            raise self.error(f"a pair in mesh is two gears, not {len(gears)}: write "
                             "[gears.pinion] (the driver) and [gears.gear]", "gears")
        (n2, t2), (n3, t3) = gears.items()
        g2 = self.gear(str(n2), t2, data, 2)
        g3 = self.gear(str(n3), t3, data, 3)
        if g2.link == g3.link:
            raise self.error(f"both gears are link {g2.link}", f"gears.{n3}.link")
        center = None
        if "center_distance" in data and g3.rack:
            raise self.error("a pinion and a rack have no center distance: the rack's pitch "
                             "line is tangent to the pinion's pitch circle", "center_distance")
        if "center_distance" in data:
            center = self.length(data["center_distance"], "center_distance", positive=True)
        return GearPair(g2, g3, center, units=self.unit, title=title, source=self.source)

    def gear(self, name: str, table: Mapping[str, Any], top: Mapping[str, Any],
             link: int) -> Gear:
        key = f"gears.{name}"
        kind = self.kind(table.get("kind", "external"), f"{key}.kind")
        if kind == GearKind.RACK:
            if link == 2:
                raise self.error("the driver (the first gear) is the pinion: only the second "
                                 "may be a rack", f"{key}.kind")
            if "teeth" in table:
                raise self.error("a rack has no number of teeth (its pitch radius is "
                                 "infinite, Sec. 7.5): leave teeth out", f"{key}.teeth")
            if "offset" in table:
                raise self.error("a rack cut with an offset is not modelled: leave offset out",
                                 f"{key}.offset")
            teeth = 0
        else:
            teeth = self.whole(table.get("teeth"), f"{key}.teeth", low=3)
        if "link" in table:
            link = self.whole(table["link"], f"{key}.link", low=2)

        def pick(k: str) -> tuple[Any, str] | None:
            if k in table:
                return table[k], f"{key}.{k}"
            if k in top:
                return top[k], k
            return None

        level = table if ("module" in table or "diametral_pitch" in table) else top
        where = f"{key}." if level is table else ""
        if "module" in level and "diametral_pitch" in level:
            raise self.error("give the module or the diametral pitch, not both",
                             f"{where}diametral_pitch")
        if "module" in level:
            module = self.length(level["module"], f"{where}module", positive=True)
        elif "diametral_pitch" in level:
            module = self.module(level["diametral_pitch"], f"{where}diametral_pitch")
        else:
            raise self.error("the tooth size is missing: module = ... (length per tooth) or "
                             "diametral_pitch = ... (teeth per length unit)", "module")
        angle = pick("pressure_angle")
        if angle is None:
            raise self.error("the pressure angle is missing (e.g. pressure_angle = 20, in "
                             "degrees)", "pressure_angle")
        phi = self.angle(*angle)
        system = self.system(pick("system"))
        addendum = (self.length(table["addendum"], f"{key}.addendum", positive=True)
                    if "addendum" in table else ADDENDUM[system] * module)
        dedendum = (self.length(table["dedendum"], f"{key}.dedendum", positive=True)
                    if "dedendum" in table else DEDENDUM[system] * module)
        offset = self.length(table["offset"], f"{key}.offset") if "offset" in table else 0.0
        if kind == GearKind.INTERNAL and offset != 0.0:
            raise self.error("teeth cut with an offset are not modelled inside an internal gear",
                             f"{key}.offset")
        if module < MIN_MODULE:
            raise self.error(f"a module too small (below {MIN_MODULE:g} {self.unit}): write the "
                             "sizes in a smaller unit",
                             f"{where}module" if "module" in level else f"{where}diametral_pitch")
        if kind != GearKind.RACK and abs(offset) >= teeth * module / 2:
            raise self.error(f"an offset of {offset:g} {self.unit} is larger than the gear",
                             f"{key}.offset")
        try:
            return Gear(name, link, teeth, module, phi, addendum, dedendum, offset,
                        clearance=(DEDENDUM[system] - ADDENDUM[system]) * module, kind=kind)
        except InputError as exc:
            raise self.error(exc.message, exc.key or key) from None

    def kind(self, value: Any, key: str) -> GearKind:
        """``external`` (the default), ``internal`` (an annular gear, Fig. 7.11) or ``rack``."""
        text = str(value).strip().lower() if isinstance(value, str) else repr(value)
        try:
            return GearKind(text)
        except ValueError:
            raise self.error(f"kind is \"external\", \"internal\" or \"rack\", not {value!r}",
                             key) from None

    def whole(self, value: Any, key: str, low: int) -> int:
        if value is None:
            raise self.error("missing: the number of teeth, a whole number", key)
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.error(f"expected a whole number, not {value!r}", key)
        if isinstance(value, float):
            if not value.is_integer():
                raise self.error(f"expected a whole number, not {value!r}", key)
            value = int(value)
        if not low <= value <= MAX_TEETH:
            raise self.error(f"expected a whole number from {low} to {MAX_TEETH}, not {value}",
                             key)
        return int(value)

    def length(self, value: Any, key: str, *, positive: bool = False) -> float:
        try:
            v, sense = parse_quantity(value, "length", self.unit)
        except ValueError as exc:
            raise self.error(str(exc), key) from None
        if sense is not None:
            raise self.error(f"a length has no sense (cw/ccw): {value!r}", key)
        if positive and not v > 0:
            raise self.error(f"expected a positive length, not {value!r}", key)
        if abs(v) > 1e12:
            raise self.error(f"a length too large: {value!r}", key)
        return v

    def angle(self, value: Any, key: str) -> float:
        try:
            deg, sense = parse_quantity(value, "angle", self.unit)
        except ValueError as exc:
            raise self.error(str(exc), key) from None
        if sense is not None or not 0.0 < deg < 90.0:
            raise self.error(f"the pressure angle must lie between 0° and 90° (exclusive), "
                             f"not {value!r}", key)
        return math.radians(deg)

    def system(self, given: tuple[Any, str] | None) -> ToothSystem:
        if given is None:
            return ToothSystem.FULL_DEPTH
        value, key = given
        try:
            return ToothSystem(str(value).strip().lower().replace("-", " ").replace("_", " "))
        except ValueError:
            raise self.error(f"unknown tooth system {value!r} (valid: "
                             f"{', '.join(repr(str(s)) for s in ToothSystem)})", key) from None

    def module(self, value: Any, k: str) -> float:
        """The module of a diametral pitch (``m = 1/P``, Sec. 7.1)."""
        if isinstance(value, bool):
            raise self.error(f"expected a number of teeth per length, not {value!r}", k)
        if isinstance(value, (int, float)):
            p = float(value)
            if not (math.isfinite(p) and p > 0):
                raise self.error(f"expected a positive diametral pitch, not {value!r}", k)
            return 1.0 / p
        if not isinstance(value, str):
            raise self.error(f"expected a number of teeth per length, not {value!r}", k)
        m = _PITCH.match(value)
        try:
            if m is None:
                raise ValueError(value)
            p = (float(m.group(1)) * length_factor(self.unit)
                 / length_factor(m.group(2).strip()))
        except ValueError:
            raise self.error(f"cannot read {value!r} as teeth per length (e.g. "
                             "\"10 teeth/in\")", k) from None
        if not (math.isfinite(p) and p > 0):
            raise self.error(f"expected a positive diametral pitch, not {value!r}", k)
        return 1.0 / p
