"""A generated class: answers files and CAD drawings with planted mistakes, marked at once.

Every planted value is derived independently of ``graphkin.check``: from the
analytic solver (:func:`solve_analytic`, loop closure by Newton's method), run
on the mechanism as the student misread it (ω2 = 900 rad/s instead of
900 rev/min, the other assembly), or from a hand derivation written out below
(a normal component drawn away from its center, an image flipped over).

Example 3.1 / 4.2 (Uicker, Pennock & Shigley, 5th ed.): the four-bar ABCD with
coupler point E and rocker point F, ω2 = 900 rev/min ccw, α2 = 0.
"""

from __future__ import annotations

import csv
import dataclasses
import io
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from spec_data import inline
from strategies import mechanisms

import graphkin
from graphkin.cli import main
from graphkin.kinematics.analytic import solve_analytic

FT = 12.0  # in per ft


def _perp(v: np.ndarray) -> np.ndarray:
    return np.array([-v[1], v[0]])


def _carried(first: str, code: str, *rest: str) -> dict[str, tuple[str, str]]:
    """The expected marks of a mistake carried through: ``first`` WRONG (``code``), the rest
    following from it."""
    return {first: ("WRONG", code), **{k: ("follows", f"follows:{first}") for k in rest}}


def _vec(v: np.ndarray, unit: str = "ft/s", f: float = FT) -> str:
    v = np.asarray(v, dtype=float) / f
    return f'"{math.hypot(*v):.5g} {unit} at {math.degrees(math.atan2(v[1], v[0])):.3f} deg"'


def _noisy(v: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """A value as read off a careful drawing: within 0.8 % and 0.8° of the exact one."""
    t = math.radians(rng.uniform(-0.8, 0.8))
    c, s = math.cos(t), math.sin(t)
    return (1 + rng.uniform(-0.008, 0.008)) * np.array([[c, -s], [s, c]]) @ np.asarray(v)


@pytest.fixture(scope="module")
def fourbar(examples: Path) -> Path:  # type: ignore[misc]
    return examples / "ex3_1_fourbar.toml"


@pytest.fixture(scope="module")
def examples() -> Path:  # module-scoped twin of conftest's fixture
    from spec_data import EXAMPLES

    return EXAMPLES


def _reversed_normal(an: graphkin.Solution) -> dict[str, object]:
    """The acceleration polygon of Example 4.2 drawn with A_CB^n away from B.

    The student lays off A_B, then +ω3² R_CB (instead of −ω3² R_CB, Eq. 4.7),
    then a tangential line ⊥ CB; from the pole −ω4² R_CD and a line ⊥ CD.
    Where they meet is c′:  A_B + ω3² R_CB + α3' k×R_CB = −ω4² R_CD + α4' k×R_CD,
    two linear equations in α3', α4'.  e′ is then laid off on b′c′ as the
    image of BCE: A_E = A_B + (A_C − A_B) R_EB / R_CB (complex division).
    """
    P = {n: np.asarray(an.position(n), dtype=float) for n in "BCDE"}
    w3, w4 = float(an.omega("3")), float(an.omega("4"))
    a_b = np.asarray(an.acceleration("B"), dtype=float)
    r_cb, r_cd = P["C"] - P["B"], P["C"] - P["D"]
    a3, a4 = np.linalg.solve(np.column_stack([_perp(r_cb), -_perp(r_cd)]),
                             -w4**2 * r_cd - a_b - w3**2 * r_cb)
    a_c = a_b + w3**2 * r_cb + a3 * _perp(r_cb)
    z = complex(*(a_c - a_b)) * complex(*(P["E"] - P["B"])) / complex(*r_cb)
    return {"alpha3": a3, "alpha4": a4, "A_C": a_c, "A_E": a_b + np.array([z.real, z.imag])}


def _class(mech_path: Path, tmp: Path) -> dict[str, tuple[Path, dict[str, tuple[str, str]]]]:
    """Answers files: name -> (file, {key: (verdict, mistake code)} expected)."""
    mech = graphkin.load(mech_path)
    an = solve_analytic(mech)
    rng = np.random.default_rng(15)
    out: dict[str, tuple[Path, dict[str, tuple[str, str]]]] = {}

    def put(name: str, text: str, expect: dict[str, tuple[str, str]]) -> None:
        f = tmp / f"{name}.toml"
        f.write_text(f'student = "{name}"\n{text}', encoding="utf-8")
        out[name] = (f, expect)

    def good_text() -> str:
        w3, w4 = float(an.omega("3")), float(an.omega("4"))
        a3, a4 = float(an.alpha("3")), float(an.alpha("4"))
        return "\n".join([
            f"theta3 = {float(an.angle('3')) + rng.uniform(-0.8, 0.8):.3f}",
            f'omega3 = "{abs(w3) * (1 + rng.uniform(-.008, .008)):.4g} rad/s '
            f'{"ccw" if w3 > 0 else "cw"}"',
            f"omega4 = {w4 * (1 + rng.uniform(-.008, .008)):.4g}",
            f"V_C = {_vec(_noisy(an.velocity('C'), rng))}",
            f"V_E = {_vec(_noisy(an.velocity('E'), rng))}",
            f"alpha3 = {a3 * (1 + rng.uniform(-.008, .008)):.4g}",
            f"alpha4 = {a4 * (1 + rng.uniform(-.008, .008)):.5g}",
            f"A_E = {_vec(_noisy(an.acceleration('E'), rng), 'ft/s^2')}", ""])

    ok = ("ok", "")
    for i in range(3):
        put(f"correct{i}", good_text(),
            {k: ok for k in ("theta3", "omega3", "omega4", "V_C", "V_E", "alpha3", "alpha4",
                             "A_E")})
    # ω4 with the wrong sense
    w4 = float(an.omega("4"))
    put("sense", f'omega4 = "{abs(w4):.4g} rad/s {"cw" if w4 > 0 else "ccw"}"\n',
        {"omega4": ("WRONG", "sense")})
    # V_E measured in in/s but labelled ft/s: 12 times too large
    put("unit12", f"V_E = {_vec(an.velocity('E'), 'ft/s', 1.0)}\n",
        {"V_E": ("WRONG", "unit:12")})
    # 900 rev/min taken as 900 rad/s: every later answer follows from it
    d = mech.drives[0]
    fast = solve_analytic(dataclasses.replace(mech, drives=(dataclasses.replace(d, rate=900.0),)))
    put("revmin", "\n".join([f"V_B = {_vec(fast.velocity('B'))}",
                             f"omega3 = {float(fast.omega('3')):.5g}",
                             f"V_E = {_vec(fast.velocity('E'))}",
                             f"A_C = {_vec(fast.acceleration('C'), 'ft/s^2')}", ""]),
        _carried("V_B", "unit:60/2π", "omega3", "V_E", "A_C"))
    # the other assembly: C mirrored about BD (the crossed four-bar, Sec. 2.5)
    b, dd = np.asarray(an.position("B")), np.asarray(an.position("D"))
    c = np.asarray(an.position("C"))
    u = (dd - b) / np.hypot(*(dd - b))
    c_other = b + 2 * ((c - b) @ u) * u - (c - b)
    crossed = solve_analytic(dataclasses.replace(
        mech, assembly={**mech.assembly, "C": tuple(c_other), "E": mech.assembly["E"],
                        "F": mech.assembly["F"]}),
        guess=None)
    assert np.hypot(*(np.asarray(crossed.position("C")) - c_other)) < 1e-6 * mech.scale
    put("branch", "\n".join([f"theta3 = {float(crossed.angle('3')):.3f}",
                             f"theta4 = {float(crossed.angle('4')):.3f}",
                             f"omega3 = {float(crossed.omega('3')):.5g}",
                             f"omega4 = {float(crossed.omega('4')):.5g}", ""]),
        _carried("theta3", "branch", "theta4", "omega3", "omega4"))
    # A_CB^n drawn away from B, carried through the polygon and the image of E
    rn = _reversed_normal(an)
    put("normal", "\n".join([f"alpha3 = {rn['alpha3']:.5g}", f"alpha4 = {rn['alpha4']:.5g}",
                             f"A_C = {_vec(rn['A_C'], 'ft/s^2')}",  # type: ignore[arg-type]
                             f"A_E = {_vec(rn['A_E'], 'ft/s^2')}", ""]),  # type: ignore[arg-type]
        _carried("alpha3", "normal-reversed", "alpha4", "A_C", "A_E"))
    # a plain positive number for α4, which is clockwise
    a4 = float(an.alpha("4"))
    assert a4 < 0
    put("positive", f"alpha4 = {abs(a4):.5g}\n", {"alpha4": ("WRONG", "sense")})
    # the velocity image of link 3 flipped: E' = (10, +4) in link 3's frame instead of (10, -4)
    th3 = float(an.angle_rad("3"))
    r = np.array([10 * math.cos(th3) - 4 * math.sin(th3), 10 * math.sin(th3) + 4 * math.cos(th3)])
    v_flip = np.asarray(an.velocity("B")) + float(an.omega("3")) * _perp(r)
    put("flipped", f"V_E = {_vec(v_flip)}\n", {"V_E": ("WRONG", "image-flipped")})
    # two mistakes at once: V_C drawn the wrong way round and read in in/s as ft/s
    put("two", f"V_C = {_vec(-np.asarray(an.velocity('C')), 'ft/s', 1.0)}\n",
        {"V_C": ("WRONG", "sense+unit:12")})
    # the difference V_EB given for the absolute V_E
    put("difference", f"V_E = {_vec(np.asarray(an.velocity('E')) - an.velocity('B'))}\n",
        {"V_E": ("WRONG", "difference-for-absolute")})
    # a typo in one key: the rest is marked
    put("typo", f'V_X = 3\nomega3 = "{float(an.omega("3")):.4g} rad/s ccw"\n',
        {"V_X": ("UNREADABLE", "unreadable"), "omega3": ok})
    return out


def test_a_class_of_answer_files(fourbar: Path, tmp_path: Path,
                                 capsys: pytest.CaptureFixture[str]) -> None:
    students = _class(fourbar, tmp_path)
    broken = tmp_path / "broken.toml"
    broken.write_text('student = "Unquoted"\nω3 = 25.4\n', encoding="utf-8")  # invalid TOML
    files = [str(f) for f, _ in students.values()] + [str(broken)]
    marks = tmp_path / "marks.csv"
    code = main(["check", str(fourbar), *files, "--csv", str(marks), "--quiet"])
    capsys.readouterr()
    assert code == 2                           # the typo and the broken file are unreadable
    rows = {r["student"]: r for r in csv.DictReader(io.StringIO(marks.read_text("utf-8")))}
    for name, (_, expect) in students.items():
        row = rows[name]
        for key, (verdict, mistake) in expect.items():
            assert (row[key], row[f"{key} mistake"]) == (verdict, mistake), (name, key, row)
    assert rows["Unquoted"]["status"] == "unreadable"
    assert "not valid TOML" in rows["Unquoted"]["summary"]
    # follow-through counted apart: one mistake, three answers that follow from it
    for name in ("revmin", "branch", "normal"):
        row = rows[name]
        assert (row["correct"], row["follows"], row["wrong"]) == ("0", "3", "1"), name
        assert row["status"] == "wrong"
    assert "3 follow from an earlier mistake" in rows["normal"]["summary"]
    for i in range(3):
        assert rows[f"correct{i}"]["status"] == "ok"
    # without the unreadable files the worst is a wrong answer: exit 1
    rest = [str(f) for n, (f, _) in students.items() if n != "typo"]
    assert main(["check", str(fourbar), *rest, "--quiet"]) == 1
    capsys.readouterr()


def test_hints_speak_of_what_was_drawn(fourbar: Path, tmp_path: Path,
                                       capsys: pytest.CaptureFixture[str]) -> None:
    students = _class(fourbar, tmp_path)
    main(["check", str(fourbar), str(students["branch"][0])])
    out = capsys.readouterr().out
    # the crossed C lies below the line from B to D (B = (-2, 3.46), D = (10, 0), the
    # mirrored C has y < 0 where the line BD is still above the x axis)
    assert "the other assembly (C below BD)" in out
    assert "right instead of left" not in out
    main(["check", str(fourbar), str(students["positive"][0])])
    out = capsys.readouterr().out
    assert "a positive number means counterclockwise; the exact value is clockwise" in out
    main(["check", str(fourbar), str(students["normal"][0])])
    out = capsys.readouterr().out
    assert "follows from the mistake in alpha3: A_CB^n drawn away from B" in out


def test_magnitude_only_is_judged_on_magnitude(fourbar: Path, tmp_path: Path,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    an = solve_analytic(graphkin.load(fourbar))
    f = tmp_path / "a.toml"
    f.write_text(f'alpha4 = "{abs(float(an.alpha("4"))):.5g} rad/s^2"\n', encoding="utf-8")
    assert main(["check", str(fourbar), str(f)]) == 0
    out = capsys.readouterr().out
    assert "magnitude only" in out


# ---- drawing accuracy on the sheet -----------------------------------------------------

@pytest.mark.parametrize(("scale", "verdict", "words"), [
    # |V_F| = ω2 ... = 376.99 in/s (analytic); 3 % of it is 11.3 in/s:
    # at 1 mm = 50 in/s that is 0.23 mm on paper (right), at 1 mm = 10 in/s 1.13 mm (wrong)
    ("1 mm = 50 in/s", "ok", "within 0.5 mm on the drawing"),
    ("1 mm = 10 in/s", "WRONG", "1.1 mm off on the drawing"),
])
def test_drawing_tolerance_in_sheet_units(fourbar: Path, tmp_path: Path, scale: str,
                                          verdict: str, words: str,
                                          capsys: pytest.CaptureFixture[str]) -> None:
    an = solve_analytic(graphkin.load(fourbar))
    v = 1.03 * np.asarray(an.velocity("F"))
    assert math.hypot(*an.velocity("F")) == pytest.approx(376.99, abs=0.01)
    f = tmp_path / "a.toml"
    f.write_text(f'tolerance = {{ drawing = "0.5 mm", scale = "{scale}" }}\n'
                 f"V_F = {_vec(v, 'in/s', 1.0)}\n", encoding="utf-8")
    main(["check", str(fourbar), str(f)])
    out = capsys.readouterr().out
    row = next(line for line in out.splitlines() if line.startswith("V_F"))
    assert f" {verdict} " in row and words in row


# ---- CAD drawings -----------------------------------------------------------------------

PER_MM = 10.0  # in/s per mm of paper: "1 mm = 10 in/s"


def _cad(path: Path, vectors: dict[str, np.ndarray], style: str, *,
         closing: tuple[str, str] | None = ("b", "c"), pole_label: str = r"O\S^V;") -> Path:
    """A velocity polygon drawn in CAD the way students draw it (mm, 1 mm = 10 in/s)."""
    import ezdxf

    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = 4
    msp = doc.modelspace()
    pole = np.array([100.0, 50.0])
    tips = {k: pole + np.asarray(v) / PER_MM for k, v in vectors.items()}
    host = msp
    origin = np.zeros(2)
    if style == "block":
        blk = doc.blocks.new("POLYGON")
        host, origin = blk, pole  # the block's own coordinates: relative to the pole
    for lab, tip in tips.items():
        p0, p1 = pole - origin, tip - origin
        d = (p1 - p0) / np.hypot(*(p1 - p0))
        base = p1 - 3.0 * d
        if style == "tapered":
            host.add_lwpolyline([(*p0, 0, 0, 0), (*base, 1.2, 0, 0), (*p1, 0, 0, 0)],
                                format="xyseb")
        elif style == "separate-taper":  # the shaft to the arrowhead's base, the taper apart
            host.add_line(tuple(p0), tuple(base))
            host.add_lwpolyline([(*base, 1.2, 0, 0), (*p1, 0, 0, 0)], format="xyseb")
        elif style == "triangle":        # a closed triangle at the tip, the shaft to its base
            host.add_line(tuple(p0), tuple(base))
            side = np.array([-d[1], d[0]]) * 0.6
            host.add_lwpolyline([tuple(base + side), tuple(p1), tuple(base - side)], close=True)
        elif style == "leader":
            host.add_leader([tuple(p1), tuple(p0)])
        else:  # two short LINEs as the arrowhead, the shaft to the tip
            host.add_line(tuple(p0), tuple(p1))
            for t in (math.radians(20), math.radians(-20)):
                c, s = math.cos(t), math.sin(t)
                back = np.array([[c, -s], [s, c]]) @ (-d) * 3.0
                host.add_line(tuple(p1), tuple(p1 + back))
        # the label 0.8 mm off the tip, beside the arrowhead
        host.add_text(lab, height=2.5).set_placement(tuple(p1 + np.array([0.8, 0.8])))
    if closing:
        a, b = (tips[k] - origin for k in closing)
        host.add_line(tuple(a), tuple(b))
    host.add_mtext(pole_label, dxfattribs={"char_height": 2.5}).set_location(
        tuple(pole - origin + np.array([-4.0, 0.8])))
    if style == "block":
        msp.add_blockref("POLYGON", tuple(pole))
    msp.add_text("Scale: 1 mm = 10 in/s", height=2.5).set_placement((60.0, 10.0))
    # a sketch of the mechanism elsewhere on the sheet, its letters are not images
    for (x0, y0), (x1, y1), lab in [((300, 300), (310, 317), "A"), ((310, 317), (360, 340), "B"),
                                    ((360, 340), (400, 300), "C")]:
        msp.add_line((x0, y0), (x1, y1))
        msp.add_text(lab, height=2.5).set_placement((x1 + 1, y1 + 1))
    doc.saveas(path)
    return path


@pytest.fixture(scope="module")
def velocities(fourbar: Path) -> dict[str, np.ndarray]:
    an = solve_analytic(graphkin.load(fourbar))
    return {p.lower(): np.asarray(an.velocity(p), dtype=float) for p in "BCEF"}


@pytest.mark.parametrize("style", ["tapered", "separate-taper", "triangle", "lines", "leader",
                                   "block"])
def test_cad_drawings_as_students_draw_them(fourbar: Path, tmp_path: Path, style: str,
                                            velocities: dict[str, np.ndarray],
                                            capsys: pytest.CaptureFixture[str]) -> None:
    dxf = _cad(tmp_path / "v.dxf", velocities, style)
    assert main(["check", str(fourbar), "--drawing", str(dxf)]) == 0
    out = capsys.readouterr().out
    assert "4 of 4 within tolerance" in out and "not turned" in out
    # the mechanism's letters A, B, C are in another drawing on the sheet: not read
    assert "V_A " not in out and "ignored" not in out


def test_a_wrong_sense_polygon_on_a_stated_scale_fails(fourbar: Path, tmp_path: Path,
                                                       velocities: dict[str, np.ndarray],
                                                       capsys: pytest.CaptureFixture[str]
                                                       ) -> None:
    # drawn for ω2 clockwise: every image point through the pole (V = ω × R reverses)
    dxf = _cad(tmp_path / "v.dxf", {k: -v for k, v in velocities.items()}, "tapered")
    assert main(["check", str(fourbar), "--drawing", str(dxf), "--csv", "-"]) == 1
    out = capsys.readouterr().out
    row = next(csv.DictReader(io.StringIO(out[out.index("file,"):])))
    assert row["correct"] == "0"
    assert row["V_B mistake"] == "sense"          # the input's sense, then carried through
    assert {row[f"V_{p} mistake"] for p in "CEF"} == {"follows:V_B"}


def test_flipped_image_in_a_cad_drawing_is_named(fourbar: Path, tmp_path: Path,
                                                 velocities: dict[str, np.ndarray],
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    an = solve_analytic(graphkin.load(fourbar))
    th3 = float(an.angle_rad("3"))
    r = np.array([10 * math.cos(th3) - 4 * math.sin(th3), 10 * math.sin(th3) + 4 * math.cos(th3)])
    v = dict(velocities)
    v["e"] = np.asarray(an.velocity("B")) + float(an.omega("3")) * _perp(r)
    dxf = _cad(tmp_path / "v.dxf", v, "lines")
    assert main(["check", str(fourbar), "--drawing", str(dxf), "--csv", "-"]) == 1
    out = capsys.readouterr().out
    row = next(csv.DictReader(io.StringIO(out[out.index("file,"):])))
    assert row["V_E mistake"] == "image-flipped" and row["correct"] == "3"


def test_svg_with_transforms_and_tspans(fourbar: Path, tmp_path: Path,
                                        velocities: dict[str, np.ndarray],
                                        capsys: pytest.CaptureFixture[str]) -> None:
    # 200 mm wide sheet, 1 user unit = 1 mm; the polygon in a group turned y-up and moved
    parts = []
    for lab, v in velocities.items():
        x, y = v / PER_MM
        d = np.array([x, y]) / math.hypot(x, y)
        c1 = np.array([x, y]) - 2.5 * d + 0.7 * np.array([-d[1], d[0]])
        c2 = c1 - 1.4 * np.array([-d[1], d[0]])
        parts.append(f'<path d="M0,0 L{x:.6f},{y:.6f}"/>'         # an arrowhead at the tip
                     f'<path d="M{x:.6f},{y:.6f} L{c1[0]:.6f},{c1[1]:.6f} '
                     f'L{c2[0]:.6f},{c2[1]:.6f} z"/>')
        parts.append(f'<text transform="translate({x + 0.8:.6f},{y + 0.8:.6f}) scale(1,-1)">'
                     f'<tspan>{lab}</tspan></text>')
    parts.append('<text transform="translate(-4,1) scale(1,-1)">O<tspan baseline-shift="sub" '
                 'font-size="2">V</tspan></text>')
    svg = ('<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="200mm" '
           'viewBox="0 0 200 200"><g transform="translate(100,150) scale(1,-1)">'
           + "".join(parts) + '</g><text x="10" y="190">Scale: 1 mm = 10 in/s</text></svg>')
    f = tmp_path / "v.svg"
    f.write_text(svg, encoding="utf-8")
    assert main(["check", str(fourbar), "--drawing", str(f)]) == 0
    assert "4 of 4 within tolerance" in capsys.readouterr().out


# ---- output that is safe to show and to open -----------------------------------------

def test_csv_cells_are_not_formulas_and_names_not_escapes(fourbar: Path, tmp_path: Path,
                                                          capsys: pytest.CaptureFixture[str]
                                                          ) -> None:
    f = tmp_path / "a.toml"
    f.write_text('student = "=HYPERLINK(\\"http://x\\")\\u001b[2J"\nomega3 = -25.4\n',
                 encoding="utf-8")
    main(["check", str(fourbar), str(f), "--csv", "-"])
    out = capsys.readouterr().out
    assert "\x1b" not in out
    row = next(csv.DictReader(io.StringIO(out[out.index("file,"):])))
    assert row["student"].startswith("'=HYPERLINK")
    for cell in row.values():
        assert cell[:1] not in ("=", "+", "-", "@") or cell.lstrip("-+").replace(".", "").isdigit()
    main(["check", str(fourbar), str(f)])
    assert "\x1b" not in capsys.readouterr().out


@pytest.mark.parametrize(("name", "content"), [
    ("nested.svg", "<svg xmlns='http://www.w3.org/2000/svg'>" + "<g>" * 1200 + "</g>" * 1200
     + "</svg>"),
    ("abc.svg", "<svg xmlns='http://www.w3.org/2000/svg'><line x1='abc' y1='0' x2='1' y2='1'/>"
     "<text>O_V</text></svg>"),
    ("nan.svg", "<svg xmlns='http://www.w3.org/2000/svg'><line x1='nan' y1='0' x2='1' y2='1'/>"
     "<text>O_V</text></svg>"),
    ("path.svg", "<svg xmlns='http://www.w3.org/2000/svg'><path d='M 1 L 2 3 Q'/>"
     "<text>O_V</text></svg>"),
    ("matrix.svg", "<svg xmlns='http://www.w3.org/2000/svg'><g transform='scale(1e308) "
     "scale(1e308)'><line x1='1' y1='0' x2='1' y2='1'/></g></svg>"),
    ("truncated.dxf", None),
    ("entities.svg", "<?xml version='1.0'?><!DOCTYPE s [<!ENTITY a 'aaaaaaaaaa'>"
     "<!ENTITY b '&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;'><!ENTITY c '&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;'>"
     "<!ENTITY d '&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;'><!ENTITY e '&d;&d;&d;&d;&d;&d;&d;&d;&d;&d;'>"
     "<!ENTITY f '&e;&e;&e;&e;&e;&e;&e;&e;&e;&e;'><!ENTITY g '&f;&f;&f;&f;&f;&f;&f;&f;&f;&f;'>"
     "]><svg xmlns='http://www.w3.org/2000/svg'><text>&g;&g;&g;&g;&g;&g;&g;</text></svg>"),
    ("xxe.svg", "<?xml version='1.0'?><!DOCTYPE s [<!ENTITY x SYSTEM 'file:///etc/passwd'>]>"
     "<svg xmlns='http://www.w3.org/2000/svg'><text>&x;</text></svg>"),
])
def test_hostile_drawings_exit_2_with_one_line(fourbar: Path, tmp_path: Path, name: str,
                                               content: str | None,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    f = tmp_path / name
    if content is None:
        import ezdxf

        doc = ezdxf.new()
        doc.modelspace().add_line((0, 0), (1, 1))
        doc.saveas(tmp_path / "full.dxf")
        full = (tmp_path / "full.dxf").read_bytes()
        f.write_bytes(b"AutoCAD Binary DXF\r\n\x1a\x00" + full[: len(full) // 3])
    else:
        f.write_text(content, encoding="utf-8")
    code = main(["check", str(fourbar), "--drawing", str(f)])
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and name in lines[0] and "Traceback" not in err
    assert "root:" not in err                       # no external entity was read


def test_huge_and_special_files_exit_2(fourbar: Path, tmp_path: Path,
                                       capsys: pytest.CaptureFixture[str]) -> None:
    import os

    big = tmp_path / "big.svg"
    with big.open("wb") as fh:                      # a sparse 30 MB file
        fh.truncate(30_000_000)
    fifo = tmp_path / "pipe.toml"
    os.mkfifo(fifo)
    folder = tmp_path / "folder.svg"
    folder.mkdir()
    for args, words in [(["--drawing", str(big)], "too large"),
                        ([str(fifo)], "not a regular file"),
                        (["--drawing", str(folder)], "not a regular file")]:
        code = main(["check", str(fourbar), *args])
        err = capsys.readouterr().err
        assert code == 2 and len(err.strip().splitlines()) == 1 and words in err, err


# ---- every kind of mechanism ----------------------------------------------------------

@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mechanisms())
def test_exact_answers_pass_and_slips_are_named_on_random_mechanisms(rm) -> None:  # type: ignore[no-untyped-def]
    """Answers from the analytic solver pass; ω with the sense reversed, V ×12 are named."""
    from graphkin.check import check, loads_answers

    mech = rm.mechanism()
    if not mech.has_rates:
        return
    an = solve_analytic(mech)
    lines = []
    for lid in mech.links:
        if lid != "1":
            lines.append(f"omega{lid} = {float(an.omega(lid)):.9g}")
    pts = [p for p in mech.point_names if p not in mech.helper_points]
    for p in pts:
        v = np.asarray(an.velocity(p), dtype=float)
        if math.hypot(*v) > 0:
            lines.append(f"V_{p} = {_vec(v, f'{mech.length_unit}/s', 1.0)}")
    rep = check(mech.solve(), loads_answers("\n".join(lines), mech))
    assert rep.ok, rep.text()
    # the first moving link's ω with its sense reversed (|ω| ≥ 3 % of the fastest, by the
    # strategy's construction), and the fastest point's velocity 12 times too large
    lid = next(k for k in mech.links if k != "1")
    fastest = max(pts, key=lambda p: math.hypot(*an.velocity(p)))
    text = (f"omega{lid} = {-float(an.omega(lid)):.9g}\n"
            f"V_{fastest} = {_vec(12 * np.asarray(an.velocity(fastest)), 'x', 1.0)}")
    text = text.replace('x at', f'{mech.length_unit}/s at')
    rows = {r.key: r for r in check(mech.solve(), loads_answers(text, mech)).rows}
    assert rows[f"omega{lid}"].verdict == "WRONG"
    assert rows[f"omega{lid}"].code in ("sense", "follows:V_" + fastest)
    assert rows[f"V_{fastest}"].code in ("unit:12", "follows:omega" + lid), rows


def test_a_nearly_stationary_coupler_is_judged_on_the_paper() -> None:
    """ω3 near zero, read off image points each within 0.5 mm of their place on the sheet.

    ω3 = (R_CB × V_CB) / |R_CB|² (V_CB = ω3 k × R_CB, Eq. 3.4); the image points b, c of
    a polygon about 100 mm across are each moved 0.5 mm (0.5 % of its size) in a random
    direction.  Relative to ω3 that is a large error, on the paper it is drawing accuracy.
    """
    from graphkin.check import check, loads_answers

    # a near-parallelogram: AB = 4, DC = 4.2, BC = 10.2, AD = 10 (a coupler nearly translating)
    mech = graphkin.loads(inline("class-near_parallelogram.toml"))
    an = solve_analytic(mech)
    w3 = abs(float(an.omega("3")))
    assert 0 < w3 < 0.05 * 10.0
    size = max(math.hypot(*an.velocity(p)) for p in mech.point_names)
    per = size / 100.0                           # in/s per mm: the polygon is 100 mm across
    r_cb = np.asarray(an.position("C")) - np.asarray(an.position("B"))
    rng = np.random.default_rng(4)
    sol = mech.solve()
    strict = 0
    for _ in range(20):
        dv = [0.5 * per * np.array([math.cos(t), math.sin(t)])
              for t in rng.uniform(0, 2 * math.pi, 2)]
        v_cb = (np.asarray(an.velocity("C")) + dv[0]) - (np.asarray(an.velocity("B")) + dv[1])
        w = float(r_cb[0] * v_cb[1] - r_cb[1] * v_cb[0]) / float(r_cb @ r_cb)
        text = (f'tolerance = {{ drawing = "0.5 mm", scale = "1 mm = {per:.9g} in/s" }}\n'
                f"omega3 = {w:.9g}\n")
        (row,) = check(sol, loads_answers(text, mech)).rows
        assert row.verdict == "ok", row
        (plain,) = check(sol, loads_answers(f"omega3 = {w:.9g}", mech)).rows
        strict += plain.verdict == "WRONG"
    assert strict >= 10          # by 2 % of the value alone most readings would fail


def test_no_follow_through_from_a_mistake_an_answer_given_right_rules_out(
        fourbar: Path) -> None:
    """V_E and V_F both 12 times too large, ω3 right: two slips of units, not ω2 × 12.

    ω2 taken 12 times too large would make ω3 12 times too large as well (the polygon
    is linear in ω2, Sec. 3.4); ω3 is right, so each velocity keeps its own diagnosis.
    """
    from graphkin.check import check, loads_answers

    mech = graphkin.load(fourbar)
    an = solve_analytic(mech)
    text = (f"omega3 = {float(an.omega('3')):.6g}\n"
            f"V_E = {_vec(an.velocity('E'), 'ft/s', 1.0)}\n"
            f"V_F = {_vec(an.velocity('F'), 'ft/s', 1.0)}\n")
    rows = {r.key: r for r in check(mech.solve(), loads_answers(text, mech)).rows}
    assert [rows[k].code for k in ("omega3", "V_E", "V_F")] == ["", "unit:12", "unit:12"]


def test_a_pole_labelled_just_o_is_read_from_the_scale(fourbar: Path, tmp_path: Path,
                                                        velocities: dict[str, np.ndarray],
                                                        capsys: pytest.CaptureFixture[str]
                                                        ) -> None:
    # "Scale: 1 mm = 10 in/s" is a velocity scale, so the pole O is O_V
    dxf = _cad(tmp_path / "v.dxf", velocities, "lines", pole_label="O")
    assert main(["check", str(fourbar), "--drawing", str(dxf)]) == 0
    assert "velocity polygon" in capsys.readouterr().out
