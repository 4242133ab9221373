"""The law by which a second input follows the first (``follows`` in a mechanism file).

Two inputs driven together are one swept parameter (issue 25): the second
drive's value is a function of the first, ``v = f(x)``, and its rates follow by
the chain rule,

    ``v' = f'(x) ẋ``,    ``v'' = f''(x) ẋ² + f'(x) ẍ``,

the same rule that carries a crank's rates to its follower through a cam's
displacement diagram (Sec. 6.3, Eqs. 6.1-6.3).  Two forms:

* linear, ``follows = { link, ratio, offset }``: ``f(x) = ratio · x + offset``;
* a table, ``follows = { link, table = [[x0, v0], [x1, v1], ...] }``: the
  cubic spline through the rows (continuous f, f' and f'', so the follower's
  velocity and acceleration are continuous).  A table over exactly one turn
  of an angle (last x = first x + 360°) is **periodic**: the law repeats
  every turn, its follower coming back to its start or turned a whole number
  of turns (a length: back to its start), and the spline closes smoothly over
  the seam.  Any other table covers its rows' range only.

Everything here is in internal units (radians or lengths).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 6.3 (displacement diagrams and their derivatives), Sec. 5.4 (several
inputs).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = ["Law", "linear_law", "table_law", "MAX_ROWS"]

Array = np.ndarray

#: The most rows a table law takes (the spline is solved as one dense system).
MAX_ROWS = 1000

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True, eq=False)
class Law:
    """``v = f(x)`` of a following input; linear (``k``, ``c``) or a spline through rows.

    Attributes
    ----------
    k, c : float
        The linear law ``k x + c`` (a table leaves them 1 and 0).
    x, y : ndarray or None
        The table's rows (internal units), x strictly increasing.
    period : float or None
        ``2π`` for a table over one turn of an angle, else None.
    """

    k: float = 1.0
    c: float = 0.0
    x: Array | None = None
    y: Array | None = None
    period: float | None = None
    _slope: float = 0.0
    _m: Array | None = field(default=None, repr=False)

    # ---- what the rest of graphkin asks ---------------------------------
    @property
    def linear(self) -> bool:
        """True for ``ratio`` and ``offset``: the rates are ``k`` times the first's."""
        return self.x is None

    @property
    def domain(self) -> tuple[float, float] | None:
        """The range of the first input the law covers; None when it covers every value."""
        if self.x is None or self.period is not None:
            return None
        return float(self.x[0]), float(self.x[-1])

    def value(self, x: Any) -> Any:
        """``f(x)``; NaN outside a table's range."""
        return self._eval(x, 0)

    def slope(self, x: Any) -> Any:
        """``f'(x)``: the follower's first-order coefficient (Sec. 3.11)."""
        return self._eval(x, 1)

    def curve(self, x: Any) -> Any:
        """``f''(x)``."""
        return self._eval(x, 2)

    def rates(self, x: Any, rate: Any, rate2: Any) -> tuple[Any, Any]:
        """The follower's rates from the first's: ``f' ẋ`` and ``f'' ẋ² + f' ẍ``."""
        d1 = self.slope(x)
        return d1 * rate, self.curve(x) * rate * rate + d1 * rate2

    # ---- evaluation -----------------------------------------------------
    def _eval(self, x: Any, order: int) -> Any:
        scalar = np.ndim(x) == 0
        xa = np.asarray(x, dtype=float)
        if self.x is None:
            out = (self.k * xa + self.c if order == 0 else
                   np.full(xa.shape, self.k if order == 1 else 0.0))
            return float(out) if scalar else out
        assert self.y is not None and self._m is not None
        kx, ky, m = self.x, self.y, self._m
        x0 = kx[0]
        if self.period is not None:
            turns = np.floor((xa - x0) / self.period)
            u = xa - turns * self.period
            u = np.clip(u, kx[0], kx[-1])
        else:
            u = xa
        i = np.clip(np.searchsorted(kx, u, side="right") - 1, 0, len(kx) - 2)
        h = kx[i + 1] - kx[i]
        t = u - kx[i]
        m0, m1 = m[i], m[i + 1]
        if order == 0:
            b = (ky[i + 1] - ky[i]) / h - h * (2 * m0 + m1) / 6
            out = ky[i] + t * (b + t * (m0 / 2 + t * (m1 - m0) / (6 * h)))
            if self.period is not None:
                out = out + self._slope * (xa - x0)  # g(u) + the follower's whole turns
        elif order == 1:
            b = (ky[i + 1] - ky[i]) / h - h * (2 * m0 + m1) / 6
            out = b + t * (m0 + t * (m1 - m0) / (2 * h))
            if self.period is not None:
                out = out + self._slope
        else:
            out = m0 + (m1 - m0) * t / h
        if self.period is None:
            out = np.where((xa < kx[0]) | (xa > kx[-1]), np.nan, out)
        return float(out) if scalar else out


def linear_law(k: float, c: float) -> Law:
    """``v = k x + c``."""
    return Law(k=float(k), c=float(c))


def table_law(x: Array, y: Array, *, angle: bool, follower_angle: bool,
              fail: Callable[[str], Exception]) -> Law:
    """The spline law through the rows ``(x, y)`` (internal units), checked.

    Parameters
    ----------
    x, y : ndarray
        The rows; ``x`` must increase strictly.
    angle : bool
        The first input is an angle (a table over one turn is then periodic).
    follower_angle : bool
        The follower is an angle (a periodic table may turn it whole turns).
    fail : callable
        Makes the one-line error from a reason.

    Raises
    ------
    Exception
        From ``fail``: fewer than two rows, x not increasing, or a table over
        one turn that does not come back to its start.
    """
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    if len(x) < 2:
        raise fail("a table needs at least two rows [first, this]")
    steps = np.diff(x)
    scale = max(float(np.ptp(x)), 1e-300)
    if not np.all(steps > 1e-9 * scale):
        k = int(np.argmin(steps > 1e-9 * scale)) + 1
        raise fail(f"the first column must increase from row to row (row {k + 1} does not): "
                   "sort the rows by the first drive's value; one value per row")
    span = float(x[-1] - x[0])
    periodic = angle and abs(span - TWO_PI) <= 1e-9 * TWO_PI
    if periodic:
        rise = float(y[-1] - y[0])
        if follower_angle:
            turns = rise / TWO_PI
            ok = abs(turns - round(turns)) <= 1e-9 * max(1.0, abs(turns))
            rise = round(turns) * TWO_PI
        else:
            ok = abs(rise) <= 1e-9 * max(1.0, float(np.ptp(y)))
            rise = 0.0
        if not ok:
            raise fail("a table over one whole turn repeats every turn: its last row must "
                       "come back to the first (the same value, or whole turns of an angle), "
                       f"not {math.degrees(y[-1] - y[0]) if follower_angle else y[-1] - y[0]:g}"
                       f"{'°' if follower_angle else ''} further on")
        slope = rise / TWO_PI
        g = y - slope * (x - x[0])
        g[-1] = g[0]
        m = _periodic_moments(x, g)
        return Law(x=x, y=g, period=TWO_PI, _slope=slope, _m=m)
    return Law(x=x, y=y, _m=_natural_moments(x, y))


def _natural_moments(x: Array, y: Array) -> Array:
    """Second derivatives M of the natural cubic spline (M = 0 at both ends)."""
    n = len(x) - 1
    m = np.zeros(n + 1)
    if n < 2:
        return m
    h = np.diff(x)
    d = np.diff(y) / h
    a = np.zeros((n - 1, n - 1))
    idx = np.arange(n - 1)
    a[idx, idx] = 2 * (h[:-1] + h[1:])
    a[idx[1:], idx[:-1]] = h[1:-1]
    a[idx[:-1], idx[1:]] = h[1:-1]
    m[1:-1] = np.linalg.solve(a, 6 * (d[1:] - d[:-1]))
    return m


def _periodic_moments(x: Array, g: Array) -> Array:
    """Second derivatives M of the periodic cubic spline through ``(x, g)``, g[-1] = g[0]."""
    n = len(x) - 1
    h = np.diff(x)
    d = np.diff(g) / h
    a = np.zeros((n, n))
    rhs = np.empty(n)
    for i in range(n):  # rows of the table: a few hundred at most, once per file
        hp, hn = h[i - 1], h[i]  # h[-1] is the last interval: the seam
        a[i, i] += 2 * (hp + hn)
        a[i, (i - 1) % n] += hp
        a[i, (i + 1) % n] += hn
        rhs[i] = 6 * (d[i] - d[i - 1])
    m = np.linalg.solve(a, rhs)
    return np.append(m, m[0])


def read_follows(raw: Any, drive: Any, leader: Any, key: str, *,
                 rate: Callable[[Any, str, str], float],
                 fail: Callable[[str, str], Exception],
                 link_id: Callable[[Any, str], str]) -> Any:
    """The drive ``drive`` with the law of its ``follows`` table applied (parse time).

    ``follows = { link = 2, ratio = 3, offset = 30 }`` (θ = 3 θ2 + 30°) or
    ``follows = { link = 2, table = [[θ2, θ], ...] }``, in the file's units
    (degrees, lengths).  Its value and rates at the file's posture come from
    the law and the first drive's.

    Parameters
    ----------
    raw : Mapping
        The ``follows`` table.
    drive, leader : Drive
        The following drive (its value a placeholder) and the first drive.
    key : str
        The drive's key (``drive[1]``).
    rate, fail, link_id : callable
        The reader's number-with-units reader, one-line error and link-id check.
    """
    import dataclasses

    lead = link_id(raw.get("link"), f"{key}.follows.link")
    if lead != leader.link or leader.kind not in ("angle", "position", "relative") \
            or leader.law is not None:
        raise fail(f"{key}.follows.link", "a drive follows the first drive, the "
                   f"swept one (link {leader.link}), not link {lead}")
    f_f = math.pi / 180.0 if drive.is_angle else 1.0
    f_l = math.pi / 180.0 if leader.is_angle else 1.0
    if "table" in raw:
        for bad in ("ratio", "offset"):
            if bad in raw:
                raise fail(f"{key}.follows.{bad}", "a law is a table or a ratio and an "
                           f"offset, not both: leave out {bad}")
        law = _read_table(raw["table"], f"{key}.follows.table", f_l, f_f, leader.is_angle,
                          drive.is_angle, fail)
        dom = law.domain
        if dom is not None and not dom[0] <= leader.value <= dom[1]:
            raise fail(f"{key}.follows.table", f"the table covers {leader.label} from "
                       f"{dom[0] / f_l:g} to {dom[1] / f_l:g} only, not the first drive's "
                       f"{leader.value / f_l:g}")
    else:
        ratio = raw.get("ratio", 1.0)
        if isinstance(ratio, bool) or not isinstance(ratio, (int, float)) \
                or not math.isfinite(float(ratio)) or abs(float(ratio)) > 1e6:
            raise fail(f"{key}.follows.ratio", "the ratio is a finite number (at most "
                       f"1e6 in size), not {str(ratio)[:40]}")
        kind = "angle" if drive.is_angle else "length"
        offset = rate(raw.get("offset", 0.0), kind, f"{key}.follows.offset")
        law = linear_law(float(ratio) * f_f / f_l, f_f * offset)
    w, a = (None, None) if leader.rate is None else law.rates(
        leader.value, leader.rate, leader.rate2 or 0.0)
    return dataclasses.replace(drive, value=law.value(leader.value), rate=w, rate2=a, law=law)


def _read_table(rows: Any, key: str, f_l: float, f_f: float, angle: bool,
                follower_angle: bool, fail: Callable[[str, str], Exception]) -> Law:
    """``[[first, this], ...]`` in the file's units, as a :class:`Law` (internal units)."""
    if not isinstance(rows, list) or not 2 <= len(rows) <= MAX_ROWS:
        raise fail(key, f"expected 2 to {MAX_ROWS} rows [[first, this], ...]")
    pairs = []
    for i, r in enumerate(rows):
        if not (isinstance(r, list) and len(r) == 2 and all(
                isinstance(v, (int, float)) and not isinstance(v, bool)
                and math.isfinite(float(v)) and abs(float(v)) <= 1e9 for v in r)):
            raise fail(f"{key}[{i}]", "a row is two finite numbers [first, this] (at most "
                       f"1e9 in size), not {str(r)[:40]}")
        pairs.append((float(r[0]) * f_l, float(r[1]) * f_f))
    xy = np.array(pairs)
    return table_law(xy[:, 0], xy[:, 1], angle=angle, follower_angle=follower_angle,
                     fail=lambda why: fail(key, why))
