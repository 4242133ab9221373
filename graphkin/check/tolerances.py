"""How close a measured answer must be: :class:`CheckTolerance` and the sheet's scale.

A measured answer passes within a fraction of the exact value and a number of
degrees (2 % and 2° by default), or within a length on the drawing when the
sheet's scale is known (:class:`SheetScale`, ``tolerance.scale`` of an
answers file: ``"1 in = 20 ft/s"``).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (a polygon drawn to scale; values read
off it are as good as the drawing).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

from graphkin.check.keys import suggest
from graphkin.errors import InputError
from graphkin.units import parse_quantity

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
_SENSE = re.compile(r"\s*\b(ccw|cw)\s*$", re.IGNORECASE)
_AT = re.compile(r"\s+at\s+|∠", re.IGNORECASE)
_INFINITY = re.compile(r"^\s*(?:inf|infinity|∞)\b\s*", re.IGNORECASE)


@dataclass(frozen=True)
class SheetScale:
    """A drawing scale: how much of a quantity one millimetre of paper stands for.

    Attributes
    ----------
    quantity : str
        ``velocity``, ``acceleration`` or ``length`` (a posture drawing).
    per_mm : float
        The quantity, in graphkin's internal units, of one millimetre on the sheet.
    text : str
        The scale as written (``"1 mm = 5 mm/s"``).
    """

    quantity: str
    per_mm: float
    text: str


def read_scale(text: str, length_unit: str, *, key: str = "tolerance.scale",
               file: str | None = None, paper_unit: str | None = None,
               kinds: tuple[str, ...] = ("velocity", "acceleration", "length")) -> SheetScale:
    """Read a scale ``"1 mm = 5 mm/s"`` (paper length = quantity).

    Both sides go through :func:`graphkin.units.parse_quantity` (no arithmetic
    is evaluated).  ``paper_unit`` is the unit of a bare number on the left.

    Examples
    --------
    >>> s = read_scale("1 mm = 5 mm/s", "mm")
    >>> s.quantity, s.per_mm
    ('velocity', 5.0)
    >>> read_scale("1 in = 1000 ft/s²", "in").quantity
    'acceleration'
    """
    if not isinstance(text, str) or "=" not in text:
        raise InputError(f"a scale reads like \"1 mm = 5 mm/s\", not {text!r}", key=key,
                         file=file)
    left, right = (_sup(t).strip() for t in text.split("=", 1))
    try:
        if paper_unit and re.fullmatch(r"\s*[-+]?[\d.]+(?:[eE][-+]?\d+)?\s*", left):
            left = f"{left} {paper_unit}"
        paper = parse_quantity(left, "length", "mm")[0]
        if not re.search(r"[A-Za-z]", left):
            raise ValueError
    except ValueError:
        raise InputError(f"the left side of the scale, {left!r}, is not a length on paper",
                         key=key, file=file) from None
    for kind in kinds:
        try:
            value = parse_quantity(right, kind, length_unit)[0]
        except ValueError:
            continue
        if not (paper > 0 and value > 0):
            raise InputError("both sides of the scale must be positive", key=key, file=file)
        per = value / paper
        if not 1e-100 <= per <= 1e100:
            # lengths on paper times the scale must stay finite (no 'inf in/s')
            raise InputError(f"the scale {text.strip()!r} is out of range: one millimetre of "
                             "paper may stand for 1e-100 to 1e100 of the quantity", key=key,
                             file=file)
        return SheetScale(kind, per, text.strip())
    raise InputError(f"the right side of the scale, {right!r}, is not a "
                     f"{' or '.join(kinds)}", key=key, file=file)


def _sup(text: str) -> str:
    return text.replace("²", "^2").replace("³", "^3").replace("·", "*")


@dataclass(frozen=True)
class CheckTolerance:
    """How close a measured value must be to count as right.

    Parameters
    ----------
    relative : float
        Fraction of the exact magnitude (0.02 = 2 %); for positions, of the
        size of the mechanism.
    angle : float
        Degrees, for directions and link angles.
    drawing : float or None
        Drawing accuracy as a length on the sheet, in millimetres: a vector is
        also right when its end lies within this distance of the exact end
        on the paper (needs the scale of its polygon).
    scales : tuple of SheetScale
        The scales of the student's drawings (one per quantity).

    Examples
    --------
    >>> CheckTolerance()
    CheckTolerance(relative=0.02, angle=2.0)
    >>> CheckTolerance.parse({"relative": "5 %", "angle": 3})
    CheckTolerance(relative=0.05, angle=3.0)
    >>> t = CheckTolerance.parse({"drawing": "0.5 mm", "scale": "1 mm = 5 mm/s"}, length_unit="mm")
    >>> t.drawing, t.per_mm("velocity")
    (0.5, 5.0)
    """

    relative: float = 0.02
    angle: float = 2.0
    drawing: float | None = None
    scales: tuple[SheetScale, ...] = ()

    def __repr__(self) -> str:
        extra = "" if self.drawing is None else f", drawing={self.drawing!r}"
        extra += "".join(f", scale={s.text!r}" for s in self.scales)
        return f"CheckTolerance(relative={self.relative!r}, angle={self.angle!r}{extra})"

    def per_mm(self, quantity: str) -> float | None:
        """How much of ``quantity`` one millimetre of the drawing stands for, if known."""
        for s in self.scales:
            if s.quantity == quantity:
                return s.per_mm
        return None

    def describe(self) -> str:
        """The tolerance in words, for the report's head."""
        text = f"{self.relative * 100:g} % of magnitude, {self.angle:g}° of direction"
        if self.drawing is not None:
            text += f", or {self.drawing:g} mm on the drawing"
            if self.scales:
                text += f" ({'; '.join(s.text for s in self.scales)})"
        return text

    @classmethod
    def parse(cls, data: Any, *, file: str | None = None,
              base: CheckTolerance | None = None, length_unit: str = "mm") -> CheckTolerance:
        """A tolerance from the ``tolerance`` table of an answers file (or CLI values)."""
        base = base or cls()
        if not isinstance(data, dict):
            raise InputError("tolerance must be a table such as "
                             "{ relative = 0.02, angle = 2.0 }", key="tolerance", file=file)
        valid = ("relative", "angle", "drawing", "scale")
        for k in data:
            if k not in valid:
                raise InputError(f"unknown key{suggest(k, valid)}; valid: {', '.join(valid)}",
                                 key=f"tolerance.{k}", file=file)
        rel, ang, drawing, scales = base.relative, base.angle, base.drawing, base.scales
        if "relative" in data:
            rel = parse_fraction(data["relative"], key="tolerance.relative", file=file)
        if "angle" in data:
            ang = parse_degrees(data["angle"], key="tolerance.angle", file=file)
        if "drawing" in data:
            try:
                drawing = parse_quantity(data["drawing"], "length", "mm")[0]
            except ValueError as exc:
                raise InputError(f"{exc} (write \"0.5 mm\")", key="tolerance.drawing",
                                 file=file) from None
            if not drawing > 0:
                raise InputError("the drawing tolerance must be a positive length",
                                 key="tolerance.drawing", file=file)
        if "scale" in data:
            raw = data["scale"]
            texts = raw if isinstance(raw, list) else [raw]
            scales = tuple(read_scale(t, length_unit, file=file) for t in texts)
        return cls(rel, ang, drawing, scales)


def parse_fraction(value: Any, *, key: str, file: str | None = None) -> float:
    """A relative tolerance: ``0.02`` or ``"2 %"``; must be positive.

    Examples
    --------
    >>> parse_fraction("2%", key="relative"), parse_fraction(0.05, key="relative")
    (0.02, 0.05)
    """
    try:
        if isinstance(value, str) and value.strip().endswith("%"):
            v = float(value.strip()[:-1]) / 100.0
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            v = float(value)
        else:
            v = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{value!r} is not a fraction (write 0.02 or \"2 %\")", key=key,
                         file=file) from None
    if not (math.isfinite(v) and v > 0):
        raise InputError(f"{value!r} must be a positive fraction", key=key, file=file)
    if v >= 1:
        # relative = 2 meant 2 %, not 200 %: a tolerance that passes any answer of the
        # right sign is a slip, not a choice
        raise InputError(f"{value!r} is {v * 100:g} %: a relative tolerance is a fraction "
                         f"below 1 (write 0.02 or \"2 %\")", key=key, file=file)
    return v


def parse_degrees(value: Any, *, key: str, file: str | None = None) -> float:
    """An angle tolerance in degrees (a number or a string with an angle unit)."""
    try:
        v = parse_quantity(_deg_text(value), "angle", "m")[0]
    except ValueError as exc:
        raise InputError(str(exc), key=key, file=file) from None
    if not v > 0:
        raise InputError(f"{value!r} must be a positive angle", key=key, file=file)
    return v


def _deg_text(value: Any) -> Any:
    if isinstance(value, str):
        return value.replace("°", " deg")
    return value
