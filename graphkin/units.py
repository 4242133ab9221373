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

__all__ = ["registry", "length_factor", "parse_rate", "parse_quantity", "RateKind"]

RateKind = str  # "omega", "alpha", "velocity", "acceleration", "length", "angle"

_SENSE = re.compile(r"\s*\b(ccw|cw)\s*$", re.IGNORECASE)

# what each kind of rate is measured in, inside graphkin ("L" is the file's length unit)
_BASE = {
    "omega": "rad/s",
    "alpha": "rad/s**2",
    "velocity": "L/s",
    "acceleration": "L/s**2",
    "length": "L",
    "angle": "deg",
}


@lru_cache(maxsize=1)
def registry() -> Any:
    """The shared pint unit registry (created on first use)."""
    import pint

    ureg: Any = pint.UnitRegistry()
    # the textbook writes revolutions as "rev" (900 rev/min)
    ureg.define("rev = revolution")
    return ureg


def length_factor(unit: str) -> float:
    """How many metres one ``unit`` is; raises ``ValueError`` if it is not a length."""
    ureg = registry()
    try:
        q = ureg.Quantity(1.0, unit)
    except Exception as exc:  # pint raises several unrelated types
        raise ValueError(f"unknown unit {unit!r}") from exc
    if q.dimensionality != ureg.meter.dimensionality:
        raise ValueError(f"{unit!r} is not a length unit")
    return float(q.to("m").magnitude)


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
        v = float(value)
        if not math.isfinite(v):
            raise ValueError(f"{value!r} is not a finite number")
        return v, None
    if not isinstance(value, str):
        raise ValueError(f"expected a number or a string with a unit, not {value!r}")
    text = value.strip()
    sense = None
    m = _SENSE.search(text)
    if m:
        sense = m.group(1).lower()
        text = text[: m.start()].strip()
    ureg = registry()
    try:
        q = ureg.Quantity(text.replace("^", "**"))
    except Exception as exc:
        raise ValueError(f"cannot read {value!r} as a quantity") from exc
    if not hasattr(q, "dimensionality"):
        q = ureg.Quantity(float(q))
    target = _BASE[kind].replace("L", f"({length_unit})")
    try:
        if q.dimensionless and kind not in ("angle",):
            mag = float(q.to("dimensionless").magnitude)
        else:
            mag = float(q.to(target).magnitude)
    except Exception as exc:
        raise ValueError(f"{value!r} is not a {kind} (expected units like {_BASE[kind]})") \
            from exc
    if not math.isfinite(mag):
        raise ValueError(f"{value!r} is not finite")
    if sense == "cw":
        mag = -mag
    return mag, sense


def parse_rate(value: Any, kind: RateKind, length_unit: str) -> float:
    """Like :func:`parse_quantity`, the value only."""
    return parse_quantity(value, kind, length_unit)[0]
