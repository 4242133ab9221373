"""Programs: covering 360°, lifts that chain, matching derivatives (Secs. 6.3, 6.8, Ex 6.2)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from graphkin.cams import Motion, Program, Rest, Segment
from graphkin.cams.examples import example_6_2
from graphkin.cams.program import Jump
from graphkin.errors import InputError

D = math.radians


def test_example_6_2_the_book_s_parameters_solve_its_equations():
    """Ex 6.2: solve Eqs. (5)-(9) here and compare with the printed L1, L3, β1, β3, β4.

    ω = 150 rev/min, uniform 25 in/s for 1.25 in: y'_B = L2/β2 = 1.59155 in/rad with
    β2 = 45°; β5 = 0.10 s · ω = 90°.  (5) L1 = (y'_B/2) β1; (6) L3 = (2 y'_B/π) β3;
    (7) π² L3/(4 β3²) = 5.26830 L4/β4²; (8) L1 + L3 = 1.75; (9) β1 + β3 + β4 = 3.92699.
    """
    w = 150 * 2 * math.pi / 60
    yB = 25 / w
    b2 = 1.25 / yB
    b5 = 0.10 * w
    assert abs(math.degrees(b2) - 45) < 1e-9 and abs(math.degrees(b5) - 90) < 1e-9
    # (5), (6), (8): L1 + L3 = (yB/2) β1 + (2 yB/π) β3 = 1.75; (7) with (6):
    # π yB/(2 β3) = 5.26830 L4/β4², so β3 = c β4², c = π yB/(2·5.26830·L4);
    # (9): β1 = R − β3 − β4.  One equation in β4:
    c = math.pi * yB / (2 * 5.26830 * 3.0)
    R = 2 * math.pi - b2 - b5

    def g(b4):
        b3 = c * b4 * b4
        return yB / 2 * (R - b3 - b4) + 2 * yB / math.pi * b3 - 1.75

    lo, hi = 0.5, 3.0
    for _ in range(200):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if g(lo) * g(mid) > 0 else (lo, mid)
    b4 = (lo + hi) / 2
    b3 = c * b4 * b4
    b1 = R - b3 - b4
    L1, L3 = yB / 2 * b1, 2 * yB / math.pi * b3
    # the book's answers (Sec. 6.8, Ex 6.2)
    assert abs(L1 - 1.1831) < 1e-4 and abs(L3 - 0.5669) < 1e-4
    assert abs(math.degrees(b1) - 85.184) < 2e-3
    assert abs(math.degrees(b3) - 32.058) < 2e-3
    assert abs(math.degrees(b4) - 107.758) < 2e-3
    assert abs(c - 0.15818) < 1e-5          # the book's Eq. (7)


def test_example_6_2_matches_at_every_joint():
    """The book's program has no jump in y, y' or y'' beyond its five printed digits."""
    p = example_6_2()
    assert p.joints() == []
    assert p.warnings() == []
    # y'_B = 2 L1/β1 = 1.59155 in/rad on both sides of B (Ex 6.2, Eq. 5)
    k = p.evaluate([D(85.184) - 1e-9, D(85.184) + 1e-9])
    assert np.allclose(k.y1, 1.59155, atol=2e-5)
    # velocity, acceleration at 150 rev/min in the uniform segment: 25 in/s, 0 (Ex 6.2)
    v, a, _ = k.rates(150 * 2 * math.pi / 60)
    assert np.allclose(v, 25.0, atol=5e-4) and np.allclose(a[1], 0.0)


def test_a_harmonic_rise_from_a_dwell_jumps_in_acceleration():
    """Sec. 6.7: a full harmonic has y'' = π²L/2β² at its ends (Eq. 6.12c): a warning naming it."""
    p = Program((Segment(Motion.DWELL, 0, D(90)), Segment(Motion.HARMONIC, 1.0, D(90)),
                 Segment(Motion.CYCLOIDAL, -1.0, D(180))))
    joints = p.joints()
    assert [(j.before, j.after) for j in joints] == [(0, 1), (1, 2)]
    left, right = joints[0].jumps[Jump.ACCELERATION]
    assert left == 0 and abs(right - math.pi**2 / (2 * (math.pi / 2) ** 2)) < 1e-12
    assert Jump.VELOCITY not in joints[0].jumps
    w = p.warnings()
    assert len(w) == 2 and "segment 2 (harmonic rise)" in w[0] and "Θ = 90°" in w[0]


def test_parabolic_motion_after_a_uniform_one_jumps_in_velocity():
    p = Program((Segment(Motion.UNIFORM, 1.0, D(180)), Segment(Motion.PARABOLIC, -1.0, D(180))))
    kinds = {k for j in p.joints() for k in j.jumps}
    assert Jump.VELOCITY in kinds and Jump.DISPLACEMENT not in kinds


def test_segments_that_do_not_cover_360_degrees_are_refused():
    with pytest.raises(InputError, match=r"cover 350°, 10° short of 360°.*segment 2"):
        Program((Segment(Motion.CYCLOIDAL, 1.0, D(170)), Segment(Motion.CYCLOIDAL, -1.0, D(180))),
                source="c.toml")


def test_a_lift_that_does_not_come_back_is_refused_naming_the_segment():
    with pytest.raises(InputError, match=r"segment 1 \(cycloidal rise\): the displacement jumps "
                                         r"from 0.5 to 0 at 0°"):
        Program((Segment(Motion.CYCLOIDAL, 1.0, D(180)), Segment(Motion.CYCLOIDAL, -0.5, D(180))))


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan])
def test_a_non_positive_angle_is_refused(bad):
    with pytest.raises(InputError, match="angle must be positive"):
        Program((Segment(Motion.CYCLOIDAL, 1.0, bad), Segment(Motion.CYCLOIDAL, -1.0, 2 * math.pi)))


def test_verdicts_do_not_move_under_a_perturbation_of_1e_12():
    """Perturbing lifts and angles by 1e-12 of their size changes no verdict."""
    p = example_6_2()
    for eps in (1e-12, -1e-12):
        q = Program(tuple(Segment(s.motion, s.lift * (1 + eps), s.angle * (1 + eps) if i < 4
                                  else 2 * math.pi - sum(t.angle * (1 + eps)
                                                         for t in p.segments[:4]),
                                  s.rest, s.name)
                          for i, s in enumerate(p.segments[:4]))
                    + (Segment(Motion.DWELL, 0.0, 2 * math.pi - sum(t.angle * (1 + eps)
                                                                     for t in p.segments[:4])),),)
        assert q.joints() == []
    harmonic = Program((Segment(Motion.DWELL, 0, D(90)), Segment(Motion.HARMONIC, 1.0, D(90)),
                        Segment(Motion.CYCLOIDAL, -1.0, D(180))))
    for eps in (1e-12, -1e-12):
        moved = Program(tuple(Segment(s.motion, s.lift * (1 + eps), s.angle, s.rest)
                              for s in harmonic.segments[:2])
                        + (Segment(Motion.CYCLOIDAL, -(1 + eps), D(180)),))
        assert [sorted(j.jumps, key=str) for j in moved.joints()] == \
            [sorted(j.jumps, key=str) for j in harmonic.joints()]


def test_a_table_segment_joins_its_neighbours():
    """Points given as a table: a jump at its first point is refused like any other."""
    th = tuple(np.radians([0, 30, 60, 90]))
    ok = Program((Segment(Motion.TABLE, 0.0, D(90), table=(th, (0.0, 0.2, 0.8, 1.0))),
                  Segment(Motion.CYCLOIDAL, -1.0, D(270))))
    k = ok.evaluate(np.radians([30.0, 60.0]))
    assert np.allclose(k.Y, [0.2, 0.8])
    with pytest.raises(InputError, match="segment 2"):
        Program((Segment(Motion.TABLE, 0.0, D(90), table=(th, (0.0, 0.2, 0.8, 1.0))),
                 Segment(Motion.CYCLOIDAL, -1.5, D(270))))


def test_rest_forms_name_the_book_s_equations():
    assert Segment(Motion.HALF_HARMONIC, 1, 1, Rest.END).equation == "Eq. (6.19), Fig. 6.20b"
    assert Segment(Motion.HALF_CYCLOIDAL, -1, 1, Rest.START).equation == "Eq. (6.24), Fig. 6.23a"
    assert Segment(Motion.POLYNOMIAL8, -1, 1).equation == "Eq. (6.17), Fig. 6.19"
