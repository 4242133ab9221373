"""Roberts-Chebyshev cognates by Cayley's diagram (Sec. 9.10), checked by graphkin's analysis."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.synthesis.cognates import cayley

OA, OB = 0j, 4 + 0j


def _pins(theta: float, crank: float = 1.5, coupler: float = 4.0,
          rocker: float = 3.5) -> tuple[complex, complex]:
    """A crank-rocker closed in form (two circles meet, Sec. 2.8), the open branch."""
    a = OA + crank * np.exp(1j * theta)
    d = OB - a
    dist = abs(d)
    along = (dist ** 2 + coupler ** 2 - rocker ** 2) / (2 * dist)
    h = np.sqrt(coupler ** 2 - along ** 2)
    return complex(a), complex(a + along * d / dist + h * 1j * d / dist)


@settings(max_examples=15, deadline=None)
@given(st.floats(-1.0, 1.0), st.floats(-1.0, 1.0))
def test_three_cognates_trace_one_coupler_curve(rx: float, ry: float) -> None:
    r = complex(rx, ry)
    if abs(r) < 0.05 or abs(r - 1) < 0.05:
        return   # P on a pin: a cognate link of no length
    for theta in (0.3, 1.7, 3.1, 4.6):
        a, b = _pins(theta)
        p = a + r * (b - a)
        cg = cayley(OA, a, b, OB, p)
        for which in ("1", "2", "3"):
            # graphkin solves each cognate from its own link lengths, at its crank's angle
            sol = graphkin.loads(cg.mechanism_toml(which)).solve()
            assert sol.position("P") == pytest.approx([p.real, p.imag], abs=1e-9)


def test_cayley_diagram_links_keep_their_lengths() -> None:
    # |O_A A2| = |AP|, |A2 B2| = |r| |O_A A|, |B2 O_C| = |r| |O_B B| (r = (P − A)/(B − A));
    # O_C does not move: the triangle O_A O_B O_C is similar to A B P
    r = 0.3 + 0.6j
    first = None
    for theta in np.linspace(0.0, 2 * np.pi, 7)[:-1]:
        a, b = _pins(float(theta))
        cg = cayley(OA, a, b, OB, a + r * (b - a))
        z = cg.points
        assert abs(z["A2"] - z["O_A"]) == pytest.approx(abs(r * (b - a)), abs=1e-12)
        assert abs(z["B2"] - z["A2"]) == pytest.approx(abs(r) * 1.5, abs=1e-12)
        assert abs(z["B2"] - z["O_C"]) == pytest.approx(abs(r) * 3.5, abs=1e-12)
        assert z["O_C"] == pytest.approx(OA + r * (OB - OA), abs=1e-12)
        first = first or cg
    assert first is not None
    # the link of each cognate that turns with the original crank (parallel to O_A A, |r| or
    # |1 − r| times as long) is its shortest: cognate 2's coupler A2 B2 (|r| 1.5 = 1.006, a
    # Grashof double-rocker), cognate 3's rocker O_C A3 (|1 − r| 1.5 = 1.383, a rocker-crank)
    from graphkin.synthesis.linkage import grashof_class

    z = first.points
    classes = {}
    for which, (o1, p1, p2, o2) in first.linkages().items():
        lengths = {"ground": abs(z[o2] - z[o1]), "crank": abs(z[p1] - z[o1]),
                   "coupler": abs(z[p2] - z[p1]), "rocker": abs(z[p2] - z[o2])}
        classes[which] = grashof_class(lengths)[0]
    assert classes == {"1": "Grashof crank-rocker", "2": "Grashof double-rocker",
                       "3": "Grashof rocker-crank"}
    assert abs(z["B2"] - z["A2"]) == pytest.approx(abs(r) * 1.5, abs=1e-12)
    assert abs(z["A3"] - z["O_C"]) == pytest.approx(abs(1 - r) * 1.5, abs=1e-12)
    # graphkin sweeps cognate 3 by its crank O_B B3 over the range it assembles
    sw = graphkin.loads(first.mechanism_toml("3")).sweep(count=72)
    assert bool(sw.assembled.any())


def test_cognates_file_cli_and_drawing(tmp_path, capsys) -> None:  # type: ignore[no-untyped-def]
    import xml.etree.ElementTree as ET

    from graphkin.cli import main

    a, b = _pins(0.7)
    p = a + (0.3 + 0.6j) * (b - a)
    f = tmp_path / "c.toml"
    f.write_text("[cognates]\n" + "".join(
        f"{k} = [{float(z.real)!r}, {float(z.imag)!r}]\n"
        for k, z in (("O_A", OA), ("A", a), ("B", b), ("O_B", OB), ("P", p))) + "write = 3\n")
    out, svg = tmp_path / "m.toml", tmp_path / "c.svg"
    assert main(["synthesize", str(f), "-o", str(out), "--draw", str(svg)]) == 0
    assert "Cognate 3: O_B = (4, 0)" in capsys.readouterr().out
    sol = graphkin.load(out).solve()
    assert sol.position("P") == pytest.approx([p.real, p.imag], abs=1e-9)
    ids = {e.get("id") for e in ET.parse(svg).iter() if e.get("id")}
    for gid in ("cognate-1", "cognate-2", "cognate-3", "coupler-curve"):
        assert f"cognates-{gid}" in ids   # the panel's gids carry its name
    for name in ("O_C", "A2", "B2", "B3", "A3"):
        assert any(i.startswith("cognates-step-") and i.endswith(f"-{name}") for i in ids), name
    f.write_text("[cognates]\nO_A = [0, 0]\nA = [0, 0]\nB = [1, 1]\nO_B = [2, 0]\nP = [1, 2]\n")
    assert main(["synthesize", str(f)]) == 2
    assert "cognates.A: O_A and A coincide" in capsys.readouterr().err
