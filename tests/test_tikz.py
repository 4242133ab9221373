"""TikZ output (issue 31): LaTeX labels, and the compiled PDF's geometry against the SVG's.

The geometry test compiles the TikZ with pdflatex (skipped when it is not
installed; ``.ci/run`` installs Debian's texlive) and reads the PDF's content
stream uncompressed: every straight-line vertex the SVG draws inside the
page must be a vertex of the PDF within 0.1 mm.  The SVG's coordinates are
matplotlib's (points from the top left), the PDF's pdfTeX's (big points from
the bottom left): two independent writers of the same scene.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.cli import main
from graphkin.render import draw
from graphkin.render.latex import to_latex
from graphkin.render.svg import to_svg
from graphkin.render.tikz import drawing_tikz

MM = 72.0 / 25.4  # big points per millimetre
PDFLATEX = shutil.which("pdflatex")
needs_tex = pytest.mark.skipif(PDFLATEX is None, reason="pdflatex is not installed")


@pytest.mark.parametrize(("text", "tex"), [
    ("ω₃", "$\\omega_{3}$"),                  # the issue's own example
    ("$A^{n}_{CB}$", "$A^{n}_{CB}$"),        # mathtext is LaTeX already
    ("I₁₃", "I$_{13}$"),                     # a run of subscripts is one subscript
    ("θ₂ = 120°", "$\\theta_{2}$ = 120$^{\\circ}$"),
    ("P% & #_x", "P\\% \\& \\#\\_x"),        # the user's letters escaped
    ("\\$5", "\\$5"),                        # plain(): a literal dollar
    ("V_BA ✓ ?", "V\\_BA $\\checkmark$ ?"),  # the book's marks
    ("$Q_{Γ}$", "$Q_{\\Gamma}$"),
    ("漢", "?"),                              # never a compile error
])
def test_labels_in_latex(text: str, tex: str) -> None:
    assert to_latex(text) == tex


def test_every_greek_letter_has_a_command() -> None:
    for ch in "αβγδεζηθικλμνξπρστυφχψωΓΔΘΛΞΠΣΦΨΩ":
        assert to_latex(ch).startswith("$\\") or to_latex(ch).startswith("$\\mathrm")


def _svg_vertices(svg: str) -> np.ndarray:
    """Vertices of the SVG's straight paths (M/L only), in bp from the bottom left."""
    height = float(re.search(r'height="([\d.]+)pt"', svg).group(1))  # type: ignore[union-attr]
    body = re.sub(r"<defs>.*?</defs>", "", svg, flags=re.S)  # marker shapes, clip rects
    pts = []
    for d in re.findall(r'<path d="([^"]*)"', body):
        if re.search(r"[CQAHV]", d):
            continue
        for x, y in re.findall(r"[ML] (-?[\d.]+) (-?[\d.]+)", d):
            pts.append((float(x), height - float(y)))
    return np.array(pts)


def _pdf_vertices(pdf: bytes) -> np.ndarray:
    """Every ``x y m`` and ``x y l`` of the PDF's uncompressed content streams (no ``cm``
    moves a path in pgf's output: its paths are written in page coordinates)."""
    text = pdf.decode("latin-1")
    pts = re.findall(r"(-?[\d.]+) (-?[\d.]+) [ml]\s", text)
    return np.array([(float(x), float(y)) for x, y in pts])


def _svg_markers(svg: str) -> np.ndarray:
    """Centres of the SVG's markers (pins, points: ``<use x= y=>``), bp from the bottom left."""
    height = float(re.search(r'height="([\d.]+)pt"', svg).group(1))  # type: ignore[union-attr]
    return np.array([(float(x), height - float(y)) for x, y in
                     re.findall(r'<use xlink:href="#[^"]+" x="(-?[\d.]+)" y="(-?[\d.]+)"', svg)])


def _pdf_markers(pdf: bytes) -> np.ndarray:
    """Centres of the PDF's closed circles (a move and four curves) and rectangles (``re``)."""
    text = pdf.decode("latin-1")
    num = r"(-?[\d.]+)"
    out = []
    for m in re.finditer(r"-?[\d.]+ -?[\d.]+ m \n((?:(?:-?[\d.]+ ){6}c \n){4})", text):
        ends = [line.split()[4:6] for line in m.group(1).strip().split("\n")]
        out.append(np.mean(np.array(ends, dtype=float), axis=0))
    for x, y, w, h in re.findall(rf"{num} {num} {num} {num} re", text):
        out.append(np.array([float(x) + float(w) / 2, float(y) + float(h) / 2]))
    return np.array(out)


def _nearest(want: np.ndarray, got: np.ndarray) -> float:
    """The largest distance from a point of ``want`` to the nearest of ``got`` (bp)."""
    worst = 0.0
    for k in range(0, len(want), 500):  # in blocks: memory stays small
        block = want[k:k + 500]
        dist = np.min(np.hypot(block[:, None, 0] - got[None, :, 0],
                               block[:, None, 1] - got[None, :, 1]), axis=1)
        worst = max(worst, float(dist.max()))
    return worst


def _compile(tex: str, tmp: Path) -> bytes:
    src = tmp / "fig.tex"
    src.write_text("\\pdfcompresslevel=0 \\pdfobjcompresslevel=0\n" + tex, encoding="utf-8")
    run = subprocess.run([PDFLATEX or "pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                          "fig.tex"], cwd=tmp, capture_output=True, text=True, timeout=120)
    assert run.returncode == 0, run.stdout[-2000:]
    return (tmp / "fig.pdf").read_bytes()


def _same_geometry(d: object, tmp: Path) -> None:
    tex = drawing_tikz(d)
    svg = to_svg(d.figure)  # type: ignore[attr-defined]
    pdf = _compile(tex, tmp)
    w, h = (float(v) for v in re.search(  # type: ignore[union-attr]
        r"/MediaBox \[0 0 ([\d.]+) ([\d.]+)\]", pdf.decode("latin-1")).groups())
    W, H = d.sheet.size  # type: ignore[attr-defined]
    assert abs(w - 72 * W) < 0.1 * MM and abs(h - 72 * H) < 0.1 * MM  # the same page
    want = _svg_vertices(svg)
    got = _pdf_vertices(pdf)
    inside = (want[:, 0] > 1) & (want[:, 0] < w - 1) & (want[:, 1] > 1) & (want[:, 1] < h - 1)
    want = want[inside]
    assert len(want) > 50
    worst = _nearest(want, got)
    assert worst < 0.1 * MM, f"a vertex of the SVG is {worst / MM:.3f} mm from the PDF's"
    # every pin and point: its marker's centre where the SVG puts it
    marks = _svg_markers(svg)
    marks = marks[(marks[:, 0] > 1) & (marks[:, 0] < w - 1) & (marks[:, 1] > 1)
                  & (marks[:, 1] < h - 1)]
    assert len(marks) >= 1
    worst = _nearest(marks, _pdf_markers(pdf))
    assert worst < 0.1 * MM, f"a marker of the SVG is {worst / MM:.3f} mm from the PDF's"


@needs_tex
def test_every_kinematic_diagram_compiles_to_the_svg_geometry(tmp_path: Path) -> None:
    """Ex. 3.1/4.2: posture, polygons, centers and the four curvature figures on one sheet."""
    sol = graphkin.examples.fourbar().solve()
    _same_geometry(draw(sol, "all"), tmp_path)


@needs_tex
def test_forces_drawing_compiles_to_the_svg_geometry(tmp_path: Path) -> None:
    spec = Path(__file__).parents[2] / "shared" / "spec" / "forces-examples"
    files = sorted(spec.glob("*.toml")) if spec.is_dir() else []
    if not files:
        pytest.skip("no forces example here")
    _same_geometry(draw(graphkin.load(files[0]).solve(), "forces"), tmp_path)


def test_draw_writes_tikz(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                          monkeypatch: pytest.MonkeyPatch) -> None:
    src = tmp_path / "fourbar.toml"
    src.write_text(graphkin.examples.text("fourbar"), encoding="utf-8")
    out = tmp_path / "v.tex"
    assert main(["draw", str(src), "-d", "velocity", "-o", str(out)]) == 0
    tex = out.read_text(encoding="utf-8")
    assert "\\begin{tikzpicture}" in tex and "\\documentclass" in tex
    assert "$\\omega_{3}$" in tex or "$\\omega_{2}$" in tex  # ω labels as LaTeX
    assert "wrote" in capsys.readouterr().err
    # -o - --format tikz: the same text on standard output
    assert main(["draw", str(src), "-d", "velocity", "-o", "-", "--format", "tikz"]) == 0
    assert capsys.readouterr().out == tex


def test_handout_page_is_refused_in_tikz(tmp_path: Path, capsys: pytest.CaptureFixture[str]
                                         ) -> None:
    src = tmp_path / "fourbar.toml"
    src.write_text(graphkin.examples.text("fourbar"), encoding="utf-8")
    assert main(["draw", str(src), "-d", "posture", "--sheet", "a4", "-o",
                 str(tmp_path / "p.tex")]) == 2
    err = capsys.readouterr().err
    assert "--output" in err and "handout" in err and "Traceback" not in err


def test_commands_write_beside_the_user_and_say_so(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str],
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    """Issue 31: draw, plot and steps without -o write FILE-STEM-... here and say ``wrote``."""
    src = tmp_path / "in" / "fourbar.toml"
    src.parent.mkdir()
    src.write_text(graphkin.examples.text("fourbar"), encoding="utf-8")
    monkeypatch.chdir(tmp_path)
    for argv, name in ((["draw", str(src), "-d", "posture"], "fourbar-posture.svg"),
                       (["plot", str(src), "--what", "omega", "--count", "12"],
                        "fourbar-plot.svg"),
                       (["steps", str(src)], "fourbar-steps-posture.html")):
        assert main(argv) == 0
        assert (tmp_path / name).is_file()
        assert f"wrote {name}" in capsys.readouterr().err
    # -o - is the SVG itself on standard output, nothing written here
    assert main(["draw", str(src), "-d", "posture", "-o", "-"]) == 0
    assert capsys.readouterr().out.lstrip().startswith("<?xml")
    assert main(["draw", str(src), "-d", "posture", "-o", "-", "--format", "pdf"]) == 2
    assert "not PDF" in capsys.readouterr().err
    # a name without a suffix says nothing of its format: refused, as before
    assert main(["draw", str(src), "-d", "posture", "-o", "noext"]) == 2
    assert "cannot tell the format" in capsys.readouterr().err
    assert not (tmp_path / "noext").exists()


def test_far_geometry_is_cut_to_the_panel(tmp_path: Path) -> None:
    """A circle 10 000 in across and a line 1000 in long: TikZ stops at 226 in, so they are
    written as the part near the panel; the visible chord of the circle stays on it."""
    from graphkin.render.scale import Scale
    from graphkin.render.scene import Item, Panel
    from graphkin.render.sheet import Sheet
    from graphkin.render.tikz import sheet_tikz

    p = Panel("posture", "posture", "", "in", scale=Scale(1.0, "in", 1.0, "in"),
              view=(0.0, 0.0, 4.0, 3.0), origin=(0.0, 0.0))
    g = p.group("far", 1.0)
    r = 5000.0  # centre 5000 in below the panel's middle: the circle crosses it at y = 1.5
    g.items.append(Item("circle", np.array([[2.0, 1.5 - r]]), "arc", radius=r))
    g.items.append(Item("path", np.array([[-1000.0, 1.0], [1000.0, 2.0]]), "aux-line"))
    g.items.append(Item("marker", np.array([[900.0, 900.0]]), "point"))
    g.items.append(Item("polygon", np.array([[-500.0, -500.0], [500.0, -500.0], [0.0, 2.0]]),
                        "plate"))
    tex = sheet_tikz(Sheet([p], (4.0, 3.0), "", "posture"))
    nums = [float(v) for v in re.findall(r"-?\d+\.?\d*", tex.split("begin{tikzpicture}")[1])]
    assert max(abs(v) for v in nums) < 1000  # nothing near TikZ's limit (16383 pt)
    # every vertex of the circle's polyline lies on the circle, within 1e-6 in
    first = [line for line in tex.splitlines() if line.startswith("\\path[draw")][0]
    pts = np.array([[float(a), float(b)] for a, b in
                    re.findall(r"\((-?[\d.]+),(-?[\d.]+)\)", first)])
    assert len(pts) >= 2
    assert np.allclose(np.hypot(pts[:, 0] - 2.0, pts[:, 1] - (1.5 - r)), r, atol=1e-4)
    if PDFLATEX is not None:
        _compile(tex, tmp_path)


def test_sweep_and_check_say_what_they_wrote(tmp_path: Path, examples: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    csv = tmp_path / "cycle.csv"
    assert main(["sweep", str(examples / "ex3_1_fourbar.toml"), "--count", "8",
                 "--csv", str(csv)]) == 0
    assert csv.is_file() and f"wrote {csv}" in capsys.readouterr().err
    answers = tmp_path / "a.toml"
    answers.write_text('omega3 = "25.4 rad/s ccw"\n', encoding="utf-8")  # Ex. 3.1: 25.38
    marks = tmp_path / "marks.csv"
    assert main(["check", str(examples / "ex3_1_fourbar.toml"), str(answers), "--csv",
                 str(marks)]) == 0
    assert marks.is_file() and f"wrote {marks}" in capsys.readouterr().err


SPEC = Path(__file__).parents[2] / "shared" / "spec"
ALL = pytest.mark.skipif(
    PDFLATEX is None or not __import__("os").environ.get("GRAPHKIN_TIKZ_ALL"),
    reason="every spec example's TikZ (about a minute): set GRAPHKIN_TIKZ_ALL=1")


@ALL
@pytest.mark.parametrize("path", sorted(p for d in ("examples", "forces-examples")
                                        for p in (SPEC / d).glob("*.toml")
                                        if p.name != "expected.toml"),
                         ids=lambda p: p.stem)
def test_every_diagram_of_every_spec_example(path: Path, tmp_path: Path) -> None:
    """The acceptance check of issue 31, opt-in: each diagram the example has, compiled."""
    from graphkin.render.sources import DiagramUnavailable

    sol = graphkin.load(path).solve()
    drawn = 0
    for k, diagram in enumerate(("posture", "velocity", "acceleration", "centers",
                                 "curvature", "forces")):
        try:
            d = draw(sol, diagram)
        except DiagramUnavailable:
            continue
        (tmp_path / str(k)).mkdir()
        _same_geometry(d, tmp_path / str(k))
        drawn += 1
    assert drawn >= 1
