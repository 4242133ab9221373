"""The dwell six-bar of Sec. 9.13, analysed by graphkin: link 6 is still while C runs the arc."""

from __future__ import annotations

import math

import numpy as np
import pytest

import graphkin
from graphkin.synthesis.dwell import DwellKind, dwell

OA, OB = 0j, 4 + 0j


def _posture(theta: float) -> tuple[complex, complex]:
    a = OA + 1.5 * np.exp(1j * theta)
    d = OB - a
    dist = abs(d)
    along = (dist ** 2 + 16 - 12.25) / (2 * dist)
    return complex(a), complex(a + (along + math.sqrt(16 - along ** 2) * 1j) * d / dist)


def test_link_6_dwells_while_the_coupler_point_runs_the_arc() -> None:
    a, b = _posture(0.5)
    c = a + (0.5 - 0.8j) * (b - a)
    dw = dwell(OA, a, b, OB, c, math.radians(60))
    # D is the arc's center: C1, C2, C3 at the radius of link 5
    for lab in ("C1", "C2", "C3"):
        v = dw.construction.evaluate()[lab]
        assert abs(abs(complex(v[0], v[1]) - dw.d) - dw.radius) < 1e-9 * dw.radius
    mech = graphkin.loads(dw.mechanism_toml())
    t0, t1 = (math.degrees(float(dw.crank[k % len(dw.crank)])) for k in (dw.start, dw.stop))
    t1 = t0 + (t1 - t0) % 360
    inside = mech.sweep(count=61, start=t0, stop=t1 + (t1 - t0) / 60)
    assert bool(inside.assembled.all())
    ang = np.unwrap(np.radians(inside.columns["angle_6"]))
    # C stays within δ = deviation of the circle of radius r5 about D; link 6 (perpendicular
    # to link 5, as long as it) turns by about δ / r6 each way: at most 2δ / r6 in all,
    # doubled for the motion of link 5's direction over the arc
    swing = float(np.ptp(ang))
    assert swing <= 4 * dw.deviation / abs(dw.d - dw.o6) + 1e-9
    whole = mech.sweep(count=360)
    assert bool(whole.assembled.all())
    moved = float(np.ptp(np.unwrap(np.radians(whole.columns["angle_6"]))))
    assert moved > 10 * swing          # outside the dwell it swings


def test_dwell_file_cli_and_drawing(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    import xml.etree.ElementTree as ET

    from graphkin.cli import main

    a, b = _posture(0.5)
    c = a + (0.5 - 0.8j) * (b - a)
    f = tmp_path / "d.toml"
    f.write_text("[dwell]\n" + "".join(
        f"{k} = [{float(z.real)!r}, {float(z.imag)!r}]\n"
        for k, z in (("O_A", OA), ("A", a), ("B", b), ("O_B", OB), ("C", c))) + "span = 60\n")
    out, svg = tmp_path / "m.toml", tmp_path / "d.svg"
    assert main(["synthesize", str(f), "-o", str(out), "--draw", str(svg)]) == 0
    assert "Dwell (Sec. 9.13)" in capsys.readouterr().out
    assert graphkin.load(out).solve() is not None
    ids = {e.get("id") for e in ET.parse(svg).iter() if e.get("id")}
    for gid in ("coupler-curve", "dwell-arc", "link-5", "link-6", "linkage-1", "fixed-pivots"):
        assert f"dwell-{gid}" in ids   # the panel's gids carry its name
    assert any(i.startswith("dwell-step-") and i.endswith("-D") for i in ids)
    f.write_text(f.read_text().replace("span = 60", "span = 400"))
    assert main(["synthesize", str(f)]) == 2
    assert "dwell.span" in capsys.readouterr().err


@pytest.mark.parametrize("local", [0.5 + 0j, 1.2 + 0.3j, 0.5 - 0.8j])
def test_slotted_link_6_dwells_while_the_coupler_point_runs_the_straight_stretch(
        local: complex) -> None:
    """Fig. 9.44: O6 on the line of the stretch; graphkin's sweep of the written file."""
    a, b = _posture(0.5)
    c = a + local * (b - a)
    dw = dwell(OA, a, b, OB, c, math.radians(60), kind=DwellKind.SLIDER)
    ev = dw.construction.evaluate()
    z1, z3, o6 = (complex(ev[k][0] / ev[k][2], ev[k][1] / ev[k][2]) for k in ("C1", "C3", "O6"))
    u = (z3 - z1) / abs(z3 - z1)
    assert abs(((o6 - z1) * u.conjugate()).imag) < 1e-9 * abs(o6 - z1)   # O6 on the line
    mech = graphkin.loads(dw.mechanism_toml())
    t0, t1 = (math.degrees(float(dw.crank[k % len(dw.crank)])) for k in (dw.start, dw.stop))
    t1 = t0 + (t1 - t0) % 360
    inside = mech.sweep(count=61, start=t0, stop=t1 + (t1 - t0) / 60)
    assert bool(inside.assembled.all())
    cz = np.asarray(inside.columns["x_C"]) + 1j * np.asarray(inside.columns["y_C"])
    # C (as graphkin moves it) within δ of the line C1C3 over the dwell
    dev = float(np.max(np.abs(((cz - z1) * u.conjugate()).imag)))
    assert dev <= dw.deviation + 1e-9 * abs(z3 - z1)
    # the slot through O6 and C then turns at most 2 asin(δ / nearest O6C) (each side of it)
    ang = np.unwrap(np.radians(inside.columns["angle_6"]))
    swing = float(np.ptp(ang))
    assert swing <= 2 * math.asin(dev / float(np.min(np.abs(cz - o6)))) + 1e-9
    whole = mech.sweep(count=360)
    assert bool(whole.assembled.all())
    moved = float(np.ptp(np.unwrap(np.radians(whole.columns["angle_6"]))))
    assert moved > 8 * swing          # outside the dwell it swings


def test_slider_dwell_file_and_drawing(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    from graphkin.cli import main

    a, b = _posture(0.5)
    c = a + 0.5 * (b - a)
    f = tmp_path / "d.toml"
    f.write_text("[dwell]\n" + "".join(
        f"{k} = [{float(z.real)!r}, {float(z.imag)!r}]\n"
        for k, z in (("O_A", OA), ("A", a), ("B", b), ("O_B", OB), ("C", c)))
        + "span = 60\nslider = true\n")
    out, svg = tmp_path / "m.toml", tmp_path / "d.svg"
    assert main(["synthesize", str(f), "-o", str(out), "--draw", str(svg)]) == 0
    assert "Fig. 9.44" in capsys.readouterr().out
    assert "[[slots]]" in out.read_text() and graphkin.load(out).solve() is not None
    assert "dwell-link-6" in svg.read_text()
    f.write_text(f.read_text().replace("slider = true", "slider = 1"))
    assert main(["synthesize", str(f)]) == 2
    assert "dwell.slider" in capsys.readouterr().err
