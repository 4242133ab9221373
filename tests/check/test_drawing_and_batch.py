"""Drawn polygons (DXF round trip, a hand-made SVG) and batch marking to CSV."""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.check.drawing import check_drawing
from graphkin.cli import main
from graphkin.kinematics.analytic import solve_analytic

REPO = Path(__file__).resolve().parents[2]
ANSWERS = REPO / "examples" / "answers"


@pytest.fixture
def fourbar(examples: Path) -> Path:
    return examples / "ex3_1_fourbar.toml"


# ---- DXF round trip ---------------------------------------------------------------

@pytest.mark.parametrize("diagram", ["velocity", "acceleration"])
def test_dxf_round_trip_is_exact(fourbar: Path, tmp_path: Path, diagram: str,
                                 capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("ezdxf")
    from graphkin.io.dxf import write_dxf

    mech = graphkin.load(fourbar)
    sol = mech.solve()
    out = write_dxf(sol, diagram, tmp_path / f"{diagram}.dxf")
    assert main(["check", str(fourbar), "--drawing", str(out)]) == 0
    capsys.readouterr()
    rep = check_drawing(sol, out)
    assert [r.key for r in rep.rows] == ([f"{diagram[0].upper()}_{p}" for p in "BCEF"])
    # every image point comes back where the analytic solver puts it (to round-off)
    an = solve_analytic(mech)
    exact = an.velocity if diagram == "velocity" else an.acceleration
    for r in rep.rows:
        assert r.verdict == "ok"
        p = r.key[2:]
        mag = float(r.given.split()[0])
        assert mag == pytest.approx(math.hypot(*exact(p)), rel=1e-3)
        assert float(r.error.split("; ")[1].split()[0]) < 1e-6


def test_dxf_labels_the_point_of_the_slotted_link(examples: Path, tmp_path: Path) -> None:
    # Example 3.3 (inverted slider): A of crank 2 and the coincident point A4 of rod 4.
    # The DXF labelled v(A@4) nothing, so the image a4 was not marked at all (audit9);
    # docs/checking.md reads "a4" as the point of link 4 at A: V_A4 = ω4 × R_AD.
    pytest.importorskip("ezdxf")
    from graphkin.io.dxf import write_dxf

    f = examples / "ex3_3_inverted_slider.toml"
    mech = graphkin.load(f)
    sol = mech.solve()
    an = solve_analytic(mech)
    r = np.asarray(an.position("A")) - np.asarray(an.position("D"))
    v_a4 = math.hypot(*r) * abs(float(an.omega("4")))
    rep = check_drawing(sol, write_dxf(sol, "velocity", tmp_path / "v.dxf"))
    rows = {r.key: r for r in rep.rows}
    assert "V_A4" in rows and rows["V_A4"].verdict == "ok"
    assert float(rows["V_A4"].given.split()[0]) == pytest.approx(v_a4, rel=1e-3)
    rep = check_drawing(sol, write_dxf(sol, "acceleration", tmp_path / "a.dxf"))
    assert {"A_A", "A_A4"} <= {r.key for r in rep.rows}


def test_started_drawing_has_only_the_first_steps(fourbar: Path, tmp_path: Path) -> None:
    pytest.importorskip("ezdxf")
    from graphkin.io.dxf import read_dxf, write_dxf

    sol = graphkin.load(fourbar).solve()
    full = read_dxf(write_dxf(sol, "velocity", tmp_path / "v.dxf"))
    start = read_dxf(write_dxf(sol, "velocity", tmp_path / "v3.dxf", upto=3))
    # steps 0-3 of Example 3.1's velocity construction: O_V, ω1, ω2, and v(B)
    assert sorted(t for t, _ in start.labels) == ["O_V", "b"]
    assert sorted(t for t, _ in full.labels) == ["O_V", "b", "c", "e", "f"]
    assert full.scale == start.scale == "1 in = 50 in/s"
    post = read_dxf(write_dxf(sol, "posture", tmp_path / "p.dxf"))
    assert {"A", "B", "C", "D", "E", "F"} <= {t for t, _ in post.labels}


def test_unreadable_drawing_exits_2(fourbar: Path, tmp_path: Path,
                                    capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "x.svg"
    bad.write_text("<svg><line")
    assert main(["check", str(fourbar), "--drawing", str(bad)]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
    assert main(["check", str(fourbar), "--drawing", str(tmp_path / "x.png")]) == 2
    capsys.readouterr()


# ---- an SVG drawn by hand, turned and scaled, with one image flipped ----------------------

def _svg(points: dict[str, np.ndarray], scale: str | None, off: float = 0.05) -> str:
    lines, texts = [], []
    o = points.pop("O_V")
    for name, p in points.items():
        # SVG's y axis points down
        lines.append(f'<line x1="{o[0]}" y1="{-o[1]}" x2="{p[0]}" y2="{-p[1]}"/>')
        texts.append(f'<text x="{p[0] + off}" y="{-p[1] - off}">{name}</text>')
    texts.append(f'<text x="{o[0] - off}" y="{-o[1] + off}">O<tspan>_V</tspan></text>')
    if scale:
        texts.append(f'<text x="0" y="0">Scale: {scale}</text>')
    body = "\n".join(lines + texts)
    return ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">'
            f'<g transform="translate(50, 50)">{body}</g></svg>')


def test_svg_fitted_to_the_crank_and_flipped_image_named(fourbar: Path, tmp_path: Path) -> None:
    mech = graphkin.load(fourbar)
    an = solve_analytic(mech)
    # the polygon drawn at 1 unit = 20 in/s, turned 30° ccw, the pole at (3, 4)
    turn = np.array([[math.cos(math.pi / 6), -math.sin(math.pi / 6)],
                     [math.sin(math.pi / 6), math.cos(math.pi / 6)]])

    def draw(v: np.ndarray) -> np.ndarray:
        return np.array([3.0, 4.0]) + turn @ (np.asarray(v) / 20.0)

    # E flipped about bc: the velocity of the mirror point E' = (10, +4) of link 3
    # (see test_textbook.test_velocity_image_flipped for the hand value 42.67 ft/s).
    th3 = float(an.angle_rad("3"))
    r = np.array([10 * math.cos(th3) - 4 * math.sin(th3), 10 * math.sin(th3) + 4 * math.cos(th3)])
    v_e_flipped = an.velocity("B") + float(an.omega("3")) * np.array([-r[1], r[0]])
    assert math.hypot(*v_e_flipped) / 12 == pytest.approx(42.67, rel=1e-3)
    pts = {"O_V": draw([0, 0]), "b": draw(an.velocity("B")), "c": draw(an.velocity("C")),
           "e": draw(v_e_flipped), "f": draw(an.velocity("F"))}
    svg = tmp_path / "v.svg"
    svg.write_text(_svg(pts, None))
    rep = check_drawing(mech.solve(), svg)
    rows = {r.key: r for r in rep.rows}
    assert rows["V_B"].verdict == "ok"       # fitted by least squares over b, c, f
    assert rows["V_C"].verdict == "ok" and rows["V_F"].verdict == "ok"
    assert rows["V_E"].verdict == "WRONG" and rows["V_E"].mistake.kind == "flipped"
    assert "turned +30.00°" not in rep.title  # the fit turns the drawing back by -30°
    assert "turned -30.00°" in rep.title


def test_svg_with_stated_scale(fourbar: Path, tmp_path: Path,
                               capsys: pytest.CaptureFixture[str]) -> None:
    mech = graphkin.load(fourbar)
    an = solve_analytic(mech)
    # 1 in of drawing = 20 ft/s = 240 in/s, not turned
    pts = {"O_V": np.zeros(2)} | {p.lower(): an.velocity(p) / 240.0 for p in "BCEF"}
    svg = tmp_path / "v.svg"
    svg.write_text(_svg(dict(pts), None))
    assert main(["check", str(fourbar), "--drawing", str(svg), "--scale", "1 in = 20 ft/s"]) == 0
    out = capsys.readouterr().out
    assert "27.77 ft/s" in out          # V_E = 333.26 in/s (analytic) in ft/s
    # the same scale noted on the drawing itself
    svg.write_text(_svg(dict(pts), "1 in = 20 ft/s"))
    assert main(["check", str(fourbar), "--drawing", str(svg)]) == 0
    assert "(scale 1 in = 20 ft/s, not turned)" in capsys.readouterr().out
    # a wrong stated scale: every vector twice too long or too short
    assert main(["check", str(fourbar), "--drawing", str(svg), "--scale", "1 in = 40 ft/s"]) == 1
    capsys.readouterr()


def test_a_reversed_polygon_is_off_by_plain_millimetres(fourbar: Path, tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    # The polygon of Example 3.1 drawn for the wrong sense of ω2 at 1 in = 10 ft/s: every
    # image is twice its length away, 2|V_B|/120 in; |V_B| = 4 in * 94.25 rad/s = 377 in/s
    # (Ex. 3.1), so b is 2 * 377 / 120 * 25.4 = 159.6 mm off: printed "160 mm", never
    # "1.6e+02 mm" (audit9: a reversed inch-sized polygon printed "1.3e+02 mm").
    mech = graphkin.load(fourbar)
    an = solve_analytic(mech)
    pts = {"O_V": np.zeros(2)} | {p.lower(): -an.velocity(p) / 120.0 for p in "BCEF"}
    svg = tmp_path / "v.svg"
    svg.write_text(_svg(dict(pts), "1 in = 10 ft/s"))
    assert main(["check", str(fourbar), "--drawing", str(svg)]) == 1
    out = capsys.readouterr().out
    assert "e+" not in out
    assert "; 160 mm on the drawing" in out and "160 mm off on the drawing" in out


# ---- batch marking ---------------------------------------------------------------------

def test_batch_csv(fourbar: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "broken.toml"
    bad.write_text("omega3 = [")
    files = [str(ANSWERS / "ex3_1_book.toml"), str(ANSWERS / "ex3_1_two_mistakes.toml"),
             str(bad)]
    marks = tmp_path / "marks.csv"
    code = main(["check", str(fourbar), *files, "--csv", str(marks), "--quiet"])
    out, err = capsys.readouterr()
    assert code == 2                                  # one file could not be read
    # one line for the broken file, and the CSV's "wrote ..." (every command says what it wrote)
    errors = [line for line in err.strip().splitlines() if not line.startswith("wrote ")]
    assert len(errors) == 1 and "broken.toml" in errors[0]
    assert any(line.startswith("wrote ") and line.endswith(".csv") for line in err.splitlines())
    rows = list(csv.DictReader(io.StringIO(marks.read_text())))
    assert [Path(r["file"]).name for r in rows] == [Path(f).name for f in files]
    book, two, broken = rows
    assert (book["student"], book["status"], book["answers"], book["within_tolerance"]) == \
        ("the textbook", "ok", "11", "11")
    assert (two["status"], two["answers"], two["within_tolerance"]) == ("wrong", "3", "1")
    assert two["omega4"] == "WRONG" and two["omega3"] == "ok" and two["V_E"] == "WRONG"
    assert two["omega4 mistake"] == "sense" and two["V_E mistake"] == "unit:12"
    assert two["omega4 given"] == "49.64 rad/s cw" and "ccw" in two["omega4 exact"]
    assert two["summary"] == "1 of 3 within tolerance, 2 wrong (omega4: sense; V_E: unit:12)."
    assert broken["status"].startswith("unreadable")
    # without the broken file the worst is a wrong answer: exit 1
    assert main(["check", str(fourbar), *files[:2], "--csv", str(marks), "--quiet"]) == 1
    capsys.readouterr()
