"""The compiled kernel of each operation that has one: the same arithmetic, bound once."""

from __future__ import annotations

from typing import Any

import numpy as np

from graphkin.construction.ops.runtime import (
    CompileInfo,
    Kernel,
    KernelFactory,
    Runtime,
    _absmax,
    _drawn_join,
    _shape,
    _vmin,
    _zero,
    kernel,
    tangent_cc,
    tangent_lc,
)
from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance


def _pair(v: Any) -> tuple[Any, Any]:
    """A constant pair: two floats, or two arrays for a batch of designs (shape ``(M, 1, 2)``)."""
    a = np.asarray(v, dtype=float)
    if a.ndim == 1:
        return float(a[0]), float(a[1])
    return a[..., 0], a[..., 1]


def _num(v: Any) -> Any:
    """A constant number: a float, or an array for a batch of designs (shape ``(M, 1)``)."""
    a = np.asarray(v, dtype=float)
    return float(a) if a.ndim == 0 else a


@kernel("rigid")
def _k_rigid(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    p, th = step.inputs
    (out,) = step.outputs
    d0, d1 = _pair(np.subtract(step.params["local_q"], step.params["local_p"]))
    offset = float(step.params.get("offset", 0.0))

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(p)
        c, s = rt.cs(th, offset)
        x, y = rt.new_point(out, _shape(ax, c, d0))
        # Q = P + R(θ) d: the rotation (c d0 - s d1, s d0 + c d1); a zero component drops out
        if _zero(d1):
            np.multiply(c, d0, out=x)
            np.multiply(s, d0, out=y)
        elif _zero(d0):
            np.multiply(s, -d1, out=x)
            np.multiply(c, d1, out=y)
        else:
            np.subtract(c * d0, s * d1, out=x)
            np.add(s * d0, c * d1, out=y)
        np.add(x, ax, out=x)
        np.add(y, ay, out=y)

    return run


@kernel("circle")
def _k_circle(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    (center,) = step.inputs
    (out,) = step.outputs
    r = _num(step.params["radius"])

    def run(rt: Runtime) -> None:
        x, y = rt.P(center)
        cx, cy, cr, _ = rt.new_rows(out, 3, _shape(x, y, r), center=True)
        cx[...] = x
        cy[...] = y
        cr[...] = r

    return run


def _turned_into(x: Any, y: Any, p: Any, q: Any, ux: Any, uy: Any, left: bool) -> None:
    """``(x, y) = p u + q k × u`` (``left``) or ``p u - q k × u``: along ``u`` and across it."""
    if left:
        np.subtract(p * ux, q * uy, out=x)
        np.add(p * uy, q * ux, out=y)
    else:
        np.add(p * ux, q * uy, out=x)
        np.subtract(p * uy, q * ux, out=y)


@kernel("intersect_circles", originating=True)
def _k_cc(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    c1, c2 = step.inputs
    (out,) = step.outputs
    left = step.params["branch"] == "left"
    k1, k2 = info.radius.get(c1), info.radius.get(c2)
    la, lr = tol.length_abs, tol.length_rel

    def run(rt: Runtime) -> bool:
        x1, y1 = rt.C(c1)
        x2, y2 = rt.C(c2)
        r1 = k1 if k1 is not None else rt.arr(c1)[..., 2]
        r2 = k2 if k2 is not None else rt.arr(c2)[..., 2]
        dx = x2 - x1
        dy = y2 - y1
        dd = dx * dx + dy * dy
        # along and across the line of centers, in units of its length d:
        # a/d = (d² + r1² - r2²) / 2d², (h/d)² = r1²/d² - (a/d)²
        p = (dd + (r1 * r1 - r2 * r2)) / (2.0 * dd)
        q2 = (r1 * r1) / dd - p * p
        clean = True
        if not _vmin(q2) >= 0.0:
            clean = False
            # tangency: a tiny negative h² from a length error below eps counts as zero
            q2 = tangent_cc(q2, dd, r1, r2, tol=tol)
        q = np.sqrt(q2)
        if not _vmin(dd) > (2.0 * (la + lr * max(_absmax(r1), _absmax(r2)))) ** 2:
            clean = False
            # concentric circles (within tolerance) have no intersection
            dist = np.sqrt(dd)
            scale = np.maximum(np.maximum(r1, r2), dist)
            q = np.where(dist <= la + lr * np.abs(scale), np.nan, q)
        x, y = rt.new_point(out, _shape(dx, x1, x2))
        # C1 + a u ± h k × u with u the unit vector from center 1 to center 2
        _turned_into(x, y, p, q, dx, dy, left)
        np.add(x, x1, out=x)
        np.add(y, y1, out=y)
        # finite inputs, every arc pair meets, no concentric pair: every entry is finite
        return clean

    return run


@kernel("intersect_line_circle", originating=True)
def _k_lc(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    line, c = step.inputs
    (out,) = step.outputs
    behind = step.params["branch"] == "behind"
    kr = info.radius.get(c)

    def run(rt: Runtime) -> bool:
        l0, l1, l2 = rt.rows(line)
        cx, cy = rt.C(c)
        r = kr if kr is not None else rt.arr(c)[..., 2]
        s = l0 * cx + l1 * cy + l2
        h2 = r * r - s * s
        clean = True
        if not _vmin(h2) >= 0.0:
            clean = False
            h2 = tangent_lc(h2, s, r, tol=tol)
        h = np.sqrt(h2)
        x, y = rt.new_point(out, _shape(s, cx, cy))
        # the foot of the perpendicular from the center, then ∓ h along the line (l1, -l0)
        _turned_into(x, y, s, h, l0, l1, not behind)
        np.subtract(cx, x, out=x)
        np.subtract(cy, y, out=y)
        return clean

    return run


@kernel("link_angle")
def _k_link_angle(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    a, b = step.inputs
    (out,) = step.outputs
    dl0, dl1 = _pair(np.subtract(step.params["local_b"], step.params["local_a"]))
    phi = _num(np.arctan2(dl1, dl0))
    cphi, sphi = _num(np.cos(phi)), _num(np.sin(phi))

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(a)
        bx, by = rt.P(b)
        dx = bx if _zero(ax) else bx - ax
        dy = by if _zero(ay) else by - ay
        t = np.arctan2(dy, dx)
        rt.put(out, t if _zero(phi) else t - phi)
        # the direction AB gives cos and sin of the line's angle (not where A == B,
        # whose angle atan2 takes as 0)
        n = np.sqrt(dx * dx + dy * dy)
        if _vmin(n) > 0.0:
            c = dx / n
            s = dy / n
            if not _zero(phi):
                c, s = c * cphi + s * sphi, s * cphi - c * sphi
            rt.trig[out] = (c, s)

    return run


@kernel("angle_along")
def _k_angle_along(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    t_, s_ = step.inputs
    (out,) = step.outputs
    phi = float(step.params["local_angle"])
    sign = float(step.params["sign"])

    def run(rt: Runtime) -> None:
        tx, ty = rt.P(t_)
        sx, sy = rt.P(s_)
        dx = (sx - tx) * sign
        dy = (sy - ty) * sign
        rt.put(out, np.arctan2(dy, dx) - phi)

    return run


@kernel("add_angle")
def _k_add_angle(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    (th,) = step.inputs
    (out,) = step.outputs
    offset = step.params["offset"]

    def run(rt: Runtime) -> None:
        rt.put(out, np.asarray(rt.env[th]) + offset)

    return run


@kernel("join", originating=True)
def _k_join(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    p, q = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> bool:
        env = rt.env
        pa, qa = env[p], env[q]
        if _drawn_join(rt, out, pa, qa):
            return False
        if not (rt.is_unit(p) and rt.is_unit(q)):
            rt.put(out, g.join(pa, qa, tol))
            rt.joins[out] = (pa, qa, env[out])
            return False
        px, py = rt.P(p)
        qx, qy = rt.P(q)
        # the cross product (px, py, 1) × (qx, qy, 1)
        a_, b_, c_, base = rt.new_rows(out, 3, _shape(px, qx))
        np.subtract(py, qy, out=a_)
        np.subtract(qx, px, out=b_)
        np.subtract(px * qy, py * qx, out=c_)
        n = np.sqrt(a_ * a_ + b_ * b_)
        # coincident points: n = |P - Q| within the length tolerance of the larger of |P|, |Q|;
        # as max(|P|, |Q|) <= |Q| + n, none is when n (1 - rel) > abs + rel |Q| everywhere
        far = pa if (np.ndim(px) == 0 and np.ndim(qx) != 0) else qa
        big = _absmax(np.asarray(far, dtype=float)[..., :2])
        clean = True
        if not _vmin(n) * (1.0 - tol.length_rel) > tol.length(2.0 * big):
            clean = False
            scale = np.maximum(np.sqrt(px * px + py * py), np.sqrt(qx * qx + qy * qy))
            n = np.where(n <= tol.length(scale), np.nan, n)
        np.divide(base, n, out=base)
        rt.joins[out] = (pa, qa, env[out])
        return clean

    return run


def _line_through(turned: bool) -> KernelFactory:
    """Kernel factory of the line through a point along or across another line.

    The new line's normal is the given line's ``(a, b)`` (``parallel``) or
    that normal turned a quarter turn, ``(-b, a)`` (``perpendicular``).
    """

    def factory(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
        line, p = step.inputs
        (out,) = step.outputs

        def run(rt: Runtime) -> None:
            a, b, _ = rt.rows(line)
            px, py, pw = rt.rows(p)
            unit = rt.is_unit(p)
            o0, o1, o2, _ = rt.new_rows(out, 3, _shape(a, px))
            if turned:
                np.negative(b, out=o0)
                o1[...] = a
            else:
                o0[...] = a
                o1[...] = b
            # through P: n · P + c = 0
            np.add(o0 * px, o1 * py, out=o2)
            np.negative(o2, out=o2)
            if not unit:
                np.divide(o2, pw, out=o2)

        return run

    return factory


kernel("perpendicular")(_line_through(True))

kernel("parallel")(_line_through(False))


@kernel("meet", originating=True)
def _k_meet(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    l1, l2 = step.inputs
    (out,) = step.outputs
    # |w| <= angle n (ideal) or |w| <= angle (coincident lines), tested on squares with margin
    gate = (tol.angle * (1.0 + 1e-6)) ** 2

    def run(rt: Runtime) -> bool:
        a1, b1, c1 = rt.rows(l1)
        a2, b2, c2 = rt.rows(l2)
        pw = a1 * b2 - b1 * a2
        px = b1 * c2 - c1 * b2
        py = c1 * a2 - a1 * c2
        n2 = px * px + py * py
        if not bool(np.all(pw * pw > gate * np.maximum(n2, 1.0))):
            # somewhere parallel (an ideal point), coincident, or not known (NaN): exactly
            rt.put(out, g.meet(rt.env[l1], rt.env[l2], tol))
            rt.dirty.add(out)
            return False
        x, y = rt.new_point(out, _shape(pw, px, py))
        # a finite point: (px, py, pw) / pw
        np.divide(px, pw, out=x)
        np.divide(py, pw, out=y)
        return True

    return run


def _point_and_vector(ufunc: Any) -> KernelFactory:
    """Kernel factory of a point moved by a vector: ``ufunc`` is np.add or np.subtract."""

    def factory(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
        p, v = step.inputs
        (out,) = step.outputs

        def run(rt: Runtime) -> None:
            ax, ay = rt.P(p)
            vx, vy = rt.V(v)
            x, y = rt.new_point(out, _shape(ax, vx))
            ufunc(ax, vx, out=x)
            ufunc(ay, vy, out=y)

        return run

    return factory

kernel("translate")(_point_and_vector(np.add))

kernel("subtract")(_point_and_vector(np.subtract))


@kernel("vector")
def _k_vector(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    p, q = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        px, py = rt.P(p)
        qx, qy = rt.P(q)
        v0, v1, _ = rt.new_rows(out, 2, _shape(px, qx))
        np.subtract(qx, px, out=v0)
        np.subtract(qy, py, out=v1)

    return run


@kernel("scale_vector")
def _k_scale_vector(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    v, s = step.inputs
    (out,) = step.outputs
    factor = step.params.get("factor", 1.0)

    def run(rt: Runtime) -> None:
        vx, vy = rt.V(v)
        k = rt.arr(s) * factor
        v0, v1, _ = rt.new_rows(out, 2, _shape(vx, k))
        np.multiply(vx, k, out=v0)
        np.multiply(vy, k, out=v1)

    return run


@kernel("similar")
def _k_similar(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel | None:
    a, b = step.inputs
    (out,) = step.outputs
    la = np.asarray(step.params["local_a"], dtype=float)
    lb = np.asarray(step.params["local_b"], dtype=float)
    lp = np.asarray(step.params["local_p"], dtype=float)
    if la.shape[-1:] != (2,) or lb.shape[-1:] != (2,) or lp.shape[-1:] != (2,):
        return None
    zr, zp = lb - la, lp - la
    den = zr[..., 0] ** 2 + zr[..., 1] ** 2
    if not np.all(den != 0.0):
        return None
    # p = a + (b - a) q with the complex ratio q = (P - A) / (B - A) of the link
    # (arrays of shape (M, 1) for a batch of designs)
    qr = _num((zp[..., 0] * zr[..., 0] + zp[..., 1] * zr[..., 1]) / den)
    qi = _num((zp[..., 1] * zr[..., 0] - zp[..., 0] * zr[..., 1]) / den)

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(a)
        bx, by = rt.P(b)
        d0 = bx if _zero(ax) else bx - ax
        d1 = by if _zero(ay) else by - ay
        x, y = rt.new_point(out, _shape(d0, ax, qr))
        np.subtract(d0 * qr, d1 * qi, out=x)
        np.add(d0 * qi, d1 * qr, out=y)
        np.add(x, ax, out=x)
        np.add(y, ay, out=y)

    return run


@kernel("velocity_difference")
def _k_vdiff(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    img, omega, a, x_ = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(a)
        xx, xy_ = rt.P(x_)
        ix, iy = rt.P(img)
        w = rt.arr(omega)
        rx = xx if _zero(ax) else xx - ax
        ry = xy_ if _zero(ay) else xy_ - ay
        x, y = rt.new_point(out, _shape(rx, ix, w))
        # V_X = V_A + ω k × R_XA
        np.multiply(w, ry, out=x)
        np.subtract(ix, x, out=x)
        np.multiply(w, rx, out=y)
        np.add(iy, y, out=y)

    return run


@kernel("acceleration_difference")
def _k_adiff(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    img, omega, alpha, a, x_ = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(a)
        xx, xy_ = rt.P(x_)
        ix, iy = rt.P(img)
        w = rt.arr(omega)
        al = rt.arr(alpha)
        w2 = w * w
        rx = xx if _zero(ax) else xx - ax
        ry = xy_ if _zero(ay) else xy_ - ay
        x, y = rt.new_point(out, _shape(rx, ix, w, al))
        # A_X = A_A + α k × R_XA - ω² R_XA
        np.add(al * ry, w2 * rx, out=x)
        np.subtract(ix, x, out=x)
        np.subtract(al * rx, w2 * ry, out=y)
        np.add(iy, y, out=y)

    return run


def _differences(rt: Runtime, a: str, b: str, ia: str,
                 ib: str) -> tuple[Any, Any, Any, Any]:
    """``R_BA`` and the image difference ``b − a`` as components (a zero term is skipped)."""
    ax, ay = rt.P(a)
    bx, by = rt.P(b)
    iax, iay = rt.P(ia)
    ibx, iby = rt.P(ib)
    return (bx if _zero(ax) else bx - ax, by if _zero(ay) else by - ay,
            ibx if _zero(iax) else ibx - iax, iby if _zero(iay) else iby - iay)


@kernel("angular_rate", originating=True)
def _k_angular_rate(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    a, b, ia, ib = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> bool:
        r0, r1, v0, v1 = _differences(rt, a, b, ia, ib)
        den = r0 * r0 + r1 * r1
        rt.put(out, (r0 * v1 - r1 * v0) / den)
        # finite inputs and two distinct points: a finite rate
        return _vmin(den) > 0.0

    return run


def _normal(sign: float) -> KernelFactory:
    """Kernel factory of ``sign |V|²/|R|² R`` with ``R = C - P``, ``V`` the images' difference.

    ``normal_component`` (``-1``: ``A^n`` toward the center, Eq. 4.7) and
    ``apparent_normal`` (``+1``, Eq. 4.15), inputs ``(P, C, image of P, image of C)``.
    """

    def factory(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
        p, c, ip, ic = step.inputs
        (out,) = step.outputs

        def run(rt: Runtime) -> bool:
            r0, r1, v0, v1 = _differences(rt, p, c, ip, ic)
            den = r0 * r0 + r1 * r1
            k = (v0 * v0 + v1 * v1) / den
            if sign < 0:
                k = -k
            o0, o1, _ = rt.new_rows(out, 2, _shape(k, r0))
            np.multiply(k, r0, out=o0)
            np.multiply(k, r1, out=o1)
            # finite inputs and two distinct points: finite
            return _vmin(den) > 0.0

        return run

    return factory


kernel("normal_component", originating=True)(_normal(-1.0))

kernel("apparent_normal", originating=True)(_normal(1.0))


@kernel("coriolis")
def _k_coriolis(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    omega, ip, ipk = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(ip)
        bx, by = rt.P(ipk)
        w2 = 2 * rt.arr(omega)
        v0 = ax - bx
        v1 = ay - by
        o0, o1, _ = rt.new_rows(out, 2, _shape(w2, v0))
        # 2 ω k × V_rel
        np.multiply(-w2, v1, out=o0)
        np.multiply(w2, v0, out=o1)

    return run


def _k_along(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    """A point a signed distance ``s`` along the direction ``p0 → p1``.

    ``add_along`` (inputs ``p, p0, p1, s``) lays it off from ``p``, ``along_line``
    (inputs ``p0, p1, s``) from ``p0``: from the first input either way.
    """
    p, (p0, p1, s) = step.inputs[0], step.inputs[-3:]
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(p)
        x0, y0 = rt.P(p0)
        x1, y1 = rt.P(p1)
        d0 = x1 - x0
        d1 = y1 - y0
        k = rt.arr(s) / np.sqrt(d0 * d0 + d1 * d1)
        x, y = rt.new_point(out, _shape(ax, d0, k))
        np.multiply(d0, k, out=x)
        np.add(ax, x, out=x)
        np.multiply(d1, k, out=y)
        np.add(ay, y, out=y)

    return run


kernel("add_along", originating=True)(_k_along)

kernel("along_line", originating=True)(_k_along)
