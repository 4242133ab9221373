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

import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.errors import InputError
from graphkin.mechanisms.model import Mechanism
from graphkin.units import parse_quantity

__all__ = ["Key", "Given", "Answers", "CheckTolerance", "parse_key", "parse_value",
           "load_answers", "loads_answers", "answers_from_dict", "KEY_HELP"]

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
class CheckTolerance:
    """How close a measured value must be to count as right.

    Parameters
    ----------
    relative : float
        Fraction of the exact magnitude (0.02 = 2 %); for positions, of the
        size of the mechanism.
    angle : float
        Degrees, for directions and link angles.

    Examples
    --------
    >>> CheckTolerance()
    CheckTolerance(relative=0.02, angle=2.0)
    >>> CheckTolerance.parse({"relative": "5 %", "angle": 3})
    CheckTolerance(relative=0.05, angle=3.0)
    """

    relative: float = 0.02
    angle: float = 2.0

    @classmethod
    def parse(cls, data: Any, *, file: str | None = None,
              base: CheckTolerance | None = None) -> CheckTolerance:
        """A tolerance from the ``tolerance`` table of an answers file (or CLI values)."""
        base = base or cls()
        if not isinstance(data, dict):
            raise InputError("tolerance must be a table such as "
                             "{ relative = 0.02, angle = 2.0 }", key="tolerance", file=file)
        unknown = set(data) - {"relative", "angle"}
        if unknown:
            raise InputError(f"unknown tolerance key {sorted(unknown)[0]!r}; valid: relative, "
                             "angle", key="tolerance", file=file)
        rel = base.relative if "relative" in data else None
        ang = base.angle if "angle" in data else None
        if "relative" in data:
            rel = parse_fraction(data["relative"], key="tolerance.relative", file=file)
        if "angle" in data:
            ang = parse_degrees(data["angle"], key="tolerance.angle", file=file)
        return cls(base.relative if rel is None else rel, base.angle if ang is None else ang)


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
    """

    text: str
    kind: str
    args: tuple[str, ...]

    @property
    def quantity(self) -> str:
        """What kind of value the key wants (for units): ``angle``, ``omega``, ``velocity``..."""
        if self.kind == "theta":
            return "angle"
        if self.kind in _SCALAR_KIND:
            return _SCALAR_KIND[self.kind]
        if self.kind in _VECTOR_KIND:
            return _VECTOR_KIND[self.kind]
        if self.kind in ("F", "T"):  # spec/forces.md
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
    >>> mech = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... D = [10, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [4, 0]
    ... [links.3]
    ... B = [0, 0]
    ... C = [18, 0]
    ... [links.4]
    ... D = [0, 0]
    ... C = [11, 0]
    ... [drive]
    ... link = 2
    ... angle = 120
    ... ''')
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
            raise InputError(f"no point {p!r}; points are {', '.join(names)}", key=raw, file=file)
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
            raise InputError(f"no point {rest!r}; points are {', '.join(names)}", key=raw,
                             file=file)
        pair = _split_pair(rest, names, raw, "points", file)
        if pair is None:
            raise InputError(f"{rest!r} is not a point or a pair of points; points are "
                             f"{', '.join(names)}", key=raw, file=file)
        if pair[0] == pair[1]:
            raise InputError("a difference needs two different points", key=raw, file=file)
        return Key(raw, kind, pair)
    raise InputError(f"unknown answer key; {KEY_HELP}", key=raw, file=file)


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
        from graphkin.mechanisms.loads import parse_answer_amount

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
        g.value, g.signed = v, sense is not None or v < 0
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
        unknown = set(value) - {"magnitude", "direction", "angle"}
        if unknown or "magnitude" not in value:
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
    """

    given: list[Given]
    tolerance: CheckTolerance = field(default_factory=CheckTolerance)
    source: str = ""
    meta: dict[str, Any] = field(default_factory=dict)

    @property
    def student(self) -> str:
        """Who wrote it (``student`` or ``name``), or ``""``."""
        return str(self.meta.get("student", self.meta.get("name", "")))


def answers_from_dict(data: dict[str, Any], mech: Mechanism, *,
                      source: str = "") -> Answers:
    """Parse the data of an answers file (see :func:`load_answers`)."""
    file = source or None
    tol = CheckTolerance()
    meta: dict[str, Any] = {}
    given: list[Given] = []
    for k, v in data.items():
        if k == "tolerance":
            tol = CheckTolerance.parse(v, file=file)
            continue
        if k in META_KEYS:
            meta[k] = v
            continue
        if isinstance(v, dict) and not _is_vector_table(v):
            raise InputError(f"unexpected table; {KEY_HELP}", key=k, file=file)
        key = parse_key(k, mech, file=file)
        given.append(parse_value(key, v, mech, file=file))
    if not given:
        raise InputError(f"no answers in the file; {KEY_HELP}", file=file)
    return Answers(given, tol, source, meta)


def _is_vector_table(v: dict[str, Any]) -> bool:
    return "magnitude" in v


def loads_answers(text: str, mech: Mechanism, *, source: str = "") -> Answers:
    """Parse answers from TOML text.

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.loads('''
    ... units = { length = "in" }
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [4, 0]
    ... [drive]
    ... link = 2
    ... angle = 120
    ... omega = "900 rev/min"
    ... ''')
    >>> ans = loads_answers('V_B = "31.4 ft/s at -150 deg"', mech)
    >>> g = ans.given[0]
    >>> round(g.value, 1), g.direction, g.unit
    (376.8, -150.0, 'ft/s')
    """
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"not valid TOML: {exc}", file=source or None) from None
    return answers_from_dict(data, mech, source=source)


def load_answers(path: str | Path, mech: Mechanism) -> Answers:
    """Read an answers file (TOML, see ``spec/answers.md``) for a mechanism.

    Raises
    ------
    InputError
        The file cannot be read, is not TOML, or has a key or value that
        cannot be used; the message names the file and the key.
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise InputError(f"cannot read the file: {getattr(exc, 'strerror', None) or exc}",
                         file=str(path)) from None
    return loads_answers(text, mech, source=str(path))
