"""Many designs at once: the recorded constructions evaluated over designs and postures together.

A designer exploring link lengths changes a few dimensions of one mechanism
file.  The constructions do not change with the dimensions -- the same
posture groups (Sec. 2.8), the same polygons (Secs. 3.4-4.6), the same named
branches -- only the constants of a few steps do: a link's local
coordinates, an arc's radius, a frame pivot.  :func:`batch` builds the
constructions once, from the file, gives those constants a leading axis of
designs, and replays the whole construction on arrays of shape
``(designs, postures)``: no Python loop over designs or postures.

Dimensions are named as in the mechanism file: ``"links.3.C"`` is the point
``C`` of link 3 in link 3's own coordinates, given as an array of shape
``(M, 2)`` (one row per design; a ``(2,)`` pair is the same for every
design).

Branch continuity
-----------------
Every design keeps the branch names chosen at the file's posture for the
file's design (``left``/``right`` of the directed line of centers), posture
after posture, as :func:`graphkin.kinematics.sweep.sweep` does for one design:
away from a dead center, keeping the name is keeping continuity, for each
design separately.  Postures where a design cannot be assembled are NaN in
every column and False in :attr:`Batch.assembled`; a design that cannot be
assembled anywhere in the range is flagged in :attr:`Batch.never_assembles`.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 1.9 (Grashof's law), Sec. 1.10 (transmission angle), Sec. 2.8 (posture),
Secs. 3.4-3.6 and 4.2-4.6 (polygons).
"""

from __future__ import annotations

import copy
import dataclasses
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphkin.construction import Construction, Evaluation
from graphkin.errors import AssemblyError, GraphkinError, InputError
from graphkin.kinematics.assembly_words import point_words
from graphkin.kinematics.sweep.columns import _columns
from graphkin.kinematics.sweep.drive_range import _count, _drive_values
from graphkin.kinematics.sweep.engine import _Block, _dyads, _Engine, _engine
from graphkin.kinematics.sweep.extra_columns import _angle_at
from graphkin.kinematics.sweep.four_bar import Grashof, fourbar, grashof
from graphkin.kinematics.sweep.run import _blank
from graphkin.mechanisms.model import Drive, Link, Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["Batch", "batch", "with_dimensions"]

Array = np.ndarray

#: Designs are evaluated in groups of about this many (design, posture) entries.
BATCH_BLOCK = 1 << 19

XY = tuple[float, float]


# ---------------------------------------------------------------------------
# dimensions
# ---------------------------------------------------------------------------

def _parse_key(mech: Mechanism, key: str) -> tuple[str, str]:
    """``"links.3.C"`` -> ``("3", "C")``, or a one-line error naming the key."""
    parts = str(key).split(".")
    if len(parts) != 3 or parts[0] != "links":
        raise InputError("a dimension is written links.<link>.<point>, e.g. links.3.C",
                         key=str(key), file=mech.source)
    _, lid, name = parts
    if lid not in mech.links:
        raise InputError(f"there is no link {lid} (links: {', '.join(mech.links)})",
                         key=str(key), file=mech.source)
    if name not in mech.links[lid].points:
        raise InputError(f"link {lid} has no point {name} "
                         f"(its points: {', '.join(mech.links[lid].points)})",
                         key=str(key), file=mech.source)
    return lid, name


def _dimension_arrays(mech: Mechanism, dimensions: Mapping[str, Any]
                      ) -> tuple[dict[tuple[str, str], Array], int]:
    """Each dimension as an ``(M, 2)`` array, and the number of designs ``M``."""
    if not dimensions:
        raise InputError("no dimensions to vary: give at least one, e.g. {'links.3.C': array}",
                         key="dimensions", file=mech.source)
    raw: dict[tuple[str, str], Array] = {}
    for key, value in dimensions.items():
        where = _parse_key(mech, key)
        try:
            a = np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            raise InputError("give the point's local (x, y) as numbers: an array of shape "
                             "(designs, 2) or one pair", key=str(key), file=mech.source) from None
        if a.ndim not in (1, 2) or a.shape[-1] != 2:
            raise InputError(f"give the point's local (x, y) as an array of shape (designs, 2) "
                             f"or one pair, not shape {a.shape}", key=str(key), file=mech.source)
        if not np.isfinite(a).all():
            raise InputError("every coordinate must be a finite number", key=str(key),
                             file=mech.source)
        raw[where] = a
    counts = {a.shape[0] for a in raw.values() if a.ndim == 2}
    if len(counts) > 1:
        raise InputError("the dimensions give different numbers of designs: "
                         + ", ".join(f"links.{k[0]}.{k[1]}: {a.shape[0]}" for k, a in raw.items()
                                     if a.ndim == 2), key="dimensions", file=mech.source)
    m = counts.pop() if counts else 1
    if m < 1:
        raise InputError("no designs: the arrays are empty", key="dimensions", file=mech.source)
    return {k: np.broadcast_to(a, (m, 2)) for k, a in raw.items()}, m


def with_dimensions(mech: Mechanism, dimensions: Mapping[str, Any]) -> Mechanism:
    """The mechanism with some points moved in their links' own coordinates (one design).

    Parameters
    ----------
    mech : Mechanism
    dimensions : mapping
        ``"links.<link>.<point>"`` -> ``(x, y)`` in the link's coordinates.

    Returns
    -------
    Mechanism
        A new mechanism; slider and slot lines through a moved point move with it.

    Raises
    ------
    InputError
        A key that names no link or point, or a value that is not a pair of numbers.

    Examples
    --------
    >>> import graphkin
    >>> m = graphkin.examples.fourbar()
    >>> longer = with_dimensions(m, {"links.3.C": (19.0, 0.0)})
    >>> longer.links["3"].points["C"], m.links["3"].points["C"]
    ((19.0, 0.0), (18.0, 0.0))
    """
    arrays, m = _dimension_arrays(mech, dimensions)
    if m != 1:
        raise InputError("with_dimensions makes one design: give one (x, y) per point "
                         "(use graphkin.batch for many)", key="dimensions", file=mech.source)
    return _design(mech, {k: (float(a[0, 0]), float(a[0, 1])) for k, a in arrays.items()})


def _design(mech: Mechanism, moved: Mapping[tuple[str, str], XY]) -> Mechanism:
    links = dict(mech.links)
    swap: dict[int, XY] = {}
    for (lid, name), xy in moved.items():
        old = links[lid].points[name]
        pts = dict(links[lid].points)
        pts[name] = xy
        links[lid] = Link(lid, pts)
        swap[id(old)] = xy

    def move(obj: Any) -> Any:
        changes = {f: swap[id(getattr(obj, f))] for f in ("p0", "p1")
                   if getattr(obj, f, None) is not None and id(getattr(obj, f)) in swap}
        return dataclasses.replace(obj, **changes) if changes else obj

    return dataclasses.replace(mech, links=links,
                               sliders=tuple(move(s) for s in mech.sliders),
                               slots=tuple(move(s) for s in mech.slots),
                               rolling=tuple(move(r) for r in mech.rolling))


# ---------------------------------------------------------------------------
# the constructions with a leading axis of designs
# ---------------------------------------------------------------------------

_LOCAL = ("xy", "local_p", "local_q", "local_a", "local_b")


def _provenance(mech: Mechanism, cx: Construction) -> dict[tuple[int, str], tuple[Any, ...]]:
    """Which file dimensions each step constant is: (step, param) -> where it comes from.

    A point's local coordinates are the file's own pair (``("point", link,
    name)``); an arc's radius is the distance between the arc's center and
    the point it locates on the link that carries both (``("radius", link,
    center, point)``).  Constants with no such source stay as they are (and
    :func:`_check` finds any that should have changed).
    """
    where: dict[int, tuple[str, str]] = {}
    for lid, link in mech.links.items():
        for name, xy in link.points.items():
            where.setdefault(id(xy), (lid, name))
    users: dict[str, list[int]] = {}
    for s in cx.steps:
        for i in s.inputs:
            users.setdefault(i, []).append(s.index)
    out: dict[tuple[int, str], tuple[Any, ...]] = {}
    for s in cx.steps:
        for p in _LOCAL:
            v = s.params.get(p)
            if v is not None and id(v) in where:
                out[(s.index, p)] = ("point", *where[id(v)])
        if s.op in ("add_angle", "line_at_angle") and "offset" in s.params:
            src = _slider_angle(mech, s, where)
            if src is not None:
                out[(s.index, "offset")] = src
        if s.op == "circle" and "radius" in s.params:
            center = s.inputs[0]
            r = float(s.params["radius"])
            for k in users.get(s.outputs[0], ()):
                user = cx.steps[k]
                if not user.op.startswith("intersect"):
                    continue
                x = user.outputs[0]
                for lid, link in mech.links.items():
                    pts = link.points
                    if center in pts and x in pts and math.isclose(
                            math.dist(pts[center], pts[x]), r, rel_tol=1e-12, abs_tol=1e-300):
                        out[(s.index, "radius")] = ("radius", lid, center, x)
                        break
                if (s.index, "radius") in out:
                    break
    return out


def _slider_angle(mech: Mechanism, step: Any, where: Mapping[int, tuple[str, str]]
                  ) -> tuple[Any, ...] | None:
    """The slider whose line's direction φ an angle step adds: ``("slide", sign, p0, p1)``.

    A slider keeps its angle on the link it slides on: θ_link = θ_on + φ
    (``add_angle``, sign +1), θ_on = θ_link - φ (sign -1), and the path of a
    point of ``on`` is the line at θ_link + φ (``line_at_angle``, labelled
    ``l_<P>(<slider key>)``).  φ is the direction of the line's two points in
    ``on``'s coordinates (Sec. 2.8), so a point of the line moved by the batch
    tilts it for that design.  ``p0``/``p1`` are ``(link, name)`` of the file's
    points, or None for a point written as a pair (which the batch cannot move).
    """
    value = float(step.params["offset"])
    out = step.outputs[0]
    for sl in mech.sliders:
        ends = (where.get(id(sl.p0)), where.get(id(sl.p1)))
        phi = sl.direction_angle
        if step.op == "line_at_angle":
            if out.endswith(f"({sl.key})") and math.isclose(value, phi, abs_tol=1e-15):
                return ("slide", 1.0, *ends)
            continue
        for sign, moved in ((1.0, sl.link), (-1.0, sl.on)):
            if out == f"θ{moved}" and math.isclose(value, sign * phi, abs_tol=1e-15):
                return ("slide", sign, *ends)
    return None


def _param_values(src: tuple[Any, ...], mech: Mechanism,
                  arrays: Mapping[tuple[str, str], Array]) -> Array | None:
    """The constant for every design (``(M, 1, 2)`` or ``(M, 1)``), or None if it does not vary."""
    def local(lid: str, name: str) -> Array | None:
        return arrays.get((lid, name))

    if src[0] == "point":
        a = local(src[1], src[2])
        return None if a is None else a[:, None, :]
    if src[0] == "slide":
        _, sign, e0, e1 = src
        moved = [None if e is None else local(*e) for e in (e0, e1)]
        if moved[0] is None and moved[1] is None:
            return None
        ends = [m if m is not None else np.asarray(mech.links[e[0]].points[e[1]], dtype=float)
                for m, e in zip(moved, (e0, e1))]
        d = ends[1] - ends[0]
        return sign * np.arctan2(d[..., 1], d[..., 0])[:, None]
    _, lid, c, x = src
    ac, ax = local(lid, c), local(lid, x)
    if ac is None and ax is None:
        return None
    pts = mech.links[lid].points
    pc = ac if ac is not None else np.asarray(pts[c], dtype=float)
    px = ax if ax is not None else np.asarray(pts[x], dtype=float)
    d = px - pc
    return np.hypot(d[..., 0], d[..., 1])[:, None]


@dataclass
class _Designs:
    """The construction with design-dependent constants, and its per-design givens."""

    cx: Construction
    params: dict[tuple[int, str], Array]
    points: dict[str, Array]  # frame points that move: label -> (M, 1, 3)

    def chunk(self, lo: int, hi: int) -> tuple[Construction, dict[str, Array]]:
        """The construction and the given points for designs ``lo:hi``."""
        steps = []
        for s in self.cx.steps:
            ch = {p: v[lo:hi] for (k, p), v in self.params.items() if k == s.index}
            steps.append(dataclasses.replace(s, params={**s.params, **ch}) if ch else s)
        return Construction(steps, self.cx.title), {k: v[lo:hi] for k, v in self.points.items()}


def _with_designs(eng: _Engine, cx: Construction,
                  arrays: Mapping[tuple[str, str], Array]) -> _Designs:
    mech = eng.mech
    prov = _provenance(mech, cx)
    params: dict[tuple[int, str], Array] = {}
    points: dict[str, Array] = {}
    steps = list(cx.steps)
    for (k, p), src in prov.items():
        v = _param_values(src, mech, arrays)
        if v is None:
            continue
        s = steps[k]
        if s.op == "point" and p == "xy":
            # a moved frame point: given for each design, as the drive is
            steps[k] = dataclasses.replace(s, op="input", params={"name": s.outputs[0]})
            points[s.outputs[0]] = np.concatenate([v, np.ones((*v.shape[:-1], 1))], axis=-1)
            continue
        params[(k, p)] = v
    return _Designs(Construction(steps, cx.title), params, points)


def _check(eng: _Engine, cx: Construction, designs: _Designs,
           arrays: Mapping[tuple[str, str], Array], m: int) -> None:
    """Build the constructions from scratch for two designs and compare every constant.

    The batch's constants are derived from the file's (:func:`_provenance`);
    this makes sure they are what the posture and polygon builders would give
    each design, or says which dimension cannot be varied this way.
    """
    for i in dict.fromkeys((0, m - 1)):
        moved = {k: (float(a[i, 0]), float(a[i, 1])) for k, a in arrays.items()}
        try:
            other = _Engine(_design(eng.mech, moved), eng.tol)
        except (AssemblyError, GraphkinError):
            continue  # this design cannot be built at any drive angle: nothing to compare
        ocx = other.combined if eng.combined is not None else (
            other.pc.construction if other.pc is not None else None)
        if ocx is None or len(ocx) != len(cx) or \
                [s.label for s in ocx.steps] != [s.label for s in cx.steps]:
            raise InputError("these dimensions change how the mechanism is constructed (the "
                             "steps differ from the file's design), so they cannot be batched",
                             key="dimensions", file=eng.mech.source)
        for s, o in zip(cx.steps, ocx.steps):
            for p, want in o.params.items():
                if p == "branch":
                    continue
                got = designs.params.get((s.index, p))
                if got is not None:
                    have: Any = got[i].reshape(-1)
                elif s.outputs[0] in designs.points and p == "xy":
                    have = designs.points[s.outputs[0]][i, 0, :2]
                else:
                    have = s.params.get(p)
                try:
                    same = np.allclose(np.asarray(have, dtype=float),
                                       np.asarray(want, dtype=float), rtol=1e-12, atol=1e-12 *
                                       max(1.0, eng.mech.scale))
                except (TypeError, ValueError):
                    same = have == want
                if not same:
                    raise InputError(
                        f"the construction of {point_words(s.outputs[0])} depends on these "
                        "dimensions in a way the batch cannot follow yet; sweep these designs "
                        "one by one",
                        key="dimensions", file=eng.mech.source)


# ---------------------------------------------------------------------------
# the result
# ---------------------------------------------------------------------------

@dataclass
class Batch:
    """Many designs of one mechanism, each swept over the same drive values.

    Attributes
    ----------
    mechanism : Mechanism
        The file's design (its branch names are every design's).
    drive : Drive
        The swept drive.
    values : ndarray, shape (N,)
        Drive values: radians for an angle, the file's length unit for a slider.
    dimensions : dict
        ``"links.<link>.<point>"`` -> ``(M, 2)``: the varied points, one row per design.
    columns : dict
        The columns of ``docs/formats/sweep-csv.md``, each of shape ``(M, N)``: row ``m`` is
        what ``sweep`` gives design ``m``; NaN where it cannot be assembled.
    valid, assembled : ndarray of bool, shape (M, N)
        As for a :class:`~graphkin.kinematics.sweep.Sweep`, per design.
    branches : dict
        Step label -> the branch every design keeps.
    notes : list of str

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 2.8, 3.4-3.6, 4.2-4.6.
    """

    mechanism: Mechanism
    drive: Drive
    values: Array
    dimensions: dict[str, Array]
    columns: dict[str, Array]
    valid: Array
    assembled: Array
    branches: dict[str, str] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    def __len__(self) -> int:
        return int(self.valid.shape[0])

    @property
    def designs(self) -> int:
        """The number of designs ``M``."""
        return len(self)

    @property
    def never_assembles(self) -> Array:
        """Shape (M,): designs that cannot be assembled at any posture of the range."""
        return np.asarray(~self.assembled.any(axis=1))

    @property
    def always_assembles(self) -> Array:
        """Shape (M,): designs that can be assembled at every posture of the range."""
        return np.asarray(self.assembled.all(axis=1))

    def design(self, m: int) -> Mechanism:
        """Design ``m`` as a mechanism of its own (to solve, draw or sweep it alone)."""
        moved = {_parse_key(self.mechanism, k): (float(a[m, 0]), float(a[m, 1]))
                 for k, a in self.dimensions.items()}
        return _design(self.mechanism, moved)

    def grashof(self) -> list[Grashof]:
        """Grashof's classification of every design (four-bars only), Sec. 1.9, Eq. 1.6."""
        base = fourbar(self.mechanism)
        a, b, c, d = base.pins
        ends = {base.frame: (a, d), base.input: (a, b), base.coupler: (b, c),
                base.output: (d, c)}
        lengths: dict[str, Array] = {}
        for lid, (p, q) in ends.items():
            pts = self.mechanism.links[lid].points
            pp = np.broadcast_to(np.asarray(pts[p], dtype=float), (len(self), 2))
            qq = np.broadcast_to(np.asarray(pts[q], dtype=float), (len(self), 2))
            pp = self.dimensions.get(f"links.{lid}.{p}", pp)
            qq = self.dimensions.get(f"links.{lid}.{q}", qq)
            lengths[lid] = np.hypot(*(qq - pp).T)
        return [grashof(dataclasses.replace(base, lengths={k: float(v[m])
                                                          for k, v in lengths.items()}))
                for m in range(len(self))]


# ---------------------------------------------------------------------------
# evaluation
# ---------------------------------------------------------------------------

def batch(mech: Mechanism, dimensions: Mapping[str, Any], count: int = 360,
          start: float | None = None, stop: float | None = None, *,
          tol: Tolerance | None = None, transmission: bool = False,
          progress: Callable[[float], None] | None = None) -> Batch:
    """Sweep many designs of a mechanism at once: dimensions as arrays, one construction.

    Parameters
    ----------
    mech : Mechanism
        The file's design: it fixes the constructions and their branch names.
    dimensions : mapping
        ``"links.<link>.<point>"`` -> array of shape ``(M, 2)`` (the point's
        local coordinates, one row per design) or ``(2,)`` (every design).
    count, start, stop
        The drive values, as for :func:`graphkin.kinematics.sweep.sweep`.
    tol : Tolerance, optional
    transmission : bool
        Add ``transmission_<P>`` columns (Sec. 1.10), as ``sweep`` does.
    progress : callable, optional
        Called with the fraction done after each group of designs.

    Returns
    -------
    Batch
        Columns of shape ``(M, N)``.

    Raises
    ------
    InputError
        A key that names no link or point, arrays of different lengths, a
        mechanism the constructions cannot solve one group at a time (rolling
        contact, several loops solved together), or dimensions that change the
        constructions themselves.

    Notes
    -----
    The constructions are built once (from the file's design, as a sweep
    builds them); the constants that depend on the varied points (local
    coordinates, arc radii, frame pivots) get a leading axis of designs, and
    the compiled replay runs on ``(designs, postures)`` arrays.  The derived
    constants are checked against constructions built from scratch for the
    first and last design (the first time a mechanism's set of varied points
    is batched).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (posture), Secs. 3.4-3.6 and
    4.2-4.6 (polygons).

    Examples
    --------
    Three coupler lengths of the four-bar of Example 3.1 (crank 4, rocker 11,
    frame 10, coupler 18 in the file), one turn of the crank in 8 steps:

    >>> import numpy as np, graphkin
    >>> m = graphkin.examples.fourbar()
    >>> b = batch(m, {"links.3.C": [[17.0, 0], [18.0, 0], [19.0, 0]]}, count=8)
    >>> b.columns["angle_4"].shape
    (3, 8)
    >>> bool(np.allclose(b.columns["x_C"][1], m.sweep(count=8).columns["x_C"], equal_nan=True))
    True
    >>> b.assembled.sum(axis=1)  # 4 + 18 > 10 + 11: the longer couplers cannot follow the crank
    array([8, 6, 6])
    """
    count = _count(count, mech)
    tol = tol or DEFAULT_TOL
    arrays, m = _dimension_arrays(mech, dimensions)
    eng = _engine(mech, tol)
    if eng.method != "construction" or eng.pc is None:
        raise InputError(f"a batch of designs needs a mechanism solved one group at a time by "
                         f"the constructions: {eng.reason}", key="dimensions", file=mech.source)
    if mech.rates is not None:
        raise InputError("a batch of designs takes the drive's own rates, not [rates] of "
                         "another link", key="rates", file=mech.source)
    rated = eng.combined is not None
    cx = eng.combined if eng.combined is not None else eng.pc.construction
    designs = _with_designs(eng, cx, arrays)
    checked = ("batch-checked", frozenset(arrays))
    if checked not in eng.extras:
        # once per mechanism and set of varied points: the derivation does not depend on values
        _check(eng, cx, designs, arrays, m)
        eng.extras[checked] = True
    user, dv, _ = _drive_values(eng, count, start, stop)
    given0: dict[str, Any] = dict(eng.held)
    if rated:
        given0.update(eng.rate_given)
        keep = eng.keep
    else:
        keep = frozenset(mech.point_names) | frozenset(eng.pc.angles.values()) | \
            frozenset(eng.pc.inputs) | frozenset(a for a, _ in eng.pc.anchors.values())
    if transmission:
        keep = keep | {x for d in _dyads(eng.pc) for x in d}
    reader = copy.copy(eng)
    reader.const_rows = {}
    per = max(1, BATCH_BLOCK // count)
    parts: list[tuple[dict[str, Array], Array, Array]] = []
    for lo in range(0, m, per):
        hi = min(m, lo + per)
        mc = hi - lo
        ccx, pts = designs.chunk(lo, hi)
        given = dict(given0)
        given.update(pts)
        for lab, inp in eng.inputs_at(np.asarray(dv, dtype=float)).items():
            given[lab] = np.broadcast_to(inp, (mc, count))
        ev = ccx.evaluate_for(keep, given, tol=tol, strict=False)
        flat = _flatten(ev, mc, count)
        fa = ev.failed_at
        n_posture = eng.n_posture if rated else len(cx)
        assembled = np.ones(mc * count, dtype=bool) if fa is None else \
            ~((np.broadcast_to(fa, (mc, count)) >= 0) &
              (np.broadcast_to(fa, (mc, count)) < n_posture)).reshape(-1)
        valid = np.broadcast_to(np.asarray(ev.valid), (mc, count)).reshape(-1).copy()
        blk = _Block(np.tile(dv, mc), flat, flat if rated else None, flat if rated else None,
                     user=np.tile(user, mc))
        cols = _columns(reader, blk)
        if transmission:
            for pin, c1, c2 in _dyads(eng.pc):
                v = flat.values
                cols[f"transmission_{pin}"] = np.broadcast_to(
                    _angle_at(v[pin], v[c1], v[c2]), (mc * count,)).astype(float)
        if not valid.all():
            _blank(cols, assembled, valid)
            for k in cols:
                if k.startswith("transmission_"):
                    cols[k][~assembled] = np.nan
        parts.append(({k: np.asarray(v).reshape(mc, count) for k, v in cols.items()},
                      valid.reshape(mc, count), assembled.reshape(mc, count)))
        if progress is not None:
            progress(hi / m)
    if len(parts) == 1:
        columns, valid_all, assembled_all = parts[0]
    else:
        columns = {k: np.concatenate([p[0][k] for p in parts]) for k in parts[0][0]}
        valid_all = np.concatenate([p[1] for p in parts])
        assembled_all = np.concatenate([p[2] for p in parts])
    notes: list[str] = []
    if eng.built_at is not None:
        notes.append(f"the file's drive cannot be assembled; the constructions were laid out "
                     f"at {math.degrees(eng.built_at):.2f}° (branches by the assembly hints there)")
    never = ~assembled_all.any(axis=1)
    if never.any():
        notes.append(f"{int(never.sum())} of {m} designs cannot be assembled anywhere in the range")
    return Batch(mech, eng.drive, dv, {f"links.{k[0]}.{k[1]}": np.array(v)
                                       for k, v in arrays.items()},
                 columns, valid_all, assembled_all, dict(eng.pc.branches), notes)


def _flatten(ev: Evaluation, mc: int, n: int) -> Evaluation:
    """The values of a ``(designs, postures)`` replay as ``(designs × postures)`` rows.

    A value with no leading axes (a constant of the file) is kept as it is;
    one with a design axis only (shape ``(M, 1, ...)``) is spread over the postures.
    """
    out: dict[str, Array] = {}
    for k, v in ev.values.items():
        a = np.asarray(v)
        if a.ndim <= 1:
            out[k] = a
        elif a.ndim == 2:
            out[k] = np.broadcast_to(a, (mc, n)).reshape(mc * n)
        else:
            # component-major, as the kernels store a point (x, y and w rows each contiguous),
            # so that this and the columns read from it are views, not copies
            c = a.shape[-1]
            out[k] = np.moveaxis(np.broadcast_to(a, (mc, n, c)), -1, 0).reshape(c, mc * n).T
    return Evaluation(out, ev.valid, None, ev.unit)
