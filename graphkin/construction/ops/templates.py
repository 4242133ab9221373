"""The templates of :mod:`graphkin.construction.codegen`: each operation's arithmetic, as source.

Each template writes what the operation's compiled kernel
(:mod:`graphkin.construction.ops.kernels`) computes, on the rows of its
inputs, and where the kernel would take its exact, slower branch (arcs that
barely meet, coincident points, nearly parallel lines, a vanishing length)
it writes a check that returns ``None`` instead, so that the construction is
replayed.  The generated function therefore computes the kernels' numbers,
in the clean case only.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (cases 1-4 of Table 2.2),
Secs. 3.4-3.6 (velocity polygon and images), Secs. 4.2-4.6 (acceleration
polygon, Coriolis component).
"""

from __future__ import annotations

import numpy as np

from graphkin.construction.codegen import Gen, _num, lit, template
from graphkin.construction.step import Step


def _pair(gen: Gen, v: object) -> tuple[str, str]:
    """The two components of a constant pair (numbers, or arrays for a batch of designs)."""
    a = np.asarray(v, dtype=float)
    return gen.num(a[..., 0]), gen.num(a[..., 1])


def _diff(gen: Gen, a: str, b: str) -> tuple[str, str]:
    """``R_BA``: the components of B - A, as names (a constant zero of A is not subtracted)."""
    ax, ay = gen.pt(a)
    bx, by = gen.pt(b)
    return gen.let(gen.sub(bx, ax), "dx"), gen.let(gen.sub(by, ay), "dy")


def _div(gen: Gen, a: str, b: str) -> str:
    """``a / b`` (b a name or a nonzero literal; a literal one drops out)."""
    if b == "1.0":
        return a
    if gen.is_zero(a):
        return "0.0"
    return f"({a} / {b})"


def _positive(gen: Gen, expr: str) -> None:
    """Return None (replay) unless every entry of ``expr`` is > 0 (NaN fails)."""
    gen.bail_unless(f"_min({expr}, None) > 0.0")


@template("rigid")
def _rigid(gen: Gen, step: Step) -> None:
    p, th = step.inputs
    ax, ay = gen.pt(p)
    d0, d1 = _pair(gen, np.subtract(step.params["local_q"], step.params["local_p"]))
    c, s = gen.cs(th, float(step.params.get("offset", 0.0)))
    # Q = P + R(θ) d: the rotation (c d0 - s d1, s d0 + c d1); a zero component drops out
    x = gen.sub(gen.mul(c, d0), gen.mul(s, d1))
    y = gen.add(gen.mul(s, d0), gen.mul(c, d1))
    gen.put_point(step.outputs[0], gen.add(x, ax), gen.add(y, ay))


@template("circle")
def _circle(gen: Gen, step: Step) -> None:
    # an arc is its center and radius: nothing to compute
    x, y = gen.pt(step.inputs[0])
    gen.put_rows(step.outputs[0], "circle", x, y, gen.num(step.params["radius"]))


@template("intersect_circles")
def _intersect_circles(gen: Gen, step: Step) -> None:
    c1, c2 = step.inputs
    x1, y1, r1 = gen.rows(c1)
    x2, y2, r2 = gen.rows(c2)
    tol = gen.tol
    dx = gen.let(gen.sub(x2, x1), "dx")
    dy = gen.let(gen.sub(y2, y1), "dy")
    dd = gen.let(gen.add(gen.mul(dx, dx), gen.mul(dy, dy)), "dd")
    k1, k2 = _num(r1), _num(r2)
    rr = lit(k1 * k1 - k2 * k2) if k1 is not None and k2 is not None \
        else f"({r1} * {r1} - {r2} * {r2})"
    # along and across the line of centers, in units of its length d:
    # a/d = (d² + r1² - r2²) / 2d², (h/d)² = r1²/d² - (a/d)²
    p = gen.let(f"({dd} + {rr}) / (2.0 * {dd})", "p")
    r1sq = lit(k1 * k1) if k1 is not None else f"({r1} * {r1})"
    q2 = gen.let(f"{r1sq} / {dd} - {p} * {p}", "q")
    # the kernel's clean case: no tangency to round, no concentric arcs
    if k1 is not None and k2 is not None:
        lim = lit((2.0 * (tol.length_abs + tol.length_rel * max(abs(k1), abs(k2)))) ** 2)
    else:
        lim = (f"(2.0 * ({lit(tol.length_abs)} + {lit(tol.length_rel)} * "
               f"max(float(_max(_abs({r1}), None)), float(_max(_abs({r2}), None))))) ** 2")
    gen.bail_unless(f"_min({dd}, None) > {lim}")
    # tangency (a dead center): a tiny negative h² from a length error counts as zero, as
    # the kernel rounds it; arcs that do not meet are not clean
    fix = gen.helper("tangent_cc")
    q2 = gen.let(gen.where(f"_min({q2}, None) >= 0.0", q2, f"{fix}({q2}, {dd}, {r1}, {r2})"), "q")
    gen.bail_unless(f"_min({q2}, None) >= 0.0")
    q = gen.let(f"_sqrt({q2})", "h")
    # C1 + a u ± h k × u with u the unit vector from center 1 to center 2
    x, y = _turned(gen, p, q, dx, dy, gen.side(step, step.params["branch"] == "left"))
    gen.put_point(step.outputs[0], gen.add(x, x1), gen.add(y, y1))


def _turned(gen: Gen, p: str, q: str, ux: str, uy: str, left: bool | str) -> tuple[str, str]:
    """``p u + q k × u`` (``left``) or ``p u - q k × u``: along ``u`` and across it.

    ``left`` is the branch (:meth:`Gen.side`): a bool, or the name of a sign
    read at run time (+1 left, -1 right: the JavaScript page can switch it).
    """
    pux, puy, qux, quy = gen.mul(p, ux), gen.mul(p, uy), gen.mul(q, ux), gen.mul(q, uy)
    if isinstance(left, str):
        qux, quy = gen.mul(left, qux), gen.mul(left, quy)
        return gen.sub(pux, quy), gen.add(puy, qux)
    if left:
        return gen.sub(pux, quy), gen.add(puy, qux)
    return gen.add(pux, quy), gen.sub(puy, qux)


@template("intersect_line_circle")
def _intersect_line_circle(gen: Gen, step: Step) -> None:
    line, c = step.inputs
    l0, l1, l2 = gen.rows(line)
    cx, cy, r = gen.rows(c)
    s = gen.let(gen.add(gen.add(gen.mul(l0, cx), gen.mul(l1, cy)), l2), "s")
    h2 = gen.let(gen.sub(gen.mul(r, r), gen.mul(s, s)), "h")
    fix = gen.helper("tangent_lc")
    h2 = gen.let(gen.where(f"_min({h2}, None) >= 0.0", h2, f"{fix}({h2}, {s}, {r})"), "h")
    gen.bail_unless(f"_min({h2}, None) >= 0.0")
    h = gen.let(f"_sqrt({h2})", "h")
    # the foot of the perpendicular from the center, then ∓ h along the line (l1, -l0)
    x, y = _turned(gen, s, h, l0, l1, gen.side(step, step.params["branch"] != "behind"))
    gen.put_point(step.outputs[0], gen.sub(cx, x), gen.sub(cy, y))


@template("link_angle")
def _link_angle(gen: Gen, step: Step) -> None:
    a, b = step.inputs
    dl = np.subtract(step.params["local_b"], step.params["local_a"])
    phi = np.arctan2(dl[..., 1], dl[..., 0])
    dx, dy = _diff(gen, a, b)
    t = f"_atan2({dy}, {dx})"
    ph = gen.num(phi)
    value = gen.sub(t, ph)

    def trig() -> tuple[str, str]:
        # the direction AB gives the cosine and sine of the line's angle (written when a
        # later step first asks for them)
        n = gen.let(f"_sqrt({gen.add(gen.mul(dx, dx), gen.mul(dy, dy))})", "n")
        _positive(gen, n)
        c, s = gen.let(f"{dx} / {n}", "c"), gen.let(f"{dy} / {n}", "s")
        if gen.is_zero(ph):
            return c, s
        cp, sp = gen.num(np.cos(phi)), gen.num(np.sin(phi))
        return (gen.let(gen.add(gen.mul(c, cp), gen.mul(s, sp)), "c"),
                gen.let(gen.sub(gen.mul(s, cp), gen.mul(c, sp)), "s"))

    gen.put_scalar(step.outputs[0], value, trig)


@template("angle_along")
def _angle_along(gen: Gen, step: Step) -> None:
    t_, s_ = step.inputs
    tx, ty = gen.pt(t_)
    sx, sy = gen.pt(s_)
    sign = lit(step.params["sign"])
    phi = lit(step.params["local_angle"])
    dy, dx = gen.mul(gen.sub(sy, ty), sign), gen.mul(gen.sub(sx, tx), sign)
    gen.put_scalar(step.outputs[0], gen.sub(f"_atan2({dy}, {dx})", phi))


@template("add_angle")
def _add_angle(gen: Gen, step: Step) -> None:
    t = gen.scalar(step.inputs[0])
    gen.put_scalar(step.outputs[0], gen.add(t, gen.num(step.params["offset"])))


@template("roll_angle")
def _roll_angle(gen: Gen, step: Step) -> None:
    # θ_l = θ_o + c - k u·(P - L0), u the unit direction of L0 L1 (no slip, Sec. 2.19)
    t = gen.scalar(step.inputs[0])
    px, py = gen.pt(step.inputs[1])
    ax, ay = gen.pt(step.inputs[2])
    bx, by = gen.pt(step.inputs[3])
    ux, uy = gen.let(gen.sub(bx, ax), "dx"), gen.let(gen.sub(by, ay), "dy")
    n = gen.let(f"_sqrt({gen.add(gen.mul(ux, ux), gen.mul(uy, uy))})", "n")
    gen.bail_unless(f"_min({n}, None) > 0.0")
    s = gen.add(gen.mul(gen.sub(px, ax), ux), gen.mul(gen.sub(py, ay), uy))
    c, k = gen.num(step.params["c"]), gen.num(step.params["k"])
    gen.put_scalar(step.outputs[0], gen.sub(gen.add(t, c), gen.mul(k, f"({s} / {n})")))


@template("roll_circle_angle")
def _roll_circle_angle(gen: Gen, step: Step) -> None:
    # θ_l = θ_o + k (θ_m + β - θ_o) + c on the covering (no slip on a circle, Sec. 2.19);
    # solved for θ_o when θ_l is the known one: θ_o = (θ_l - k (θ_m + β) - c) / (1 - k)
    t, tm = gen.scalar(step.inputs[0]), gen.scalar(step.inputs[1])
    k, beta, c = (gen.num(step.params[n]) for n in ("k", "beta", "c"))
    psi = gen.let(gen.add(tm, beta), "t")
    if step.params["solve"] == "rolling":
        gen.put_scalar(step.outputs[0],
                       gen.add(gen.add(t, gen.mul(k, gen.sub(psi, t))), c))
        return
    den = gen.let(gen.sub("1.0", k), "t")
    gen.put_scalar(step.outputs[0],
                   gen.let(f"{gen.sub(gen.sub(t, gen.mul(k, psi)), c)} / {den}", "t"))


@template("planetary_arm")
def _planetary_arm(gen: Gen, step: Step) -> None:
    # θ_A = u θ_F + v θ_L + w: the train formula integrated on the covering (Eq. 7.25)
    f, last = gen.scalar(step.inputs[0]), gen.scalar(step.inputs[1])
    u, v, w = (gen.num(step.params[n]) for n in ("u", "v", "w"))
    gen.put_scalar(step.outputs[0], gen.add(gen.add(gen.mul(u, f), gen.mul(v, last)), w))


def _join_homogeneous(gen: Gen, step: Step) -> None:
    """The line through two points, either of them at infinity: ``p × q``, normalized.

    Written only by the centers' JavaScript writer (``gen.homogeneous``):
    Kennedy's lines through a center at infinity (a slider's) are the
    parallels through the other center.  Two points at infinity, or two
    coincident points, have no line (``|(a, b)|`` vanishing against ``|c|``).
    """
    px, py, pw = gen.rows(step.inputs[0])
    qx, qy, qw = gen.rows(step.inputs[1])
    a = gen.let(gen.sub(gen.mul(py, qw), gen.mul(pw, qy)), "a")
    b = gen.let(gen.sub(gen.mul(pw, qx), gen.mul(px, qw)), "b")
    c = gen.let(gen.sub(gen.mul(px, qy), gen.mul(py, qx)), "c")
    n = gen.let(f"_sqrt({gen.add(gen.mul(a, a), gen.mul(b, b))})", "n")
    # in the points' own scale: |a, b| against the rel. tolerance of |c| (|p||q| sin)
    gen.bail_unless(f"{n} > {lit(gen.tol.length_rel)} * _abs({c})")
    gen.put_rows(step.outputs[0], "line", *(_div(gen, r, n) for r in (a, b, c)))


@template("join")
def _join(gen: Gen, step: Step) -> None:
    p, q = step.inputs
    # homogeneous rows of a point (a point at infinity) exist only in the JavaScript writer
    if getattr(gen, "homogeneous", False) or any(
            gen.val(i).form == "rows" and gen.val(i).kind == "point" for i in (p, q)):
        _join_homogeneous(gen, step)
        return
    px, py = gen.pt(p)
    qx, qy = gen.pt(q)
    tol = gen.tol
    # the cross product (px, py, 1) × (qx, qy, 1), normalized
    a = gen.let(gen.sub(py, qy), "a")
    b = gen.let(gen.sub(qx, px), "b")
    c = gen.let(gen.sub(gen.mul(px, qy), gen.mul(py, qx)), "c")
    n = gen.let(f"_sqrt({gen.add(gen.mul(a, a), gen.mul(b, b))})", "n")
    # the kernel's clean case (no two coincident points): n (1 - rel) > abs + rel 2 |far|
    far = gen.val(p) if gen.val(p).const is not None else gen.val(q)
    if far.const is not None:
        big = lit(float(np.max(np.abs(np.asarray(far.const)[..., :2]))))
    else:
        fx, fy = far.ex[0], far.ex[1]
        big = f"max(float(_max(_abs({fx}), None)), float(_max(_abs({fy}), None)))"
    gen.bail_unless(f"_min({n}, None) * {lit(1.0 - tol.length_rel)} > "
                    f"{lit(tol.length_abs)} + {lit(2.0 * tol.length_rel)} * {big}")
    gen.put_rows(step.outputs[0], "line", *(_div(gen, r, n) for r in (a, b, c)))


def _line_through(turned: bool) -> None:
    """The template of the line through a point with the normal ``(a, b)`` or ``(-b, a)``."""

    def tpl(gen: Gen, step: Step) -> None:
        line, p = step.inputs
        a, b, _ = gen.rows(line)
        px, py, pw = gen.rows(p)
        n0, n1 = (gen.neg(b), a) if turned else (a, b)
        c = gen.neg(gen.add(gen.mul(n0, px), gen.mul(n1, py)))
        gen.put_rows(step.outputs[0], "line", n0, n1, _div(gen, c, pw))

    template("perpendicular" if turned else "parallel")(tpl)


_line_through(True)
_line_through(False)


@template("meet")
def _meet(gen: Gen, step: Step) -> None:
    a1, b1, c1 = gen.rows(step.inputs[0])
    a2, b2, c2 = gen.rows(step.inputs[1])
    pw = gen.let(gen.sub(gen.mul(a1, b2), gen.mul(b1, a2)), "w")
    px = gen.let(gen.sub(gen.mul(b1, c2), gen.mul(c1, b2)), "x")
    py = gen.let(gen.sub(gen.mul(c1, a2), gen.mul(a1, c2)), "y")
    if getattr(gen, "homogeneous", False):
        # the centers' writer (jsgen, homogeneous): parallel lines meet at infinity, kept as
        # (x, y, 0); only coincident lines (every row zero) have no meet
        n2 = gen.add(gen.add(gen.mul(px, px), gen.mul(py, py)), gen.mul(pw, pw))
        n = gen.let(f"_sqrt({n2})", "n")
        _positive(gen, n)
        gen.put_rows(step.outputs[0], "point", *(_div(gen, r, n) for r in (px, py, pw)))
        return
    n2 = gen.add(gen.mul(px, px), gen.mul(py, py))
    # the kernel's clean case: nowhere parallel, coincident or NaN
    gate = lit((gen.tol.angle * (1.0 + 1e-6)) ** 2)
    gen.bail_unless(gen.every(f"{pw} * {pw} > {gate} * _maximum({n2}, 1.0)"))
    gen.put_point(step.outputs[0], _div(gen, px, pw), _div(gen, py, pw))


def _point_and_vector(sign: str) -> None:
    def tpl(gen: Gen, step: Step) -> None:
        ax, ay = gen.pt(step.inputs[0])
        vx, vy, *_ = gen.rows(step.inputs[1])
        op = gen.add if sign == "+" else gen.sub
        gen.put_point(step.outputs[0], op(ax, vx), op(ay, vy))

    template("translate" if sign == "+" else "subtract")(tpl)


_point_and_vector("+")
_point_and_vector("-")


@template("vector")
def _vector(gen: Gen, step: Step) -> None:
    px, py = gen.pt(step.inputs[0])
    qx, qy = gen.pt(step.inputs[1])
    gen.put_rows(step.outputs[0], "vector", gen.sub(qx, px), gen.sub(qy, py))


@template("scale_vector")
def _scale_vector(gen: Gen, step: Step) -> None:
    vx, vy, *_ = gen.rows(step.inputs[0])
    k = gen.scalar(step.inputs[1])
    f = gen.num(step.params.get("factor", 1.0))
    k = gen.let(gen.mul(k, f), "k")
    gen.put_rows(step.outputs[0], "vector", gen.mul(vx, k), gen.mul(vy, k))


@template("similar")
def _similar(gen: Gen, step: Step) -> None:
    la = np.asarray(step.params["local_a"], dtype=float)
    lb = np.asarray(step.params["local_b"], dtype=float)
    lp = np.asarray(step.params["local_p"], dtype=float)
    zr, zp = lb - la, lp - la
    den = zr[..., 0] ** 2 + zr[..., 1] ** 2
    if la.shape[-1:] != (2,) or lb.shape[-1:] != (2,) or lp.shape[-1:] != (2,) or \
            not np.all(den != 0.0):
        gen.generic(step)
        return
    # p = a + (b - a) q with the complex ratio q = (P - A) / (B - A) of the link
    qr = gen.num((zp[..., 0] * zr[..., 0] + zp[..., 1] * zr[..., 1]) / den)
    qi = gen.num((zp[..., 1] * zr[..., 0] - zp[..., 0] * zr[..., 1]) / den)
    a, b = step.inputs
    ax, ay = gen.pt(a)
    d0, d1 = _diff(gen, a, b)
    gen.put_point(step.outputs[0], gen.add(gen.sub(gen.mul(d0, qr), gen.mul(d1, qi)), ax),
                  gen.add(gen.add(gen.mul(d0, qi), gen.mul(d1, qr)), ay))


@template("image")
def _image(gen: Gen, step: Step) -> None:
    # Mehmke's theorem (Secs. 3.5, 4.3): p' = a' + (b' - a') q, the complex ratio
    # q = (P - A) / (B - A) of the link's points taken from their positions now (the
    # acceleration image of the point of a link at I, whose tip is J: Sec. 4.15)
    a, b, ia, ib, p = step.inputs
    r0, r1 = _diff(gen, a, b)
    s0, s1 = _diff(gen, a, p)
    den = gen.let(gen.add(gen.mul(r0, r0), gen.mul(r1, r1)), "dd")
    _positive(gen, den)  # A and B apart: the general function divides by |B - A|²
    qr = gen.let(_div(gen, gen.add(gen.mul(s0, r0), gen.mul(s1, r1)), den), "q")
    qi = gen.let(_div(gen, gen.sub(gen.mul(s1, r0), gen.mul(s0, r1)), den), "q")
    ax, ay = gen.pt(ia)
    d0, d1 = _diff(gen, ia, ib)
    gen.put_point(step.outputs[0], gen.add(ax, gen.sub(gen.mul(d0, qr), gen.mul(d1, qi))),
                  gen.add(ay, gen.add(gen.mul(d0, qi), gen.mul(d1, qr))))


@template("velocity_difference")
def _velocity_difference(gen: Gen, step: Step) -> None:
    img, omega, a, x_ = step.inputs
    ix, iy = gen.pt(img)
    rx, ry = _diff(gen, a, x_)
    w = gen.scalar(omega)
    # V_X = V_A + ω k × R_XA
    gen.put_point(step.outputs[0], gen.sub(ix, gen.mul(w, ry)), gen.add(iy, gen.mul(w, rx)))


@template("acceleration_difference")
def _acceleration_difference(gen: Gen, step: Step) -> None:
    img, omega, alpha, a, x_ = step.inputs
    ix, iy = gen.pt(img)
    rx, ry = _diff(gen, a, x_)
    w, al = gen.scalar(omega), gen.scalar(alpha)
    w2 = gen.let(gen.mul(w, w), "w")
    # A_X = A_A + α k × R_XA - ω² R_XA
    gen.put_point(step.outputs[0], gen.sub(ix, gen.add(gen.mul(al, ry), gen.mul(w2, rx))),
                  gen.add(iy, gen.sub(gen.mul(al, rx), gen.mul(w2, ry))))


def _differences(gen: Gen, step: Step) -> tuple[str, str, str, str, str]:
    """``R_BA``, the image difference ``b − a`` and ``|R_BA|²`` (checked > 0)."""
    a, b, ia, ib = step.inputs
    r0, r1 = _diff(gen, a, b)
    v0, v1 = _diff(gen, ia, ib)
    den = gen.let(gen.add(gen.mul(r0, r0), gen.mul(r1, r1)), "dd")
    _positive(gen, den)
    return r0, r1, v0, v1, den


@template("angular_rate")
def _angular_rate(gen: Gen, step: Step) -> None:
    r0, r1, v0, v1, den = _differences(gen, step)
    gen.put_scalar(step.outputs[0], _div(gen, gen.sub(gen.mul(r0, v1), gen.mul(r1, v0)), den))


def _normal(sign: float) -> None:
    """``sign |V|²/|R|² R``: ``normal_component`` (-1, Eq. 4.7), ``apparent_normal`` (+1)."""

    def tpl(gen: Gen, step: Step) -> None:
        r0, r1, v0, v1, den = _differences(gen, step)
        k = _div(gen, gen.add(gen.mul(v0, v0), gen.mul(v1, v1)), den)
        k = gen.let(gen.neg(k) if sign < 0 else k, "k")
        gen.put_rows(step.outputs[0], "vector", gen.mul(k, r0), gen.mul(k, r1))

    template("normal_component" if sign < 0 else "apparent_normal")(tpl)


_normal(-1.0)
_normal(1.0)


@template("coriolis")
def _coriolis(gen: Gen, step: Step) -> None:
    omega, ip, ipk = step.inputs
    w2 = gen.let(gen.mul("2.0", gen.scalar(omega)), "w")
    v0, v1 = _diff(gen, ipk, ip)
    # 2 ω k × V_rel
    gen.put_rows(step.outputs[0], "vector", gen.mul(gen.neg(w2), v1), gen.mul(w2, v0))


@template("rolling_normal")
def _rolling_normal(gen: Gen, step: Step) -> None:
    # A^r = factor (ω_i - ω_j)² (P - C): toward the roller's center (Eq. 4.19)
    c, center, wi, wj = step.inputs
    r0, r1 = _diff(gen, c, center)
    w = gen.let(gen.sub(gen.scalar(wi), gen.scalar(wj)), "w")
    k = gen.let(gen.mul(gen.num(step.params.get("factor", 1.0)), gen.mul(w, w)), "k")
    gen.put_rows(step.outputs[0], "vector", gen.mul(k, r0), gen.mul(k, r1))


def _along(gen: Gen, step: Step) -> None:
    # add_along (p, p0, p1, s) and along_line (p0, p1, s): from the first input, a signed
    # distance s along the direction p0 → p1
    p, (p0, p1, s) = step.inputs[0], step.inputs[-3:]
    ax, ay = gen.pt(p)
    d0, d1 = _diff(gen, p0, p1)
    dd = gen.let(gen.add(gen.mul(d0, d0), gen.mul(d1, d1)), "dd")
    _positive(gen, dd)
    k = gen.let(f"{gen.scalar(s)} / _sqrt({dd})", "k")
    gen.put_point(step.outputs[0], gen.add(ax, gen.mul(d0, k)), gen.add(ay, gen.mul(d1, k)))


template("add_along")(_along)

template("along_line")(_along)


@template("point")
def _point(gen: Gen, step: Step) -> None:
    # a given point (a frame pivot): the Python writer folds it when the function is written,
    # the JavaScript writer keeps its coordinates parameters (they can be dragged)
    gen.put_point(step.outputs[0], *_pair(gen, step.params["xy"]))


@template("scalar")
def _scalar(gen: Gen, step: Step) -> None:
    # a given number (the frame's angle): folded by the Python writer, a parameter in JS
    gen.put_scalar(step.outputs[0], gen.num(step.params["value"]))


# ---- templates the JavaScript writer needs (Python calls the general functions) ----------
# Each writes the operation's own formula (compass.py, points.py, drives.py) and returns
# None wherever the formula would divide by zero or take a root of a negative number.

@template("copy_point", python=False)
def _copy_point(gen: Gen, step: Step) -> None:
    v = gen.val(step.inputs[0])
    if v.form == "rows":  # a homogeneous point (the centers' writer): its three rows
        gen.put_rows(step.outputs[0], "point", *v.ex)
        return
    gen.put_point(step.outputs[0], *gen.pt(step.inputs[0]))


@template("at_infinity_on", python=False)
def _at_infinity_on(gen: Gen, step: Step) -> None:
    # the point at infinity of a line (a, b, c): its direction (b, -a), w = 0
    a, b, _ = gen.rows(step.inputs[0])
    gen.put_rows(step.outputs[0], "point", b, gen.neg(a), "0.0")


template("same_point", python=False)(_copy_point)


@template("point_xy", python=False)
def _point_xy(gen: Gen, step: Step) -> None:
    x, y = step.inputs
    gen.put_point(step.outputs[0], gen.scalar(x), gen.scalar(y))


@template("add_angles", python=False)
def _add_angles(gen: Gen, step: Step) -> None:
    a, b = (gen.scalar(i) for i in step.inputs)
    sign = float(step.params.get("sign", 1.0))
    gen.put_scalar(step.outputs[0], gen.add(a, b) if sign == 1.0 else gen.sub(a, b)
                   if sign == -1.0 else gen.add(a, gen.mul(lit(sign), b)))


@template("circle_on_diameter", python=False)
def _circle_on_diameter(gen: Gen, step: Step) -> None:
    # Thales: the center is the midpoint of PQ, the radius half of |PQ|
    px, py = gen.pt(step.inputs[0])
    dx, dy = _diff(gen, *step.inputs)
    gen.put_rows(step.outputs[0], "circle", gen.add(px, gen.mul("0.5", dx)),
                 gen.add(py, gen.mul("0.5", dy)),
                 f"0.5 * _sqrt({gen.add(gen.mul(dx, dx), gen.mul(dy, dy))})")


def _line_through_direction(gen: Gen, px: str, py: str, dx: str, dy: str) -> tuple[str, ...]:
    """The line through (px, py) directed along (dx, dy): ``(-dy, dx, px dy - py dx) / |d|``."""
    n = gen.let(f"_sqrt({gen.add(gen.mul(dx, dx), gen.mul(dy, dy))})", "n")
    _positive(gen, n)
    c = gen.sub(gen.mul(px, dy), gen.mul(py, dx))
    return tuple(_div(gen, r, n) for r in (gen.neg(dy), dx, c))


@template("line_at_angle", python=False)
def _line_at_angle(gen: Gen, step: Step) -> None:
    px, py = gen.pt(step.inputs[0])
    c, s = gen.cs(step.inputs[1], float(step.params.get("offset", 0.0)))
    gen.put_rows(step.outputs[0], "line", *_line_through_direction(gen, px, py, c, s))


@template("coordinate_line", python=False)
def _coordinate_line(gen: Gen, step: Step) -> None:
    # x = s directed +y, or y = s directed +x
    s = gen.scalar(step.inputs[0])
    if step.params["axis"] == "x":
        gen.put_rows(step.outputs[0], "line", *_line_through_direction(gen, s, "0.0", "0.0",
                                                                          "1.0"))
    else:
        gen.put_rows(step.outputs[0], "line", *_line_through_direction(gen, "0.0", s, "1.0",
                                                                          "0.0"))


@template("perpendicular_cw", python=False)
def _perpendicular_cw(gen: Gen, step: Step) -> None:
    line, p = step.inputs
    a, b, _ = gen.rows(line)
    px, py, pw = gen.rows(p)
    # the counterclockwise perpendicular (-b, a, c) turned end for end
    c = gen.add(gen.mul(gen.neg(b), px), gen.mul(a, py))
    gen.put_rows(step.outputs[0], "line", b, gen.neg(a), _div(gen, c, pw))


def _finite_xy(gen: Gen, label: str) -> tuple[str, str]:
    """A point's x and y; a homogeneous row ``(x, y, w)`` (the centers' writer) divided by w.

    Replay (None) unless ``w`` is clearly nonzero: the point must be finite.
    """
    v = gen.val(label)
    if v.form == "point":
        return gen.pt(label)
    x, y, w = gen.rows(label)
    gen.bail_unless(f"_abs({w}) > 0.0")
    return gen.let(f"{x} / {w}", "x"), gen.let(f"{y} / {w}", "y")


@template("along_ray", python=False)
def _along_ray(gen: Gen, step: Step) -> None:
    # a center at a given distance from a point towards another (two circles touching on
    # their line of centers, Sec. 3.13): the points finite
    ax, ay = _finite_xy(gen, step.inputs[0])
    bx, by = _finite_xy(gen, step.inputs[1])
    dx, dy = gen.let(gen.sub(bx, ax), "dx"), gen.let(gen.sub(by, ay), "dy")
    n = gen.let(f"_sqrt({gen.add(gen.mul(dx, dx), gen.mul(dy, dy))})", "n")
    _positive(gen, n)
    k = gen.let(f"{gen.num(step.params['distance'])} / {n}", "k")
    x, y = gen.add(ax, gen.mul(dx, k)), gen.add(ay, gen.mul(dy, k))
    if getattr(gen, "homogeneous", False):  # the centers' writer: every point as (x, y, w)
        gen.put_rows(step.outputs[0], "point", x, y, "1.0")
    else:
        gen.put_point(step.outputs[0], x, y)


@template("tangent_foot", python=False)
def _tangent_foot(gen: Gen, step: Step) -> None:
    # T = P + (d²/D) ŝ ± (d t/D) k × ŝ, D = |PS|, t = √(D² − d²)
    ax, ay = gen.pt(step.inputs[0])
    vx, vy = _diff(gen, *step.inputs)
    dist = gen.let(f"_sqrt({gen.add(gen.mul(vx, vx), gen.mul(vy, vy))})", "n")
    _positive(gen, dist)
    d = gen.num(step.params["offset"])
    t2 = gen.let(f"({dist} - {d}) * ({dist} + {d})", "q")
    gen.bail_unless(f"_min({t2}, None) >= 0.0")
    t = gen.let(f"_sqrt({t2})", "h")
    ux, uy = gen.let(f"{vx} / {dist}", "c"), gen.let(f"{vy} / {dist}", "s")
    p = gen.let(f"{d} * {d} / {dist}", "p")
    q = gen.let(f"{d} * {t} / {dist}", "q")
    x, y = _turned(gen, p, q, ux, uy, gen.side(step, step.params["branch"] == "left"))
    gen.put_point(step.outputs[0], gen.add(ax, x), gen.add(ay, y))


@template("equal_velocity_point", python=False)
def _equal_velocity_point(gen: Gen, step: Step) -> None:
    # Iij from the velocities (Sec. 3.12): with u_k = V_Pk - ω_k k × P_k (the image's pole
    # cancels), the homogeneous point (k × (u_i - u_j), ω_i - ω_j); points are read as rows
    # (x, y, w), so the centers' homogeneous writer takes them too
    xs = []
    for p in (step.inputs[0], step.inputs[1], step.inputs[3], step.inputs[4]):
        x, y, w = gen.rows(p)
        if w != "1.0":
            gen.bail_unless(f"_abs({w}) > 0.0")
        xs.append((_div(gen, x, w), _div(gen, y, w)))
    (pix, piy), (vix, viy), (pjx, pjy), (vjx, vjy) = xs
    wi, wj = gen.scalar(step.inputs[2]), gen.scalar(step.inputs[5])
    # du = (v_i - v_j) - ω_i k × P_i + ω_j k × P_j, with k × (x, y) = (-y, x)
    dx = gen.let(gen.add(gen.sub(gen.sub(vix, vjx), gen.mul(wj, pjy)), gen.mul(wi, piy)), "dx")
    dy = gen.let(gen.add(gen.sub(gen.sub(viy, vjy), gen.mul(wi, pix)), gen.mul(wj, pjx)), "dy")
    dw = gen.let(gen.sub(wi, wj), "w")
    s = gen.num(step.params.get("scale", 1.0))
    sw = gen.mul(s, dw)
    # the largest row scales the point (no square to underflow); zero: no relative motion
    n = gen.let(f"_maximum(_maximum(_abs({dx}), _abs({dy})), _abs({sw}))", "n")
    _positive(gen, n)
    gen.put_rows(step.outputs[0], "point", _div(gen, gen.neg(dy), n), _div(gen, dx, n),
                 _div(gen, dw, n))


# ---- the curvature constructions' circles (Secs. 4.13-4.17), JavaScript only -------------

@template("circumcircle", python=False)
def _circumcircle(gen: Gen, step: Step) -> None:
    # the circle through P, Q, R: with b = Q - P, c = R - P and d = 2 (b × c), the center is
    # P + (c_y |b|² - b_y |c|², b_x |c|² - c_x |b|²) / d; collinear points have none
    p, q, r = step.inputs
    px, py = gen.pt(p)
    bx, by = _diff(gen, p, q)
    cx, cy = _diff(gen, p, r)
    bb = gen.let(gen.add(gen.mul(bx, bx), gen.mul(by, by)), "dd")
    cc = gen.let(gen.add(gen.mul(cx, cx), gen.mul(cy, cy)), "dd")
    d = gen.let(gen.mul("2.0", gen.sub(gen.mul(bx, cy), gen.mul(by, cx))), "d")
    gen.bail_unless(f"_abs({d}) > {lit(gen.tol.angle)} * ({bb} + {cc})")
    ux = gen.let(_div(gen, gen.sub(gen.mul(cy, bb), gen.mul(by, cc)), d), "x")
    uy = gen.let(_div(gen, gen.sub(gen.mul(bx, cc), gen.mul(cx, bb)), d), "y")
    gen.put_rows(step.outputs[0], "circle", gen.add(px, ux), gen.add(py, uy),
                 f"_sqrt({gen.add(gen.mul(ux, ux), gen.mul(uy, uy))})")


@template("other_intersection", python=False)
def _other_intersection(gen: Gen, step: Step) -> None:
    # two circles through P meet again at P's mirror in their line of centers O1 O2
    x1, y1, _ = gen.rows(step.inputs[0])
    x2, y2, _ = gen.rows(step.inputs[1])
    px, py = gen.pt(step.inputs[2])
    ux, uy = gen.let(gen.sub(x2, x1), "dx"), gen.let(gen.sub(y2, y1), "dy")
    uu = gen.let(gen.add(gen.mul(ux, ux), gen.mul(uy, uy)), "dd")
    _positive(gen, uu)
    wx, wy = gen.let(gen.sub(px, x1), "dx"), gen.let(gen.sub(py, y1), "dy")
    k = gen.let(_div(gen, gen.add(gen.mul(wx, ux), gen.mul(wy, uy)), uu), "k")
    # P' = 2 (O1 + k u) - P
    gen.put_point(step.outputs[0], gen.sub(gen.mul("2.0", gen.add(x1, gen.mul(k, ux))), px),
                  gen.sub(gen.mul("2.0", gen.add(y1, gen.mul(k, uy))), py))


@template("second_on_circle", python=False)
def _second_on_circle(gen: Gen, step: Step) -> None:
    # a line through a point P of a circle meets it again at 2 F - P, F the foot of the
    # perpendicular from the circle's center to the line (a, b, c)
    a, b, c = gen.rows(step.inputs[0])
    ox, oy, _ = gen.rows(step.inputs[1])
    px, py = gen.pt(step.inputs[2])
    nn = gen.let(gen.add(gen.mul(a, a), gen.mul(b, b)), "dd")
    _positive(gen, nn)
    s = gen.let(_div(gen, gen.add(gen.add(gen.mul(a, ox), gen.mul(b, oy)), c), nn), "s")
    gen.put_point(step.outputs[0], gen.sub(gen.mul("2.0", gen.sub(ox, gen.mul(a, s))), px),
                  gen.sub(gen.mul("2.0", gen.sub(oy, gen.mul(b, s))), py))


@template("parallelogram", python=False)
def _parallelogram(gen: Gen, step: Step) -> None:
    # complete the parallelogram P, A, G, B: G = A + B - P (finite vertices)
    px, py = gen.pt(step.inputs[0])
    ax, ay = gen.pt(step.inputs[1])
    bx, by = gen.pt(step.inputs[2])
    gen.put_point(step.outputs[0], gen.sub(gen.add(ax, bx), px), gen.sub(gen.add(ay, by), py))


# a disk cam's program and center of curvature (Ch. 6), and an instant center on the
# best-conditioned pair of its lines of centers (Sec. 3.13), the Bresse circle and Γ of any
# posture (Sec. 4.15), Ball's point of any posture (Sec. 4.17): templates of their own modules
from graphkin.construction.ops import ball, bresse, cam_program, kennedy  # noqa: E402, F401
