"""Read and validate a gear-train file (``docs/formats/gears.md``, "Gear trains").

::

    title = "Example 7.8 (Fig. 7.35)"
    [teeth]                 # every gear's teeth (or [radii]: pitch radii)
    2 = 40
    4 = 20
    5 = 80
    [[mesh]]
    gears = [2, 4]          # driver, driven; external contact
    arm = 3                 # the member carrying both axes (default: the frame)
    [[mesh]]
    gears = [4, 5]
    contact = "internal"
    arm = 3
    [speeds]                # as many as the train's degrees of freedom
    2 = "100 rev/min ccw"
    3 = "200 rev/min ccw"

Every problem is one :class:`~graphkin.errors.InputError` naming the file and
the key (exit status 2).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.12-7.16.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from fractions import Fraction
from pathlib import Path
from typing import Any

from graphkin.errors import InputError
from graphkin.files import parse_toml, read_text
from graphkin.gears.file import tooth_size
from graphkin.gears.train import FRAME, Contact, Mesh, Train
from graphkin.keys import TRAIN, check_keys
from graphkin.units import parse_quantity, quantity, split_number

__all__ = ["load_train", "train_from_dict", "is_train_file"]


def is_train_file(data: Mapping[str, Any]) -> bool:
    """Whether parsed TOML is a gear-train file (it has ``[[mesh]]`` tables)."""
    return "mesh" in data and "links" not in data


def load_train(path: str | Path) -> Train:
    """Read a gear-train file."""
    return train_from_dict(parse_toml(read_text(path), str(path)), str(path))


def _name(value: Any, key: str, source: str) -> str:
    if isinstance(value, bool) or not isinstance(value, (str, int)):
        raise InputError(f"a gear or arm is named by a number or a word, not {value!r}",
                         key=key, file=source)
    return str(value).strip()


def train_from_dict(data: Mapping[str, Any], source: str = "<dict>") -> Train:
    """Build the :class:`Train` of parsed TOML."""
    check_keys(data, TRAIN, source)
    title = data.get("title", "")
    if not isinstance(title, str):
        raise InputError(f"the title is text, not {title!r}", key="title", file=source)
    if ("teeth" in data) == ("radii" in data):
        raise InputError("give every gear's [teeth] or its [radii] (one of the two)",
                         key="teeth", file=source)
    table = "teeth" if "teeth" in data else "radii"
    sizes = data[table]
    if not isinstance(sizes, Mapping) or not sizes:
        raise InputError(f"expected a table [{table}] of <gear> = number", key=table,
                         file=source)
    size: dict[str, Fraction] = {}
    for name, v in sizes.items():
        key = f"{table}.{name}"
        if table == "teeth" and (isinstance(v, bool) or not isinstance(v, int) or v < 3):
            raise InputError(f"expected a whole number of teeth (3 or more), not {v!r}",
                             key=key, file=source)
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v) \
                or v <= 0 or v > 1e9:
            raise InputError(f"expected a positive number, not {v!r}", key=key, file=source)
        size[str(name)] = Fraction(v).limit_denominator(10**9)
    length_unit, module = tooth_size(data, source)
    if module is not None and table == "radii":
        raise InputError("the [radii] are the gears' sizes already: a module or diametral "
                         "pitch goes with [teeth]",
                         key="module" if "module" in data else "diametral_pitch", file=source)
    meshes = _meshes(data.get("mesh"), size, source)
    joined = _joined(data.get("joined", []), source)
    given, unit, turns = _given(data, source)
    train = Train(size, meshes, joined, given, unit, title, source, turns,
                  by_teeth=table == "teeth", length_unit=length_unit, module=module)
    known = set(train.members) | {FRAME}
    for member in given:
        if member not in known:
            raise InputError(f"no gear or arm named {member!r} (the train has "
                             f"{', '.join(train.members)})",
                             key=f"{'turns' if turns else 'speeds'}.{member}", file=source)
    return train


def _meshes(value: Any, size: dict[str, Fraction], source: str) -> list[Mesh]:
    if not isinstance(value, list) or not value or not all(isinstance(m, Mapping)
                                                           for m in value):
        raise InputError("expected [[mesh]] tables, one for each pair of gears in mesh",
                         key="mesh", file=source)
    out = []
    for i, m in enumerate(value):
        key = f"mesh[{i}]"
        pair = m.get("gears")
        if not isinstance(pair, list) or len(pair) != 2:
            raise InputError("expected gears = [driver, driven]", key=f"{key}.gears",
                             file=source)
        a, b = (_name(x, f"{key}.gears", source) for x in pair)
        for g in (a, b):
            if g not in size:
                raise InputError(f"gear {g!r} has no size in [teeth] or [radii]",
                                 key=f"{key}.gears", file=source)
        if a == b:
            raise InputError("a gear cannot mesh with itself", key=f"{key}.gears", file=source)
        try:
            contact = Contact(str(m.get("contact", "external")).strip().lower())
        except ValueError:
            raise InputError(f"contact is \"external\" or \"internal\", not "
                             f"{m.get('contact')!r}", key=f"{key}.contact", file=source) \
                from None
        arm = _name(m.get("arm", FRAME), f"{key}.arm", source)
        if arm in (a, b):
            raise InputError("a gear cannot carry its own mesh", key=f"{key}.arm", file=source)
        out.append(Mesh(a, b, contact, arm))
    return out


def _joined(value: Any, source: str) -> list[tuple[str, ...]]:
    if not isinstance(value, list) or not all(isinstance(j, Mapping) for j in value):
        raise InputError("expected [[joined]] tables: members = [..]", key="joined",
                         file=source)
    out = []
    for i, j in enumerate(value):
        members = j.get("members")
        if not isinstance(members, list) or len(members) < 2:
            raise InputError("expected members = [a, b, ...] (two or more)",
                             key=f"joined[{i}].members", file=source)
        out.append(tuple(_name(x, f"joined[{i}].members", source) for x in members))
    return out


def _given(data: Mapping[str, Any], source: str) -> tuple[dict[str, float], str, bool]:
    if "speeds" in data and "turns" in data:
        raise InputError("give [speeds] or [turns], not both", key="turns", file=source)
    turns = "turns" in data
    key = "turns" if turns else "speeds"
    table = data.get(key)
    if not isinstance(table, Mapping) or not table:
        raise InputError(f"expected a table [{key}] of <member> = motion", key=key,
                         file=source)
    unit = "deg" if turns else "rad/s"
    for v in table.values():   # the unit of the report: the first one written
        if isinstance(v, str):
            text = v.strip()
            for sense in ("ccw", "cw"):
                if text.lower().endswith(sense):
                    text = text[: -len(sense)].strip()
                    break
            try:
                written = split_number(text)[1]
            except ValueError:
                written = ""
            if written:
                unit = written
            break
    given: dict[str, float] = {}
    for name, v in table.items():
        k = f"{key}.{name}"
        try:
            value, _ = parse_quantity(v, "angle" if turns else "omega", "mm")
        except ValueError as exc:
            raise InputError(str(exc), key=k, file=source) from None
        given[str(name)] = value
    # every motion in the report's unit
    try:
        factor = float(quantity(f"1 {unit}").to("deg" if turns else "rad/s").magnitude)
    except Exception:   # pint's many error types
        raise InputError(f"{unit!r} is not a unit of {'angle' if turns else 'angular velocity'}",
                         key=key, file=source) from None
    return {m: v / factor for m, v in given.items()}, unit, turns
