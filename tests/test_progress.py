"""Progress bars: on a terminal for jobs past a second, never in a pipe or a log."""

from __future__ import annotations

import io

import graphkin
from graphkin import progress
from graphkin.cli import main


class _Tty(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_a_terminal_gets_a_bar_and_a_pipe_does_not(monkeypatch):
    monkeypatch.setattr(progress, "DELAY", 0.0)
    tty = _Tty()
    monkeypatch.setattr("sys.stderr", tty)
    assert progress.enabled()
    with progress.bar("sweep", total=10, unit="posture") as b:
        b.fraction(0.5)
        b.update(5)
    text = tty.getvalue()
    assert "sweep:" in text and "/10 " in text and "posture/s" in text
    pipe = io.StringIO()
    monkeypatch.setattr("sys.stderr", pipe)
    assert not progress.enabled()
    assert list(progress.track(range(3), "gallery", unit="figure")) == [0, 1, 2]
    assert pipe.getvalue() == ""


def test_short_jobs_print_nothing_even_on_a_terminal(monkeypatch):
    tty = _Tty()
    monkeypatch.setattr("sys.stderr", tty)
    with progress.bar("sweep", total=10) as b:  # done well inside DELAY = 1 s
        b.update(10)
    assert tty.getvalue() == ""


def test_sweep_command_writes_the_same_csv_through_the_counting_writer(tmp_path, capsys):
    path = tmp_path / "fourbar.toml"
    path.write_text(graphkin.examples.text("fourbar"), encoding="utf-8")
    out = tmp_path / "out.csv"
    assert main(["sweep", str(path), "--count", "50", "--csv", str(out)]) == 0
    expect = graphkin.load(path).sweep(count=50).csv_text()
    assert out.read_text(encoding="utf-8") == expect
    assert main(["sweep", str(path), "--count", "50"]) == 0
    captured = capsys.readouterr()
    assert captured.out == expect
    assert "%|" not in captured.err  # captured output is no terminal: no bar


def test_counting_writer_counts_rows():
    fh = io.StringIO()
    with progress.bar("rows", total=5, show=False) as b:
        w = progress.CountingWriter(fh, b, every=2)
        for i in range(5):
            w.write(f"{i}\n")
        w.flush()
    assert fh.getvalue() == "0\n1\n2\n3\n4\n"
