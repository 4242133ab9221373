"""``graphkin check FILE --scan ...``: the command line, a class PDF, the debug image, errors."""

from __future__ import annotations

import csv
import io
import sys
from pathlib import Path

import numpy as np
import pytest

from graphkin.cli import main


def test_without_opencv_one_line(tmp_path: Path, examples: Path,
                                 capsys: pytest.CaptureFixture[str],
                                 monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "cv2", None)          # import cv2 -> ImportError
    photo = tmp_path / "p.jpg"
    photo.write_bytes(b"not read")
    assert main(["check", str(examples / "ex3_1_fourbar.toml"), "--scan", str(photo)]) == 2
    assert capsys.readouterr().err == \
        'graphkin: --scan needs OpenCV: pip install "graphkin[scan]"\n'


def test_a_class_pdf_one_report_per_page(tmp_path: Path, examples: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    cv2 = pytest.importorskip("cv2")
    pytest.importorskip("pypdfium2")
    from scan.photos import class_pdf, exact_images, hand_photo, layout_for, sheet_pixels

    import graphkin

    src = examples / "ex3_1_fourbar.toml"
    sol = graphkin.load(src).solve()
    lay = layout_for(sol, "velocity", src.read_text())
    sheet = sheet_pixels(sol, lay)
    right = exact_images(sol, lay)
    pole = np.array(lay.pole)
    reversed_ = {n: 2 * pole - p for n, p in right.items()}
    blank = np.full((1400, 1000), 235, np.uint8)           # a page with no worksheet on it
    pdf = tmp_path / "class.pdf"
    class_pdf(pdf, [hand_photo(sol, lay, sheet, right, "mild", 1),
                    hand_photo(sol, lay, sheet, reversed_, "scan", 2), blank])
    jpg = tmp_path / "one.jpg"
    cv2.imwrite(str(jpg), hand_photo(sol, lay, sheet, right, "phone", 3))
    out = tmp_path / "marks.csv"
    show = tmp_path / "seen.png"
    code = main(["check", str(src), "--scan", str(pdf), str(jpg), "--csv", str(out),
                 "--show", str(show)])
    err = capsys.readouterr().err
    assert code == 2                                       # the blank page is unreadable
    assert "class.pdf p.3: --scan: no graphkin worksheet markers found" in err
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    assert [r["file"] for r in rows] == [f"{pdf} p.1", f"{pdf} p.2", f"{pdf} p.3", str(jpg)]
    assert [r["V_B"] for r in rows] == ["ok", "WRONG", "", "ok"]
    assert rows[1]["V_B mistake"] == "sense"
    assert rows[0]["score_percent"] == rows[3]["score_percent"] == "100"
    # one debug image per page read: the rectified A4 sheet at 5 px/mm
    for k in (1, 2, 4):
        img = cv2.imread(str(tmp_path / f"seen-{k}.png"))
        assert img.shape[:2] == (1485, 1050)
    assert not (tmp_path / "seen-3.png").exists()


def test_scan_errors_are_one_line(tmp_path: Path, examples: Path,
                                  capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("cv2")
    src = str(examples / "ex3_1_fourbar.toml")
    bad = tmp_path / "notes.txt"
    bad.write_text("hello")
    assert main(["check", src, "--scan", str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.strip().count("\n") == 0 and "not an image" in err
    assert main(["check", src, "--scan", str(tmp_path / "missing.jpg")]) == 2
    assert "no such file" in capsys.readouterr().err
    answers = tmp_path / "a.toml"
    answers.write_text('omega2 = "900 rev/min ccw"\n')
    assert main(["check", src, str(answers), "--show", str(tmp_path / "s.png")]) == 2
    assert capsys.readouterr().err == \
        "graphkin: --show: --show draws what --scan read: give --scan PHOTO\n"


def test_the_worksheet_pdf_itself_knows_its_mechanism(tmp_path: Path, examples: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    # graphkin worksheet's own PDF (filled in on a tablet, say) carries the file's hash
    pytest.importorskip("cv2")
    pytest.importorskip("pypdfium2")
    src = examples / "ex3_1_fourbar.toml"
    other = tmp_path / "other.toml"
    other.write_text(src.read_text() + "\n# another file\n")
    sheet = tmp_path / "sheet.pdf"
    assert main(["worksheet", str(src), "-d", "velocity", "-o", str(sheet)]) == 0
    capsys.readouterr()
    assert main(["check", str(other), "--scan", str(sheet)]) == 2
    err = capsys.readouterr().err
    assert err.startswith(f"graphkin: {sheet}: --scan: this worksheet was printed for another "
                          "mechanism file")
    # the same file: nothing drawn yet, every image not found
    assert main(["check", str(src), "--scan", str(sheet), "--quiet"]) == 1
    assert "4 wrong (V_B: not-found; V_C: not-found; V_E: not-found; V_F: not-found)" in \
        capsys.readouterr().out
