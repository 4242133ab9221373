"""Fitting a drawn polygon's scale and turn robustly: one or two wrong images do not move it.

A polygon drawn without a stated scale is compared with the exact one through
one complex factor ``k``: ``exact ≈ k × drawn`` for every vector from the pole
(``|k|`` the scale, ``arg k`` the turn of the drawing).  A least-squares fit
over every image would let one wrong image pull the scale off and mark the
right ones wrong, so the factor is chosen by consensus:

* each image alone, each pair of images, and all of them together propose a
  factor (deterministic: no random samples, the same verdicts on every run);
* a proposal is worth the number of images it puts within half the marking
  tolerance of their exact places, then the number within the tolerance, then
  whether it agrees with the image of the input link (the image a student
  draws first, from ω2 × R), then how closely;
* the best proposal's images within tolerance are the fit's; the factor is
  refitted to them by least squares (each image weighted by its own size, so a
  short vector counts as much as a long one), and every other image is left
  out of the fit, with the reason in words.

When the sheet gives the directions (a stated scale, the mechanism drawn on
the same sheet, a printed worksheet), the turn is fixed and only the scale is
fitted, from the vectors' lengths: a polygon drawn for the reversed sense of
the input's ω then has every vector reversed, and is marked so.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity polygon drawn to a
scale chosen for the first known vector, V_A = ω2 R_AO2), Sec. 4.3.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

__all__ = ["Fit", "fit_factor", "MAX_PAIRS"]

#: above this many images, only single images and the whole set propose factors
MAX_PAIRS = 60
#: a proposal's images "agree" within this fraction of the marking tolerance
_TIGHT = 0.5


@dataclass
class Fit:
    """The fitted factor and which images it was fitted to.

    Attributes
    ----------
    factor : complex
        ``exact ≈ factor × drawn`` (the quantity per drawing unit, turned).
    used : list of str
        The images the factor was fitted to (in the given order).
    left_out : dict
        Image -> why it was left out of the fit, in words ("drawn 10.0 % too
        long for the scale that b, e, f agree on").
    fixed_turn : bool
        The turn was given, only the scale fitted.
    agreed : bool
        Two or more images agree on the factor (else it was taken from one).
    """

    factor: complex
    used: list[str]
    left_out: dict[str, str] = field(default_factory=dict)
    fixed_turn: bool = False
    agreed: bool = True


def _radius(e: np.ndarray, scale: np.ndarray, relative: float, sheet: float) -> np.ndarray:
    """The marking tolerance of each image (quantity units) at each proposed scale.

    ``e`` (N,) exact magnitudes, ``scale`` (C,) proposed |k|: (C, N).  The
    larger of ``relative`` × |exact| and the drawing tolerance (``sheet``
    drawing units, times the scale).
    """
    return np.maximum(relative * e[None, :], sheet * scale[:, None])


def _proposals(n: int) -> list[tuple[int, ...]]:
    """Which images propose a factor: each alone, each pair (up to MAX_PAIRS images), all."""
    out: list[tuple[int, ...]] = [(i,) for i in range(n)]
    if n <= MAX_PAIRS:
        out += list(itertools.combinations(range(n), 2))
    if n > 2:
        out.append(tuple(range(n)))
    return out


def _least_squares(d: np.ndarray, e: np.ndarray, sets: Sequence[Sequence[int]],
                   turn: complex | None) -> np.ndarray:
    """The factor of each set of images, by least squares weighted by 1/|exact|².

    Free turn: ``k = Σ w conj(d) e / Σ w |d|²``; a fixed turn ``u``: the scale
    from the lengths, ``s = Σ w |d| |e| / Σ w |d|²``, ``k = s u``.
    """
    w = 1.0 / np.abs(e) ** 2
    mask = np.zeros((len(sets), len(d)))
    for c, s in enumerate(sets):
        mask[c, list(s)] = 1.0
    den = mask @ (w * np.abs(d) ** 2)
    if turn is None:
        return np.asarray((mask @ (w * np.conj(d) * e)) / den, dtype=complex)
    return (mask @ (w * np.abs(d) * np.abs(e))) / den * turn


def _misfit(k: np.ndarray, d: np.ndarray, e: np.ndarray, turn: complex | None,
            relative: float, sheet: float) -> np.ndarray:
    """Each image's distance from its exact place at each factor, in tolerances: (C, N)."""
    scale = np.abs(k)
    if turn is None:
        off = np.abs(k[:, None] * d[None, :] - e[None, :])
    else:
        off = np.abs(scale[:, None] * np.abs(d)[None, :] - np.abs(e)[None, :])
    return np.asarray(off / _radius(np.abs(e), scale, relative, sheet))


def fit_factor(names: Sequence[str], drawn: Sequence[complex], exact: Sequence[complex], *,
               relative: float, sheet: float = 0.0, turn: complex | None = None,
               prefer: Sequence[str] = ()) -> Fit:
    """The factor ``k`` with ``exact ≈ k × drawn``, fitted by consensus, then least squares.

    Parameters
    ----------
    names : sequence of str
        The images (their names, in the order the report lists them).
    drawn, exact : sequence of complex
        Each image's vector from the pole: on the drawing (drawing units), and
        exact (quantity units).  None may be zero.
    relative : float
        The marking tolerance, a fraction of each exact magnitude.
    sheet : float
        The drawing tolerance in drawing units (0: unknown).
    turn : complex, optional
        A unit complex number: the turn is fixed (the sheet gives the
        directions) and only the scale is fitted, from the lengths.
    prefer : sequence of str
        Images that win a tie (the input link's images).

    Returns
    -------
    Fit

    Examples
    --------
    Three images drawn at 1 unit = 2 (turned 90°), the third 10 % too long:
    the first two fix the factor, the third is left out and says why.

    >>> f = fit_factor(["b", "c", "e"], [1j, 2j, 1.1j], [2, 4, 2], relative=0.02)
    >>> f.factor == -2j, f.used
    (True, ['b', 'c'])
    >>> f.left_out["e"]
    'drawn 10.0 % too long for the scale and turn that b, c agree on'
    """
    d = np.asarray(drawn, dtype=complex)
    e = np.asarray(exact, dtype=complex)
    if not (len(d) == len(e) == len(names)) or not len(d):
        raise ValueError("one drawn and one exact vector per image")
    # fitted on vectors scaled to at most 1 (no squares of 1e200 overflowing), scaled back
    big_d, big_e = float(np.max(np.abs(d))), float(np.max(np.abs(e)))
    d, e, sheet = d / big_d, e / big_e, sheet / big_d
    u = None if turn is None else complex(turn) / abs(turn)
    sets = _proposals(len(d))
    k = _least_squares(d, e, sets, u)
    rho = _misfit(k, d, e, u, relative, sheet)
    pref = np.array([n in set(prefer) for n in names])
    tight = (rho <= _TIGHT).sum(axis=1)
    full = (rho <= 1.0).sum(axis=1)
    liked = ((rho <= 1.0) & pref[None, :]).any(axis=1)
    close = -np.minimum(rho, 1.0).sum(axis=1)
    # lexsort: the last key is the first; the best is the last row; ties go to the earliest
    best = int(np.lexsort((-np.arange(len(sets)), close, liked, full, tight))[-1])
    used = np.flatnonzero(rho[best] <= 1.0)
    if not len(used):
        used = np.array(sets[best])
    for _ in range(2):  # refit to the agreeing images, and once more to those it keeps
        kf = _least_squares(d, e, [tuple(used)], u)
        now = np.flatnonzero(_misfit(kf, d, e, u, relative, sheet)[0] <= 1.0)
        if not len(now) or set(now) == set(used):
            break
        used = now
    factor = complex(_least_squares(d, e, [tuple(used)], u)[0]) * (big_e / big_d)
    fit = Fit(factor, [names[int(i)] for i in used], fixed_turn=u is not None,
              agreed=len(used) >= 2 or len(d) == 1)
    agree = ", ".join(fit.used)
    what = "the scale" if u is not None else "the scale and turn"
    by = f"that {agree} agree on" if len(used) >= 2 else f"taken from {agree}"
    for i in range(len(d)):
        if i not in set(used.tolist()):
            z = complex(_least_squares(d, e, [tuple(used)], u)[0]) * d[i]
            fit.left_out[names[i]] = f"{_how_off(z, e[i], u is not None)} " \
                                     f"for {what} {by}"
    return fit


def _how_off(z: complex, e: complex, lengths_only: bool) -> str:
    """How a drawn vector (scaled and turned) is off its exact value, in words."""
    ratio = abs(z) / abs(e) - 1.0
    parts = []
    if abs(ratio) >= 0.0005:
        parts.append(f"drawn {abs(ratio) * 100:.1f} % too {'long' if ratio > 0 else 'short'}")
    if not lengths_only:
        turn = math.degrees(math.atan2((z / e).imag, (z / e).real))
        if abs(turn) > 170.0:
            parts.insert(0, "drawn the other way round (its sense reversed)")
        elif abs(turn) >= 0.05:
            parts.append(f"{abs(turn):.1f}° off in direction")
    return " and ".join(parts) or "off"
