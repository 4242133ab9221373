"""The operation ``ball_point`` (graphkin/construction/ops/ball.py) against independent routes.

Ball's point U is where the cubic of stationary curvature meets the
inflection circle again (Uicker, Pennock & Shigley, 5th ed., Sec. 4.17).  The
references here use none of graphkin's curvature code:

* the velocity pole I and the inflection pole J of the coupler from the
  solution's link state (``V_I = 0``: a 2x2 solve, Eq. 3.4; ``J = I + A_I/ω²``,
  Sec. 4.13, Eqs. 4.46-4.47);
* ``1/M`` and ``1/N`` from Eq. 4.55 in its polar form, ``1/r = 1/(M sin ψ) -
  1/(N cos ψ)``, at the two pins of constant path curvature (a four-bar's A
  and B, a slider-crank's A and C), a 2x2 solve;
* U where the circle ``r = d sin ψ`` meets Eq. 4.55, the root of
  ``cos ψ (1 - d/M) + (d/N) sin ψ`` on (0, π), found by bisection.

Also: ``N = ∞`` gives ``U = J`` by the formula (a cubic point on the centrode
normal, Eq. 4.57 with x = 0), the degenerate cases give none (NaN), never a
wrong point, 1e-12 of round-off moves neither U nor the verdicts, Example
4.16's construction makes U = J with this operation, and the code both
writers emit for it (Python and JavaScript, from the one template) equals the
replay.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from jsrun import close, js_or_skip, run_js
from spec_data import EXAMPLES
from strategies import examples, fourbars, slider_cranks

import graphkin
from graphkin.construction import Construction
from graphkin.construction.codegen import TEMPLATES, generate
from graphkin.construction.jsgen import RUNTIME, generate_js
from graphkin.construction.ops import OPS, templates  # noqa: F401  (registers ball.py)
from graphkin.files import load_toml
from graphkin.kinematics.curvature.link import link_curvature
from graphkin.mechanisms import from_dict
from graphkin.tolerance import DEFAULT_TOL

REL = 1e-9


def _h(p) -> np.ndarray:
    return np.array([float(p[0]), float(p[1]), 1.0])


def _op(i, j, a, b) -> np.ndarray:
    """``ball_point`` on finite points; its Cartesian U (NaN when none)."""
    u = OPS["ball_point"](_h(i), _h(j), _h(a), _h(b), tol=DEFAULT_TOL)[0]
    return u[:2] / u[2]


# ---------------------------------------------------------------------------
# the independent reference: the polar form of Eq. 4.55 and a bisection
# ---------------------------------------------------------------------------

def _poles(sol, lid: str) -> tuple[np.ndarray, np.ndarray]:
    """I (zero velocity, Eq. 3.4) and J = I + A_I/ω² (Sec. 4.13) from the link's state."""
    st_ = sol.links[lid]
    w, o = float(st_.omega), np.asarray(st_.origin, dtype=float)
    vo = np.asarray(st_.origin_velocity, dtype=float)
    ao = np.asarray(st_.origin_acceleration, dtype=float)
    # V_I = V_O + ω k × (I - O) = 0
    i = o + np.linalg.solve(np.array([[0.0, -w], [w, 0.0]]), -vo)
    # A_I = A_O + α k × R - ω² R, R = I - O (Eq. 4.5)
    r = i - o
    a_i = ao + float(st_.alpha) * np.array([-r[1], r[0]]) - w * w * r
    return i, i + a_i / (w * w)


def _polar_ball(i, j, pins) -> tuple[np.ndarray, float] | None:
    """U by Eq. 4.55 (polar) and bisection, and how well the pins condition it; None if poor."""
    u = j - i
    d = float(np.hypot(*u))
    n_hat = u / d
    t_hat = np.array([n_hat[1], -n_hat[0]])  # T: N turned 90° clockwise (Sec. 4.12)
    rows, rhs = [], []
    for p in pins:
        r = np.asarray(p, dtype=float) - i
        psi = math.atan2(float(r @ n_hat), float(r @ t_hat))
        if min(abs(math.sin(psi)), abs(math.cos(psi))) < 0.05:
            return None  # near T or N: the polar form divides by ~0
        rows.append([1.0 / math.sin(psi), -1.0 / math.cos(psi)])
        rhs.append(1.0 / float(np.hypot(*r)))
    a = np.array(rows)
    if np.linalg.cond(a) > 1e4:
        return None
    inv_m, inv_n = np.linalg.solve(a, np.array(rhs))

    def g(psi: float) -> float:
        # Eq. 4.55 on the circle r = d sin ψ, times d sin ψ cos ψ
        return math.cos(psi) * (1.0 - d * inv_m) + d * inv_n * math.sin(psi)

    lo, hi = 0.0, math.pi
    glo = g(lo)
    if glo == 0.0 or glo * g(hi) > 0.0:
        return None
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if g(mid) * glo > 0.0:
            lo = mid
        else:
            hi = mid
    psi = 0.5 * (lo + hi)
    if math.sin(psi) < 0.05:
        return None  # U next to I: conditioned by the cubic's double point
    return i + d * math.sin(psi) * (math.cos(psi) * t_hat + math.sin(psi) * n_hat), d


def _pins(rm) -> tuple[str, str]:
    """The coupler's two pins of constant path curvature (tests/strategies.py's names)."""
    return ("A", "B") if rm.kind.startswith("fourbar") else ("A", "C")


@examples(40)
@given(rm=st.one_of(fourbars(other_rates=False), slider_cranks()))
def test_ball_point_equals_eq_4_55_by_bisection(rm) -> None:
    # random four-bars (pins A, B about O2, O4) and slider-cranks (A about O2, C on the
    # frame's line: a straight path), coupler 3
    sol = graphkin.solve(rm.mechanism())
    assume(sol.has_rates and sol.has_accelerations)
    w = float(sol.links["3"].omega)
    size = float(rm.mechanism().scale)
    assume(abs(w) > 1e-3)
    i, j = _poles(sol, "3")
    assume(1e-2 * size < float(np.hypot(*(j - i))) < 1e2 * size)
    pins = [np.asarray(sol.position(n), dtype=float) for n in _pins(rm)]
    ref = _polar_ball(i, j, pins)
    assume(ref is not None)
    u_ref, d = ref
    got = _op(i, j, *pins)
    scale = max(size, d, float(np.abs(u_ref).max()))
    np.testing.assert_allclose(got, u_ref, rtol=0, atol=REL * scale)
    # on the inflection circle (Thales: IU ⊥ JU)
    assert abs(float((got - i) @ (got - j))) <= REL * scale * scale
    # the verdict and the value do not move with round-off: every input moved by 1e-12
    rng = np.random.default_rng(4)
    moved = [p + 1e-12 * scale * rng.uniform(-1, 1, 2) for p in (i, j, *pins)]
    np.testing.assert_allclose(_op(*moved), got, rtol=0, atol=REL * scale)


_num = st.floats(-10.0, 10.0, allow_nan=False)


@settings(max_examples=40, deadline=None)
@given(i=st.tuples(_num, _num), u=st.tuples(_num, _num), a=st.tuples(_num, _num),
       lam=st.floats(-3.0, 3.0), eps=st.floats(-1e-3, 1e-3))
def test_n_infinite_gives_j_by_the_formula(i, u, a, lam, eps) -> None:
    # Eq. 4.57 at a point of the cubic on the centrode normal (x = 0, y ≠ 0): -y³/N = 0, so
    # N = ∞; the cubic then contains N, meets the inflection circle on IJ at J, and U = J
    # (Example 4.16).  Moved off N by eps (of d), U moves continuously: by O(eps) at most.
    i, u, a = np.array(i), np.array(u), np.array(a)
    d = float(np.hypot(*u))
    assume(d > 0.5 and abs(lam) > 0.1)
    j = i + u
    t = np.array([u[1], -u[0]])  # T to the length d
    r = a - i
    x, y = float(r @ t) / d, float(r @ u) / d
    assume(abs(x) > 0.1 * d and abs(y) > 0.1 * d and np.hypot(x, y) > 0.3 * d)
    # A off the inflection circle x² + y² = d y: with B on N it would make d/M = 1, the cubic
    # the circle and N together, and no Ball's point (test_degenerate_cases_are_none)
    assume(abs(x * x + y * y - d * y) > 0.1 * d * d)
    b = i + lam * u
    assume(abs(lam - 1.0) > 0.1)  # B not at J
    size = 1.0 + float(np.abs([*i, *j, *a, *b]).max())
    got = _op(i, j, a, b)
    np.testing.assert_allclose(got, j, rtol=0, atol=REL * size)
    off = _op(i, j, a, b + eps * t)
    assert np.all(np.isfinite(off))
    assert float(np.hypot(*(off - j))) <= 1e3 * abs(eps) * size + REL * size


def test_example_4_16_u_is_j_made_by_ball_point() -> None:
    # Example 4.16 (Fig. 4.39): I = (0, -1) in, J = (-2, -3) in, A = (0, 1), B = (2, 1); B is
    # on the centrode normal (I + (-1)(J - I)), so N = ∞ and Ball's point is J (the book).
    # By hand in the operation's terms: u = J - I = (-2, -2), d² = 8, t = (-2, 2);
    # A: (x̂, ŷ) = (0.5, -0.5), row (0.25, 0.25, 0.25); B: (0, -1), row (0, 1, 0);
    # (μ, ν, κ) = (-0.25, 0, 0.25): d/M = -1, d/N = 0; p = 0, q = -0.5, U = I + u = J
    np.testing.assert_allclose(_op([0, -1], [-2, -3], [0, 1], [2, 1]), [-2.0, -3.0],
                               rtol=0, atol=1e-15)
    path = EXAMPLES / "ex4_16_cubic.toml"
    k = link_curvature(graphkin.load(path).solve(), "3")
    made = [s for s in k.construction.steps if s.outputs[0] == "U"]
    assert [s.op for s in made] == ["ball_point"] and made[0].role.name == "RESULT"
    assert k.sections["U"] == "ball_at_j"
    np.testing.assert_allclose(k.ball_point, k.inflection_pole, rtol=0, atol=1e-12)


def test_example_4_16_moved_by_round_off_keeps_u_at_j() -> None:
    # every point of the file moved by 1e-12 of its size: N is infinite or astronomically
    # large, the construction finds U either way (ball_point or Hain's), within 1e-9 of J
    path = EXAMPLES / "ex4_16_cubic.toml"
    data = load_toml(path)
    eps = 1e-12 * graphkin.load(path).scale
    for k, lk in enumerate(data["links"].values()):
        for m, n in enumerate(lk):
            lk[n] = [lk[n][0] + eps * ((k + m) % 3 - 1), lk[n][1] - eps * ((k * m) % 3 - 1)]
    mech = from_dict(data, source=path.name)
    lc = link_curvature(mech.solve(), "3")
    assert lc.ball_point is not None
    np.testing.assert_allclose(lc.ball_point, lc.inflection_pole, rtol=0,
                               atol=REL * (1.0 + mech.scale))


def _cubic_points(m: float, n: float, d: float, psis) -> list[np.ndarray]:
    """Points of Eq. 4.55 with I at the origin, T = x, N = y (so J = (0, d))."""
    out = []
    for psi in psis:
        inv = (1.0 / m if m else 0.0) / math.sin(psi) - (1.0 / n if n else 0.0) / math.cos(psi)
        r = 1.0 / inv
        out.append(np.array([r * math.cos(psi), r * math.sin(psi)]))
    return out


def test_degenerate_cases_are_none() -> None:
    i, j = np.zeros(2), np.array([0.0, 2.0])
    a, b = np.array([1.0, 3.0]), np.array([-2.0, 1.0])
    # a link turning about a frame pivot: J = I, the inflection circle is a point
    assert np.all(np.isnan(_op(i, i, a, b)))
    # A and B the same point: they do not determine the cubic
    assert np.all(np.isnan(_op(i, j, a, a)))
    # both on the inflection circle: d/M = 1, d/N = 0, the cubic is the circle and N
    on = [np.array([1.0, 1.0]), np.array([-math.sqrt(0.75), 1.5])]
    assert np.all(np.isnan(_op(i, j, *on)))
    # M = d: the line x(d/M - 1) = (d/N) y is T, tangent to the circle at I: U only at I
    pa, pb = _cubic_points(2.0, 5.0, 2.0, (0.7, 2.1))
    assert np.all(np.isnan(_op(i, j, pa, pb)))
    # ... and just away from it (M = 2.1) U is a finite point of the circle near I
    pa, pb = _cubic_points(2.1, 5.0, 2.0, (0.7, 2.1))
    got = _op(i, j, pa, pb)
    assert np.all(np.isfinite(got)) and abs(float(got @ (got - j))) < 1e-12


def _construction() -> Construction:
    cx = Construction()
    for n in "IJAB":
        cx.add("input", (), (f"{n}x",), name=f"{n}x")
        cx.add("input", (), (f"{n}y",), name=f"{n}y")
        cx.add("point_xy", (f"{n}x", f"{n}y"), (n,))
    cx.add("ball_point", ("I", "J", "A", "B"), ("U",))
    return cx


@pytest.fixture(scope="module")
def _js():
    js_or_skip()
    yield
    close()


@pytest.mark.usefixtures("_js")
@settings(max_examples=25, deadline=None)
@given(xy=st.lists(st.floats(-10.0, 10.0), min_size=8, max_size=8), on_n=st.booleans(),
       spread=st.floats(0.0, 0.05))
def test_the_emitted_code_equals_the_replay(xy: list[float], on_n: bool, spread: float) -> None:
    # the one template written out by both writers (Python over a batch of postures,
    # JavaScript on one) against Construction.replay (the numpy operation); with on_n, B is
    # put on the centrode normal (N = ∞, U = J) and the batch spreads round it
    assert "ball_point" in TEMPLATES
    pts = np.reshape(np.array(xy), (4, 2))
    if on_n:
        pts[3] = pts[0] + 1.7 * (pts[1] - pts[0])
    u, r = pts[1] - pts[0], pts[2] - pts[0]
    # A off I and off the centrode normal (with B on N it alone fixes M)
    assume(float(np.hypot(*u)) > 0.5 and float(np.hypot(*r)) > 0.5)
    assume(abs(float(u[0] * r[1] - u[1] * r[0])) > 0.1 * float(np.hypot(*u) * np.hypot(*r)))
    cx = _construction()
    names = [f"{n}{c}" for n in "IJAB" for c in "xy"]
    # a batch: the posture and the same with A and B moved by up to `spread`
    base = pts.reshape(-1)
    k = np.linspace(-1.0, 1.0, 5)
    batch = {nm: base[m] + (spread * k * (1 + m) if m >= 4 else 0.0 * k)
             for m, nm in enumerate(names)}
    ref = cx.replay(batch, strict=False)
    u_ref = np.asarray(ref.values["U"], dtype=float)
    u_ref = u_ref[:, :2] / u_ref[:, 2:]
    py = generate(cx.steps, varying=names, requests=[("U", "value")])
    got = py.values(*[batch[nm] for nm in names])
    scale = 1.0 + float(np.abs(base).max())
    if got is not None:  # the clean case: every posture of the batch has a U
        g = np.asarray(got["U"], dtype=float)
        np.testing.assert_allclose(g[:, :2] / g[:, 2:], u_ref, rtol=0, atol=REL * scale)
    else:
        assert not bool(np.all(ref.valid))
    fn = generate_js(cx.steps, requests=["U"], soft=True)
    cases = [{nm: float(batch[nm][m]) for nm in names} for m in range(len(k))]
    src = RUNTIME + fn.source + f"\nconst C = {json.dumps(cases)};" + (
        f"\nconst RESULT = C.map((I) => {fn.name}(I, {json.dumps(fn.values)}));")
    for out, r in zip(run_js(src), u_ref):
        if not np.all(np.isfinite(r)):
            assert out["U"] is None
        else:
            np.testing.assert_allclose(out["U"], r, rtol=0, atol=REL * scale)
    if on_n:  # the middle posture is the one with B on N: U = J
        np.testing.assert_allclose(u_ref[2], pts[1], rtol=0, atol=REL * scale)
