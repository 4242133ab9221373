"""The four cases of C = A + B (Table 2.2) against the complex-polar closed forms.

The graphic constructions of Sec. 2.8 are checked against an independent
oracle, the closed forms of Sec. 2.11 (Eqs. 2.43-2.50, written for
``C e^{jθ_C} = A e^{jθ_A} + B e^{jθ_B}``), to 1e-9 of the figure's size, on
random triangles (Hypothesis), and against worked examples of the book.
References are to Uicker, Pennock & Shigley, 5th ed.
"""

from __future__ import annotations

import cmath
import math
import pickle

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st
from numpy.testing import assert_allclose

from graphkin.construction import OPS, Along, Mark, Role, Side
from graphkin.errors import (
    ConstructionError,
    InputError,
    NoIntersectionError,
    ParallelDirectionsError,
)
from graphkin.geometry import Vector
from graphkin.geometry import ops as g
from graphkin.kinematics.vector_equation import (
    Polar,
    VectorEquationCase,
    solve_vector_equation,
)

REL = 1e-9  # agreement with the closed forms, relative to the size of the triangle

# ---- the oracle: Sec. 2.11 ------------------------------------------------------------


def _case_1(A: complex, B: complex) -> list[complex]:
    """Eqs. 2.43-2.44: C from A and B (C = A + B)."""
    a, ta, b, tb = abs(A), cmath.phase(A), abs(B), cmath.phase(B)
    C = math.sqrt(a * a + b * b + 2 * a * b * math.cos(tb - ta))                  # (2.43)
    tc = math.atan2(a * math.sin(ta) + b * math.sin(tb),
                    a * math.cos(ta) + b * math.cos(tb))                           # (2.44)
    return [cmath.rect(C, tc)]


def _case_2(C: complex, ta: float, b: float) -> list[tuple[complex, complex]]:
    """Eqs. 2.45-2.46: A (magnitude along θ_A) and θ_B, given C, θ_A and B."""
    c, tc = abs(C), cmath.phase(C)
    s = c * math.sin(tc - ta) / b
    out = []
    for psi in (math.asin(s), math.pi - math.asin(s)):   # the arcsine is double-valued
        tb = ta + psi                                                              # (2.45)
        a = c * math.cos(tc - ta) - b * math.cos(tb - ta)                          # (2.46)
        out.append((cmath.rect(a, ta), cmath.rect(b, tb)))
    return out


def _case_3(C: complex, ta: float, tb: float) -> list[tuple[complex, complex]]:
    """Eqs. 2.47-2.48: magnitudes A and B, given C, θ_A and θ_B."""
    c, tc = abs(C), cmath.phase(C)
    b = c * math.sin(tc - ta) / math.sin(tb - ta)                                  # (2.47)
    a = c * math.sin(tc - tb) / math.sin(ta - tb)                                  # (2.48)
    return [(cmath.rect(a, ta), cmath.rect(b, tb))]


def _case_4(C: complex, a: float, b: float) -> list[tuple[complex, complex]]:
    """Eqs. 2.49-2.50: θ_A and θ_B, given C, A and B, paired by Eq. (i)."""
    c, tc = abs(C), cmath.phase(C)
    alpha = math.acos((c * c + a * a - b * b) / (2 * a * c))                       # (2.50)
    beta = math.acos((c * c + b * b - a * a) / (2 * b * c))                        # (2.49)
    # Eq. (i), A sin(θ_A - θ_C) = -B sin(θ_B - θ_C): opposite signs for A, B > 0
    return [(cmath.rect(a, tc + sign * alpha), cmath.rect(b, tc - sign * beta))
            for sign in (1, -1)]


def closed_form(knowns: dict[str, Polar]) -> list[dict[str, complex]]:
    """Every solution of C = A + B from the closed forms, as complex numbers.

    Cases whose known vector is A or B are first rewritten in the form of
    Eq. 2.42 with the known vector on the left: A = C + (-B), B = C + (-A).  A
    negated vector keeps its magnitude and turns its direction by 180°.
    """
    case = VectorEquationCase.of(knowns["A"], knowns["B"], knowns["C"])
    if case == VectorEquationCase.CASE_1:
        (u,) = [n for n in "ABC" if not knowns[n].is_known]
        v = {n: complex(*knowns[n].vector) for n in "ABC" if n != u}
        if u == "C":
            return [{**v, "C": _case_1(v["A"], v["B"])[0]}]
        other = "B" if u == "A" else "A"
        return [{**v, u: _case_1(v["C"], -v[other])[0]}]
    (z,) = [n for n in "ABC" if knowns[n].is_known]
    x, y = ("A", "B") if z == "C" else ("C", "B" if z == "A" else "A")
    sign = {x: 1.0, y: 1.0 if z == "C" else -1.0}   # z = x + sign*y, written z = x' + y'

    def turned(n: str) -> float:  # the direction of x' or y'
        t = knowns[n].angle
        assert t is not None
        return t + (math.pi if sign[n] < 0 else 0.0)

    Z = complex(*knowns[z].vector)
    pairs: list[tuple[complex, complex]]
    if case == VectorEquationCase.CASE_3:
        pairs = _case_3(Z, turned(x), turned(y))
    elif case == VectorEquationCase.CASE_4:
        pairs = _case_4(Z, knowns[x].magnitude, knowns[y].magnitude)  # type: ignore[arg-type]
    else:
        line, arc = (x, y) if knowns[x].magnitude is None else (y, x)
        solved = _case_2(Z, turned(line), knowns[arc].magnitude)  # type: ignore[arg-type]
        pairs = [(p[0], p[1]) if line == x else (p[1], p[0]) for p in solved]
    return [{z: Z, x: px * sign[x], y: py * sign[y]} for px, py in pairs]


# ---- random triangles -----------------------------------------------------------------

magnitudes = st.floats(0.1, 100)
angles = st.floats(-math.pi, math.pi, allow_subnormal=False)
triangles = st.builds(lambda a, ta, b, tb: (cmath.rect(a, ta), cmath.rect(b, tb)),
                      magnitudes, angles, magnitudes, angles)
# which parts are unknown: (vector, part) pairs, for each case and each assignment
UNKNOWNS = {
    1: [((n, "magnitude"), (n, "angle")) for n in "ABC"],
    2: [((m, "magnitude"), (d, "angle")) for m in "ABC" for d in "ABC" if m != d],
    3: [((m, "magnitude"), (n, "magnitude")) for m, n in ("AB", "AC", "BC")],
    4: [((m, "angle"), (n, "angle")) for m, n in ("AB", "AC", "BC")],
}


def _knowns(A: complex, B: complex, hidden) -> dict[str, Polar]:
    true = {"A": A, "B": B, "C": A + B}
    out = {}
    for n, v in true.items():
        m, t = abs(v), cmath.phase(v)
        out[n] = Polar(None if (n, "magnitude") in hidden else m,
                       None if (n, "angle") in hidden else t)
    return out


def _well_conditioned(k: dict[str, Polar], case: int) -> bool:
    """Keep away from tangency and from parallel lines, where the closed forms lose digits."""
    if case == 1:
        return True
    (z,) = [n for n in "ABC" if k[n].is_known]
    x, y = [n for n in "ABC" if n != z]
    zm = abs(k[z].magnitude)  # type: ignore[arg-type]
    if case == 3:
        return abs(math.sin(k[x].angle - k[y].angle)) > 1e-2  # type: ignore[operator]
    if case == 4:
        a, b = k[x].magnitude, k[y].magnitude
        return zm > 1e-3 * max(a, b) and all(  # type: ignore[type-var]
            abs((zm**2 + p**2 - q**2) / (2 * p * zm)) < 1 - 1e-3 for p, q in ((a, b), (b, a)))
    line, arc = (x, y) if k[x].magnitude is None else (y, x)
    offset = abs(Vector.polar(1, k[line].angle).cross(k[z].vector))  # type: ignore[arg-type]
    return offset < (1 - 1e-3) * k[arc].magnitude  # type: ignore[operator]


def _match(result, expected: list[dict[str, complex]], scale: float) -> None:
    assert len(result.solutions) == len(expected)
    for sol in result.solutions:
        got = {n: complex(*getattr(sol, n)) for n in "ABC"}
        err = min(max(abs(got[n] - e[n]) for n in "ABC") for e in expected)
        assert err <= REL * scale, (got, expected)
    for e in expected:  # and every closed-form solution is found
        err = min(max(abs(complex(*getattr(s, n)) - e[n]) for n in "ABC")
                  for s in result.solutions)
        assert err <= REL * scale


@pytest.mark.parametrize("case", [1, 2, 3, 4])
@given(data=st.data())
def test_every_case_agrees_with_the_closed_forms(case, data):
    A, B = data.draw(triangles)
    hidden = data.draw(st.sampled_from(UNKNOWNS[case]))
    k = _knowns(A, B, hidden)
    assume(_well_conditioned(k, case))
    scale = max(abs(A), abs(B), abs(A + B))
    result = solve_vector_equation(k["A"], k["B"], k["C"])
    assert result.case == case
    _match(result, closed_form(k), scale)
    # the triangle the knowns were taken from is one of the solutions
    assert min(max(abs(complex(*s.A) - A), abs(complex(*s.B) - B))
               for s in result.solutions) <= REL * scale
    for s in result.solutions:  # each solution closes: C = A + B
        assert abs(complex(*(s.A + s.B - s.C))) <= REL * scale



def _solved_case(AB, hidden, case: int):
    """The knowns of triangle ``AB`` with ``hidden`` unknown (well conditioned), solved."""
    A, B = AB
    k = _knowns(A, B, hidden)
    assume(_well_conditioned(k, case))
    return k, solve_vector_equation(k["A"], k["B"], k["C"])

@given(triangles, st.sampled_from(UNKNOWNS[4]))
def test_case_4_left_is_left_of_the_known_vector(AB, hidden):
    k, r = _solved_case(AB, hidden, 4)
    assert r.branches == ("left", "right")
    (z,) = [n for n in "ABC" if k[n].is_known]
    # the free vertex seen from the known vector's origin: left = positive cross product
    # (A = P - O, B = T - P, C = T - O, so the free vertex minus z's origin is:)
    off = {"C": lambda s: s.A, "A": lambda s: s.C, "B": lambda s: -s.A}[z]
    zv = k[z].vector
    left, right = r.solutions
    assert zv.cross(off(left)) > 0 > zv.cross(off(right))


@given(triangles, st.sampled_from(UNKNOWNS[2]))
def test_case_2_behind_comes_first_along_the_known_direction(AB, hidden):
    k, r = _solved_case(AB, hidden, 2)
    assert r.branches == ("behind", "ahead")
    (line,) = [n for n in "ABC" if k[n].magnitude is None]
    u = Vector.polar(1, k[line].angle)  # type: ignore[arg-type]
    # the free vertex is the end of the line's vector away from the known vector;
    # its position along u, relative to the line's anchor, orders the branches
    behind, ahead = r.solutions
    (z,) = [n for n in "ABC" if k[n].is_known]
    # A = P - O, B = T - P, C = T - O; the free vertex is the one not on the known vector
    ends = {"A": ("O", "P"), "B": ("P", "T"), "C": ("O", "T")}
    (free,) = {"O", "P", "T"} - set(ends[z])
    free_is_tip = ends[line][1] == free

    def along(s) -> float:
        v = getattr(s, line)
        return v.dot(u) if free_is_tip else -v.dot(u)

    assert along(behind) < along(ahead)


# ---- textbook examples ----------------------------------------------------------------


def test_example_2_3_case_1_addition():
    # 10∠30° + 8∠-15° = 16.65∠10.1° (Sec. 2.10, Example 2.3)
    r = solve_vector_equation(Polar.deg(10, 30), Polar.deg(8, -15), Polar())
    assert r.case == VectorEquationCase.CASE_1 and r.branches == (None,)
    C = r.polar()[2]
    assert C.magnitude == pytest.approx(16.647, abs=5e-4)
    assert math.degrees(C.angle) == pytest.approx(10.14, abs=5e-3)


def test_example_2_4_case_1():
    # R_AO4 = R_O2O4 + R_AO2 = 9 in∠90° + 4.5 in∠135° = 12.59 in∠104.64° (Example 2.4)
    r = solve_vector_equation(Polar.deg(9, 90), Polar.deg(4.5, 135), Polar())
    C = r.polar()[2]
    assert C.magnitude == pytest.approx(12.59, abs=5e-3)
    assert math.degrees(C.angle) == pytest.approx(104.64, abs=5e-3)


def test_example_2_5_case_4_with_a_negative_magnitude():
    # Example 2.5: S = R_BA - R_BO4 with S = 0.400 m∠15° - 0.200 m∠30° = 0.213 m∠0.95°,
    # R_BA = 0.350 m and -R_BO4 = -0.300 m: θ3 = 59.46° and θ4 = 96.76° (open),
    # θ3' = -57.56° and θ4' = -94.86° (crossed)
    S = Vector.polar(0.400, math.radians(15)) - Vector.polar(0.200, math.radians(30))
    assert S.magnitude == pytest.approx(0.213, abs=5e-4)
    r = solve_vector_equation(Polar(0.350), Polar(-0.300), Polar(S.magnitude, S.angle))
    (a1, b1, _), (a2, b2, _) = r.polar(0), r.polar(1)
    assert r.branches == ("left", "right")
    assert (b1.magnitude, b2.magnitude) == (-0.300, -0.300)
    assert [round(math.degrees(t), 2) for t in (a1.angle, b1.angle, a2.angle, b2.angle)] == \
        [59.46, 96.76, -57.56, -94.86]
    # a negative magnitude points along θ + 180°: the vector itself is -0.3∠θ4
    assert abs(r.solutions[0].B - Vector.polar(-0.300, b1.angle)) < 1e-12


def test_gallery_case_2_numbers():
    # C = 8∠0°, θ_A = 30°, B = 5: the line passes 8 sin 30° = 4 from the terminus of C,
    # so A = 8 cos 30° ∓ sqrt(25 - 16) = 6.9282 ∓ 3 (behind, ahead)
    r = solve_vector_equation(Polar.deg(None, 30), Polar(5), Polar.deg(8, 0))
    a = [r.polar(k)[0].magnitude for k in range(2)]
    assert a == pytest.approx([8 * math.cos(math.radians(30)) - 3,
                               8 * math.cos(math.radians(30)) + 3], rel=1e-12)


def test_case_3_magnitudes_may_be_negative():
    # C = 1∠0° from lines at 90° through O and at 45° through T: A = -1 (down), B = √2
    r = solve_vector_equation(Polar.deg(None, 90), Polar.deg(None, 45), Polar.deg(1, 0))
    A, B, _ = r.polar()
    assert A.magnitude == pytest.approx(-1.0) and B.magnitude == pytest.approx(math.sqrt(2))
    assert math.degrees(A.angle) == pytest.approx(90)


def test_tangent_arcs_give_the_same_solution_twice():
    # 3 + 5 = 8: a dead-center posture, both branches at (3, 0)
    r = solve_vector_equation(Polar(3), Polar(5), Polar(8, 0.0))
    assert len(r.solutions) == 2 and r.solutions[0] == r.solutions[1]
    assert r.solutions[0].A == Vector(3, 0)


# ---- the recorded construction --------------------------------------------------------


@pytest.mark.parametrize("knowns, case", [
    ((Polar(3, 0.2), Polar(4, 1.0), Polar()), 1),
    ((Polar(), Polar(4, 1.0), Polar(5, 0.0)), 1),
    ((Polar(angle=0.5), Polar(4.0), Polar(5.0, 0.0)), 2),
    ((Polar(3.0, 1.0), Polar(angle=2.0), Polar(4.0)), 2),
    ((Polar(angle=1.0), Polar(angle=-1.0), Polar(5.0, 0.0)), 3),
    ((Polar(3.0, 1.0), Polar(angle=0.0), Polar(angle=2.0)), 3),
    ((Polar(3.0), Polar(4.0), Polar(5.0, 0.0)), 4),
    ((Polar(3.0, 0.3), Polar(4.0), Polar(6.0)), 4),
])
def test_every_step_carries_the_marked_equation(knowns, case):
    r = solve_vector_equation(*knowns)
    cx = r.construction
    assert len(cx) > 0
    for step in cx:
        assert step.op in OPS
        assert step.equation is r.equation
        assert step.equation.case == case
        # exactly two unknowns: two ? marks (Sec. 2.8)
        assert str(step.equation).count("?") == 2 and step.equation.unknowns == 2
        assert step.note.endswith(".") and step.note[0].isupper()
        assert step.role in set(Role)
    marks = {t.name: (t.magnitude, t.direction) for t in (*r.equation.lhs, *r.equation.rhs)}
    assert marks == {n: k.marks for n, k in zip("ABC", knowns)}
    # the branches of two-way steps are recorded by name, in the case's order
    two_way = [s.branch for s in cx if s.op in ("intersect_circles", "intersect_line_circle")]
    assert tuple(two_way) == tuple(b for b in r.branches if b) == r.case.branches
    assert [s.role for s in cx if s.op in ("point", "input")] == \
        [Role.GIVEN] * sum(s.op in ("point", "input") for s in cx)


def test_case_4_steps_follow_the_book():
    # Fig. 2.13: draw C, arc of radius A about its origin, arc of radius B about its terminus
    r = solve_vector_equation(Polar(3), Polar(4), Polar(5, 0.0))
    ops = [(s.op, s.label, s.inputs, s.branch) for s in r.construction]
    assert ops == [
        ("point", "O", (), None),
        ("input", "theta_C", (), None),
        ("rigid", "T", ("O", "theta_C"), None),
        ("circle", "k_A", ("O",), None),
        ("circle", "k_B", ("T",), None),
        ("intersect_circles", "P", ("k_A", "k_B"), "left"),
        ("vector", "A", ("O", "P"), None),
        ("vector", "B", ("P", "T"), None),
        ("intersect_circles", "P'", ("k_A", "k_B"), "right"),
        ("vector", "A'", ("O", "P'"), None),
        ("vector", "B'", ("P'", "T"), None),
    ]
    assert "radius A centered at the origin of C" in r.construction.step_of("k_A").note
    assert r.construction.step_of("P").step_id == "step-05-P"


def test_replay_and_batch_evaluation():
    r = solve_vector_equation(Polar(3), Polar(4), Polar(5, 0.0))
    ev = r.construction.evaluate(r.inputs)
    assert_allclose(ev["A"], np.asarray(r.solutions[0].A))
    # the same construction on 50 directions of C at once equals 50 separate solves
    t = np.linspace(-math.pi, math.pi, 50)
    batch = r.construction.evaluate({"theta_C": t}, strict=False)
    assert batch["P"].shape == (50, 3) and bool(np.all(batch.valid))
    for i, ti in enumerate(t):
        one = solve_vector_equation(Polar(3), Polar(4), Polar(5, float(ti)))
        assert_allclose(batch["A"][i], np.asarray(one.solutions[0].A), rtol=0, atol=1e-12)
        assert_allclose(batch["B'"][i], np.asarray(one.solutions[1].B), rtol=0, atol=1e-12)


def test_one_branch_on_request():
    both = solve_vector_equation(Polar(3), Polar(4), Polar(5, 0.0))
    right = solve_vector_equation(Polar(3), Polar(4), Polar(5, 0.0), branch=Side.RIGHT)
    assert right.branches == ("right",) and right.solutions == (both.solutions[1],)
    assert both.solution("right") == both.solutions[1]
    ahead = solve_vector_equation(Polar(angle=0.5), Polar(4.0), Polar(5.0, 0.0),
                                  branch=Along.AHEAD)
    assert ahead.branches == ("ahead",)
    with pytest.raises(KeyError, match="left, right"):
        both.solution("ahead")


# ---- no solution ----------------------------------------------------------------------


def test_case_4_arcs_too_far_apart():
    # |A| + |B| = 1 + 2 < |C| = 8
    with pytest.raises(NoIntersectionError) as info:
        solve_vector_equation(Polar(1), Polar(2), Polar(8, 0.0))
    err = info.value
    assert isinstance(err, ConstructionError) and isinstance(err, ValueError)
    assert err.step == "P"
    assert str(err).startswith("case 4 has no solution: ") and "step" not in str(err)
    assert "|A| + |B| = 3 < |C| = 8" in str(err)
    again = pickle.loads(pickle.dumps(err))
    assert type(again) is NoIntersectionError and again.step == "P"


def test_case_4_one_arc_inside_the_other():
    # ||A| - |B|| = 9 - 1 = 8 > |C| = 2
    with pytest.raises(NoIntersectionError, match="inside") as info:
        solve_vector_equation(Polar(9), Polar(1), Polar(2, 0.0))
    assert info.value.step == "P"


def test_case_4_only_the_asked_branch_is_missing_too():
    with pytest.raises(NoIntersectionError):
        solve_vector_equation(Polar(1), Polar(2), Polar(8, 0.0), branch="right")


def test_case_2_arc_misses_the_line():
    # the line through O at 90° passes 8 from T = (8, 0); the arc about T has radius 1
    with pytest.raises(NoIntersectionError, match="passes 8 from the center") as info:
        solve_vector_equation(Polar.deg(None, 90), Polar(1), Polar.deg(8, 0))
    assert info.value.step == "P"


@pytest.mark.parametrize("ta, tb, word", [
    (10, 10, "infinite"),       # parallel, distinct: C = 8∠0° is not along them
    (10, 190, "infinite"),      # opposite directions are parallel too
    (0, 180, "indeterminate"),  # collinear with C: indeterminate (Sec. 2.8)
    (0, 0, "indeterminate"),
])
def test_case_3_parallel_directions(ta, tb, word):
    with pytest.raises(ParallelDirectionsError, match=word) as info:
        solve_vector_equation(Polar.deg(None, ta), Polar.deg(None, tb), Polar.deg(8, 0))
    err = info.value
    assert err.step == "P" and err.vectors == ("A", "B")
    dx, dy = err.directions
    assert dx == Vector.polar(1, math.radians(ta)) and dy == Vector.polar(1, math.radians(tb))
    assert pickle.loads(pickle.dumps(err)).directions == err.directions


def test_case_3_nearly_parallel_by_angle_tolerance():
    # 1e-12 rad apart: parallel for Tolerance.angle = 1e-9
    with pytest.raises(ParallelDirectionsError):
        solve_vector_equation(Polar(angle=0.3), Polar(angle=0.3 + 1e-12), Polar(8.0, 0.0))


# ---- bad input ------------------------------------------------------------------------


@pytest.mark.parametrize("knowns, key, match", [
    ((Polar(3), Polar(4), Polar(5)), None, "exactly two unknowns"),
    ((Polar(3, 0.0), Polar(4, 0.0), Polar(7, 0.0)), None, "this one has 0"),
    ((Polar(math.nan), Polar(4), Polar(5, 0.0)), "A.magnitude", "finite"),
    ((Polar(3), Polar(4, True), Polar(5)), "B.angle", "finite"),
    ((Polar(0.0), Polar(4), Polar(5, 0.0)), "A.magnitude", "zero"),
    (((3, None), Polar(4), Polar(5, 0.0)), "A", "Polar"),
])
def test_bad_knowns(knowns, key, match):
    with pytest.raises(InputError, match=match) as info:
        solve_vector_equation(*knowns)
    assert info.value.key == key


@pytest.mark.parametrize("knowns, branch, match", [
    ((Polar(3), Polar(4), Polar(5, 0.0)), "ahead", "left, right"),
    ((Polar(angle=0.5), Polar(4.0), Polar(5.0, 0.0)), Side.LEFT, "behind, ahead"),
    ((Polar(angle=1.0), Polar(angle=-1.0), Polar(5.0, 0.0)), "left", "one solution"),
])
def test_bad_branch(knowns, branch, match):
    with pytest.raises(InputError, match=match) as info:
        solve_vector_equation(*knowns, branch=branch)
    assert info.value.key == "branch"


def test_case_enum():
    assert [int(c) for c in VectorEquationCase] == [1, 2, 3, 4]
    assert VectorEquationCase.CASE_3.unknowns.startswith("two magnitudes")
    assert VectorEquationCase.CASE_2.figure == "Fig. 2.11"
    assert VectorEquationCase.of(Polar(angle=1.0), Polar(2.0), Polar(3.0, 0.0)) == 2
    assert Polar(2.0).marks == (Mark.KNOWN, Mark.UNKNOWN)
    assert str(Polar()) == "?∠?"
    # the oracle itself on Fig. 2.13's numbers: a 3-4-5 triangle
    sols = closed_form({"A": Polar(3.0), "B": Polar(4.0), "C": Polar(5.0, 0.0)})
    assert sorted(round(math.degrees(cmath.phase(s["A"])), 4) for s in sols) == \
        [-53.1301, 53.1301]
    assert g.distance(g.point(0, 0), g.point(3, 4)) == 5.0
