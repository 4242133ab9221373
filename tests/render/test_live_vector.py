"""``graphkin live VECTORFILE``: the construction of C = A + B (Sec. 2.8), dragged in Chromium.

A vector file (docs/formats/vector.md) opens as its construction: the given
vector, the line(s) of known direction, the arc(s) of known magnitude and
their intersections, re-solved in the page by the written-out construction on
every pointer move.  For random files of every case of Table 2.2 (every
vector in turn the known one) the handles are dragged with real pointer
events, and the page's solutions, read back from headless Chromium, equal

* ``graphkin vector`` of the file the page saves (its JSON), and
* the closed forms of Sec. 2.11 (Eqs. 2.43-2.50), written here independently,

to 1e-9, each solution under the branch name the construction's rule gives it
(case 4: ``left`` has the found vertex left of the known vector; case 2:
``behind`` comes first along the direction of the line).  A file whose arc
misses the line (or whose arcs miss, or whose lines are parallel) reads "no
solution" on the page, with ``graphkin vector``'s reason, and never a NaN.
"""

from __future__ import annotations

import cmath
import json
import math
import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, example, given, settings
from hypothesis import strategies as st

from graphkin.cli import main
from graphkin.errors import GraphkinError
from graphkin.kinematics.vector_equation import NAMES, solve_vector_equation
from graphkin.kinematics.vector_file import loads
from graphkin.output.vector import vector_json

GALLERY = Path(__file__).resolve().parents[2] / "gallery" / "vector"
FILES = sorted(GALLERY.glob("*.toml"))
STATE = "window.graphkinLive.state()"


def _page(browser, tmp: Path, text: str, name: str = "v.toml") -> Path:
    src = tmp / name
    src.write_text(text, encoding="utf-8")
    out = tmp / (src.stem + ".html")
    assert main(["live", str(src), "-o", str(out)]) == 0
    browser.open(out)
    return out


def _drag(browser, start, stop, n: int = 4) -> list:
    """Drag with pointer events; returns the handles as they stand before the release."""
    x0, y0 = start
    browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x0, y=y0)
    browser.send("Input.dispatchMouseEvent", type="mousePressed", x=x0, y=y0, button="left",
                 clickCount=1)
    for k in range(1, n + 1):
        browser.send("Input.dispatchMouseEvent", type="mouseMoved", button="left", buttons=1,
                     x=x0 + (stop[0] - x0) * k / n, y=y0 + (stop[1] - y0) * k / n)
    before = browser.js("window.graphkinLive.handles()")
    browser.send("Input.dispatchMouseEvent", type="mouseReleased", x=stop[0], y=stop[1],
                 button="left", clickCount=1)
    return before


# ---- the closed forms of Sec. 2.11, for any vector known ------------------------------------

def _closed_form(kn: dict) -> list[dict[str, complex]] | None:
    """Every solution of C = A + B as complex numbers, by Eqs. 2.43-2.50; None: no solution.

    ``kn`` maps each name to (magnitude or None, angle in radians or None).  The
    known vector Z is moved to the left as the book's C: Z = X' + Y' with
    X' = s_X X and Y' = s_Y Y (C = A + B, A = C - B, B = C - A).
    """
    known = [n for n in NAMES if None not in kn[n]]
    if len(known) == 2:  # case 1 (Eqs. 2.43-2.44): the third by addition or subtraction
        v = {n: kn[n][0] * cmath.exp(1j * kn[n][1]) for n in known}
        if "C" not in v:
            v["C"] = v["A"] + v["B"]
        elif "A" not in v:
            v["A"] = v["C"] - v["B"]
        else:
            v["B"] = v["C"] - v["A"]
        return [v]
    (z,) = known
    x, y = [n for n in NAMES if n != z]
    sign = {"C": {"A": 1, "B": 1}, "A": {"C": 1, "B": -1}, "B": {"C": 1, "A": -1}}[z]
    Z, tz = kn[z]
    zc = Z * cmath.exp(1j * tz)
    out = []
    if kn[x][0] is None and kn[y][0] is None:  # case 3 (Eqs. 2.47-2.48)
        tx, ty = kn[x][1], kn[y][1]
        xm = Z * math.sin(tz - ty) / math.sin(tx - ty)
        ym = Z * math.sin(tz - tx) / math.sin(ty - tx)
        return [{z: zc, x: sign[x] * xm * cmath.exp(1j * tx), y: sign[y] * ym * cmath.exp(1j * ty)}]
    if kn[x][1] is None and kn[y][1] is None:  # case 4 (Eqs. 2.49-2.50)
        X, Y = abs(kn[x][0]), abs(kn[y][0])
        cx = (Z * Z + X * X - Y * Y) / (2 * X * Z)
        cy = (Z * Z + Y * Y - X * X) / (2 * Y * Z)
        if abs(cx) > 1 or abs(cy) > 1:
            return None
        for pm in (1, -1):
            xv = X * cmath.exp(1j * (tz + pm * math.acos(cx)))
            yv = Y * cmath.exp(1j * (tz - pm * math.acos(cy)))
            out.append({z: zc, x: sign[x] * xv, y: sign[y] * yv})
        return out
    # case 2 (Eqs. 2.45-2.46): the line's vector L (direction known), the arc's R (magnitude)
    line, arc = (x, y) if kn[x][0] is None else (y, x)
    tl, R = kn[line][1], abs(kn[arc][0])
    s = Z * math.sin(tz - tl) / R
    if abs(s) > 1:
        return None
    for tr in (tl + math.asin(s), tl + math.pi - math.asin(s)):
        lm = Z * math.cos(tz - tl) - R * math.cos(tr - tl)
        out.append({z: zc, line: sign[line] * lm * cmath.exp(1j * tl),
                    arc: sign[arc] * R * cmath.exp(1j * tr)})
    return out


def _named(kn: dict, sols: list[dict[str, complex]]) -> dict[str | None, dict[str, complex]]:
    """Each solution under the branch the construction's rule names (Side / Along)."""
    known = [n for n in NAMES if None not in kn[n]]
    if len(sols) == 1:
        return {None: sols[0]}  # cases 1 and 3: one solution
    (z,) = known
    ends = {"A": ("O", "P"), "B": ("P", "T"), "C": ("O", "T")}
    (free,) = {"O", "P", "T"} - set(ends[z])

    def found(s: dict[str, complex]) -> complex:  # the found vertex, from the tail of Z
        pts = {"O": 0j, "P": s["A"], "T": s["C"]}  # O at the origin: P = A, T = C
        return pts[free] - pts[ends[z][0]]

    if all(kn[n][1] is None for n in NAMES if n != z):  # case 4: left of the known vector
        return {"left" if (s[z].conjugate() * found(s)).imag > 0 else "right": s for s in sols}
    # case 2: along the known direction of the line's vector, "behind" comes first
    (line,) = [n for n in NAMES if n != z and kn[n][0] is None]
    u = cmath.exp(1j * kn[line][1])
    first, second = sorted(sols, key=lambda s: (u.conjugate() * found(s)).real)
    return {"behind": first, "ahead": second}


def _knowns(text: str) -> dict:
    vf = loads(text)
    return {n: (vf.knowns[n].magnitude, vf.knowns[n].angle) for n in NAMES}


def _check_page(browser, tmp: Path) -> tuple[dict, str]:
    """The page's values against graphkin vector of the saved file and Sec. 2.11's forms."""
    state = browser.js(STATE)
    saved = browser.js("window.graphkinLive.toml()")
    body = browser.js("document.body.innerText")
    assert "NaN" not in body and "undefined" not in body
    (tmp / "saved.toml").write_text(saved, encoding="utf-8")
    vf = loads(saved, source="saved.toml")
    kn = {n: (vf.knowns[n].magnitude, vf.knowns[n].angle) for n in NAMES}
    # the page's given values are the saved file's (what it saves is what it shows)
    for n in NAMES:
        for got, ref in zip((state["given"][n]["m"], state["given"][n]["a"]), kn[n]):
            assert (got is None) == (ref is None), n
            if ref is not None:
                assert abs(got - ref) <= 1e-12 * (1 + abs(ref)), n
    oracle = _closed_form(kn)
    sols = state["solutions"]
    try:
        result = solve_vector_equation(*(vf.knowns[n] for n in NAMES))
    except GraphkinError as exc:
        # no solution: the page says so in graphkin's words, every solution null, no number
        assert all(s is None for s in sols), "graphkin vector found none, the page did"
        said = browser.js("document.getElementById('gk-status').textContent")
        assert "has no solution" in said and said.split("has no solution")[1] in str(exc)
        assert "no solution" in browser.js("document.getElementById('gk-table').textContent")
        # (the closed form would find one only at a tangency's round-off, skipped)
        assert oracle is None, f"Sec. 2.11 finds a solution, graphkin vector not: {exc}"
        return state, "none"
    assert oracle is not None, "graphkin vector found a solution, Sec. 2.11 none"
    ref = vector_json(vf, result)["solutions"]
    named = _named(kn, oracle)
    size = 1.0 + max(abs(v) for s in oracle for v in s.values())
    assert len(sols) == len(ref) == len(named)
    for page, cli in zip(sols, ref):
        assert page is not None
        assert page["branch"] == cli["branch"]
        exact = named[cli["branch"]]
        for n in NAMES:
            for k in ("x", "y", "magnitude"):
                assert abs(page[n][k] - cli[n][k]) <= 1e-9 * size, (n, k, page[n], cli[n])
            d = page[n]["angle_deg"] - cli[n]["angle_deg"]
            assert abs(math.remainder(d, 360.0)) <= 1e-9 * 360, (n, page[n], cli[n])
            # the closed form, Sec. 2.11: the vector itself, to 1e-9 of the figure's size
            assert abs(complex(page[n]["x"], page[n]["y"]) - exact[n]) <= 1e-9 * size, \
                (n, page[n], exact[n])
    return state, "solved"


# ---- random vector files of every case ----------------------------------------------------

@st.composite
def vector_files(draw) -> str:
    """A vector file of a random case, every vector in turn the known one (or case 1's two)."""
    case = draw(st.sampled_from((1, 2, 3, 4)))
    mag = st.floats(0.5, 20.0).map(lambda v: round(v, 3))
    ang = st.floats(-180.0, 180.0).map(lambda v: round(v, 2))
    parts = {n: {"magnitude": draw(mag), "angle": draw(ang)} for n in NAMES}
    if case == 1:
        u = draw(st.sampled_from(NAMES))
        parts[u] = {}
    else:
        z = draw(st.sampled_from(NAMES))
        x, y = [n for n in NAMES if n != z]
        if case == 2:
            if draw(st.booleans()):
                x, y = y, x
            del parts[x]["magnitude"], parts[y]["angle"]
        elif case == 3:
            del parts[x]["magnitude"], parts[y]["magnitude"]
            d = math.radians(parts[x]["angle"] - parts[y]["angle"])
            assume(abs(math.sin(d)) > 0.05)  # not nearly parallel (tested on its own below)
        else:
            del parts[x]["angle"], parts[y]["angle"]
    head = []
    if draw(st.booleans()):
        head.append('units = "in"')
    branch = {2: ("behind", "ahead"), 4: ("left", "right")}.get(case)
    if branch and draw(st.booleans()):
        head.append(f'branch = "{draw(st.sampled_from(branch))}"')
    body = []
    for n in NAMES:
        body.append(f"[{n}]")
        body += [f"{k} = {v}" for k, v in parts[n].items()]
    return "\n".join(head + body) + "\n"


def _margin(kn: dict) -> float:
    """How far from a tangency (relative): a verdict there rests on round-off; skipped."""
    known = [n for n in NAMES if None not in kn[n]]
    if len(known) != 1:
        return 1.0
    (z,) = known
    Z = abs(kn[z][0])
    others = [n for n in NAMES if n != z]
    if all(kn[n][1] is None for n in others):
        X, Y = (abs(kn[n][0]) for n in others)
        return min(abs(X + Y - Z), abs(abs(X - Y) - Z)) / (X + Y + Z)
    lines = [n for n in others if kn[n][0] is None]
    if len(lines) == 1:
        (arc,) = [n for n in others if n not in lines]
        R = abs(kn[arc][0])
        return abs(R - abs(Z * math.sin(kn[z][1] - kn[lines[0]][1]))) / (R + Z)
    return 1.0


# the drawing moved under the pointer when a status line came and went while dragging
@example(text="[A]\nmagnitude = 0.5\n[B]\nmagnitude = 1.188\nangle = 0.0\n[C]\nangle = 29.0\n",
         moves=[(2, 0, 1), (2, 0, -6), (0, -1, 0)])
@settings(max_examples=30, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(text=vector_files(),
       moves=st.lists(st.tuples(st.integers(0, 5), st.integers(-70, 70), st.integers(-70, 70)),
                      min_size=3, max_size=3))
def test_random_files_dragged_equal_graphkin_vector_and_the_closed_form(browser, text, moves):
    assume(_margin(_knowns(text)) > 1e-6)
    with tempfile.TemporaryDirectory(prefix="gk-live-vector-") as d:
        tmp = Path(d)
        _page(browser, tmp, text)
        _check_page(browser, tmp)                  # as the file says
        handles = browser.js("window.graphkinLive.handles()")
        for i, (j, dx, dy) in enumerate(moves):
            k = (i + j) % len(handles)             # which handle: each given part in turn
            h = handles[k]
            if h["client"] is None:
                continue
            x, y = h["client"]
            on_top = browser.js(f"document.elementFromPoint({x}, {y}).getAttribute("
                                "'data-handle')")
            if on_top != str(k):                   # another handle lies over it
                continue
            stop = (min(max(x + dx, 20), 700), min(max(y + dy, 200), 650))
            before = _drag(browser, (x, y), stop)
            moved = before[k]["client"]
            # the handle followed the pointer (an arc keeps a least radius)
            if moved is not None and before[k]["kind"] != "magnitude":
                assert math.dist(moved, stop) < 1.5, (h, moved, stop)
            state = browser.js(STATE)
            kn = {n: (state["given"][n]["m"], state["given"][n]["a"]) for n in NAMES}
            if _margin(kn) > 1e-6:
                _check_page(browser, tmp)
            handles = browser.js("window.graphkinLive.handles()")
        assert browser.errors() == []


# ---- the gallery, no solution, the branch, undo and reset ---------------------------------

def test_the_gallery_has_vector_files() -> None:
    assert {p.name for p in FILES} >= {"case2.toml", "case4.toml"}


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_a_gallery_vector_file_opens_as_graphkin_vector_solves_it(browser, tmp_path, path,
                                                                  capsys) -> None:
    out = tmp_path / "page.html"
    assert main(["live", str(path), "-o", str(out)]) == 0
    assert "wrote" in capsys.readouterr().err
    html = out.read_text(encoding="utf-8")
    assert len(html.encode("utf-8")) < 1_000_000
    assert "<script src" not in html and "<link" not in html  # offline: nothing fetched
    assert main(["vector", str(path), "--json"]) == 0
    ref = json.loads(capsys.readouterr().out)["solutions"]
    browser.open(out)
    sols = browser.js(STATE)["solutions"]
    assert [s["branch"] for s in sols] == [r["branch"] for r in ref]
    for s, r in zip(sols, ref):
        for n in NAMES:
            for k in ("x", "y", "magnitude", "angle_deg"):
                assert abs(s[n][k] - r[n][k]) <= 1e-9 * (1 + abs(r[n][k])), (n, k)
    # the table reads as graphkin vector's report: "3.9282 in ∠30°"
    table = browser.js("document.getElementById('gk-table').textContent")
    assert f"{ref[0]['A']['magnitude']:.6g} in \u2220{ref[0]['A']['angle_deg']:.6g}\u00b0" in table
    assert browser.errors() == []


def test_no_solution_reads_as_such_in_graphkin_vectors_words(browser, tmp_path, capsys) -> None:
    # case 2 (Fig. 2.11): the line through O at 30° passes 8 sin 30° = 4 from T, the arc's
    # radius is 3 < 4: the arc misses the line
    text = 'units = "in"\n[C]\nmagnitude = 8\nangle = 0\n[A]\nangle = 30\n[B]\nmagnitude = 3\n'
    _page(browser, tmp_path, text, "miss.toml")
    state = browser.js(STATE)
    assert state["solutions"] == [None, None]
    said = browser.js("document.getElementById('gk-status').textContent")
    assert said == ("case 2 has no solution: the line with the direction of A passes 4 from the "
                    "center of the arc of radius |B| = 3, so they do not meet")
    table = browser.js("document.getElementById('gk-table').textContent")
    assert table.count("no solution") == 2 and "NaN" not in table
    assert main(["vector", str(tmp_path / "miss.toml")]) == 2
    assert said.split(": ", 1)[1] in capsys.readouterr().err
    # case 4: |A| + |B| = 7 < |C| = 9; case 3: parallel directions
    _page(browser, tmp_path, "[C]\nmagnitude = 9\nangle = 10\n[A]\nmagnitude = 3\n[B]\n"
                             "magnitude = 4\n", "arcs.toml")
    said = browser.js("document.getElementById('gk-status').textContent")
    assert "the arcs do not meet: |A| + |B| = 7 < |C| = 9" in said
    _page(browser, tmp_path, "[C]\nmagnitude = 5\nangle = 0\n[A]\nangle = 40\n[B]\n"
                             "angle = 220\n", "parallel.toml")
    said = browser.js("document.getElementById('gk-status').textContent")
    assert "are parallel; the lines are parallel but distinct" in said
    assert browser.js(STATE)["solutions"] == [None]
    assert "NaN" not in browser.js("document.body.innerText")
    assert browser.errors() == []


def test_the_chosen_solution_switches_and_is_saved(browser, tmp_path, capsys) -> None:
    _page(browser, tmp_path, (GALLERY / "case4.toml").read_text(encoding="utf-8"), "c4.toml")
    assert browser.js(STATE)["chosen"] == 0
    assert "branch" not in browser.js("window.graphkinLive.toml()")  # the file's, unchanged
    browser.js("document.getElementById('gk-solution').value = '1';"
               "document.getElementById('gk-solution').dispatchEvent(new Event('change'))")
    assert browser.js(STATE)["chosen"] == 1
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    assert main(["vector", str(saved)]) == 0
    out = capsys.readouterr().out
    # Eqs. 2.49-2.50: the 3-4-5 triangle's right branch, θ_A = -acos(3/5), θ_B = +acos(4/5)
    assert "solution 1 (right):" in out and "left" not in out
    assert f"∠{-math.degrees(math.acos(0.6)):.6g}°" in out
    row = browser.js("document.querySelector('#gk-table tr.gk-chosen').textContent")
    assert row.startswith("solution 2 (right)")


def test_undo_and_reset_return_the_files_values(browser, tmp_path) -> None:
    text = (GALLERY / "case2.toml").read_text(encoding="utf-8")
    _page(browser, tmp_path, text, "c2.toml")
    first = browser.js("window.graphkinLive.toml()")
    h = browser.js("window.graphkinLive.handles()")
    tip = next(x for x in h if x["kind"] == "vector")["client"]
    _drag(browser, tip, (tip[0] + 40, tip[1] - 30))
    _drag(browser, *(lambda c: (c, (c[0] - 25, c[1] + 15)))(
        next(x for x in browser.js("window.graphkinLive.handles()")
             if x["kind"] == "magnitude")["client"]))
    assert browser.js("window.graphkinLive.toml()") != first
    browser.js("document.getElementById('gk-undo').click()")
    browser.js("document.getElementById('gk-undo').click()")
    assert browser.js("window.graphkinLive.toml()") == first
    _drag(browser, tip, (tip[0] - 30, tip[1] - 30))
    browser.js("document.getElementById('gk-reset').click()")
    assert browser.js("window.graphkinLive.toml()") == first
    # the unedited file's values are kept as it writes them (C = 8, A's angle 30)
    vf = loads(first)
    assert vf.knowns["C"].magnitude == 8.0 and vf.knowns["A"].angle == math.radians(30)
    assert np.isfinite(browser.js(STATE)["solutions"][0]["A"]["magnitude"])
    assert browser.errors() == []


def test_a_hostile_title_is_text_and_a_magnitude_with_a_unit_is_kept_until_dragged(
        browser, tmp_path) -> None:
    title = "</script><b id=\"gk-x\">x</b>&amp; \u2028"
    text = (f"title = {json.dumps(title)}\nunits = {{ length = \"in\" }}\n"
            "[C]\nmagnitude = \"203.2 mm\"\nangle = \"0 rad\"\n[A]\nangle = 30\n[B]\n"
            "magnitude = 5\n")
    _page(browser, tmp_path, text, "units.toml")
    assert browser.js("document.getElementById('gk-x')") is None
    assert browser.js("document.querySelector('h1').textContent") == title
    saved = browser.js("window.graphkinLive.toml()")
    assert 'magnitude = "203.2 mm"' in saved and 'angle = "0 rad"' in saved
    # 203.2 mm = 8 in: the gallery's case 2, A = 8 cos 30° ∓ 3 (Eqs. 2.45-2.46)
    sols = browser.js(STATE)["solutions"]
    assert abs(sols[0]["A"]["magnitude"] - (8 * math.cos(math.radians(30)) - 3)) < 1e-9
    tip = next(x for x in browser.js("window.graphkinLive.handles()") if x["kind"] == "vector")
    _drag(browser, tip["client"], (tip["client"][0] + 30, tip["client"][1]))
    vf = loads(browser.js("window.graphkinLive.toml()"))  # now a number in the file's unit
    assert isinstance(vf.knowns["C"].magnitude, float) and vf.knowns["C"].magnitude > 8.0
    _check_page(browser, tmp_path)


@pytest.mark.parametrize(("text", "said"), [
    ('branch = "ahead"\n[C]\nmagnitude = 5\nangle = 0\n[A]\nmagnitude = 3\n[B]\nmagnitude = 4\n',
     "branch: case 4 has the branches left, right, not 'ahead'"),
    ("[C]\nmagnitude = 5\n[A]\nmagnitude = 3\n[B]\nmagnitude = 4\n",
     "C = A + B is solvable for exactly two unknowns"),
])
def test_a_vector_file_graphkin_vector_refuses_is_refused_in_its_line(tmp_path, capsys, text,
                                                                      said) -> None:
    src = tmp_path / "bad.toml"
    src.write_text(text, encoding="utf-8")
    assert main(["vector", str(src)]) == 2
    ref = capsys.readouterr().err.strip()
    assert main(["live", str(src), "-o", str(tmp_path / "p.html")]) == 2
    err = capsys.readouterr().err.strip()
    assert err == ref and len(err.splitlines()) == 1 and said in err
    assert not (tmp_path / "p.html").exists()


@pytest.mark.parametrize("C", [7.0, 7.0 * (1 + 1e-12), 7.0 * (1 - 1e-12)])
def test_tangent_arcs_solve_on_the_page_as_in_graphkin_vector(browser, tmp_path, C) -> None:
    # |A| + |B| = |C| (3 + 4 = 7): the arcs touch, one solution twice (Sec. 2.8); a change
    # of 1e-12 of the size does not move the verdict, on the page or in graphkin vector
    text = f"[C]\nmagnitude = {C!r}\nangle = 20\n[A]\nmagnitude = 3\n[B]\nmagnitude = 4\n"
    r = solve_vector_equation(*(loads(text).knowns[n] for n in NAMES))
    _page(browser, tmp_path, text, "touch.toml")
    sols = browser.js(STATE)["solutions"]
    assert len(sols) == len(r.solutions) == 2 and None not in sols
    for s in sols:  # A and B along C: the touching point is 3/7 of the way from O to T
        for n in NAMES:  # the angle to the square root of round-off (a tangency's h = √q)
            assert abs(s[n]["angle_deg"] - 20.0) < 1e-4, (n, s[n])
