"""A second input following the first through a table (issue 25, item 2).

``follows = { link = 2, table = [[θ2, θ3], ...] }``: the law is the cubic
spline through the rows, periodic when the rows span one turn of θ2.  Held to
what is known without graphkin's code:

* a table sampled from the linear law θ3 = 3 θ2 − 315° gives exactly the sweep
  of ``follows = { ratio = 3, offset = -315 }`` (a spline through the rows of a
  line is the line);
* at random parameters (rows every 360°/n, θ3 = 3 θ2 − 315° + A sin(θ2 + φ)):
  at the rows the swept θ3 is the row's and B is where the circles of radius
  6 about A and C meet (the two-circle solution of the five-bar, written
  here); between the rows θ3 and ω3 stay within the spline's error bounds of
  the sampled function (Hall and Meyer: |f − s| ≤ 5/384 h⁴ max|f⁗|, and
  |f' − s'| ≤ (√3/216 + 1/24) h³ max|f⁗|);
* ω3 and α3 agree with central differences of the swept θ3 and ω3 (positions
  only: the chain rule of the rates is not used);
* a table that does not cover a whole turn limits the sweep to its rows, and
  bad tables are one line naming the key.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.errors import InputError

ROOT = Path(__file__).resolve().parents[1]
LINEAR = ROOT / "examples" / "fivebar_coupled.toml"
TABLE = ROOT / "examples" / "fivebar_table.toml"


def _with_table(rows: list[tuple[float, float]], text: str | None = None) -> str:
    text = text or LINEAR.read_text(encoding="utf-8")
    table = ", ".join(f"[{x!r}, {y!r}]" for x, y in rows)
    return text.replace("follows = { link = 2, ratio = 3, offset = -315 }",
                        f"follows = {{ link = 2, table = [{table}] }}")


def _two_circles(t2: np.ndarray, t3: np.ndarray) -> np.ndarray:
    """B of the five-bar: |AB| = |CB| = 6, on the left of A → C (the file's branch)."""
    a = np.stack([2.5 * np.cos(t2), 2.5 * np.sin(t2)], -1)
    c = np.stack([6 + 4 * np.cos(t3), 4 * np.sin(t3)], -1)
    d = c - a
    dist = np.hypot(d[:, 0], d[:, 1])
    h = np.sqrt(np.maximum(36.0 - (dist / 2) ** 2, 0.0))
    n = np.stack([-d[:, 1], d[:, 0]], -1) / dist[:, None]
    return (a + c) / 2 + h[:, None] * n


def test_a_table_of_the_linear_law_is_the_linear_law() -> None:
    rows = [(float(x), 3.0 * x - 315.0) for x in range(0, 361, 45)]
    lin = graphkin.load(LINEAR).sweep(count=72)
    tab = graphkin.loads(_with_table(rows)).sweep(count=72)
    for name, col in lin.columns.items():
        assert np.allclose(tab.columns[name], col, atol=1e-9, equal_nan=True), name


@settings(max_examples=12, deadline=None)
@given(n=st.integers(8, 36), amp=st.floats(0.0, 20.0), phase=st.floats(0.0, 360.0))
def test_random_tables_agree_with_the_closed_form(n: int, amp: float, phase: float) -> None:
    def f(x: np.ndarray) -> np.ndarray:  # degrees in, degrees out
        return 3 * x - 315 + amp * np.sin(np.radians(x + phase))

    xs = np.linspace(0.0, 360.0, n + 1)
    mech = graphkin.loads(_with_table([(float(x), float(f(x))) for x in xs]))
    # at the rows: θ3 is the row's, B the two-circle solution
    sw = mech.sweep(count=n, start=0.0, stop=360.0)
    good = np.asarray(sw.assembled, dtype=bool)
    t2 = np.radians(np.asarray(sw.columns["drive"], dtype=float))
    t3 = np.radians(f(xs[:-1]))
    d3 = np.radians(sw.columns["angle_3"]) - t3
    assert np.all(np.abs(np.angle(np.exp(1j * d3)))[good] < 1e-9)
    b = np.stack([sw.columns["x_B"], sw.columns["y_B"]], -1)
    assert np.allclose(b[good], _two_circles(t2, t3)[good], atol=1e-8)
    # between the rows: the spline's error bounds, in radians (f⁗ = A sin, |f⁗| <= A)
    h, a = math.radians(360.0 / n), math.radians(amp)
    rng = np.random.default_rng(n)
    for v in rng.uniform(0.0, 360.0, 6):
        one = mech.sweep(count=1, start=float(v), stop=float(v) + 1e-3)
        err = np.angle(np.exp(1j * (np.radians(one.columns["angle_3"][0]) - np.radians(f(v)))))
        assert abs(err) <= 5 / 384 * h**4 * a * 1.01 + 1e-12
        w_true = 10.0 * (3 + a * math.cos(math.radians(v + phase)))
        bound = (math.sqrt(3) / 216 + 1 / 24) * h**3 * a * 10.0
        assert abs(one.columns["omega_3"][0] - w_true) <= bound * 1.01 + 1e-9


def test_the_rates_agree_with_differences_of_the_positions() -> None:
    """ω3 = dθ3/dθ2 · ω2 and α3 = dω3/dθ2 · ω2 (α2 = 0), by central differences."""
    mech = graphkin.load(TABLE)
    step = 0.01
    sw = mech.sweep(count=3600, start=0.0, stop=36.0)  # θ2 every 0.01°
    th = np.unwrap(np.radians(sw.columns["angle_3"]))
    w = np.asarray(sw.columns["omega_3"])
    dt = math.radians(step) / 10.0  # the time of one step at ω2 = 10 rad/s
    w_fd = (th[2:] - th[:-2]) / (2 * dt)
    a_fd = (w[2:] - w[:-2]) / (2 * dt)
    assert np.allclose(w[1:-1], w_fd, rtol=1e-6, atol=1e-6)
    assert np.allclose(sw.columns["alpha_3"][1:-1], a_fd, rtol=1e-4, atol=1e-3)


def test_the_file_posture_and_the_periodic_seam() -> None:
    """At θ2 = 120° the follower is the spline's; over the seam (360°) it is smooth."""
    mech = graphkin.load(TABLE)
    sol = mech.solve()
    f = 3 * 120 - 315 + 15 * math.sin(math.radians(120))
    assert float(sol.angle(3)) == pytest.approx(f, abs=0.05)  # rows every 30°
    sw = mech.sweep(count=3, start=359.99, stop=360.02)
    w = np.asarray(sw.columns["omega_3"])
    assert np.all(np.abs(np.diff(w)) < 1e-3)
    th = np.unwrap(np.radians(sw.columns["angle_3"]))
    assert th[1] - th[0] == pytest.approx(th[2] - th[1], rel=1e-3)


def test_a_table_over_part_of_a_turn_limits_the_sweep() -> None:
    rows = [(float(x), 3.0 * x - 315.0) for x in (90, 120, 150, 180)]
    mech = graphkin.loads(_with_table(rows))
    sw = mech.sweep(count=9)
    assert sw.columns["drive"][0] == 90.0 and sw.columns["drive"][-1] == 170.0
    with pytest.raises(InputError, match="covers the first drive from 90 to 180 only") as e:
        mech.sweep(count=4, start=100.0, stop=250.0)
    assert e.value.key == "--to"


@pytest.mark.parametrize("table,words", [
    ("[[0, 0]]", "2 to 1000 rows"),
    ("[[0, 0], [0, 10]]", "must increase"),
    ("[[0, 0], [90, 10], [60, 20]]", "must increase"),
    ("[[0, 0], [360, 10]]", "must come back"),
    ("[[0, 0], [90, 'x']]", "two finite numbers"),
    ("[[0, 0], [90, nan]]", "two finite numbers"),
    ("[[200, 0], [300, 10]]", "covers θ2 from 200 to 300 only"),
    ("5", "2 to 1000 rows"),
])
def test_bad_tables_are_one_line(table: str, words: str) -> None:
    text = LINEAR.read_text(encoding="utf-8").replace(
        "follows = { link = 2, ratio = 3, offset = -315 }",
        f"follows = {{ link = 2, table = {table} }}")
    with pytest.raises(InputError) as info:
        graphkin.loads(text)
    line = info.value.one_line()
    assert line.startswith("<mechanism>: drive[1].follows.table") and words in line, line
    assert "\n" not in line


def test_table_with_a_ratio_is_refused() -> None:
    text = LINEAR.read_text(encoding="utf-8").replace(
        "ratio = 3, offset = -315", "ratio = 3, table = [[0, 0], [360, 1080]]")
    with pytest.raises(InputError) as info:
        graphkin.loads(text)
    assert info.value.one_line().startswith("<mechanism>: drive[1].follows.ratio: a law is a")


def test_plot_and_animate_move_the_follower(tmp_path: Path) -> None:
    from graphkin.cli import main

    assert main(["plot", str(TABLE), "--what", "angle,omega", "--count", "24", "-o",
                 str(tmp_path / "p.svg")]) == 0
    assert main(["animate", str(TABLE), "--count", "12", "-o", str(tmp_path / "a.html")]) == 0
    assert "held at the file" not in (tmp_path / "a.html").read_text(encoding="utf-8")


@pytest.mark.parametrize("path", [LINEAR, TABLE])
def test_live_moves_the_follower_with_the_drive(path: Path, tmp_path: Path) -> None:
    """The live page moves the follower by its law with the first drive (the page's values
    against `solve` after drags: tests/render/test_live_laws.py); the page is written and
    carries the law, not a fixed angle for the follower."""
    import contextlib
    import io

    import graphkin
    from graphkin.cli import main
    from graphkin.files import load_toml
    from graphkin.render.live import live_data

    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        rc = main(["live", str(path), "-o", str(tmp_path / "l.html")])
    assert rc == 0 and (tmp_path / "l.html").exists(), err.getvalue()
    data, _ = live_data(graphkin.load(path), load_toml(path), path.name)
    assert data.get("follow"), "the page has no follower's law"
