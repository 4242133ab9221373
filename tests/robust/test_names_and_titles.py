"""The user's names and titles never change an answer nor reach code (issue 25, items 1 and 3).

Two classes of hostile text:

* **Point names spelt like the constructions' own labels** (``F_43``, ``P_4``,
  ``θ2``, ``ω3``, ``n_1-4``, ``I13``, ``s4``): such a point was read for the
  force, angle or rate of that name (Ex 11.4 gave T12 = 1.00 lbf·in) or
  crashed.  Every name of that grammar is refused in one line naming the
  key; every other name -- however odd -- gives exactly the answers of the
  file with the plain name.
* **Titles** with a superscript ``²``, a ligature, quotes, a newline,
  ``__import__``, right-to-left marks and ``<!--<script>``: every command ends
  cleanly, the generated sweep function holds none of it, and the animate
  page's data parses back to the very title.
"""

from __future__ import annotations

import io
import json
import keyword
import re
import sys
import tokenize
from pathlib import Path

import pytest

import graphkin
from graphkin.mechanisms.parse import LABEL_PREFIXES, LINK_SYMBOLS

sys.path.insert(0, str(Path(__file__).parent))
from test_hostile_corpus import assert_clean, run  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
EX11_4 = ROOT / "gallery" / "mechanisms" / "ex11_4_slider_crank_friction.toml"
FOURBAR = ROOT / "graphkin" / "examples" / "data" / "fourbar.toml"


def _renamed(path: Path, old: str, new: str) -> str:
    """The file's text with point ``old`` renamed ``new`` (a quoted TOML key)."""
    quoted = json.dumps(new, ensure_ascii=True)
    text = path.read_text(encoding="utf-8")
    text = re.sub(rf"^{old} = ", lambda _m: f"{quoted} = ", text, flags=re.M)
    return text.replace(f'"{old}"', quoted)


def _label_like(links: list[str]) -> list[str]:
    names = [f"{p}_{x}" for p in LABEL_PREFIXES for x in ("43", "4", "1-4", "Q")]
    names += [f"{s}{lid}" for s in LINK_SYMBOLS for lid in links]
    names += [f"I{a}{b}" for a in links for b in links if a != b]
    names += ["I1-4", "θ", "ω_3", "α"]
    return names


@pytest.mark.parametrize("name", _label_like(["1", "2", "3", "4"]))
def test_names_like_labels_are_refused_in_one_line(name: str, tmp_path: Path) -> None:
    f = tmp_path / "m.toml"
    f.write_text(_renamed(EX11_4, "Q", name), encoding="utf-8")
    rc, out, err = run(["solve", str(f)])
    assert_clean(rc, out, err)
    assert rc == 2 and f"links.4.{name}: a point cannot be named" in err, err


def _numbers(data: object, name: str, path: str = "") -> dict[str, float]:
    """Every number of a JSON answer by its path, the renamed point's key written @."""
    out: dict[str, float] = {}
    if isinstance(data, dict):
        for k, v in data.items():
            out.update(_numbers(v, name, f"{path}/{'@' if k == name else k}"))
    elif isinstance(data, list):
        for i, v in enumerate(data):
            out.update(_numbers(v, name, f"{path}/{i}"))
    elif isinstance(data, (int, float)) and not isinstance(data, bool):
        out[path] = float(data)
    return out


def _answers(path: Path, name: str) -> dict[str, float]:
    rc, out, err = run(["solve", str(path), "--json"])
    assert rc == 0, err
    return _numbers(json.loads(out), name)


def _torques(path: Path) -> str:
    rc, out, err = run(["sweep", str(path), "--count", "4", "--torque"])
    assert rc == 0, err
    return "\n".join(",".join(r.split(",")[:1] + r.split(",")[-1:]) for r in out.splitlines())


ODD = ["a_b_c", "O_2", "P%", "Ω", "x_B", "l"]


@pytest.mark.parametrize("name", ODD)
def test_other_names_give_the_same_answers(name: str, tmp_path: Path) -> None:
    """Ex 11.4 with its load point renamed: the same forces, torque and swept torque."""
    base, f = tmp_path / "base.toml", tmp_path / "m.toml"
    base.write_text(_renamed(EX11_4, "Q", "Zq"), encoding="utf-8")
    f.write_text(_renamed(EX11_4, "Q", name), encoding="utf-8")
    ref, got = _answers(base, "Zq"), _answers(f, name)
    assert len(ref) > 50 and got == ref
    assert _torques(f) == _torques(base)


HOSTILE_TITLE = ('x² ﬁ "quoted" \'single\' \\ back\nnew line __import__("os").system("x") '
                 '\u202eRTL\u202c \u200f <!--<script> </script> ]]> {{}} %s ${x}')


def _titled(tmp_path: Path) -> Path:
    text = FOURBAR.read_text(encoding="utf-8")
    text = re.sub(r"^title = .*$", lambda _m: "title = " + json.dumps(HOSTILE_TITLE),
                  text, flags=re.M)
    f = tmp_path / "t.toml"
    f.write_text(text, encoding="utf-8")
    return f


def test_a_hostile_title_through_every_command(tmp_path: Path) -> None:
    f = _titled(tmp_path)
    assert graphkin.load(f).title == HOSTILE_TITLE
    for argv in (["solve", "{f}"], ["solve", "{f}", "--json"],
                 ["sweep", "{f}", "--count", "6", "--torque"],
                 ["sweep", "{f}", "--count", "6", "--singular", "--centers"],
                 ["plot", "{f}", "--count", "12", "-o", "{t}/p.svg"],
                 ["animate", "{f}", "--count", "6", "-o", "{t}/a.html"],
                 ["steps", "{f}", "-o", "{t}/s.html"],
                 ["draw", "{f}", "-d", "velocity", "-o", "{t}/d.svg"]):
        rc, out, err = run([a.format(f=f, t=tmp_path) for a in argv])
        assert_clean(rc, out, err)
        # no forces in the file: sweep --torque is refused in one line, all else succeeds
        assert rc == (2 if "--torque" in argv else 0), (argv, err)
    # the other files with a title or a name: a student's answers and a vector equation
    ans = tmp_path / "ans.toml"
    ans.write_text(f"student = {json.dumps(HOSTILE_TITLE)}\nomega3 = \"25 rad/s ccw\"\n",
                   encoding="utf-8")
    rc, out, err = run(["check", str(f), str(ans), "--csv", str(tmp_path / "marks.csv")])
    assert "Traceback" not in err and rc in (0, 1), err
    vec = tmp_path / "v.toml"
    vec.write_text(f"title = {json.dumps(HOSTILE_TITLE)}\n[C]\nmagnitude = 5\nangle = 0\n"
                   "[A]\nmagnitude = 3\n[B]\nmagnitude = 4\n", encoding="utf-8")
    rc, out, err = run(["vector", str(vec)])
    assert_clean(rc, out, err)
    assert rc == 0, err
    page = (tmp_path / "a.html").read_text(encoding="utf-8")
    blob = re.search(r'<script type="application/json" id="cycle-data">(.*?)</script>', page,
                     re.S)
    assert blob is not None and "<" not in blob.group(1)
    assert json.loads(blob.group(1))["title"] == HOSTILE_TITLE
    # the page's markup holds the title escaped: one <script> element of data, one of code
    assert page.count("<script") == 2 and "<!--<script>" not in page


def test_generated_code_holds_no_user_text(tmp_path: Path) -> None:
    from graphkin.kinematics.sweep.engine import _Engine
    from graphkin.kinematics.sweep.fast import _build
    from graphkin.tolerance import DEFAULT_TOL

    mech = graphkin.load(_titled(tmp_path))
    fast = _build(_Engine(mech, DEFAULT_TOL))
    assert fast is not None
    src = fast.generated.source
    assert src.isascii()
    toks = list(tokenize.generate_tokens(io.StringIO(src).readline))
    # no string literal at all, and every name graphkin's own or Python's
    assert not [t for t in toks if t.type == tokenize.STRING]
    names = {t.string for t in toks if t.type == tokenize.NAME}
    ours = re.compile(r"^(_[a-z]+\d*|_gk_sweep)$")
    python = set(keyword.kwlist) | {"np", "float", "max", "min", "abs", "all", "any"}
    assert {n for n in names if not ours.match(n)} <= python, names


@pytest.mark.parametrize("argv,option", [
    (["animate", "{f}", "-o", "{f}"], "--output"),
    (["animate", "{f}", "-o", "{link}"], "--output"),
    (["animate", "{f}", "--count", "4", "--gif", "{f}"], "--gif"),
    (["animate", "{f}", "--count", "4", "--gif", "{t}/a.toml"], "--gif"),
])
def test_animate_never_overwrites_the_input(argv: list[str], option: str,
                                            tmp_path: Path) -> None:
    f = tmp_path / "m.toml"
    text = FOURBAR.read_text(encoding="utf-8")
    f.write_text(text, encoding="utf-8")
    link = tmp_path / "same.html"
    link.symlink_to(f)
    rc, out, err = run([a.format(f=f, link=link, t=tmp_path) for a in argv])
    assert_clean(rc, out, err)
    assert rc == 2 and option in err, err
    assert f.read_text(encoding="utf-8") == text


def test_frames_never_overwrite_an_input(tmp_path: Path) -> None:
    f = tmp_path / "cycle-000.svg"  # a mechanism file named like the first frame
    text = FOURBAR.read_text(encoding="utf-8")
    f.write_text(text, encoding="utf-8")
    rc, out, err = run(["animate", str(f), "--count", "3", "--frames", str(tmp_path)])
    assert_clean(rc, out, err)
    assert rc == 2 and "--frames" in err and f.read_text(encoding="utf-8") == text
