"""Several inputs coupled to one swept parameter by a law (issue 25, item 2).

The five-bar of Examples 5.1-5.4 with θ3 = 3 θ2 − 315° (``follows``): swept
through a whole turn of θ2, every posture is held to an independent solution
written here -- A and C from the inputs, B where the circles of radius 6 about
them meet (the branch of the file: B on the left of A→C), ω4 and ω5 from the
velocity equation V_A + ω4 k×R_BA = V_C + ω5 k×R_BC solved by hand (Cramer) --
and the file's posture is the book's (θ3 = 45° at θ2 = 120°).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
FILE = ROOT / "examples" / "fivebar_coupled.toml"


def _closed_form(t2: np.ndarray, w2: float) -> dict[str, np.ndarray]:
    t3 = 3 * t2 - math.radians(315)
    w3 = 3 * w2
    a = np.stack([2.5 * np.cos(t2), 2.5 * np.sin(t2)], -1)
    c = np.stack([6 + 4 * np.cos(t3), 4 * np.sin(t3)], -1)
    d = c - a
    dist = np.hypot(d[:, 0], d[:, 1])
    h = np.sqrt(np.maximum(36.0 - (dist / 2) ** 2, 0.0))
    mid = (a + c) / 2
    n = np.stack([-d[:, 1], d[:, 0]], -1) / dist[:, None]
    b = mid + h[:, None] * n                      # left of A -> C (the file's branch)
    ok = dist < 12.0
    va = w2 * np.stack([-a[:, 1], a[:, 0]], -1)
    vc = w3 * np.stack([-(c[:, 1]), c[:, 0] - 6], -1)
    rba, rbc = b - a, b - c
    # ω4 k×R_BA − ω5 k×R_BC = V_C − V_A: two equations, unknowns ω4, ω5 (Cramer)
    m11, m12 = -rba[:, 1], rbc[:, 1]
    m21, m22 = rba[:, 0], -rbc[:, 0]
    r = vc - va
    det = m11 * m22 - m12 * m21
    w4 = (r[:, 0] * m22 - m12 * r[:, 1]) / det
    w5 = (m11 * r[:, 1] - r[:, 0] * m21) / det
    return {"B": b, "ok": ok, "t3": t3, "w4": w4, "w5": w5}


def test_the_file_posture_is_the_books() -> None:
    sol = graphkin.load(FILE).solve()
    assert float(sol.angle(3)) == pytest.approx(45.0, abs=1e-9)
    assert float(sol.omega(3)) == pytest.approx(30.0, rel=1e-12)


def test_swept_along_the_law_agrees_with_the_closed_form() -> None:
    mech = graphkin.load(FILE)
    sw = mech.sweep(count=360)
    cols = sw.columns
    t2 = np.radians(np.asarray(cols["drive"], dtype=float))
    ref = _closed_form(t2, 10.0)
    good = np.asarray(sw.assembled, dtype=bool)
    assert good.sum() > 100
    # the swept θ3 is the law's, at every posture
    d3 = np.radians(cols["angle_3"][good]) - ref["t3"][good]
    assert np.all(np.abs(np.angle(np.exp(1j * d3))) < 1e-9)
    # assembled exactly where the two circles meet (away from the tangent postures)
    clear = np.abs(np.hypot(*(np.stack([2.5 * np.cos(t2), 2.5 * np.sin(t2)], -1)
                              - np.stack([6 + 4 * np.cos(ref["t3"]), 4 * np.sin(ref["t3"])],
                                         -1)).T) - 12.0) > 1e-6
    assert np.array_equal(good[clear], ref["ok"][clear])
    b = np.stack([cols["x_B"], cols["y_B"]], -1)[good]
    assert np.allclose(b, ref["B"][good], atol=1e-9)
    assert np.allclose(cols["omega_3"][good], 30.0, rtol=1e-12)
    assert np.allclose(cols["omega_4"][good], ref["w4"][good], rtol=1e-7, atol=1e-7)
    assert np.allclose(cols["omega_5"][good], ref["w5"][good], rtol=1e-7, atol=1e-7)


def test_the_analytic_solver_agrees_at_every_posture() -> None:
    """The Newton solver of the loop equations, given both inputs at each posture."""
    from graphkin.kinematics.analytic import solve_analytic_many

    mech = graphkin.load(FILE)
    sw = mech.sweep(count=360)
    good = np.asarray(sw.assembled, dtype=bool)
    t2 = np.radians(np.asarray(sw.columns["drive"], dtype=float))
    full = np.stack([t2, 3 * t2 - math.radians(315)], -1)
    # Newton goes on from each posture to the next: at steps of 1° it stays with the motion
    # (at 5° steps it lost it past θ2 = 395°, where B swings fast round A)
    sol = solve_analytic_many(mech, full)
    b = np.asarray(sol.position("B"))
    ok = good & np.asarray(sol.valid, dtype=bool)
    assert ok.all()
    assert np.allclose(b[ok], np.stack([sw.columns["x_B"], sw.columns["y_B"]], -1)[ok],
                       atol=1e-8)


def test_plot_and_animate_sweep_both_inputs(tmp_path: Path) -> None:
    from graphkin.cli import main

    assert main(["plot", str(FILE), "--what", "angle", "--count", "24", "-o",
                 str(tmp_path / "p.svg")]) == 0
    assert main(["animate", str(FILE), "--count", "12", "-o", str(tmp_path / "a.html")]) == 0
    assert "held at the file" not in (tmp_path / "a.html").read_text(encoding="utf-8")


@pytest.mark.parametrize("change,key", [
    (("[[drive]]\nlink = 2\nangle = 120", "[[drive]]\nlink = 2\nangle = 120\n"
      "follows = { link = 3 }"), "drive[0].follows"),
    (("follows = { link = 2,", "angle = 45\nfollows = { link = 2,"), "drive[1].angle"),
    (("follows = { link = 2,", "follows = { link = 5,"), "drive[1].follows.link"),
    (("ratio = 3", "ratio = nan"), "drive[1].follows.ratio"),
    (("ratio = 3", "ratio = 3, speed = 2"), "drive[1].follows.speed"),
    (("offset = -315", 'offset = "x"'), "drive[1].follows.offset"),
])
def test_bad_laws_are_one_line(change: tuple[str, str], key: str) -> None:
    text = FILE.read_text(encoding="utf-8")
    assert change[0] in text
    with pytest.raises(InputError) as info:
        graphkin.loads(text.replace(change[0], change[1], 1))
    assert info.value.one_line().startswith(f"<mechanism>: {key}"), info.value.one_line()
