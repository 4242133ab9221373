"""The documentation tells the truth: its files load, its numbers hold, it names no outside path."""

from __future__ import annotations

import math
import re
import tomllib
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.cli import main
from graphkin.keys import SYNTHESIS as _SYNTHESIS
from graphkin.keys import VECTOR, check_keys

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
PAGES = sorted(DOCS.rglob("*.md"))
BLOCK = re.compile(r"```toml\n(.*?)```", re.DOTALL)


def _toml_blocks():
    for page in PAGES:
        for k, block in enumerate(BLOCK.findall(page.read_text(encoding="utf-8"))):
            if "--8<--" not in block:
                yield pytest.param(page, block, id=f"{page.relative_to(DOCS)}#{k}")


@pytest.mark.parametrize("page,block", list(_toml_blocks()))
def test_every_toml_example_in_the_docs_is_valid(page, block):
    data = tomllib.loads(block)          # TOML at all
    if "gears" in data and "links" not in data:
        from graphkin.gears.file import from_dict as gears_from_dict

        gears_from_dict(data, source=str(page))     # a whole gear file: it loads
    elif "mesh" in data and "links" not in data:
        from graphkin.gears.train_file import train_from_dict

        train_from_dict(data, source=str(page))     # a whole gear-train file: it loads
    elif "links" in data and "1" in data["links"] and "drive" in data:
        graphkin.from_dict(data, source=str(page))   # a whole mechanism: it loads
    elif set(data) & {"cam", "follower", "segment"}:
        from graphkin.keys import CAM

        check_keys(data, CAM, str(page))           # a cam file or a fragment of one
        if {"cam", "follower", "segment"} <= set(data):
            from graphkin.cams.parse import loads_cam

            loads_cam(block, str(page))            # a whole cam file: it loads
    elif set(data) & (set(_SYNTHESIS) - {"title", "units", "gallery"}):
        from graphkin.keys import SYNTHESIS

        check_keys(data, SYNTHESIS, str(page))      # a synthesis file (docs/formats/synthesis.md)
    elif set(data) & {"A", "B", "C"}:
        check_keys(data, VECTOR, str(page))
    elif "links" not in data and any(k in data for k in ("omega3", "theta3", "V_E",
                                                          "tolerance", "student")):
        # answers files (their keys are checked in tests/check): the tolerance table parses
        if "tolerance" in data:
            from graphkin.check.answers import CheckTolerance

            CheckTolerance.parse(data["tolerance"], file=str(page))
    else:
        # a fragment of a mechanism file: every key is one the format knows
        from graphkin.keys import MECHANISM

        check_keys(data, MECHANISM, str(page))


@pytest.mark.parametrize("path", sorted(DOCS.rglob("*.toml")), ids=lambda p: p.name)
def test_tutorial_files_solve(path):
    sol = graphkin.load(path).solve()
    assert sol.method == "construction"


def test_tutorial_slider_crank_against_the_hand_derivation():
    # in-line slider-crank, r = 2 in, l = 8 in, θ2 = 60°, ω2 = 1800 rev/min ccw:
    # sin θ3 = -r sin θ2 / L (C on the line through A); V_C = -r ω2 sin(θ2 - θ3) / cos θ3
    sol = graphkin.load(DOCS / "tutorial" / "slider_crank.toml").solve()
    th2, r, rod, w2 = math.radians(60), 2.0, 8.0, 1800 * 2 * math.pi / 60
    th3 = -math.asin(r * math.sin(th2) / rod)
    assert float(sol.angle(3)) == pytest.approx(math.degrees(th3), abs=1e-9)
    vc = -r * w2 * math.sin(th2 - th3) / math.cos(th3)
    np.testing.assert_allclose(sol.velocity("C"), [vc, 0.0], atol=1e-9 * abs(vc))
    assert abs(vc) == pytest.approx(368.29, abs=0.01)   # the number the tutorial prints


def test_tutorial_quick_return_limit_positions(tmp_path, capsys):
    # the lever stops where the crank O2B is perpendicular to O4B: sin φ = |O2B| / |O2O4|
    # = 2/4, so θ4 = 90° ∓ 30° at θ2 = 330° and 210° (crank perpendicular to the lever)
    path = DOCS / "tutorial" / "quick_return.toml"
    code = main(["sweep", str(path), "--count", "3600", "--singular",
                 "--csv", str(tmp_path / "c.csv")])
    assert code == 0
    err = capsys.readouterr().err
    assert "limit position of link 4 (ω4 = 0) at drive 210.00°, θ4 = 120.00°" in err
    assert "limit position of link 4 (ω4 = 0) at drive 330.00°, θ4 = 60.00°" in err


def test_no_file_names_a_path_outside_the_repository():
    # the repository is self-contained: no folder beside it, no absolute machine paths
    # (.ci/run alone may run a checker of the folder beside the clone when it is there)
    outside = [".." + "/shared", "shared" + "/spec", "shared" + "/tools", "/" + "work/"]
    skip = {".git", ".venv", "site", "build", "dist", "__pycache__", ".hypothesis",
            ".benchmarks", ".pytest_cache", ".ruff_cache", ".mypy_cache"}
    bad = []
    for path in ROOT.rglob("*"):
        rel = path.relative_to(ROOT)
        if any(part in skip or part.endswith(".egg-info") for part in rel.parts):
            continue
        if rel.as_posix() == ".ci/run":
            continue
        if not path.is_file() or path.suffix in {".png", ".pdf", ".gz", ".whl"}:
            continue
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        for needle in outside:
            if needle in text:
                bad.append(f"{rel}: {needle}")
    assert not bad, bad


def test_every_command_is_in_the_cli_reference():
    import pkgutil

    import graphkin.commands as commands

    page = (DOCS / "reference" / "cli.md").read_text(encoding="utf-8")
    for info in pkgutil.iter_modules(commands.__path__):
        # gallery is a maintainers' command (docs/maintainers.md); _args and the like are helpers
        if info.name not in {"gallery"} and not info.name.startswith("_"):
            assert f"`graphkin {info.name}" in page, info.name


def test_every_command_the_docs_name_exists():
    # audit9: docs/forces.md sent the reader to `graphkin forces`, which is no command
    # (the force analysis is part of `graphkin solve`)
    import pkgutil

    import graphkin.commands as commands

    verbs = {i.name for i in pkgutil.iter_modules(commands.__path__)}
    named = re.compile(r"`graphkin ([a-z][a-z_-]*)")
    bad = [f"{page.relative_to(ROOT)}: graphkin {verb}"
           for page in [*PAGES, ROOT / "README.md"]
           for verb in named.findall(page.read_text(encoding="utf-8")) if verb not in verbs]
    assert not bad, bad
