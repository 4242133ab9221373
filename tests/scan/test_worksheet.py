"""``graphkin worksheet``: the sheet's layout, markers and identity.

The markers' bit patterns are compared with OpenCV's own dictionary; the
scale is checked against its definition (the smallest round scale at which
the polygon and its 180° turn fit around the pole), not against a number the
code printed.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.cli import main
from graphkin.render.worksheet_layout import (
    ARUCO_4X4_50,
    MAX_UPTO,
    _round_up,
    corner_ids,
    decode_ids,
    marker_bits,
    worksheet_layout,
)


def test_marker_bits_are_opencvs_dict_4x4_50() -> None:
    cv2 = pytest.importorskip("cv2")
    d = cv2.aruco.getPredefinedDictionary(cv2.aruco.DICT_4X4_50)
    assert len(ARUCO_4X4_50) == 50
    for i in range(50):
        img = cv2.aruco.generateImageMarker(d, i, 6)       # 6 x 6 cells, 1 px each
        assert np.array_equal(marker_bits(i), (img == 0).astype(int)), i


def test_marker_ids_say_diagram_paper_and_steps() -> None:
    seen = set()
    for diagram in ("velocity", "acceleration"):
        for paper in ("a4", "letter"):
            ids = corner_ids(diagram, paper)
            assert not seen & set(ids)
            seen |= set(ids)
            for k in (0, 5, MAX_UPTO):
                assert decode_ids([ids[2], 16 + k, ids[0]]) == (diagram, paper, k)
            assert decode_ids(list(ids[:3])) == (diagram, paper, None)
    assert seen == set(range(16))
    assert decode_ids([40, 49]) is None


@pytest.mark.parametrize("x,want", [(6.5, 8.0), (8.0, 8.0), (0.0123, 0.015), (101.0, 150.0),
                                    (7.9, 8.0), (1.0, 1.0)])
def test_round_scales(x: float, want: float) -> None:
    assert math.isclose(_round_up(x), want)


@pytest.mark.parametrize("diagram", ["velocity", "acceleration"])
@pytest.mark.parametrize("paper", ["a4", "letter"])
def test_the_polygon_fits_at_the_smallest_round_scale(diagram: str, paper: str) -> None:
    sol = graphkin.examples.fourbar().solve()
    lay = worksheet_layout(sol, diagram, paper, "0" * 10)
    f = sol.velocity if diagram == "velocity" else sol.acceleration
    vec = np.array([f(n) for n in sol.mechanism.point_names])
    x0, y0, x1, y1 = lay.polygon_box
    px, py = lay.pole

    def fits(k: float) -> bool:
        # the polygon and the polygon turned 180° within 44 % of the area's sides of the pole
        return bool(np.all(np.abs(vec[:, 0]) / k <= 0.44 * (x1 - x0) * (1 + 1e-9))
                    and np.all(np.abs(vec[:, 1]) / k <= 0.44 * (y1 - y0) * (1 + 1e-9)))

    # round scales: 1, 1.5, 2, 2.5, 3, 4, 5, 6, 8 times a power of ten
    rounds = sorted(r * 10.0**e for r in (1, 1.5, 2, 2.5, 3, 4, 5, 6, 8) for e in range(-3, 8))
    assert any(math.isclose(lay.per_mm, r) for r in rounds)
    assert fits(lay.per_mm)
    assert not fits(max(r for r in rounds if r < lay.per_mm * (1 - 1e-9)))
    # the pole in the middle of the area, inside the paper, clear of the markers
    assert (px, py) == ((x0 + x1) / 2, (y0 + y1) / 2)
    w, h = lay.size
    for _, mx, my in lay.markers:
        assert 0 < mx and mx + 18 < w and 0 < my and my + 18 < h
        assert not (x0 < mx + 18 and mx < x1 and y0 < my + 18 and my < y1)


def test_worksheet_pdf_carries_its_identity(tmp_path: Path, examples: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    pdfium = pytest.importorskip("pypdfium2")
    out = tmp_path / "sheet.pdf"
    src = examples / "ex3_1_fourbar.toml"
    assert main(["worksheet", str(src), "-d", "velocity", "-o", str(out)]) == 0
    doc = pdfium.PdfDocument(str(out))
    assert len(doc) == 1
    w, h = doc[0].get_size()                       # points: A4 = 595.3 x 841.9
    assert math.isclose(w, 210 / 25.4 * 72, abs_tol=0.5)
    assert math.isclose(h, 297 / 25.4 * 72, abs_tol=0.5)
    ident = json.loads(doc.get_metadata_dict()["Subject"])
    import hashlib

    assert ident["digest"] == hashlib.sha256(src.read_bytes()).hexdigest()[:10]
    assert ident["diagram"] == "velocity" and ident["paper"] == "a4"
    # the scale printed: 1 mm stands for per_mm in/s
    assert ident["scale_text"] == f"1 mm = {ident['per_mm']:.6g} in/s"
    assert "wrote" in capsys.readouterr().err


def test_worksheet_upto_prints_steps_and_says_so(tmp_path: Path, examples: Path) -> None:
    out = tmp_path / "sheet.svg"
    assert main(["worksheet", str(examples / "ex3_1_fourbar.toml"), "-d", "acceleration",
                 "--sheet", "letter", "--upto", "3", "-o", str(out)]) == 0
    text = out.read_text()
    assert 'id="marker-19"' in text                # 16 + 3
    assert 'id="marker-12"' in text                # acceleration on letter: corner ids 12-15
    assert "steps 0-2 given" in text


@pytest.mark.parametrize("argv,words", [
    (["-d", "velocity", "-o", "x.txt"], "write the worksheet to a .pdf, .png or .svg"),
    (["-d", "velocity", "-o", "x.pdf", "--upto", "40"], "between 0 and 33"),
])
def test_worksheet_errors_are_one_line(tmp_path: Path, examples: Path, argv: list[str],
                                       words: str, capsys: pytest.CaptureFixture[str]) -> None:
    argv = [a if not a.startswith("x.") else str(tmp_path / a) for a in argv]
    with pytest.raises(SystemExit) if "--upto" in argv else _nothing():
        code = main(["worksheet", str(examples / "ex3_1_fourbar.toml"), *argv])
        assert code == 2
    err = capsys.readouterr().err
    assert words in err
    assert "Traceback" not in err


def test_worksheet_needs_rates(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    src = tmp_path / "norates.toml"
    src.write_text('[links.1]\nA = [0, 0]\nD = [4, 0]\n[links.2]\nA = [0, 0]\nB = [1, 0]\n'
                   '[links.3]\nB = [0, 0]\nC = [4, 0]\n[links.4]\nD = [0, 0]\nC = [3, 0]\n'
                   '[drive]\nlink = 2\nangle = 60\n')
    assert main(["worksheet", str(src), "-d", "velocity", "-o", str(tmp_path / "s.pdf")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "no rates" in err


class _nothing:
    def __enter__(self) -> None:
        return None

    def __exit__(self, *exc: object) -> None:
        return None


def test_worksheet_states_the_given_rates(tmp_path: Path, examples: Path) -> None:
    # a polygon cannot be drawn without the input's rates: Example 3.1 gives
    # ω2 = 900 rev/min ccw = 900 · 2π/60 = 94.2478 rad/s, and α2 = 0 for the acceleration
    out = tmp_path / "sheet.svg"
    assert main(["worksheet", str(examples / "ex3_1_fourbar.toml"), "-d", "acceleration",
                 "--sheet", "a4", "-o", str(out)]) == 0
    text = out.read_text()
    assert "Given ω₂ = 94.2478 rad/s ccw, α₂ = 0 rad/s²." in text
    out_v = tmp_path / "v.svg"
    assert main(["worksheet", str(examples / "ex3_1_fourbar.toml"), "-d", "velocity",
                 "-o", str(out_v)]) == 0
    text = out_v.read_text()
    assert "Given ω₂ = 94.2478 rad/s ccw." in text and "α₂" not in text
    assert "from O_V" not in text                    # the pole typeset, not a raw name


def test_worksheet_states_a_slider_drive_in_the_books_words(tmp_path: Path,
                                                             examples: Path) -> None:
    """A slider-driven file gives the slider point's velocity, as the book states it.

    Example 3.2 (p. 3272 of the text): "driven by slider 4 at a constant velocity
    V_C = -10 î m/s": in mm (the file's unit) 10000 mm/s pointing along -x, ∠180°,
    and A_C = 0 (constant velocity).  It used to say "Given ds4 = -10000 mm/s",
    the project's own symbol.  On a moving link (Example 4.4: "the block (link 3)
    is sliding outward on link 2 at 30 m/s", link 2 at 30°) it is the velocity
    relative to that link, V_A3/2 (Sec. 3.5), along the rod at 30°.
    """
    out = tmp_path / "sheet.svg"
    assert main(["worksheet", str(examples / "ex3_2_slider_driven.toml"), "-d", "acceleration",
                 "-o", str(out)]) == 0
    text = out.read_text()
    assert "Given V_C = 10000 mm/s ∠180.00°, A_C = 0 mm/s²." in text
    assert "ds4" not in text
    out = tmp_path / "block.svg"
    assert main(["worksheet", str(examples / "ex4_4_coriolis_block.toml"), "-d", "velocity",
                 "-o", str(out)]) == 0
    text = out.read_text()
    assert "V_A3/2 = 30000 mm/s ∠30.00°" in text and "ds3" not in text
    # the same rates given in [rates] of the slider, not in [drive]: the same words
    spec = (examples / "ex3_2_slider_driven.toml").read_text()
    for key in ('velocity = "-10 m/s"', "acceleration = 0"):
        spec = spec.replace(key + "\n", "")
    spec += '\n[rates]\nlink = 4\nvelocity = "-10 m/s"\nacceleration = 0\n'
    (tmp_path / "rates.toml").write_text(spec)
    assert main(["worksheet", str(tmp_path / "rates.toml"), "-d", "acceleration",
                 "-o", str(tmp_path / "rates.svg")]) == 0
    assert "Given V_C = 10000 mm/s ∠180.00°, A_C = 0 mm/s²." in (tmp_path / "rates.svg").read_text()
