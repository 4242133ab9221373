"""Sweeps: the same constructions on whole arrays of drive values (``docs/formats/sweep-csv.md``).

Every number a sweep gives is checked against something computed another way:
single solves of the mechanism with its drive set to that value (through
``graphkin.mechanisms.from_dict`` with the file's data changed), the
independent analytic solver (Newton on the constraint equations), a
closed-form four-bar (Freudenstein's equation, ``benchmarks/fourbar_closed_form.py``),
and hand derivations (law of cosines) written in the comments.
"""

from __future__ import annotations

import copy
import csv
import importlib.util
import io
import math
import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from spec_data import BENCH
from strategies import RandomMechanism, examples, mechanisms

import graphkin
from graphkin.construction import Construction
from graphkin.errors import InputError
from graphkin.kinematics.polygons import build_polygons
from graphkin.kinematics.posture import build_posture
from graphkin.kinematics.sweep import (
    FourBar,
    fourbar,
    grashof,
    sweep,
    transmission_angle,
    wrap_degrees,
)
from graphkin.kinematics.sweep import run as sweep_run

ROOT = Path(__file__).resolve().parents[1]

REL = 1e-9  # sweeps and single postures evaluate the same steps: they agree to rounding

FOURBAR = """
title = "test four-bar"
units = {{ length = "mm" }}
[links.1]
A = [0, 0]
D = [{d}, 0]
[links.2]
A = [0, 0]
B = [{a}, 0]
[links.3]
B = [0, 0]
C = [{b}, 0]
E = [3, -2]
[links.4]
D = [0, 0]
C = [{c}, 0]
[drive]
link = 2
angle = {angle}
omega = 10
alpha = -3
[assembly]
C = [{hx}, {hy}]
"""


def _fourbar(d: float, a: float, b: float, c: float, angle: float = 60.0,
             hint: tuple[float, float] = (8.0, 6.0)) -> graphkin.Mechanism:
    return graphkin.loads(FOURBAR.format(d=d, a=a, b=b, c=c, angle=angle, hx=hint[0],
                                         hy=hint[1]))


@pytest.fixture(scope="module")
def bench() -> graphkin.Mechanism:
    return graphkin.load(BENCH)


def _closed_form():
    spec = importlib.util.spec_from_file_location(
        "fourbar_closed_form", ROOT / "benchmarks" / "fourbar_closed_form.py")
    assert spec is not None and spec.loader is not None
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def _data(path: Path) -> dict:
    with open(path, "rb") as fh:
        return tomllib.load(fh)


def _at(data: dict, value: float) -> graphkin.Mechanism:
    """The file's mechanism with its (first) drive set to ``value``."""
    d = copy.deepcopy(data)
    drive = d["drive"][0] if isinstance(d["drive"], list) else d["drive"]
    drive["angle" if "angle" in drive else "position"] = float(value)
    return graphkin.from_dict(d)


def _close(a: float, b: float, scale: float, rel: float = REL) -> bool:
    return abs(a - b) <= rel * max(1.0, scale)


def _compare_with_solve(sw, data: dict, i: int, rel: float = REL) -> None:
    """Column by column, posture ``i`` of a sweep equals a single solve on the same branches."""
    mech = _at(data, sw.columns["drive"][i])
    sol = graphkin.solve(mech, branches=dict(sw.branches))
    for key, col in sw.columns.items():
        kind, _, name = key.partition("_")
        got = float(col[i])
        if kind == "drive":
            continue
        if kind == "angle":
            ref = math.degrees(float(sol.angle_rad(name)))
            assert abs(math.remainder(got - ref, 360.0)) <= rel * 360, (key, i, got, ref)
        elif kind in ("omega", "alpha"):
            ref = float(getattr(sol, kind)(name))
            assert _close(got, ref, abs(ref), rel), (key, i, got, ref)
        else:
            f = {"x": sol.position, "y": sol.position, "vx": sol.velocity, "vy": sol.velocity,
                 "ax": sol.acceleration, "ay": sol.acceleration}[kind]
            v = f(name)
            ref = float(v[0] if kind.endswith("x") else v[1])
            assert _close(got, ref, float(np.hypot(*v)), rel), (key, i, got, ref)


# ---------------------------------------------------------------------------
# the contract: columns, order, defaults
# ---------------------------------------------------------------------------

def test_columns_and_order_follow_the_spec(bench: graphkin.Mechanism) -> None:
    # docs/formats/sweep-csv.md: drive; per link (file order) angle, omega, alpha; per named point
    # (file order, once) x, y, vx, vy, ax, ay -- built here from the TOML itself
    data = _data(BENCH)
    want = ["drive"]
    for lid in data["links"]:
        want += [f"angle_{lid}", f"omega_{lid}", f"alpha_{lid}"]
    seen: list[str] = []
    for pts in data["links"].values():
        seen += [p for p in pts if p not in seen]
    for p in seen:
        want += [f"{k}_{p}" for k in ("x", "y", "vx", "vy", "ax", "ay")]
    sw = bench.sweep(count=12)
    assert list(sw.columns) == want
    assert all(np.shape(c) == (12,) for c in sw.columns.values())
    header = next(csv.reader(io.StringIO(sw.csv_text())))
    assert header == want


def test_default_range_is_one_turn_from_the_file_angle(bench: graphkin.Mechanism) -> None:
    sw = bench.sweep(count=8)
    # the file's drive angle is 120°; one full turn, the end excluded: 120 + 45 k
    np.testing.assert_allclose(sw.columns["drive"], 120.0 + 45.0 * np.arange(8), atol=1e-12)
    sw = bench.sweep(count=4, start=10, stop=30)
    np.testing.assert_allclose(sw.columns["drive"], [10, 15, 20, 25], atol=1e-12)


def test_angles_are_degrees_and_the_drive_rates_apply_everywhere(
        bench: graphkin.Mechanism) -> None:
    sw = bench.sweep(count=36)
    # the crank is the drive: its angle is the drive value wrapped to (-180, 180]
    assert np.all(np.abs(np.remainder(sw.columns["angle_2"] - sw.columns["drive"] + 180, 360)
                         - 180) < 1e-9)
    assert np.all(sw.columns["angle_2"] <= 180) and np.all(sw.columns["angle_2"] > -180)
    # omega = "900 rev/min" = 30π rad/s, alpha = 0 at every posture
    np.testing.assert_allclose(sw.columns["omega_2"], 30 * math.pi, rtol=1e-15)
    assert np.all(sw.columns["alpha_2"] == 0)


def test_wrap_degrees() -> None:
    np.testing.assert_array_equal(wrap_degrees(np.radians([180.0, -180.0, 540.0, -90.0, 0.0])),
                                  [180.0, 180.0, 180.0, -90.0, 0.0])


def test_count_must_be_positive(bench: graphkin.Mechanism) -> None:
    with pytest.raises(InputError):
        bench.sweep(count=0)


# ---------------------------------------------------------------------------
# the same numbers as single solves, the analytic solver and the closed form
# ---------------------------------------------------------------------------

def test_bench_sweep_equals_single_solves(bench: graphkin.Mechanism) -> None:
    sw = bench.sweep(count=360)
    assert sw.valid.all() and sw.method == "construction"
    for i in range(0, 360, 29):
        _compare_with_solve(sw, _data(BENCH), i)


EXAMPLE_FILES = ["ex2_5_open.toml", "ex2_5_crossed.toml", "ex3_1_fourbar.toml",
                 "ex3_3_inverted_slider.toml", "ex4_4_coriolis_block.toml",
                 "ex4_11_rapsons_slide.toml", "ex4_16_cubic.toml", "ex5_4_fivebar.toml",
                 "ex4_7_cam_follower.toml"]


@pytest.mark.parametrize("name", EXAMPLE_FILES)
def test_example_sweeps_equal_single_solves(examples: Path, name: str) -> None:
    path = examples / name
    mech = graphkin.load(path)
    sw = mech.sweep(count=24)
    data = _data(path)
    for i in np.flatnonzero(sw.valid)[::3]:
        _compare_with_solve(sw, data, int(i))


@pytest.mark.parametrize("name", ["ex3_2_slider_driven.toml", "ex4_14_inflection_bresse.toml"])
def test_slider_drive_and_rates_of_another_link(examples: Path, name: str) -> None:
    # a slider drive sweeps positions; [rates] of another link are met posture by posture.
    # Near the toggles the rates blow up and carry the round-off of the ratio with them,
    # so these are checked at 1e-6 of the largest rate.
    path = examples / name
    mech = graphkin.load(path)
    sw = mech.sweep(count=24)
    data = _data(path)
    ok = np.flatnonzero(sw.valid)
    assert ok.size > 10
    for i in ok[::2]:
        _compare_with_solve(sw, data, int(i), rel=1e-6)
    if name.startswith("ex4_14"):
        # [rates]: link 3 turns at 5 rad/s ccw and 20 rad/s² cw at every posture
        np.testing.assert_allclose(sw.columns["omega_3"][ok], 5.0, rtol=1e-6)
        np.testing.assert_allclose(sw.columns["alpha_3"][ok], -20.0, rtol=1e-6)
    else:
        # the slider's travel: drive values are positions in mm, C moves along y = -20
        np.testing.assert_allclose(sw.columns["x_C"][ok], sw.columns["drive"][ok], atol=1e-9)
        np.testing.assert_allclose(sw.columns["y_C"][ok], -20.0, atol=1e-9)


def test_several_drives_hold_the_others(examples: Path) -> None:
    mech = graphkin.load(examples / "ex5_4_fivebar.toml")
    sw = mech.sweep(count=12)
    # the second drive, link 3, stays at 45° and turns at 5 rad/s cw throughout
    np.testing.assert_allclose(sw.columns["angle_3"], 45.0, atol=1e-12)
    np.testing.assert_allclose(sw.columns["omega_3"], -5.0, atol=1e-12)


def test_sweep_agrees_with_the_analytic_solver(bench: graphkin.Mechanism,
                                               examples: Path) -> None:
    from graphkin.kinematics.analytic import solve_analytic

    for mech in (bench, graphkin.load(examples / "ex3_3_inverted_slider.toml"),
                 graphkin.load(examples / "ex4_11_rapsons_slide.toml")):
        sw = mech.sweep(count=36)
        sol = sw.solution
        for i in np.flatnonzero(sw.valid)[::5]:
            m2 = _at(_raw(mech), sw.columns["drive"][i])
            # Newton from the sweep's own pose stays on its branch; the numbers are its own
            guess = {lid: (float(sol.links[lid].origin[i, 0]), float(sol.links[lid].origin[i, 1]),
                           float(sol.links[lid].angle[i])) for lid in mech.moving}
            ref = solve_analytic(m2, guess=guess)
            for lid in mech.moving:
                a = math.degrees(float(ref.angle_rad(lid)))
                assert abs(math.remainder(sw.columns[f"angle_{lid}"][i] - a, 360)) < 1e-9
                for kind in ("omega", "alpha"):
                    r = float(getattr(ref, kind)(lid))
                    assert _close(float(sw.columns[f"{kind}_{lid}"][i]), r, abs(r)), (lid, kind)
            for p in mech.point_names:
                for k, f in (("", ref.position), ("v", ref.velocity), ("a", ref.acceleration)):
                    v = f(p)
                    got = (sw.columns[f"{k}x_{p}" if k else f"x_{p}"][i],
                           sw.columns[f"{k}y_{p}" if k else f"y_{p}"][i])
                    scale = float(np.hypot(*v))
                    assert _close(got[0], float(v[0]), scale) and _close(got[1], float(v[1]), scale)


def _raw(mech: graphkin.Mechanism) -> dict:
    path = Path(mech.source)
    return _data(path)


def test_3600_postures_equal_the_closed_form(bench: graphkin.Mechanism) -> None:
    cf = _closed_form()
    fb = cf.fourbar_from_mechanism(bench)
    sw = bench.sweep(count=3600)
    d = bench.drives[0]
    idx = np.arange(0, 3600, 97)
    ref = fb.solve(sw.values[idx], d.rate, d.rate2 or 0.0)
    assert list(ref) == list(sw.columns)
    for key, col in ref.items():
        got = sw.columns[key][idx]
        if key.startswith("angle_"):
            err = np.abs(np.remainder(got - col + 180, 360) - 180)
            assert np.all(err < 1e-9), key
        else:
            np.testing.assert_allclose(got, col, rtol=REL, atol=REL * np.max(np.abs(col)),
                                       err_msg=key)


# ---------------------------------------------------------------------------
# the compiled evaluation is the step-by-step replay
# ---------------------------------------------------------------------------

def _same_evaluation(a, b) -> None:
    assert set(a.values) == set(b.values)
    np.testing.assert_array_equal(np.asarray(a.valid), np.asarray(b.valid))
    if a.failed_at is None or b.failed_at is None:
        assert a.failed_at is None and b.failed_at is None
    else:
        np.testing.assert_array_equal(a.failed_at, b.failed_at)
    for k in a.values:
        x, y = np.asarray(a.values[k], dtype=float), np.asarray(b.values[k], dtype=float)
        assert x.shape == y.shape, k
        np.testing.assert_array_equal(np.isnan(x), np.isnan(y), err_msg=k)
        ok = np.isfinite(x) & np.isfinite(y)
        if k.startswith("θ"):
            # an angle is the same angle a turn away: atan2 of a direction that rounds to
            # either side of the -x axis gives ±π
            x = y + np.remainder(x - y + np.pi, 2 * np.pi) - np.pi
        np.testing.assert_allclose(x[ok], y[ok], rtol=1e-9, atol=1e-9 * max(1.0, np.abs(y[ok]).max(
            initial=0.0)), err_msg=k)


@pytest.mark.parametrize("name", ["ex3_1_fourbar.toml", "ex3_2_slider_driven.toml",
                                  "ex3_3_inverted_slider.toml", "ex4_4_coriolis_block.toml",
                                  "ex4_7_cam_follower.toml", "ex4_11_rapsons_slide.toml",
                                  "ex5_4_fivebar.toml"])
def test_compiled_evaluation_equals_the_replay(examples: Path, name: str) -> None:
    # Construction.evaluate compiles the steps into kernels; Construction.replay runs the
    # general operations one by one.  On a whole turn (with ranges that do not assemble,
    # for ex3_1) and on one posture they give the same values, NaN entries and failures.
    mech = graphkin.load(examples / name)
    pc = build_posture(mech)
    pol = build_polygons(mech, pc)
    d = mech.drives[0]
    label = f"θ{d.link}" if d.kind == "angle" else f"s{d.link}"
    span = 2 * math.pi if d.kind == "angle" else 0.6 * d.value
    given = dict(pc.inputs)
    given[label] = d.value + span * (np.arange(97) / 97 - (0.5 if d.kind != "angle" else 0.0))
    for g in (given, dict(pc.inputs)):
        a = pc.construction.evaluate(g, strict=False)
        b = pc.construction.replay(g, strict=False)
        _same_evaluation(a, b)
        vin = {w: 1.5 for w, _ in pol.rate_inputs.values()}
        ain = {al: -0.5 for _, al in pol.rate_inputs.values()}
        av = pol.velocity.evaluate(vin, values=a.values, strict=False)
        bv = pol.velocity.replay(vin, values=b.values, strict=False)
        _same_evaluation(av, bv)
        _same_evaluation(pol.acceleration.evaluate(ain, values=av.values, strict=False),
                         pol.acceleration.replay(ain, values=bv.values, strict=False))


@examples(40)
@given(rm=mechanisms(), span=st.floats(0.05, 3.0))
def test_random_mechanisms_compiled_equals_replay(rm: RandomMechanism, span: float) -> None:
    # random four-bars, slider-cranks, inverted slider-cranks, slots, double sliders,
    # six-bars and five-bars (tests/strategies.py), swept around their posture far enough
    # to leave the range where they assemble
    from graphkin.kinematics.posture import NotDecomposable

    mech = rm.mechanism()
    try:
        pc = build_posture(mech)
    except NotDecomposable:
        return
    pol = build_polygons(mech, pc)
    d = mech.drives[0]
    label = f"θ{d.link}" if d.kind == "angle" else f"s{d.link}"
    scale = 1.0 if d.kind == "angle" else mech.scale
    given = dict(pc.inputs)
    given[label] = d.value + span * scale * np.linspace(-1.0, 1.0, 41)
    a = pc.construction.evaluate(given, strict=False)
    b = pc.construction.replay(given, strict=False)
    _same_evaluation(a, b)
    vin = {w: 2.0 for w, _ in pol.rate_inputs.values()}
    ain = {al: 0.5 for _, al in pol.rate_inputs.values()}
    av = pol.velocity.evaluate(vin, values=a.values, strict=False)
    bv = pol.velocity.replay(vin, values=b.values, strict=False)
    _same_evaluation(av, bv)
    _same_evaluation(pol.acceleration.evaluate(ain, values=av.values, strict=False),
                     pol.acceleration.replay(ain, values=bv.values, strict=False))
    # keeping only some values changes nothing in those
    keep = {s.outputs[0] for s in pc.construction.steps[-3:]}
    c = pc.construction.evaluate_for(keep, given, strict=False)
    np.testing.assert_array_equal(np.asarray(c.valid), np.asarray(a.valid))
    for k in keep:
        np.testing.assert_array_equal(np.asarray(c.values[k]), np.asarray(a.values[k]))
    assert set(c.values) <= keep | set(given)


def test_compiled_evaluation_raises_like_the_replay() -> None:
    cx = Construction()
    cx.add("point", (), ("A",), xy=(0.0, 0.0))
    cx.add("input", (), ("r",), name="r")
    cx.add("point", (), ("D",), xy=(8.0, 0.0))
    cx.add("circle", ("A",), ("k_A",), radius=5.0)
    cx.add("circle", ("D",), ("k_D",), radius=2.0)
    cx.add("intersect_circles", ("k_A", "k_D"), ("C",), branch="left")
    # 5 + 2 < 8: the arcs do not meet
    with pytest.raises(graphkin.NoIntersectionError):
        cx.evaluate({"r": 1.0})
    with pytest.raises(graphkin.ConstructionError):
        cx.evaluate()  # the input r is not given
    ev = cx.evaluate({"r": 1.0}, strict=False)
    assert not bool(ev.valid) and int(ev.failed_at) == 5


# ---------------------------------------------------------------------------
# postures that cannot be assembled, dead centers, limit positions
# ---------------------------------------------------------------------------

def _non_grashof() -> graphkin.Mechanism:
    # frame 10, crank 6, coupler 5, rocker 7: s + l = 15 > p + q = 13
    return _fourbar(10, 6, 5, 7, angle=60, hint=(8, 6))


def test_unassemblable_range_is_reported_and_left_empty() -> None:
    mech = _non_grashof()
    sw = mech.sweep(count=360)
    # Hand derivation: C exists while |BD| <= 5 + 7 = 12, with
    # |BD|² = 6² + 10² - 2·6·10 cos θ2, so cos θ2 >= (36 + 100 - 144)/120 = -1/15:
    # θ2 in [-93.823°, 93.823°]; it cannot be assembled for 93.82° < θ2 < 266.18°.
    edge = math.degrees(math.acos(-1 / 15))
    (rng,) = sw.unassembled
    assert abs(rng[0] - edge) < 0.005 and abs(rng[1] - (360 - edge)) < 0.005
    bad = (sw.columns["drive"] > edge) & (sw.columns["drive"] < 360 - edge)
    np.testing.assert_array_equal(~sw.assembled, bad)
    rows = list(csv.reader(io.StringIO(sw.csv_text())))[1:]
    for row, b in zip(rows, bad):
        assert row[0] != ""
        assert all(c == "" for c in row[1:]) == bool(b)
        assert all(c.lower() not in ("nan", "inf", "-inf") for c in row)
    note = f"cannot assemble for drive {edge:.2f}° to {360 - edge:.2f}°"
    assert note in sw.report()
    # the two ends are dead centers of the dyad at C (the arcs are tangent there)
    dead = [s for s in sw.singular if s.kind == "dead-center"]
    assert [s.label for s in dead] == ["C", "C"]
    assert abs(dead[0].drive - edge) < 0.005 and abs(dead[1].drive - (360 - edge)) < 0.005


def test_cli_reports_the_range_on_stderr_and_exits_zero(tmp_path: Path) -> None:
    f = tmp_path / "ng.toml"
    f.write_text(FOURBAR.format(d=10, a=6, b=5, c=7, angle=60, hx=8, hy=6), encoding="utf-8")
    out = tmp_path / "out.csv"
    r = subprocess.run([sys.executable, "-m", "graphkin.cli", "sweep", str(f), "--count", "72",
                        "--csv", str(out)], capture_output=True, text=True, check=False)
    assert r.returncode == 0, r.stderr
    lines = [ln for ln in r.stderr.splitlines() if "cannot assemble" in ln]
    assert len(lines) == 1 and lines[0].endswith("cannot assemble for drive 93.82° to 266.18°")
    rows = list(csv.reader(out.open(encoding="utf-8")))
    assert len(rows) == 73 and rows[0][0] == "drive"
    r = subprocess.run([sys.executable, "-m", "graphkin.cli", "sweep", str(f), "--count", "0"],
                       capture_output=True, text=True, check=False)
    assert r.returncode == 2 and "count" in r.stderr and "Traceback" not in r.stderr


def test_limit_positions_of_the_rocker(bench: graphkin.Mechanism) -> None:
    sw = bench.sweep(count=90)
    limits = sorted(s.drive % 360 for s in sw.singular if s.kind == "limit")
    # Sec. 1.10: the rocker stops where crank and coupler are in line, |AC| = 12 ± 4.
    # Law of cosines in triangle ACD (|AD| = 10, |DC| = 11):
    # |AC| = 16: cos ∠DAC = (256 + 100 - 121)/320, the crank along AC at 42.75°;
    # |AC| = 8:  cos ∠DAC = (64 + 100 - 121)/160 = 74.41°, the crank opposite: 254.41°.
    want = sorted([math.degrees(math.acos(235 / 320)),
                   180 + math.degrees(math.acos(43 / 160))])
    assert len(limits) == 2
    assert abs(limits[0] - want[0]) < 0.005 and abs(limits[1] - want[1]) < 0.005


def test_change_point_branches_meet_without_a_gap() -> None:
    # A parallelogram, frame 10, crank 4, coupler 10, rocker 4: s + l = p + q (change point).
    # At θ2 = 0° and 180° all four links lie on the frame line, |BD| = 10 ∓ 4 = 6 or 14 =
    # |10 ∓ 4|: the arcs about B and D are tangent and the two branches meet.
    mech = _fourbar(10, 4, 10, 4, angle=90, hint=(10, 4))
    sw = mech.sweep(count=72, start=-30, stop=330)
    assert sw.assembled.all()
    dead = [s.drive for s in sw.singular if s.kind == "dead-center"]
    assert len(dead) == 2
    for d, want in zip(sorted(dead), (0.0, 180.0)):
        assert abs(math.remainder(d - want, 360.0)) < 0.01
    assert any("change point" in line for line in sw.report())


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(start=st.floats(-720, 720), span=st.floats(-400, 400), count=st.integers(1, 60))
def test_random_ranges_never_write_nan(start: float, span: float, count: int) -> None:
    for mech in (_non_grashof(), _fourbar(10, 4, 12, 11, angle=120, hint=(9, 11))):
        try:
            sw = sweep(mech, count=count, start=start, stop=start + span)
        except InputError as exc:
            # postures the floats cannot tell apart are refused in one line (issue 25)
            assert "too narrow" in str(exc) and abs(span) / count <= 1e-9 * 1440, exc
            continue
        text = sw.csv_text().lower()
        assert "nan" not in text and "inf" not in text
        rows = list(csv.reader(io.StringIO(text)))
        assert len(rows) == count + 1
        for row in rows[1:]:
            for c in row:
                assert c == "" or math.isfinite(float(c))
        # every posture is either complete or empty but for the drive
        for row, ok in zip(rows[1:], sw.assembled):
            assert (row[1] != "") == bool(ok)


def test_analytic_fallback_says_so_and_still_works() -> None:
    path = ROOT / "examples" / "stephenson3_fallback.toml"
    if not path.exists():
        pytest.skip("no Stephenson III example in this checkout")
    mech = graphkin.load(path)
    sw = mech.sweep(count=12, start=0, stop=30)
    assert sw.method == "analytic"
    assert any("analytic" in n for n in sw.notes)
    assert sw.valid.any()
    # positions satisfy the pin constraints: D is 79.06 mm from C on link 5
    # (|(75, -25)| = √6250) and 25.5 mm from O6 on link 6 (|(-5, 25)| = √650)
    ok = sw.valid
    dcd = np.hypot(sw.columns["x_D"] - sw.columns["x_C"], sw.columns["y_D"] - sw.columns["y_C"])
    np.testing.assert_allclose(dcd[ok], math.sqrt(6250), rtol=1e-9)
    dod = np.hypot(sw.columns["x_D"] - 130, sw.columns["y_D"] - 10)
    np.testing.assert_allclose(dod[ok], math.sqrt(650), rtol=1e-9)


def test_long_sweeps_go_in_blocks_and_tell_progress(monkeypatch: pytest.MonkeyPatch,
                                                    bench: graphkin.Mechanism) -> None:
    whole = bench.sweep(count=40)
    monkeypatch.setattr(sweep_run, "BLOCK", 16)  # where sweep() reads it
    seen: list[float] = []
    parts = sweep(bench, count=40, progress=seen.append)
    assert seen == [16 / 40, 32 / 40, 1.0]
    for k, col in whole.columns.items():
        np.testing.assert_allclose(parts.columns[k], col, rtol=1e-12, atol=1e-9)
    assert parts.solution.links["3"].angle.shape == (40,)


# ---------------------------------------------------------------------------
# Grashof's law and the transmission angle
# ---------------------------------------------------------------------------

def _fb(frame: float, inp: float, coupler: float, out: float) -> FourBar:
    return FourBar("1", "2", "3", "4", ("A", "B", "C", "D"),
                   {"1": frame, "2": inp, "3": coupler, "4": out})


def test_grashof_classification_textbook_cases() -> None:
    # Sec. 1.9, Eq. 1.6: the shortest link s turns fully relative to the others iff
    # s + l <= p + q.  Which link is fixed names the linkage (Fig. 1.28): s beside the
    # frame -> crank-rocker; s the frame -> double-crank (drag link); s the coupler ->
    # double-rocker.  One chain s = 2, p = 5, q = 6, l = 7 (2 + 7 = 9 < 11), inverted:
    g = grashof(_fb(6, 2, 7, 5))
    assert g.kind == "crank-rocker" and g.cranks == ("2",) and g.grashof
    g = grashof(_fb(6, 5, 7, 2))
    assert g.kind == "crank-rocker" and g.cranks == ("4",)
    g = grashof(_fb(2, 5, 6, 7))
    assert g.kind == "double-crank" and g.cranks == ("2", "4")
    g = grashof(_fb(6, 5, 2, 7))
    assert g.kind == "double-rocker" and g.cranks == ()
    # Example 1.6: s = 3 (frame), l = 6, p = 4, q = 5: 3 + 6 = 4 + 5, Grashof, a drag
    # link -- and, the equality holding, a change point
    g = grashof(_fb(3, 4, 6, 5))
    assert g.kind == "double-crank" and g.change_point and g.grashof
    # non-Grashof: 5 + 10 > 6 + 7, no link turns fully
    g = grashof(_fb(10, 6, 5, 7))
    assert g.kind == "non-Grashof" and not g.grashof and g.cranks == ()
    assert (g.s, g.l, g.p + g.q) == (5.0, 10.0, 13.0)


def test_grashof_of_a_file(bench: graphkin.Mechanism, examples: Path) -> None:
    # bench: frame 10, crank 4, coupler 12, rocker 11: 4 + 12 = 16 < 21, crank beside the frame
    g = grashof(bench)
    assert g.kind == "crank-rocker" and g.cranks == ("2",)
    assert fourbar(bench).pins == ("A", "B", "C", "D")
    with pytest.raises(InputError):
        grashof(graphkin.load(examples / "ex3_2_slider_driven.toml"))


def test_transmission_angle_example_1_7() -> None:
    # Example 1.7: R_DA = 180, R_BA = 60, R_CB = 210, R_CD = 120 mm, crank at 60°: γ = 48.65°
    mech = graphkin.loads(FOURBAR.replace("E = [3, -2]\n", "").format(
        d=180, a=60, b=210, c=120, angle=60, hx=150, hy=110))
    assert abs(float(transmission_angle(mech)) - 48.65) < 0.005


def test_transmission_angle_extremes_with_the_crank_on_the_frame_line(
        bench: graphkin.Mechanism) -> None:
    # Sec. 1.10: the extremes occur with the crank along AD.  θ2 = 0: |BD| = 6,
    # cos γ = (12² + 11² - 6²)/(2·12·11) = 229/264; θ2 = 180°: |BD| = 14, cos γ = 69/264.
    sw = bench.sweep(count=360, start=0, stop=360, transmission=True)
    col = sw.columns["transmission_C"]
    gmin, gmax = math.degrees(math.acos(229 / 264)), math.degrees(math.acos(69 / 264))
    assert abs(col[0] - gmin) < 1e-9 and abs(col[180] - gmax) < 1e-9
    assert abs(col.min() - gmin) < 1e-9 and abs(col.max() - gmax) < 1e-9
    np.testing.assert_allclose(transmission_angle(sw), col, atol=1e-9)


def test_extra_columns(bench: graphkin.Mechanism) -> None:
    sw = bench.sweep(count=24, centers=True, curvature=True)
    cols = sw.columns
    if "x_I13" in cols:
        # I24 lies on the frame line AD and on the line BC (Kennedy), so y = 0
        np.testing.assert_allclose(cols["y_I24"], 0.0, atol=1e-9)
        # I12 is the pin A
        np.testing.assert_allclose(cols["x_I12"], 0.0, atol=1e-12)
    if "rho_B" in cols:
        # B turns about A at a constant radius 4: its path's radius of curvature is 4
        np.testing.assert_allclose(cols["rho_B"], 4.0, rtol=1e-9)
        np.testing.assert_allclose(cols["cx_B"], 0.0, atol=1e-9)
        # C swings about D on radius 11.  Its radius comes through Euler-Savary from
        # link 3's inflection circle, whose diameter reaches 1.3e6 in (1e5 times the
        # crank) at one of these postures: round-off grows with that ratio (6e-10 on
        # one machine, 1.3e-9 on another), so 1e-6 -- a wrong construction is off by O(1)
        np.testing.assert_allclose(cols["rho_C"], 11.0, rtol=1e-6)


def test_importing_the_sweep_does_not_import_matplotlib() -> None:
    code = ("import sys, graphkin, graphkin.kinematics.sweep, graphkin.commands.sweep; "
            "print('matplotlib' in sys.modules)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert r.stdout.strip() == "False"


def test_extra_columns_at_the_file_posture_of_example_3_1(examples: Path) -> None:
    # the first posture of a default sweep is the file's: tests/data/spec/expected.toml gives
    # I13 = (5.42613, -9.39833), I24 = (-11.0627, 0), the inflection diameter of link 3,
    # 40.3807 in, and the radius of curvature of E's path, 4.320695 in (Example 3.1)
    mech = graphkin.load(examples / "ex3_1_fourbar.toml")
    sw = mech.sweep(count=4, centers=True, curvature=True)
    cols = sw.columns
    if "x_I13" in cols:
        assert abs(cols["x_I13"][0] - 5.42613) < 1e-4 and abs(cols["y_I13"][0] + 9.39833) < 1e-4
        assert abs(cols["x_I24"][0] + 11.0627) < 1e-4 and abs(cols["y_I24"][0]) < 1e-9
    if "rho_E" in cols:
        assert abs(cols["inflection_diameter_3"][0] - 40.3807) < 1e-4
        assert abs(cols["rho_E"][0] - 4.320695) < 1e-6
        # link 2 turns about the fixed pivot A: its inflection pole is the pole itself
        assert abs(cols["inflection_diameter_2"][0]) < 1e-9


def test_rolling_contact_is_swept_by_the_analytic_solver():
    # Uicker Ex. 3.9: the wheel rolls on the ground, so away from the file's drive its
    # angle follows the travel of its center: θ4 = −(x_G − 200)/ρ with ρ = 100 mm and
    # θ4 = 0 at the file's posture (x_G = 200).  The center stays 100 mm above the ground.
    from pathlib import Path

    import graphkin

    mech = graphkin.load(Path(__file__).resolve().parents[1] / "examples"
                         / "ex3_9_rolling_wheel.toml")
    sw = mech.sweep(count=7, start=90.0, stop=125.0)
    assert sw.method == "analytic"
    x = sw.columns["x_G"]
    np.testing.assert_allclose(sw.columns["y_G"], 100.0, atol=1e-9)
    np.testing.assert_allclose(np.radians(sw.columns["angle_4"]), -(x - 200.0) / 100.0,
                               atol=1e-9)


def test_a_file_drawn_in_its_dead_zone_still_sweeps():
    # Example 3.1's crank cannot pass from 326.88° to 33.12° (the coupler and rocker
    # cannot close: |BD| > BC + CD there).  A file whose drive stands in that zone
    # is laid out at the first angle of the turn that assembles, and sweeps the same
    # branch as the book's file (same hints).
    from spec_data import EXAMPLES

    import graphkin

    text = (EXAMPLES / "ex3_1_fourbar.toml").read_text().replace("angle = 120", "angle = 0")
    dead = graphkin.loads(text).sweep(count=36)
    book = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml").sweep(count=36, start=0.0)
    assert any("cannot be assembled" in n for n in dead.notes)
    assert not dead.valid[0] and dead.valid[4]
    np.testing.assert_array_equal(dead.valid, book.valid)
    ok = dead.valid
    np.testing.assert_allclose(dead.columns["angle_3"][ok], book.columns["angle_3"][ok],
                               atol=1e-9)


# ---------------------------------------------------------------------------
# centers and curvature columns against the single-posture constructions
# ---------------------------------------------------------------------------

def _with_drive(mech: graphkin.Mechanism, value: float) -> graphkin.Mechanism:
    """The mechanism with its first drive at ``value`` (rad)."""
    import dataclasses

    d = dataclasses.replace(mech.drives[0], value=value)
    return dataclasses.replace(mech, drives=(d, *mech.drives[1:]))


@pytest.mark.parametrize("k", [0, 5, 11, 17, 23])
def test_swept_centers_are_the_single_posture_kennedy_centers(bench: graphkin.Mechanism,
                                                              k: int) -> None:
    # the sweep resolves the Kennedy search once and replays its steps on the arrays; at each
    # posture the centers must be where the single-posture search (its own choice of lines)
    # puts them
    from graphkin.kinematics.instant_centers import instant_centers

    sw = bench.sweep(count=24, centers=True)
    ic = instant_centers(graphkin.solve(_with_drive(bench, float(sw.values[k]))))
    scale = bench.scale
    for c in ic.centers.values():
        x, y = c.xy
        np.testing.assert_allclose(sw.columns[f"x_{c.label}"][k], x, atol=1e-9 * scale,
                                   rtol=1e-9)
        np.testing.assert_allclose(sw.columns[f"y_{c.label}"][k], y, atol=1e-9 * scale,
                                   rtol=1e-9)


@pytest.mark.parametrize("k", [0, 5, 11, 17, 23])
def test_swept_curvature_is_the_single_posture_construction(bench: graphkin.Mechanism,
                                                            k: int) -> None:
    # J, the inflection diameter and Γ of every moving link, and ρ and the center of
    # curvature of every moving point, as the single-posture constructions of Secs. 4.14-4.16
    # (Euler-Savary, Bobillier, Hartmann) find them
    from graphkin.kinematics.curvature import curvature, path_curvatures

    sw = bench.sweep(count=24, curvature=True)
    sol = graphkin.solve(_with_drive(bench, float(sw.values[k])))
    cols = sw.columns
    scale = bench.scale
    for lid, lc in curvature(sol).items():
        # the diameter reaches 1e5 crank lengths near the crank-rocker's toggles: scale-aware
        big = max(scale, float(lc.inflection_diameter))
        np.testing.assert_allclose(cols[f"inflection_diameter_{lid}"][k],
                                   lc.inflection_diameter, rtol=1e-7, atol=1e-9 * big)
        np.testing.assert_allclose([cols[f"jx_{lid}"][k], cols[f"jy_{lid}"][k]],
                                   lc.inflection_pole, rtol=1e-7, atol=1e-9 * big)
        np.testing.assert_allclose([cols[f"gx_{lid}"][k], cols[f"gy_{lid}"][k]],
                                   lc.acceleration_center, rtol=1e-7, atol=1e-9 * scale)
    for name, pcv in path_curvatures(sol).items():
        if pcv.radius is None:
            assert f"rho_{name}" not in cols or not np.isfinite(cols[f"rho_{name}"][k])
            continue
        np.testing.assert_allclose(cols[f"rho_{name}"][k], pcv.radius, rtol=1e-7)
        assert pcv.center is not None
        np.testing.assert_allclose([cols[f"cx_{name}"][k], cols[f"cy_{name}"][k]],
                                   pcv.center, rtol=1e-7, atol=1e-7 * scale)


@settings(max_examples=15, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(mechanisms())
def test_swept_centers_and_curvature_of_random_mechanisms(rm: RandomMechanism) -> None:
    # the file's posture is the first of a default sweep: there the swept centers must be the
    # single-posture Kennedy search's and the curvature columns the single-posture
    # constructions' (pins, sliders, slots: the primary centers come from the columns)
    from graphkin.kinematics.curvature import curvature, path_curvatures
    from graphkin.kinematics.instant_centers import instant_centers

    mech = rm.mechanism()
    d = mech.drives[0]
    # an angle drive's sweep starts at the file's angle; a slider's is told to
    span = {} if d.kind == "angle" else {"start": d.value, "stop": d.value + 0.1 * mech.scale}
    try:
        sw = mech.sweep(count=6, centers=True, curvature=True, **span)
        sol = graphkin.solve(mech)
    except graphkin.GraphkinError:
        return
    if not sw.valid[0] or sw.method != "construction":
        return
    cols = sw.columns
    scale = mech.scale
    for c in instant_centers(sol).centers.values():
        if f"x_{c.label}" not in cols or c.is_ideal:
            continue
        x, y = c.xy
        tol = 1e-7 * max(scale, abs(x), abs(y))
        assert abs(cols[f"x_{c.label}"][0] - x) <= tol, c.label
        assert abs(cols[f"y_{c.label}"][0] - y) <= tol, c.label
    for lid, lc in curvature(sol).items():
        big = max(scale, float(lc.inflection_diameter))
        np.testing.assert_allclose(cols[f"inflection_diameter_{lid}"][0],
                                   lc.inflection_diameter, rtol=1e-6, atol=1e-7 * big)
        np.testing.assert_allclose([cols[f"gx_{lid}"][0], cols[f"gy_{lid}"][0]],
                                   lc.acceleration_center, rtol=1e-6, atol=1e-7 * scale)
    for name, pcv in path_curvatures(sol).items():
        if pcv.radius is None or f"rho_{name}" not in cols:
            continue
        np.testing.assert_allclose(cols[f"rho_{name}"][0], pcv.radius, rtol=1e-6,
                                   atol=1e-9 * scale)
