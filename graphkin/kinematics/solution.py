"""The solved state of a mechanism: every link's angle, origin and their rates.

A :class:`Solution` is the common currency of graphkin: the graphic
constructions and the independent analytic solver both produce one, and the
instant centers, curvature, reports and drawings read one.  Its arrays have a
leading shape: ``()`` for one posture, ``(N,)`` for a sweep.

References
----------
Uicker, Pennock & Shigley, 5th ed., Eq. 3.4 (V_P = V_O + ω × R_PO) and Eq. 4.5
(A_P = A_O + α × R_PO - ω² R_PO).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from graphkin.mechanisms.model import FRAME, Mechanism

if TYPE_CHECKING:
    from graphkin.construction import Construction

__all__ = ["LinkState", "Solution", "perp"]


def perp(v: np.ndarray) -> np.ndarray:
    """The vector turned 90° counterclockwise: ``k × v``."""
    v = np.asarray(v, dtype=float)
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


@dataclass
class LinkState:
    """Pose of one link and, when known, its rates.

    Attributes
    ----------
    angle : ndarray
        θ, the direction of the link's own x axis (rad).
    origin : ndarray, shape (..., 2)
        Where the link's local origin is.
    omega, alpha : ndarray or None
        Angular velocity and acceleration (counterclockwise positive).
    origin_velocity, origin_acceleration : ndarray or None, shape (..., 2)
        Velocity and acceleration of the (possibly virtual) point at the origin.
    """

    angle: np.ndarray
    origin: np.ndarray
    omega: np.ndarray | None = None
    alpha: np.ndarray | None = None
    origin_velocity: np.ndarray | None = None
    origin_acceleration: np.ndarray | None = None

    def _r(self, local: Any) -> np.ndarray:
        loc = np.asarray(local, dtype=float)
        c, s = np.cos(self.angle), np.sin(self.angle)
        return np.stack([c * loc[..., 0] - s * loc[..., 1], s * loc[..., 0] + c * loc[..., 1]],
                        axis=-1)

    def position(self, local: Any) -> np.ndarray:
        """World position of the body point with local coordinates ``local``."""
        return self.origin + self._r(local)

    def velocity(self, local: Any) -> np.ndarray:
        """Velocity of a body point: ``V_O + ω × R`` (Eq. 3.4)."""
        if self.omega is None or self.origin_velocity is None:
            raise ValueError("velocities are not known (the file gives no rates)")
        return self.origin_velocity + np.asarray(self.omega)[..., None] * perp(self._r(local))

    def acceleration(self, local: Any) -> np.ndarray:
        """Acceleration of a body point: ``A_O + α × R - ω² R`` (Eq. 4.5)."""
        if self.alpha is None or self.origin_acceleration is None or self.omega is None:
            raise ValueError("accelerations are not known (the file gives no rates)")
        r = self._r(local)
        w = np.asarray(self.omega)[..., None]
        return self.origin_acceleration + np.asarray(self.alpha)[..., None] * perp(r) - w**2 * r


@dataclass
class Solution:
    """A mechanism solved at one posture or at many.

    Attributes
    ----------
    mechanism : Mechanism
    links : dict
        Link id -> :class:`LinkState` (the frame included, at rest).
    method : str
        ``"construction"`` when every unknown was found by the graphic
        constructions, ``"analytic"`` when the analytic solver did the work
        (and ``notes`` says why).
    constructions : dict
        Diagram name (``posture``, ``velocity``, ``acceleration``) -> Construction.
    valid : ndarray of bool
        Which postures could be assembled (all True for one solved posture).
    notes : list of str
        Remarks for the report (fallbacks, branches chosen).
    branches : dict
        Step label -> chosen branch name.
    """

    mechanism: Mechanism
    links: dict[str, LinkState]
    method: str = "construction"
    constructions: dict[str, Construction] = field(default_factory=dict)
    valid: np.ndarray = field(default_factory=lambda: np.array(True))
    notes: list[str] = field(default_factory=list)
    branches: dict[str, str] = field(default_factory=dict)
    values: dict[str, dict[str, np.ndarray]] = field(default_factory=dict)

    def __repr__(self) -> str:
        """A short summary: the link angles (and ω) and the diagrams (never raises).

        >>> import graphkin
        >>> graphkin.examples.fourbar().solve()  # doctest: +ELLIPSIS
        <Solution of 'Four-bar ...' by construction: θ2 = 120°, θ3 = 20.92°, ... rad/s; ...>
        """
        try:
            title = self.mechanism.title or self.mechanism.source
            shape = np.shape(self.valid)
            head = f"<Solution of {title!r} by {self.method}"
            if shape:
                return f"{head}: {shape[0]} postures ({int(np.sum(self.valid))} assembled)>"
            moving = [k for k in self.links if k != FRAME]
            text = ", ".join(f"θ{k} = {float(np.degrees(self.links[k].angle)):.4g}°"
                             for k in moving)
            if self.has_rates:
                text += "; " + ", ".join(f"ω{k} = {float(self.links[k].omega):.4g}"  # type: ignore[arg-type]
                                         for k in moving) + " rad/s"
            if self.constructions:
                text += f"; diagrams {' '.join(self.constructions)}"
            return f"{head}: {text}>"
        except Exception:  # a repr never raises
            return f"<Solution at {id(self):#x}>"

    @property
    def has_rates(self) -> bool:
        """True when velocities (and accelerations) are known."""
        return all(s.omega is not None for s in self.links.values())

    @property
    def has_accelerations(self) -> bool:
        """True when accelerations are known."""
        return all(s.alpha is not None for s in self.links.values())

    def velocity_scale(self) -> float:
        """The size of the velocities: the largest ``|V|`` of a named point or ``|ω|`` × size.

        Verdicts on a velocity (a slider at rest on its guide, the sense of ω) are
        taken relative to it (:func:`graphkin.tolerance.is_zero`); 0 without rates.
        """
        if not self.has_rates:
            return 0.0
        size = self.mechanism.size
        big = 0.0
        for lid, st in self.links.items():
            big = max(big, float(np.nanmax(np.abs(np.asarray(st.omega)), initial=0.0)) * size)
            pts = self.mechanism.links[lid].points
            if pts:
                v = st.velocity(np.array(list(pts.values()), dtype=float).reshape(
                    (len(pts),) + (1,) * np.ndim(st.angle) + (2,)))
                big = max(big, float(np.nanmax(np.hypot(v[..., 0], v[..., 1]), initial=0.0)))
        return big

    def owner(self, name: str) -> str:
        """A link that carries point ``name``: the frame for a fixed point, else the first."""
        owners = self.mechanism.point_links[name]
        return FRAME if FRAME in owners else owners[0]

    def position(self, name: str, link: str | None = None) -> np.ndarray:
        """World position of named point ``name`` (of ``link``, default its owner)."""
        lid = link or self.owner(name)
        return self.links[lid].position(self.mechanism.links[lid].points[name])

    def velocity(self, name: str, link: str | None = None) -> np.ndarray:
        """Absolute velocity of named point ``name`` (of ``link``)."""
        lid = link or self.owner(name)
        try:
            return self.links[lid].velocity(self.mechanism.links[lid].points[name])
        except ValueError:
            raise self._no_rates("velocities") from None

    def acceleration(self, name: str, link: str | None = None) -> np.ndarray:
        """Absolute acceleration of named point ``name`` (of ``link``)."""
        lid = link or self.owner(name)
        try:
            return self.links[lid].acceleration(self.mechanism.links[lid].points[name])
        except ValueError:
            raise self._no_rates("accelerations") from None

    def _no_rates(self, what: str) -> ValueError:
        """Why the rates are unknown: the file gives none, or this posture is a dead point.

        At a toggle or dead-center posture (Sec. 3.5) the file's rates cannot
        be carried through: that is said, not "the file gives no rates".
        """
        from graphkin.errors import InputError

        mech = self.mechanism
        if not mech.has_rates:
            return InputError(f"{what} are not known (the file gives no rates)", key="drive",
                              file=mech.source)
        why = next((n for n in self.notes if "toggle or dead-center" in n
                    or "undetermined" in n or "dead" in n), None)
        return InputError(f"{what} are not defined in this posture although the file gives "
                          "rates" + (f": {why}" if why else
                                     " (a toggle or dead-center posture, Sec. 3.5)"),
                          key="drive", file=mech.source)

    def _repr_svg_(self) -> str | None:
        """Jupyter: the solved posture drawn inline, without the table (a fraction of a second).

        Another diagram shows itself the same way: ``sol.draw("velocity")``;
        the whole sheet is ``sol.draw("all")``.  matplotlib is imported only here.
        """
        from graphkin.render import repr_svg

        return repr_svg(self, "posture", table=False)

    def draw(self, diagram: str = "posture", ax: Any = None, **kw: Any) -> Any:
        """Draw a diagram of this solution; see :func:`graphkin.render.draw`."""
        from graphkin.render import draw

        return draw(self, diagram, ax=ax, **kw)

    def _link(self, link: str | int) -> LinkState:
        """The state of ``link`` (an id as in the file: ``"3"`` or ``3``)."""
        lid = str(link)
        try:
            return self.links[lid]
        except KeyError:
            from graphkin.errors import InputError

            raise InputError(f"no link {lid!r} (links: {', '.join(self.links)})",
                             key=lid) from None

    def angle(self, link: str | int) -> np.ndarray:
        """θ of ``link`` in degrees, counterclockwise from +x (:meth:`angle_rad` in radians).

        >>> import graphkin
        >>> sol = graphkin.examples.fourbar().solve()
        >>> round(float(sol.angle(3)), 2)  # Example 3.1: the book gives 20.92°
        20.92
        """
        return np.degrees(self._link(link).angle)

    def angle_rad(self, link: str | int) -> np.ndarray:
        """θ of ``link`` (rad)."""
        return self._link(link).angle

    def omega(self, link: str | int) -> np.ndarray:
        """ω of ``link`` (rad/s, counterclockwise positive)."""
        w = self._link(link).omega
        if w is None:
            raise self._no_rates("velocities")
        return w

    def alpha(self, link: str | int) -> np.ndarray:
        """α of ``link`` (rad/s², counterclockwise positive)."""
        a = self._link(link).alpha
        if a is None:
            raise self._no_rates("accelerations")
        return a
