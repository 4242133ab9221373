"""Compiled kernels: their registry, the runtime they read and write, the fallback."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from graphkin.construction.ops.registry import OPS
from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

Array = np.ndarray

# ---------------------------------------------------------------------------
# Compiled kernels: the same operations, specialised once per step.
#
# A construction evaluated on whole arrays (a sweep) spends its time in the
# temporaries of the general functions above (np.stack, np.where, hypot,
# homogeneous divisions) and in reading data that has left the cache.  Each
# kernel below does the arithmetic of one step with its constants bound once:
# a point's Cartesian rows are read once per evaluation and shared; points
# stored with w == 1 skip the homogeneous division; tolerance decisions are
# made exactly, but only where a cheap bound cannot rule them out; outputs
# are written row by row straight into one block ``(k, ...)`` seen as
# ``(..., k)``; the cosine and sine of a link angle measured from two points
# are those points' direction; a constant zero is not subtracted.  The
# results are those of the general functions up to rounding (``sqrt(x² + y²)``
# for ``hypot``, the direction for ``cos(atan2(y, x))``), with the same NaN
# entries.  An operation without a kernel runs through its
# general function.
# ---------------------------------------------------------------------------

Kernel = Callable[["Runtime"], "bool | None"]
"""A compiled step: returns True when its outputs are certainly finite (given finite inputs)."""

KernelFactory = Callable[..., "Kernel | None"]

KERNELS: dict[str, KernelFactory] = {}

ORIGINATING: set[str] = set()
"""Operations that can turn finite inputs into non-finite outputs (the others cannot)."""

_ND = np.ndarray


def kernel(name: str, originating: bool = False) -> Callable[[KernelFactory], KernelFactory]:
    """Register the kernel factory of operation ``name``.

    The factory is called as ``factory(step, tol, info)`` and returns a
    callable ``run(rt)`` that reads the step's inputs from the runtime and
    stores its outputs, or ``None`` to fall back to the general function.
    ``originating`` operations can give non-finite outputs for finite inputs
    (no intersection, a division by a length that may vanish).
    """

    def deco(f: KernelFactory) -> KernelFactory:
        KERNELS[name] = f
        if originating:
            ORIGINATING.add(name)
        return f

    return deco


class CompileInfo:
    """What is known of the labels when a construction is compiled.

    Attributes
    ----------
    const : dict
        Labels whose values are constant (folded): label -> array.
    radius : dict
        Circles whose radius is a step constant: label -> radius.
    """

    def __init__(self) -> None:
        self.const: dict[str, Array] = {}
        self.radius: dict[str, float] = {}

    def forget(self, label: str) -> None:
        """A step (re)defines ``label``: drop what was known of it."""
        self.const.pop(label, None)
        self.radius.pop(label, None)


def _shape(*xs: Any) -> tuple[int, ...]:
    """The broadcast shape of the arguments (arrays, numpy scalars, floats)."""
    s: tuple[int, ...] = ()
    for x in xs:
        if type(x) is _ND:
            t = x.shape
            if t != s and t:
                s = t if not s else np.broadcast_shapes(s, t)
    return s


def _zero(v: Any) -> bool:
    """True for a constant (a float) equal to zero: subtracting it is skipped."""
    return type(v) is float and v == 0.0


def _vmin(x: Any) -> float:
    """Smallest entry, NaN ignored (NaN when every entry is NaN)."""
    if type(x) is not _ND or x.ndim == 0:
        return float(x)
    return float(np.fmin.reduce(x, axis=None))


def _all_finite(a: Any) -> bool:
    """True when every entry is finite (a sum first: finite sums need no second look)."""
    a = np.asarray(a)
    if a.dtype.kind not in "fc":
        return True
    if math.isfinite(np.add.reduce(a, axis=None)):
        return True
    return bool(np.isfinite(a).all())


def tangent_cc(q2: Any, dd: Any, r1: Any, r2: Any, *, tol: Tolerance) -> Any:
    """(h/d)² of two arcs with a round-off below the length tolerance taken as a tangency."""
    dist = np.sqrt(dd)
    scale = np.maximum(np.maximum(r1, r2), dist)
    eps = tol.length_abs + tol.length_rel * np.abs(scale)
    return np.where((q2 < 0) & (q2 * dd > -2 * eps * scale), 0.0, q2)


def tangent_lc(h2: Any, s: Any, r: Any, *, tol: Tolerance) -> Any:
    """h² of a line and an arc with a round-off below the length tolerance taken as zero."""
    eps = tol.length_abs + tol.length_rel * np.abs(np.maximum(r, np.abs(s)))
    return np.where((h2 < 0) & (h2 > -2 * eps * np.maximum(r, 1e-300)), 0.0, h2)


def _absmax(a: Any) -> float:
    """Largest absolute entry (NaN ignored)."""
    if type(a) is not _ND or a.ndim == 0:
        return abs(float(a))
    return float(np.fmax.reduce(np.abs(a), axis=None))


def _drawn_join(rt: Runtime, out: str, p: Any, q: Any) -> bool:
    """True when this replay already drew the line ``out`` through these very point arrays.

    The acceleration polygon redraws the posture's lines that the velocity
    polygon drew; replayed together they are drawn once.
    """
    hit = rt.joins.get(out)
    return hit is not None and hit[0] is p and hit[1] is q and rt.env.get(out) is hit[2]


class Runtime:
    """The state of one compiled evaluation.

    Attributes
    ----------
    env : dict
        Label -> array (what :class:`~graphkin.construction.protocol.Evaluation` returns).
    xy : dict
        Label -> Cartesian rows ``(x, y)`` of a point (or a circle's center,
        or a vector's components), read once.  Constant points have floats.
    unit : set
        Point labels stored with ``w == 1`` (or all NaN): their first two
        rows are their Cartesian coordinates.
    trig : dict
        Angle label -> ``(cos, sin)``.
    dirty : set
        Labels whose consumers must be checked for non-finite entries:
        inputs given with non-finite entries, points that may be at infinity.
    joins : dict
        Line label -> the point arrays it was drawn through (and the line).
    """

    __slots__ = ("env", "xy", "unit", "trig", "trig_off", "dirty", "joins")

    def __init__(self, env: dict[str, Array]) -> None:
        self.env = env
        self.xy: dict[str, tuple[Any, Any]] = {}
        self.unit: set[str] = set()
        self.trig: dict[str, tuple[Any, Any]] = {}
        self.trig_off: dict[tuple[str, float], tuple[Any, Any]] = {}
        self.dirty: set[str] = set()
        self.joins: dict[str, tuple[Any, Any, Any]] = {}

    # ---- inputs --------------------------------------------------------
    def arr(self, label: str) -> Array:
        """The value of ``label`` as a float array."""
        a = self.env[label]
        if type(a) is not _ND or a.dtype != np.float64:
            a = np.asarray(a, dtype=float)
        return a

    def P(self, label: str) -> tuple[Any, Any]:
        """Cartesian rows of a point (NaN for a point at infinity)."""
        r = self.xy.get(label)
        if r is not None:
            return r
        p = self.arr(label)
        if (p[..., 2] == 1.0).all():
            r = (p[..., 0], p[..., 1])
            self.unit.add(label)
        else:
            q = g.xy(p)
            r = (q[..., 0], q[..., 1])
            self.dirty.add(label)
        self.xy[label] = r
        return r

    def is_unit(self, label: str) -> bool:
        """True when the point's ``w`` is exactly 1 (so its rows are its Cartesian coordinates)."""
        if label not in self.xy:
            self.P(label)
        return label in self.unit

    def C(self, label: str) -> tuple[Any, Any]:
        """First two rows of a circle (its center) or of a vector (its components)."""
        r = self.xy.get(label)
        if r is not None:
            return r
        c = self.arr(label)
        r = (c[..., 0], c[..., 1])
        self.xy[label] = r
        return r

    V = C

    def rows(self, label: str) -> tuple[Any, Any, Any]:
        """The three homogeneous rows of a point, line or circle."""
        a = self.arr(label)
        return a[..., 0], a[..., 1], a[..., 2]

    def cs(self, label: str, offset: float = 0.0) -> tuple[Any, Any]:
        """The cosine and sine of an angle (plus a constant offset), computed once."""
        if offset == 0.0:
            r = self.trig.get(label)
            if r is None:
                t = self.arr(label)
                r = self.trig[label] = (np.cos(t), np.sin(t))
            return r
        r = self.trig_off.get((label, offset))
        if r is None:
            t = self.arr(label) + offset
            r = self.trig_off[(label, offset)] = (np.cos(t), np.sin(t))
        return r

    # ---- outputs -------------------------------------------------------
    def _forget(self, label: str) -> None:
        self.xy.pop(label, None)
        self.unit.discard(label)
        self.dirty.discard(label)
        self.trig.pop(label, None)
        if self.trig_off:
            for k in [k for k in self.trig_off if k[0] == label]:
                del self.trig_off[k]

    def new_point(self, label: str, shape: tuple[int, ...]) -> tuple[Array, Array]:
        """Store a new finite-form point ``(x, y, 1)``; returns its x and y rows to fill."""
        base = np.empty((3, *shape))
        base[2] = 1.0
        if shape:
            x, y = base[0], base[1]
            self.env[label] = base.T if len(shape) == 1 else np.moveaxis(base, 0, -1)
        else:
            x, y = base[0, ...], base[1, ...]
            self.env[label] = base
        self.xy[label] = (x, y)
        self.unit.add(label)
        if self.dirty:
            self.dirty.discard(label)
        if self.trig:
            self.trig.pop(label, None)
        if self.trig_off:
            for k in [k for k in self.trig_off if k[0] == label]:
                del self.trig_off[k]
        return x, y

    def new_rows(self, label: str, k: int, shape: tuple[int, ...], *,
                 center: bool = False) -> tuple[Array, ...]:
        """Store a new line, circle (``k = 3``) or vector (``k = 2``); returns its rows to fill.

        The block itself comes last.
        """
        base = np.empty((k, *shape))
        self._forget(label)
        if shape:
            rows = tuple(base[i] for i in range(k))
            self.env[label] = base.T if len(shape) == 1 else np.moveaxis(base, 0, -1)
        else:
            rows = tuple(base[i, ...] for i in range(k))
            self.env[label] = base
        if center or k == 2:
            self.xy[label] = (rows[0], rows[1])
        return (*rows, base)

    def put(self, label: str, value: Any) -> None:
        """Store any value (a scalar array, or what a general function returned)."""
        self._forget(label)
        self.env[label] = value


def generic_kernel(step: Any, tol: Tolerance) -> Kernel:
    """Run a step through its general function (no kernel, or an exact fallback)."""
    fn = OPS[step.op]
    ins, outs, params = step.inputs, step.outputs, step.params
    points = step.kind == "point"

    def run(rt: Runtime) -> None:
        vals = fn(*[rt.env[i] for i in ins], tol=tol, **params)
        for name, v in zip(outs, vals):
            rt.put(name, v)
            if points:
                rt.dirty.add(name)

    return run
