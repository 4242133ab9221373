"""The teaching page: structure, equations with ✓/? marks, frames, and a real headless browser."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from spec_data import EXAMPLES

from graphkin.cli import main
from graphkin.render.teach import steps_html, write_frames

NAME = "ex2_5_open"  # the smallest construction (Example 2.5: two arcs, case 4)


@pytest.fixture(scope="module")
def page(gk) -> str:
    return steps_html(gk.solved(NAME), "posture")


def test_one_section_per_step_with_its_drawing(gk, page):
    cx = gk.solved(NAME).constructions["posture"]
    found = [int(k) for k in re.findall(r'<section class="step"[^>]*data-step="(\d+)"', page)]
    assert found == [s.index for s in cx]
    # each frame's ids are prefixed so that the frames can share the page
    for s in cx:
        assert f'id="f{s.index:02d}-{s.step_id}"' in page
    assert len(re.findall(r"<svg[\s>]", page)) == len(cx)


def test_equations_show_the_marks_and_the_notes(gk, page):
    cx = gk.solved(NAME).constructions["posture"]
    step = next(s for s in cx if s.equation is not None and s.equation.case == 4)
    # case 4 (Table 2.2): both directions unknown, R_BA(✓?) = R_BO4(✓?)
    assert "✓?" in page and "(case 4)" in page
    assert step.note in page


def test_page_is_self_contained(page):
    assert not re.search(r'\b(src|href)="(https?:)?//', page)
    assert "<script src" not in page and "<link " not in page


def test_frames_are_numbered_svgs(gk, tmp_path):
    paths = write_frames(gk.solved(NAME), "posture", tmp_path / "frames")
    cx = gk.solved(NAME).constructions["posture"]
    assert [p.name for p in paths] == [f"step-{k:02d}.svg" for k in range(len(cx))]
    last = ET.parse(paths[-1]).getroot()
    ids = {el.get("id") for el in last.iter()}
    assert {s.step_id for s in cx} <= ids
    first = {el.get("id") for el in ET.parse(paths[0]).getroot().iter()}
    assert cx[0].step_id in first and cx[-1].step_id not in first


def test_cli_steps_writes_the_page(tmp_path, gk):
    out = tmp_path / "p.html"
    assert main(["steps", str(EXAMPLES / f"{NAME}.toml"), "-o", str(out)]) == 0
    assert out.read_text(encoding="utf-8").count('<section class="step"') == len(
        gk.solved(NAME).constructions["posture"])


def _chromium() -> str | None:
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def test_page_runs_in_headless_chromium(tmp_path, page, gk):
    exe = _chromium()
    if exe is None:
        pytest.skip("chromium is not installed")
    html_file = tmp_path / "page.html"
    html_file.write_text(page, encoding="utf-8")
    cmd = [exe, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
           "--disable-background-networking", "--disable-component-update", "--disable-sync",
           f"--user-data-dir={tmp_path / 'profile'}", "--enable-logging=stderr", "--v=0",
           "--dump-dom", html_file.as_uri() + "#selftest"]
    run = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stderr[-2000:]
    m = re.search(r'<pre id="selftest-result">(.*?)</pre>', run.stdout, re.S)
    assert m, "the page's self-test did not run"
    result = json.loads(m.group(1).replace("&quot;", '"'))
    n = len(gk.solved(NAME).constructions["posture"])
    assert result["steps"] == n
    assert result["forward"] == list(range(n))  # "next" visits every step in order
    assert result["back"] == list(range(n - 2, -1, -1))  # the left arrow walks back
    assert result["prevDisabled"] is True
    assert result["errors"] == []
    assert "Uncaught" not in run.stderr
    assert Path(html_file).exists()
