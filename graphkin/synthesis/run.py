"""One entry point: a synthesis file in, constructions, linkages and checks out.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 9.3-9.7, 9.11.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import combinations

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Role
from graphkin.errors import InputError
from graphkin.synthesis import analytic as an
from graphkin.synthesis import four, three
from graphkin.synthesis.cognates import Cognates, cayley
from graphkin.synthesis.dwell import Dwell, DwellKind, dwell
from graphkin.synthesis.five import BurmesterPoint, burmester_points
from graphkin.synthesis.function import FunctionDesign, chebyshev_construction, design
from graphkin.synthesis.limits import CrankRocker, crank_rocker
from graphkin.synthesis.linkage import Linkage
from graphkin.synthesis.overlay import Overlay, overlay
from graphkin.synthesis.postures import DIAGRAM, Postures, add_poles, add_postures
from graphkin.synthesis.spec import Spec

__all__ = ["Result", "synthesize"]


@dataclass
class Result:
    """What a synthesis found.

    Attributes
    ----------
    kind : str
        ``"2 postures"`` ... ``"5 postures"`` or ``"function"``.
    construction : Construction or None
        The recorded construction (poles, triangle, pivots; for four and five
        postures the curve's, with the input ``t``).
    selection : Construction or None
        Four postures: the chosen center points and their circle points.
    curves : Curves or None
        Four and five postures: the center-point and circle-point curves.
    burmester : list
        Five postures: the Burmester points.
    candidates : list of Linkage
        The linkages found, each with its checks.
    function : FunctionDesign or None
    dyads : dict
        Path generation: the complex vectors r1 ... r5 of Sec. 9.12 and the
        rotations β2, β3 of the rocker (radians, as real numbers).
    cognates : Cognates or None
        The Roberts-Chebyshev cognates (Cayley's diagram).
    dwell : Dwell or None
        The dwell six-bar (Sec. 9.13).
    overlay : Overlay or None
        The overlay method's fit (Sec. 9.8).
    crank_rocker : CrankRocker or None
        The crank-rocker of two limit postures and a time ratio (Sec. 9.3).
    """

    spec: Spec
    kind: str
    construction: Construction | None = None
    selection: Construction | None = None
    curves: four.Curves | None = None
    burmester: list[BurmesterPoint] = field(default_factory=list)
    candidates: list[Linkage] = field(default_factory=list)
    function: FunctionDesign | None = None
    dyads: dict[str, complex] = field(default_factory=dict)
    cognates: Cognates | None = None
    dwell: Dwell | None = None
    overlay: Overlay | None = None
    crank_rocker: CrankRocker | None = None

    @property
    def postures(self) -> Postures | None:
        """The body's postures: the file's, or (path generation) the coupler's at the points."""
        if self.spec.postures is not None:
            return self.spec.postures
        return self.candidates[0].post if self.candidates else None

    @property
    def chosen(self) -> Linkage | None:
        """The first candidate that passes every check, else the first candidate."""
        for c in self.candidates:
            if c.ok:
                return c
        return self.candidates[0] if self.candidates else None

    def mechanism_toml(self) -> str:
        """The mechanism file of the result (assembled in the first design posture)."""
        if self.function is not None:
            return self.function.mechanism_toml(self.spec.title, self.spec.units)
        if self.dwell is not None:
            return self.dwell.mechanism_toml(self.spec.units, self.spec.title)
        if self.crank_rocker is not None:
            return self.crank_rocker.mechanism_toml(self.spec.units, self.spec.title)
        if self.overlay is not None:
            return self.overlay.mechanism_toml(self.spec.units, self.spec.title)
        if self.cognates is not None:
            return self.cognates.mechanism_toml(self.spec.write, self.spec.units,
                                                self.spec.title)
        link = self.chosen
        if link is None:
            raise InputError("no linkage was found, so no mechanism can be written",
                             key="postures", file=self.spec.source)
        return link.mechanism_toml(0, self.spec.title, self.spec.units)


def _pivot_names(post: Postures) -> tuple[str, str]:
    free = [c for c in "ABGHKL" if c not in post.names]
    return free[0], free[1]


def synthesize(spec: Spec) -> Result:
    """Carry out the synthesis a file asks for.

    Raises
    ------
    InputError
        A choice the postures cannot meet (no pivots given where they are
        needed, collinear poles, no real Burmester point...), naming the key.
    """
    if spec.function is not None:
        return _function(spec)
    if spec.path is not None:
        return _path(spec)
    if spec.coupler is not None:
        from graphkin.synthesis.coupler import coupler_curve

        f = spec.coupler
        cc = coupler_curve(f["points"], f["O4"], f["O2"], f["R"], f["r"], spec.source)
        return Result(spec, "coupler curve (Sec. 9.9)", cc.construction,
                      candidates=[cc.linkage])
    if spec.overlay is not None:
        ov = overlay(spec.overlay, spec.closed, spec.source)
        return Result(spec, "overlay (Sec. 9.8)", overlay=ov)
    if spec.dwell is not None:
        z = spec.dwell
        try:
            kind = DwellKind.SLIDER if spec.dwell_slider else DwellKind.ARC
            dw = dwell(z["O_A"], z["A"], z["B"], z["O_B"], z["C"], spec.dwell_span, kind=kind)
        except InputError as exc:
            raise InputError(exc.message, key="dwell", file=spec.source) from None
        return Result(spec, "dwell six-bar" + (" with a slider" if spec.dwell_slider else ""),
                      dw.construction, dwell=dw)
    if spec.crank_rocker is not None:
        lim = spec.crank_rocker
        cr = crank_rocker(lim["O4"], lim["B1"], lim["swing"], lim["Q"], lim["x_angle"],
                          spec.source)
        return Result(spec, "crank-rocker from limit postures (Sec. 9.3)", cr.construction,
                      crank_rocker=cr)
    if spec.cognates is not None:
        z = spec.cognates
        cg = cayley(z["O_A"], z["A"], z["B"], z["O_B"], z["P"])
        return Result(spec, "cognates (Roberts-Chebyshev)", cg.construction, cognates=cg)
    post = spec.postures
    assert post is not None
    return {2: _two, 3: _three, 4: _four, 5: _five}[post.n](spec, post)


def _need(spec: Spec, what: str) -> InputError:
    return InputError(f"choose the {what} in [pivots] (two points, one per dyad)",
                      key="pivots", file=spec.source)


def _two(spec: Spec, post: Postures) -> Result:
    if spec.circle_points is None or spec.center_points is None:
        raise _need(spec, "circle_points (moving pivots in posture 1) and center_points")
    cx = Construction(title="two postures")
    labels = add_postures(cx, post)
    add_poles(cx, post, labels, [(1, 2)])
    names = _pivot_names(post)
    piv = []
    for name, a1, near in zip(names, spec.circle_points, spec.center_points):
        local = post.local(np.array(a1))
        cx.add("point", (), (f"{name}1",), xy=a1, role=Role.GIVEN, diagram=DIAGRAM,
               note=f"{name}1: the chosen moving pivot in posture 1.")
        cx.add("rigid", (labels[1][0], labels[1][2]), (f"{name}2",), local_p=(0.0, 0.0),
               local_q=local, role=Role.RESULT, diagram=DIAGRAM,
               note=f"{name}2: the pivot carried with the body to posture 2.")
        cx.add("bisector", (f"{name}1", f"{name}2"), (f"b_{name}12",), diagram=DIAGRAM,
               note=f"the bisector of {name}1{name}2: it passes through P12 (Fig. 9.6).")
        cx.add("point", (), (f"{name}*",), xy=near, role=Role.GIVEN, diagram=DIAGRAM,
               note=f"the point chosen near the bisector for O_{name}.")
        cx.add("perpendicular", (f"b_{name}12", f"{name}*"), (f"n_{name}",), diagram=DIAGRAM,
               note="the perpendicular to the bisector from the chosen point.")
        cx.add("meet", (f"b_{name}12", f"n_{name}"), (f"O_{name}",), role=Role.RESULT,
               diagram=DIAGRAM, note=f"O_{name}: the fixed pivot, on the bisector (Sec. 9.3).")
        piv.append(name)
    ev = cx.evaluate()
    pts = {k: complex(ev[k][0] / ev[k][2], ev[k][1] / ev[k][2])
           for k in (f"O_{piv[0]}", f"O_{piv[1]}", f"{piv[0]}1", f"{piv[1]}1")}
    link = Linkage(post, pts[f"O_{piv[0]}"], pts[f"O_{piv[1]}"], pts[f"{piv[0]}1"],
                   pts[f"{piv[1]}1"], names)
    link.check()
    return Result(spec, "2 postures", cx, candidates=[link])


def _three(spec: Spec, post: Postures) -> Result:
    if spec.circle_points is None and spec.center_points is None:
        raise _need(spec, "circle_points or center_points")
    poles = [an.pole(complex(*post.points[i]), post.angles[i], complex(*post.points[j]),
                     post.angles[j]) for i, j in ((0, 1), (1, 2), (2, 0))]
    u, v = poles[1] - poles[0], poles[2] - poles[0]
    if abs(u.real * v.imag - u.imag * v.real) <= 1e-9 * post.scale ** 2:
        same = max(abs(u), abs(v)) <= 1e-9 * post.scale
        raise InputError("the poles P12, P23, P31 " + (
            "coincide (the three postures turn about one point)" if same else
            "are collinear") + ": the pole triangle degenerates (Sec. 9.4)",
            key="postures", file=spec.source)
    cx = three.pole_triangle(post)
    three.straight_line_locus(cx)
    names = _pivot_names(post)
    centers, circles = [], []
    for name, k in zip(names, range(2)):
        if spec.circle_points is not None:
            a1 = spec.circle_points[k]
            lab = three.center_from_circle_point(cx, post, name, a1)
            centers.append(lab)
            circles.append(f"{name}1")
        else:
            assert spec.center_points is not None
            lab = three.circle_point_from_center(cx, post, name, spec.center_points[k])
            centers.append(f"O_{name}")
            circles.append(lab)
    ev = cx.evaluate(strict=False)

    def z(lab: str) -> complex:
        v = ev[lab]
        return complex(v[0] / v[2], v[1] / v[2])

    for lab in centers + circles:
        if not np.isfinite(z(lab)):
            raise InputError(f"{lab} is at infinity for these postures (its three positions "
                             "are on a line): choose another pivot", key="pivots",
                             file=spec.source)
    link = Linkage(post, z(centers[0]), z(centers[1]), z(circles[0]), z(circles[1]), names)
    link.check()
    return Result(spec, "3 postures", cx, candidates=[link])


def _four(spec: Spec, post: Postures) -> Result:
    cx = four.burmester_construction(post)
    cv = four.curves(post, cx=cx)
    if spec.center_points is None:
        raise _need(spec, "center_points (near the center-point curve)")
    names = _pivot_names(post)
    fine = four.curves(post, 20001, cx=cx)
    chosen = []
    for near in spec.center_points:
        target = complex(*near)
        dist = np.abs(fine.center - target)
        if not np.any(np.isfinite(dist)):
            raise InputError("the center-point curve has no finite point", key="postures",
                             file=spec.source)
        b, i = np.unravel_index(np.nanargmin(dist), dist.shape)
        chosen.append(_nearest_on_curve(cx, post, int(b), fine.t, int(i), target))
    if abs(chosen[0][0] - chosen[1][0]) <= 1e-3 * post.scale:
        raise InputError("both center points fall on the same point of the center-point curve "
                         f"near ({chosen[0][0].real:.4g}, {chosen[0][0].imag:.4g}): choose them "
                         "near two different points of it (draw it with --draw)",
                         key="pivots.center_points", file=spec.source)
    sel = Construction(title="four postures: the chosen center points")
    labels = add_postures(sel, post)
    add_poles(sel, post, labels, [(1, 2), (1, 3), (1, 4)])
    for name, (m, _) in zip(names, chosen):
        sel.add("point", (), (f"O_{name}",), xy=(m.real, m.imag), role=Role.GIVEN,
                diagram=DIAGRAM, note=f"O_{name}: the point of the center-point curve chosen "
                                      f"as a fixed pivot.")
        four.circle_point_steps(sel, post, f"O_{name}", name, post.n)
    link = Linkage(post, chosen[0][0], chosen[1][0], chosen[0][1], chosen[1][1], names)
    link.check()
    return Result(spec, "4 postures", cx, sel, cv, candidates=[link])


def _nearest_on_curve(cx: Construction, post: Postures, b: int, t: np.ndarray, i: int,
                      target: complex) -> tuple[complex, complex]:
    """The center point of branch ``b`` nearest ``target``, and its circle point.

    Golden-section search in t between the samples either side of the nearest
    sample ``i`` (each step one evaluation of the construction on two values of t);
    every point it returns is a point of the curve, exact to round-off.
    """
    name = four.letters(post)[b]

    def at(tt: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ev = cx.evaluate({"t": np.asarray(tt, dtype=float)}, strict=False)
        return four._cplx(ev[f"{name}_C"]), four._cplx(ev[f"{name}1"])

    lo, hi = float(t[max(i - 1, 0)]), float(t[min(i + 1, len(t) - 1)])
    g = (math.sqrt(5.0) - 1.0) / 2.0
    for _ in range(60):
        m1, m2 = hi - g * (hi - lo), lo + g * (hi - lo)
        c, _ = at(np.array([m1, m2]))
        d1, d2 = (abs(z - target) if np.isfinite(z) else math.inf for z in c)
        if d1 <= d2:
            hi = m2
        else:
            lo = m1
        if hi - lo <= 1e-14 * (1.0 + abs(lo)):
            break
    c, a = at(np.array([t[i], 0.5 * (lo + hi)]))
    k = 1 if np.isfinite(c[1]) and abs(c[1] - target) <= abs(c[0] - target) else 0
    return complex(c[k]), complex(a[k])


def _five(spec: Spec, post: Postures) -> Result:
    pts, cx = burmester_points(post)
    if len(pts) < 2:
        raise InputError(f"{len(pts)} real Burmester point(s): five postures this far apart "
                         "have no four-bar (Sec. 9.6)", key="postures", file=spec.source)
    four_post = Postures(post.points[:4], post.angles[:4], post.names, post.second,
                         post.source, post.key, post.tol, post.second_given)
    cv = four.curves(four_post, cx=cx)
    names = _pivot_names(post)
    cands = []
    for p, q in combinations(pts, 2):
        link = Linkage(post, p.center, q.center, p.circle, q.circle, names)
        link.check()
        cands.append(link)
    return Result(spec, "5 postures", cx, None, cv, burmester=pts, candidates=cands)


def _path(spec: Spec) -> Result:
    """A crank, coupler and rocker through three precision points with timing (Sec. 9.12).

    The crank-and-coupler dyad from Eq. 3 (two complex linear equations), the
    rocker dyad pinned on the coupler from Eqs. 5-10 (the determinant of Eq. 7
    vanishes; the trivial root β = 0 left out).  The coupler, with the coupler
    point S as its reference point, becomes the body of three postures, and
    the linkage is checked and written like any other.
    """
    ps = spec.path
    assert ps is not None
    r2, r3, r1 = an.crank_coupler_dyad(ps.crank, ps.coupler, ps.points)
    size = float(np.max(np.abs(ps.points - ps.points[0])))
    if not all(np.isfinite(z) for z in (r1, r2, r3)) or min(abs(r2), abs(r3)) <= 1e-9 * size:
        raise InputError("no crank and coupler reach the three precision points with these "
                         "rotations (the dyad equations are singular)", key="path",
                         file=spec.source)
    turn = np.exp(1j * (ps.crank - ps.crank[0]))
    roll = np.exp(1j * ps.coupler)
    crank_pin = r1 + r2 * turn
    pin = crank_pin + ps.rocker_pin * r3 * roll
    roots = an.rocker_dyad(ps.coupler, -pin)
    if not roots:
        raise InputError("no rocker pinned there reaches the three positions (Eq. 7 has no "
                         "real root but β = 0)", key="path.rocker_pin", file=spec.source)
    r4, r5, b2, b3 = roots[0]
    ang = float(np.angle(r3)) + ps.coupler
    post = Postures(np.stack([ps.points.real, ps.points.imag], axis=-1), ang, ("S", "T"),
                    (0.0, 0.25 * abs(r3)), spec.source, "path", second_given=False)
    link = Linkage(post, r1, r5, complex(crank_pin[0]), complex(pin[0]), ("A", "B"))
    link.check()
    return Result(spec, "path (3 precision points)", candidates=[link],
                  dyads={"r1": r1, "r2": r2, "r3": r3, "r4": r4, "r5": r5,
                         "beta2": complex(b2), "beta3": complex(b3)})


def _function(spec: Spec) -> Result:
    """Function generation (Sec. 9.11), its linkage checked like the others.

    The coupler BC at the three precision points is the body of three
    postures (its midpoint as the reference point), so the branch, order,
    Grashof, toggle and transmission checks are the same as for body guidance.
    """
    assert spec.function is not None
    try:
        fd = design(spec.function)
    except np.linalg.LinAlgError:
        raise InputError("Freudenstein's equations (9.24) are singular for these precision "
                         "points: no linkage (choose another range, start or span)",
                         key="function", file=spec.source) from None
    r1, r2, r3, r4 = fd.lengths
    if not np.isfinite(r3):
        raise InputError("Freudenstein's equation gives r3² < 0 for these angles: no linkage "
                         "(choose other starts or spans)", key="function", file=spec.source)
    b = r2 * np.exp(1j * fd.phi)
    c = complex(r1, 0.0) - r4 * np.exp(1j * fd.psi)
    mid = (b + c) / 2
    post = Postures(np.stack([mid.real, mid.imag], axis=-1), np.angle(c - b), ("M", "N"),
                    (0.0, 0.25 * r3), spec.source, "function", second_given=False)
    link = Linkage(post, 0j, complex(r1, 0.0), complex(b[0]), complex(c[0]), ("B", "C"))
    link.check()
    x0, x1 = spec.function.x_range
    cheb = chebyshev_construction(x0, x1, spec.function.points)
    return Result(spec, "function", cheb, candidates=[link], function=fd)
