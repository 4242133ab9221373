"""Messages in the user's words (issue 31): what cannot be assembled and why, check's hints.

Every expected number is derived by hand in the comments.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import graphkin
from graphkin.check.compare import direction_text
from graphkin.check.keys import suggest
from graphkin.cli import main
from graphkin.errors import AssemblyError

SHORT_ROD = """
title = "slider-crank whose rod is too short"
units = { length = "mm" }
[links.1]
O = [0, 0]
S = [0, -20]
T = [100, -20]
[links.2]
O = [0, 0]
A = [10, 0]
[links.3]
A = [0, 0]
B = [15, 0]
[links.4]
B = [0, 0]
[[sliders]]
link = 4
on = 1
point = "B"
line = ["S", "T"]
[drive]
link = 2
angle = 90
"""

SHORT_COUPLER = """
title = "four-bar that cannot close"
units = { length = "mm" }
[links.1]
A = [0, 0]
D = [100, 0]
[links.2]
A = [0, 0]
B = [10, 0]
[links.3]
B = [0, 0]
C = [20, 0]
[links.4]
D = [0, 0]
C = [30, 0]
[drive]
link = 2
angle = 90
"""


def test_a_rod_too_short_for_its_slider_line() -> None:
    # crank OA = 10 mm at 90°: A = (0, 10); the slider line y = -20 is 30 mm from A,
    # the rod AB is 15 mm: it needs at least 30 mm
    with pytest.raises(AssemblyError) as e:
        graphkin.loads(SHORT_ROD).solve()
    msg = str(e.value)
    assert "link 3 (AB = 15 mm) cannot reach the slider line of B" in msg
    assert "it needs at least 30 mm" in msg
    assert "l_B(" not in msg and "k_B(" not in msg  # no construction labels


def test_two_links_that_cannot_reach_each_other(tmp_path: Path,
                                                capsys: pytest.CaptureFixture[str]) -> None:
    # B = (0, 10), D = (100, 0): |BD| = sqrt(100² + 10²) = 100.5 mm > BC + DC = 20 + 30 = 50
    f = tmp_path / "m.toml"
    f.write_text(SHORT_COUPLER, encoding="utf-8")
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "m.toml" in err
    assert ("link 3 (BC = 20 mm) and link 4 (DC = 30 mm) cannot reach each other: B and D "
            "are 100.5 mm apart, more than 20 + 30 = 50 mm") in err


def test_a_posture_a_hair_past_its_limit_shows_the_digits_that_differ() -> None:
    # Crank O2A = 2.5, coupler AB = 8 (|AB - O2A| = 5.5), rocker O4B = 5 from O4 = (7, 1.5),
    # driven by the rocker at θ4 = 142.08°: B = O4 + 5 (cos, sin)142.08° = (3.05565, 4.57280),
    # |O2B| = sqrt(3.05565² + 4.57280²) = 5.49978 < 5.5. At four digits both read "5.5"
    # (audit9: "only 5.5 in apart, less than ... 5.5 in").
    text = """units = "in"
[links.1]
O2 = [0, 0]
O4 = [7, 1.5]
[links.2]
O2 = [0, 0]
A = [2.5, 0]
[links.3]
A = [0, 0]
B = [8, 0]
[links.4]
O4 = [0, 0]
B = [5, 0]
[drive]
link = 4
angle = 142.08
"""
    with pytest.raises(AssemblyError) as e:
        graphkin.loads(text).solve()
    assert ("O2 and B are only 5.4998 in apart, less than the difference of their lengths, "
            "5.5 in") in str(e.value)


def test_a_key_in_the_wrong_case_is_suggested_first() -> None:
    # V_e: V_P is as close by letters, but V_E is the same key in another case
    assert suggest("V_e", ["V_P", "V_E", "V_C"]) == " (did you mean 'V_E'?)"
    assert suggest("v_p", ["V_P", "V_E"]) == " (did you mean 'V_P'?)"


@pytest.mark.parametrize(("deg", "text"), [
    (-180.0, "180.00°"), (-179.996, "180.00°"), (180.0 - 1e-12, "180.00°"),
    (-179.99, "-179.99°"), (-0.001, "0.00°"), (359.999, "0.00°"), (90.0, "90.00°"),
])
def test_a_direction_is_never_printed_as_minus_180(deg: float, text: str) -> None:
    assert direction_text(deg) == text


def test_relative_omega_given_for_the_absolute_one(tmp_path: Path, examples: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    # Example 3.1: ω3 = 25.38 rad/s ccw, ω4 = 49.50 rad/s ccw (book: 25.4 and 49.5), so
    # ω3/4 = ω3 − ω4 = −24.12 rad/s, i.e. 24.1 rad/s cw: the relative-ω mistake
    f = tmp_path / "answers.toml"
    f.write_text('omega3 = "24.1 rad/s cw"\n', encoding="utf-8")
    assert main(["check", str(examples / "ex3_1_fourbar.toml"), str(f)]) == 1
    out = capsys.readouterr().out
    assert "ω3/4 = ω3 − ω4" in out and "no usual mistake" not in out
    # the sense is wrong and so is the size: the rule says both
    assert "sense reversed and size outside" in out


def test_rates_at_a_dead_point_are_not_blamed_on_the_file() -> None:
    """Issue 31: the file gives rates; at a dead center they are undefined, not missing."""
    import math

    # slider_crank: crank AB = 50 mm, rod BC = 140 mm, slider line 20 mm below A. A, B, C
    # in line (the slider at its far dead center) when |AC| = 190 mm: x_C = sqrt(190² - 20²)
    text = graphkin.examples.text("slider_crank")
    assert "position = 164" in text
    x = math.sqrt(190.0**2 - 20.0**2)
    sol = graphkin.loads(text.replace("position = 164", f"position = {x!r}")).solve()
    with pytest.raises(ValueError, match="not defined in this posture although the file "
                                         "gives rates") as e:
        sol.velocity("B")
    assert "dead" in str(e.value) and "gives no rates" not in str(e.value)
    # a file without rates still says so
    import re

    bare = re.sub(r"(?m)^(omega|alpha) = .*\n", "", graphkin.examples.text("fourbar"))
    sol = graphkin.loads(bare).solve()
    assert not sol.mechanism.has_rates
    with pytest.raises(ValueError, match="the file gives no rates"):
        sol.omega(3)


def test_a_slot_normal_is_named_in_words(capsys: pytest.CaptureFixture[str],
                                         tmp_path: Path) -> None:
    f = tmp_path / "cam.toml"
    f.write_text(graphkin.examples.text("cam_follower"), encoding="utf-8")
    assert main(["solve", str(f)]) == 0
    out = capsys.readouterr().out
    assert "the slot's normal at B" in out and "n(B)" not in out


@pytest.mark.parametrize(("name", "doc"), [("quick_return", "quick_return.toml"),
                                           ("inline_engine", "slider_crank.toml")])
def test_the_tutorials_files_ship_with_graphkin(name: str, doc: str) -> None:
    """Issue 31: `graphkin example NAME` gives the tutorial's own file (no drift)."""
    tutorial = Path(__file__).parents[1] / "docs" / "tutorial" / doc
    assert graphkin.examples.text(name) == tutorial.read_text(encoding="utf-8")
    assert name in graphkin.examples.names()
    assert getattr(graphkin.examples, name)().title == graphkin.load(tutorial).title


# --- a key written as the book writes it must be quoted in TOML (audit7) -------------------
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from graphkin.errors import InputError  # noqa: E402
from graphkin.files import parse_toml  # noqa: E402

_BOOK_KEYS = st.builds(lambda a, b, c: a + b + c,
                       st.sampled_from(["ω", "α", "A_A", "V_", "θ", "O"]),
                       st.sampled_from(["3", "^c", "^n", "₂", "_B", "^t"]),
                       st.sampled_from(["", "4", "'"]))


@settings(max_examples=40, deadline=None)
@given(key=_BOOK_KEYS, line=st.integers(0, 3))
def test_an_unquoted_book_key_is_told_to_be_quoted(key: str, line: int) -> None:
    # TOML's bare keys are A-Za-z0-9_- only (toml.io, "Keys"): ω3 = ... is a syntax error
    # whose one line must say how to write it, "ω3" = ...
    if all(c.isascii() and (c.isalnum() or c in "_-") for c in key):
        return
    text = "\n".join([f"k{i} = 1" for i in range(line)] + [f'{key} = "5 rad/s"'])
    with pytest.raises(InputError) as err:
        parse_toml(text, "a.toml")
    msg = str(err.value)
    assert len(msg.splitlines()) == 1 and f'"{key}" = ...' in msg


def test_other_toml_errors_get_no_quoting_hint() -> None:
    for text in ('title = "x\n', "[links.1]\nA = [0, 0\n", "a = = 1\n"):
        with pytest.raises(InputError) as err:
            parse_toml(text, "a.toml")
        assert "quote a key" not in str(err.value)
