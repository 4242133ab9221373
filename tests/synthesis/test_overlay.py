"""The overlay method (Sec. 9.8): a generated atlas of coupler curves searched for a path."""

from __future__ import annotations

import math

import numpy as np
import pytest

import graphkin
from graphkin.cli import main
from graphkin.errors import InputError
from graphkin.synthesis import loads_spec, synthesize
from graphkin.synthesis.overlay import SAMPLES, atlas, overlay, trace


def _spec(z: np.ndarray, closed: bool) -> str:
    pts = ", ".join(f"[{float(p.real)!r}, {float(p.imag)!r}]" for p in z)
    return (f'title = "overlay"\nunits = "in"\n[overlay]\npoints = [{pts}]\n'
            f"closed = {'true' if closed else 'false'}\n")


def test_an_atlas_curve_moved_turned_and_scaled_is_found_and_traced_by_graphkin() -> None:
    # a curve of the atlas itself, laid elsewhere by z -> s z + t (turned 40°, 3.5 times as
    # large): the fit is exact, and graphkin's own sweep of the written mechanism passes
    # through every point of the path (the crank stepped as the atlas samples it)
    book = atlas()
    row = 137
    s, t = 3.5 * np.exp(1j * math.radians(40.0)), 12.0 - 4.0j
    path = s * book.curves[row] + t
    res = synthesize(loads_spec(_spec(path, True)))
    ov = res.overlay
    assert ov is not None and ov.residual < 1e-9
    mech = graphkin.loads(res.mechanism_toml())
    start = math.degrees(float(np.angle(ov.a - ov.o2)))
    sw = mech.sweep(count=SAMPLES, start=start, stop=start + 360.0)   # k·360°/SAMPLES
    traced = np.asarray(sw.columns["x_P"]) + 1j * np.asarray(sw.columns["y_P"])
    size = float(np.max(np.abs(path - path.mean())))
    gap = np.min(np.abs(path[:, None] - traced[None, :]), axis=1)
    assert float(np.max(gap)) < 1e-6 * size


def test_a_stretch_of_another_four_bars_curve_is_fitted_closely() -> None:
    # the coupler curve of a crank-rocker not in the atlas (coupler 2.7, rocker 3.1, frame
    # 2.9, point (0.9, 1.3)), a stretch of it turned, scaled and moved: the best atlas curve
    # lays on it within a few per cent of its size (the atlas is a grid, Hrones-Nelson's
    # steps), and the written four-bar, swept by graphkin, passes near every point
    dims = np.array([[1.0, 2.7, 3.1, 2.9, 0.9, 1.3]])
    z = trace(dims, np.linspace(0.5, 3.0, 40))[0]
    path = 3 * (0.5 - 1.2j) * np.exp(0.7j) * z + (10 + 5j)
    res = synthesize(loads_spec(_spec(path, False)))
    ov = res.overlay
    assert ov is not None and ov.residual < 0.01
    sw = graphkin.loads(res.mechanism_toml()).sweep(count=721)
    traced = np.asarray(sw.columns["x_P"]) + 1j * np.asarray(sw.columns["y_P"])
    size = float(np.max(np.abs(path - path.mean())))
    gap = np.min(np.abs(path[:, None] - traced[None, :]), axis=1)
    assert float(np.max(gap)) < 0.05 * size


def test_the_fit_does_not_depend_on_where_the_path_is_or_how_large() -> None:
    # position, rotation and scale invariance: the same path moved, turned and scaled picks
    # the same atlas curve with the same residual
    dims = np.array([[1.0, 2.2, 2.6, 2.4, 0.3, -0.8]])
    z = trace(dims, np.linspace(0.0, 4.0, 30))[0]
    a = overlay(z)
    b = overlay(0.01 * np.exp(2.0j) * z + (1e3 - 7e2j))
    assert a.row == b.row
    assert b.residual == pytest.approx(a.residual, rel=1e-6, abs=1e-12)


def test_too_few_points_is_one_line_and_exit_2(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(InputError, match="at least four points") as info:
        loads_spec('[overlay]\npoints = [[0, 0], [1, 0], [2, 1]]\n')
    assert info.value.key == "overlay.points"
    f = tmp_path / "bad.toml"
    f.write_text('[overlay]\npoints = [[0, 0], [0, 0], [0, 0], [0, 0]]\n', encoding="utf-8")
    assert main(["synthesize", str(f)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "overlay.points" in err[0] and "coincide" in err[0]
