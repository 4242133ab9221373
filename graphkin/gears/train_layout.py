"""A gear-train file laid out as a mechanism: where its gears stand, so that it can be drawn.

A train file (docs/formats/gears.md, "Gear trains") names its gears by their
teeth or pitch radii, the meshes and the member carrying both axes of each
mesh; it does not say where the gears stand.  :func:`train_mechanism` lays it
out as a mechanism file of ``[[rolling]]`` circles (as Example 11.7 is
written), so ``graphkin live`` can open it:

1. **Sizes.** Pitch radii are the ``[radii]`` (in the file's ``units``, mm
   by default), or ``N m / 2`` (Eq. 7.2) for ``[teeth]``, with the file's
   ``module`` or ``diametral_pitch`` (m = 1/P), else a nominal module
   ``m = 1 mm``: only the ratios of a train count (Eq. 7.24), and
   ``graphkin live`` says so.
2. **Links.** Members on one shaft (``[[joined]]``) are one link; a member
   given at rest (``0`` in ``[speeds]``/``[turns]``) is part of the frame,
   link 1, as the book draws a fixed ring or sun; the first other given
   motion is the drive (at 0°: every link as drawn), its ω the given motion
   (a turn ``[turns]`` becomes that turn per second), and a second input
   ``follows`` it at the ratio of their motions, so both turn together.
3. **Axes.** A member whose axis is fixed (an arm, a gear in a mesh carried
   by the frame, a gear held or driven) turns about a frame point; in a mesh
   carried by an arm, such a gear is coaxial with the arm (a sun, a ring)
   and the other gear is a planet, its axis a point of the arm; when neither
   gear of an arm's mesh is known, a gear in mesh with a planet is coaxial
   with the arm (the ring round a planet), else the mesh's first gear is.
   An arm may be carried by another arm: a planet of arm A that is the arm
   B of another mesh (or on B's shaft), or a planet of A in a mesh B
   carries, puts B's axis on A's pin, and B's planets are points of B.
   Where these rules leave no consistent layout, every choice of each arm
   mesh's planet is tried (an arm as a planet before a gear given a
   motion).  A member given a motion on a moving pin is driven by its angle
   relative to that arm, at ``ω − ω_arm`` (the train's, Eq. 7.25).
4. **Distances.** Meshing axes are ``R1 + R2`` apart (external) or
   ``R_ring − R_planet`` (internal).  Going through the meshes in the file's
   order, the first mesh that reaches an axis places it; each later mesh
   between two placed axes is checked.  Where the distance differs (the
   teeth of Ferguson's paradox, Example 7.10: a 20-tooth planet in mesh with
   gears of 100, 101 and 99 teeth on one axis) the gears are drawn with
   their *operating* pitch circles at the distance the layout has, which
   divide it in the ratio of the teeth (Sec. 7.9, Eq. 7.2: what
   profile-shifted teeth run on), so every speed ratio is still the teeth's;
   the layout says so in one line.
5. **Directions.** The first axis is at the origin; a new axis goes from the
   axis that places it in the first of 24 directions (every 15°, starting
   with 0° or straight away from the centroid of the axes placed so far,
   then alternating either side) where each of its gears clears every gear
   already drawn, except the gears of its own axis and of an axis a mesh
   joins to it (they stand where the train puts them, one behind the other
   as in Fig. 7.36).  A ring clears a gear wholly inside or outside its
   pitch circle.  If no direction clears, the one with the least overlap is
   taken and said so.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.9, 7.12-7.16 (Figs. 7.35-7.44),
Example 11.7 (Fig. 11.17).
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.errors import InputError
from graphkin.gears.train import FRAME, Contact, Mesh, Train, solve
from graphkin.tolerance import DEFAULT_TOL, is_zero

__all__ = ["TrainLayout", "train_mechanism", "NOMINAL_MODULE", "clearance"]

NOMINAL_MODULE = 1.0
"""The module (mm per tooth) a train given by ``[teeth]`` is drawn with: ``R = N/2`` mm."""

_FRAME_LINK = "1"
_DIRECTIONS = 24


@dataclass
class TrainLayout:
    """A train laid out as a mechanism.

    Attributes
    ----------
    data : dict
        The mechanism file (as parsed TOML would be).
    link_of : dict
        Each member of the train -> its link (``"1"`` for the frame).
    center : dict
        Each gear -> its axis ``(x, y)`` as drawn (in the mechanism's ``units``).
    radius : dict
        Each gear -> its standard pitch radius (in the mechanism's ``units``).
    axis_point : dict
        Each gear -> the name of its axis point in the mechanism file.
    ring : set
        The gears that are the outer gear of an internal mesh.
    spaced : set
        Pairs of gears drawn where the train puts them (one axis, or two axes a
        mesh joins); every other pair is kept clear of each other.
    operating : list
        For each mesh, the pitch radii its rolling circles have (driver, driven).
    notes : list of str
        One line each: what the layout chose or changed, and why.
    """

    data: dict[str, Any]
    link_of: dict[str, str]
    center: dict[str, tuple[float, float]]
    radius: dict[str, float]
    axis_point: dict[str, str] = field(default_factory=dict)
    ring: set[str] = field(default_factory=set)
    spaced: set[frozenset[str]] = field(default_factory=set)
    operating: list[tuple[float, float]] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


def clearance(p: tuple[float, float], r: float, p_ring: bool,
              q: tuple[float, float], s: float, q_ring: bool) -> float:
    """How far apart two pitch circles are drawn (negative: they overlap).

    A ring (the outer gear of an internal mesh) clears a gear wholly inside
    or wholly outside its pitch circle.
    """
    d = math.hypot(p[0] - q[0], p[1] - q[1])
    outside = d - (r + s)
    inside = max(s - (d + r) if q_ring else -math.inf, r - (d + s) if p_ring else -math.inf)
    return max(outside, inside)


class _Layout:
    """The steps of :func:`train_mechanism` (docstring of the module)."""

    def __init__(self, train: Train, source: str) -> None:
        self.t = train
        self.src = source
        self.notes: list[str] = []
        self.shaft = train.shaft()
        module = NOMINAL_MODULE if train.module is None else train.module
        scale = module / 2.0 if train.by_teeth else 1.0
        self.unit = train.length_unit if train.module is not None or not train.by_teeth \
            else "mm"
        self.r = {g: float(n) * scale for g, n in train.size.items()}
        self.ring = {(m.driven if train.size[m.driven] > train.size[m.driver] else m.driver)
                     for m in train.meshes if m.contact == Contact.INTERNAL}
        for i, m in enumerate(train.meshes):
            if m.contact == Contact.INTERNAL and train.size[m.driver] == train.size[m.driven]:
                raise InputError(f"gears {m.driver!r} and {m.driven!r} are one size: a ring "
                                 "is larger than the gear inside it", key=f"mesh[{i}].contact",
                                 file=source)
        frame = self.shaft[FRAME]
        self.held = {self.shaft[m] for m, v in train.given.items() if v == 0.0} | {frame}

    # --- links ---------------------------------------------------------------------------
    def link(self, member: str) -> str:
        s = self.shaft[member]
        return _FRAME_LINK if s in self.held else self.link_names[s]

    def name_links(self) -> None:
        taken = {_FRAME_LINK}
        self.link_names: dict[str, str] = {}
        for m in self.t.members:
            s = self.shaft[m]
            if s in self.held or s in self.link_names:
                continue
            name = s
            if name in taken:   # a moving member named 1: the frame is link 1
                name = _fresh(f"{s}m", taken)
                self.notes.append(f"member {s!r} is link {name!r} (link 1 is the frame)")
            taken.add(name)
            self.link_names[s] = name

    # --- which gears are coaxial with their arm --------------------------------------------
    def classify(self) -> None:
        """Which gear of each arm's mesh is a planet of that arm, which is on its axis.

        A gear held, on the frame's axes, or given a motion turns about a frame
        point; so does an arm unless a mesh puts it on another arm.  In a mesh
        carried by arm ``A``, a gear on ``A``'s axis (``A`` itself, a gear that
        turns about a frame point when ``A`` does, or a planet of another arm,
        which cannot also be ``A``'s) makes the other gear a planet of ``A``.
        When both would be on ``A``'s axis and one of them is another arm (or
        on an arm's shaft), that arm is the planet: its axis is a point of
        ``A``, an arm carried by an arm (Sec. 7.15, Fig. 7.41 with a planet
        that is itself an arm).
        """
        t, sh = self.t, self.shaft
        arms = {sh[a] for a in t.arms}
        hard = set(self.held)
        for m in t.meshes:
            if m.arm == FRAME:
                hard |= {sh[m.driver], sh[m.driven]}
        self.hard = hard
        central: set[str] = hard | {sh[m] for m in t.given} | arms
        soft = arms - hard
        self.planet_of: dict[str, str] = {}
        self.planet_mesh: dict[str, int] = {}

        def on_axis(g: str, arm: str) -> bool:
            if g == arm:
                return True
            if g in self.planet_of:
                return self.planet_of[g] != arm
            return g in central

        todo = [i for i, m in enumerate(t.meshes) if m.arm != FRAME]
        while todo:
            progress = False
            for i in list(todo):
                m = t.meshes[i]
                a, b, arm = sh[m.driver], sh[m.driven], sh[m.arm]
                if on_axis(a, arm) and on_axis(b, arm):
                    # an arm (or a gear on an arm's shaft) on the axis of a gear this arm
                    # carries: the inner arm is a planet of this one
                    cand = [g for g in (a, b) if g in soft and g != arm
                            and g not in self.planet_of]
                    if len(cand) == 1:
                        self.planet_of[cand[0]] = arm
                        self.planet_mesh[cand[0]] = i
                        central.discard(cand[0])
                        progress = True
                else:
                    for x, y in ((a, b), (b, a)):
                        if on_axis(x, arm) and y not in self.planet_of and y not in central:
                            self.planet_of[y] = arm
                            self.planet_mesh[y] = i
                            progress = True
                if all(g in central or g in self.planet_of for g in (a, b)):
                    todo.remove(i)
            if progress or not todo:
                continue
            # stuck: a gear in mesh with a planet is coaxial with the arm (a ring), else the
            # first gear of the first open mesh is
            for i in todo:
                m = t.meshes[i]
                a, b = sh[m.driver], sh[m.driven]
                if a in self.planet_of and b not in self.planet_of:
                    central.add(b)
                    break
                if b in self.planet_of and a not in self.planet_of:
                    central.add(a)
                    break
            else:
                central.add(sh[t.meshes[todo[0]].driver])
        self.central = central
        try:
            self._axes()
        except InputError as exc:   # the rule above fails an arm on an arm: search
            if not self._search(given={sh[m] for m in t.given}, arms=arms):
                raise exc from None

    def _axes(self) -> None:
        """The axes of :attr:`planet_of`: each gear on its arm's axis unless it is its planet."""
        t, sh = self.t, self.shaft
        self.axis = {s: s for s in dict.fromkeys(sh.values())}
        for m in t.meshes:
            a, b, arm = sh[m.driver], sh[m.driven], sh[m.arm]
            if m.arm == FRAME:
                continue
            for g in (a, b):
                if self.planet_of.get(g) != arm:
                    self._union(g, arm)
        self._carriers()
        for i, m in enumerate(t.meshes):
            if self._root(sh[m.driver]) == self._root(sh[m.driven]):
                raise InputError(f"gears {m.driver!r} and {m.driven!r} would turn about one "
                                 "axis and cannot mesh: no planar layout of this train (each "
                                 "is joined to the other, or held, driven, an arm or on the "
                                 "frame's axes, so coaxial with the arm carrying their mesh)",
                                 key=f"mesh[{i}].gears", file=self.src)

    def _search(self, given: set[str], arms: set[str]) -> bool:
        """Every choice of the planet of each arm's mesh, the fewest given gears and arms first.

        A planet that is an arm (an arm on an arm) counts 1, a gear given a
        motion 2 (an input shaft is rather on a frame axis), any other gear 0.

        Used when the rule of :meth:`classify` leaves no planar layout (a gear
        given a motion, or an arm, that is a planet of another arm); the first
        choice whose axes are consistent (:meth:`_axes`) is kept.  At most
        2^12 choices; returns whether one was found.
        """
        t, sh = self.t, self.shaft
        carried = [i for i, m in enumerate(t.meshes) if m.arm != FRAME]
        if len(carried) > 12:
            return False
        options = []
        for i in carried:
            m = t.meshes[i]
            options.append([g for g in (sh[m.driver], sh[m.driven])
                            if g not in self.hard and g != sh[m.arm]])
        choices = []
        for pick in itertools.product(*options):
            planet_of: dict[str, str] = {}
            where: dict[str, int] = {}
            for i, g in zip(carried, pick, strict=True):
                arm = sh[t.meshes[i].arm]
                if planet_of.setdefault(g, arm) != arm:
                    break
                where.setdefault(g, i)
            else:
                cost = sum(1 if g in arms else 2 if g in given else 0 for g in planet_of)
                choices.append((cost, planet_of, where))
        for _, planet_of, where in sorted(choices, key=lambda c: c[0]):
            self.planet_of, self.planet_mesh = planet_of, where
            try:
                self._axes()
            except InputError:
                continue
            return True
        return False

    def _carriers(self) -> None:
        """Each axis -> the member it is a point of (an arm, or the frame); refuse a contradiction.

        An axis is a point of arm ``A`` when a gear on it is a planet of ``A``;
        of the frame when a gear on it is held or meshes on the frame's axes;
        else of the frame (an arm's own axis, by default).  An axis that would
        be a point of two members, or an arm carried, through other arms, by
        itself, has no planar layout.
        """
        t, sh = self.t, self.shaft
        shafts = list(dict.fromkeys([*(sh[m] for m in t.members), sh[FRAME]]))
        self.carrier: dict[str, str] = {}
        why: dict[str, tuple[str, str]] = {}
        for s in shafts:
            n = self._root(s)
            name = next((g for g in t.members if sh[g] == s), s)
            if s in self.planet_of:
                c, w = self.planet_of[s], f"a planet of arm {self.planet_of[s]!r}"
            elif s in self.held:
                c, w = FRAME, "given at rest, 0, so part of the frame"
            elif s in self.hard:
                c, w = FRAME, "in a mesh on the frame, so about a frame point"
            else:
                continue
            if self.carrier.get(n, c) != c:
                other, w0 = why[n]
                planet = s if s in self.planet_of else next(
                    k for k in shafts if self._root(k) == n and k in self.planet_of)
                raise InputError(f"{other!r} ({w0}) and {name!r} ({w}) would turn about one "
                                 "axis, which cannot be both: no planar layout of the train",
                                 key=f"mesh[{self.planet_mesh[planet]}].arm", file=self.src)
            self.carrier[n] = c
            why.setdefault(n, (name, w))
        for s in shafts:
            self.carrier.setdefault(self._root(s), FRAME)
        for s in shafts:   # an arm carried, through arms, by itself
            seen: list[str] = []
            n = self._root(s)
            while self.carrier[n] != FRAME:
                if n in seen:
                    ring = [self.carrier[k] for k in seen[seen.index(n):]]
                    what = (f"arm {ring[0]!r} would turn on a pin of itself" if len(ring) == 1
                            else f"arms {' and '.join(repr(a) for a in ring)} would each be "
                            "carried by the other (each turns on a pin of the next)")
                    raise InputError(f"{what}: no planar layout of the train",
                                     key=f"mesh[{self.planet_mesh[ring[0]]}].arm"
                                     if ring[0] in self.planet_mesh else "mesh", file=self.src)
                seen.append(n)
                n = self._root(self.carrier[n])

    def _root(self, s: str) -> str:
        while self.axis[s] != s:
            s = self.axis[s]
        return s

    def _union(self, a: str, b: str) -> None:
        ra, rb = self._root(a), self._root(b)
        if ra != rb:
            self.axis[rb] = ra

    # --- distances and directions ---------------------------------------------------------
    def distance(self, m: Mesh, ra: float, rb: float) -> float:
        return abs(ra - rb) if m.contact == Contact.INTERNAL else ra + rb

    def place(self) -> None:
        t, sh = self.t, self.shaft
        ends = [(self._root(sh[m.driver]), self._root(sh[m.driven])) for m in t.meshes]
        self.adjacent = {frozenset(e) for e in ends}
        self.gears_on: dict[str, list[str]] = {}
        for g in t.size:
            self.gears_on.setdefault(self._root(sh[g]), []).append(g)
        self.pos: dict[str, tuple[float, float]] = {}
        placer: set[int] = set()
        size = max(self.r.values())
        while True:
            progress = True
            while progress:
                progress = False
                for i, (na, nb) in enumerate(ends):
                    if (na in self.pos) == (nb in self.pos):
                        continue
                    known, new = (na, nb) if na in self.pos else (nb, na)
                    m = t.meshes[i]
                    self._put(new, known, self.distance(m, self.r[m.driver], self.r[m.driven]),
                              i)
                    placer.add(i)
                    progress = True
            rest = [na for na, _ in ends if na not in self.pos]
            if not rest:
                break
            # another train beside the first (nothing joins them): to the right, clear
            right = max((self.pos[n][0] + max(self.r[g] for g in self.gears_on[n])
                         for n in self.pos), default=-size)
            first = rest[0]
            self.pos[first] = ((right + max(self.r[g] for g in self.gears_on[first]) + size)
                               if self.pos else 0.0, 0.0)
        self.operating = [(self.r[m.driver], self.r[m.driven]) for m in t.meshes]
        shifted = []
        for i, (na, nb) in enumerate(ends):
            if i in placer:
                continue
            m = t.meshes[i]
            c = math.dist(self.pos[na], self.pos[nb])
            want = self.distance(m, self.r[m.driver], self.r[m.driven])
            if abs(c - want) <= DEFAULT_TOL.length(size):
                continue
            # the operating pitch circles at C divide it in the ratio of the teeth (Eq. 7.2)
            na_, nb_ = float(t.size[m.driver]), float(t.size[m.driven])
            k = c / (abs(nb_ - na_) if m.contact == Contact.INTERNAL else na_ + nb_)
            self.operating[i] = (k * na_, k * nb_)
            shifted.append((i, m, want, c))
        if shifted:
            i0 = shifted[0][0]
            u = self.unit
            what = "; ".join(f"mesh[{i}] ({m.driver}-{m.driven}) needs {_g(w)} {u} and is "
                             f"{_g(c)} {u} apart" for i, m, w, c in shifted)
            self.notes.append(
                f"mesh[{i0}]: the axes the other meshes place do not leave the standard "
                f"center distance ({what}): those gears are drawn with their operating pitch "
                "circles at that distance, C N/(N1 ± N2), as profile-shifted teeth run "
                "(Sec. 7.9); every speed ratio is still the teeth's")

    def _put(self, new: str, known: str, d: float, i: int) -> None:
        """Place axis ``new`` at ``d`` from ``known``: the first clear direction."""
        placed = list(self.pos.values())
        cx = sum(p[0] for p in placed) / len(placed)
        cy = sum(p[1] for p in placed) / len(placed)
        k = self.pos[known]
        away = math.hypot(k[0] - cx, k[1] - cy)
        base = math.atan2(k[1] - cy, k[0] - cx) if away > DEFAULT_TOL.length(d) else 0.0
        best, best_gap = None, -math.inf
        for j in range(_DIRECTIONS):
            step = (j + 1) // 2 * (1 if j % 2 else -1)
            a = base + step * 2.0 * math.pi / _DIRECTIONS
            p = (k[0] + d * math.cos(a), k[1] + d * math.sin(a))
            gap = self._gap(new, p)
            if gap > DEFAULT_TOL.length(d):   # apart, beyond round-off (touching is not clear)
                best = p
                break
            if gap > best_gap:
                best, best_gap = p, gap
        else:
            self.notes.append(f"mesh[{i}]: the gears on the axis it places "
                              f"({', '.join(self.gears_on[new])}) overlap a gear they do not "
                              "mesh with in every direction tried: drawn where they overlap "
                              "least")
        assert best is not None
        self.pos[new] = best

    def _gap(self, new: str, p: tuple[float, float]) -> float:
        gap = math.inf
        for n, q in self.pos.items():
            if frozenset((n, new)) in self.adjacent:
                continue
            for g in self.gears_on.get(new, []):
                for h in self.gears_on.get(n, []):
                    gap = min(gap, clearance(p, self.r[g], g in self.ring,
                                             q, self.r[h], h in self.ring))
        return gap

    # --- the mechanism file -------------------------------------------------------------------
    def point_names(self) -> None:
        taken = {_FRAME_LINK, *self.link_names.values()}
        self.point: dict[str, str] = {}
        for m in self.t.members:   # an axis is named by its first member in the file
            n = self._root(self.shaft[m])
            if n in self.pos and n not in self.point:
                self.point[n] = _fresh(f"O{m}", taken)
        self.pitch = {g: _fresh(f"A{g}", taken) for g in self.t.size}

    def build(self) -> dict[str, Any]:
        t, sh = self.t, self.shaft
        links: dict[str, dict[str, list[float]]] = {_FRAME_LINK: {}}
        for lid in self.link_names.values():
            links[lid] = {}
        arms = {sh[a] for a in t.arms}
        for s in dict.fromkeys(sh[m] for m in t.members):
            node = self._root(s)
            if node not in self.pos:
                if s in arms:
                    raise InputError(f"arm {s!r} carries no gear on its own axis (a sun or a "
                                     "ring): nothing says where it turns", key="mesh",
                                     file=self.src)
                continue
            xy = [*self.pos[node]]
            lid = _FRAME_LINK if s in self.held else self.link_names[s]
            links[lid][self.point[node]] = xy
            arm = self.carrier[node]
            if arm == FRAME:                  # a fixed axis: a frame pivot
                links[_FRAME_LINK][self.point[node]] = xy
            else:                             # a planet's axis: a point of its arm (which
                alid = self.link(arm)         # may itself turn on another arm)
                links[alid][self.point[node]] = xy
                links[alid][self.point[self._root(arm)]] = [*self.pos[self._root(arm)]]
        count: dict[str, int] = {}
        for g in self.r:
            lid = self.link(g)
            if lid != _FRAME_LINK:
                node = self._root(sh[g])
                c = self.pos[node]
                # on the pitch circle, off the line of centers: above the axis, the next gear
                # of the same axis 45° further round
                k = count[node] = count.get(node, -1) + 1
                turn = math.pi / 2 + k * math.pi / 4
                rg = self.operating_radius(g)
                links[lid][self.pitch[g]] = [c[0] + rg * math.cos(turn),
                                             c[1] + rg * math.sin(turn)]
        rolling = []
        for i, m in enumerate(t.meshes):
            ra, rb = self.operating[i]
            a = (m.driver, ra)
            b = (m.driven, rb)
            if m.contact == Contact.INTERNAL:
                inner, outer = (a, b) if ra < rb else (b, a)
                first, second = inner, outer
            else:
                first, second = b, a
            if self.link(first[0]) == _FRAME_LINK:
                first, second = second, first
            if self.link(first[0]) == self.link(second[0]):
                raise InputError(f"gears {m.driver!r} and {m.driven!r} are one link and "
                                 "cannot mesh", key=f"mesh[{i}].gears", file=self.src)
            rolling.append({
                "link": self.link(first[0]), "on": self.link(second[0]),
                "circle": {"center": self.point[self._root(sh[first[0]])],
                           "radius": first[1]},
                "on_circle": {"center": self.point[self._root(sh[second[0]])],
                              "radius": second[1]},
                "contact": "inside" if m.contact == Contact.INTERNAL else "outside"})
        return {"title": t.title or Path(self.src).stem, "units": self.unit, "links": links,
                "rolling": rolling, "drive": self.drives()}

    def operating_radius(self, g: str) -> float:
        for i, m in enumerate(self.t.meshes):
            if g in (m.driver, m.driven):
                return self.operating[i][0 if g == m.driver else 1]
        return self.r[g]

    def drives(self) -> list[dict[str, Any]]:
        """The given motions as drives: the first the swept one, the others following it.

        A member turning on a pin of a moving arm (an arm carried by an arm) is
        driven by its angle relative to that arm, ``θ_m/C`` (``relative_to``),
        at ``ω_m − ω_C`` with ``ω_C`` the train's (the mesh equations, Eq. 7.25);
        the swept drive is the first whose rate is not 0.
        """
        t = self.t
        sol = solve(t)
        freedom = sol.freedom - len(self.held - {self.shaft[FRAME]})
        unit = t.unit + ("/s" if t.turns else "")
        scale = max(abs(v) for v in t.given.values())
        out: list[dict[str, Any]] = []
        seen: set[str] = set()
        left: list[str] = []
        todo: list[tuple[str, str, str | None, float]] = []
        # the mesh equations and the members held, as rows over the shafts (as solve writes
        # them): a given motion drives only if it is independent of those and of the drives
        # before it (a motion that follows from them is left to follow)
        cols = {x: j for j, x in enumerate(dict.fromkeys(self.shaft[m] for m in t.members))}
        rows = []
        for m in t.meshes:
            r = float(m.ratio(t.size))
            row = np.zeros(len(cols))
            for x, c in ((m.driven, 1.0), (m.driver, -r), (m.arm, r - 1.0)):
                if self.shaft[x] in cols:
                    row[cols[self.shaft[x]]] += c
            rows.append(row)
        for x in self.held - {self.shaft[FRAME]}:
            rows.append(np.eye(len(cols))[cols[x]])
        rank = np.linalg.matrix_rank(np.array(rows)) if rows else 0
        for member, v in t.given.items():
            if v == 0.0 or member == FRAME:
                continue
            lid = self.link(member)
            trial = [*rows, np.eye(len(cols))[cols[self.shaft[member]]]]
            if lid in seen or len(todo) == freedom or np.linalg.matrix_rank(
                    np.array(trial)) == rank:
                left.append(member)
                continue
            rows, rank = trial, rank + 1
            seen.add(lid)
            arm = self.carrier[self._root(self.shaft[member])]
            rel = None if arm == FRAME or self.link(arm) == _FRAME_LINK else self.link(arm)
            rate = v - sol.omega[arm] if rel is not None else v
            todo.append((member, lid, rel, 0.0 if is_zero(rate, scale) else rate))
        # the swept drive turns (a member that turns with its arm follows it at ratio 0)
        todo.sort(key=lambda d: is_zero(d[3], scale))
        first = todo[0][3] if todo else 0.0
        if todo and first == 0.0:
            raise InputError(f"{todo[0][0]!r} turns with the arm it turns on, as does every "
                             "member given a motion before the train's degrees of freedom are "
                             "all given: give first the motion of a member that turns about a "
                             "frame point", key=f"{'turns' if t.turns else 'speeds'}."
                             f"{todo[0][0]}", file=self.src)
        for _member, lid, rel, rate in todo:
            d: dict[str, Any] = {"link": lid}
            if rel is not None:
                d["relative_to"] = rel
            if out:   # a second input turns with the first at the ratio of their speeds
                d["follows"] = {"link": out[0]["link"], "ratio": rate / first}
            else:
                d |= {"angle": 0.0, "omega": f"{rate:.17g} {unit}"}
            out.append(d)
        key = "turns" if t.turns else "speeds"
        if not out:
            raise InputError("every given motion holds a member at rest, so nothing turns: "
                             "give a member a motion that is not 0 to see the train move",
                             key=key, file=self.src)
        if left:
            self.notes.append(f"{key}.{left[0]}: the train's {freedom} degree(s) of freedom "
                              "are driven by the motions given before it; it follows from "
                              "them")
        return out


def _g(x: float) -> str:
    return f"{x:.6g}"


def _fresh(base: str, taken: set[str]) -> str:
    name, k = base, 1
    while name in taken:
        k += 1
        name = f"{base}_{k}"
    taken.add(name)
    return name


def train_mechanism(train: Train, path: str | Path) -> TrainLayout:
    """Lay a gear train out as a mechanism of gears rolling on their axes and arms.

    Parameters
    ----------
    train : Train
        The train (:func:`graphkin.gears.train_file.load_train`).
    path : str or Path
        The train file, for messages.

    Returns
    -------
    TrainLayout
        The mechanism file (``data``), each member's link, each gear's axis and
        radius, and the notes (one line each) of what the layout chose.

    Raises
    ------
    InputError
        A train the mechanism equations refuse (:func:`graphkin.gears.train.solve`),
        two meshing gears that would turn about one axis, an axis that would be a
        point of a moving arm and of the frame (a planet on two arms, a member
        given 0 on a moving pin), arms that would each turn on a pin of the other.

    Examples
    --------
    >>> from graphkin.gears.train_file import train_from_dict
    >>> t = train_from_dict({"teeth": {"2": 40, "4": 20, "5": 80},
    ...                      "mesh": [{"gears": [2, 4], "arm": 3},
    ...                               {"gears": [4, 5], "contact": "internal", "arm": 3}],
    ...                      "speeds": {"2": 10, "5": 0}})
    >>> lay = train_mechanism(t, "ex7_8.toml")
    >>> lay.link_of, lay.center["4"]
    ({'2': '2', '4': '4', '5': '1', '3': '3'}, (30.0, 0.0))
    """
    src = str(path)
    solve(train)   # a train the mesh equations refuse is refused here, in its own words
    lay = _Layout(train, src)
    lay.name_links()
    lay.classify()
    lay.place()
    lay.point_names()
    data = lay.build()
    spaced = set()
    gears = list(train.size)
    for i, g in enumerate(gears):
        for h in gears[i + 1:]:
            ng, nh = lay._root(lay.shaft[g]), lay._root(lay.shaft[h])
            if ng == nh or frozenset((ng, nh)) in lay.adjacent:
                spaced.add(frozenset((g, h)))
    notes = list(lay.notes)
    return TrainLayout(
        data=data, link_of={m: lay.link(m) for m in train.members},
        center={g: lay.pos[lay._root(lay.shaft[g])] for g in train.size}, radius=dict(lay.r),
        axis_point={g: lay.point[lay._root(lay.shaft[g])] for g in train.size},
        ring=set(lay.ring), spaced=spaced, operating=list(lay.operating), notes=notes)
