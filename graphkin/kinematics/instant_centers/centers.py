"""The instant centers found and how: :class:`Center`, :class:`InstantCenters`, known contacts."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

import numpy as np

from graphkin.construction import Construction
from graphkin.errors import GraphkinError, IdealPointError, InputError
from graphkin.geometry import ops as g
from graphkin.geometry.point import Point
from graphkin.kinematics.instant_centers.labels import _parse_pair, center_label
from graphkin.kinematics.solution import Solution

__all__ = ["How", "KnownCenter", "KnownLine", "Center", "InstantCenters"]

Pair = tuple[str, str]

Array = np.ndarray

# ---------------------------------------------------------------------------
# values
# ---------------------------------------------------------------------------

class How(StrEnum):
    """How an instant center was found."""

    PRIMARY = "primary"
    """By inspection: a pin, a slider (at infinity) or a point of rolling contact."""
    KENNEDY = "kennedy"
    """By the Aronhold-Kennedy theorem: the meet of two lines of centers."""
    VELOCITIES = "velocities"
    """From the velocities: the point where both links have the same velocity."""


@dataclass(frozen=True)
class KnownCenter:
    """A primary center known by inspection that the mechanism file does not state.

    Use it for rolling contact (the point of contact is the instant center of
    the two bodies, Fig. 3.25) until the file format has it.

    Parameters
    ----------
    links : pair of link ids
    point : (x, y)
        World coordinates at the solution's posture (arrays for a batch).
    source : str
        What it is, for the notes (``"rolling contact"``).
    """

    links: tuple[object, object]
    point: tuple[Any, Any]
    source: str = "rolling contact"


@dataclass(frozen=True)
class KnownLine:
    """A line known to carry an instant center: the common normal at a direct contact.

    Parameters
    ----------
    links : pair of link ids
    through : (x, y)
        A point of the line (the contact point), world coordinates.
    direction : (dx, dy)
        Direction of the common normal.
    source : str
    """

    links: tuple[object, object]
    through: tuple[Any, Any]
    direction: tuple[Any, Any]
    source: str = "direct contact"


@dataclass
class Center:
    """One instant center and how it was found.

    Attributes
    ----------
    pair : (str, str)
        The two links, lower id first.
    label : str
        ``"I13"``.
    point : ndarray, shape (..., 3)
        Homogeneous coordinates: ``(x, y, 1)``, or ``(dx, dy, 0)`` at infinity.
    how : How
        Primary, Kennedy or velocities.
    source : str
        ``"pin B"``, ``"slider 4 on 1"``, ``"Kennedy"``...
    order : int
        Order of discovery (1 = first), as on the Kennedy circle.
    lines : tuple of str
        Labels of the lines of centers it was found on.
    triangles : tuple of (str, str, str)
        The link triangles whose lines of centers were used.
    speed_dependent : bool
        True when it depends on the ratio of the input speeds (several degrees
        of freedom, Sec. 5.4): it was found from the velocities.
    note : str
        One sentence in the book's words.
    """

    pair: Pair
    label: str
    point: Array
    how: How
    source: str
    order: int
    lines: tuple[str, ...] = ()
    triangles: tuple[tuple[str, str, str], ...] = ()
    speed_dependent: bool = False
    note: str = ""

    @property
    def is_ideal(self) -> Any:
        """True where the center is at infinity (an array for a batch)."""
        return g.is_ideal(self.point)

    @property
    def xy(self) -> Array:
        """Finite coordinates.

        Raises
        ------
        IdealPointError
            For one posture whose center is at infinity.
        """
        if self.point.ndim == 1 and self.point[2] == 0.0:
            raise IdealPointError(f"{self.label} is at infinity; ask for .direction",
                                  label=self.label)
        return g.xy(self.point)

    @property
    def direction(self) -> Array:
        """Unit direction of a center at infinity (NaN where finite, for a batch).

        Raises
        ------
        GraphkinError
            For one posture whose center is finite.
        """
        if self.point.ndim == 1 and self.point[2] != 0.0:
            raise GraphkinError(f"{self.label} is a finite point; ask for .xy", label=self.label)
        d = self.point[..., :2]
        return np.where(g.is_ideal(self.point)[..., None], d, np.nan)

    def as_point(self) -> Point:
        """The center as a :class:`~graphkin.geometry.Point` (one posture only)."""
        return Point.from_array(self.point)

    def __repr__(self) -> str:
        if self.point.ndim == 1:
            if self.point[2] == 0.0:
                where = f"at infinity ({self.point[0]:.6g}, {self.point[1]:.6g})"
            else:
                where = f"({self.point[0]:.6g}, {self.point[1]:.6g})"
        else:
            where = f"{self.point.shape[0]} postures"
        return f"<{self.label} {where}, {self.how.value}, #{self.order}>"


@dataclass
class InstantCenters:
    """All instant centers of a solved mechanism and their construction.

    Attributes
    ----------
    solution : Solution
    links : list of str
        Link ids in the book's order (the Kennedy circle's numbers).
    centers : dict
        Pair -> :class:`Center`, in order of discovery.
    construction : Construction
        The recorded steps (``diagram="centers"``).
    values : dict
        Label -> array: every point and line of the construction.
    missing : list of pairs
        Centers that could not be found (several degrees of freedom and no
        velocities in the file).
    notes : list of str
    """

    solution: Solution
    links: list[str]
    centers: dict[Pair, Center]
    construction: Construction
    values: dict[str, Array]
    missing: list[Pair] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def __getitem__(self, key: object) -> Center:
        """``ic["I13"]``, ``ic["1-3"]``, ``ic[1, 3]`` or ``ic[("3", "1")]``."""
        pair = _parse_pair(key)
        if pair not in self.centers:
            if pair in self.missing:
                raise KeyError(f"{center_label(*pair)} was not found: {'; '.join(self.notes)}")
            raise KeyError(f"no links {pair[0]} and {pair[1]} in this mechanism")
        return self.centers[pair]

    def __contains__(self, key: object) -> bool:
        try:
            return _parse_pair(key) in self.centers
        except (KeyError, InputError):
            return False

    def __iter__(self) -> Any:
        return iter(self.centers.values())

    def __len__(self) -> int:
        return len(self.centers)

    def center(self, i: object, j: object) -> Center:
        """The center of links ``i`` and ``j`` (either order)."""
        return self[(i, j)]

    @property
    def order(self) -> list[str]:
        """Labels in order of discovery."""
        return [c.label for c in self.centers.values()]

    @property
    def count(self) -> int:
        """``N = n(n-1)/2`` (Eq. 3.20)."""
        n = len(self.links)
        return n * (n - 1) // 2

    def kennedy_circle(self) -> dict[str, Any]:
        """The Kennedy circle (Fig. 3.22b) as plain data, for drawing.

        Returns
        -------
        dict
            ``links``: ids in order around the circle; ``positions``: id ->
            (x, y) on a unit circle (link 1 at the top, then counterclockwise);
            ``edges``: one per pair, ``{"pair", "label", "order", "how",
            "known"}`` with ``order`` ``None`` and ``known`` False for a
            center not found (a dashed line).
        """
        n = len(self.links)
        pos = {lid: (math.cos(math.pi / 2 + 2 * math.pi * k / n),
                     math.sin(math.pi / 2 + 2 * math.pi * k / n))
               for k, lid in enumerate(self.links)}
        edges = []
        for c in self.centers.values():
            edges.append({"pair": c.pair, "label": c.label, "order": c.order,
                          "how": c.how.value, "known": True})
        for p in self.missing:
            edges.append({"pair": p, "label": center_label(*p), "order": None, "how": None,
                          "known": False})
        return {"links": list(self.links), "positions": pos, "edges": edges}

# ---------------------------------------------------------------------------
# the search
# ---------------------------------------------------------------------------

def _as_float(x: Any) -> Any:
    a = np.asarray(x, dtype=float)
    return float(a) if a.ndim == 0 else a
