"""``[[bodies]]``: what a link looks like where its equivalent mechanism does not show it.

The book solves a circular cam and its flat-faced follower as the equivalent
pin-in-slot (Sec. 4.6, Example 4.7, Fig. 4.18) but draws the cam's disc and
the follower's face.  A mechanism file says so with an optional, drawing-only
table per body::

    [[bodies]]
    link = 2
    circle = { center = "B", radius = 1.5 }   # the cam's disc about its center B

    [[bodies]]
    link = 3
    face = [[-1.4, -0.6], [-1.4, 3.6]]        # the follower's flat face

    [[bodies]]
    link = 4
    outline = ["B", "C", [2, 3]]              # a plate through these corners

Points are a point name of the link or ``[x, y]`` in the link's own
coordinates; the radius is a number (the file's length unit) or a string
with its unit.  A body changes no position, velocity or acceleration
(``docs/formats/mechanism.md#bodies``).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

from graphkin.errors import InputError
from graphkin.mechanisms.model import XY, Body, Link
from graphkin.units import parse_rate

__all__ = ["read_bodies", "SHAPES"]

SHAPES = ("circle", "face", "outline")
"""The keys of a body's shape; a body has exactly one."""

Fail = Callable[[str | None, str], InputError]


def read_bodies(data: Mapping[str, Any], links: Mapping[str, Link], length_unit: str,
                fail: Fail, xy: Callable[[Any, str], XY]) -> tuple[Body, ...]:
    """The ``[[bodies]]`` of a parsed mechanism file, checked.

    Parameters
    ----------
    data : mapping
        The parsed TOML (its keys already checked against :data:`graphkin.keys.MECHANISM`).
    links : mapping
        Link id -> :class:`~graphkin.mechanisms.model.Link` (already read).
    length_unit : str
        ``units.length``: the unit of a bare radius.
    fail : callable
        ``fail(key, reason)`` -> the :class:`InputError` to raise.
    xy : callable
        ``xy(value, key)`` -> a checked, finite point ``(x, y)``.

    Returns
    -------
    tuple of Body
        In file order; empty when the file has none.

    Examples
    --------
    >>> from graphkin.mechanisms import from_dict
    >>> m = from_dict({"units": "in", "links": {
    ...     "1": {"A": [0, 0], "D": [5, 0]}, "2": {"A": [0, 0], "B": [3, 0]},
    ...     "3": {"D": [0, 0], "S1": [-2.9, 0], "S2": [-2.9, 1]}},
    ...     "slots": [{"link": 2, "on": 3, "point": "B", "line": ["S1", "S2"]}],
    ...     "drive": {"link": 2, "angle": 45}, "assembly": {"B": [2.1, 2.1]},
    ...     "bodies": [{"link": 2, "circle": {"center": "B", "radius": "38.1 mm"}}]})
    >>> b = m.bodies[0]
    >>> b.kind, b.center, round(b.radius, 9)
    ('circle', (3.0, 0.0), 1.5)
    """
    raw = data.get("bodies", [])
    if isinstance(raw, Mapping):
        raw = [raw]
    if not isinstance(raw, list):
        raise fail("bodies", "expected [[bodies]] tables")
    out: list[Body] = []
    for i, entry in enumerate(raw):
        key = f"bodies[{i}]"
        if not isinstance(entry, Mapping):
            raise fail(key, f"expected a table, not {entry!r}")
        lv = entry.get("link")
        if isinstance(lv, bool) or not isinstance(lv, (int, str)):
            raise fail(f"{key}.link", f"a body names its link: a number or a name, not {lv!r}")
        lid = str(lv)
        if lid not in links:
            raise fail(f"{key}.link", f"no link {lid!r} (links: {', '.join(links)})")
        shapes = [s for s in SHAPES if s in entry]
        if len(shapes) != 1:
            raise fail(key, "a body has exactly one of circle = { center, radius }, "
                       "face = [p0, p1] or outline = [p0, p1, p2, ...]")
        shape = shapes[0]

        def point(value: Any, where: str, lid: str = lid) -> XY:
            if isinstance(value, str):
                if value not in links[lid].points:
                    names = ", ".join(links[lid].points) or "none"
                    raise fail(where, f"link {lid} has no point {value!r} (its points: {names})")
                return links[lid].points[value]
            return xy(value, where)

        if shape == "circle":
            c = entry["circle"]
            if not isinstance(c, Mapping):
                raise fail(f"{key}.circle", "a circle is { center = ..., radius = ... }")
            if "center" not in c or "radius" not in c:
                raise fail(f"{key}.circle", "a circle needs its center and its radius")
            center = point(c["center"], f"{key}.circle.center")
            r = c["radius"]
            if isinstance(r, bool) or not isinstance(r, (int, float, str)):
                raise fail(f"{key}.circle.radius", f"the radius must be a number, not {r!r}")
            try:
                radius = parse_rate(r, "length", length_unit)
            except ValueError as exc:
                raise fail(f"{key}.circle.radius", str(exc)[:200]) from None
            if not (math.isfinite(radius) and radius > 0):
                raise fail(f"{key}.circle.radius", f"the radius must be positive, not {r!r}")
            out.append(Body(i, lid, "circle", center=center, radius=radius, key=key))
            continue
        pts_raw = entry[shape]
        need = 2 if shape == "face" else 3
        if not isinstance(pts_raw, list) or (len(pts_raw) != 2 if shape == "face"
                                             else len(pts_raw) < 3):
            what = "two points" if shape == "face" else "three or more points"
            raise fail(f"{key}.{shape}", f"a {shape} is {what}: point names or [x, y]")
        pts = tuple(point(v, f"{key}.{shape}[{j}]") for j, v in enumerate(pts_raw))
        span = max(math.hypot(p[0] - q[0], p[1] - q[1]) for p in pts for q in pts)
        size = max(1.0, *(abs(c) for p in pts for c in p))
        if span <= 1e-12 * size or len(set(pts)) < need:
            raise fail(f"{key}.{shape}", f"degenerate {shape}: its points coincide")
        out.append(Body(i, lid, shape, points=pts, key=key))
    return tuple(out)
