"""The live page's inputs that follow the first drive by a law (``follows``), moved with it.

A mechanism with two inputs coupled by a law (:mod:`graphkin.mechanisms.laws`,
Sec. 5.4 of Uicker, Pennock & Shigley, 5th ed.) is swept as one parameter:
the second input's value is ``f(x)`` of the first, ``x``, and its rates
follow by the chain rule, as a cam's follower through its displacement
diagram (Sec. 6.3, Eqs. 6.1-6.3),

    ``ω_f = f'(x) ω``,    ``α_f = f''(x) ω² + f'(x) α``.

The page does what ``graphkin sweep`` does (``_Engine.inputs_at`` and
``_Engine.rates_at``): on every drag it sets the follower's input from the
first drive's value before the construction runs, and, for a table law (whose
rates change with the posture), the follower's rate inputs too; a linear law's
rates ``k ω`` and ``k α`` are constants of the construction like the first
drive's.  The law is not a construction step in Python either (the sweep
evaluates it outside the construction), so there is no template to share:
the page gets the law's *coefficients* from :class:`~graphkin.mechanisms.laws.Law`
as data (``k``, ``c``; or the spline's rows, its second derivatives ``M`` and,
periodic, the follower's whole turns per turn) and :data:`LAWS_JS` only
evaluates them, the same arithmetic as ``Law._eval`` (tested against it,
tests/render/test_live_laws.py).

The page's script (:mod:`graphkin.render.live_app`) calls ``gkFollow`` wherever
it sets the first drive's input before calling ``construction(I, K)`` (a drag,
the coupler curves of the whole cycle), the recorded construction's function
or Newton's method's (:mod:`graphkin.render.live_newton`) alike.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 5.4 (several inputs), Sec. 6.3 (displacement diagrams and their
derivatives).
"""

from __future__ import annotations

import math
from typing import Any

from graphkin.mechanisms.laws import Law
from graphkin.mechanisms.model import Mechanism

__all__ = ["LAWS_JS", "law_data", "follow_data"]

LAWS_JS = """\
// f(x) (order 0), f'(x) (1) or f''(x) (2) of a law from its coefficients (render/live_laws.py;
// the arithmetic of graphkin.mechanisms.laws.Law._eval, one value)
function gkLaw(L, x, order) {
  if (!L.x) return order === 0 ? L.k * x + L.c : (order === 1 ? L.k : 0.0);
  const kx = L.x, ky = L.y, m = L.m, n = kx.length;
  let u = x;
  if (L.period !== null) {
    const turns = Math.floor((x - kx[0]) / L.period);
    u = Math.min(Math.max(x - turns * L.period, kx[0]), kx[n - 1]);
  } else if (!(x >= kx[0] && x <= kx[n - 1])) {
    return NaN;  // outside the table's rows: no posture (graphkin's NaN)
  }
  let lo = 0, hi = n;  // the number of rows at or below u (searchsorted, side right)
  while (lo < hi) { const mid = (lo + hi) >> 1; if (kx[mid] <= u) lo = mid + 1; else hi = mid; }
  const i = Math.min(Math.max(lo - 1, 0), n - 2);
  const h = kx[i + 1] - kx[i], t = u - kx[i], m0 = m[i], m1 = m[i + 1];
  if (order === 2) return m0 + (m1 - m0) * t / h;
  const b = (ky[i + 1] - ky[i]) / h - h * (2 * m0 + m1) / 6;
  if (order === 1) {
    const out = b + t * (m0 + t * (m1 - m0) / (2 * h));
    return L.period !== null ? out + L.slope : out;
  }
  const out = ky[i] + t * (b + t * (m0 / 2 + t * (m1 - m0) / (6 * h)));
  return L.period !== null ? out + L.slope * (x - kx[0]) : out;
}
// the inputs that follow the first drive (D.follow): set from its value in I, then the
// construction
function gkFollow(F, I) {
  const x = I[F.label];
  for (const f of F.laws) {
    I[f.label] = gkLaw(f.law, x, 0);
    if (f.rates) {  // a table: rates by the chain rule, ω_f = f' ω, α_f = f'' ω² + f' α
      const d1 = gkLaw(f.law, x, 1);
      I[f.rates[0]] = d1 * F.rate;
      I[f.rates[1]] = gkLaw(f.law, x, 2) * F.rate * F.rate + d1 * F.rate2;
    }
  }
  return I;
}
// why the page has no posture at the first drive's value x: outside a table's rows (a table
// says nothing beyond them), or "" (render/live_app.py says why otherwise)
function gkFollowWhy(F, x) {
  for (const f of F.laws) if (f.outside && !Number.isFinite(gkLaw(f.law, x, 0))) return f.outside;
  return "";
}
// the first drive's angle v (degrees) the page saves at its value x (rad): where x is within a
// table's rows but v, converted back as graphkin reads it (v · (π/180)), falls a round-off
// outside them (x at the last row: 300° -> 300.00000000000006°), v moved in by that round-off
function gkFollowSaved(F, v, x) {
  if (!F.degrees) return v;
  for (const f of F.laws) {
    const L = f.law;
    if (!L.x || L.period !== null) continue;
    const lo = L.x[0], hi = L.x[L.x.length - 1], f1 = Math.PI / 180.0;
    const step = () => Math.max(Math.abs(v) * Number.EPSILON, Number.MIN_VALUE);
    for (let k = 0; k < 8 && x >= lo && x <= hi && v * f1 > hi; k++) v -= step();
    for (let k = 0; k < 8 && x >= lo && x <= hi && v * f1 < lo; k++) v += step();
  }
  return v;
}
"""
"""The evaluation of the laws' coefficients and the setting of the followers' inputs."""


def law_data(law: Law) -> dict[str, Any]:
    """The coefficients of ``law`` as JSON-able data for :data:`LAWS_JS`'s ``gkLaw``.

    Parameters
    ----------
    law : Law
        A linear law (``k``, ``c``) or a table's cubic spline (rows ``x``,
        ``y``, second derivatives ``m``; periodic: ``period`` and the
        follower's rise per turn, ``slope``), internal units.
    """
    if law.linear:
        return {"k": float(law.k), "c": float(law.c)}
    assert law.x is not None and law.y is not None and law._m is not None
    return {"x": [float(v) for v in law.x], "y": [float(v) for v in law.y],
            "m": [float(v) for v in law._m],
            "period": None if law.period is None else float(law.period),
            "slope": float(law._slope)}


def follow_data(mech: Mechanism, rates: dict[str, list[str]] | None) -> dict[str, Any] | None:
    """The page's ``follow``: the first drive's label and rates, and each follower's law.

    Parameters
    ----------
    mech : Mechanism
        The mechanism (its drives after the first with a ``law``).
    rates : dict or None
        For each follower by a table whose rates change with the posture, the
        labels of its rate inputs (``ω3``, ``α3``: the sweep's
        ``_Engine.coupled_rates``); None when the page has no polygons.

    Returns
    -------
    dict or None
        None when no input follows the first.
    """
    d0 = mech.drives[0]
    laws = [(d.label, d.law) for d in mech.drives if d.law is not None]
    if not laws:
        return None
    return {"label": d0.label, "rate": float(d0.rate or 0.0), "rate2": float(d0.rate2 or 0.0),
            "degrees": d0.is_angle,
            "laws": [{"label": lab, "law": law_data(law),
                      "rates": None if rates is None else rates.get(lab),
                      "outside": _outside(law, d0, lab, mech.length_unit)}
                     for lab, law in laws]}


def _outside(law: Law, lead: Any, label: str, unit: str) -> str:
    """The page's line where the first drive leaves a table's rows; "" for a law of every value."""
    dom = law.domain
    if dom is None:
        return ""
    lo, hi = (math.degrees(v) if lead.is_angle else v for v in dom)
    u = "°" if lead.is_angle else f" {unit}"
    return (f"{lead.label} is outside the rows of the table {label} follows it by "
            f"({lo:g}{u} to {hi:g}{u}), which says nothing beyond them: drag back.")
