"""Every hostile reproducer of issue 14, run through the command line in-process.

Each file in ``tests/data/hostile/`` must end cleanly with every command:
exit status 0, or 2 with exactly one line on standard error; never a
traceback, never a warning line, never a NaN or infinity printed.  The files
that must be refused say why in their one line (checked below for a few).
"""

from __future__ import annotations

import contextlib
import io
import os
from pathlib import Path

import pytest

from graphkin.cli import main

HOSTILE = Path(__file__).parent.parent / "data" / "hostile"
FILES = sorted(HOSTILE.glob("*.toml"))


def run(argv: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            rc = main(argv)
        except SystemExit as exc:  # argparse
            rc = int(exc.code or 0)
    return rc, out.getvalue(), err.getvalue()


def assert_clean(rc: int, out: str, err: str) -> None:
    assert "Traceback" not in err and "Warning" not in err, err
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert rc in (0, 2), (rc, err)
    if rc == 2:
        assert len(lines) == 1 and lines[0].startswith("graphkin: "), err
    for bad in (" nan", "nan°", "+inf", "-inf", " inf "):
        assert bad not in out.lower(), out
    assert "\x1b" not in out + err and "\x07" not in out + err


COMMANDS = [["solve"], ["solve", "--json"], ["solve", "--steps"],
            ["sweep", "--count", "6", "--csv", "{tmp}/out.csv"],
            ["steps", "-o", "{tmp}/out.html"]]


@pytest.mark.parametrize("path", FILES, ids=[p.stem for p in FILES])
@pytest.mark.parametrize("command", COMMANDS, ids=lambda c: " ".join(c[:2]))
def test_every_hostile_file_ends_cleanly(path: Path, command: list[str], tmp_path: Path) -> None:
    argv = [command[0], str(path), *(a.format(tmp=tmp_path) for a in command[1:])]
    assert_clean(*run(argv))


@pytest.mark.parametrize("name,reason", [
    ("big_int_coordinate", "links.1.D: a coordinate too large"),
    ("big_int_rate", "drive.omega: a number too large"),
    ("power_tower_rate", "drive.omega: cannot read '9**9**9 rad/s'"),
    ("power_tower_unit", "units.length"),
    ("coordinates_1e200", "not supported"),
    ("nested_arrays", "nested too deep"),
    ("rolling_assembly_not_table", "assembly: expected a table"),
])
def test_refusals_name_the_key_and_the_reason(name: str, reason: str) -> None:
    rc, _, err = run(["solve", str(HOSTILE / f"{name}.toml")])
    assert rc == 2 and reason in err, err


def test_control_characters_in_a_title_are_shown_escaped() -> None:
    rc, out, _ = run(["solve", str(HOSTILE / "title_escape.toml")])
    # the title starts with ESC ] 0 ; owned BEL (which would retitle the terminal)
    assert rc == 0 and out.startswith("\\u001b]0;owned\\u0007")


@pytest.mark.parametrize("special", ["/dev/zero", "/dev/urandom", "folder", "fifo", "huge"])
def test_files_that_are_not_small_regular_files(special: str, tmp_path: Path) -> None:
    if special == "folder":
        path = str(tmp_path)
    elif special == "fifo":
        path = str(tmp_path / "pipe.toml")
        os.mkfifo(path)  # no writer: reading it would block for ever
    elif special == "huge":
        path = str(tmp_path / "huge.toml")
        with open(path, "wb") as fh:
            fh.truncate(21 * 1024 * 1024)  # sparse: 21 MB of NUL bytes
    else:
        path = special
        if not Path(path).exists():
            pytest.skip(f"{path} does not exist here")
    for cmd in (["solve", path], ["vector", path], ["check", path, path]):
        rc, out, err = run(cmd)
        assert_clean(rc, out, err)
        assert rc == 2 and ("not a regular file" in err or "too large" in err), err


@pytest.mark.parametrize("argv,option", [
    (["draw", "{f}", "-o", "{tmp}/x.png", "--dpi", "0"], "--dpi"),
    (["draw", "{f}", "-o", "{tmp}/x.png", "--dpi", "nan"], "--dpi"),
    (["draw", "{f}", "-o", "{tmp}/x.png", "--dpi", "5000"], "--dpi"),
    (["sweep", "{f}", "--count", "1e8"], "--count"),
    (["sweep", "{f}", "--count", "100000000"], "--count"),
    (["sweep", "{f}", "--from", "nan"], "--from"),
    (["plot", "{f}", "-o", "{tmp}/x.svg", "--to", "inf"], "--to"),
])
def test_bad_options_are_one_line(argv: list[str], option: str, tmp_path: Path) -> None:
    f = HOSTILE / "sweep_like.toml"
    rc, out, err = run([a.format(f=f, tmp=tmp_path) for a in argv])
    assert_clean(rc, out, err)
    assert rc == 2 and option in err


@pytest.mark.parametrize("argv,option", [
    (["steps", "{f}", "-o", "{f}"], "--output"),
    (["sweep", "{f}", "--count", "4", "--csv", "{f}"], "--csv"),
    (["draw", "{f}", "-o", "{link}"], "--output"),
])
def test_outputs_never_overwrite_the_input(argv: list[str], option: str, tmp_path: Path) -> None:
    f = tmp_path / "m.toml"
    text = (HOSTILE / "sweep_like.toml").read_text(encoding="utf-8")
    f.write_text(text, encoding="utf-8")
    link = tmp_path / "same.svg"
    os.link(f, link)  # the same file under another name
    rc, out, err = run([a.format(f=f, link=link) for a in argv])
    assert_clean(rc, out, err)
    assert rc == 2 and option in err and "input file" in err
    assert f.read_text(encoding="utf-8") == text


def test_dxf_is_byte_identical(tmp_path: Path) -> None:
    pytest.importorskip("ezdxf")
    f = HOSTILE / "sweep_like.toml"
    outs = []
    for k in range(2):
        out = tmp_path / f"p{k}.dxf"
        rc, _, err = run(["draw", str(f), "-d", "velocity", "-o", str(out)])
        assert rc == 0, err
        outs.append(out.read_bytes())
    assert outs[0] == outs[1]
