"""Mutated mechanism files never end in a traceback (issue 14, item 9).

Hypothesis takes the textbook mechanisms that ship with graphkin and mutates
their parsed TOML (deletes, duplicates or renames keys, changes types, puts
extreme numbers and odd names in), writes the result back as TOML and runs
the commands in-process.  Only clean outcomes are asserted: exit status 0,
or 2 with one line; nothing else may escape.
"""

from __future__ import annotations

import contextlib
import io
import math
import tomllib
from pathlib import Path
from typing import Any

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin.cli import main
from graphkin.examples import names, text

BASES = {n: tomllib.loads(text(n)) for n in names()}

EXTREMES = [0, -1, 1e308, -1e308, 1e200, 1e-300, 10**30, -(10**25), 1e14, 0.0, 5e-324,
            "9**9**9 rad/s", "1e999 rad/s", "", "nan", "inf", "\x1b]0;x\x07", "$\\frac{$",
            "P%", "a_b_c", "_", True, [], {}, [1, 2, 3], [[1, 2]], {"x": 1}, "900 rev/min cw"]
NAMES = ["", "1", "99", "A", "B", "C", "_", "P%", "a_b_c", "\x1b[2J", "é", "links", "drive"]


def _paths(data: Any, prefix: tuple = ()) -> list[tuple]:
    out = [prefix] if prefix else []
    if isinstance(data, dict):
        for k, v in data.items():
            out += _paths(v, (*prefix, k))
    elif isinstance(data, list):
        for i, v in enumerate(data):
            out += _paths(v, (*prefix, i))
    return out


def _parent(data: Any, path: tuple) -> Any:
    for k in path[:-1]:
        data = data[k]
    return data


@st.composite
def mutated(draw: st.DrawFn) -> dict:
    import copy

    data = copy.deepcopy(BASES[draw(st.sampled_from(sorted(BASES)))])
    for _ in range(draw(st.integers(1, 3))):
        paths = _paths(data)
        if not paths:
            break
        path = draw(st.sampled_from(paths))
        parent, key = _parent(data, path), path[-1]
        op = draw(st.sampled_from(["delete", "duplicate", "rename", "value", "scale"]))
        if op == "delete":
            del parent[key]
        elif op == "duplicate" and isinstance(parent, list):
            parent.append(copy.deepcopy(parent[key]))
        elif op == "duplicate" and isinstance(parent, dict):
            parent[f"{key}2"] = copy.deepcopy(parent[key])
        elif op == "rename" and isinstance(parent, dict):
            parent[draw(st.sampled_from(NAMES))] = parent.pop(key)
        elif op == "scale" and isinstance(parent[key], (int, float)) \
                and not isinstance(parent[key], bool):
            parent[key] = parent[key] * draw(st.sampled_from([1e-12, 1e12, -1, 1e300]))
        else:
            parent[key] = copy.deepcopy(draw(st.sampled_from(EXTREMES)))
    return data


def _toml(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):
        return '"' + "".join(c if c.isprintable() and c not in '"\\' else f"\\u{ord(c):04x}"
                             for c in value) + '"'
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    return "{" + ", ".join(f"{_toml(str(k))} = {_toml(v)}" for k, v in value.items()) + "}"


def dumps(data: dict) -> str:
    return "\n".join(f"{_toml(str(k))} = {_toml(v)}" for k, v in data.items()) + "\n"


COMMANDS = [["solve"], ["solve", "--json", "--steps"], ["sweep", "--count", "5", "--csv", "OUT"]]


@settings(max_examples=int(__import__("os").environ.get("MUT_EXAMPLES", "40")), deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(data=mutated(), command=st.sampled_from(COMMANDS))
def test_mutated_files_end_cleanly(data: dict, command: list[str], tmp_path: Path) -> None:
    f = tmp_path / "m.toml"
    f.write_text(dumps(data), encoding="utf-8")
    argv = [command[0], str(f), *(str(tmp_path / "o.csv") if a == "OUT" else a
                                   for a in command[1:])]
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            rc = main(argv)
        except SystemExit as exc:
            rc = int(exc.code or 0)
    e = err.getvalue()
    assert rc in (0, 2), e
    assert "Traceback" not in e and "internal error" not in e and "cannot handle" not in e, e
    if rc == 2:
        assert len([ln for ln in e.splitlines() if ln.strip()]) == 1, e
    assert " nan " not in out.getvalue() and "nan°" not in out.getvalue()
