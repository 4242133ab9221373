"""``[[bodies]]``: a drawing-only description of what a link looks like (Ex. 4.7, Fig. 4.18a)."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

import graphkin
from graphkin.cli import main

ROOT = Path(__file__).resolve().parents[2]
CAM = (ROOT / "tests/data/spec/ex4_7_cam_follower.toml").read_text(encoding="utf-8")


def _with(body: str) -> str:
    return CAM.replace("[drive]", textwrap.dedent(body) + "\n[drive]", 1)


def test_a_body_changes_no_result():
    # drawing only: the disc of radius 1.5 in about B adds no constraint (Example 4.7)
    plain = graphkin.loads(CAM).solve()
    drawn = graphkin.loads(_with("""
        [[bodies]]
        link = 2
        circle = { center = "B", radius = "38.1 mm" }
        [[bodies]]
        link = 3
        face = [[-1.4, 0.6], [-1.4, 3.6]]
        [[bodies]]
        link = 3
        outline = ["D", "C", [-1.4, 0]]
        """)).solve()
    assert drawn.omega("3") == plain.omega("3") and drawn.alpha("3") == plain.alpha("3")
    b = drawn.mechanism.bodies
    assert [x.kind for x in b] == ["circle", "face", "outline"]
    assert b[0].center == (3.0, 0.0) and b[0].radius == pytest.approx(1.5, rel=1e-12)  # 38.1/25.4
    assert b[2].points[1] == (-1.4, 2.142428528562855)


CASES = [
    ("no shape", "[[bodies]]\nlink = 2\n", "bodies[0]", "exactly one"),
    ("two shapes", '[[bodies]]\nlink = 2\ncircle = { center = "B", radius = 1 }\n'
     'face = [[0, 0], [1, 0]]\n', "bodies[0]", "exactly one"),
    ("no link", '[[bodies]]\nlink = 7\ncircle = { center = "B", radius = 1 }\n',
     "bodies[0].link", "no link '7'"),
    ("point of another link", '[[bodies]]\nlink = 2\ncircle = { center = "C", radius = 1 }\n',
     "bodies[0].circle.center", "link 2 has no point 'C'"),
    ("negative radius", '[[bodies]]\nlink = 2\ncircle = { center = "B", radius = -1 }\n',
     "bodies[0].circle.radius", "positive"),
    ("radius not a length", '[[bodies]]\nlink = 2\ncircle = { center = "B", radius = "1 s" }\n',
     "bodies[0].circle.radius", ""),
    ("no radius", '[[bodies]]\nlink = 2\ncircle = { center = "B" }\n',
     "bodies[0].circle", "radius"),
    ("face of one point", "[[bodies]]\nlink = 3\nface = [[0, 0]]\n", "bodies[0].face", "two"),
    ("degenerate face", "[[bodies]]\nlink = 3\nface = [[1, 1], [1, 1]]\n", "bodies[0].face",
     "degenerate"),
    ("outline of two", '[[bodies]]\nlink = 3\noutline = ["D", "C"]\n', "bodies[0].outline",
     "three"),
    ("NaN corner", "[[bodies]]\nlink = 3\noutline = [[0, 0], [1, nan], [0, 1]]\n",
     "bodies[0].outline[1]", "finite"),
    ("misspelt key", '[[bodies]]\nlink = 2\ncirlce = { center = "B", radius = 1 }\n',
     "bodies[0].cirlce", "did you mean 'circle'"),
    ("misspelt circle key", '[[bodies]]\nlink = 2\ncircle = { centre = "B", radius = 1 }\n',
     "bodies[0].circle.centre", "did you mean 'center'"),
]


@pytest.mark.parametrize("name,body,key,reason", CASES, ids=[c[0] for c in CASES])
def test_a_bad_body_exits_2_with_one_line(tmp_path, capsys, name, body, key, reason):
    path = tmp_path / "cam.toml"
    path.write_text(_with(body), encoding="utf-8")
    code = main(["solve", str(path)])
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err, err
    assert str(path) in lines[0] and key in lines[0] and reason in lines[0], lines[0]
