"""A disk cam's program and its center of curvature as operations of the one table (Ch. 6).

Two operations, each one template (:data:`~graphkin.construction.codegen.TEMPLATES`)
that the Python writer (:mod:`graphkin.construction.codegen`) and the
JavaScript writer (:mod:`graphkin.construction.jsgen`) both read, so that the
live page of a cam mechanism turns the cam with the arithmetic Python checks:

* ``cam_program`` (Secs. 6.3-6.8): from the cam link's angle θ2, the cam angle
  ``Θ = s(θ2 − shift)`` taken into [0, 2π), and the follower's displacement
  ``Y`` and kinematic coefficients ``y'``, ``y''`` (Eqs. 6.1-6.3) of the
  segment Θ falls in: ``Y = Y_k + h f(u)``, ``y' = h f'(u)/β``,
  ``y'' = h f''(u)/β²`` with ``u = (Θ − Θ_k)/β`` and ``f`` the segment's
  standard motion (Eqs. 6.5-6.25) or a polynomial in ``u``;
* ``cam_center`` (Secs. 6.9-6.10, 4.7): for a knife-edge or roller follower
  (translating or oscillating), the trace point, its Θ-derivatives turned into
  the cam's frame, the pitch curve's radius of curvature (Eq. 6.37), its
  center of curvature ``K`` on the cam (the equivalent linkage's pin), the
  coupler's length ``|ρ|``, the trace point ``T`` and the contact point in the
  mechanism's frame.  A pitch curve that is straight there (``|ρ|`` beyond
  10⁶ times the cam's size, as :func:`graphkin.cams.equivalent.equivalent_linkage`
  refuses it) has no center: the function returns None (Python) or null
  (JavaScript).

The parameters are plain numbers (the construction layer knows no cam): the
cam layer writes them (:mod:`graphkin.cams.turning`).  Each operation's
general function (:data:`~graphkin.construction.ops.registry.OPS`, for the
replay) runs the same template, compiled: there is one source of the
arithmetic.  The independent check is :mod:`graphkin.cams.analytic`
(tests/construction/test_cam_program.py).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 6.3-6.8 (Eqs. 6.1-6.25), 6.10
(Eqs. 6.32-6.37), 4.7 (the equivalent linkage).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from graphkin.construction.codegen import Gen, lit, template
from graphkin.construction.ops.registry import op
from graphkin.construction.step import Step
from graphkin.tolerance import VERDICT_REL, Tolerance

__all__ = ["MOTIONS", "STRAIGHT"]

Array = np.ndarray

STRAIGHT = 1e6
"""A radius of curvature beyond this many times the cam's size is a straight surface
(the bound of :func:`graphkin.cams.equivalent.equivalent_linkage`)."""

_PI = math.pi
Shape = Callable[[Gen, str, Sequence[float]], tuple[str, str, str]]


def _cs(gen: Gen, k: float, u: str) -> tuple[str, str]:
    a = gen.let(f"{lit(k)} * {u}", "w")
    return gen.let(f"_cos({a})", "c"), gen.let(f"_sin({a})", "s")


def _harmonic(gen: Gen, u: str, _: Sequence[float]) -> tuple[str, str, str]:
    c, s = _cs(gen, _PI, u)             # Eq. (6.12)
    return f"0.5 * (1.0 - {c})", f"{lit(0.5 * _PI)} * {s}", f"{lit(0.5 * _PI ** 2)} * {c}"


def _cycloidal(gen: Gen, u: str, _: Sequence[float]) -> tuple[str, str, str]:
    c, s = _cs(gen, 2 * _PI, u)         # Eq. (6.13)
    return f"{u} - {s} / {lit(2 * _PI)}", f"1.0 - {c}", f"{lit(2 * _PI)} * {s}"


def _half_harmonic_start(gen: Gen, u: str, _: Sequence[float]) -> tuple[str, str, str]:
    k = _PI / 2                          # Eq. (6.18)
    c, s = _cs(gen, k, u)
    return f"1.0 - {c}", f"{lit(k)} * {s}", f"{lit(k * k)} * {c}"


def _half_harmonic_end(gen: Gen, u: str, _: Sequence[float]) -> tuple[str, str, str]:
    k = _PI / 2                          # Eq. (6.19)
    c, s = _cs(gen, k, u)
    return s, f"{lit(k)} * {c}", f"{lit(-k * k)} * {s}"


def _half_cycloidal_start(gen: Gen, u: str, _: Sequence[float]) -> tuple[str, str, str]:
    c, s = _cs(gen, _PI, u)             # Eq. (6.22)
    return f"{u} - {s} / {lit(_PI)}", f"1.0 - {c}", f"{lit(_PI)} * {s}"


def _half_cycloidal_end(gen: Gen, u: str, _: Sequence[float]) -> tuple[str, str, str]:
    c, s = _cs(gen, _PI, u)             # Eq. (6.23)
    return f"{u} + {s} / {lit(_PI)}", f"1.0 + {c}", f"{lit(-_PI)} * {s}"


def _parabolic(gen: Gen, u: str, _: Sequence[float]) -> tuple[str, str, str]:
    sel = gen.helper("select")           # Eqs. (6.5)-(6.6): two parabolas meeting at mid-rise
    first = f"{u} <= 0.5"
    v = gen.let(f"1.0 - {u}", "v")
    return (f"{sel}({first}, 2.0 * {u} * {u}, 1.0 - 2.0 * {v} * {v})",
            f"{sel}({first}, 4.0 * {u}, 4.0 * {v})", f"{sel}({first}, 4.0, -4.0)")


def _horner(gen: Gen, u: str, coef: Sequence[float]) -> str:
    out = gen.num(coef[-1])
    for c in reversed(coef[:-1]):
        out = gen.let(f"{gen.num(c)} + {u} * {out}", "p")
    return out


def _poly(gen: Gen, u: str, coef: Sequence[float]) -> tuple[str, str, str]:
    # f = Σ c_i u^i (Eqs. 6.14, 6.17 and the 3-4-5 polynomial), f' and f'' term by term
    c0 = [float(c) for c in coef] + [0.0, 0.0, 0.0]
    c1 = [i * c0[i] for i in range(1, len(c0))]
    c2 = [i * c1[i] for i in range(1, len(c1))]
    return _horner(gen, u, c0), _horner(gen, u, c1), _horner(gen, u, c2)


def _pieces(gen: Gen, u: str, rows: Sequence[float]) -> tuple[str, str, str]:
    # a piecewise "acceleration" integrated in closed form (the modified trapezoid), 8 numbers
    # a piece: x0, ref, ω, A, B, C, c0, c1 (graphkin.cams.motions.piece_rows)
    sel = gen.helper("select")
    out: tuple[str, ...] | None = None
    for k in range(0, len(rows), 8):
        x0, ref, w, a, b, c, c0, c1 = (gen.num(v) for v in rows[k:k + 8])
        t = gen.let(f"{u} - {ref}", "t")
        sn, cs = gen.let(f"_sin({w} * {t})", "s"), gen.let(f"_cos({w} * {t})", "c")
        v = f"(-{a} * {cs} + {b} * {sn}) / {w} + {c} * {t}"
        s = f"-({a} * {sn} + {b} * {cs}) / ({w} * {w}) + 0.5 * {c} * {t} * {t}"
        piece = (f"{c0} + {c1} * {u} + {s}", f"{c1} + {v}", f"{a} * {sn} + {b} * {cs} + {c}")
        out = piece if out is None else tuple(
            gen.let(f"{sel}({u} >= {x0}, {n}, {o})", "f") for n, o in zip(piece, out))
    assert out is not None and len(out) == 3
    return out[0], out[1], out[2]


MOTIONS: dict[str, Shape] = {
    "dwell": lambda gen, u, c: ("0.0", "0.0", "0.0"),
    "uniform": lambda gen, u, c: (u, "1.0", "0.0"),
    "parabolic": _parabolic,
    "harmonic": _harmonic,
    "cycloidal": _cycloidal,
    "half_harmonic_start": _half_harmonic_start,
    "half_harmonic_end": _half_harmonic_end,
    "half_cycloidal_start": _half_cycloidal_start,
    "half_cycloidal_end": _half_cycloidal_end,
    "poly": _poly,
    "pieces": _pieces,
}
"""The shapes ``f(u), f'(u), f''(u)`` a segment of ``cam_program`` may have, as expressions."""


@template("cam_program")
def _cam_program(gen: Gen, step: Step) -> None:
    """Θ, Y, y', y'' at the cam link's angle (params ``s``, ``shift``, ``segments``).

    ``segments``: rows ``(motion, Θ_k, β, Y_k, h, coefficients)`` in order from
    Θ = 0; a boundary angle belongs to the segment that starts there (as
    :meth:`graphkin.cams.program.Program.evaluate`).
    """
    p = step.params
    sel, floor = gen.helper("select"), gen.helper("floor")
    th2 = gen.scalar(step.inputs[0])
    t = gen.let(f"{lit(float(p['s']))} * ({th2} - {gen.num(p['shift'])})", "t")
    two = lit(2 * _PI)
    th = gen.let(f"{t} - {two} * {floor}({t} / {two})", "th")
    out: tuple[str, str, str] | None = None
    for motion, start, beta, base, h, coef in p["segments"]:
        if motion not in MOTIONS:
            raise ValueError(f"cam_program: no motion {motion!r}")
        a, b = gen.num(start), gen.num(beta)
        x = gen.let(f"({th} - {a}) / {b}", "u")
        u = gen.let(f"{sel}({x} < 0.0, 0.0, {sel}({x} > 1.0, 1.0, {x}))", "u")
        f0, f1, f2 = MOTIONS[motion](gen, u, coef)
        hh, y0 = gen.num(h), gen.num(base)
        seg = (gen.let(f"{y0} + {hh} * ({f0})", "Y"), gen.let(f"{hh} * ({f1}) / {b}", "y"),
               gen.let(f"{hh} * ({f2}) / ({b} * {b})", "y"))
        out = seg if out is None else tuple(        # type: ignore[assignment]
            gen.let(f"{sel}({th} >= {a}, {n}, {o})", "y") for n, o in zip(seg, out))
    assert out is not None
    gen.put_scalar(step.outputs[0], th)
    for lab, ex in zip(step.outputs[1:], out):
        gen.put_scalar(lab, ex)


def _mul(a: tuple[str, str], b: tuple[str, str]) -> tuple[str, str]:
    """The complex product as two real expressions."""
    (ar, ai), (br, bi) = ((f"({x})" for x in a), (f"({x})" for x in b))
    return (f"({ar} * {br} - {ai} * {bi})", f"({ar} * {bi} + {ai} * {br})")


def _lets(gen: Gen, z: tuple[str, str], hint: str) -> tuple[str, str]:
    return gen.let(z[0], hint), gen.let(z[1], hint)


@template("cam_center")
def _cam_center(gen: Gen, step: Step) -> None:
    """The pitch curve's center of curvature on the cam, ``|ρ|``, ``T`` and the contact.

    Inputs ``Θ, Y, y', y''`` (``cam_program``'s outputs); outputs ``K`` (the
    center of curvature in the cam link's own coordinates from the cam's
    center, mechanism units), ``R`` (``|ρ|``, mechanism units), ``T`` and
    ``C`` (the trace and contact points in the mechanism's frame) and ``ρ``
    (the pitch curve's signed radius of curvature, cam units, positive convex;
    the profile's is ``ρ − r_r``, Eq. 6.38).
    """
    p = step.params
    th, Y, y1, y2 = (gen.scalar(i) for i in step.inputs)
    s = float(p["s"])
    if p["follower"] == "oscillating_flat":
        _flat_center(gen, step, th, Y, y1, y2)
        return
    if p["follower"] == "translating_flat":
        _translating_flat_center(gen, step, th, Y, y1, y2)
        return
    if p["follower"] == "oscillating":
        sig, arm = float(p["sig"]), gen.num(p["arm"])
        th4 = gen.let(f"{gen.num(p['arm0'])} + {lit(sig)} * {Y}", "a")
        ex, ey = gen.let(f"_cos({th4})", "c"), gen.let(f"_sin({th4})", "s")
        # P = O4 + r4 e^{iθ4}, P' = i r4 σ y' e^{iθ4}, P'' = r4 e^{iθ4} (i σ y'' − y'²)
        pf = _lets(gen, (f"{gen.num(p['pivot'][0])} + {arm} * {ex}",
                         f"{gen.num(p['pivot'][1])} + {arm} * {ey}"), "p")
        k1 = gen.let(f"{arm} * {lit(sig)} * {y1}", "k")
        pf1 = _lets(gen, (f"-{k1} * {ey}", f"{k1} * {ex}"), "p")
        q = (gen.let(f"-{arm} * {y1} * {y1}", "k"), gen.let(f"{arm} * {lit(sig)} * {y2}", "k"))
        pf2 = _lets(gen, _mul(q, (ex, ey)), "p")
    else:
        # P = ε + i(Y0 + Y), P' = i y', P'' = i y'' (Fig. 6.27)
        pf = (gen.num(p["offset"]), gen.let(f"{gen.num(p['y0'])} + {Y}", "p"))
        pf1, pf2 = ("0.0", y1), ("0.0", y2)
    # into the cam's frame, r = e^{−isΘ}: p = r P, p' = r (P' − i s P), p'' = r (P'' − 2is P' − P)
    c, sn = gen.let(f"_cos({th})", "c"), gen.let(f"{lit(s)} * _sin({th})", "s")
    r = (c, f"(-{sn})")
    q1 = (f"{pf1[0]} + {lit(s)} * {pf[1]}", f"{pf1[1]} - {lit(s)} * {pf[0]}")
    q2 = (f"{pf2[0]} + {lit(2 * s)} * {pf1[1]} - {pf[0]}",
          f"{pf2[1]} - {lit(2 * s)} * {pf1[0]} - {pf[1]}")
    p0 = _lets(gen, _mul(r, pf), "q")
    p1 = _lets(gen, _mul(r, q1), "q")
    p2 = _lets(gen, _mul(r, q2), "q")
    w = gen.let(f"_sqrt({p1[0]} * {p1[0]} + {p1[1]} * {p1[1]})", "w")
    curl = gen.let(f"{p1[0]} * {p2[1]} - {p1[1]} * {p2[0]}", "k")     # Im(p̄' p'')
    w3 = gen.let(f"{w} * {w} * {w}", "w")
    # a straight pitch curve here: no center of curvature (Eq. 6.37's ρ infinite)
    gen.bail_unless(f"_min({w3}, None) < {lit(STRAIGHT)} * {gen.num(p['size'])} * "
                    f"_min(_abs({curl}), None)")
    rho = gen.let(f"{lit(-s)} * {w3} / {curl}", "rho")                  # Eq. (6.37), convex > 0
    # the inward normal −i s p'/|p'|; the center p + ρ n; the contact p + r_r n (Eq. 6.36)
    n = (gen.let(f"{lit(s)} * {p1[1]} / {w}", "n"), gen.let(f"{lit(-s)} * {p1[0]} / {w}", "n"))
    scale, rr = gen.num(p["scale"]), gen.num(p["roller"])
    kx = gen.let(f"{p0[0]} + {rho} * {n[0]}", "kx")
    ky = gen.let(f"{p0[1]} + {rho} * {n[1]}", "ky")
    # a dwell: the pitch curve is a circle about the cam's center, its center of curvature
    # that center itself, not a round-off away (Kennedy's line through both has no direction)
    sel = gen.helper("select")
    at = gen.let(f"_sqrt({kx} * {kx} + {ky} * {ky}) <= {lit(VERDICT_REL)} * {gen.num(p['size'])}",
                 "at")
    gen.put_point(step.outputs[0], f"{sel}({at}, 0.0, {kx} * {scale})",
                  f"{sel}({at}, 0.0, {ky} * {scale})")
    gen.put_scalar(step.outputs[1], f"_abs({rho}) * {scale}")
    # the mechanism's frame: O2 + e^{i(axis − 90°)} scale · (fixed cam frame)
    ax, ay = gen.num(p["rot"][0]), gen.num(p["rot"][1])
    ox, oy = gen.num(p["o2"][0]), gen.num(p["o2"][1])
    nf = _mul((c, sn), n)                                                # e^{isΘ} n
    cf = (f"({pf[0]} + {rr} * {nf[0]})", f"({pf[1]} + {rr} * {nf[1]})")
    for lab, z in ((step.outputs[2], pf), (step.outputs[3], cf)):
        m = _mul((ax, ay), z)
        gen.put_point(lab, f"{ox} + {scale} * {m[0]}", f"{oy} + {scale} * {m[1]}")
    gen.put_scalar(step.outputs[4], rho)


def _translating_flat_center(gen: Gen, step: Step, th: str, Y: str, y1: str, y2: str) -> None:
    """``cam_center`` for a translating flat face (Sec. 6.9, Eqs. 6.26-6.27).

    In the fixed cam frame the contact is ``(s y', R0 + Y)`` (Eq. 6.26), the
    profile's radius of curvature ``ρ = R0 + Y + y''`` (Eq. 6.27) and its center
    ``K = (s y', −y'')``, turned into the cam's own frame by ``e^{−isΘ}``.
    Outputs as for an oscillating flat face: the second is the slot's offset
    ``−ρ`` along the follower's own x (its guide), and the third the slot's
    start ``F<f>a`` (the follower's point ``(−ρ, size)``,
    :func:`graphkin.cams.equivalent.equivalent_linkage`).
    """
    p = step.params
    s = float(p["s"])
    size = gen.num(p["size"])
    pp = gen.let(f"{gen.num(p['y0'])} + {Y}", "p")
    rho = gen.let(f"{pp} + {y2}", "rho")
    c, sn = gen.let(f"_cos({th})", "c"), gen.let(f"{lit(s)} * _sin({th})", "s")
    kf = (gen.let(f"{lit(s)} * {y1}", "k"), gen.let(f"-{y2}", "k"))
    kz = _lets(gen, _mul((c, f"(-{sn})"), kf), "k")                      # e^{−isΘ} K
    scale = gen.num(p["scale"])
    sel = gen.helper("select")
    at = gen.let(f"_sqrt({kz[0]} * {kz[0]} + {kz[1]} * {kz[1]}) <= {lit(VERDICT_REL)} * "
                 f"{size}", "at")
    gen.put_point(step.outputs[0], f"{sel}({at}, 0.0, {kz[0]} * {scale})",
                  f"{sel}({at}, 0.0, {kz[1]} * {scale})")
    gen.put_scalar(step.outputs[1], f"(-{rho}) * {scale}")
    ax, ay = gen.num(p["rot"][0]), gen.num(p["rot"][1])
    o2x, o2y = gen.num(p["o2"][0]), gen.num(p["o2"][1])
    start = (f"({gen.num(p['offset'])} - {size})", f"({pp} - {rho})")
    cf = (kf[0], pp)
    for lab, z in ((step.outputs[2], start), (step.outputs[3], cf)):
        m = _mul((ax, ay), z)
        gen.put_point(lab, f"{o2x} + {scale} * {m[0]}", f"{o2y} + {scale} * {m[1]}")
    gen.put_scalar(step.outputs[4], rho)


def _flat_center(gen: Gen, step: Step, th: str, Y: str, y1: str, y2: str) -> None:
    """``cam_center`` for an oscillating flat face (Sec. 6.9, the profile as an envelope).

    The face's line in the fixed cam frame is ``n·X = p`` with ``n = σ i e^{iθ4}``,
    ``θ4 = θ4₀ + σY`` and ``p = σ n₀·O4 − e`` (``e`` the face's offset); in the cam's
    own frame its normal turns at ``a' = σy' − s``.  The envelope's contact is
    ``(p + i p'/a') N`` and its radius of curvature ``ρ = p + (p''a' − p'a'')/a'³``
    (``N = e^{−isΘ} n``; the profile's, not the pitch curve's); the center of
    curvature ``K = (p + i p'/a' − ρ) N``.  Outputs as for a roller, but the second
    is the slot's offset ``y = −σ(e + ρ)`` in the follower's own coordinates
    (:func:`graphkin.cams.equivalent.equivalent_linkage`) and the third the
    follower's point on that line at its pivot's foot, ``O4 + i y e^{iθ4}``.
    """
    p = step.params
    s, sig = float(p["s"]), float(p["sig"])
    th4 = gen.let(f"{gen.num(p['arm0'])} + {lit(sig)} * {Y}", "a")
    ex, ey = gen.let(f"_cos({th4})", "c"), gen.let(f"_sin({th4})", "s")
    ox, oy = gen.num(p["pivot"][0]), gen.num(p["pivot"][1])
    # n = i e^{iθ4}: n·O4 and (i n)·O4 = −e^{iθ4}·O4
    d0 = gen.let(f"-{ey} * {ox} + {ex} * {oy}", "d")
    d1 = gen.let(f"-{ex} * {ox} - {ey} * {oy}", "d")
    t1, t2 = gen.let(f"{lit(sig)} * {y1}", "t"), gen.let(f"{lit(sig)} * {y2}", "t")
    pp = gen.let(f"{lit(sig)} * {d0} - {gen.num(p['face_offset'])}", "p")
    p1 = gen.let(f"{lit(sig)} * {d1} * {t1}", "p")
    p2 = gen.let(f"{lit(sig)} * ({d1} * {t2} - {d0} * {t1} * {t1})", "p")
    a1 = gen.let(f"{t1} - {lit(s)}", "a")
    num = gen.let(f"{p2} * {a1} - {p1} * {t2}", "k")
    a3 = gen.let(f"{a1} * {a1} * {a1}", "a")
    # a straight profile here (ρ beyond 10⁶ sizes): no center of curvature
    gen.bail_unless(f"_min(_abs({num}), None) < {lit(STRAIGHT)} * {gen.num(p['size'])} * "
                    f"_min(_abs({a3}), None)")
    rho = gen.let(f"{pp} + {num} / {a3}", "rho")
    pa = gen.let(f"{p1} / {a1}", "p")
    nf = (gen.let(f"{lit(-sig)} * {ey}", "n"), gen.let(f"{lit(sig)} * {ex}", "n"))
    c, sn = gen.let(f"_cos({th})", "c"), gen.let(f"{lit(s)} * _sin({th})", "s")
    big = _lets(gen, _mul((c, f"(-{sn})"), nf), "q")                    # N = e^{−isΘ} n
    kz = _lets(gen, _mul((f"{pp} - {rho}", pa), big), "k")
    scale = gen.num(p["scale"])
    sel = gen.helper("select")
    at = gen.let(f"_sqrt({kz[0]} * {kz[0]} + {kz[1]} * {kz[1]}) <= {lit(VERDICT_REL)} * "
                 f"{gen.num(p['size'])}", "at")
    gen.put_point(step.outputs[0], f"{sel}({at}, 0.0, {kz[0]} * {scale})",
                  f"{sel}({at}, 0.0, {kz[1]} * {scale})")
    yy = gen.let(f"{lit(-sig)} * ({gen.num(p['face_offset'])} + {rho})", "y")
    gen.put_scalar(step.outputs[1], f"{yy} * {scale}")
    ax, ay = gen.num(p["rot"][0]), gen.num(p["rot"][1])
    o2x, o2y = gen.num(p["o2"][0]), gen.num(p["o2"][1])
    foot = (f"({ox} - {yy} * {ey})", f"({oy} + {yy} * {ex})")            # O4 + i y e^{iθ4}
    cf = _mul((pp, pa), nf)                                              # (p + i p/a') n
    for lab, z in ((step.outputs[2], foot), (step.outputs[3], cf)):
        m = _mul((ax, ay), z)
        gen.put_point(lab, f"{o2x} + {scale} * {m[0]}", f"{o2y} + {scale} * {m[1]}")
    gen.put_scalar(step.outputs[4], rho)


def _general(name: str, labels: tuple[str, ...]) -> Callable[..., tuple[Array, ...]]:
    """The operation's general function: its template, compiled (one source)."""

    def run(*ins: Array, tol: Tolerance, **params: Any) -> tuple[Array, ...]:
        from graphkin.construction.codegen import generate

        names = [f"in{k}" for k in range(len(ins))]
        steps = [Step(k, lab, "input", (), (lab,), {"name": lab}) for k, lab in enumerate(names)]
        steps.append(Step(len(steps), name, name, tuple(names), labels, params))
        arrays = np.broadcast_arrays(*(np.asarray(a, dtype=float) for a in ins))
        shape = arrays[0].shape
        flat = [a.ravel() for a in arrays]
        kinds = ["x", "y"] if name == "cam_center" else []
        req = [(lab, part) for lab in labels for part in
               (kinds if name == "cam_center" and lab in labels[0:1] + labels[2:4]
                else ["value"])]
        fn = generate(steps, varying=names, requests=req, tol=tol, name=name)
        rows: list[list[float]] = [[] for _ in req]
        for k in range(flat[0].size):        # one cam angle at a time: a segment is chosen
            got = fn.fn(*(np.array([f[k]]) for f in flat))
            for i in range(len(req)):
                rows[i].append(float(np.ravel(got[i])[0]) if got is not None else math.nan)
        vals = [np.asarray(v).reshape(shape) for v in rows]
        out: list[Array] = []
        i = 0
        for lab in labels:
            if name == "cam_center" and lab in labels[0:1] + labels[2:4]:
                out.append(np.stack([vals[i], vals[i + 1], np.ones(shape)], axis=-1))
                i += 2
            else:
                out.append(vals[i])
                i += 1
        return tuple(out)

    return run


op("cam_program", kind="scalar")(_general("cam_program", ("Θ", "Y", "y1", "y2")))
op("cam_center", kind="point")(_general("cam_center", ("K", "R", "T", "C", "ρ")))
