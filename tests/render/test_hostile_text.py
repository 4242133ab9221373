"""User strings never break a drawing: point names and titles are text, not mathtext (issue 14)."""

from __future__ import annotations

import re
from html import unescape

import pytest
from spec_data import EXAMPLES

import graphkin
from graphkin.render import draw, to_bytes
from graphkin.render.text import is_math, math_escape, math_ok, plain

HOSTILE = ["P%", "_", "a_b_c", "$\\frac{$", "$x$", "a^b{", "}{", "\\", "&~"]


def _renamed(name: str, title: str) -> graphkin.Mechanism:
    """Example 4.7 (cam and follower, with a Coriolis component) with C renamed and a new title."""
    text = (EXAMPLES / "ex4_7_cam_follower.toml").read_text()
    quoted = '"' + name.replace("\\", "\\\\").replace('"', '\\"') + '"'
    text = re.sub(r'(?<![\w"])C(?![\w"])', lambda _m: quoted, text)
    t = title.replace("\\", "\\\\")
    text = re.sub(r"^title = .*$", lambda _m: f'title = "{t}"', text, flags=re.M)
    return graphkin.loads(text)


def _texts(svg: bytes) -> list[str]:
    return [unescape(t) for t in re.findall(r"<text[^>]*>([^<]*)<", svg.decode())]


@pytest.mark.parametrize("name", HOSTILE)
def test_hostile_point_name_and_title_draw_as_typed(name):
    mech = _renamed(name, f"T {name} $a$ $\\frac{{$")
    sol = mech.solve()
    for diagram in ("all", "acceleration", "centers", "curvature"):
        svg = to_bytes(draw(sol, diagram).figure)  # no ParseSyntaxException
        texts = _texts(svg)
        if diagram in ("all", "acceleration"):
            # the point's letter is printed as typed (the SVG keeps text as text)
            assert name in texts, (diagram, texts)
        # the title is printed as typed, dollar signs and all (a sheet with curvature
        # figures adds whose curvature they show: ": curvature of link 3")
        title = f"T {name} $a$ $\\frac{{$"
        assert any(t == title or t.startswith(title + ": curvature of link") for t in texts)


def test_escapes_parse_or_stay_plain():
    for name in HOSTILE:
        assert not is_math(plain(name))
        inner = math_escape(name)
        if inner is not None:
            assert math_ok(f"$A^{{n}}_{{{inner}}}$"), name
    assert math_escape("x$") is None
