"""The vector file: ``C = A + B`` stated in a small TOML file, read for ``graphkin vector``.

The file states what is known of each vector; a part that is left out (or
written ``"?"``, the book's mark) is unknown, and exactly two parts must be::

    title = "Case 4 (Fig. 2.13)"   # optional
    units = "in"                   # optional: the unit of every magnitude
                                   # (also units = { length = "in" })
    branch = "left"                # optional: keep one branch (case 2: behind/ahead,
                                   #           case 4: left/right)
    [A]
    magnitude = 3                  # a number in `units`, or a string "76.2 mm"
    [B]
    magnitude = 4
    [C]
    magnitude = 5
    angle = 0                      # degrees, or a string with a unit: "0.5 rad"

Every mistake in the file becomes an :class:`~graphkin.errors.InputError`
naming the file and the key, which the CLI prints as one line (exit status 2).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 and Table 2.2 (the four cases); results are written ``R∠θ`` as in
Sec. 2.10, Example 2.3.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from graphkin.errors import InputError
from graphkin.files import parse_toml, read_text
from graphkin.keys import VECTOR, check_keys, read_units
from graphkin.kinematics.vector_equation import NAMES, Polar

__all__ = ["VectorFile", "load", "loads"]


@dataclass(frozen=True)
class VectorFile:
    """The contents of a vector file.

    Attributes
    ----------
    knowns : dict
        ``"A"``, ``"B"``, ``"C"`` -> :class:`~graphkin.kinematics.vector_equation.Polar`
        (angles in radians, magnitudes in ``units``).
    units : str or None
        The unit of the magnitudes, as written.
    branch : str or None
        The branch to keep, as written.
    title : str
    source : str
        The file name (for messages).
    """

    knowns: Mapping[str, Polar]
    units: str | None = None
    branch: str | None = None
    title: str = ""
    source: str = "<vector file>"


def load(path: str | Path) -> VectorFile:
    """Read a vector file.

    Raises
    ------
    InputError
        The file cannot be read or says something unusable (naming the key).
    """
    p = Path(path)
    return loads(read_text(p), source=str(p))


def loads(text: str, source: str = "<vector file>") -> VectorFile:
    r"""Parse the text of a vector file (see :func:`load`).

    Examples
    --------
    >>> f = loads('units = "in"\n[A]\nmagnitude = 3\n[B]\nmagnitude = "101.6 mm"\n'
    ...           '[C]\nmagnitude = 5\nangle = 0\n')
    >>> str(f.knowns["A"]), str(f.knowns["B"]), str(f.knowns["C"])
    ('3∠?', '4∠?', '5∠0°')
    """
    data = parse_toml(text, source)

    def fail(key: str | None, message: str) -> InputError:
        return InputError(message, key=key, file=source)

    check_keys(data, VECTOR, source)
    title = data.get("title", "")
    if not isinstance(title, str):
        raise fail("title", f"expected a string, not {title!r}")
    if len(title) > 1000:  # as a mechanism's title (graphkin.mechanisms.parse.MAX_TITLE)
        raise fail("title", f"the title has {len(title)} characters; at most 1000 are drawn")
    units = None
    if "units" in data:
        units = read_units(data["units"], "units", source, VECTOR["units"]).get("length")
    if units is not None:
        try:
            _quantity(f"1 {units}")
        except ValueError:
            raise fail("units", f"unknown unit {units!r}") from None
    branch = data.get("branch")
    if branch is not None and not isinstance(branch, str):
        raise fail("branch", f"expected a branch name such as \"left\", not {branch!r}")
    knowns = {}
    for name in NAMES:
        table = data.get(name, {})
        if not isinstance(table, Mapping):
            raise fail(name, f"expected a table [{name}] with magnitude and angle, "
                             f"not {table!r}")
        try:
            m = _magnitude(table.get("magnitude"), units)
        except ValueError as exc:
            raise fail(f"{name}.magnitude", str(exc)) from None
        try:
            a = _angle(table.get("angle"))
        except ValueError as exc:
            raise fail(f"{name}.angle", str(exc)) from None
        knowns[name] = Polar(m, a)
    return VectorFile(knowns, units, branch, title, source)

def _quantity(text: str) -> Any:
    from graphkin.units import quantity

    return quantity(text)  # the number read by float(); pint sees only a checked unit


def _read(value: Any) -> float | str | None:
    """A number, ``None`` for unknown (absent or ``"?"``), or a quantity string to convert."""
    if isinstance(value, bool):
        raise ValueError(f"expected a number, not {value!r}")
    if isinstance(value, (int, float)):
        if not math.isfinite(value):
            raise ValueError(f"expected a finite number, not {value!r}")
        return float(value)
    if value is None or (isinstance(value, str) and value.strip() == "?"):
        return None
    if not isinstance(value, str):
        raise ValueError(f"expected a number, a string with a unit, or \"?\", not {value!r}")
    return value


def _convert(text: str, unit: str, what: str) -> float:
    q = _quantity(text)
    if getattr(q, "unitless", True):
        raise ValueError(f"{text!r} has no unit; {what}")
    try:
        out = float(q.to(unit).magnitude)
    except Exception:
        raise ValueError(f"cannot convert {text!r} to {unit}") from None
    if not math.isfinite(out):
        raise ValueError(f"{text!r} is not finite")
    return out


def _magnitude(value: Any, units: str | None) -> float | None:
    x = _read(value)
    if not isinstance(x, str):
        return x
    if units is None:
        if getattr(_quantity(x), "unitless", True):
            raise ValueError(f"expected a number, not {x!r}")
        raise ValueError(f"{x!r} has a unit, so the file needs `units = ...` "
                         "(the unit of every magnitude)")
    return _convert(x, units, "write a plain number in the file's units")


def _angle(value: Any) -> float | None:
    x = _read(value)
    if x is None:
        return None
    if not isinstance(x, str):
        return math.radians(x)
    return _convert(x, "radian", "write a plain number of degrees, or a unit as in \"0.5 rad\"")
