"""Read and validate a mechanism file (``docs/formats/mechanism.md``).

Every problem becomes an :class:`~graphkin.errors.InputError` naming the file,
the dotted key and the reason, so the CLI can print one line and exit 2.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from graphkin.errors import InputError
from graphkin.files import parse_toml, read_text
from graphkin.keys import MECHANISM, check_keys, design_file, nearest, read_units
from graphkin.mechanisms.bodies import read_bodies
from graphkin.mechanisms.cam_joint import with_cams
from graphkin.mechanisms.checks import added_points, check_rates_given, zero_length_notes
from graphkin.mechanisms.loading import force_fields
from graphkin.mechanisms.model import (
    FRAME,
    XY,
    Drive,
    Link,
    Mechanism,
    Pin,
    Rates,
    Rolling,
    Slider,
    Slot,
)
from graphkin.mechanisms.names import LABEL_PREFIXES, LINK_SYMBOLS, contact_names, label_like
from graphkin.units import length_factor, parse_rate

__all__ = ["load", "loads", "from_dict", "MAX_MAGNITUDE", "LABEL_PREFIXES", "LINK_SYMBOLS",
           "label_like"]

#: The largest coordinate, length or rate accepted (squares and products of such numbers,
#: as the constructions form them, stay finite).
MAX_MAGNITUDE = 1e100

#: The largest ratio of the longest to the shortest length of a mechanism (the distances
#: between the points of each link): tolerances are 1e-9 of the size, so beyond this the
#: shortest link would be lost in them.
MAX_RANGE = 1e9


#: The longest title (characters): drawings and pages lay it out.
MAX_TITLE = 1000
#: The longest point name or link id (characters): labels are drawn on every figure.
MAX_NAME = 64

#: Characters the constructions use in their labels (graphkin.kinematics.posture and
#: polygons): ``#`` construction points, ``:`` a path's points, ``@`` coincident points,
#: ``(``/``)`` images and loci, ``>`` posture lines.  A point name cannot contain them.
RESERVED_CHARACTERS = "#:@()>"


def _short(value: Any, limit: int = 80) -> str:
    """``repr`` of a value cut to ``limit`` characters (a hostile value is not echoed whole)."""
    text = value if isinstance(value, str) else repr(value)
    return text if len(text) <= limit else text[:limit - 1] + "…"

def load(path: str | Path) -> Mechanism:
    """Read a mechanism file.

    Parameters
    ----------
    path : str or Path
        A TOML file in the format of ``docs/formats/mechanism.md``.

    Returns
    -------
    Mechanism

    Raises
    ------
    InputError
        The file cannot be read, or says something impossible (naming the key).
    """
    p = Path(path)
    return loads(read_text(p), source=str(p))


def loads(text: str, source: str = "<mechanism>") -> Mechanism:
    """Parse mechanism-file text (see :func:`load`)."""
    data = parse_toml(text, source)
    return from_dict(data, source=source)


def from_dict(data: Mapping[str, Any], source: str = "<mechanism>") -> Mechanism:
    """Build and validate a :class:`Mechanism` from parsed TOML data ([[cams]]: Sec. 4.7)."""
    other = design_file(data)
    if other is not None:  # not "unknown key 'cam' (did you mean 'cams'?)"
        what, verb, key = other
        name = source if not source.startswith("<") else "FILE"
        raise InputError(f"this is {what}, not a mechanism file: 'graphkin {verb} {name}' "
                         "reads it", key=key, file=source)
    return with_cams(data, source,
                     lambda d: _Parser(d, source, added_points(data, d)).mechanism())


class _Parser:
    def __init__(self, data: Mapping[str, Any], source: str,
                 added: frozenset[str] = frozenset()) -> None:
        self.data = data
        self.source = source
        self.added = added   # points of a cam's equivalent linkage, not the user's
        self.line_names: set[str] = set()  # points named to define a slider's or slot's line

    def fail(self, key: str | None, message: str) -> InputError:
        return InputError(message, key=key, file=self.source)

    # ---- small readers -------------------------------------------------
    def xy(self, value: Any, key: str) -> XY:
        if (not isinstance(value, list) or len(value) != 2
                or not all(isinstance(v, (int, float)) and not isinstance(v, bool)
                           for v in value)):
            raise self.fail(key, f"a point must be two numbers [x, y], not {value!r}")
        try:
            x, y = float(value[0]), float(value[1])
        except OverflowError:  # an integer of hundreds of digits
            raise self.fail(key, "a coordinate too large for a float (beyond 1e308)") from None
        if not (math.isfinite(x) and math.isfinite(y)):
            raise self.fail(key, f"coordinates must be finite numbers, not {_short(value)}")
        if max(abs(x), abs(y)) > MAX_MAGNITUDE:
            raise self.fail(key, f"coordinates beyond ±{MAX_MAGNITUDE:g} are not supported "
                            "(choose a larger length unit)")
        return (x, y)

    def point_name(self, name: str, key: str) -> None:
        """Refuse a point name that a construction label could be confused with.

        The constructions name their own points from the file's: ``C#3`` (a
        construction point), ``sliders[0]:L0`` (a line's point), ``C@4`` (the
        point of link 4 at C), ``v(C)`` (an image), ``k_C(B)`` (a locus) and
        ``R_CB:B>C`` (a posture line); a point name holding one of those
        characters could clash with them.
        """
        bad = sorted({c for c in name if c in RESERVED_CHARACTERS})
        if bad:
            raise self.fail(key, f"a point name cannot contain {' or '.join(map(repr, bad))} "
                            "(the constructions use it in their own labels)")

    def not_a_label(self, name: str, key: str) -> None:
        """Refuse a point name spelt like a label the constructions make of their own.

        The constructions name their values in the book's notation, from link
        ids and point names: ``θ3``, ``ω3``, ``α3``, ``s4`` (a slider's travel),
        ``I13`` (an instant center), ``F_43``, ``P_4``, ``T_12``, ``n_1-4`` (the
        force analysis), ``V_B``, ``A_B``, ``k_B`` (polygons and loci).  A point
        so named would be read for that value (a torque of 1.00 lbf·in instead
        of 184.98): it is refused here, in one line (issue 25).
        """
        why = label_like(name, self.links)
        if why:
            raise self.fail(key, f"a point cannot be named {_short(name)!r}: {why} (rename it)")

    def table(self, value: Any, key: str) -> Mapping[str, Any]:
        if not isinstance(value, Mapping):
            raise self.fail(key, f"expected a table, not {value!r}")
        return value

    def link_id(self, value: Any, key: str) -> str:
        if isinstance(value, bool) or not isinstance(value, (int, str)):
            raise self.fail(key, f"a link id must be a number or a name, not {value!r}")
        lid = str(value)
        if lid not in self.links:
            raise self.fail(key, f"no link {lid!r} (links: {', '.join(self.links)})")
        return lid

    def point_of(self, link: str, value: Any, key: str) -> str:
        if not isinstance(value, str):
            raise self.fail(key, f"a point is named by a string, not {value!r}")
        if value not in self.links[link].points:
            names = ", ".join(self.links[link].points) or "none"
            raise self.fail(key, f"link {link} has no point {value!r} (its points: {names})")
        return value

    def line_in(self, link: str, value: Any, key: str) -> tuple[XY, XY]:
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(key, "a line is two points: [[x0, y0], [x1, y1]] or point names")
        pts = []
        for i, v in enumerate(value):
            if isinstance(v, str):
                pts.append(self.links[link].points[self.point_of(link, v, f"{key}[{i}]")])
                self.line_names.add(v)
            else:
                pts.append(self.xy(v, f"{key}[{i}]"))
        (x0, y0), (x1, y1) = pts
        if math.hypot(x1 - x0, y1 - y0) <= 1e-12 * max(1.0, abs(x0), abs(y0)):
            raise self.fail(key, "degenerate line: its two points coincide")
        return pts[0], pts[1]

    def rate(self, value: Any, kind: str, key: str) -> float:
        try:
            v = parse_rate(value, kind, self.unit)
        except ValueError as exc:
            raise self.fail(key, _short(str(exc), 200)) from None
        if abs(v) > MAX_MAGNITUDE:
            raise self.fail(key, f"values beyond ±{MAX_MAGNITUDE:g} are not supported")
        return v

    def entries(self, name: str) -> list[Mapping[str, Any]]:
        raw = self.data.get(name, [])
        if isinstance(raw, Mapping):
            raw = [raw]
        if not isinstance(raw, list):
            raise self.fail(name, f"expected [[{name}]] tables")
        return [self.table(r, f"{name}[{i}]") for i, r in enumerate(raw)]

    # ---- the mechanism -----------------------------------------------
    def mechanism(self) -> Mechanism:
        data = self.data
        check_keys(data, MECHANISM, self.source)
        title = data.get("title", "")
        if not isinstance(title, str):
            raise self.fail("title", "the title must be a string")
        if len(title) > MAX_TITLE:
            # every drawing and page lays the title out: 200 kB took 70 s and 3.5 GB
            raise self.fail("title", f"the title has {len(title)} characters; at most "
                            f"{MAX_TITLE} are drawn")
        self.units = read_units(data.get("units", {}), "units", self.source)
        self.unit = self.units.get("length", "mm")
        try:
            length_factor(self.unit)
        except ValueError as exc:
            raise self.fail("units.length", str(exc)) from None

        links_raw = self.table(data.get("links"), "links") if "links" in data else None
        if not links_raw:
            raise self.fail("links", "a mechanism needs [links.1] (the frame) and moving links")
        self.links: dict[str, Link] = {}
        for lid, pts in links_raw.items():
            key = f"links.{lid}"
            for what, name in (("link id", str(lid)), *(("point name", str(n)) for n in
                                                          (pts if isinstance(pts, Mapping)
                                                           else ()))):
                if len(name) > MAX_NAME:
                    raise self.fail(key if what == "link id" else f"{key}.{_short(name, 20)}",
                                    f"a {what} of {len(name)} characters; at most {MAX_NAME}")
            pts = self.table(pts, key)
            for n in pts:
                self.point_name(str(n), f"{key}.{n}")
            points = {str(n): self.xy(v, f"{key}.{n}") for n, v in pts.items()}
            self.links[str(lid)] = Link(str(lid), points)
        if FRAME not in self.links:
            raise self.fail("links", "link 1 (the frame) is missing")
        for lid, lk in self.links.items():
            for n in lk.points:
                self.not_a_label(n, f"links.{lid}.{n}")
        if len(self.links) < 2:
            raise self.fail("links", "a mechanism needs at least one moving link")

        pins = []
        owners: dict[str, list[str]] = {}
        for lid, lk in self.links.items():
            for n in lk.points:
                owners.setdefault(n, []).append(lid)
        for n, lids in owners.items():
            if len(lids) > 1:
                pins.append(Pin(n, tuple(lids)))

        sliders = []
        for i, s in enumerate(self.entries("sliders")):
            key = f"sliders[{i}]"
            link, on = self.pair(s, key, "a link cannot slide on itself")
            point = self.point_of(link, s.get("point"), f"{key}.point")
            if "line" not in s:
                raise self.fail(f"{key}.line", "a slider needs its line")
            p0, p1 = self.line_in(on, s["line"], f"{key}.line")
            sliders.append(Slider(i, link, on, point, p0, p1, key))

        slots = []
        for i, s in enumerate(self.entries("slots")):
            key = f"slots[{i}]"
            link, on = self.pair(s, key, "a slot and its pin must be on different links")
            point = self.point_of(link, s.get("point"), f"{key}.point")
            if ("line" in s) == ("circle" in s):
                raise self.fail(key, "a slot has either a line or a circle")
            if "line" in s:
                p0, p1 = self.line_in(on, s["line"], f"{key}.line")
                slots.append(Slot(i, link, on, point, p0=p0, p1=p1, key=key))
            else:
                c = self.table(s["circle"], f"{key}.circle")
                cv = c.get("center")
                if isinstance(cv, str):
                    center = self.links[on].points[self.point_of(on, cv, f"{key}.circle.center")]
                else:
                    center = self.xy(cv, f"{key}.circle.center")
                r = c.get("radius")
                if isinstance(r, bool) or not isinstance(r, (int, float, str)):
                    raise self.fail(f"{key}.circle.radius", "the radius must be a number")
                r = self.rate(r, "length", f"{key}.circle.radius")
                if not r > 0:
                    raise self.fail(f"{key}.circle.radius", f"the radius must be positive, not {r}")
                slots.append(Slot(i, link, on, point, center=center, radius=r, key=key))

        rolling = self.rolling_entries(len(slots), sliders)
        names = contact_names(len(rolling), set(owners))
        rolling = [(dataclasses.replace(r, contact_name=n), sl) for (r, sl), n in
                   zip(rolling, names)]
        slots += [r_slot for _, r_slot in rolling if r_slot is not None]
        drives = self.drives(pins, sliders)
        rates = self.rates_table(sliders)
        assembly = {}
        for n, v in self.table(data.get("assembly", {}), "assembly").items():
            if n not in owners:
                raise self.fail(f"assembly.{n}", f"no point named {n!r}")
            assembly[str(n)] = self.xy(v, f"assembly.{n}")

        mech = Mechanism(links=self.links, pins=tuple(pins), sliders=tuple(sliders),
                         slots=tuple(slots), rolling=tuple(r for r, _ in rolling),
                         drives=tuple(drives), rates=rates,
                         assembly=assembly, title=title, length_unit=self.unit,
                         source=self.source, line_points=frozenset(self.line_names),
                         bodies=read_bodies(data, self.links, self.unit, self.fail, self.xy),
                         **force_fields(data, self.links, self.unit, self.fail))
        self.check_mobility(mech)
        self.check_range(mech)
        mech = dataclasses.replace(mech, notes=zero_length_notes(mech, self.added))
        check_rates_given(mech, self.fail)
        if rates is not None and len(mech.drives) != 1:
            raise self.fail("rates", "[rates] fixes one rate: it needs a single input (a "
                            "drive with both x and y is two)")
        rolling_links = {r.link for r in mech.rolling}
        for d in mech.drives:  # (a drive relative to a rolling link is solved)
            if d.kind == "angle" and d.pivot is None and d.link in rolling_links:
                raise self.fail(f"{d.key}.link", f"link {d.link} rolls and is not pinned to "
                                "the frame: its absolute angle as the drive is not supported "
                                "yet (drive the arm or the wheel's carrier by its angle)")
            if mech.has_forces and d.kind == "angle" and d.pivot is None:
                raise self.fail(d.key, f"a force analysis ([[loads]], [inertia]) with the "
                                f"absolute angle of link {d.link}, which is not pinned to the "
                                "frame, as the drive is not supported yet (drive a link pinned "
                                "to the frame, or a slider)")
            if mech.has_forces and d.kind in ("relative", "x", "y"):
                what = "a joint angle" if d.kind == "relative" else "a point's coordinate"
                raise self.fail(d.key, f"a force analysis ([[loads]], [inertia]) with {what} "
                                "as the drive is not supported yet (drive the link by its "
                                "angle or a slider by its position)")
        return mech

    def pair(self, entry: Mapping[str, Any], key: str, same: str) -> tuple[str, str]:
        """The two links of a slider, slot or rolling contact (``link`` on ``on``), distinct."""
        link = self.link_id(entry.get("link"), f"{key}.link")
        on = self.link_id(entry.get("on"), f"{key}.on")
        if link == on:
            raise self.fail(f"{key}.on", same)
        return link, on

    def rolling_entries(self, first_slot: int,
                        sliders: list[Slider] | None = None) -> list[tuple[Rolling, Slot | None]]:
        """Rolling contacts, each with the equivalent slot of its circle's center.

        No slot when the links already hold the center's distance from the surface:
        a link that carries both centers (gears on fixed centers, a planet on its
        arm), or a slider parallel to the line between the link carrying the center
        and the line's link (a rack sliding under a pinion on a fixed pivot, a wheel
        on a carriage rolling on the ground).
        """
        out: list[tuple[Rolling, Slot | None]] = []
        for i, r in enumerate(self.entries("rolling")):
            key = f"rolling[{i}]"
            link, on = self.pair(r, key, "a link cannot roll on itself")
            if link == FRAME:
                raise self.fail(f"{key}.link", "the rolling circle must be on a moving link "
                                "(a line rolling on a fixed circle is not supported yet)")
            c = self.table(r.get("circle"), f"{key}.circle")
            center = self.point_of(link, c.get("center"), f"{key}.circle.center")
            rad = c.get("radius")
            if isinstance(rad, bool) or not isinstance(rad, (int, float, str)):
                raise self.fail(f"{key}.circle.radius", "the radius must be a number")
            rad = self.rate(rad, "length", f"{key}.circle.radius")
            if not rad > 0:
                raise self.fail(f"{key}.circle.radius", f"the radius must be positive, not {rad}")
            angle = math.radians(self.rate(r.get("angle", 0.0), "angle", f"{key}.angle"))
            given = "angle" in r
            if ("line" in r) == ("on_circle" in r):
                raise self.fail(key, "rolling contact needs the surface it rolls on: a line "
                                "(line = [...]) or a circle (on_circle = {center, radius})")
            if "on_circle" in r:
                oc = self.table(r["on_circle"], f"{key}.on_circle")
                ocv = oc.get("center")
                if isinstance(ocv, str):
                    ocen = self.links[on].points[self.point_of(on, ocv,
                                                               f"{key}.on_circle.center")]
                else:
                    ocen = self.xy(ocv, f"{key}.on_circle.center")
                orad = oc.get("radius")
                if isinstance(orad, bool) or not isinstance(orad, (int, float, str)):
                    raise self.fail(f"{key}.on_circle.radius", "the radius must be a number")
                orad = self.rate(orad, "length", f"{key}.on_circle.radius")
                if not orad > 0:
                    raise self.fail(f"{key}.on_circle.radius",
                                    f"the radius must be positive, not {orad}")
                contact = r.get("contact", "outside")
                if contact not in ("outside", "inside"):
                    raise self.fail(f"{key}.contact", "contact must be \"outside\" (external "
                                    f"gears) or \"inside\" (a ring), not {contact!r}")
                if contact == "inside" and not orad > rad:
                    raise self.fail(f"{key}.on_circle.radius", "a circle rolling inside "
                                    "needs a larger circle to roll in")
                path = orad + rad if contact == "outside" else orad - rad
                # a point of `on` at its circle's center, and a link that carries it and the
                # rolling circle's center: then the distance of the centers is already held
                named = [q for q, loc in self.links[on].points.items()
                         if math.hypot(loc[0] - ocen[0], loc[1] - ocen[1])
                         <= 1e-12 * max(1.0, abs(ocen[0]), abs(ocen[1]))]
                common = [(q, lk) for q in named for lk in self.links.values()
                          if q in lk.points and center in lk.points]
                if common:
                    q, lk = common[0]
                    (qx, qy), (cx, cy) = lk.points[q], lk.points[center]
                    dist = math.hypot(cx - qx, cy - qy)
                    if abs(dist - path) > 1e-9 * max(1.0, path):
                        raise self.fail(f"{key}.on_circle.radius", f"the centers {q} and "
                                        f"{center} are {dist:.6g} apart on link {lk.id}; "
                                        f"rolling {contact} needs {path:.6g}")
                    roll = Rolling(i, link, on, center, rad, angle=angle, key=key,
                                   angle_given=given, on_center=ocen, on_radius=orad,
                                   contact=contact, on_center_point=q, fixed_centers=True)
                    out.append((roll, None))
                    continue
                roll = Rolling(i, link, on, center, rad, angle=angle, key=key, angle_given=given,
                               on_center=ocen, on_radius=orad, contact=contact,
                               on_center_point=named[0] if named else None)
                slot = Slot(first_slot + i, link, on, center, center=ocen, radius=path,
                            key=roll.slot_key)
                out.append((roll, slot))
                continue
            p0, p1 = self.line_in(on, r["line"], f"{key}.line")
            side = r.get("side")
            if side is None:
                hints = self.table(self.data.get("assembly", {}), "assembly")
                hint = hints.get(center) if on == FRAME else None
                if hint is not None:
                    hint = self.xy(hint, f"assembly.{center}")
                if hint is None:
                    raise self.fail(f"{key}.side", "say on which side of the line the circle "
                                    "lies: side = \"left\" or \"right\" (of the line's direction)")
                cross = ((p1[0] - p0[0]) * (hint[1] - p0[1]) - (p1[1] - p0[1]) * (hint[0] - p0[0]))
                side = "left" if cross > 0 else "right"
            if side not in ("left", "right"):
                raise self.fail(f"{key}.side", f"side must be \"left\" or \"right\", not {side!r}")
            sgn = 1.0 if side == "left" else -1.0
            held = _held_offset(self.links, sliders or [], center, on, p0, p1)
            if held is not None:
                if abs(held - sgn * rad) > 1e-9 * max(1.0, rad, abs(held)):
                    where = (f"{abs(held):.6g} to the {'left' if held > 0 else 'right'} of"
                             if abs(held) > 1e-9 * max(1.0, rad) else "on")
                    raise self.fail(f"{key}.circle.radius", f"the slider keeps the center "
                                    f"{center} {where} the line; rolling on its {side} needs "
                                    f"{rad:.6g}")
                out.append((Rolling(i, link, on, center, rad, p0, p1, side, angle, key,
                                    fixed_centers=True, angle_given=given), None))
                continue
            roll = Rolling(i, link, on, center, rad, p0, p1, side, angle, key,
                           angle_given=given)
            # the center runs on the line offset by the radius toward its side
            ux, uy = p1[0] - p0[0], p1[1] - p0[1]
            n = math.hypot(ux, uy)
            ox, oy = -uy / n * rad * sgn, ux / n * rad * sgn
            slot = Slot(first_slot + i, link, on, center, p0=(p0[0] + ox, p0[1] + oy),
                        p1=(p1[0] + ox, p1[1] + oy), key=roll.slot_key)
            out.append((roll, slot))
        return out

    def drives(self, pins: list[Pin], sliders: list[Slider]) -> list[Drive]:
        raw = self.data.get("drive")
        if raw is None:
            raise self.fail("drive", "the file needs a [drive] (what fixes the posture)")
        items = [raw] if isinstance(raw, Mapping) else raw
        if not isinstance(items, list) or not items:
            raise self.fail("drive", "expected [drive] or [[drive]] tables")
        multi = not isinstance(raw, Mapping)
        out: list[Drive] = []
        seen: set[str] = set()
        laws: list[tuple[int, Mapping[str, Any], str]] = []
        for i, d in enumerate(items):
            key = f"drive[{i}]" if multi else "drive"
            d = self.table(d, key)
            if "follows" in d:
                d = self.follower(d, key, i, pins)
                laws.append((len(out), d["follows"], key))
            if "point" in d:
                out += self.point_drive(d, key, len(out), seen)
                continue
            for bad in ("x", "y", "vx", "vy", "ax", "ay"):
                if bad in d:
                    raise self.fail(f"{key}.{bad}", "a coordinate drive names its point: "
                                    "point = \"C\"")
            lid = self.link_id(d.get("link"), f"{key}.link")
            if lid == FRAME:
                raise self.fail(f"{key}.link", "the frame cannot be driven")
            if "relative_to" in d:
                out.append(self.relative_drive(d, key, lid, len(out), seen))
                continue
            if lid in seen:
                raise self.fail(f"{key}.link", f"link {lid} is driven twice")
            seen.add(lid)
            has_angle, has_pos = "angle" in d, "position" in d
            if has_angle == has_pos:
                raise self.fail(key, "a drive gives either angle (revolute) or position (slider)")
            if has_angle:
                pivot = next((p.name for p in pins if lid in p.links and FRAME in p.links), None)

                value = math.radians(self.rate(d["angle"], "angle", f"{key}.angle"))
                rate = self.rate(d["omega"], "omega", f"{key}.omega") if "omega" in d else None
                rate2 = self.rate(d["alpha"], "alpha", f"{key}.alpha") if "alpha" in d else None
                for bad in ("velocity", "acceleration"):
                    if bad in d:
                        raise self.fail(f"{key}.{bad}", "a revolute drive takes omega and alpha")
                out.append(Drive(len(out), lid, "angle", value, rate, rate2, pivot=pivot,
                                 key=key))
            else:
                slider = next((s for s in sliders if s.link == lid), None)
                if slider is None:
                    raise self.fail(f"{key}.link", f"link {lid} is not a slider, so a position "
                                    "cannot drive it (drive a pinned link by angle)")
                value = self.rate(d["position"], "length", f"{key}.position")
                rate = (self.rate(d["velocity"], "velocity", f"{key}.velocity")
                        if "velocity" in d else None)
                rate2 = (self.rate(d["acceleration"], "acceleration", f"{key}.acceleration")
                         if "acceleration" in d else None)
                for bad in ("omega", "alpha"):
                    if bad in d:
                        raise self.fail(f"{key}.{bad}",
                                        "a slider drive takes velocity and acceleration")
                out.append(Drive(len(out), lid, "position", value, rate, rate2, slider=slider,
                                 key=key))
        for idx, raw, key in laws:
            out[idx] = self.coupled(out[idx], out[0], raw, key)
        has = [d.rate is not None for d in out]
        if any(has) and not all(has):
            raise self.fail("drive", "give the rate of every drive or of none")
        return out

    def follower(self, d: Mapping[str, Any], key: str, i: int, pins: list[Pin]
                 ) -> dict[str, Any]:
        """A drive with ``follows``: checked, with a placeholder value (the law sets it)."""
        if i == 0:
            raise self.fail(f"{key}.follows", "the first drive is the swept parameter: it "
                            "cannot follow another (put the leading drive first)")
        for bad in ("angle", "position", "omega", "alpha", "velocity", "acceleration",
                    "point", "x", "y"):
            if bad in d:
                raise self.fail(f"{key}.{bad}", "a drive that follows the first gets its value "
                                f"and its rates from the law: leave out {bad}")
        self.table(d["follows"], f"{key}.follows")
        out = dict(d)
        lid = str(d.get("link"))
        pinned = any(lid in p.links and FRAME in p.links for p in pins)
        out["angle" if "relative_to" in d or pinned else "position"] = 0.0
        return out

    def coupled(self, drive: Drive, leader: Drive, raw: Mapping[str, Any], key: str) -> Drive:
        """The law of a following drive (linear or a table, :mod:`.laws`), applied."""
        from graphkin.mechanisms.laws import read_follows

        return read_follows(raw, drive, leader, key, rate=self.rate, fail=self.fail,  # type: ignore[no-any-return]
                            link_id=self.link_id)

    def relative_drive(self, d: Mapping[str, Any], key: str, lid: str, index: int,
                       seen: set[str]) -> Drive:
        """``link = 3, relative_to = 2, angle = -15``: the joint angle θ3/2 = θ3 − θ2 (P5.7)."""
        rel = self.link_id(d.get("relative_to"), f"{key}.relative_to")
        if rel == FRAME:
            raise self.fail(f"{key}.relative_to", "an angle relative to the frame is the "
                            "absolute angle: leave out relative_to")
        if rel == lid:
            raise self.fail(f"{key}.relative_to", f"link {lid} cannot be driven relative to "
                            "itself")
        for bad in ("position", "velocity", "acceleration"):
            if bad in d:
                raise self.fail(f"{key}.{bad}", "a relative drive gives the angle between two "
                                "links: angle, omega and alpha")
        if "angle" not in d:
            raise self.fail(f"{key}.angle", f"a drive relative to link {rel} needs its angle "
                            f"θ{lid}/{rel}")
        pair = f"{lid}/{rel}"
        if pair in seen or f"{rel}/{lid}" in seen:
            raise self.fail(f"{key}.relative_to", f"the angle between links {lid} and {rel} is "
                            "driven twice")
        seen.add(pair)
        value = math.radians(self.rate(d["angle"], "angle", f"{key}.angle"))
        rate = self.rate(d["omega"], "omega", f"{key}.omega") if "omega" in d else None
        rate2 = self.rate(d["alpha"], "alpha", f"{key}.alpha") if "alpha" in d else None
        return Drive(index, lid, "relative", value, rate, rate2, key=key, relative_to=rel)

    def point_drive(self, d: Mapping[str, Any], key: str, index: int,
                    seen: set[str]) -> list[Drive]:
        """``point = "C", x = 300, y = 100``: a point's coordinates in the frame (P5.13)."""
        name = d["point"]
        if not isinstance(name, str):
            raise self.fail(f"{key}.point", f"a point is named by a string, not {name!r}")
        owners = [lid for lid, lk in self.links.items() if name in lk.points]
        if not owners:
            raise self.fail(f"{key}.point", f"no link has a point {_short(name)!r}")
        moving = [lid for lid in owners if lid != FRAME]
        if FRAME in owners or not moving:
            raise self.fail(f"{key}.point", f"point {name} is fixed in the frame: its "
                            "coordinates cannot drive the mechanism")
        if "link" in d:
            lid = self.link_id(d.get("link"), f"{key}.link")
            if lid not in moving:
                raise self.fail(f"{key}.link", f"link {lid} has no point {name!r} "
                                f"(it is on link {', '.join(moving)})")
        else:
            lid = moving[0]
        for bad in ("angle", "position", "omega", "alpha", "velocity", "acceleration",
                    "relative_to"):
            if bad in d:
                raise self.fail(f"{key}.{bad}", "a coordinate drive gives x and/or y of its "
                                "point, with vx, vy, ax, ay")
        if "x" not in d and "y" not in d:
            raise self.fail(key, f"a drive of point {name} gives its x and/or y")
        out: list[Drive] = []
        for axis in ("x", "y"):
            for rate_key in (f"v{axis}", f"a{axis}"):
                if rate_key in d and axis not in d:
                    raise self.fail(f"{key}.{rate_key}", f"{rate_key} is the rate of {axis}, "
                                    f"which this drive does not give")
            if axis not in d:
                continue
            what = f"{axis}_{name}"
            if what in seen:
                raise self.fail(f"{key}.{axis}", f"{axis} of point {name} is driven twice")
            seen.add(what)
            value = self.rate(d[axis], "length", f"{key}.{axis}")
            rate = self.rate(d[f"v{axis}"], "velocity", f"{key}.v{axis}") \
                if f"v{axis}" in d else None
            rate2 = self.rate(d[f"a{axis}"], "acceleration", f"{key}.a{axis}") \
                if f"a{axis}" in d else None
            out.append(Drive(index + len(out), lid, axis, value, rate, rate2, key=key,
                             point=name))
        return out

    def rates_table(self, sliders: list[Slider]) -> Rates | None:
        if "rates" not in self.data:
            return None
        r = self.table(self.data["rates"], "rates")
        lid = self.link_id(r.get("link"), "rates.link")
        if lid == FRAME:
            raise self.fail("rates.link", "the frame does not move")
        if "omega" in r or "alpha" in r:
            rate = self.rate(r["omega"], "omega", "rates.omega") if "omega" in r else None
            rate2 = self.rate(r["alpha"], "alpha", "rates.alpha") if "alpha" in r else None
            kind = "angle"
        else:
            if not any(s.link == lid for s in sliders):
                raise self.fail("rates", "give omega/alpha of a link, or velocity/acceleration "
                                "of a slider")
            rate = self.rate(r["velocity"], "velocity", "rates.velocity") \
                if "velocity" in r else None
            rate2 = self.rate(r["acceleration"], "acceleration", "rates.acceleration") \
                if "acceleration" in r else None
            kind = "position"
        if rate is None:
            raise self.fail("rates", "[rates] needs omega (or velocity for a slider)")
        drives = self.data.get("drive")
        if isinstance(drives, list) and len(drives) > 1:
            raise self.fail("rates", "[rates] fixes one rate: it needs a single drive")
        if isinstance(drives, Mapping) and any(k in drives for k in
                                               ("omega", "alpha", "velocity", "acceleration")):
            raise self.fail("rates", "rates are given twice: in [drive] and in [rates]")
        return Rates(lid, kind, rate, rate2)

    def check_range(self, mech: Mechanism) -> None:
        """Refuse a mechanism whose lengths span more than :data:`MAX_RANGE` (one line).

        Lengths are compared to a tolerance relative to the mechanism's size
        (1e-9 of it): when one link reaches 1e14 while another is 4 long, the
        short one is below that tolerance and every construction, and the
        analytic solver's Jacobian, would see it as a point.  The message names
        the farthest point and the shortest distance instead of calling the
        posture singular.
        """
        far: tuple[float, str, str, str] = (0.0, "", "", "")
        short: tuple[float, str, str, str] = (math.inf, "", "", "")
        shapes = {lid: [(n, p) for n, p in link.points.items() if n not in mech.helper_points]
                  for lid, link in mech.links.items()}
        extents = sorted(math.hypot(max(p[0] for _, p in pts) - min(p[0] for _, p in pts),
                                    max(p[1] for _, p in pts) - min(p[1] for _, p in pts))
                         for pts in shapes.values() if len(pts) > 1)
        if not extents:
            return
        # points nearer than the tolerance of a typical link are one point to the solver
        # (two pivots at 1e-282 from each other): not a length
        floor = 1e-9 * extents[len(extents) // 2]
        for lid, pts in shapes.items():
            if len(pts) < 2:
                continue
            # the point of the link farthest from its first point, and the nearest pair
            n0, p0 = pts[0]
            for n, p in pts[1:]:
                d = math.hypot(p[0] - p0[0], p[1] - p0[1])
                if d > far[0]:
                    far = (d, lid, n, n0)
            for a in range(len(pts)):
                for b in range(a + 1, len(pts)):
                    (na, pa), (nb, pb) = pts[a], pts[b]
                    d = math.hypot(pa[0] - pb[0], pa[1] - pb[1])
                    if floor < d < short[0]:
                        short = (d, lid, na, nb)
                if len(pts) > 60:  # a long list of points: its first point's distances
                    break
        if short[0] == math.inf or far[0] <= MAX_RANGE * short[0]:
            return
        d, lid, n, n0 = far
        raise self.fail(f"links.{lid}.{n}", f"point {n} of link {lid} lies {d:.3g} from {n0}, "
                        f"{d / short[0]:.2g} times the shortest length of the mechanism "
                        f"({short[2]}{short[3]} of link {short[1]}, {short[0]:.3g}): lengths are "
                        "compared to 1e-9 of the mechanism's size, so a range beyond "
                        f"{MAX_RANGE:.0e} cannot be solved; bring {n} nearer".replace("e+0", "e"))

    def check_mobility(self, mech: Mechanism) -> None:
        m = mech.mobility()
        n = len(mech.drives)
        if m != n:
            message = (f"wrong number of constraints: the mechanism has {m} degree(s) of "
                       f"freedom (Kutzbach) but {n} drive(s)")
            if m > n:
                message += _lonely_points(mech)
            raise self.fail("drive", message)
        for lid in mech.moving:
            link = mech.links[lid]
            slid = any(s.link == lid or s.on == lid for s in mech.sliders)
            if not link.points and not slid:
                raise self.fail(f"links.{lid}", "a moving link needs at least one point")



def _lonely_points(mech: Mechanism) -> str:
    """Name the points that appear in only one link: a misspelt pin is among them.

    A pin is a point name shared by two links (docs/formats/mechanism.md), so ``Cc`` in link 4
    where link 3 has ``C`` leaves two free ends and two more degrees of freedom.
    """
    owners: dict[str, list[str]] = {}
    for lid, lk in mech.links.items():
        for name in lk.points:
            owners.setdefault(name, []).append(lid)
    lonely = {name: lids[0] for name, lids in owners.items()
              if len(lids) == 1 and name not in mech.line_points}
    if not lonely:
        return ""
    listed = ", ".join(f"{name} (link {lid})" for name, lid in lonely.items())
    text = f"; points named in only one link: {listed}"
    for name, lid in lonely.items():
        guess = nearest(name, [o for o, olid in lonely.items() if olid != lid])
        if guess is not None:
            text += (f"; {name!r} (link {lid}) and {guess!r} (link {lonely[guess]}) look "
                     "alike: is a pin misspelt?")
            break
    return text


def _held_offset(links: Mapping[str, Link], sliders: list[Slider], center: str, on: str,
                 p0: XY, p1: XY) -> float | None:
    """The signed distance (left +) at which a slider holds a center from the line p0 p1 of ``on``.

    None unless a link A carrying the point ``center`` and the link ``on`` are
    joined by a slider parallel to the line: then A translates along it relative
    to ``on`` and the center keeps its distance from the line (the equivalent slot
    would repeat the slider's constraint, and Kutzbach's count would be one short).
    """
    ux, uy = p1[0] - p0[0], p1[1] - p0[1]
    n = math.hypot(ux, uy)
    ux, uy = ux / n, uy / n
    for s in sliders:
        for a in (s.link, s.on):
            other = s.on if a == s.link else s.link
            if other != on or center not in links[a].points:
                continue
            c = links[a].points[center]
            phi = s.direction_angle
            cs, sn = math.cos(phi), math.sin(phi)
            if a == s.link:  # A slides on `on`: A's axes are the slide's, in on's coordinates
                sx, sy = s.p1[0] - s.p0[0], s.p1[1] - s.p0[1]
                if abs(ux * sy - uy * sx) > 1e-9 * math.hypot(sx, sy):
                    continue
                q = links[a].points[s.point]
                dx, dy = c[0] - q[0], c[1] - q[1]
                wx, wy = s.p0[0] + cs * dx - sn * dy, s.p0[1] + sn * dx + cs * dy
            else:  # `on` slides on A along its own x axis
                if abs(uy) > 1e-9:
                    continue
                q = links[on].points[s.point]
                dx, dy = c[0] - s.p0[0], c[1] - s.p0[1]
                wx, wy = cs * dx + sn * dy + q[0], -sn * dx + cs * dy + q[1]
            return ux * (wy - p0[1]) - uy * (wx - p0[0])
    return None
