"""Units at the edges: pint turns the file's strings into graphkin's floats.

Inside graphkin, lengths are in the mechanism file's length unit, angles in
radians and times in seconds.  Rates in files may be plain numbers (rad/s,
rad/s², length/s, length/s²) or strings with a unit and a sense:
``"900 rev/min"``, ``"20 rad/s^2 cw"``, ``"-10 m/s"`` (``cw`` means negative).
"""

from __future__ import annotations

import math
import re
from functools import lru_cache
from typing import Any

__all__ = ["registry", "length_factor", "parse_rate", "parse_quantity", "quantity", "split_number",
           "check_unit", "RateKind"]

RateKind = str  # "omega", "alpha", "velocity", "acceleration", "length", "angle"

_SENSE = re.compile(r"\s*\b(ccw|cw)\s*$", re.IGNORECASE)

# A number as written in a file: read by Python's float(), never evaluated.
_NUMBER = re.compile(r"\s*([+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)\s*(.*)$", re.DOTALL)
# One unit name with an optional small exponent (^2, **-1, ², ³, ⁻¹), as pint spells them.
_UNIT_WORD = (r"(?:[A-Za-z_°µμΩ][A-Za-z_0-9°µμΩ]*|\))"
              r"(?:\s*(?:\^|\*\*)\s*[+-]?\d{1,2}(?:\.\d{1,3})?|[⁻¹²³]+)?")
_UNIT = re.compile(rf"\s*\(*\s*{_UNIT_WORD}(?:\s*(?:\*|/|·|\s)\s*\(*\s*{_UNIT_WORD}|\s*\))*\s*$")
#: Longest unit text accepted (a unit is a few words; anything longer is not a unit).
MAX_UNIT_CHARS = 64

# what each kind of rate is measured in, inside graphkin ("L" is the file's length unit)
_BASE = {
    "omega": "rad/s",
    "alpha": "rad/s**2",
    "velocity": "L/s",
    "acceleration": "L/s**2",
    "length": "L",
    "angle": "deg",
}

#: What each kind of rate is, in the user's words, for the messages.
_WHAT = {
    "omega": "an angular velocity",
    "alpha": "an angular acceleration",
    "velocity": "a velocity",
    "acceleration": "an acceleration",
    "length": "a length",
    "angle": "an angle",
}


@lru_cache(maxsize=1)
def registry() -> Any:
    """The shared pint unit registry (created on first use)."""
    import pint

    ureg: Any = pint.UnitRegistry()
    # the textbook writes revolutions as "rev" (900 rev/min)
    ureg.define("rev = revolution")
    return ureg


def check_unit(unit: str) -> str:
    """Accept a unit expression only if pint can read it without evaluating arithmetic.

    Unit names joined by ``*``, ``/``, ``·`` or spaces, each with an optional
    exponent of at most two digits (``s^2``, ``s**-1``, ``s²``), and
    parentheses.  Anything else (``9**9**9``, function calls, long text) is
    refused before pint sees it, so no unit string can make pint compute for
    ever.

    Raises
    ------
    ValueError
        The text is not a unit expression.

    Examples
    --------
    >>> check_unit("rad/s^2")
    'rad/s^2'
    >>> check_unit("9**9**9 rad")
    Traceback (most recent call last):
    ...
    ValueError: '9**9**9 rad' is not a unit
    """
    if (not isinstance(unit, str) or len(unit) > MAX_UNIT_CHARS or not _UNIT.match(unit)
            or unit.count("(") != unit.count(")")):
        raise ValueError(f"{unit!r} is not a unit")
    return unit


def split_number(text: str) -> tuple[float, str]:
    """Split ``"900 rev/min"`` into the number, read by ``float``, and the unit text.

    The number is never evaluated as an expression; the unit is checked by
    :func:`check_unit` (an empty unit is allowed).

    Raises
    ------
    ValueError
        No number at the start, a number too large for a float, or a bad unit.

    Examples
    --------
    >>> split_number("-1.5e3 mm/s")
    (-1500.0, 'mm/s')
    >>> split_number("36")
    (36.0, '')
    """
    m = _NUMBER.match(text)
    if not m:
        raise ValueError(f"cannot read {text!r} as a number with a unit")
    try:
        value = float(m.group(1))
    except (OverflowError, ValueError):
        raise ValueError(f"cannot read {text!r} as a number with a unit") from None
    if not math.isfinite(value):
        raise ValueError(f"{text!r} is not a finite number")
    unit = m.group(2).strip()
    if unit:
        try:
            check_unit(unit)
        except ValueError:
            raise ValueError(f"cannot read {text!r} as a number with a unit") from None
    return value, unit


def quantity(text: str) -> Any:
    """A pint Quantity from ``"1 in"``: the number by :func:`split_number`, pint the unit only.

    Raises
    ------
    ValueError
        Unreadable text or an unknown unit.
    """
    value, unit = split_number(text)
    ureg = registry()
    try:
        return ureg.Quantity(value, unit.replace("^", "**") or "dimensionless")
    except Exception as exc:  # pint raises several unrelated types
        raise ValueError(f"unknown unit in {text!r}") from exc


def _as_float(value: int | float) -> float:
    """A file's number as a float; integers too large for a float raise ValueError."""
    try:
        v = float(value)
    except OverflowError:
        raise ValueError("a number too large (beyond 1e308)") from None
    if not math.isfinite(v):
        raise ValueError(f"{value!r} is not a finite number")
    return v


#: Metres per unit of the commonest length units, as pint gives them (bit for bit; a test
#: checks): a file in one of these does not wait half a second for pint's registry to load.
_COMMON_LENGTHS = {"mm": 0.001, "cm": 0.01, "m": 1.0, "km": 1000.0, "in": 0.0254,
                   "inch": 0.0254, "ft": 0.30479999999999996, "yd": 0.9144}


def length_factor(unit: str) -> float:
    """How many metres one ``unit`` is; raises ``ValueError`` if it is not a length."""
    if unit in _COMMON_LENGTHS:
        return _COMMON_LENGTHS[unit]
    ureg = registry()
    if unit.strip().lower() in ("mil", "mils"):
        raise ValueError(f"{unit!r} is an angle to pint (a milliradian), not a length: "
                         "write 'thou' for 1/1000 in")
    try:
        check_unit(unit)
        q = ureg.Quantity(1.0, unit)
    except Exception as exc:  # pint raises several unrelated types
        near = sorted(_LENGTH_NAMES, key=lambda s: (_distance(s, unit), len(s)))[0]
        hint = f": did you mean {near!r}?" if _distance(near, unit) <= 2 else ""
        raise ValueError(f"unknown unit {unit!r}{hint}") from exc
    if q.dimensionality != ureg.meter.dimensionality:
        raise ValueError(f"{unit!r} is not a length unit")
    spelled = _spellings(unit)
    if spelled is not None and unit not in spelled:
        best = sorted(spelled, key=lambda s: (_distance(s, unit), len(s)))[0]
        raise ValueError(f"{unit!r} is not a unit's name: did you mean {best!r}?")
    return float(q.to("m").magnitude)


_LENGTH_NAMES = ("mm", "cm", "m", "km", "in", "ft", "yd", "inch", "inches", "foot", "feet",
                 "yard", "yards", "thou", "meter", "meters", "metre", "metres", "millimeter",
                 "millimeters", "millimetre", "millimetres", "centimeter", "centimeters",
                 "centimetre", "centimetres", "micrometer", "micrometre")
"""Length names a misspelling is compared with (the nearest is suggested)."""


def _plural(name: str) -> str:
    """English plural of a unit's name: inches, feet, meters."""
    if name == "foot":
        return "feet"
    return name + ("es" if name.endswith(("ch", "sh", "s", "x", "z")) else "s")


def _spellings(unit: str) -> set[str] | None:
    """The ways to write the single unit pint reads ``unit`` as (None: not a single unit).

    Pint reads a plural loosely (``inchs``, ``inchess`` are inches); a file's
    unit is printed as written, so only the unit's name, its plural, its
    symbol and its aliases, after a prefix's name, symbol or alias, are taken.
    """
    ureg = registry()
    try:
        ((prefix, name, _),) = ureg.parse_unit_name(unit)
        u, p = ureg._units[name], ureg._prefixes[prefix]
    except Exception:  # not one unit (a product), or pint's tables changed
        return None
    heads = {prefix, p.symbol or "", *p.aliases}
    tails = {name, _plural(name), u.symbol or name, *u.aliases, *map(_plural, u.aliases)}
    return {h + t for h in heads for t in tails if t}


def _distance(a: str, b: str) -> int:
    """Levenshtein distance (edits between two short names)."""
    row = list(range(len(b) + 1))
    for i, ca in enumerate(a, 1):
        prev, row[0] = row[0], i
        for j, cb in enumerate(b, 1):
            prev, row[j] = row[j], min(row[j] + 1, row[j - 1] + 1, prev + (ca != cb))
    return row[-1]


#: Radians per unit of the common angle units, and seconds per unit of time, as pint gives
#: the conversions (a test compares them with pint bit for bit).
_ANGLES = {"rad": 1.0, "radian": 1.0, "radians": 1.0, "deg": math.pi / 180.0,
           "degree": math.pi / 180.0, "degrees": math.pi / 180.0, "rev": 2.0 * math.pi,
           "revolution": 2.0 * math.pi, "revolutions": 2.0 * math.pi}
_METRIC = ("mm", "cm", "m", "km")
_IMPERIAL = {"in": 1.0, "inch": 1.0, "ft": 12.0, "yd": 36.0}
_TIMES = {"s": 1.0, "sec": 1.0, "second": 1.0, "min": 60.0, "minute": 60.0}
_COMMON_UNIT = re.compile(r"^([A-Za-z]+)(?:\s*/\s*([A-Za-z]+)(\s*(?:\^|\*\*)\s*2|²)?)?$")


def _common(text: str, kind: RateKind, length_unit: str) -> float | None:
    """The usual quantities without pint (``"900 rev/min"``, ``"3 rad/s^2"``, ``"10 in/s"``).

    Angles in rad, deg or rev over s or min, and lengths in the file's own unit
    over s: the first use of a unit string no longer loads pint's registry
    (half a second).  Anything else is None, for pint.
    """
    try:
        number, unit = split_number(text)
    except ValueError:
        return None
    m = _COMMON_UNIT.match(unit)
    if m is None:
        return None
    top, per, square = m.group(1), m.group(2), m.group(3)
    power = 0 if per is None else (2 if square else 1)
    if per is not None and per not in _TIMES:
        return None
    t = 1.0 if per is None else _TIMES[per] ** power
    if kind in ("omega", "alpha", "angle") and top in _ANGLES:
        if kind == "angle":
            return number * (_ANGLES[top] * (180.0 / math.pi)) if power == 0 and \
                top not in ("deg", "degree", "degrees") else (number if power == 0 else None)
        if power != (1 if kind == "omega" else 2):
            return None
        return number * (_ANGLES[top] / t)
    want = {"length": 0, "velocity": 1, "acceleration": 2}.get(kind)
    if want is None or power != want:
        return None
    if top == length_unit:
        return number * (1.0 / t)
    if top in _METRIC and length_unit in _METRIC and per in (None, "s"):
        # m/s in a mm file: powers of ten, which pint converts by the same one product
        return number * (_COMMON_LENGTHS[top] / _COMMON_LENGTHS[length_unit])
    if top in _IMPERIAL and length_unit in _IMPERIAL and per in (None, "s"):
        # ft/s in an in file: pint converts within the family by whole ratios of inches
        return number * (_IMPERIAL[top] / _IMPERIAL[length_unit])
    return None


def parse_quantity(value: Any, kind: RateKind, length_unit: str) -> tuple[float, str | None]:
    """Parse a number or a unit string into graphkin's internal unit for ``kind``.

    Returns
    -------
    value : float
        In the internal unit (rad/s, rad/s², L/s, L/s², L or degrees).
    sense : str or None
        ``"cw"``, ``"ccw"`` or None as written.

    Raises
    ------
    ValueError
        Unreadable text, an unknown unit, a unit of the wrong kind, NaN or infinity.

    Examples
    --------
    >>> round(parse_quantity("900 rev/min", "omega", "in")[0], 6)
    94.24778
    >>> parse_quantity("36 rad/s cw", "omega", "in")
    (-36.0, 'cw')
    >>> parse_quantity("-10 m/s", "velocity", "mm")
    (-10000.0, None)
    """
    if isinstance(value, bool):
        raise ValueError(f"expected a number or a string with a unit, not {value!r}")
    if isinstance(value, (int, float)):
        return _as_float(value), None
    if not isinstance(value, str):
        raise ValueError(f"expected a number or a string with a unit, not {value!r}")
    text = value.strip()
    sense = None
    m = _SENSE.search(text)
    if m:
        sense = m.group(1).lower()
        text = text[: m.start()].strip()
    fast = _common(text, kind, length_unit)
    if fast is not None:
        _one_sign(value, fast, sense)
        return (-fast if sense == "cw" else fast), sense
    try:
        q = quantity(text)
    except ValueError:
        raise ValueError(f"cannot read {value!r} as a quantity") from None
    target = _BASE[kind].replace("L", f"({length_unit})")
    try:
        if q.unitless and kind not in ("angle",):
            # a bare number in a string ("10"); a dimensionless *unit* ("12 rad",
            # "2 rev": a rate without its "/s") is not taken for the default unit
            mag = float(q.to("dimensionless").magnitude)
        else:
            mag = float(q.to(target).magnitude)
    except Exception as exc:
        like = _BASE[kind].replace("L", length_unit).replace("**2", "^2")
        raise ValueError(f"{value!r} is not {_WHAT[kind]} (give a unit like {like})") \
            from exc
    if not math.isfinite(mag):
        raise ValueError(f"{value!r} is not finite")
    _one_sign(value, mag, sense)
    if sense == "cw":
        mag = -mag
    return mag, sense


def _one_sign(value: str, mag: float, sense: str | None) -> None:
    """Refuse a negative number with a sense word: ``"-120 rev/min cw"`` says the sense twice.

    ``cw`` already means negative (counterclockwise is positive), so a
    double negative is a mistake, not a ccw rate.
    """
    if sense is not None and mag < 0:
        plain = value.strip().lstrip("-").strip()
        raise ValueError(f"{value!r} has both a minus sign and {sense!r}: {sense} already gives "
                         f"the sense, so write {plain!r} (or the signed value without "
                         f"{sense!r})")


def parse_rate(value: Any, kind: RateKind, length_unit: str) -> float:
    """Like :func:`parse_quantity`, the value only."""
    return parse_quantity(value, kind, length_unit)[0]
