"""The overlay method (Sec. 9.8): a four-bar whose coupler curve fits a desired path.

The book lays a transparency of the desired path over an atlas of coupler
curves (Hrones and Nelson's) and slides and turns it until one curve fits;
then the linkage of that curve is drawn to the path's scale.  Here the atlas
is generated: a grid of crank-rocker proportions (the crank 1, the coupler,
rocker and frame each 1.5 ... 3.5, Grashof with the crank the shortest, Sec.
1.10) and, on each coupler, a grid of coupler points in the coupler's frame
(A at the origin, B on the x axis, steps of half the coupler's length), the
curves traced over one turn of the crank.  Sliding and turning the
transparency is the similarity (translation, rotation, scale) that best lays
a stretch of each curve on the path, in the least-squares sense, found in
closed form with complex numbers; every stretch of every curve (its start,
and its length as a fraction of the curve) is tried at once as numpy arrays,
and the path is tried both ways round.  The best fit's linkage is carried to
the path by the same similarity and written as a mechanism file.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 9.8 (Fig. 9.29); Hrones and Nelson,
*Analysis of the Four-Bar Linkage* (1951).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.errors import InputError

__all__ = ["Atlas", "atlas", "Overlay", "overlay", "resample"]

LENGTHS = (1.5, 2.0, 2.5, 3.0, 3.5)
"""The coupler, rocker and frame lengths of the atlas, for a crank of 1."""
POINT_X = (-0.5, 0.0, 0.5, 1.0, 1.5)
POINT_Y = (-1.0, -0.5, 0.5, 1.0)
"""The coupler points of the atlas, in coupler lengths, in the coupler's frame."""
SAMPLES = 96
"""Crank positions per turn on each atlas curve."""
STARTS = 32
FRACTIONS = (0.2, 0.3, 0.45, 0.6, 0.8, 1.0)
"""Where a stretch of a curve starts (of ``STARTS`` evenly spaced along its length) and how
much of the curve's length it takes."""
M = 32
"""Points on which a stretch and the path are compared."""


@dataclass(frozen=True)
class Atlas:
    """The generated atlas: one row per coupler curve.

    Attributes
    ----------
    dims : ndarray (K, 5)
        crank, coupler, rocker, frame, and the row's coupler point (x, y) as
        ``dims[:, 4] + 1j dims[:, 5]``; shape (K, 6).
    curves : ndarray complex (K, SAMPLES)
        The coupler point over one turn of the crank (O2 at the origin, O4 on
        the positive x axis).
    """

    dims: np.ndarray
    curves: np.ndarray


def _crank_rockers() -> np.ndarray:
    g = np.array(np.meshgrid(LENGTHS, LENGTHS, LENGTHS, indexing="ij")).reshape(3, -1).T
    out = []
    for r3, r4, r1 in g:
        links = sorted([1.0, r3, r4, r1])
        # Grashof with the crank the shortest, clear of the change-point case by 5 %
        if links[0] + links[3] <= 0.95 * (links[1] + links[2]):
            out.append((1.0, r3, r4, r1))
    return np.array(out)


def trace(dims: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Coupler points of crank-rockers ``dims`` (K, 6) at crank angles ``theta`` (open branch).

    O2 at the origin, O4 = (r1, 0); B left of A -> O4 (Sec. 2.8's two circles).
    """
    r2, r3, r4, r1 = (dims[:, k:k + 1] for k in range(4))
    p = dims[:, 4:5] + 1j * dims[:, 5:6]
    a = r2 * np.exp(1j * theta)[None, :]
    d = r1 - a
    dist = np.abs(d)
    along = (dist ** 2 + r3 ** 2 - r4 ** 2) / (2 * dist)
    h = np.sqrt(np.maximum(r3 ** 2 - along ** 2, 0.0))
    b = a + (along + 1j * h) * d / dist
    return a + p * (b - a) / r3


def atlas() -> Atlas:
    """The atlas of coupler curves (about 1100 curves of ``SAMPLES`` points)."""
    links = _crank_rockers()
    px, py = np.meshgrid(POINT_X, POINT_Y, indexing="ij")
    pts = np.stack([px.ravel(), py.ravel()], axis=1)
    dims = np.array([[*lk, x * lk[1], y * lk[1]] for lk in links for x, y in pts])
    theta = np.arange(SAMPLES) * (math.tau / SAMPLES)
    return Atlas(dims, trace(dims, theta))


def resample(z: np.ndarray, start: np.ndarray, length: np.ndarray, closed: bool,
             m: int = M) -> np.ndarray:
    """``m`` points evenly spaced by arc length along each row of ``z``, from ``start`` on.

    ``z`` (K, N) complex curves; ``start`` and ``length`` (K, W) as fractions of each
    curve's length (a closed curve wraps round).  Returns (K, W, m).
    """
    zz = np.concatenate([z, z[:, :1]], axis=1) if closed else z
    seg = np.abs(np.diff(zz, axis=1))
    s = np.concatenate([np.zeros((z.shape[0], 1)), np.cumsum(seg, axis=1)], axis=1)
    total = s[:, -1:]
    u = np.linspace(0.0, 1.0, m)
    want = (start[..., None] + length[..., None] * u) * total[:, :, None]
    if closed:
        want = np.mod(want, total[:, :, None])
    k, w = want.shape[:2]
    # one interpolation for every row: each row's arc lengths shifted past the one before
    shift = (np.arange(k) * (2.0 * float(np.max(total)) + 1.0))[:, None]
    x = (s + shift).ravel()
    q = (want + shift[:, :, None]).ravel()
    re = np.interp(q, x, zz.real.ravel())
    im = np.interp(q, x, zz.imag.ravel())
    return (re + 1j * im).reshape(k, w, m)


@dataclass(frozen=True)
class Overlay:
    """The best fit of the atlas to a path, carried to the path's place and scale.

    Attributes
    ----------
    path : ndarray complex
        The desired path (the file's points).
    row : int
        The atlas curve that fits.
    similarity : complex, complex
        ``z -> a z + b`` laying the atlas curve on the path.
    residual : float
        The RMS distance of the path from the laid curve, over the path's size.
    reversed : bool
        Whether the path is run the other way round from the crank's turn.
    o2, o4, a, b, p : complex
        The linkage laid on the path: pivots, pins and coupler point, at the
        crank angle where the fitting stretch starts.
    curve : ndarray complex
        The whole coupler curve, laid on the path.
    dims : ndarray
        The atlas row (crank, coupler, rocker, frame, point x, point y).
    """

    path: np.ndarray
    row: int
    similarity: tuple[complex, complex]
    residual: float
    reversed: bool
    o2: complex
    o4: complex
    a: complex
    b: complex
    p: complex
    curve: np.ndarray
    dims: np.ndarray

    def mechanism_toml(self, units: str = "mm", title: str = "") -> str:
        """The four-bar of the fit as a mechanism file (the crank where the stretch starts)."""
        def xy(z: complex) -> str:
            return f"[{float(z.real)!r}, {float(z.imag)!r}]"

        r2, r3, r4 = abs(self.a - self.o2), abs(self.b - self.a), abs(self.b - self.o4)
        pl = (self.p - self.a) * np.exp(-1j * np.angle(self.b - self.a))
        return "\n".join([
            f'title = "{title or "Four-bar by the overlay method"}"',
            f'units = {{ length = "{units}" }}', "",
            "[links.1]", f"O2 = {xy(self.o2)}", f"O4 = {xy(self.o4)}", "",
            "[links.2]", "O2 = [0.0, 0.0]", f"A = [{r2!r}, 0.0]", "",
            "[links.3]", "A = [0.0, 0.0]", f"B = [{r3!r}, 0.0]", f"P = {xy(complex(pl))}", "",
            "[links.4]", "O4 = [0.0, 0.0]", f"B = [{r4!r}, 0.0]", "",
            "[drive]", "link = 2", f"angle = {math.degrees(float(np.angle(self.a - self.o2)))!r}",
            "", "[assembly]", f"B = {xy(self.b)}", ""])


def overlay(points: np.ndarray, closed: bool = False, source: str = "<synthesis>",
            book: Atlas | None = None) -> Overlay:
    """The atlas curve whose stretch best fits the path ``points`` (complex, in order).

    Raises
    ------
    InputError
        Fewer than four points, or points that do not span a path.
    """
    w = np.asarray(points, dtype=complex)
    if w.size < 4:
        raise InputError("give at least four points of the path", key="overlay.points",
                         file=source)
    size = float(np.max(np.abs(w - w.mean())))
    if not size > 0 or not np.all(np.isfinite(w)):
        raise InputError("the points of the path coincide", key="overlay.points", file=source)
    book = book if book is not None else atlas()
    # the path by its own arc length, m points, both ways round; centred
    target = resample(w[None, :], np.zeros((1, 1)), np.ones((1, 1)), closed)[0, 0]
    targets = np.stack([target, target[::-1]]) - target.mean()
    fr = (1.0,) if closed else FRACTIONS
    starts = np.arange(STARTS) / STARTS
    st, ln = (g.ravel() for g in np.meshgrid(starts, fr, indexing="ij"))
    best = (math.inf, 0, 0, 0)
    chunk = 256
    for lo in range(0, book.curves.shape[0], chunk):
        z = book.curves[lo:lo + chunk]
        k = z.shape[0]
        win = resample(z, np.broadcast_to(st, (k, st.size)), np.broadcast_to(ln, (k, ln.size)),
                       True)
        win = win - win.mean(axis=-1, keepdims=True)
        zz = np.sum(np.abs(win) ** 2, axis=-1)
        for o in range(2):
            tw = targets[o]
            cross = np.sum(np.conj(win) * tw, axis=-1)
            with np.errstate(invalid="ignore", divide="ignore"):
                res = np.sum(np.abs(tw) ** 2) - np.abs(cross) ** 2 / zz
            res = np.where(zz > 0, res, np.inf)
            ii, jj = np.unravel_index(int(np.argmin(res)), res.shape)
            if res[ii, jj] < best[0]:
                best = (float(res[ii, jj]), lo + int(ii), int(jj), o)
    err, row, j, o = best
    z = book.curves[row:row + 1]
    win = resample(z, np.array([[st[j]]]), np.array([[ln[j]]]), True)[0, 0]
    tw = targets[o] + target.mean()
    zc, tc = win - win.mean(), tw - tw.mean()
    a = complex(np.sum(np.conj(zc) * tc) / np.sum(np.abs(zc) ** 2))
    b = complex(tw.mean() - a * win.mean())
    dims = book.dims[row]
    # the crank angle where the stretch starts: the nearest sample of the atlas curve
    k0 = int(np.argmin(np.abs(book.curves[row] - win[0])))
    theta = k0 * (math.tau / SAMPLES)
    r2, r3, r4, r1 = dims[:4]
    pa = r2 * np.exp(1j * theta)
    d = r1 - pa
    dist = abs(d)
    along = (dist ** 2 + r3 ** 2 - r4 ** 2) / (2 * dist)
    pb = pa + (along + 1j * math.sqrt(max(r3 ** 2 - along ** 2, 0.0))) * d / dist
    pp = pa + complex(dims[4], dims[5]) * (pb - pa) / r3

    def lay(q: complex | np.ndarray) -> complex | np.ndarray:
        return a * q + b

    rms = math.sqrt(max(err, 0.0) / M) / size
    return Overlay(w, row, (a, b), rms, bool(o), complex(lay(0j)), complex(lay(complex(r1))),
                   complex(lay(pa)), complex(lay(pb)), complex(lay(pp)),
                   np.asarray(lay(book.curves[row])), dims)
