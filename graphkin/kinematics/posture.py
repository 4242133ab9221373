"""Graphic posture analysis: a mechanism decomposed into the book's constructions.

The frame is drawn first, then the input link at its drive angle (case 1),
then each unknown point is found from points already known, one group at a
time, exactly as a draftsman would (Sec. 2.8, Figs. 2.14-2.16):

* a point on two links that each have one known point: two arcs (case 4);
* a point on a link that has one known point and on a slider whose angle is
  known: an arc and a line (case 2);
* a point on two links that both translate along known lines: two lines (case 3);
* a link with one known point carrying a slot (or the rod of an inverted
  slider-crank) through which a known point passes: the tangent from that
  point to the circle of the slot's offset (Thales' circle and an arc, case 4);
* a link with one known point whose pin runs in a slot of a known link:
  an arc and the slot (case 2 or 4).

Every two-way choice takes the branch whose points lie nearer the file's
assembly hints and records the branch by name.  Mechanisms that cannot be
solved one group at a time are left to the analytic solver (the caller says so).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 and Table 2.2.
"""

from __future__ import annotations

import copy
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphkin.construction import Construction, Mark, Role, Step, Term, VectorEquation
from graphkin.construction.ops import OPS
from graphkin.errors import AssemblyError, ConstructionError
from graphkin.geometry import ops as g
from graphkin.kinematics import posture_drives as pd
from graphkin.kinematics import posture_slides as ps
from graphkin.kinematics.posture_branches import (
    _differ_tolerance,
    _hint_distance,
    _layout_distance,
    _new_points,
)
from graphkin.mechanisms.model import FRAME, XY, Drive, Mechanism, Rolling, Slider, Slot
from graphkin.tolerance import Tolerance

__all__ = ["PostureConstruction", "build_posture", "NotDecomposable"]

K, U, C_, I_ = Mark.KNOWN, Mark.UNKNOWN, Mark.CONSTRAINED, Mark.INPUT


class NotDecomposable(ConstructionError):
    """The mechanism cannot be solved one group at a time (the analytic solver takes over)."""


@dataclass
class PostureConstruction:
    """The recorded posture construction of a mechanism and how to read links from it.

    Attributes
    ----------
    construction : Construction
        The steps.
    inputs : dict
        Label of each drive input -> its value at the file's posture.
    anchors : dict
        Link id -> (label of a point of the link, its local coordinates).
    angles : dict
        Link id -> label of the link's angle θ.
    known : dict
        Link id -> {label: local coordinates} of every point of the link that
        the construction places (named points and construction points).
    branches : dict
        Step label -> branch taken.
    notes : list of str
    """

    construction: Construction
    inputs: dict[str, float]
    anchors: dict[str, tuple[str, XY]]
    angles: dict[str, str]
    known: dict[str, dict[str, XY]]
    branches: dict[str, str] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    values: dict[str, np.ndarray] = field(default_factory=dict)
    events: list[tuple[object, ...]] = field(default_factory=list)


@dataclass(frozen=True)
class _Group:
    """A group that can be constructed now.

    ``kind`` is ``dyad`` (a pin on two links, each with a locus), ``pin_in_slot``
    (a link turning about a known point with its pin in a known slot),
    ``slot_through`` (a link turning about a known point whose slot or line
    passes through a known point) or ``inverted`` (the rod of an inverted
    slider-crank and its block) or ``coordinate`` (a point with one driven
    coordinate; ``pin`` names its link).
    """

    kind: str
    pin: str = ""
    links: tuple[str, str] = ("", "")
    path: Slider | Slot | None = None
    drive: Drive | None = None
    slides: tuple[Slider | Slot, ...] = ()


class _Builder:
    """Adds steps and evaluates them at once on the file's posture."""

    def __init__(self, mech: Mechanism, tol: Tolerance) -> None:
        self.mech = mech
        self.tol = tol
        self.cx = Construction(title=mech.title)
        self.env: dict[str, np.ndarray] = {}
        self.inputs: dict[str, float] = {}
        self.known: dict[str, dict[str, XY]] = {k: {} for k in mech.links}
        self.angle: dict[str, str] = {}
        self.placed: set[str] = set()
        self.anchor: dict[str, tuple[str, XY]] = {}
        self.branches: dict[str, str] = {}
        self.notes: list[str] = []
        self.events: list[tuple[object, ...]] = []
        self.forced: dict[str, str] = {}
        self.rolled: list[tuple[Rolling, Slider]] = []
        #: rolling contact -> the constant c of its roller's angle laid off from its travel
        #: (a sweep, :func:`rolling_travel`); without it the roller stands at its phase
        self.travel: dict[str, float] = {}
        self.serial = 0

    # ---- steps --------------------------------------------------------
    def add(self, op: str, inputs: tuple[str, ...], outputs: tuple[str, ...],
            **kw: Any) -> None:
        step = self.cx.add(op, inputs, outputs, **kw)
        if op == "input":
            return
        args = [self.env[i] for i in step.inputs]
        with np.errstate(invalid="ignore", divide="ignore"):
            outs = OPS[op](*args, tol=self.tol, **step.params)
        for name, val in zip(step.outputs, outs):
            self.env[name] = np.asarray(val, dtype=float)
        for val in outs:
            if not np.all(np.isfinite(val)) and step.kind != "point":
                raise self._fail(step)
            if step.kind == "point" and np.any(np.isnan(val)):
                raise self._fail(step)

    def _fail(self, step: Step) -> ConstructionError:
        from graphkin.construction.protocol import _failure
        from graphkin.kinematics.assembly_words import assembly_words, placement_words

        args = [self.env[i] for i in step.inputs]
        exc = _failure(step, args)
        words = (assembly_words(self.mech, step, args)  # which link is short, by how much
                 or placement_words(step))
        return AssemblyError(f"cannot assemble at this drive: {words}", step=step.label,
                             objects=getattr(exc, "objects", {}))

    def fresh(self, stem: str) -> str:
        self.serial += 1
        return f"{stem}#{self.serial}"

    def link_name(self, lid: str) -> str:
        return "frame" if lid == FRAME else f"link {lid}"

    # ---- knowledge ---------------------------------------------------
    def known_points(self, lid: str) -> dict[str, XY]:
        """Known points of a link: its named points first, then construction points."""
        out = {name: loc for name, loc in self.mech.links[lid].points.items()
               if name in self.env}
        for lab, loc in self.known[lid].items():
            out.setdefault(lab, loc)
        return out

    def distinct_known(self, lid: str) -> list[tuple[str, XY]]:
        pts: list[tuple[str, XY]] = []
        for lab, loc in self.known_points(lid).items():
            if all(math.hypot(loc[0] - q[0], loc[1] - q[1]) > self.tol.length(self.mech.scale)
                   for _, q in pts):
                pts.append((lab, loc))
        return pts

    # ---- the frame and the drives -----------------------------------
    def start(self) -> None:
        frame = self.mech.links[FRAME]
        self.add("scalar", (), ("θ1",), value=0.0, role=Role.GIVEN,
                 note="The frame, link 1, is fixed.")
        self.angle[FRAME] = "θ1"
        for name, xy in frame.points.items():
            self.add("point", (), (name,), xy=xy, role=Role.GIVEN,
                     note=f"Locate the fixed point {name} of the frame.")
        self.place(FRAME)
        for d in self.mech.drives:
            if pd.start_drive(self, d):
                continue
            if d.kind == "angle":
                lab = f"θ{d.link}"
                self.inputs[lab] = d.value
                self.env[lab] = np.asarray(d.value)
                self.add("input", (), (lab,), name=lab, role=Role.GIVEN,
                         note=f"The input: link {d.link} stands at θ{d.link} = "
                              f"{math.degrees(d.value):.6g}°.")
                self.angle[d.link] = lab
                self.events.append(("input", d))
            else:
                lab = f"s{d.link}"
                self.inputs[lab] = d.value
                self.env[lab] = np.asarray(d.value)
                self.add("input", (), (lab,), name=lab, role=Role.GIVEN,
                         note=f"The input: the slider {d.link} has travelled {d.value:.6g} along "
                              "its line.")
                self.events.append(("input", d))
        pd.finish_pairs(self)
        pd.start_phases(self)

    def place(self, lid: str) -> None:
        """Lay off every point of a link from one known point and its angle (case 1)."""
        link = self.mech.links[lid]
        known = self.distinct_known(lid)
        if lid not in self.angle:
            (a, la), (b, lb) = known[0], known[1]
            lab = f"θ{lid}"
            self.add("link_angle", (a, b), (lab,), local_a=la, local_b=lb, role=Role.RESULT,
                     note=f"Measure the angle of {self.link_name(lid)} from {_n(a)}{_n(b)}: "
                          f"θ{lid}.")
            self.angle[lid] = lab
            self.events.append(("link_angle", lid, a, b))
        th = self.angle[lid]
        if lid == FRAME:
            self.placed.add(lid)
            self.place_paths(lid, None, None, th)
            return
        anchor, aloc = known[0]
        self.anchor[lid] = (anchor, aloc)
        self.placed.add(lid)
        self.events.append(("placed", lid, anchor))
        for name, loc in link.points.items():
            if name in self.env:
                continue
            eq = VectorEquation((Term(f"R_{name}", U, U),),
                                (Term(f"R_{_n(anchor)}"), Term(f"R_{name}{_n(anchor)}", K, C_)),
                                case=1)
            self.add("rigid", (anchor, th), (name,), local_p=aloc, local_q=loc,
                     role=Role.RESULT, equation=eq,
                     note=f"Lay off {_n(anchor)}{name} on {self.link_name(lid)} at its angle: "
                          f"{name} (case 1).")
            self.events.append(("point", lid, name, anchor))
        self.place_paths(lid, anchor, aloc, th)

    def place_paths(self, lid: str, anchor: str | None, aloc: XY | None, th: str) -> None:
        """Mark the slider lines and slot paths carried by a placed link."""

        def mark(lab: str, loc: XY, note: str) -> None:
            if lab in self.env:
                return
            if anchor is None:
                self.add("point", (), (lab,), xy=loc, role=Role.GIVEN, note=note)
            else:
                self.add("rigid", (anchor, th), (lab,), local_p=aloc, local_q=loc, note=note)

        for r in self.mech.rolling:
            if r.on == lid and r.p0 is not None and r.p1 is not None:
                for tag, loc in (("L0", r.p0), ("L1", r.p1)):
                    mark(f"{r.key}:{tag}", loc, f"Mark the surface that {r.link} rolls on.")
                if f"{r.key}:line" not in self.env:
                    self.add("join", (f"{r.key}:L0", f"{r.key}:L1"), (f"{r.key}:line",),
                             note=f"Draw the surface of {self.link_name(lid)} that link "
                                  f"{r.link} rolls on.")
        paths: list[Slider | Slot] = [*self.mech.sliders, *self.mech.slots]
        for path in paths:
            if path.on != lid:
                continue
            key = path.key
            if path.p0 is not None and path.p1 is not None:
                for tag, loc in (("L0", path.p0), ("L1", path.p1)):
                    lab = f"{key}:{tag}"
                    mark(lab, loc, f"Mark the line of {key} on {self.link_name(lid)}.")
                    self.known[lid][lab] = loc
                if f"{key}:line" not in self.env:
                    self.add("join", (f"{key}:L0", f"{key}:L1"), (f"{key}:line",),
                             note=f"Draw the path of {path.point}: the line of {key}.")
            elif isinstance(path, Slot) and path.center is not None:
                lab = f"{key}:O"
                if f"{key}:k" not in self.env:
                    mark(lab, path.center, f"Mark the center of the circular slot {key}.")
                    self.add("circle", (lab,), (f"{key}:k",), radius=path.radius,
                             note=f"Draw the circular path of {path.point} ({key}).")
                self.known[lid][lab] = path.center

    # ---- propagation -------------------------------------------------
    def propagate(self) -> None:
        changed = True
        while changed:
            changed = False
            for s in self.mech.sliders:
                a, b = s.link, s.on
                if b in self.angle and a not in self.angle:
                    self.add("add_angle", (self.angle[b],), (f"θ{a}",),
                             offset=s.direction_angle,
                             note=f"The slider {a} keeps its angle on {self.link_name(b)}: θ{a}.")
                    self.angle[a] = f"θ{a}"
                    self.events.append(("same_angle", a, b))
                    changed = True
                elif a in self.angle and b not in self.angle:
                    self.add("add_angle", (self.angle[a],), (f"θ{b}",),
                             offset=-s.direction_angle,
                             note=f"{self.link_name(b).capitalize()} keeps its angle to the "
                                  f"slider {a}: θ{b}.")
                    self.angle[b] = f"θ{b}"
                    self.events.append(("same_angle", b, a))
                    changed = True
            changed = pd.propagate_drives(self) or changed
            for d in self.mech.drives:
                ds = d.slider
                if d.kind == "position" and ds is not None and ds.on in self.placed \
                        and ds.point not in self.env:
                    eq = VectorEquation((Term(f"R_{ds.point}", U, U),),
                                        (Term(f"R_{ds.key}:L0"), Term(f"R_{ds.point}", I_, K)),
                                        case=1)
                    self.add("along_line", (f"{ds.key}:L0", f"{ds.key}:L1", f"s{d.link}"),
                             (ds.point,), role=Role.RESULT, equation=eq,
                             note=f"Lay off the travel s{d.link} along the line: {ds.point}.")
                    self.events.append(("slider_drive", d))
                    changed = True
            for r, ds in self.rolled:
                if ds.on in self.placed and ds.point not in self.env:
                    self.add("along_line", (f"{ds.key}:L0", f"{ds.key}:L1", f"s{ds.link}"),
                             (ds.point,), role=Role.RESULT,
                             note=f"Lay off the travel s{ds.link} along the line: {ds.point}.")
                    self.events.append(("roll_travel", r, ds))
                    changed = True
            for r in self.mech.rolling:
                c = r.contact_label
                if r.link in self.placed and r.on in self.placed and c not in self.env:
                    if r.on_line:
                        self.add("perpendicular", (f"{r.key}:line", r.center), (f"{r.key}:n",),
                                 note=f"The common normal: through {r.center} perpendicular to "
                                      "the surface.")
                        self.add("meet", (f"{r.key}:line", f"{r.key}:n"), (c,),
                                 role=Role.RESULT,
                                 note="It meets the surface at the point of contact.")
                    else:
                        o = r.on_center_point if r.fixed_centers else f"{r.slot_key}:O"
                        assert o is not None
                        self.add("along_ray", (o, r.center), (c,),
                                 distance=r.on_radius, role=Role.RESULT,
                                 note=f"The circles touch on their line of centers, at "
                                      f"{r.on_radius:.6g} from the center of link {r.on}'s circle.")
                    self.events.append(("contact", r))
                    changed = True
            changed = pd.roll_angles(self) or changed
            for lid in self.mech.links:
                if lid in self.placed:
                    continue
                pts = self.distinct_known(lid)
                if (lid in self.angle and pts) or len(pts) >= 2:
                    self.place(lid)
                    changed = True

    def unplaced(self) -> list[str]:
        return [k for k in self.mech.links if k not in self.placed]

    # ---- loci --------------------------------------------------------
    def locus(self, lid: str, name: str, loc: XY) -> tuple[str, str, str, tuple[str, ...]]:
        """Construct the locus of the point ``name`` (local ``loc``) of an unplaced link.

        Returns (label, kind, vector name, motion) with kind "circle" or "line";
        motion is ("rot", link, P) for a link turning about its known point P, or
        ("slide", link, k, line label) for a link translating on the placed link k.
        """
        pts = self.distinct_known(lid)
        if lid not in self.angle and len(pts) == 1:
            p, ploc = pts[0]
            radius = math.hypot(loc[0] - ploc[0], loc[1] - ploc[1])
            lab = f"k_{name}({_n(p)})"
            if lab not in self.env:
                self.add("circle", (p,), (lab,), radius=radius,
                         note=f"About {_n(p)} draw an arc of radius {_n(p)}{name} = "
                              f"{radius:.6g}.")
            return lab, "circle", f"R_{name}{_n(p)}", ("rot", lid, p)
        if lid in self.angle and not pts:
            th = self.angle[lid]
            for s in self.mech.sliders:  # a slider's path (a slot's is the pin's only)
                if (s.link == lid and s.on in self.placed) or \
                        (s.on == lid and s.link in self.placed):
                    return ps.slide_locus(self, lid, name, loc, s)
            for r in self.mech.rolling:
                slot = r.slot_key  # the center's equivalent slot
                if r.link == lid and r.on in self.placed and not r.fixed_centers:
                    cloc = self.mech.links[lid].points[r.center]
                    x = self.fresh(f"{name}'")
                    start = f"{slot}:L0" if r.on_line else f"{slot}:O"
                    self.add("rigid", (start, th), (x,), local_p=cloc, local_q=loc,
                             note=f"Where {name} would be with the center {r.center} at "
                                  + ("the path's start." if r.on_line else
                                     "the center of its path."))
                    if r.on_line:
                        lab = f"l_{name}({r.key})"
                        self.add("parallel", (f"{slot}:line", x), (lab,),
                                 note=f"Through it draw the path of {name}, parallel to the "
                                      "surface.")
                        return lab, "line", f"R_{name}", ("roll", lid, r.key)
                    lab = f"k_{name}({r.key})"
                    path = next(t for t in self.mech.slots if t.key == slot)
                    self.add("circle", (x,), (lab,), radius=path.radius,
                             note=f"About it draw the path of {name}: an arc of the radius of "
                                  "the center's path.")
                    return lab, "circle", f"R_{name}", ("roll", lid, r.key)
        raise AssertionError("no locus")

    # ---- groups ------------------------------------------------------
    def options(self) -> list[_Group]:
        """The groups that can be constructed now, in a fixed order."""
        out: list[_Group] = []
        mech = self.mech
        for pin in mech.pins:
            if pin.name in self.env:
                continue
            links = [k for k in pin.links if k not in self.placed]
            for i in range(len(links)):
                for j in range(i + 1, len(links)):
                    if self.can_locus(links[i]) and self.can_locus(links[j]):
                        out.append(_Group("dyad", pin=pin.name, links=(links[i], links[j])))
        for slot in mech.slots:
            if (slot.link not in self.placed and slot.on in self.placed
                    and self.one_point(slot.link)):
                out.append(_Group("pin_in_slot", path=slot))
            # a roller's center whose angle waits for its travel (roll_angle): its path is
            # drawn through the center alone, as the roller's angle plays no part in it
            rolled = slot.point in self.env and any(
                r.slot_key == slot.key and r.key in self.travel for r in mech.rolling)
            if (slot.on not in self.placed and (slot.link in self.placed or rolled)
                    and self.one_point(slot.on)):
                out.append(_Group("slot_through", path=slot))
        out += [_Group("coordinate", pin=lid, drive=d) for d, lid in pd.coordinate_groups(self)]
        out += ps.two_slides_groups(self)
        out += ps.pins_in_line_groups(self)
        for sl in mech.sliders:
            # the rod of an inverted slider-crank: the block has one known point, no angle
            if (sl.on not in self.placed and sl.link not in self.placed
                    and self.one_point(sl.on) and self.one_point(sl.link)):
                out.append(_Group("inverted", path=sl))
        return out

    def one_point(self, lid: str) -> bool:
        return lid not in self.angle and len(self.distinct_known(lid)) == 1

    def can_locus(self, lid: str) -> bool:
        if self.one_point(lid):
            return True
        if lid in self.angle and not self.distinct_known(lid):
            return any((sl.link == lid and sl.on in self.placed) or
                       (sl.on == lid and sl.link in self.placed) for sl in self.mech.sliders) or \
                any(r.link == lid and r.on in self.placed and not r.fixed_centers
                    for r in self.mech.rolling)
        return False

    def do(self, group: _Group, branch: str | None) -> list[str]:
        """Construct one group; returns the branch names possible for it."""
        kind = group.kind
        if kind == "dyad":
            name, (li, lj) = group.pin, group.links
            mech = self.mech
            loc_i = mech.links[li].points[name]
            loc_j = mech.links[lj].points[name]
            (la, ka, va, ma) = self.locus(li, name, loc_i)
            (lb, kb, vb, mb) = self.locus(lj, name, loc_j)
            if ka == "line" and kb == "circle":
                (la, ka, va, ma), (lb, kb, vb, mb) = (lb, kb, vb, mb), (la, ka, va, ma)
            self.events.append(("dyad", name, ma, mb))
            mark = {"circle": (K, U), "line": (U, K)}
            eq = VectorEquation((Term(va, *mark[ka]),), (Term(vb, *mark[kb]),),
                                case={("circle", "circle"): 4, ("line", "line"): 3}.get(
                                    (ka, kb), 2))
            two_way = {  # Table 2.2: (operation, its inputs, its branches, the words)
                ("circle", "circle"): ("intersect_circles", (la, lb), ["left", "right"],
                                       f"The arcs meet at {name} (case 4)."),
                ("circle", "line"): ("intersect_line_circle", (lb, la), ["behind", "ahead"],
                                     f"The arc cuts the line at {name} (case 2)."),
            }.get((ka, kb))
            if two_way is not None:
                op, inputs, names, note = two_way
                self.add(op, inputs, (name,), branch=branch or names[0], role=Role.RESULT,
                         equation=eq, note=note)
                return names
            self.add("meet", (la, lb), (name,), role=Role.RESULT, equation=eq,
                     note=f"The two lines meet at {name} (case 3).")
            if not np.isfinite(g.xy(self.env[name])).all():
                raise AssemblyError(f"cannot assemble: the paths of {name} are parallel",
                                    step=name)
            return [""]
        if kind == "two_slides":
            return ps.do_two_slides(self, group.links[0], group.pin, group.slides)
        if kind == "pins_in_line":
            return ps.do_pins_in_line(self, group.links[0], group.slides, branch)
        if kind == "coordinate":
            assert group.drive is not None
            return pd.do_coordinate(self, group.drive, group.pin, branch)
        path = group.path
        assert path is not None
        if kind == "pin_in_slot":
            assert isinstance(path, Slot)
            s = path
            lid = s.link
            (p, ploc), = self.distinct_known(lid)
            sloc = self.mech.links[lid].points[s.point]
            r = math.hypot(sloc[0] - ploc[0], sloc[1] - ploc[1])
            k = f"k_{s.point}({_n(p)})"
            self.events.append(("pin_in_slot", s, lid, p))
            self.add("circle", (p,), (k,), radius=r,
                     note=f"About {_n(p)} draw an arc through the pin's distance.")
            # the slot's line (case 2: its direction known) or its circle (case 4)
            op, slot, names, marks, case, what = (
                ("intersect_line_circle", f"{s.key}:line", ["behind", "ahead"], (U, K), 2,
                 "slot") if s.is_line else
                ("intersect_circles", f"{s.key}:k", ["left", "right"], (K, U), 4,
                 "circular slot"))
            self.add(op, (slot, k), (s.point,), branch=branch or names[0], role=Role.RESULT,
                     equation=VectorEquation((Term(f"R_{s.point}", *marks),),
                                             (Term(f"R_{s.point}{_n(p)}", K, U),), case=case),
                     note=f"The arc cuts the {what} at {s.point} (case {case}).")
            return names
        if kind in ("slot_through", "inverted"):
            lid = path.on
            if kind == "slot_through":
                spoint = path.point
                delta = (0.0, 0.0)
            else:
                assert isinstance(path, Slider)
                # the block's known point A stands off the slide by a constant vector in the rod
                (spoint, aloc), = self.distinct_known(path.link)
                bloc = self.mech.links[path.link].points[path.point]
                c, sn = math.cos(path.direction_angle), math.sin(path.direction_angle)
                dx, dy = aloc[0] - bloc[0], aloc[1] - bloc[1]
                delta = (c * dx - sn * dy, sn * dx + c * dy)
            (p, ploc), = self.distinct_known(lid)
            self.events.append(("relative", path, lid, p, spoint))
            if path.p0 is not None:
                return self.tangent(lid, p, ploc, spoint, path, delta, branch)
            assert isinstance(path, Slot)
            return self.circle_slot_through(lid, p, ploc, spoint, path, branch)
        raise AssertionError(kind)

    def tangent(self, lid: str, p: str, ploc: XY, spoint: str, s: Slider | Slot, delta: XY,
                branch: str | None) -> list[str]:
        """Place a link turning about P so that its line passes through the known point S."""
        assert s.p0 is not None and s.p1 is not None
        q0 = (s.p0[0] + delta[0], s.p0[1] + delta[1])
        q1 = (s.p1[0] + delta[0], s.p1[1] + delta[1])
        ux, uy = q1[0] - q0[0], q1[1] - q0[1]
        n = math.hypot(ux, uy)
        ux, uy = ux / n, uy / n
        t = (ploc[0] - q0[0]) * ux + (ploc[1] - q0[1]) * uy
        foot = (q0[0] + t * ux, q0[1] + t * uy)
        d = math.hypot(foot[0] - ploc[0], foot[1] - ploc[1])
        key = s.key
        if d <= self.tol.length(self.mech.scale):
            # the line passes through the pivot: it is the line P-S itself
            lab = f"{key}:T"
            r = max(n, 1.0)
            self.add("join", (p, spoint), (f"{key}:PS",),
                     note=f"The path passes through {_n(p)}: draw the line {_n(p)}{_n(spoint)}.")
            self.add("circle", (p,), (f"{key}:u",), radius=r,
                     note=f"About {_n(p)} mark a unit length on it.")
            names = ["ahead", "behind"]
            br = branch or names[0]
            self.add("intersect_line_circle", (f"{key}:PS", f"{key}:u"), (lab,), branch=br,
                     role=Role.AUXILIARY,
                     equation=VectorEquation((Term(f"R_{_n(spoint)}{_n(p)}", U, K),),
                                             (Term(f"R_{_n(spoint)}{_n(p)}", U, K),), case=1),
                     note=f"The slide lies along {_n(p)}{_n(spoint)}.")
            # the mark lies on the slide a distance r from the pivot, in the slide's direction
            self.known[lid][lab] = (ploc[0] + r * ux, ploc[1] + r * uy)
            return names
        lab = f"{key}:T"
        self.add("circle_on_diameter", (p, spoint), (f"{key}:thales",),
                 note=f"Draw the circle on the diameter {_n(p)}{_n(spoint)} (Thales).")
        self.add("circle", (p,), (f"{key}:offset",), radius=d,
                 note=f"About {_n(p)} draw an arc of the path's offset {d:.6g}.")
        names = ["left", "right"]
        self.add("tangent_foot", (p, spoint), (lab,), offset=d,
                 branch=branch or names[0], role=Role.AUXILIARY,
                 equation=VectorEquation((Term(f"R_{_n(spoint)}{_n(p)}"),),
                                         (Term(f"R_T{_n(p)}", K, U),
                                          Term(f"R_{_n(spoint)}T", U, U)), case=4),
                 note="They meet at the foot T of the perpendicular from the pivot to the path.")
        # the path runs from T through S: its direction fixes the link's angle (better
        # conditioned than the short PT when the path passes close to the pivot)
        nx, ny = (foot[0] - ploc[0]) / d, (foot[1] - ploc[1]) / d
        o = 1.0 if nx * uy - ny * ux > 0 else -1.0
        sigma = 1.0 if (branch or names[0]) == "left" else -1.0
        th = f"θ{lid}"
        self.add("angle_along", (lab, spoint), (th,), local_angle=math.atan2(uy, ux),
                 sign=-o * sigma, role=Role.RESULT,
                 note=f"The path runs through T and {_n(spoint)}: it gives θ{lid}.")
        self.angle[lid] = th
        return names

    def circle_slot_through(self, lid: str, p: str, ploc: XY, spoint: str, s: Slot,
                            branch: str | None) -> list[str]:
        """Place a link turning about P whose circular slot passes through the known point S."""
        assert s.center is not None and s.radius is not None
        cloc = s.center
        key = s.key
        r1 = math.hypot(cloc[0] - ploc[0], cloc[1] - ploc[1])
        self.add("circle", (p,), (f"{key}:kc",), radius=r1,
                 note=f"About {_n(p)} draw the arc of the slot's center.")
        self.add("circle", (spoint,), (f"{key}:ks",), radius=s.radius,
                 note=f"About {_n(spoint)} draw an arc of the slot's radius.")
        names = ["left", "right"]
        lab = f"{key}:O"
        self.add("intersect_circles", (f"{key}:kc", f"{key}:ks"), (lab,),
                 branch=branch or names[0], role=Role.RESULT,
                 note="They meet at the slot's center (case 4).")
        self.known[lid][lab] = cloc
        return names


def _n(label: str) -> str:
    """A label as printed in a vector name (construction points keep their base)."""
    return label.split("#")[0].split(":")[-1]


def _fork(b: _Builder) -> _Builder:
    """A copy of the builder that can take one branch without touching ``b``.

    Only the containers are copied (one level deep): values are arrays that
    the steps never change in place, and steps are frozen records.
    """
    t = copy.copy(b)
    t.cx = Construction(list(b.cx.steps), b.cx.title)
    t.env = dict(b.env)
    t.inputs = dict(b.inputs)
    t.known = {k: dict(v) for k, v in b.known.items()}
    t.angle = dict(b.angle)
    t.placed = set(b.placed)
    t.anchor = dict(b.anchor)
    t.branches = dict(b.branches)
    t.notes = list(b.notes)
    t.events = list(b.events)
    t.rolled = list(b.rolled)
    return t


def _try(b: _Builder, group: _Group,
         branch: str | None) -> tuple[_Builder | AssemblyError, list[str], str]:
    """Construct the group on a fork of ``b`` with ``branch``, then propagate.

    Returns the fork (or the error that stopped it after the group itself),
    the group's branch names and the label of its branch step.  An error in
    the group itself (its arcs do not meet) is raised: every branch shares it.
    """
    t = _fork(b)
    names = t.do(group, branch)
    steps = t.cx.steps[len(b.cx.steps):]
    label = next((s.label for s in reversed(steps) if s.branch), "")
    try:
        t.propagate()
    except AssemblyError as exc:
        return exc, names, label
    return t, names, label


def _choose(b: _Builder, group: _Group, names: list[str],
            trials: dict[str, _Builder | AssemblyError]) -> tuple[str, str]:
    """Pick the branch of a two-way group; returns (branch, reason).

    The choice is local: each branch is carried out for this group only (and
    what follows from it at once), never through the rest of the mechanism,
    so the work grows linearly with the number of groups.  The hinted points
    that the branches place apart decide (the nearer wins); when no hint tells
    them apart, the branch that leaves the new links nearest their own drawing
    in the file is taken.  A branch that cannot be assembled is dropped.
    """
    for name in names:
        if name not in trials:
            trials[name] = _try(b, group, name)[0]
    finished = {n: t for n, t in trials.items() if isinstance(t, _Builder)}
    if not finished:
        raise next(t for t in trials.values() if isinstance(t, AssemblyError))
    if len(finished) == 1:
        return next(iter(finished)), "the other branch cannot be assembled"
    first, second = finished.values()
    new = [n for n in _new_points(b, first) if n in b.mech.assembly and n in second.env]
    differ = []
    origin = np.zeros(2)
    for n in new:
        p, q = g.xy(first.env[n]), g.xy(second.env[n])
        if not (np.all(np.isfinite(p)) and np.all(np.isfinite(q))):
            continue
        origin = p
        if float(np.hypot(*(p - q))) > _differ_tolerance(b, p):
            differ.append(n)
    if differ:
        best = min(finished, key=lambda n: _hint_distance(finished[n], differ, origin))
        return best, "assembly hint"
    best = min(finished, key=lambda n: _layout_distance(b, finished[n]))
    return best, "no assembly hint decides it; took the branch nearest the file's drawing"


def _finish(b: _Builder) -> None:
    """Propagate, then construct groups one at a time, choosing each branch locally."""
    b.propagate()
    while b.unplaced():
        opts = b.options()
        if not opts:
            left = ", ".join(b.link_name(k) for k in b.unplaced())
            raise NotDecomposable(f"{left} cannot be found one group at a time", step=left)
        group = opts[0]
        first, names, label = _try(b, group, None)
        if len(names) == 1:
            if isinstance(first, AssemblyError):
                raise first
            b.__dict__.update(first.__dict__)
            continue
        trials: dict[str, _Builder | AssemblyError] = {names[0]: first}
        if label in b.forced:
            chosen, reason = b.forced[label], "branch asked for"
            if chosen not in names:
                from graphkin.kinematics.assembly_words import point_words

                raise ConstructionError(f"the branches of {point_words(label)} are "
                                        f"{', '.join(names)}, not {chosen!r}", step=label)
            if chosen not in trials:
                trials[chosen] = _try(b, group, chosen)[0]
        else:
            chosen, reason = _choose(b, group, names, trials)
        done = trials[chosen]
        if isinstance(done, AssemblyError):
            raise done
        b.__dict__.update(done.__dict__)
        b.branches[label] = chosen
        if reason not in ("assembly hint", "branch asked for"):
            b.notes.append(f"{label}: {reason} ({chosen})")


def build_posture(mech: Mechanism, tol: Tolerance | None = None,
                  branches: dict[str, str] | None = None,
                  travel: dict[str, float] | None = None) -> PostureConstruction:
    """Decompose a mechanism into the book's posture constructions and carry them out.

    Parameters
    ----------
    mech : Mechanism
    tol : Tolerance, optional
    branches : dict, optional
        Step label -> branch name, to force a branch instead of following the
        assembly hints (e.g. ``{"C": "right"}`` for the other posture of a four-bar).
    travel : dict, optional
        Rolling contact -> constant ``c``: its roller's angle is laid off from
        its travel (``roll_angle``, for a sweep; see
        :func:`graphkin.kinematics.posture_drives.rolling_travel`) instead of
        standing at the contact's phase.

    Returns
    -------
    PostureConstruction

    Raises
    ------
    NotDecomposable
        When some links cannot be found one group at a time.
    AssemblyError
        When the mechanism cannot be assembled at the file's drive.
    """
    from graphkin.tolerance import DEFAULT_TOL

    b = _Builder(mech, tol or DEFAULT_TOL)
    b.travel = dict(travel or {})
    b.forced = dict(branches or {})
    b.start()
    _finish(b)
    rolled = {id(ev[1]) for ev in b.events if ev[0] == "roll_angle"}
    for r in mech.rolling:
        if r.key in b.travel and not r.on_line and id(r) not in rolled:
            # both gears' angles found otherwise: the no-slip condition would go unused
            raise NotDecomposable(f"{r.key}: no gear of the contact is left to lay off from "
                                  "the other's angle", step=r.key)
    known = {lid: b.known_points(lid) for lid in mech.links}
    return PostureConstruction(b.cx, b.inputs, b.anchor, b.angle, known, b.branches, b.notes,
                               b.env, b.events)
