"""Coupler-curve synthesis through four precision points by point reduction (Sec. 9.9)."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.cli import main
from graphkin.errors import InputError
from graphkin.synthesis import loads_spec, synthesize
from graphkin.synthesis.coupler import coupler_curve
from graphkin.synthesis.postures import evaluate_points

SPEC = """title = "Coupler-curve synthesis"
units = "in"
[coupler_curve]
points = [[0, 0], [1, 0.6], [2, 0.7], [3, 0.2]]
O4 = [1.5, -2]
O2 = [-1, -1.5]
R = 2.0
r = 1.5
"""


@given(pts=st.lists(st.tuples(st.floats(-3, 3), st.floats(-3, 3)), min_size=4, max_size=4),
       big_r=st.floats(1.0, 4.0), r=st.floats(1.0, 4.0), o4=st.floats(-4, 4),
       o2=st.floats(-4, 4))
@settings(max_examples=20, deadline=None)
def test_the_linkage_passes_through_every_precision_point(pts, big_r, r, o4, o2) -> None:
    c = np.array([complex(x, y) for x, y in pts])
    assume(min(abs(c[i] - c[j]) for i in range(4) for j in range(i)) > 0.3)
    try:
        res = coupler_curve(c, complex(o4, -3.0), complex(o2, -2.0), big_r, r)
    except InputError:
        assume(False)
        return
    link = res.linkage
    # independent of the construction: the coupler carried rigidly by A and C (complex
    # numbers) puts B_j on one circle about O4 and A_j on one circle about O2 (Sec. 9.9)
    a = evaluate_points(res.construction, ["A1", "A2", "A3", "A4"])
    a = np.array([a[f"A{j}"] for j in (1, 2, 3, 4)])
    turn = (a - c) / (a[0] - c[0])
    assert np.allclose(np.abs(turn), 1.0, atol=1e-9)
    b = a + (link.b1 - a[0]) * turn
    size = float(np.max(np.abs(c - c.mean()))) + big_r + r
    assert np.ptp(np.abs(b - link.o_b)) < 1e-9 * size
    assert np.ptp(np.abs(a - link.o_a)) < 1e-9 * size


def test_graphkin_solves_the_written_file_through_the_four_points(tmp_path) -> None:  # type: ignore[no-untyped-def]
    res = synthesize(loads_spec(SPEC))
    link = res.chosen
    assert link is not None
    want = [0j, 1 + 0.6j, 2 + 0.7j, 3 + 0.2j]
    for k in range(4):
        sol = graphkin.loads(link.mechanism_toml(k, units="in")).solve()
        assert complex(*sol.position("C")) == pytest.approx(want[k], abs=1e-9)
    # the checks say what the book warns of: a branch defect (postures 2 and 4)
    checks = {c.name: c for c in link.checks}
    assert not checks["branch"].passed and "2, 4" in checks["branch"].detail
    f = tmp_path / "cc.toml"
    f.write_text(SPEC, encoding="utf-8")
    assert main(["synthesize", str(f), "-o", str(tmp_path / "m.toml")]) == 0
    assert graphkin.load(tmp_path / "m.toml").solve() is not None


def test_radii_whose_arcs_miss_are_one_line(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    f = tmp_path / "bad.toml"
    f.write_text(SPEC.replace("R = 2.0", "R = 0.01").replace("r = 1.5", "r = 0.01"),
                 encoding="utf-8")
    assert main(["synthesize", str(f)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "coupler_curve" in err[0] and "do not meet" in err[0]
