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

from graphkin.check.keys import (
    KEY_HELP,
    META_KEYS,
    Key,
    parse_key,
    point_on_link,
    suggest,
    valid_keys,
)
from graphkin.check.text import printable
from graphkin.check.tolerances import (
    CheckTolerance,
    SheetScale,
    _deg_text,
    parse_degrees,
    parse_fraction,
    read_scale,
)
from graphkin.errors import InputError
from graphkin.files import quote_hint
from graphkin.mechanisms.model import Mechanism
from graphkin.units import parse_quantity

__all__ = ["Key", "Given", "Answers", "CheckTolerance", "SheetScale", "parse_key", "parse_value",
           "load_answers", "loads_answers", "answers_from_dict", "read_scale", "valid_keys",
           "read_limited", "MAX_FILE_BYTES", "KEY_HELP", "META_KEYS", "point_on_link",
           "suggest", "parse_degrees", "parse_fraction"]

#: the largest answers file or drawing read (bytes): a class's files are a few kB
MAX_FILE_BYTES = 20_000_000

_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
_SENSE = re.compile(r"\s*\b(ccw|cw)\s*$", re.IGNORECASE)
_AT = re.compile(r"\s+at\s+|∠", re.IGNORECASE)
_INFINITY = re.compile(r"^\s*(?:inf|infinity|∞)\b\s*", re.IGNORECASE)


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


def _no_sense(sense: str | None, value: Any, key: str, file: str | None) -> None:
    """Refuse cw/ccw on a vector or a length: only ω and α turn (answers.md).

    ``V_E = "27.6 ft/s cw"`` was read as the magnitude alone, the sense dropped
    without a word; the student meant a direction, or wrote ω's sense on V.
    """
    if sense is not None:
        raise InputError(f"{value!r}: cw/ccw is the sense of an ω or α; give a velocity, "
                         "an acceleration or a length its direction (\"27.6 ft/s at 165 "
                         "deg\") or its magnitude alone", key=key, file=file)


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
        v, sense, g.unit, g.factor = _quantity(value, "length", mech, k, file)
        _no_sense(sense, value, k, file)
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
        mag, sense, g.unit, g.factor = _quantity(value["magnitude"], kind, mech, k, file)
        _no_sense(sense, value["magnitude"], k, file)
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
        mag, sense, g.unit, g.factor = _quantity(parts[0].strip(), kind, mech, k, file)
        _no_sense(sense, value, k, file)
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
        raise InputError(f"not valid TOML: {exc}{quote_hint(text, exc)}",
                         file=source or None) from None
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
