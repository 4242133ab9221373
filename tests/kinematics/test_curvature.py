"""Curvature theory (Secs. 4.12-4.17) against independent oracles and the textbook.

Oracles, none of which uses graphkin.kinematics.curvature:

* the radius and center of curvature of a path from the Solution's velocity
  and acceleration, ``κ = (v × a)/|v|³`` and ``center = P + |v|² k×v/(v × a)``;
* the velocity pole and Γ as the body points of zero velocity / zero
  acceleration, by a 2x2 linear solve from ``LinkState`` (Eqs. 3.4, 4.5);
* the inflection circle as the points with ``a × v = 0``, the Bresse circle as
  the points with ``a · v = 0`` (Sec. 4.15);
* stationary curvature (the cubic, Ball's point) and the centrodes by finite
  differences over the drive: the mechanism is solved again at drive ± h and
  the same body point (the same local coordinates) is followed;
* the printed numbers of Examples 4.12, 4.14 and 4.16 (Sec. and Ans. numbers
  in the comments).
"""

from __future__ import annotations

import copy
import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, example, given
from pinned import BALL_FAR, BALL_FARTHER
from spec_data import inline
from strategies import examples, fourbars, mechanisms, slider_cranks

import graphkin
from graphkin.errors import GraphkinError
from graphkin.kinematics.curvature import (
    curvature,
    curvature_json,
    curvature_text,
    euler_savary,
    link_curvature,
    path_curvatures,
    paths_json,
)
from graphkin.kinematics.solution import LinkState, Solution
from graphkin.mechanisms import from_dict
from graphkin.output import solution_to_dict

GALLERY = Path(__file__).resolve().parents[2] / "gallery" / "curvature"
HYP = examples(40)
FD = examples(15)
REL = 1e-9


# ---------------------------------------------------------------------------
# independent oracles
# ---------------------------------------------------------------------------

def _cross(u, v):
    return float(u[0] * v[1] - u[1] * v[0])


def _perp(v):
    return np.array([-v[1], v[0]])


def kappa(v, a):
    """Signed path curvature from velocity and acceleration."""
    return _cross(v, a) / math.hypot(*v) ** 3


def center_of_curvature(p, v, a):
    """P + |v|² k×v / (v × a) (undefined for a straight path)."""
    return np.asarray(p) + (v @ v) * _perp(v) / _cross(v, a)


def zero_velocity_point(st: LinkState):
    """Solve V_O + ω k×(X - O) = 0 for X."""
    w = float(st.omega)
    m = np.array([[0.0, -w], [w, 0.0]])
    return st.origin + np.linalg.solve(m, -st.origin_velocity)


def zero_acceleration_point(st: LinkState):
    """Solve A_O + α k×(X - O) - ω² (X - O) = 0 for X."""
    w2, al = float(st.omega) ** 2, float(st.alpha)
    m = np.array([[-w2, -al], [al, -w2]])
    return st.origin + np.linalg.solve(m, -st.origin_acceleration)


def local_of(st: LinkState, p):
    c, s = math.cos(float(st.angle)), math.sin(float(st.angle))
    d = np.asarray(p, dtype=float) - st.origin
    return np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])


def figure_size(sol: Solution):
    """The diagonal of the box around the named points (the drawing's size)."""
    pts = np.array([sol.position(n) for n in sol.mechanism.point_names])
    return float(np.hypot(*(pts.max(axis=0) - pts.min(axis=0))))


def speeds(sol: Solution):
    m = sol.mechanism
    vref = max(math.hypot(*sol.velocity(n)) for n in m.point_names)
    aref = max(math.hypot(*sol.acceleration(n)) for n in m.point_names)
    return vref, aref


def check_paths(sol: Solution):
    """Every path's radius and center equal the velocity/acceleration oracle.

    The oracle reads v and a from the Solution, whose absolute errors are of
    the order of (round-off) x (largest speed, largest acceleration): the
    tolerance is 1e-9 relative, scaled by how much a small |v| amplifies those.
    """
    mech = sol.mechanism
    size = figure_size(sol)
    vref, aref = speeds(sol)
    for name, pc in path_curvatures(sol).items():
        p, v, a = sol.position(name), sol.velocity(name), sol.acceleration(name)
        sp = math.hypot(*v)
        if frame_only(mech, name):
            continue
        if sp <= 1e-6 * vref:  # at rest or nearly: the oracle has no digits left
            continue
        k = kappa(v, a)
        cond = (vref / sp) ** 2 + aref / (sp * sp / size)
        tol_k = REL * cond * (abs(k) + 1.0 / size)
        if pc.radius is None:
            assert pc.how == "straight", (name, pc)
            assert abs(k) <= tol_k, (name, k)
            continue
        assert abs(1.0 / pc.radius - abs(k)) <= tol_k, (name, pc.radius, 1 / k)
        if abs(k) * size > 1e-3:  # a center within reach
            c = center_of_curvature(p, v, a)
            rho = 1.0 / abs(k)
            np.testing.assert_allclose(pc.center, c, rtol=0,
                                       atol=REL * cond * (size + rho * rho / size))


def frame_only(mech, name):
    return all(lid == "1" for lid in mech.point_links[name])


def check_link(sol: Solution, lid: str):
    """I, J, Γ and the two circles of one link against the oracles."""
    k = link_curvature(sol, lid)
    st = sol.links[lid]
    size = figure_size(sol)
    scale = size + k.inflection_diameter + float(np.hypot(*k.velocity_pole))
    i0 = zero_velocity_point(st)
    np.testing.assert_allclose(k.velocity_pole, i0, rtol=0, atol=1e-8 * scale)
    g0 = zero_acceleration_point(st)
    # Γ can lie far away (ω⁴ + α² small against the accelerations): its round-off is then
    # relative to its own distance, not to the figure's size
    # and a link turning slowly against the rest of the mechanism (a [rates] target that barely
    # moves) amplifies it by |V|max / (|ω| size)
    amp = speeds(sol)[0] / max(abs(float(st.omega)) * size, 1e-300)
    gscale = scale + float(np.hypot(*g0)) * (1.0 + amp)
    np.testing.assert_allclose(k.acceleration_center, g0, rtol=0, atol=1e-8 * gscale)
    if "Γ (four circles)" in k.values:
        gg = k.values["Γ (four circles)"]
        np.testing.assert_allclose(gg[:2] / gg[2], g0, rtol=0, atol=1e-7 * gscale)
    # J = I + A_I/ω², with A_I the acceleration of the body point at I (Eqs. 4.46-4.47)
    ai = st.acceleration(local_of(st, i0))
    np.testing.assert_allclose(k.inflection_pole, i0 + ai / float(st.omega) ** 2, rtol=0,
                               atol=1e-8 * scale)
    if k.inflection_diameter <= 1e-6 * size:
        return k
    c = (k.velocity_pole + k.inflection_pole) / 2
    rad = k.inflection_diameter / 2
    w, al = abs(float(st.omega)), abs(float(st.alpha))
    vs, acs = w * scale, (w * w + al) * scale
    for t in np.linspace(0.3, 2 * math.pi, 7):
        x = c + rad * np.array([math.cos(t), math.sin(t)])
        if np.hypot(*(x - k.velocity_pole)) < 1e-3 * k.inflection_diameter:
            continue  # I itself: at rest
        loc = local_of(st, x)
        v, a = st.velocity(loc), st.acceleration(loc)
        # on the inflection circle the normal acceleration vanishes: a × v = 0
        # (to round-off of the velocities ~ |ω| scale and accelerations ~ (ω² + |α|) scale)
        assert abs(_cross(a, v)) <= 1e-9 * vs * acs, t
    if k.bresse_pole is not None and k.bresse_diameter < 1e3 * size:
        cb = (k.velocity_pole + k.bresse_pole) / 2
        rb = k.bresse_diameter / 2
        for t in np.linspace(0.3, 2 * math.pi, 7):
            x = cb + rb * np.array([math.cos(t), math.sin(t)])
            if np.hypot(*(x - k.velocity_pole)) < 1e-3 * k.bresse_diameter:
                continue
            loc = local_of(st, x)
            v, a = st.velocity(loc), st.acceleration(loc)
            assert abs(a @ v) <= 1e-9 * vs * acs * (1 + k.bresse_diameter / scale), t
    # the positive normal points toward J; T is N turned 90° clockwise (Example 4.16)
    n = (k.inflection_pole - k.velocity_pole) / k.inflection_diameter
    np.testing.assert_allclose(k.normal, n, atol=1e-12)
    np.testing.assert_allclose(k.tangent, [n[1], -n[0]], atol=1e-12)
    return k


# ---------------------------------------------------------------------------
# solving again at drive ± h (finite differences over the drive)
# ---------------------------------------------------------------------------

def resolve(data: dict, h: float, size: float):
    d = copy.deepcopy(data)
    drive = d["drive"]
    if "angle" in drive:
        drive["angle"] = float(drive["angle"]) + math.degrees(h)
    else:
        drive["position"] = float(drive["position"]) + h * size
    return from_dict(d, source="<perturbed>").solve()


STEPS = (-2, -1, 1, 2)


def derivative(f, h):
    """Five-point central difference from f(-2h), f(-h), f(h), f(2h)."""
    fm2, fm1, fp1, fp2 = f
    return (fm2 - 8 * fm1 + 8 * fp1 - fp2) / (12 * h)


class Around:
    """The mechanism solved at drive + j h for j in -2..2, to follow body points."""

    def __init__(self, data: dict, sol: Solution, lid: str, h: float = 2e-3):
        self.size = sol.mechanism.scale  # the unit of a slider drive's travel (as resolve)
        self.h, self.lid = h, lid
        self.sols = {j: resolve(data, j * h, self.size) for j in STEPS}
        self.sols[0] = sol
        # dφ/dh of the link itself, to measure curvature rates per turn of the link
        self.dphi = derivative([float(self.sols[j].links[lid].angle) for j in STEPS], h)

    def kappa_of(self, loc, j):
        st = self.sols[j].links[self.lid]
        return kappa(st.velocity(loc), st.acceleration(loc))

    def dkappa_dphi(self, loc):
        """dκ/dφ of the body point with local coordinates loc (φ: the link's angle)."""
        return derivative([self.kappa_of(loc, j) for j in STEPS], self.h) / self.dphi

    def dkappa_dphi_richardson(self, loc, data: dict):
        """dκ/dφ by Richardson's extrapolation over steps h and h/2, and its error bound.

        The five-point stencil's error is c h⁴ f⁽⁵⁾.  Near Ball's point of a
        slowly turning coupler κ(φ) bends so sharply that this is of the order
        of 1e-6/size at h = 1e-4 (two four-bars found by Hypothesis, ω₃/ω₂ =
        -0.16 and -0.03: 2.0e-6 and 5.5e-6 at h = 1e-4, 80 times more at 3e-4,
        the ratio 3⁴ of pure truncation, and round-off taking over below 3e-5).
        (16 D(h/2) - D(h))/15 cancels the h⁴ term; |D(h) - D(h/2)| bounds what
        is left.  A wrong Ball's point is not hidden by it: moving the point by
        1e-6 of the mechanism's size changes dκ/dφ·size by 1 to 15 there.
        """
        if not hasattr(self, "_half"):
            self._half = Around(data, self.sols[0], self.lid, h=self.h / 2)
        coarse, fine = self.dkappa_dphi(loc), self._half.dkappa_dphi(loc)
        return (16 * fine - coarse) / 15, abs(fine - coarse)


def load_data(path: Path) -> dict:
    with open(path, "rb") as fh:
        return tomllib.load(fh)


# ---------------------------------------------------------------------------
# closed forms
# ---------------------------------------------------------------------------

def test_euler_savary_rolling_wheel():
    # a wheel of radius R rolls on a line: I is the contact point, J the center
    # (its path is straight), and the top of the wheel is the apex of a cycloid,
    # whose radius of curvature is 4R: the center of curvature is 2R below I.
    r = 1.5
    top = euler_savary([0, 0], [0, r], [0, 2 * r])
    np.testing.assert_allclose(top, [0, -2 * r, 1])
    center = euler_savary([0, 0], [0, r], [0, r])
    assert center[2] == 0.0  # at infinity: the center moves on a straight line
    assert np.all(np.isnan(euler_savary([0, 0], [0, r], [0, 0])))  # I is at rest


def test_euler_savary_eq_4_43_example_4_12_arithmetic():
    # Example 4.12 (Sec. 4.12): the book measures R_CI = 3.10 in and R_CJ_C = -1.75 in
    # (positive sense from C toward I), and Eq. 4.43 gives rho = 3.10²/(-1.75) = -5.49 in.
    # Put I at the origin and the ray along +x (the positive sense reversed: x = -R).
    c = np.array([-3.10, 0.0])
    jc = np.array([-3.10 - 1.75, 0.0])
    cp = euler_savary([0, 0], jc, c)  # J on the ray: the ray is the centrode normal
    rho = c[0] - cp[0] / cp[2]
    assert rho == pytest.approx(5.49, abs=0.005)  # book: -5.49 in, C above C'
    assert cp[0] / cp[2] < c[0]  # C' beyond C, away from I


# ---------------------------------------------------------------------------
# random mechanisms (Hypothesis)
# ---------------------------------------------------------------------------

@HYP
@given(mechanisms())
def test_paths_equal_velocity_acceleration_oracle(rm):
    sol = graphkin.solve(rm.mechanism())
    if not sol.has_rates:
        return
    check_paths(sol)
    json.dumps(solution_to_dict(sol), allow_nan=False)  # never NaN in the output


@HYP
@given(mechanisms())
def test_poles_circles_and_gamma_equal_oracles(rm):
    sol = graphkin.solve(rm.mechanism())
    if not sol.has_rates:
        return
    for lid in curvature(sol):
        k = check_link(sol, lid)
        for name, h in k.conjugates.items():
            # every conjugate point agrees with Euler-Savary (Eq. 4.42) from I and J
            closed = euler_savary(k.velocity_pole, k.inflection_pole,
                                  sol.position(name, lid))
            if not np.all(np.isfinite(h)) or h[2] == 0.0 or closed[2] == 0.0:
                continue
            rho = float(np.hypot(*(sol.position(name, lid) - closed[:2])))
            np.testing.assert_allclose(h[:2] / h[2], closed[:2], rtol=0,
                                       atol=1e-8 * (figure_size(sol) + rho * rho
                                                    / figure_size(sol)))


@HYP
@given(fourbars())
def test_bobillier_and_accelerations_agree_fourbar(rm):
    sol = graphkin.solve(rm.mechanism())
    k = link_curvature(sol, "3")
    ra, rb = sol.position("A") - sol.position("O2"), sol.position("B") - sol.position("O4")
    if abs(_cross(ra, rb)) > 0.05 * np.hypot(*ra) * np.hypot(*rb):  # rays crossing well
        assert k.method in ("bobillier", "euler-savary")
    size = figure_size(sol)
    scale = size + k.inflection_diameter
    for method in ("bobillier", "euler-savary", "accelerations"):
        other = link_curvature(sol, "3", method=method)
        np.testing.assert_allclose(other.inflection_pole, k.inflection_pole, rtol=0,
                                   atol=1e-9 * scale)
        np.testing.assert_allclose(other.velocity_pole, k.velocity_pole, rtol=0,
                                   atol=1e-9 * scale)
    # the coupler of a four-bar always has Hain's cubic through its two pins
    assert k.cubic is not None
    for pin in ("A", "B"):
        resid = k.cubic.residual(sol.position(pin, "3"))
        assert abs(resid) <= 1e-8 * (size + k.inflection_diameter) ** 2


@HYP
@given(slider_cranks())
def test_bobillier_and_accelerations_agree_slider_crank(rm):
    sol = graphkin.solve(rm.mechanism())
    if abs(float(sol.omega("3"))) * figure_size(sol) <= 1e-6 * speeds(sol)[0]:
        return
    k = link_curvature(sol, "3")
    other = link_curvature(sol, "3", method="accelerations")
    scale = figure_size(sol) + k.inflection_diameter
    np.testing.assert_allclose(other.inflection_pole, k.inflection_pole, rtol=0,
                               atol=1e-9 * scale)
    # the slider's pin C moves straight: it is on the inflection circle
    c = sol.position("C", "3")
    assert abs(np.hypot(*(c - (k.velocity_pole + k.inflection_pole) / 2))
               - k.inflection_diameter / 2) <= 1e-9 * scale


def _cubic_points(k, size):
    out = []
    for psi in np.linspace(0.2, 2 * math.pi, 13):
        p = k.cubic.point(psi)
        r = float(np.hypot(*(p - k.velocity_pole)))
        if np.all(np.isfinite(p)) and 0.3 * size < r < 3 * size:
            out.append(p)
    return out


# BALL_FAR, BALL_FARTHER: found by Hypothesis, kept in tests/pinned.py


@FD
@given(fourbars(other_rates=False))
@example(BALL_FAR)
@example(BALL_FARTHER)
def test_cubic_and_ball_point_have_stationary_curvature(rm):
    sol = graphkin.solve(rm.mechanism())
    k = link_curvature(sol, "3")
    size = figure_size(sol)
    st = sol.links["3"]
    pts = _cubic_points(k, size)
    ball = k.ball_point
    if ball is not None and np.hypot(*(ball - k.velocity_pole)) < 0.2 * size:
        ball = None  # too near I: the oracle's v is too small to resolve κ there
    assume(pts or ball is not None)
    ar = Around(rm.data, sol, "3", h=1e-4)
    for p in pts:
        loc = local_of(st, p)
        kap = abs(ar.kappa_of(loc, 0))
        if kap * size > 20:
            continue  # a tiny radius near I: its curvature varies too fast for the stencil
        # a generic point's |dκ/dφ| is of the order of |κ| + 1/size (see the test below)
        rate, err = ar.dkappa_dphi_richardson(loc, rm.data)
        assert abs(rate) <= 1e-6 * (kap + 1 / size) + err, p
    if ball is not None:
        loc = local_of(st, ball)
        assert abs(ar.kappa_of(loc, 0)) * size <= 1e-8  # an inflection point ...
        rate, err = ar.dkappa_dphi_richardson(loc, rm.data)
        assert abs(rate) * size <= 1e-6 + err * size  # ... of stationary curvature


@FD
@given(fourbars(other_rates=False))
def test_centrode_curvatures_and_N_by_finite_differences(rm):
    sol = graphkin.solve(rm.mechanism())
    k = link_curvature(sol, "3")
    size = figure_size(sol)
    assume(k.inflection_diameter < 20 * size)
    assume(k.moving_centrode is not None and k.moving_centrode[1] is not None)
    assume(k.fixed_centrode is not None and k.fixed_centrode[1] is not None)
    assume(abs(k.moving_centrode[0]) < 10 * size and abs(k.fixed_centrode[0]) < 10 * size)
    ar = Around(rm.data, sol, "3", h=1e-3)
    poles = {j: zero_velocity_point(s.links["3"]) for j, s in ar.sols.items()}
    fixed = [poles[j] for j in STEPS]
    moving = [local_of(ar.sols[j].links["3"], poles[j]) for j in STEPS]
    st = sol.links["3"]

    def center(curve, p0):
        # the five-point stencil for r' and r'' (f0 from the posture itself)
        d1 = derivative(curve, ar.h)
        fm2, fm1, fp1, fp2 = curve
        d2 = (-fm2 + 16 * fm1 - 30 * p0 + 16 * fp1 - fp2) / (12 * ar.h ** 2)
        kap = _cross(d1, d2) / math.hypot(*d1) ** 3
        return p0 + _perp(d1) / math.hypot(*d1) / kap

    of = center(fixed, poles[0])
    om_local = center(moving, local_of(st, poles[0]))
    om = st.position(om_local)
    np.testing.assert_allclose(k.fixed_centrode[1], of, rtol=0, atol=1e-5 * size)
    np.testing.assert_allclose(k.moving_centrode[1], om, rtol=0, atol=1e-5 * size)
    # 1/N = (1/(3 R_JI)) dR_JI/ds (Eq. 4.56), s the pole's travel along +T
    diam = []
    for j in STEPS:
        s = ar.sols[j].links["3"]
        ai = s.acceleration(local_of(s, poles[j]))
        diam.append(math.hypot(*ai) / float(s.omega) ** 2)
    ds = float(derivative(fixed, ar.h) @ k.tangent)
    inv_n = derivative(diam, ar.h) / ds / (3 * k.inflection_diameter)
    inv_n_k = 0.0 if math.isinf(k.cubic.N) else 1.0 / k.cubic.N
    assert inv_n == pytest.approx(inv_n_k, abs=1e-5 / size)


# ---------------------------------------------------------------------------
# the spec examples and the textbook
# ---------------------------------------------------------------------------

def _spec(examples, name):
    return graphkin.load(examples / name).solve()


@pytest.mark.parametrize("fname", ["ex3_1_fourbar.toml", "ex4_11_rapsons_slide.toml",
                                   "ex4_14_inflection_bresse.toml", "ex4_16_cubic.toml"])
def test_spec_examples_against_oracles(examples, fname):
    sol = _spec(examples, fname)
    check_paths(sol)
    for lid in curvature(sol):
        check_link(sol, lid)


def test_generic_point_is_not_stationary(examples):
    # the finite-difference test above must be able to fail: a coupler point off the
    # cubic (E of Example 3.1) has a curvature that changes with the crank angle
    data = load_data(examples / "ex3_1_fourbar.toml")
    sol = graphkin.load(examples / "ex3_1_fourbar.toml").solve()
    k = link_curvature(sol, "3")
    loc = sol.mechanism.links["3"].points["E"]
    assert abs(k.cubic.residual(sol.position("E"))) > 1.0
    ar = Around(data, sol, "3")
    assert abs(ar.dkappa_dphi(np.asarray(loc))) * figure_size(sol) > 1e-2


def test_rapsons_slide_example_4_15(examples):
    # Example 4.15, Ans. (25)-(26): rho_B = -11.0 ft (magnitude 11), center (0, 0) = O4
    sol = _spec(examples, "ex4_11_rapsons_slide.toml")
    p = paths_json(sol)
    assert p["B"]["radius_of_curvature"] == pytest.approx(11.0, abs=1e-9)
    np.testing.assert_allclose(p["B"]["center_of_curvature"], [0.0, 0.0], atol=1e-9)
    # the block's pin A rides on the rod, which slides on a frame line: a straight path
    assert p["A"] == {"radius_of_curvature": None, "center_of_curvature": None,
                      "how": "straight", "link": "3"}
    # the block has one conjugate pair only: J from the accelerations
    assert curvature(sol)["3"].method == "accelerations"


def test_example_4_12_slider_crank():
    # Example 4.12 (Sec. 4.12), Figs. 4.26-4.27: R_AO2 = 2 in, R_BA = 2.5 in; crank at 30°,
    # in-line (recovered from the printed R_AI = 2.64 in, see the gallery file).
    sol = graphkin.load(GALLERY / "ex4_12_slider_crank.toml").solve()
    k = link_curvature(sol, "3")
    a, b = sol.position("A"), sol.position("B")
    # hand derivation: B = (√3 + √21/2, 0); I on O2A above B; R_AI = √7;
    # Eq. 4.43: R_AJ_A = R_AI²/R_AA' = 7/(-2) = -3.5 in, so J_A = -1.5 (cos30°, sin30°);
    # the inflection circle passes through I, B (B' at infinity) and J_A.
    bx = math.sqrt(3) + math.sqrt(21) / 2
    i = np.array([bx, bx * math.tan(math.radians(30))])
    np.testing.assert_allclose(k.velocity_pole, i, atol=1e-12)
    assert np.hypot(*(a - i)) == pytest.approx(math.sqrt(7), abs=1e-12)  # book: 2.64 in
    ja = -1.5 * np.array([math.cos(math.radians(30)), math.sin(math.radians(30))])
    assert np.hypot(*(a - ja)) == pytest.approx(3.5, abs=1e-12)  # book: 3.48 in
    # circumcircle of I, B, J_A (perpendicular bisectors), diameter 2R
    m = np.array([2 * (b - i), 2 * (ja - i)])
    cen = np.linalg.solve(m, np.array([b @ b - i @ i, ja @ ja - i @ i]))
    np.testing.assert_allclose((k.velocity_pole + k.inflection_pole) / 2, cen, atol=1e-12)
    assert k.inflection_diameter == pytest.approx(2 * np.hypot(*(cen - i)), abs=1e-12)
    # book: R_JI = 6.28 in, measured on the drawing; exact 6.2065 in (1.2 % off)
    assert k.inflection_diameter == pytest.approx(6.28, abs=0.1)
    # J is (-√3, 0), on the slider's line; Ball's point is the slider pin B (on the
    # inflection circle, moving on a straight line: a point of the cubic)
    np.testing.assert_allclose(k.inflection_pole, [-math.sqrt(3), 0.0], atol=1e-12)
    np.testing.assert_allclose(k.ball_point, b, atol=1e-9)
    assert k.method == "bobillier"


def test_example_4_14_book_numbers():
    # Example 4.14 (Sec. 4.15), Figs. 4.35-4.36: book values measured on the drawing,
    # so compared to drawing accuracy (the exact ones are in gallery/curvature/NOTES.md).
    sol = graphkin.load(GALLERY / "ex4_14_fourbar.toml").solve()
    k = link_curvature(sol, "3")
    i, j = k.velocity_pole, k.inflection_pole
    pos = {n: sol.position(n) for n in "ABC"}
    r = {n: float(np.hypot(*(pos[n] - i))) for n in "ABC"}
    xj = {n: float((j - i) @ (pos[n] - i)) / r[n] for n in "ABC"}  # R_J_nI = R_JI sin ψ
    assert r["A"] == pytest.approx(14.14, abs=0.03)  # Ans. (b) R_AI = 14.14 in
    assert r["B"] == pytest.approx(18.20, abs=0.05)  # R_BI = 18.20 in
    assert r["A"] - xj["A"] == pytest.approx(33.31, abs=0.05)  # R_AJ_A = 33.31 in
    assert r["B"] - xj["B"] == pytest.approx(27.60, abs=0.1)  # R_BJ_B = 27.60 in
    assert k.inflection_diameter == pytest.approx(19.26, abs=0.02)  # Ans. (2)
    assert k.bresse_diameter == pytest.approx(24.08, abs=0.03)  # Ans. (3): b = -24.08 in
    # ... "the negative sign indicates that the Bresse circle lies on the positive side of T"
    assert float((k.bresse_pole - i) @ k.tangent) > 0
    assert r["C"] == pytest.approx(14.67, abs=0.03)  # Ans. (4) R_CI = 14.67 in
    assert r["C"] - xj["C"] == pytest.approx(28.62, abs=0.1)  # R_CJ_C = 28.62 in
    assert paths_json(sol)["C"]["radius_of_curvature"] == pytest.approx(7.52, abs=0.01)
    assert np.hypot(*sol.velocity("C")) == pytest.approx(73.25, abs=0.05)  # Ans. (5)
    assert float(sol.omega("2")) == pytest.approx(11.78, abs=0.005)  # Ans. (6), ccw
    assert np.hypot(*k.pole_velocity) == pytest.approx(96.3, abs=0.1)  # Ans. (7)
    assert np.hypot(*k.pole_acceleration) == pytest.approx(481.5, abs=0.5)  # Ans. (8)
    # "A_I is directed from I toward J"
    assert float(k.pole_acceleration @ (j - i)) > 0
    rgc = float(np.hypot(*(pos["C"] - k.acceleration_center)))
    assert rgc == pytest.approx(29.64, abs=0.03)  # Ans. (9): R_ΓC = 29.64 in
    assert np.hypot(*sol.acceleration("C")) == pytest.approx(948.94, abs=1.0)  # Ans. (9)
    assert math.degrees(k.gamma) == pytest.approx(-38.66, abs=0.005)  # Ans. (10)
    # Ans. (1): the angle from the collineation axis IQ to the first ray (link 2) is 29.08° cw
    q = k.values["Q"]
    axis, ray2 = q[:2] / q[2] - i, pos["A"] - sol.position("O2")
    ang = math.degrees(math.atan2(_cross(axis, ray2), axis @ ray2))
    assert ang == pytest.approx(-29.08, abs=0.02)
    # Bobillier's theorem: the same angle from the second ray (link 4) to T
    ray4 = pos["B"] - sol.position("O4")
    ang4 = math.degrees(math.atan2(_cross(ray4, k.tangent), ray4 @ k.tangent))
    assert (ang4 - ang) % 180 == pytest.approx(0, abs=1e-9) or \
        (ang4 - ang) % 180 == pytest.approx(180, abs=1e-9)
    # Γ lies on both circles (Fig. 4.34)
    g = k.acceleration_center
    assert np.hypot(*(g - (i + j) / 2)) == pytest.approx(k.inflection_diameter / 2, abs=1e-9)
    assert np.hypot(*(g - (i + k.bresse_pole) / 2)) == pytest.approx(k.bresse_diameter / 2,
                                                                      abs=1e-9)


def test_example_4_16_book_numbers_and_misprints():
    # Example 4.16 (Sec. 4.17), Figs. 4.39-4.40.
    path = GALLERY / "ex4_16_fourbar.toml"
    sol = graphkin.load(path).solve()
    k = link_curvature(sol, "3")
    i = k.velocity_pole
    np.testing.assert_allclose(i, [0, -1], atol=1e-12)  # I = I13 on O2A and O4B
    s2 = math.sqrt(2)
    assert np.hypot(*(sol.position("A") - i)) == pytest.approx(2)  # Eq. (5b)
    assert np.hypot(*(sol.position("B") - i)) == pytest.approx(2 * s2)  # Eq. (5b)
    assert k.inflection_diameter == pytest.approx(2 * s2, abs=1e-12)  # Ans. (3): 2.83 in
    # "J_B lies on the centrode normal: this inflection point is the inflection pole"
    np.testing.assert_allclose(k.inflection_pole, [-2, -3], atol=1e-12)
    # ψ_A = -45°, ψ_B = -90° from T (Eq. 5a)
    for n, psi in (("A", -45.0), ("B", -90.0)):
        d = sol.position(n) - i
        got = math.degrees(math.atan2(_cross(k.tangent, d), k.tangent @ d))
        assert got == pytest.approx(psi, abs=1e-9)
    assert k.cubic.M == pytest.approx(-2 * s2, abs=1e-12)  # Ans. (7): M = -2√2 in
    assert math.isinf(k.cubic.N)  # "the parameter N tends to infinity"
    np.testing.assert_allclose(k.ball_point, k.inflection_pole, atol=1e-12)  # Ball = J
    cj = curvature_json(sol)["3"]
    assert cj["cubic"]["N"] is None and cj["cubic"]["M"] == pytest.approx(-2 * s2)
    # (c) C: ψ_C = -71.57° (Eq. 20), R_J_C I = -2.68 in (Eq. 21), ρ_C = 1.02 in (Ans. 22),
    # C' = (0.54, 1.09) in from I (Ans. 23-24)
    d = sol.position("C") - i
    assert math.degrees(math.atan2(_cross(k.tangent, d), k.tangent @ d)) == \
        pytest.approx(-71.57, abs=0.005)
    assert k.inflection_diameter * math.sin(math.atan2(_cross(k.tangent, d),
                                                       k.tangent @ d)) == \
        pytest.approx(-2.68, abs=0.005)
    pc = path_curvatures(sol)["C"]
    assert pc.radius == pytest.approx(1.02, abs=0.005)
    np.testing.assert_allclose(pc.center - i, [0.54, 1.09], atol=0.01)
    # θ3' = ω3/ω2 = 0.5 (Eq. 17)
    assert float(sol.omega("3") / sol.omega("2")) == pytest.approx(0.5)

    # (a), (b): the centrode radii.  The book prints R_IO_M = √2 in (Ans. 10b) and
    # R_IO_F = 2√2 in (Ans. 12), from R_JI = M = -2√2 in its Eq. 7; with R_JI = +2√2
    # (its own Ans. 3), Eq. 4.56 gives R_IO_M = R_JI/4 and Eq. 11 R_IO_F = R_JI/5.
    rm, om = k.moving_centrode
    rf, of = k.fixed_centrode
    assert rm == pytest.approx(s2 / 2, abs=1e-12)
    assert rf == pytest.approx(2 * s2 / 5, abs=1e-12)
    np.testing.assert_allclose(om, [0.5, -0.5], atol=1e-12)
    np.testing.assert_allclose(of, [0.4, -0.6], atol=1e-12)
    # independent evidence: the loci of I13 in the frame and in the coupler, differentiated
    # over the crank angle, have exactly these radii -- not the book's √2 and 2√2
    data = load_data(path)
    ar = Around(data, sol, "3", h=1e-3)
    poles = {j: zero_velocity_point(s.links["3"]) for j, s in ar.sols.items()}

    def radius(curve, p0):
        d1 = derivative(curve, ar.h)
        fm2, fm1, fp1, fp2 = curve
        d2 = (-fm2 + 16 * fm1 - 30 * p0 + 16 * fp1 - fp2) / (12 * ar.h ** 2)
        return math.hypot(*d1) ** 3 / abs(_cross(d1, d2))

    r_fixed = radius([poles[j] for j in STEPS], poles[0])
    st = sol.links["3"]
    r_moving = radius([local_of(ar.sols[j].links["3"], poles[j]) for j in STEPS],
                      local_of(st, poles[0]))
    assert r_fixed == pytest.approx(2 * s2 / 5, abs=1e-6)
    assert r_moving == pytest.approx(s2 / 2, abs=1e-6)
    assert abs(r_moving - s2) > 0.5 and abs(r_fixed - 2 * s2) > 2  # the book's values fail
    # and dR_JI/ds = 0 here (Eq. 8b), since N is infinite
    diam = []
    for j in STEPS:
        s = ar.sols[j].links["3"]
        diam.append(math.hypot(*s.acceleration(local_of(s, poles[j]))) / float(s.omega) ** 2)
    assert abs(derivative(diam, ar.h)) <= 1e-6


def test_example_4_16_cubic_points_are_stationary():
    # the degenerate cubic: the centrode normal and the circle of diameter M through A, B
    # about O4 (the book); points on either have stationary curvature, C (off it) has not
    path = GALLERY / "ex4_16_fourbar.toml"
    sol = graphkin.load(path).solve()
    k = link_curvature(sol, "3")
    st = sol.links["3"]
    ar = Around(load_data(path), sol, "3")
    on_normal = k.velocity_pole - 1.3 * k.normal
    on_circle = np.array([1.0, 0.0]) + math.sqrt(2) * np.array([math.cos(2.0),
                                                                 math.sin(2.0)])
    for p in (on_normal, on_circle):
        assert abs(k.cubic.residual(p)) <= 1e-12
        assert abs(ar.dkappa_dphi(local_of(st, p))) <= 1e-6
    assert abs(ar.dkappa_dphi(local_of(st, sol.position("C")))) > 1e-2


def test_constructions_replay_and_book_words():
    sol = graphkin.load(GALLERY / "ex4_14_fourbar.toml").solve()
    k = link_curvature(sol, "3")
    cx = k.construction
    assert all(s.diagram == "curvature" for s in cx)
    replay = cx.evaluate()
    for label in ("I", "J", "Γ", "U", "G_N", "G_T", "C'"):
        np.testing.assert_allclose(replay[label], k.values[label], atol=1e-12)
    notes = {s.label: s.note for s in cx}
    assert "collineation axis" in notes["IQ"]
    assert "inflection pole J" in notes["J"]
    assert "Bobillier" in notes["C'"]
    # the pivoted crank: no construction beyond its pivot; I = J = Γ = O2
    k2 = link_curvature(sol, "2")
    assert k2.method == "pivot" and k2.inflection_diameter == 0.0
    assert k2.cubic is None


def test_hartmann_and_bobillier_conjugates_agree():
    # Example 4.13 constructs C' by Bobillier (Fig. 4.30); Fig. 4.25 by Hartmann: both
    # give the Euler-Savary conjugate.  Force Hartmann by asking the acceleration route.
    sol = graphkin.load(GALLERY / "ex4_14_fourbar.toml").solve()
    kb = link_curvature(sol, "3")
    kh = link_curvature(sol, "3", method="accelerations")
    assert "Hartmann" in kh.construction.step_of("C'").note
    assert "Bobillier" in kb.construction.step_of("C'").note
    np.testing.assert_allclose(kb.conjugates["C"], kh.conjugates["C"], atol=1e-9)


def test_json_contract():
    sol = graphkin.load(GALLERY / "ex4_14_fourbar.toml").solve()
    cj, pj = curvature_json(sol), paths_json(sol)
    assert set(cj) == {"2", "3", "4"}
    for key in ("velocity_pole", "inflection_pole", "inflection_diameter",
                "acceleration_center", "bresse_diameter", "cubic", "ball_point"):
        assert key in cj["3"]
    assert set(cj["3"]["cubic"]) >= {"tangent", "M", "N"}
    assert set(pj) == {"O2", "O4", "A", "B", "C"}
    assert pj["O2"]["radius_of_curvature"] is None  # at rest
    json.dumps(cj, allow_nan=False)
    json.dumps(pj, allow_nan=False)
    text = curvature_text(sol)
    assert "R_JI = 19.249" in text and "Ball's point" in text


def test_no_rates_and_batch_give_none():
    sol = graphkin.loads(inline("curvature-crank_without_rates.toml")).solve()
    assert curvature_json(sol) is None and paths_json(sol) is None
    assert curvature_text(sol) is None
    with pytest.raises(GraphkinError):
        link_curvature(sol, "2")
    # a batch of two postures (a sweep's shape)
    one = graphkin.load(GALLERY / "ex4_16_fourbar.toml").solve()
    links = {lid: LinkState(np.array([s.angle, s.angle]), np.stack([s.origin, s.origin]),
                            np.array([s.omega, s.omega]), np.array([s.alpha, s.alpha]),
                            np.stack([s.origin_velocity] * 2),
                            np.stack([s.origin_acceleration] * 2))
             for lid, s in one.links.items()}
    batch = Solution(one.mechanism, links, valid=np.array([True, True]))
    assert curvature_json(batch) is None and paths_json(batch) is None
    with pytest.raises(GraphkinError):
        link_curvature(batch, "3")


def test_alpha_zero_bresse_is_null_and_gamma_is_j():
    # Sec. 4.15: with α = 0 the Bresse circle is the centrode normal and Γ = J
    sol = graphkin.load(GALLERY / "ex4_12_slider_crank.toml").solve()
    sol.links["3"].alpha = np.array(0.0)  # an instant of the coupler with α3 = 0
    st = sol.links["3"]
    # make the body consistent with α = 0: A_O from the point at Γ... simply recompute
    # the origin acceleration so that the acceleration of A stays that of the crank pin
    a_pin = np.array(sol.links["2"].acceleration(sol.mechanism.links["2"].points["A"]))
    r = st.position(sol.mechanism.links["3"].points["A"]) - st.origin
    st.origin_acceleration = a_pin + float(st.omega) ** 2 * r
    k = link_curvature(sol, "3", method="accelerations")
    assert k.bresse_diameter is None and k.bresse_pole is None
    np.testing.assert_allclose(k.acceleration_center, k.inflection_pole, atol=1e-12)
    np.testing.assert_allclose(k.acceleration_center, zero_acceleration_point(st),
                               atol=1e-9)
    assert curvature_json(sol)["3"]["bresse_diameter"] is None


def test_link_that_does_not_turn_is_left_out(examples):
    # Rapson's slide: the rod 2 translates (ω2 = 0): no curvature entry, its pin's path
    # comes from the turning block 3
    sol = _spec(examples, "ex4_11_rapsons_slide.toml")
    assert "2" not in curvature_json(sol)
    with pytest.raises(GraphkinError):
        link_curvature(sol, "2")


TRAMMEL = inline("curvature-trammel.toml")


def test_elliptic_trammel_cardan_circle():
    # A = (3, 0) on the x axis, B = (0, 4) on the y axis: both conjugates at infinity, so
    # A'B' is the line at infinity and the construction through W has no answer; J_A = A
    # and J_B = B (Eq. 4.43 with R_AA' infinite).  I = (3, 4); the inflection circle
    # through I, A, B has the diameter IO = 5 = AB (Cardan's circle: every point of the
    # coupler on it moves on a straight line through O).
    sol = graphkin.loads(TRAMMEL).solve()
    k = link_curvature(sol, "3")
    assert k.method == "euler-savary"
    np.testing.assert_allclose(k.velocity_pole, [3, 4], atol=1e-12)
    np.testing.assert_allclose(k.inflection_pole, [0, 0], atol=1e-12)
    # the whole circle has constant (zero) curvature: the cubic is that circle (M = R_JI)
    # and the centrode normal (N infinite); it meets the inflection circle everywhere, so
    # Ball's point is not a single point
    assert k.cubic.M == pytest.approx(5.0, abs=1e-12)
    assert math.isinf(k.cubic.N)
    assert k.ball_point is None and curvature_json(sol)["3"]["ball_point"] is None
    check_paths(sol)
    check_link(sol, "3")
    # Cardan motion: the moving centrode is the circle of diameter AB (it coincides with the
    # inflection circle) rolling inside the fixed centrode, the circle of radius AB about
    # O = J.  These are exactly the answers Example 4.16 prints for its own linkage, where
    # they do not hold (there M = -R_JI, here M = +R_JI).
    rm, om = k.moving_centrode
    rf, of = k.fixed_centrode
    assert abs(rm) == pytest.approx(2.5, abs=1e-12) and abs(rf) == pytest.approx(5, abs=1e-12)
    np.testing.assert_allclose(om, [1.5, 2.0], atol=1e-12)
    np.testing.assert_allclose(of, [0.0, 0.0], atol=1e-12)


def test_velocity_pole_is_the_instant_center_i13(examples):
    # the velocity pole of the motion 3/1 is the instant center I13 (Sec. 4.12), found by
    # the instant-centers module through Kennedy's theorem: two independent routes
    ic = pytest.importorskip("graphkin.kinematics.instant_centers")
    sol = _spec(examples, "ex3_1_fourbar.toml")
    got = ic.instant_centers_json(sol)["1-3"]["position"]
    np.testing.assert_allclose(link_curvature(sol, "3").velocity_pole, got, atol=1e-9)
