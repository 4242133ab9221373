"""Function generation when Eqs. 9.25-9.27 give negative lengths (Sec. 9.11).

Freudenstein's lengths carry signs: K1 < 0 gives r4 < 0, and the rocker's
angle θ4 of the loop r2 e^{iφ} + r3 e^{iθ3} + r4 e^{iθ4} = r1 (Fig. 9.39) is
then the angle of O4 − C plus 180°.  The structural error once took the angle
of O4 − C itself, and reported |Δy| = 13.6 for y = x² on [0.5, 2.5] (y spans
6) where the linkage is within 0.13 of it.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.synthesis.function import _rocker, design
from graphkin.synthesis.spec import load_spec, loads_spec

DATA = Path(__file__).parent / "data"


def test_negative_r4_structural_error_matches_the_written_linkage() -> None:
    # The file (an acceptance input): y = x² on [0.5, 2.5], φ from 40° over 100°,
    # ψ from 200° over 80°, r1 = 3 in.  Eq. 9.25 gives r4 = r1/K1 < 0 here.
    spec = load_spec(DATA / "audit_function_negative_r4.toml")
    assert spec.function is not None
    fd = design(spec.function, samples=51)
    assert fd.lengths[3] < 0 and fd.lengths[1] < 0
    # The written mechanism, swept by graphkin's constructions (not the closed form
    # of design()): the rocker's own angle is θ4 of the loop + 180° (link 4 is written
    # O4 -> C, i.e. along -r4 e^{iθ4}); y generated = ya + (ψ − ψ0)(yb − ya)/Δψ.
    mech = graphkin.loads(fd.mechanism_toml())
    phi = 40.0 + 100.0 * (fd.error_x - 0.5) / 2.0
    sw = mech.sweep(count=phi.size, start=float(phi[0]), stop=float(phi[-1] + 2.0))
    assert np.allclose(np.degrees(sw.values), phi)
    psi = np.mod(sw.columns["angle_4"] + 180.0 - 200.0 + 180.0, 360.0) - 180.0 + 200.0
    y_gen = 0.25 + (psi - 200.0) * 6.0 / 80.0
    by_sweep = y_gen - fd.error_x ** 2
    assert fd.error == pytest.approx(by_sweep, abs=1e-9)
    # three precision points: the error vanishes there and stays small between
    assert np.nanmax(np.abs(fd.error)) < 0.2


@settings(max_examples=40, deadline=None)
@given(start_in=st.floats(-170, 170), span_in=st.floats(40, 150),
       start_out=st.floats(-170, 170), span_out=st.floats(40, 150),
       sense=st.sampled_from([1.0, -1.0]),
       expr=st.sampled_from(["x**2", "1/x", "sqrt(x)", "log(x)", "exp(x/2)"]))
def test_rocker_angle_hits_psi_at_the_precision_points(start_in: float, span_in: float,
                                                       start_out: float, span_out: float,
                                                       sense: float, expr: str) -> None:
    # Whatever the signs of r2 and r4, the loop solved at φ_j on the design's branch
    # puts the rocker at ψ_j (the equations Freudenstein's K were solved from).
    spec = loads_spec(f'[function]\nexpression = "{expr}"\nrange = [1, 2]\n'
                      f"input = {{ start = {start_in!r}, span = {span_in!r} }}\n"
                      f"output = {{ start = {start_out!r}, span = {sense * span_out!r} }}\n")
    assert spec.function is not None
    fd = design(spec.function, samples=11)
    if not all(math.isfinite(v) for v in fd.lengths):
        return                                   # r3² < 0: no linkage (reported elsewhere)
    th, h2 = _rocker(fd.phi, fd.lengths, fd.branch)
    scale = max(abs(v) for v in fd.lengths)
    assert np.all(h2 > -1e-9 * scale ** 2)
    # the side of C from B -> O4 at each precision point (the assembly branch); a
    # point on the other branch than the first is a branch defect, reported by the
    # checks, and the loop solved on the first's branch cannot reach it
    r1, r2, _r3, r4 = fd.lengths
    b = r2 * np.exp(1j * fd.phi)
    c = r1 - r4 * np.exp(1j * fd.psi)
    u, v = r1 - b, c - b
    side = np.sign(u.real * v.imag - u.imag * v.real)
    same = side == side[0]
    miss = np.abs(np.remainder(th - fd.psi + math.pi, math.tau) - math.pi)
    assert miss[same] == pytest.approx(np.zeros(int(same.sum())), abs=1e-6)
