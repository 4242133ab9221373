"""Drawings and answers that run away or overflow (issue 25: limits before the work).

* A small DXF of nested blocks expanding to over a million entities is refused
  from its block structure before any is read (it ran 31 s), naming the file.
* An SVG of thousands of chained lines is read in linear time (58 s for 4000
  lines, 9 GB for 10 MB): vertices are clustered through a grid, and a file of
  more elements than a polygon drawing could hold is refused while it is walked.
* A scale whose products overflow is refused (``inf in/s``), naming the drawing
  when the scale is the one noted in it; an answer of 1e308 is marked wrong with
  its error's order (``+inf %``).
"""

from __future__ import annotations

import math
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin.check.polygon import _any_within, _cluster
from graphkin.check.svg import MAX_ELEMENTS

sys.path.insert(0, str(Path(__file__).parent))
from test_hostile_corpus import assert_clean, run  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
FOURBAR = ROOT / "examples" / "fourbar.toml"


def _svg(body: str, scale: str = "1 mm = 10 in/s") -> str:
    return ('<svg xmlns="http://www.w3.org/2000/svg" width="200mm" height="200mm" '
            'viewBox="0 0 200 200"><g transform="translate(100,100) scale(1,-1)">' + body
            + f'</g><text x="10" y="190">Scale: {scale}</text></svg>')


def _chain(n: int) -> str:
    pts = [(math.cos(k * 0.01) * 50 + k * 0.001, math.sin(k * 0.013) * 50) for k in range(n + 1)]
    lines = "".join(f'<line x1="{a[0]:.4f}" y1="{a[1]:.4f}" x2="{b[0]:.4f}" y2="{b[1]:.4f}"/>'
                    for a, b in zip(pts, pts[1:]))
    return _svg(lines + '<text x="0" y="0">O_V</text><text x="30" y="10">b</text>')


def test_thousands_of_chained_lines_are_read_in_linear_time(tmp_path: Path) -> None:
    f = tmp_path / "chain.svg"
    f.write_text(_chain(4000), encoding="utf-8")
    t0 = time.perf_counter()
    rc, out, err = run(["check", str(FOURBAR), "--drawing", str(f)])
    assert rc in (0, 1) and not err.strip(), err  # 1: the polygon is marked wrong
    assert time.perf_counter() - t0 < 30.0  # was 58 s: every end against every vertex


def test_more_elements_than_a_polygon_drawing_holds(tmp_path: Path) -> None:
    f = tmp_path / "many.svg"
    f.write_text(_svg('<line x1="0" y1="0" x2="1" y2="1"/>' * (MAX_ELEMENTS + 1)),
                 encoding="utf-8")
    rc, out, err = run(["check", str(FOURBAR), "--drawing", str(f)])
    assert_clean(rc, out, err)
    assert rc == 2 and str(f) in err and "elements" in err, err


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(st.floats(-50, 50), st.floats(-50, 50)), min_size=1, max_size=60),
       st.floats(0.01, 20.0))
def test_grid_clustering_is_the_pairwise_one(pts: list, eps: float) -> None:
    """The grid gives the vertices the former all-pairs loop gave (first within eps)."""
    ends = np.array(pts, dtype=float)
    verts: list[np.ndarray] = []
    index = []
    for e in ends:
        for j, v in enumerate(verts):
            if float(np.hypot(*(e - v))) <= eps:
                index.append(j)
                break
        else:
            index.append(len(verts))
            verts.append(e)
    got_v, got_i = _cluster(ends, eps)
    assert list(got_i) == index and len(got_v) == len(verts)
    others = ends[::2] + 0.5 * eps
    brute = np.array([bool(np.any(np.hypot(*(others - p).T) <= eps)) for p in ends])
    assert np.array_equal(_any_within(ends, others, eps), brute)


def test_nested_blocks_refused_before_reading(tmp_path: Path) -> None:
    ezdxf = pytest.importorskip("ezdxf")
    doc = ezdxf.new()
    b0 = doc.blocks.new("B0")
    for i in range(10):
        b0.add_line((0, i), (1, i))
    for k in range(1, 7):  # 10^6 lines from a file of 24 kB
        b = doc.blocks.new(f"B{k}")
        for i in range(10):
            b.add_blockref(f"B{k - 1}", (i, 0))
    doc.modelspace().add_blockref("B6", (0, 0))
    f = tmp_path / "nested.dxf"
    doc.saveas(f)
    t0 = time.perf_counter()
    rc, out, err = run(["check", str(FOURBAR), "--drawing", str(f)])
    assert_clean(rc, out, err)
    assert rc == 2 and str(f) in err and "through its blocks" in err, err
    assert time.perf_counter() - t0 < 20.0  # was 31 s


def test_a_noted_scale_that_overflows_names_the_drawing(tmp_path: Path) -> None:
    f = tmp_path / "big.svg"
    f.write_text(_svg('<line x1="0" y1="0" x2="30" y2="10"/><text x="31" y="11">b</text>'
                      '<text x="-4" y="1">O_V</text>', scale="1 mm = 1e307 in/s"),
                 encoding="utf-8")
    rc, out, err = run(["check", str(FOURBAR), "--drawing", str(f)])
    assert_clean(rc, out, err)
    assert rc == 2 and f"{f}: its noted scale" in err and "out of range" in err, err
    rc, out, err = run(["check", str(FOURBAR), "--drawing", str(f), "--scale",
                        "1 mm = 1e-200 in/s"])
    assert_clean(rc, out, err)
    assert rc == 2 and "--scale" in err


def test_an_answer_of_1e308_is_wrong_with_a_finite_error(tmp_path: Path) -> None:
    a = tmp_path / "a.toml"
    a.write_text('student = "x"\nomega3 = "1e308 rad/s ccw"\n', encoding="utf-8")
    rc, out, err = run(["check", str(FOURBAR), str(a)])
    assert "Traceback" not in err and "inf" not in out
    assert rc == 1 and "over +1e+06 %" in out and "WRONG" in out, out
