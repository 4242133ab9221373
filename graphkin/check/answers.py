"""Reading an answers file: textbook keys (``omega3``, ``V_E``, ``I13``) and measured values.

A key names a quantity of the mechanism in the book's notation; a value is a
number in the mechanism file's units or a string with any unit pint knows,
``cw``/``ccw`` for a sense and ``at <deg>`` (or ``∠<deg>``) for a direction.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.2-3.4 (notation ``V_P``, ``V_PQ``,
``ω``), 3.13 (instant centers ``I_ij``), 4.2-4.6 (``A_PQ^n``, ``A_PQ^t``,
Coriolis), 4.14 (radius of curvature of a path).
"""

from __future__ import annotations

import difflib
import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.check.text import printable
from graphkin.errors import InputError
from graphkin.mechanisms.model import Mechanism
from graphkin.units import parse_quantity

__all__ = ["Key", "Given", "Answers", "CheckTolerance", "SheetScale", "parse_key", "parse_value",
           "load_answers", "loads_answers", "answers_from_dict", "read_scale", "valid_keys",
           "read_limited", "MAX_FILE_BYTES", "KEY_HELP"]

#: the largest answers file or drawing read (bytes): a class's files are a few kB
MAX_FILE_BYTES = 20_000_000

KEY_HELP = ("keys are theta<k>, omega<k>, alpha<k>, V_<P>, A_<P>, V_<P><Q>, A_<P><Q>, "
            "A_<P><Q>^n, A_<P><Q>^t, A_<P>^c, R_<P>, R_<P><Q>, I<i><j>, rho_<P>, "
            "F_<i><j> (force by link i on link j), T_1<k> (the drive's torque)")

#: keys of an answers file that are not answers
META_KEYS = ("tolerance", "student", "name", "title", "comment", "notes", "mechanism")

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
_SENSE = re.compile(r"\s*\b(ccw|cw)\s*$", re.IGNORECASE)
_AT = re.compile(r"\s+at\s+|∠", re.IGNORECASE)
_INFINITY = re.compile(r"^\s*(?:inf|infinity|∞)\b\s*", re.IGNORECASE)
_SCALAR_KIND = {"omega": "omega", "alpha": "alpha"}
_VECTOR_KIND = {"V": "velocity", "A": "acceleration", "An": "acceleration",
                "At": "acceleration", "Ac": "acceleration", "R": "length"}
_GREEK = {"θ": "theta", "ω": "omega", "α": "alpha", "ρ": "rho"}


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
        return SheetScale(kind, value / paper, text.strip())
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


@dataclass(frozen=True)
class Key:
    """A quantity named in textbook notation.

    Attributes
    ----------
    text : str
        The key as written.
    kind : str
        ``theta``, ``omega``, ``alpha`` (args: link), ``V``, ``A``, ``R``
        (args: point, or point and reference point), ``An``, ``At`` (the
        normal and tangential components of ``A_PQ``), ``Ac`` (the Coriolis
        component at a point), ``I`` (args: two link ids), ``rho`` (a point).
    args : tuple of str
    link : str or None
        For ``V_A4``, ``A_A4``: the link whose coincident point at A is meant
        (the book's A4, Sec. 3.6), else None.
    """

    text: str
    kind: str
    args: tuple[str, ...]
    link: str | None = field(default=None, repr=False)

    @property
    def quantity(self) -> str:
        """What kind of value the key wants (for units): ``angle``, ``omega``, ``velocity``..."""
        if self.kind == "theta":
            return "angle"
        if self.kind in _SCALAR_KIND:
            return _SCALAR_KIND[self.kind]
        if self.kind in _VECTOR_KIND:
            return _VECTOR_KIND[self.kind]
        if self.kind in ("F", "T"):  # docs/forces.md
            return "force" if self.kind == "F" else "torque"
        return "length"

    @property
    def shape(self) -> str:
        """How the value compares: ``angle``, ``scalar``, ``vector``, ``point``, ``magnitude``."""
        if self.kind == "theta":
            return "angle"
        if self.kind in _SCALAR_KIND or self.kind == "T":
            return "scalar"
        if self.kind == "I" or (self.kind == "R" and len(self.args) == 1):
            return "point"
        if self.kind == "rho":
            return "magnitude"
        return "vector"

    def pretty(self) -> str:
        """The key in the book's symbols: ``ω3``, ``V_CB``, ``I13``."""
        sym = {"theta": "θ", "omega": "ω", "alpha": "α"}
        if self.kind in sym:
            return sym[self.kind] + self.args[0]
        return self.text


def _split_pair(rest: str, names: list[str], key: str, what: str,
                file: str | None) -> tuple[str, str] | None:
    if "-" in rest:
        a, _, b = rest.partition("-")
        if a in names and b in names:
            return a, b
        raise InputError(f"{rest!r} is not two {what} separated by '-'; {what}: "
                         f"{', '.join(names)}", key=key, file=file)
    splits = [(rest[:i], rest[i:]) for i in range(1, len(rest))
              if rest[:i] in names and rest[i:] in names]
    if len(splits) == 1:
        return splits[0]
    if len(splits) > 1:
        raise InputError(f"{rest!r} can be read as {' or '.join('-'.join(s) for s in splits)}; "
                         f"write it with a '-'", key=key, file=file)
    return None


def parse_key(text: str, mech: Mechanism, *, file: str | None = None) -> Key:
    """Read an answer key against a mechanism's link ids and point names.

    Raises
    ------
    InputError
        Unknown kind of key, unknown link or point, or an ambiguous pair.

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.examples.fourbar()
    >>> parse_key("V_CB", mech)
    Key(text='V_CB', kind='V', args=('C', 'B'))
    >>> parse_key("omega3", mech).args, parse_key("I13", mech).args
    (('3',), ('1', '3'))
    >>> parse_key("A_CB^n", mech).kind
    'An'
    """
    raw = text
    s = text.strip()
    for g, name in _GREEK.items():
        if s.startswith(g):
            s = name + s[len(g):]
    names = list(mech.point_names)
    links = list(mech.links)
    shown = [n for n in names if n not in mech.helper_points]  # never slot-definition points

    m = re.fullmatch(r"(theta|omega|alpha)_?(.+)", s)
    if m:
        lid = m.group(2)
        if lid not in links:
            raise InputError(f"no link {lid!r}; links are {', '.join(links)}", key=raw, file=file)
        return Key(raw, m.group(1), (lid,))
    m = re.fullmatch(r"rho_(.+)", s)
    if m:
        p = m.group(1)
        if p not in names:
            raise InputError(f"no point {p!r}; points are {', '.join(shown)}", key=raw, file=file)
        return Key(raw, "rho", (p,))
    m = re.fullmatch(r"I_?(.+)", s)
    if m:
        rest = m.group(1)
        pair = _split_pair(rest, links, raw, "link ids", file)
        if pair is None or pair[0] == pair[1]:
            raise InputError(f"{rest!r} is not two different link ids; links are "
                             f"{', '.join(links)} (write I1-13 for long ids)", key=raw, file=file)
        a, b = sorted(pair, key=_id_order)
        return Key(raw, "I", (a, b))
    m = re.fullmatch(r"([FT])_?(.+)", s)
    if m and mech.has_forces:  # a joint force F_34 or the drive's torque T_12 (Ch. 11-12)
        rest = m.group(2)
        pair = _split_pair(rest, links, raw, "link ids", file)
        if pair is None or pair[0] == pair[1]:
            raise InputError(f"{rest!r} is not two different link ids; links are "
                             f"{', '.join(links)} (write F_3-4 for long ids)", key=raw, file=file)
        return Key(raw, m.group(1), pair)
    m = re.fullmatch(r"([VAR])_(.+)", s)
    if m:
        letter, rest = m.group(1), m.group(2)
        kind = letter
        if rest not in names and letter == "A":
            sm = re.fullmatch(r"(.+?)(?:\^|_)([ntc])", rest)
            if sm:
                rest, comp = sm.group(1), sm.group(2)
                kind = {"n": "An", "t": "At", "c": "Ac"}[comp]
        if rest in names:
            if kind in ("An", "At"):
                raise InputError(f"{kind[-1]} components belong to a difference such as "
                                 f"A_{rest}B^{kind[-1]}", key=raw, file=file)
            return Key(raw, kind, (rest,))
        if kind == "Ac":
            raise InputError(f"no point {rest!r}; points are {', '.join(shown)}", key=raw,
                             file=file)
        pair = _split_pair(rest, names, raw, "points", file)
        if pair is None and kind in ("V", "A"):
            on = point_on_link(rest, mech)
            if on is not None:
                return Key(raw, kind, (on[0],), link=on[1])
        if pair is None:
            raise InputError(f"{rest!r} is not a point or a pair of points; points are "
                             f"{', '.join(shown)}", key=raw, file=file)
        if pair[0] == pair[1]:
            raise InputError("a difference needs two different points", key=raw, file=file)
        return Key(raw, kind, pair)
    raise InputError(f"unknown answer key; {KEY_HELP}", key=raw, file=file)


def point_on_link(text: str, mech: Mechanism) -> tuple[str, str] | None:
    """``"A4"`` -> ``("A", "4")``: the point of link 4 that coincides with A (Sec. 3.6).

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [2, 0]
    ... [drive]
    ... link = 2
    ... angle = 90
    ... ''')
    >>> point_on_link("B1", mech), point_on_link("B3", mech)
    (('B', '1'), None)
    """
    text = text.replace("@", "")
    for i in range(len(text) - 1, 0, -1):
        name, lid = text[:i], text[i:]
        if name in mech.point_names and lid in mech.links:
            return name, lid
    return None


def _id_order(lid: str) -> tuple[int, int | str]:
    return (0, int(lid)) if lid.isdigit() else (1, lid)


@dataclass
class Given:
    """A measured value, in graphkin's internal units (file length unit, rad, s).

    Attributes
    ----------
    key : Key
    raw : object
        The value as written.
    value : float or None
        Scalar (signed for ω, α; degrees for θ), or the magnitude of a vector.
    signed : bool
        For ω, α: whether a sense was given (``cw``/``ccw`` or a minus sign).
    direction : float or None
        Direction of a vector in degrees, when measured.
    point : ndarray or None
        A position ``[x, y]`` (I, R_P).
    ideal : bool
        An instant center given at infinity (``direction`` then holds its direction).
    unit : str
        The unit to show values in, and ``factor`` its size in internal units.
    """

    key: Key
    raw: Any
    value: float | None = None
    signed: bool = False
    direction: float | None = None
    point: np.ndarray | None = None
    ideal: bool = False
    unit: str = ""
    factor: float = 1.0
    vector: np.ndarray | None = None
    note: str = ""

    def components(self) -> np.ndarray | None:
        """The vector ``[x, y]`` when magnitude and direction are both known."""
        if self.vector is not None:
            return self.vector
        if self.value is None or self.direction is None:
            return None
        t = math.radians(self.direction)
        return self.value * np.array([math.cos(t), math.sin(t)])


def _unit_text(text: str) -> str:
    m = _NUMBER.match(text)
    return m.group(2).strip() if m else ""


def _factor(unit: str, kind: str, length_unit: str) -> float:
    try:
        return parse_quantity(f"1 {unit}", kind, length_unit)[0]
    except ValueError:
        return 1.0


def _default_unit(kind: str, length_unit: str) -> str:
    if kind in ("force", "torque"):
        return ""
    return {"omega": "rad/s", "alpha": "rad/s^2", "velocity": f"{length_unit}/s",
            "acceleration": f"{length_unit}/s^2", "length": length_unit, "angle": "deg"}[kind]


def _quantity(value: Any, kind: str, mech: Mechanism, key: str,
              file: str | None) -> tuple[float, str | None, str, float]:
    """(internal value, sense, display unit, unit factor) of one number or string."""
    lu = mech.length_unit
    if kind in ("force", "torque"):
        from graphkin.mechanisms.loading import parse_answer_amount

        try:
            return parse_answer_amount(value, kind, mech)
        except ValueError as exc:
            raise InputError(str(exc), key=key, file=file) from None
    text = _deg_text(value) if kind == "angle" else value
    try:
        v, sense = parse_quantity(text, kind, lu)
    except ValueError as exc:
        raise InputError(str(exc), key=key, file=file) from None
    unit = ""
    if isinstance(value, str):
        unit = _unit_text(_SENSE.sub("", value.replace("°", " deg")))
    if not unit:
        return v, sense, _default_unit(kind, lu), 1.0
    return v, sense, unit, _factor(unit, kind, lu)


def parse_value(key: Key, value: Any, mech: Mechanism, *, file: str | None = None) -> Given:
    """Read a measured value for ``key``.

    Raises
    ------
    InputError
        A value of the wrong kind or form, an unknown unit.
    """
    k = key.text
    kind = key.quantity
    g = Given(key, value)
    if isinstance(value, bool) or value is None:
        raise InputError(f"{value!r} is not a measured value", key=k, file=file)
    if key.shape == "angle":
        v, _, g.unit, g.factor = _quantity(value, "angle", mech, k, file)
        g.value = v
        if g.unit in ("deg", "degree", "degrees"):
            g.unit, g.factor = "deg", 1.0
        return g
    if key.shape == "scalar":
        v, sense, g.unit, g.factor = _quantity(value, kind, mech, k, file)
        # a number is signed (ccw positive, answers.md); so is a string with a sense or a
        # sign; a string with a unit and neither ("5.9 rad/s") gives the magnitude only
        g.value = v
        g.signed = not isinstance(value, str) or sense is not None \
            or value.strip()[:1] in "+-"
        if not g.signed:
            g.note = "magnitude only: judged on its size (write cw/ccw or a sign for a sense)"
        return g
    if key.shape == "magnitude":
        if isinstance(value, str) and _INFINITY.match(value):
            g.value, g.unit = math.inf, mech.length_unit
            return g
        v, _, g.unit, g.factor = _quantity(value, "length", mech, k, file)
        g.value = abs(v)
        return g
    if key.shape == "point":
        if isinstance(value, str) and key.kind == "I":
            m = _INFINITY.match(value)
            if not m:
                raise InputError("an instant center is a position [x, y], or \"infinity at "
                                 "<deg>\" for one at infinity", key=k, file=file)
            rest = value[m.end():].strip()
            rest = re.sub(r"^(at\s+|∠)", "", rest, flags=re.IGNORECASE)
            if not rest:
                raise InputError("give the direction of an instant center at infinity: "
                                 "\"infinity at 30 deg\"", key=k, file=file)
            g.ideal = True
            g.direction = _quantity(rest, "angle", mech, k, file)[0]
            g.unit = mech.length_unit
            return g
        xy, g.unit, g.factor = _pair(value, "length", mech, k, file)
        g.point = xy
        return g
    # vectors
    if isinstance(value, dict):
        valid = ("magnitude", "direction", "angle")
        for u in value:
            if u not in valid:
                raise InputError(f"unknown key{suggest(u, valid)}; a vector table has "
                                 "magnitude and, optionally, direction", key=f"{k}.{u}",
                                 file=file)
        if "magnitude" not in value:
            raise InputError("a vector table has magnitude and, optionally, direction",
                             key=k, file=file)
        mag, _, g.unit, g.factor = _quantity(value["magnitude"], kind, mech, k, file)
        d = value.get("direction", value.get("angle"))
        g.value = abs(mag)
        if d is not None:
            g.direction = _quantity(d, "angle", mech, k, file)[0] + (180.0 if mag < 0 else 0.0)
        return g
    if isinstance(value, list):
        xy, g.unit, g.factor = _pair(value, kind, mech, k, file)
        g.vector = xy
        g.value = float(np.hypot(*xy))
        g.direction = math.degrees(math.atan2(xy[1], xy[0])) if g.value > 0 else None
        return g
    if isinstance(value, str):
        parts = _AT.split(value, maxsplit=1)
        mag, _, g.unit, g.factor = _quantity(parts[0].strip(), kind, mech, k, file)
        g.value = abs(mag)
        if len(parts) == 2:
            g.direction = (_quantity(parts[1].strip(), "angle", mech, k, file)[0]
                           + (180.0 if mag < 0 else 0.0))
        return g
    mag, _, g.unit, g.factor = _quantity(value, kind, mech, k, file)
    g.value = abs(mag)
    return g


def _pair(value: Any, kind: str, mech: Mechanism, key: str,
          file: str | None) -> tuple[np.ndarray, str, float]:
    if not isinstance(value, list) or len(value) != 2:
        raise InputError("expected a pair [x, y]", key=key, file=file)
    out = []
    unit, factor = _default_unit(kind, mech.length_unit), 1.0
    for v in value:
        x, _, u, f = _quantity(v, kind, mech, key, file)
        if isinstance(v, str) and _unit_text(v):
            unit, factor = u, f
        out.append(x)
    return np.array(out, dtype=float), unit, factor


@dataclass
class Answers:
    """A parsed answers file.

    Attributes
    ----------
    given : list of Given
        In file order.
    tolerance : CheckTolerance
    source : str
    meta : dict
        ``student``, ``name``, ``title``... as written.
    unreadable : list of InputError
        The entries that could not be read (each names its key): reported, and
        the rest of the file is marked all the same.
    """

    given: list[Given]
    tolerance: CheckTolerance = field(default_factory=CheckTolerance)
    source: str = ""
    meta: dict[str, Any] = field(default_factory=dict)
    unreadable: list[InputError] = field(default_factory=list)

    @property
    def student(self) -> str:
        """Who wrote it (``student`` or ``name``), or ``""``."""
        return str(self.meta.get("student", self.meta.get("name", "")))


def valid_keys(mech: Mechanism) -> list[str]:
    """Every answer key of the usual forms for a mechanism, and the other keys of the file.

    For suggestions (``difflib``) when a key is misspelt.
    """
    links = list(mech.links)
    moving = [lid for lid in links if lid != "1"]
    helpers = mech.helper_points
    names = [n for n in mech.point_names if n not in helpers]
    keys = list(META_KEYS)
    for lid in moving:
        keys += [f"theta{lid}", f"omega{lid}", f"alpha{lid}"]
    for n in names:
        keys += [f"V_{n}", f"A_{n}", f"R_{n}", f"rho_{n}"]
    for link in mech.links.values():
        pts = [n for n in link.points if n in names]
        for p in pts:
            for q in pts:
                if p != q:
                    sep = "" if len(p) == len(q) == 1 else "-"
                    keys += [f"V_{p}{sep}{q}", f"A_{p}{sep}{q}", f"A_{p}{sep}{q}^n",
                             f"A_{p}{sep}{q}^t"]
    for i, a in enumerate(links):
        for b in links[i + 1:]:
            keys.append(f"I{a}{b}" if len(a) == len(b) == 1 else f"I{a}-{b}")
    return list(dict.fromkeys(keys))


def suggest(word: str, valid: Any) -> str:
    """``" (did you mean 'x'?)"`` for the nearest valid key, or ``""``.

    Examples
    --------
    >>> suggest("titel", ["title", "student"])
    " (did you mean 'title'?)"
    """
    near = difflib.get_close_matches(word, list(valid), n=1, cutoff=0.6)
    return f" (did you mean {near[0]!r}?)" if near else ""


def answers_from_dict(data: dict[str, Any], mech: Mechanism, *,
                      source: str = "") -> Answers:
    """Parse the data of an answers file (see :func:`load_answers`).

    An entry that cannot be read (an unknown key, a value of the wrong form) is
    kept in :attr:`Answers.unreadable` with the nearest valid key, and the rest
    is read all the same (a class of forty: one typo costs one answer).

    Raises
    ------
    InputError
        Nothing in the file can be marked (the first problem, or "no answers").
    """
    file = source or None
    tol = CheckTolerance()
    meta: dict[str, Any] = {}
    given: list[Given] = []
    bad: list[InputError] = []
    known: list[str] | None = None
    for k, v in data.items():
        try:
            if k == "tolerance":
                tol = CheckTolerance.parse(v, file=file, length_unit=mech.length_unit)
                continue
            if k in META_KEYS:
                meta[k] = v
                continue
            if isinstance(v, dict) and not _is_vector_table(v):
                raise InputError(f"unexpected table; {KEY_HELP}", key=k, file=file)
            try:
                key = parse_key(k, mech, file=file)
            except InputError as exc:
                known = known if known is not None else valid_keys(mech)
                raise InputError(exc.message + suggest(k, known), key=k, file=file) from None
            given.append(parse_value(key, v, mech, file=file))
        except InputError as exc:
            bad.append(InputError(printable(exc.message), key=printable(exc.key or k),
                                  file=exc.file))
    if not given:
        if bad:
            raise bad[0]
        raise InputError(f"no answers in the file; {KEY_HELP}", file=file)
    return Answers(given, tol, source, meta, bad)


def _is_vector_table(v: dict[str, Any]) -> bool:
    near = {"magnitude", "direction", "angle"}
    return "magnitude" in v or any(difflib.get_close_matches(k, near, n=1) for k in v)


def loads_answers(text: str, mech: Mechanism, *, source: str = "") -> Answers:
    """Parse answers from TOML text.

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.examples.fourbar()
    >>> ans = loads_answers('V_B = "31.4 ft/s at -150 deg"', mech)
    >>> g = ans.given[0]
    >>> round(g.value, 1), g.direction, g.unit
    (376.8, -150.0, 'ft/s')
    """
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"not valid TOML: {exc}", file=source or None) from None
    except RecursionError:
        raise InputError("not valid TOML: nested too deeply", file=source or None) from None
    return answers_from_dict(data, mech, source=source)


def read_limited(path: str | Path, what: str = "file") -> str:
    """The text of a regular file of at most :data:`MAX_FILE_BYTES` (UTF-8).

    Raises
    ------
    InputError
        Not a regular file (a pipe, a device), too large, unreadable, not UTF-8.
    """
    path = Path(path)
    try:
        st = path.stat()
        if not path.is_file():
            raise InputError(f"cannot read the {what}: not a regular file", file=str(path))
        if st.st_size > MAX_FILE_BYTES:
            raise InputError(f"cannot read the {what}: file too large ({st.st_size} bytes; "
                             f"the limit is {MAX_FILE_BYTES // 1_000_000} MB)", file=str(path))
        with path.open("rb") as fh:
            raw = fh.read(MAX_FILE_BYTES + 1)
        if len(raw) > MAX_FILE_BYTES:
            raise InputError(f"cannot read the {what}: file too large", file=str(path))
        return raw.decode("utf-8")
    except OSError as exc:
        raise InputError(f"cannot read the {what}: {exc.strerror or exc}",
                         file=str(path)) from None
    except UnicodeDecodeError:
        raise InputError(f"cannot read the {what}: not UTF-8 text", file=str(path)) from None


def load_answers(path: str | Path, mech: Mechanism) -> Answers:
    """Read an answers file (TOML, see ``docs/formats/answers.md``) for a mechanism.

    Raises
    ------
    InputError
        The file cannot be read, is not TOML, or has nothing that can be
        marked; the message names the file and the key.
    """
    text = read_limited(path)
    return loads_answers(text, mech, source=str(path))


def student_of(text: str) -> str:
    r"""The student's name from an answers file's text, even when the TOML is broken.

    Examples
    --------
    >>> student_of('student = "A. Student"\nomega3 = ')
    'A. Student'
    """
    m = re.search(r'^\s*(?:student|name)\s*=\s*"([^"\n]*)"', text, re.MULTILINE)
    return m.group(1) if m else ""
