"""A mutation fuzzer over the newer features, fixed seed, fixed budget (issue 25, item 5).

The first fuzzer (test_mutations.py) mutates the textbook mechanisms; this one
starts from files that use what came later -- loads and inertia, friction,
rolling with loads and gear teeth, ``[rates]``, drives between links, point
drives, several drives -- and runs what came later on them: ``solve --json``,
``sweep --torque`` and ``animate``.  The mutations are those of the first
fuzzer plus the hostile names and titles of this round.  A ``random.Random``
with a fixed seed draws the cases, and the loop stops after a few seconds (at
least 12 cases), so CI runs the same sequence every time.  Only clean ends are
asserted: exit 0, or 2 with one line; never "cannot handle this input".

The design chapters have their own files and commands, fuzzed the same way
by a second loop: cam files (``cam``, ``cam --json``, ``cam -o``), gear pairs
and trains (``gears``, ``gears --json``, ``steps``) and synthesis files
(``synthesize``, ``synthesize -o``, whose written mechanism must read back).
"""

from __future__ import annotations

import contextlib
import copy
import io
import os
import random
import sys
import time
import tomllib
from pathlib import Path

from graphkin.cli import main

sys.path.insert(0, str(Path(__file__).parent))
from test_mutations import EXTREMES, NAMES, _parent, _paths, dumps  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
BASES = [ROOT / "gallery" / "mechanisms" / f for f in (
    "ex11_4_slider_crank_friction.toml", "ex11_5_cam_follower_friction.toml",
    "ex12_3_elliptic_trammel.toml", "ex12_4_fourbar_dynamic.toml", "fig5_5_fivebar.toml",
    "p5_7_robots.toml", "p5_13_pantograph.toml")] + [
    ROOT / "tests" / "forces" / "data" / "rolling_wheel_loaded.toml",
    ROOT / "tests" / "forces" / "data" / "spur_gears.toml",
    ROOT / "examples" / "planetary_outside.toml", ROOT / "examples" / "fivebar_coupled.toml",
    ROOT / "examples" / "fivebar_table.toml"]
DATA = {p.stem: tomllib.loads(p.read_text(encoding="utf-8")) for p in BASES if p.exists()}
for d in DATA.values():
    d.pop("gallery", None)

DESIGN_BASES = [ROOT / "examples" / "cams" / f for f in (
    "ex6_3_flat_face.toml", "ex6_5_roller.toml", "ex6_7_oscillating.toml")] + [
    ROOT / "examples" / "gears" / "ex7_1.toml", ROOT / "examples" / "gears" / "fig7_18.toml",
    ROOT / "examples" / "gears" / "trains" / "ex7_4.toml"]
DESIGN = {p.stem: tomllib.loads(p.read_text(encoding="utf-8")) for p in DESIGN_BASES
          if p.exists()}
DESIGN["postures"] = {"title": "Two postures", "units": "in",
                      "postures": [{"point": [0, 0], "angle": 0},
                                   {"point": [1, 0.5], "angle": 30}],
                      "pivots": {"circle_points": [[0.5, -1], [1.5, -1]],
                                 "center_points": [[0, -3], [3, -3]]}}
DESIGN["function"] = {"title": "1/x", "function": {
    "expression": "1/x", "range": [1, 2], "input": {"start": 30, "span": 90},
    "output": {"start": 240, "span": 90}, "ground": 1.0}}
for d in DESIGN.values():
    d.pop("gallery", None)

HOSTILE = ["F_43", "P_4", "θ2", "ω3", "n_1-4", "I13", "s4", "x²", "ﬁ", "\u202e", "<!--<script>",
           '"', "__import__('os')", "a\nb", "O_2"]
SEED = int(os.environ.get("FUZZ_SEED", "25"))
BUDGET = float(os.environ.get("FUZZ_SECONDS", "4"))
MIN_CASES = 12


def mutate(rng: random.Random, data: dict) -> dict:
    data = copy.deepcopy(data)
    for _ in range(rng.randint(1, 3)):
        paths = _paths(data)
        if not paths:
            break
        path = rng.choice(paths)
        parent, key = _parent(data, path), path[-1]
        op = rng.choice(["delete", "duplicate", "rename", "value", "scale", "hostile",
                         "title"])
        if op == "delete":
            del parent[key]
        elif op == "duplicate" and isinstance(parent, list):
            parent.append(copy.deepcopy(parent[key]))
        elif op == "rename" and isinstance(parent, dict):
            parent[rng.choice(NAMES + HOSTILE)] = parent.pop(key)
        elif op == "scale" and isinstance(parent[key], (int, float)) \
                and not isinstance(parent[key], bool):
            parent[key] = parent[key] * rng.choice([1e-12, 1e12, -1, 1e300, 0])
        elif op == "hostile":
            parent[key] = rng.choice(HOSTILE)
        elif op == "title":
            data["title"] = "".join(rng.choice(HOSTILE) for _ in range(3))
        else:
            parent[key] = copy.deepcopy(rng.choice(EXTREMES))
    return data


def _run(argv: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            rc = main(argv)
        except SystemExit as exc:
            rc = int(exc.code or 0)
    return rc, out.getvalue(), err.getvalue()


def test_newer_features_fuzzed_end_cleanly(tmp_path: Path) -> None:
    rng = random.Random(SEED)
    names = sorted(DATA)
    t0, n = time.perf_counter(), 0
    while n < MIN_CASES or time.perf_counter() - t0 < BUDGET:
        name = rng.choice(names)
        data = mutate(rng, DATA[name])
        f = tmp_path / "m.toml"
        f.write_text(dumps(data), encoding="utf-8")
        command = rng.choice([["solve", "--json"], ["sweep", "--count", "4", "--torque"],
                              ["sweep", "--count", "4", "--singular"],
                              ["animate", "--count", "3", "-o", str(tmp_path / "a.html")]])
        rc, out, err = _run([command[0], str(f), *command[1:]])
        case = f"case {n} ({name}, {' '.join(command)}): {err}\n{dumps(data)}"
        assert rc in (0, 2), case
        assert "Traceback" not in err and "cannot handle" not in err, case
        if rc == 2:
            assert len([ln for ln in err.splitlines() if ln.strip()]) == 1, case
        assert " nan " not in out and "nan°" not in out, case
        n += 1


def _design_commands(name: str, tmp: Path) -> list[list[str]]:
    if name.startswith(("ex6", "fig6")):
        return [["cam"], ["cam", "--json"], ["cam", "-o", str(tmp / "c.svg")]]
    if name in ("postures", "function"):
        return [["synthesize"], ["synthesize", "--json"],
                ["synthesize", "-o", str(tmp / "out.toml")]]
    return [["gears"], ["gears", "--json"], ["steps", "-o", str(tmp / "g.html")]]


def test_design_files_fuzzed_end_cleanly(tmp_path: Path) -> None:
    """Cams, gears and synthesis: the same mutations, their own commands, a fixed budget."""
    rng = random.Random(SEED + 1)
    names = sorted(DESIGN)
    t0, n = time.perf_counter(), 0
    while n < MIN_CASES or time.perf_counter() - t0 < BUDGET:
        name = rng.choice(names)
        data = mutate(rng, DESIGN[name])
        f = tmp_path / "d.toml"
        f.write_text(dumps(data), encoding="utf-8")
        command = rng.choice(_design_commands(name, tmp_path))
        (tmp_path / "out.toml").unlink(missing_ok=True)
        rc, out, err = _run([command[0], str(f), *command[1:]])
        case = f"case {n} ({name}, {' '.join(command)}): {err}\n{dumps(data)}"
        assert rc in (0, 2), case
        assert "Traceback" not in err and "cannot handle" not in err, case
        if rc == 2:
            assert len([ln for ln in err.splitlines() if ln.strip()]) == 1, case
        assert " nan " not in out and "nan°" not in out, case
        if rc == 0 and "-o" in command and command[0] == "synthesize":
            rc2, _, err2 = _run(["solve", str(tmp_path / "out.toml")])
            assert rc2 in (0, 2) and "cannot handle" not in err2 and "not valid TOML" \
                not in err2, case + err2
        n += 1
