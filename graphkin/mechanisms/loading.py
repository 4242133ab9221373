"""Loads, mass properties and gravity in a mechanism file (``docs/formats/mechanism.md``).

``units.force``, ``[[loads]]``, ``[inertia.N]`` and ``[gravity]`` are read here
into plain frozen values that :class:`~graphkin.mechanisms.model.Mechanism`
carries; :mod:`graphkin.forces` does the force analysis.  Inside graphkin a
force is in the file's force unit F, a length in its length unit L, so a mass
is stored in F·s²/L and a moment of inertia in F·L·s² (then ``m A`` is a force
in F and ``I α`` a torque in F·L, with no conversion in the analysis).

Quantities are read with pint at this edge only, and only as *a number and a
unit*: ``"120 lbf at 220 deg"``, ``"35 lbf*in cw"``, ``"0.012 kg*m^2"``.  No
arithmetic is evaluated (``"2*60 lbf"`` is refused).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 11.3 (units: lb·s²/in for masses in
the inch system), 12.3 (d'Alembert: inertia force and inertia torque).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from graphkin.errors import InputError

__all__ = ["Load", "Inertia", "force_fields", "parse_amount", "parse_answer_amount",
           "STANDARD_GRAVITY"]

STANDARD_GRAVITY = 9.80665
"""Standard gravity (m/s²): ``weight = mass × g0`` (a weight in lbf gives its mass)."""

TOP_KEYS = frozenset({"loads", "inertia", "gravity"})
"""The top-level keys of the forces format (``units.force`` lives in ``[units]``)."""

LOAD_KEYS = frozenset({"link", "point", "force", "torque"})
INERTIA_KEYS = frozenset({"center", "mass", "weight", "moment"})
GRAVITY_KEYS = frozenset({"acceleration"})

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
_AT = re.compile(r"^(.*?)\s+at\s+(.*)$", re.IGNORECASE)
_SENSE = re.compile(r"^(.*?)\s*\b(ccw|cw)\s*$", re.IGNORECASE)
_EXPONENT = re.compile(r"(\^|\*\*)\s*[-+]?\d+(\.\d+)?")


@dataclass(frozen=True, slots=True)
class Load:
    """An applied force or couple on a link (``[[loads]]``).

    Attributes
    ----------
    index : int
        Position among the file's ``[[loads]]``.
    link : str
        The loaded link.
    point : str or None
        A named point of ``link`` on the force's line of action (None for a couple).
    force : tuple of float or None
        ``(Fx, Fy)`` in the file's force unit.
    torque : float or None
        A couple, ccw positive, in force unit × length unit.
    """

    index: int
    link: str
    point: str | None = None
    force: tuple[float, float] | None = None
    torque: float | None = None

    @property
    def key(self) -> str:
        """The file key, for messages: ``loads[0]``."""
        return f"loads[{self.index}]"


@dataclass(frozen=True, slots=True)
class Inertia:
    """Mass properties of a link (``[inertia.N]``, Sec. 12.3).

    Attributes
    ----------
    link : str
    center : str
        The named point at the center of mass G.
    mass : float
        m, in force unit × s² / length unit (so ``m A_G`` is in the force unit).
    moment : float
        I_G, in force unit × length unit × s².
    """

    link: str
    center: str
    mass: float
    moment: float = 0.0


# ---------------------------------------------------------------------------
# quantities: a number and a unit, never an expression
# ---------------------------------------------------------------------------

#: The kinds of quantity a mechanism file's loads and masses take, in the user's words,
#: by pint's dimensionality (the message says "is not a force", not "[length] * [mass] ...").
_KINDS = {
    "[length] * [mass] / [time] ** 2": "a force",
    "[length] ** 2 * [mass] / [time] ** 2": "a torque",
    "[mass]": "a mass",
    "[length] ** 2 * [mass]": "a moment of inertia",
    "[mass] / [time] ** 2": "a spring rate (a force per length)",
    "[length]": "a length",
    "dimensionless": "an angle",
    "[length] / [time] ** 2": "an acceleration",
}


def parse_amount(value: Any, unit: str, default_unit: str) -> float:
    """A number (in ``default_unit``) or ``"<number> <unit>"`` converted to ``unit``.

    Parameters
    ----------
    value : float or str
    unit : str
        The pint unit wanted (``"lbf"``, ``"N*mm"``, ``"lbf*s**2/in"``).
    default_unit : str
        What a bare number is in.

    Raises
    ------
    ValueError
        Not a number with a unit, arithmetic, an unknown unit or one of the wrong kind.

    Examples
    --------
    >>> round(parse_amount("0.8 kN", "N", "N"), 9)
    800.0
    >>> round(parse_amount("1.5 kg", "N*s**2/mm", "N*s**2/mm"), 9)
    0.0015
    >>> parse_amount(35, "lbf*in", "lbf*in")
    35.0
    """
    from graphkin.units import registry

    if isinstance(value, bool):
        raise ValueError(f"expected a number or a string with a unit, not {value!r}")
    if isinstance(value, (int, float)):
        v = float(value)
        if not math.isfinite(v):
            raise ValueError(f"{value!r} is not a finite number")
        if default_unit == unit:
            return v
        text = f"{v!r} {default_unit}"
    elif isinstance(value, str):
        text = value
    else:
        raise ValueError(f"expected a number or a string with a unit, not {value!r}")
    m = _NUMBER.match(text)
    if not m:
        raise ValueError(f"cannot read {value!r}: expected a number and a unit, "
                         "such as \"120 lbf\"")
    number, unit_text = float(m.group(1)), m.group(2)
    if not math.isfinite(number):
        raise ValueError(f"{value!r} is not finite")
    if not unit_text:
        unit_text = default_unit
    elif re.search(r"\d", _EXPONENT.sub("", unit_text)) or re.search(r"[+]|\s-\s", unit_text):
        raise ValueError(f"cannot read {value!r}: write one number and a unit (no arithmetic)")
    if unit_text.strip() == unit:
        return number  # "120 lbf" in a lbf file: no conversion, no pint registry to load
    ureg = registry()
    try:
        u = ureg.parse_units(unit_text.replace("^", "**"))
        q = ureg.Quantity(number, u)
        out = float(q.to(unit).magnitude)
    except Exception as exc:  # pint raises several unrelated types
        want = ureg.parse_units(unit).dimensionality
        what = _KINDS.get(str(want), f"a quantity in units of {want}")
        like = default_unit.replace("**", "^").replace("(", "").replace(")", "")
        raise ValueError(f"{value!r} is not {what} (give a unit like {like})") from exc
    if not math.isfinite(out):
        raise ValueError(f"{value!r} is not finite")
    return out


def parse_answer_amount(value: Any, kind: str, mech: Any) -> tuple[float, str | None, str,
                                                                   float]:
    """A measured force or torque of an answers file: (value, sense, unit shown, unit size).

    ``kind`` is ``"force"`` (in the file's force unit) or ``"torque"`` (force ×
    length, ``cw`` negative).

    Examples
    --------
    >>> import graphkin
    >>> m = graphkin.examples.fourbar()      # an inch file; forces in N (the default)
    >>> v, sense, unit, factor = parse_answer_amount("183 lbf*in cw", "torque", m)
    >>> round(v, 2), sense, unit              # 183 lbf·in = 814.02 N·in, clockwise
    (-814.02, 'cw', 'lbf*in')
    """
    unit = mech.force_unit if kind == "force" else f"({mech.force_unit})*({mech.length_unit})"
    shown = mech.force_unit if kind == "force" else f"{mech.force_unit}*{mech.length_unit}"
    sense = None
    if isinstance(value, str):
        m = _SENSE.match(value.strip())
        if m:
            value, sense = m.group(1), m.group(2).lower()
    v = parse_amount(value, unit, unit)
    if sense == "cw":
        v = -v
    written = _NUMBER.match(value) if isinstance(value, str) else None
    if written and written.group(2):
        shown = written.group(2)
        return v, sense, shown, parse_amount(f"1 {shown}", unit, unit)
    return v, sense, shown, 1.0


def _angle(text: str) -> float:
    """Degrees from ``"220 deg"``, ``"220"``, ``"-1.2 rad"``, ``"220°"``."""
    t = text.strip().replace("°", " deg")
    return parse_amount(t, "deg", "deg")


def _direction(value: Any, unit: str, default_unit: str) -> tuple[float, float]:
    """``"<magnitude> <unit> at <angle> deg"`` or ``[x, y]`` as Cartesian components."""
    if isinstance(value, list):
        if len(value) != 2 or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                                      for v in value):
            raise ValueError(f"a vector is two numbers [x, y] or \"<magnitude> at <angle> "
                             f"deg\", not {value!r}")
        x, y = float(value[0]), float(value[1])
        if not (math.isfinite(x) and math.isfinite(y)):
            raise ValueError(f"components must be finite, not {value!r}")
        if default_unit != unit:
            k = parse_amount(1.0, unit, default_unit)
            x, y = x * k, y * k
        return (x, y)
    if not isinstance(value, str):
        raise ValueError(f"expected \"<magnitude> <unit> at <angle> deg\" or [x, y], "
                         f"not {value!r}")
    m = _AT.match(value.strip())
    if not m:
        raise ValueError(f"{value!r} has no direction: write \"<magnitude> <unit> at <angle> "
                         "deg\" (ccw from +x) or [x, y]")
    mag = parse_amount(m.group(1), unit, default_unit)
    try:
        ang = math.radians(_angle(m.group(2)))
    except ValueError:
        raise ValueError(f"cannot read the direction {m.group(2)!r} in {value!r} "
                         "(degrees ccw from +x)") from None
    return (mag * math.cos(ang), mag * math.sin(ang))


def _torque(value: Any, unit: str) -> float:
    """A couple: a number (ccw positive) or ``"35 lbf*in cw"``."""
    sense = 1.0
    if isinstance(value, str):
        m = _SENSE.match(value.strip())
        if m:
            value = m.group(1)
            sense = -1.0 if m.group(2).lower() == "cw" else 1.0
    return sense * parse_amount(value, unit, unit)


# ---------------------------------------------------------------------------
# the hook called by mechanisms/parse.py
# ---------------------------------------------------------------------------

def force_fields(data: Mapping[str, Any], links: Mapping[str, Any], length_unit: str,
                 fail: Callable[[str | None, str], InputError]) -> dict[str, Any]:
    """The Mechanism fields of the forces format (docs/formats/mechanism.md).

    Parameters
    ----------
    data : mapping
        The parsed TOML.
    links : mapping
        Link id -> :class:`~graphkin.mechanisms.model.Link` (already read).
    length_unit : str
        ``units.length``.
    fail : callable
        ``fail(key, reason)`` -> the :class:`InputError` to raise.

    Returns
    -------
    dict
        ``force_unit``, ``loads``, ``inertia``, ``gravity`` (empty when absent).
    """
    from graphkin.mechanisms.model import FRAME

    units = data.get("units", {})
    force_unit = units.get("force", "N") if isinstance(units, Mapping) else "N"
    if not isinstance(force_unit, str):
        raise fail("units.force", "the force unit must be a string such as \"N\" or \"lbf\"")
    try:
        if force_unit not in ("N", "kN", "MN", "mN", "lbf", "kip", "kgf"):  # known: no pint
            parse_amount(1.0, "N", force_unit)
    except ValueError:
        raise fail("units.force", f"{force_unit!r} is not a force unit (such as N, kN, "
                   "lbf)") from None
    out: dict[str, Any] = {"force_unit": force_unit}
    if not any(k in data for k in TOP_KEYS):
        for table in ("sliders", "slots"):
            raw = data.get(table, [])
            for i, item in enumerate(raw if isinstance(raw, list) else [raw]):
                if isinstance(item, Mapping) and ("friction" in item or "impending" in item):
                    raise fail(f"{table}[{i}].friction", "friction acts in a force analysis: "
                               "the file has no [[loads]] and no [inertia.N]")
        raw = data.get("rolling", [])
        for i, item in enumerate(raw if isinstance(raw, list) else [raw]):
            if isinstance(item, Mapping) and "pressure_angle" in item:
                raise fail(f"rolling[{i}].pressure_angle", "the pressure angle acts in a force "
                           "analysis: the file has no [[loads]] and no [inertia.N]")
        return out
    if "loads" not in data and "inertia" not in data:
        raise fail("gravity", "gravity acts on the links with [inertia.N] (mass and "
                   "center); none has one")
    L, F = f"({length_unit})", f"({force_unit})"
    torque_unit = f"{F}*{L}"

    def link_of(value: Any, key: str) -> str:
        if isinstance(value, bool) or not isinstance(value, (int, str)):
            raise fail(key, f"a link id must be a number or a name, not {value!r}")
        lid = str(value)
        if lid not in links:
            raise fail(key, f"no link {lid!r} (links: {', '.join(links)})")
        if lid == FRAME:
            raise fail(key, "a load on the frame holds nothing: load a moving link")
        return lid

    def point_of(lid: str, value: Any, key: str) -> str:
        if not isinstance(value, str):
            raise fail(key, f"a point is named by a string, not {value!r}")
        if value not in links[lid].points:
            names = ", ".join(links[lid].points) or "none"
            raise fail(key, f"link {lid} has no point {value!r} (its points: {names})")
        return value

    def unknown(table: Mapping[str, Any], allowed: frozenset[str], key: str) -> None:
        for k in table:
            if k not in allowed:
                raise fail(f"{key}.{k}", f"unknown key (valid: {', '.join(sorted(allowed))})")

    raw = data.get("loads", [])
    if isinstance(raw, Mapping):
        raw = [raw]
    if not isinstance(raw, list):
        raise fail("loads", "expected [[loads]] tables")
    loads: list[Load] = []
    for i, item in enumerate(raw):
        key = f"loads[{i}]"
        if not isinstance(item, Mapping):
            raise fail(key, f"expected a table, not {item!r}")
        unknown(item, LOAD_KEYS, key)
        lid = link_of(item.get("link"), f"{key}.link")
        has_f, has_t = "force" in item, "torque" in item
        if has_f == has_t:
            raise fail(key, "a load gives either force (with its point) or torque (a couple)")
        if has_f:
            if "point" not in item:
                raise fail(f"{key}.point", "a force needs a point of the link on its line "
                           "of action")
            name = point_of(lid, item["point"], f"{key}.point")
            try:
                fxy = _direction(item["force"], force_unit, force_unit)
            except ValueError as exc:
                raise fail(f"{key}.force", str(exc)) from None
            loads.append(Load(i, lid, name, force=fxy))
        else:
            if "point" in item:
                raise fail(f"{key}.point", "a couple has no point (give force for a force)")
            try:
                t = _torque(item["torque"], torque_unit)
            except ValueError as exc:
                raise fail(f"{key}.torque", str(exc)) from None
            loads.append(Load(i, lid, torque=t))
    out["loads"] = tuple(loads)

    inertia: dict[str, Inertia] = {}
    raw_in = data.get("inertia", {})
    if not isinstance(raw_in, Mapping):
        raise fail("inertia", "expected [inertia.N] tables, one per link")
    mass_unit, moment_unit = f"{F}*s**2/{L}", f"{F}*{L}*s**2"
    for lid_raw, item in raw_in.items():
        key = f"inertia.{lid_raw}"
        lid = link_of(lid_raw, key)
        if not isinstance(item, Mapping):
            raise fail(key, f"expected a table, not {item!r}")
        unknown(item, INERTIA_KEYS, key)
        if "center" not in item:
            raise fail(f"{key}.center", "name the point at the center of mass (center = \"G3\")")
        center = point_of(lid, item["center"], f"{key}.center")
        if ("mass" in item) == ("weight" in item):
            raise fail(key, "give either mass or weight")
        try:
            if "mass" in item:
                mass = parse_amount(item["mass"], mass_unit, mass_unit)
            else:
                w = parse_amount(item["weight"], force_unit, force_unit)
                mass = w / parse_amount(STANDARD_GRAVITY, f"{L}/s**2", "m/s**2")
        except ValueError as exc:
            which = "mass" if "mass" in item else "weight"
            raise fail(f"{key}.{which}", str(exc)) from None
        if not mass >= 0:
            which = "mass" if "mass" in item else "weight"
            raise fail(f"{key}.{which}", f"a {which} cannot be negative ({item[which]!r})")
        moment = 0.0
        if "moment" in item:
            try:
                moment = parse_amount(item["moment"], moment_unit, moment_unit)
            except ValueError as exc:
                raise fail(f"{key}.moment", str(exc)) from None
            if not moment >= 0:
                raise fail(f"{key}.moment", f"a moment of inertia cannot be negative "
                           f"({item['moment']!r})")
        inertia[lid] = Inertia(lid, center, mass, moment)
    out["inertia"] = inertia

    friction: dict[str, tuple[float, str | None]] = {}
    for table, i, item in _rough(data):
        key = f"{table}[{i}]"
        mu = item.get("friction")
        if isinstance(mu, bool) or not isinstance(mu, (int, float)) or not \
                (math.isfinite(float(mu)) and float(mu) >= 0):
            raise fail(f"{key}.friction", "the coefficient of friction is a number >= 0, "
                       f"not {mu!r}")
        imp = item.get("impending")
        if imp is not None and imp not in ("ahead", "behind"):
            raise fail(f"{key}.impending", "the impending motion of the slider (or of the pin "
                       "in the slot) along its line is \"ahead\" (toward the line's second "
                       f"point) or \"behind\", not {imp!r}")
        friction[key] = (float(mu), imp)
    if friction:
        out["friction"] = friction
    pressure: dict[str, float] = {}
    raw_r = data.get("rolling", [])
    for i, item in enumerate(raw_r if isinstance(raw_r, list) else [raw_r]):
        if not isinstance(item, Mapping) or "pressure_angle" not in item:
            continue
        phi = item["pressure_angle"]
        if isinstance(phi, bool) or not isinstance(phi, (int, float)) or not \
                (math.isfinite(float(phi)) and 0 <= float(phi) < 45):
            raise fail(f"rolling[{i}].pressure_angle", "the pressure angle of the gear teeth "
                       f"is a number of degrees, 0 <= φ < 45 (20 is usual), not {phi!r}")
        pressure[f"rolling[{i}]"] = math.radians(float(phi))
    if pressure:
        out["pressure"] = pressure

    if "gravity" in data:
        g = data["gravity"]
        if not isinstance(g, Mapping):
            raise fail("gravity", "expected a [gravity] table with acceleration = "
                       "\"9.80665 m/s^2 at -90 deg\"")
        unknown(g, GRAVITY_KEYS, "gravity")
        if "acceleration" not in g:
            raise fail("gravity.acceleration", "give the acceleration of gravity, e.g. "
                       "\"9.80665 m/s^2 at -90 deg\"")
        try:
            out["gravity"] = _direction(g["acceleration"], f"{L}/s**2", f"{L}/s**2")
        except ValueError as exc:
            raise fail("gravity.acceleration", str(exc)) from None
        if not inertia:
            raise fail("gravity", "gravity acts on the links with [inertia.N] (mass and "
                       "center); none has one")
    return out


def _rough(data: Mapping[str, Any]) -> list[tuple[str, int, Mapping[str, Any]]]:
    """The ``[[sliders]]`` and ``[[slots]]`` entries that give friction (Sec. 11.10)."""
    out = []
    for table in ("sliders", "slots"):
        raw = data.get(table, [])
        if isinstance(raw, Mapping):
            raw = [raw]
        for i, item in enumerate(raw if isinstance(raw, list) else []):
            if isinstance(item, Mapping) and ("friction" in item or "impending" in item):
                out.append((table, i, item))
    return out
