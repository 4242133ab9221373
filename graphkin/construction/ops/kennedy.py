"""``kennedy_center``: an instant center on the best-conditioned pair of its lines of centers.

Kennedy's theorem (Sec. 3.13) puts the center ``Iij`` on the line of centers
of every triangle ``(i, j, k)`` whose centers ``Iik`` and ``Ijk`` are known,
and on the common normal of a direct contact (Sec. 3.14).  Any two of those
lines give ``Iij``; which two meet cleanly depends on the posture (two lines
that meet well at one posture are parallel, or coincide, at another).  The
search of :mod:`graphkin.kinematics.instant_centers.kennedy` chooses them at
the posture it is given; this operation takes *every* candidate line and
chooses at each posture it is evaluated on, by the same measure:

* a line joining two centers ``P`` and ``Q`` is as good as the sine of the
  angle between them as unit homogeneous vectors, in coordinates scaled by
  the mechanism's size ``s`` (``(x/s, y/s, w)``: how far apart they are, or
  how far apart in direction for a center at infinity); a given line (a
  common normal) counts 1; and a line is no better than it has a direction,
  ``|(a, b)|`` of the unit ``(a, b, c/s)`` (the line at infinity has none);
* two lines meet as well as the sine of the angle between them as unit
  vectors ``(a, b, c/s)`` (how far from coincident they are);
* a pair is as good as the least of its three; the best pair is taken, the
  first of equals in the order given (a later pair only when better by more
  than :data:`graphkin.tolerance.VERDICT_REL`: round-off never decides).  Below the angle tolerance
  (:class:`graphkin.tolerance.Tolerance`) no pair is clean and there is no
  answer (NaN; the written-out function returns null).

Two centers of one triangle that coincide (within the length tolerance; at
infinity, in direction) give ``Iij`` at once: all three links move alike
there (as the search takes it, before any meet); the index is then the number
of pairs plus the line's.

With ``pairs`` of one line, ``Iij`` is known to be at infinity (both links
slide on a third: two centers of a triangle at infinity, Fig. 3.27): it is
the point at infinity of the best of its lines.

The outputs are the center (homogeneous), the two lines used (unit normal;
the same line twice at infinity) and the index of the pair used, so the page
draws the lines the posture uses.  The operation is one entry of the table
both writers read (``@template(..., python=False)``): the JavaScript writer
writes the template; the Python writer and the replay call the numpy general
function below, which the template is tested against
(tests/render/test_live_cam_centers.py).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 3.13-3.15 (the Aronhold-Kennedy
theorem, the Kennedy circle), Sec. 3.14 (direct contact: the common normal).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphkin.construction.codegen import Gen, lit, template
from graphkin.construction.ops.registry import op
from graphkin.construction.step import Step
from graphkin.tolerance import VERDICT_REL, Tolerance

__all__: list[str] = []

#: A later pair is taken only when it meets better by more than round-off of the measure
#: (a sine, at most 1): equals, to the last digits, keep the first, on every machine.
_MARGIN = VERDICT_REL

Array = np.ndarray


def _hat(v: Array, scale: float, point: bool) -> Array:
    """A point ``(x/s, y/s, w)`` or a line ``(a, b, c/s)``, as a unit vector."""
    f = np.array([1.0 / scale, 1.0 / scale, 1.0] if point else [1.0, 1.0, 1.0 / scale])
    q = np.asarray(v, dtype=float) * f
    n = np.linalg.norm(q, axis=-1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        return q / n


def _sine(u: Array, v: Array) -> Array:
    s = np.linalg.norm(np.cross(u, v), axis=-1)
    return np.where(np.isfinite(s), s, 0.0)


@op("kennedy_center")
def _kennedy_center(*ins: Array, tol: Tolerance, lines: Any, pairs: Any,
                    scale: float) -> tuple[Array, ...]:
    """``Iij`` on the best-conditioned pair of its candidate lines (module docstring).

    Parameters
    ----------
    *ins : arrays
        The centers and given lines the candidate lines are made of (homogeneous).
    lines : tuple of tuple of int
        Each candidate line: ``(k, m)`` the line joining inputs k and m, or
        ``(k,)`` the given line input k.
    pairs : tuple of tuple of int
        The candidate pairs of lines ``(a, b)``, in order of preference; ``(a,)``
        for a center at infinity on line a.
    scale : float
        The mechanism's size.

    Returns
    -------
    (center, line, line, index)
        NaN where no pair is clean.
    """
    shape = np.broadcast_shapes(*(np.shape(a)[:-1] for a in ins))
    rows, quals = [], []
    for spec in lines:
        if len(spec) == 1:
            ln = np.broadcast_to(np.asarray(ins[spec[0]], dtype=float), (*shape, 3))
            q = np.ones(shape)
        else:
            p, r = (np.asarray(ins[k], dtype=float) for k in spec)
            ln = np.broadcast_to(np.cross(p, r), (*shape, 3))
            q = np.broadcast_to(_sine(_hat(p, scale, True), _hat(r, scale, True)), shape)
        n = np.hypot(ln[..., 0], ln[..., 1])
        rows.append(ln / np.where(n > 0.0, n, 1.0)[..., None])
        # and as good as it has a direction: the line at infinity (two centers at infinity
        # joined) has none
        with np.errstate(invalid="ignore", divide="ignore"):
            fin = n / np.linalg.norm(ln * np.array([1.0, 1.0, 1.0 / scale]), axis=-1)
        quals.append(np.minimum(q, np.where(np.isfinite(fin), fin, 0.0)))
    best = np.full(shape, -1.0 - _MARGIN)
    out = np.full((*shape, 3), np.nan)
    la, lb = np.full((*shape, 3), np.nan), np.full((*shape, 3), np.nan)
    index = np.full(shape, np.nan)
    for k, pair in enumerate(pairs):
        a = rows[pair[0]]
        b = rows[pair[-1]]
        if len(pair) == 1:
            pt = np.stack([a[..., 1], -a[..., 0], np.zeros(shape)], axis=-1)
            q = quals[pair[0]]
        else:
            pt = np.cross(a, b)
            q = np.minimum(np.minimum(quals[pair[0]], quals[pair[1]]),
                           _sine(_hat(a, scale, False), _hat(b, scale, False)))
        take = q > best + _MARGIN
        best = np.where(take, q, best)
        out = np.where(take[..., None], pt, out)
        la = np.where(take[..., None], a, la)
        lb = np.where(take[..., None], b, lb)
        index = np.where(take, float(k), index)
    ok = best > tol.angle
    # two centers of a triangle that coincide (within the length tolerance; at infinity, in
    # direction): all three links move alike there, and Iij is that point (as the search
    # takes it first); the first such triangle in the order given
    for m, spec in reversed(list(enumerate(lines))):
        if len(spec) != 2:
            continue
        p, r = (np.broadcast_to(np.asarray(ins[x], dtype=float), (*shape, 3)) for x in spec)
        same = _coincide(p, r, tol, scale)
        ok = ok | same
        out = np.where(same[..., None], p, out)
        la = np.where(same[..., None], rows[m], la)
        lb = np.where(same[..., None], rows[m], lb)
        index = np.where(same, float(len(pairs) + m), index)
    n = np.linalg.norm(out, axis=-1, keepdims=True)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = out / n
    bad = ~ok[..., None]
    return (np.where(bad, np.nan, out), np.where(bad, np.nan, la), np.where(bad, np.nan, lb),
            np.where(ok, index, np.nan))


def _coincide(p: Array, r: Array, tol: Tolerance, scale: float) -> Array:
    """Two homogeneous points are one: within the length tolerance, or one direction at infinity."""
    pn, rn = np.hypot(p[..., 0], p[..., 1]), np.hypot(r[..., 0], r[..., 1])
    pw, rw = p[..., 2], r[..., 2]
    ideal = (np.abs(pw) <= tol.angle * pn) & (np.abs(rw) <= tol.angle * rn)
    cross = np.abs(p[..., 0] * r[..., 1] - p[..., 1] * r[..., 0])
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        d = np.hypot(p[..., 0] / pw - r[..., 0] / rw, p[..., 1] / pw - r[..., 1] / rw)
    return np.where(ideal, cross <= tol.angle * pn * rn,
                    (pw != 0.0) & (rw != 0.0) & (d <= tol.length(scale)))


def _min2(gen: Gen, a: str, b: str) -> str:
    return gen.let(gen.where(f"{a} < {b}", a, b), "q")


@template("kennedy_center", python=False)
def _kennedy_center_js(gen: Gen, step: Step) -> None:
    # the same measure as the numpy above: the joins' and the meets' sines in coordinates
    # scaled by the mechanism's size, the best pair taken (the first of equals)
    s = gen.num(step.params["scale"])
    s2 = gen.let(f"{s} * {s}", "s")
    rows: list[tuple[str, str, str]] = []
    quals: list[str] = []
    for spec in step.params["lines"]:
        if len(spec) == 1:
            a, b, c = gen.rows(step.inputs[spec[0]])
            q = "1.0"
        else:
            px, py, pw = gen.rows(step.inputs[spec[0]])
            qx, qy, qw = gen.rows(step.inputs[spec[1]])
            a = gen.let(gen.sub(gen.mul(py, qw), gen.mul(pw, qy)), "a")
            b = gen.let(gen.sub(gen.mul(pw, qx), gen.mul(px, qw)), "b")
            c = gen.let(gen.sub(gen.mul(px, qy), gen.mul(py, qx)), "c")
            # (x/s, y/s, w) of P and Q: their cross product is (a/s, b/s, c/s²)
            npn = gen.let(f"_sqrt(({px} * {px} + {py} * {py}) / {s2} + {pw} * {pw})", "n")
            nqn = gen.let(f"_sqrt(({qx} * {qx} + {qy} * {qy}) / {s2} + {qw} * {qw})", "n")
            q = gen.let(f"_sqrt(({a} * {a} + {b} * {b}) / {s2} + {c} * {c} / ({s2} * {s2})) / "
                        f"({npn} * {nqn})", "q")
        n0 = gen.let(f"_sqrt({a} * {a} + {b} * {b})", "n")
        n = gen.let(gen.where(f"{n0} > 0.0", n0, "1.0"), "n")
        rows.append((gen.let(f"{a} / {n}", "a"), gen.let(f"{b} / {n}", "b"),
                     gen.let(f"{c} / {n}", "c")))
        # and as good as it has a direction (none for the line at infinity)
        fin = gen.let(gen.where(f"{n0} > 0.0", f"{n0} / _sqrt({n0} * {n0} + {c} * {c} / {s2})",
                                "0.0"), "q")
        quals.append(_min2(gen, q, fin))
    best = None
    chosen: list[str] = []
    for k, pair in enumerate(step.params["pairs"]):
        a1, b1, c1 = rows[pair[0]]
        a2, b2, c2 = rows[pair[-1]]
        if len(pair) == 1:
            x, y, w = b1, gen.neg(a1), "0.0"
            q = quals[pair[0]]
        else:
            x = gen.let(gen.sub(gen.mul(b1, c2), gen.mul(c1, b2)), "x")
            y = gen.let(gen.sub(gen.mul(c1, a2), gen.mul(a1, c2)), "y")
            w = gen.let(gen.sub(gen.mul(a1, b2), gen.mul(b1, a2)), "w")
            # (a, b, c/s) of each line: their cross product is (x/s, y/s, w)
            n1 = gen.let(f"_sqrt({a1} * {a1} + {b1} * {b1} + {c1} * {c1} / {s2})", "n")
            n2 = gen.let(f"_sqrt({a2} * {a2} + {b2} * {b2} + {c2} * {c2} / {s2})", "n")
            # a line of no direction (two coincident centers joined) counts 0, never NaN
            nn = gen.let(f"{n1} * {n2}", "n")
            sine = gen.let(gen.where(f"{nn} > 0.0", f"_sqrt(({x} * {x} + {y} * {y}) / {s2} + "
                                     f"{w} * {w}) / {nn}", "0.0"), "q")
            q = _min2(gen, _min2(gen, quals[pair[0]], quals[pair[1]]), sine)
        vals = [x, y, w, a1, b1, c1, a2, b2, c2, lit(float(k))]
        if best is None:
            best, chosen = q, vals
            continue
        take = gen.let(f"{q} > {best} + {lit(_MARGIN)}", "ok")
        chosen = [gen.let(gen.where(take, v, old), "t") for v, old in zip(vals, chosen)]
        best = gen.let(gen.where(take, q, best), "q")
    assert best is not None
    ok = gen.let(f"{best} > {lit(gen.tol.angle)}", "ok")
    # two centers of a triangle that coincide: Iij is that point (the numpy's _coincide)
    tol = gen.tol
    for m, spec in reversed(list(enumerate(step.params["lines"]))):
        if len(spec) != 2:
            continue
        px, py, pw = gen.rows(step.inputs[spec[0]])
        qx, qy, qw = gen.rows(step.inputs[spec[1]])
        pn = gen.let(f"_sqrt({px} * {px} + {py} * {py})", "n")
        qn = gen.let(f"_sqrt({qx} * {qx} + {qy} * {qy})", "n")
        ang = lit(tol.angle)
        ideal = f"(_abs({pw}) <= {ang} * {pn} && _abs({qw}) <= {ang} * {qn})"
        cross = f"_abs({px} * {qy} - {py} * {qx}) <= {ang} * {pn} * {qn}"
        dx = f"({px} / {pw} - {qx} / {qw})"
        dy = f"({py} / {pw} - {qy} / {qw})"
        near = (f"{pw} !== 0.0 && {qw} !== 0.0 && _sqrt({dx} * {dx} + {dy} * {dy}) <= "
                f"{lit(tol.length_abs)} + {lit(tol.length_rel)} * {s}")
        same = gen.let(gen.where(ideal, cross, f"({near})"), "ok")
        ok = gen.let(f"{ok} || {same}", "ok")
        vals = [px, py, pw, *rows[m], *rows[m], lit(float(len(step.params["pairs"]) + m))]
        chosen = [gen.let(gen.where(same, v, old), "t") for v, old in zip(vals, chosen)]
    gen.bail_unless(ok)
    x, y, w = chosen[:3]
    n = gen.let(f"_sqrt({x} * {x} + {y} * {y} + {w} * {w})", "n")
    gen.put_rows(step.outputs[0], "point", *(gen.let(f"{v} / {n}", "x") for v in (x, y, w)))
    gen.put_rows(step.outputs[1], "line", *chosen[3:6])
    gen.put_rows(step.outputs[2], "line", *chosen[6:9])
    gen.put_scalar(step.outputs[3], chosen[9])
