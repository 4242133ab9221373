"""How graphkin writes numbers, angles, vectors and tables for people: one helper each.

A leaf module (numpy and the standard library only), like :mod:`graphkin.errors`
and :mod:`graphkin.tolerance`, so that every layer writes values the same way:
the reports and JSON of :mod:`graphkin.output`, the labels and tables of
:mod:`graphkin.render`, the marking of :mod:`graphkin.check`, the construction
tables of :mod:`graphkin.construction` and the notes of a sweep.

Conventions (the book's): angles are shown in degrees, counterclockwise from
the positive x axis, in (-180°, 180°] (Sec. 2.2); a vector is written as its
magnitude and direction, ``27.8 ft/s ∠165.30°``; an angular rate as its
magnitude and sense, ``25.38 rad/s ccw``.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Secs. 2.2 (angles) and 3.1-3.4 (results as the book states them).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any, overload

import numpy as np

__all__ = ["wrap_degrees", "fmt", "g6", "fmt_angle", "direction_degrees", "sense", "polar",
           "xy", "table", "ROUND_OFF", "toml_string", "unit_text", "degrees_text"]

ROUND_OFF = 1e-12
"""Coordinates below this fraction of the mechanism's size are written as 0 (round-off)."""


_HALF_TURN_ROUND_OFF = 1e-7
"""Degrees: an angle this close to -180° is reported as 180° (round-off of a half turn)."""


@overload
def wrap_degrees(rad: float) -> float: ...
@overload
def wrap_degrees(rad: np.ndarray) -> np.ndarray: ...
def wrap_degrees(rad: Any) -> Any:
    """Angles (rad) as degrees in (-180, 180]: a float for a number, else element by element.

    ``d - 360 k`` with ``k = ceil((d - 180) / 360)``, the turn that brings ``d``
    into the range; the subtraction is exact (the two terms are within a
    factor of two), so an angle already in the range comes back unchanged.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.2 (angles measured counterclockwise from +x).

    Examples
    --------
    >>> wrap_degrees(math.pi), wrap_degrees(-math.pi), wrap_degrees(-2 * math.pi)
    (180.0, 180.0, 0.0)
    >>> wrap_degrees(np.array([np.pi, -np.pi, 3 * np.pi / 2, 0.25]))
    array([180.        , 180.        , -90.        ,  14.32394488])
    """
    d = np.degrees(np.asarray(rad, dtype=float))
    k = np.ceil((d - 180.0) * (1.0 / 360.0))
    d = d - 360.0 * k + 0.0
    # round-off of the half turn is the half turn: -179.9999999999 is 180 on every machine
    d = np.where(d <= -180.0 + _HALF_TURN_ROUND_OFF, d + 360.0, d)
    if isinstance(rad, (int, float, np.floating, np.integer)):
        return float(d)
    return d


def fmt(x: float, digits: int = 5, *, trim: bool = True) -> str:
    """A number with ``digits`` significant digits, without an exponent for everyday sizes.

    ``trim`` (drawings, reports) drops trailing zeros and writes a missing
    value as ``—``; ``trim=False`` keeps the figures a student writes
    (``2.500``), as the marking of answers does.

    Examples
    --------
    >>> fmt(25.38276), fmt(-1819.361), fmt(3250000.0), fmt(0.0), fmt(1e-14)
    ('25.383', '-1819.4', '3250000', '0', '1e-14')
    >>> fmt(35530.6, 4, trim=False), fmt(2.5, 4, trim=False), fmt(0.054321, 4, trim=False)
    ('35531', '2.500', '0.05432')

    A tie of the last digit is rounded away from zero, whichever way round-off moved it:

    >>> fmt(218.75, 4), fmt(218.75 * (1 - 1e-15), 4), fmt(-0.125, 2)
    ('218.8', '218.8', '-0.13')
    """
    x = float(x)
    if not trim and (x == 0 or not math.isfinite(x)):
        return f"{x:g}"
    if not math.isfinite(x):
        return "—"
    if x == 0:
        return "0"
    ax = abs(x)
    plain = (1e-4 <= ax < 1e9) if trim else (1e-3 <= ax < 1e7)
    if not plain:
        if not trim:
            return f"{x:.{digits}g}"
        return f"{x:.{max(digits - 3, 1)}g}".replace("e-0", "e-").replace("e+0", "e")
    decimals = max(digits - 1 - math.floor(math.log10(ax)), 0)
    # a value on a tie of its last digit (T = 218.75 to four digits) is rounded away from
    # zero: half-to-even on the binary value would print 218.7 or 218.8 as the last digit of
    # a solve went, on another machine the other
    s = f"{x * (1.0 + 1e-9):.{decimals}f}"
    if trim and "." in s:
        s = s.rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


_POWERS = (("**2", "²"), ("^2", "²"), ("**3", "³"), ("^3", "³"))


def unit_text(unit: str) -> str:
    """A unit as every report writes it, with superscript powers: ``mm/s^2`` -> ``mm/s²``.

    Examples
    --------
    >>> unit_text("mm/s^2"), unit_text("in/s**3"), unit_text("rad/s"), unit_text("mm/rad²")
    ('mm/s²', 'in/s³', 'rad/s', 'mm/rad²')
    """
    for a, b in _POWERS:
        unit = unit.replace(a, b)
    return unit


def g6(x: float) -> str:
    """A value in a text report: six significant digits (``%.6g``).

    Examples
    --------
    >>> g6(25.382761), g6(-0.0), g6(1e-7)
    ('25.3828', '-0', '1e-07')
    """
    return f"{x:.6g}"


def direction_degrees(v: Any) -> float:
    """The direction of a 2-vector in degrees, ``atan2``'s range (-180, 180].

    Examples
    --------
    >>> direction_degrees([0.0, 1.0])
    90.0
    """
    return math.degrees(math.atan2(float(v[1]), float(v[0])))


def degrees_text(rad: float, decimals: int = 4) -> str:
    """An angle in degrees in (-180, 180], written with ``decimals``: the half turn is 180.

    An angle of a half turn is π or -π as the last digit of a solve goes: it
    prints as ``180`` on every machine, and one that rounds to zero as ``0``.

    Examples
    --------
    >>> degrees_text(math.pi), degrees_text(-math.pi), degrees_text(-1e-9, 2)
    ('180.0000', '180.0000', '0.00')
    """
    half = 0.5 * 10.0 ** -decimals
    d = math.degrees(math.remainder(rad, 2 * math.pi))
    if d <= -180.0 + half:
        d = 180.0
    if abs(d) < half:
        d = 0.0
    return f"{d:.{decimals}f}"


def fmt_angle(rad: float) -> str:
    """An angle in degrees in (-180, 180] with two decimals: ``∠154.05°``.

    Examples
    --------
    >>> fmt_angle(math.pi), fmt_angle(-1e-9)
    ('∠180.00°', '∠0.00°')
    """
    d = math.degrees(rad) % 360.0
    if d > 180.0:
        d -= 360.0
    if abs(d) < 0.005:
        d = 0.0
    if d <= -179.995:  # prints as the half turn: 180.00, never -180.00
        d = 180.0
    return f"∠{d:.2f}°"


def sense(w: float) -> str:
    """The sense of an angular quantity: ``ccw``, ``cw``, or ``""`` for zero.

    Examples
    --------
    >>> sense(2.0), sense(-1.0), sense(0.0)
    ('ccw', 'cw', '')
    """
    return "ccw" if w > 0 else ("cw" if w < 0 else "")


def clean(x: float, tiny: float = 0.0) -> float:
    """``x``, or 0 when it is round-off: no larger than ``tiny`` (and never ``-0``).

    Reports print what the arithmetic left of a zero (``1.77e-10 mm/s²`` for a
    slider that does not accelerate) as 0, so that they say what is meant and
    are the same on every machine.

    Examples
    --------
    >>> clean(1.8e-10, 1e-6), clean(-0.0), clean(2.5, 1e-6)
    (0.0, 0.0, 2.5)
    """
    x = float(x)
    return 0.0 if abs(x) <= tiny else x


def polar(v: Any, unit: str, tiny: float = 0.0) -> str:
    """A vector as the book writes it: magnitude, unit and direction, ``27.8 ft/s ∠165.30°``.

    A magnitude no larger than ``tiny`` (round-off) is printed as 0.

    Examples
    --------
    >>> polar([0.0, -2.0], "in/s"), polar([0.0, 0.0], "in/s"), polar([1e-10, 0], "in/s", 1e-6)
    ('2 in/s ∠-90.00°', '0 in/s', '0 in/s')
    """
    mag = float(np.hypot(float(v[0]), float(v[1])))
    if mag <= tiny:
        return f"0 {unit}"
    return f"{g6(mag)} {unit} {fmt_angle(math.atan2(float(v[1]), float(v[0])))}"


def xy(p: Any, unit: str, scale: float | None = None) -> str:
    """A point's coordinates, ``(x, y) unit``; ``—`` when it is missing or not finite.

    With ``scale`` (the mechanism's size), a coordinate below
    :data:`ROUND_OFF` of it is written as 0.

    Examples
    --------
    >>> xy([1.5, 2e-17], "in", 10.0), xy(None, "in")
    ('(1.5, 0) in', '—')
    """
    if p is None or not np.all(np.isfinite(np.asarray(p, dtype=float)[:2])):
        return "—"
    x, y = (float(c) + 0.0 for c in p[:2])
    if scale is not None:
        x, y = (0.0 if abs(c) < ROUND_OFF * scale else c for c in (x, y))
    return f"({g6(x)}, {g6(y)}) {unit}"


def table(rows: Sequence[Sequence[str]], indent: str = "") -> list[str]:
    """Rows of cells as aligned lines: each column as wide as its widest cell, two spaces apart.

    Trailing spaces are dropped, so an empty last cell leaves no gap.

    Examples
    --------
    >>> for line in table([("#", "center", "found by"), ("1", "I12", "pin A")], "  "):
    ...     print(line)
      #  center  found by
      1  I12     pin A
    """
    if not rows:
        return []
    widths = [max(len(r[i]) for r in rows if i < len(r)) for i in range(max(map(len, rows)))]
    return [(indent + "  ".join(c.ljust(w) for c, w in zip(r, widths))).rstrip() for r in rows]


_SCRIPT_ESCAPES = {ord("<"): "\\u003c", ord(">"): "\\u003e", ord("&"): "\\u0026",
                   0x2028: "\\u2028", 0x2029: "\\u2029"}


def script_json(data: Any) -> str:
    r"""JSON to put inside an HTML ``<script>`` element, whatever text it holds.

    ``<``, ``>`` and ``&`` are written as ``\u003c``, ``\u003e``, ``\u0026`` (the
    same string to ``JSON.parse``), so a title holding ``</script>`` or
    ``<!--<script>`` can neither close the element nor put the parser in its
    double-escaped state; U+2028 and U+2029 are escaped for old script parsers.

    Examples
    --------
    >>> script_json({"title": "<!--<script>"})
    '{"title":"\\u003c!--\\u003cscript\\u003e"}'
    """
    import json

    return json.dumps(data, separators=(",", ":"), ensure_ascii=False).translate(_SCRIPT_ESCAPES)


def toml_string(text: str) -> str:
    r"""``text`` as a TOML basic string, quotes included: a user's title written into a file.

    JSON's escapes are TOML's (``\"``, ``\\``, ``\n``, ``\u0007``); DEL, which
    TOML refuses raw and JSON keeps, is escaped too, so any title reads back as itself.

    Examples
    --------
    >>> toml_string('a "b"\nc')
    '"a \\"b\\"\\nc"'
    """
    import json

    return json.dumps(text, ensure_ascii=False).replace("\x7f", "\\u007f")
