"""The cycle as pictures for slides: one SVG or PNG per posture, or an animated GIF.

The same data as the animation page (:func:`graphkin.render.cycle_data.cycle_data`,
from one sweep) drawn with matplotlib: the mechanism, and its velocity and
acceleration polygons to the fixed scale of the page.  The GIF is written by
matplotlib's Pillow writer (Pillow is a dependency of matplotlib).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4, 4.4.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.errors import InputError
from graphkin.mechanisms.model import Mechanism
from graphkin.render.cycle_data import cycle_data
from graphkin.render.style import STYLES, rc_context

__all__ = ["write_cycle_frames", "write_cycle_gif"]


LABEL_PT = float(STYLES["label"]["size"])
"""Point letters at ``draw``'s size (points)."""
SMALL_PT = float(STYLES["label-small"]["size"])
TITLE_PT = float(STYLES["title"]["size"])
_AROUND = ((1, 1), (1, -1), (-1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1))


class _Letters:
    """Letters of one panel, each where it overlaps no letter placed before it.

    Its usual place (up and right of its point) first, then rings around the
    point, farther out where it is crowded; inside the panel when it can be.
    Boxes are on paper (inches), sized from matplotlib's font metrics
    (:func:`graphkin.render.labels.text_size`), as ``draw`` places its labels.
    """

    def __init__(self, ax: Any) -> None:
        ax.apply_aspect()  # the panel's final box (an equal aspect shrinks it when drawn)
        self.ax = ax
        dpi = ax.figure.dpi
        self.frame = np.asarray(ax.get_window_extent().get_points()).ravel() / dpi
        self.placed: list[np.ndarray] = []

    def _cost(self, b: np.ndarray) -> float:
        f = self.frame
        out = max(f[0] - b[0], 0.0) + max(f[1] - b[1], 0.0) + max(b[2] - f[2], 0.0) \
            + max(b[3] - f[3], 0.0)
        cost = 1e6 * out
        for q in self.placed:
            ox = min(b[2], q[2]) - max(b[0], q[0])
            oy = min(b[3], q[3]) - max(b[1], q[1])
            if ox > 0 and oy > 0:
                cost += ox * oy
        return cost

    def put(self, xy: np.ndarray, text: str, size: float = LABEL_PT) -> None:
        """Letter the point ``xy`` (data units) with ``text`` at ``size`` points."""
        from graphkin.render.labels import text_size

        w, h = text_size(text, size)
        a = np.asarray(self.ax.transData.transform(xy), dtype=float) / self.ax.figure.dpi
        gap = 3.0 / 72  # the letter's usual offset: 3 pt up and right of its point
        tries = [(gap, gap)]
        for r in (0.5, 1.3, 2.3, 3.5):
            step = r * h
            for ux, uy in _AROUND:
                tries.append((ux * step + (gap if ux > 0 else -w - gap if ux < 0 else -w / 2),
                              uy * step + (gap if uy > 0 else -h - gap if uy < 0 else -h / 2)))
        best, least = None, math.inf
        for dx, dy in tries:
            b = np.array([a[0] + dx, a[1] + dy, a[0] + dx + w, a[1] + dy + h])
            c = self._cost(b)
            if c < least:
                best, least = b, c
            if c == 0:
                break
        assert best is not None
        self.placed.append(best)
        off = (best[:2] - a) * 72  # points
        self.ax.annotate(text, (xy[0], xy[1]), xytext=(off[0], off[1]),
                         textcoords="offset points", fontsize=size, ha="left", va="bottom")


def _val(series: list[int | None], q: float, i: int) -> float:
    v = series[i]
    return float("nan") if v is None else v * q


class _Drawer:
    """Draws one posture of the cycle's data into a matplotlib figure."""

    def __init__(self, data: dict[str, Any]) -> None:
        from matplotlib.figure import Figure

        self.d = data
        rated = bool(data["rates"])
        n = 3 if rated else 1
        self.fig = Figure(figsize=(4.2 * n, 4.0), dpi=100)
        self.axes = [self.fig.add_subplot(1, n, k + 1) for k in range(n)]
        self.kinds = ["mechanism"] + (["velocity", "acceleration"] if rated else [])

    def point(self, name: str, i: int, kind: str) -> np.ndarray:
        p, q = self.d["points"][name], self.d["q"]
        if kind == "mechanism":
            return np.array([_val(p["x"], q["L"], i), _val(p["y"], q["L"], i)])
        k = "v" if kind == "velocity" else "a"
        qq = q["V"] if kind == "velocity" else q["A"]
        return np.array([_val(p[k + "x"], qq, i), _val(p[k + "y"], qq, i)])

    def _bodies(self, ax: Any, i: int) -> None:
        """The bodies (a cam's profile, a roller, a face), turned and moved with their links."""
        from matplotlib.patches import Circle, Polygon

        qL = self.d["q"]["L"]
        for bd in self.d.get("bodies", []):
            o = np.array([_val(bd["ox"], qL, i), _val(bd["oy"], qL, i)])
            a = math.radians(_val(bd["angle"], 1e-4, i))
            if not (np.isfinite(o).all() and math.isfinite(a)):
                continue
            c, s = math.cos(a), math.sin(a)
            xy = np.array([[o[0] + c * x - s * y, o[1] + s * x + c * y] for x, y in bd["local"]])
            if bd["kind"] == "circle":
                ax.add_patch(Circle(tuple(xy[0]), bd["r"], fc="#eef3fa", ec="k", lw=0.8))
            elif bd["kind"] == "outline":
                ax.add_patch(Polygon(xy, closed=True, fc="#eef3fa", ec="k", lw=0.8))
            else:
                ax.plot(xy[:, 0], xy[:, 1], color="k", lw=2.5)

    def draw(self, i: int) -> Any:
        d = self.d
        for ax, kind in zip(self.axes, self.kinds):
            ax.clear()
            view = d["view"] if kind == "mechanism" else d[kind]["view"]
            ax.set_xlim(view[0], view[2])
            ax.set_ylim(view[1], view[3])
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            title = {"mechanism": "Mechanism", "velocity": "Velocity polygon",
                     "acceleration": "Acceleration polygon"}[kind]
            if kind != "mechanism":
                sc = d[kind]["scale"]
                title += f"  (bar: {sc['value']:g} {sc['unit']})"
                x0, y0 = view[0] + 0.05 * (view[2] - view[0]), view[1] + 0.05 * (view[3] - view[1])
                ax.plot([x0, x0 + sc["bar"]], [y0, y0], color="k", lw=1.5)
            ax.set_title(title, fontsize=TITLE_PT)
            if kind == "mechanism":
                self._bodies(ax, i)
            for lk in d["links"]:
                pts = [self.point(p, i, kind) for p in lk["points"]]
                if len(pts) < 2 or not all(np.isfinite(q).all() for q in pts):
                    continue
                arr = np.array(pts + ([pts[0]] if len(pts) >= 3 else []))
                if kind == "mechanism":
                    if len(pts) >= 3:
                        ax.fill(arr[:, 0], arr[:, 1], color=lk["fill"], alpha=0.9, lw=0)
                    ax.plot(arr[:, 0], arr[:, 1], color="k", lw=2 if len(pts) == 2 else 1.2)
                else:
                    if len(pts) >= 3:
                        ax.fill(arr[:, 0], arr[:, 1], color=lk["fill"], alpha=0.5, lw=0)
                    ax.plot(arr[:, 0], arr[:, 1], color="#555", lw=0.8)
            letters = _Letters(ax)
            for name in d["points"]:
                q = self.point(name, i, kind)
                if not np.isfinite(q).all():
                    continue
                if kind == "mechanism":
                    ax.plot(*q, "o", ms=4, mfc="w" if name in d["pins"] else "k", mec="k")
                    letters.put(q, name)
                elif name not in d["frame"]:
                    ax.annotate("", (q[0], q[1]), (0, 0),
                                arrowprops={"arrowstyle": "-|>", "lw": 1.2})
                    letters.put(q, name.lower() + ("′" if kind == "acceleration" else ""))
            if kind != "mechanism":
                ax.plot(0, 0, "o", color="#c62828", ms=4)
        unit = "°" if d["drive"]["unit"] == "°" else " " + d["drive"]["unit"]
        state = "" if d["valid"][i] == "1" else "  (cannot be assembled)"
        self.fig.suptitle(f"{d['title']}: {d['drive']['label']} = "
                          f"{d['drive']['values'][i]:.2f}{unit}{state}", fontsize=TITLE_PT)
        return self.fig


def write_cycle_frames(mech: Mechanism, directory: str | Path, *, count: int = 360,
                       start: float | None = None, stop: float | None = None,
                       fmt: str = "svg", keep: Sequence[str | Path] = ()) -> list[Path]:
    """Write one picture per posture of the cycle (``cycle-000.svg``, ...).

    Parameters
    ----------
    mech : Mechanism
    directory : str or Path
    count : int
    start, stop : float, optional
        The drive range, as for ``graphkin sweep``.
    fmt : str
        ``svg`` or ``png``.
    keep : sequence of path
        Files that must not be overwritten (the command's inputs): refused
        before any frame is written.

    Returns
    -------
    list of Path

    Raises
    ------
    InputError
        An unknown format, or a frame would overwrite a file of ``keep``.
    """
    from graphkin.files import check_output

    if fmt not in ("svg", "png"):
        raise InputError(f"frames are svg or png, not {fmt!r}", key="--frames")
    data = cycle_data(mech, count=count, start=start, stop=stop)
    out = Path(directory)
    width = max(3, len(str(data["n"] - 1)))
    paths = [out / f"cycle-{i:0{width}d}.{fmt}" for i in range(data["n"])]
    for p in paths:  # nothing the user gave may be lost: checked before any is written
        check_output(p, list(keep), "--frames")
    out.mkdir(parents=True, exist_ok=True)
    with rc_context():  # real text in the SVG, deterministic ids
        drawer = _Drawer(data)
        for k, i in enumerate(_in_time(data)):  # frame k is the k-th posture in time
            p = paths[k]
            drawer.draw(i).savefig(p, format=fmt,
                                   metadata={"Date": None} if fmt == "svg" else None)
    return paths


def write_cycle_gif(mech: Mechanism, path: str | Path, *, count: int = 120,
                    start: float | None = None, stop: float | None = None,
                    fps: int = 20) -> Path:
    """Write the cycle as an animated GIF (postures that cannot be assembled are skipped).

    Parameters
    ----------
    mech : Mechanism
    path : str or Path
    count : int
        Number of postures (frames).
    start, stop : float, optional
    fps : int
        Frames per second.

    Returns
    -------
    Path
    """
    from matplotlib.animation import PillowWriter

    data = cycle_data(mech, count=count, start=start, stop=stop)
    writer = PillowWriter(fps=fps)
    p = Path(path)
    with rc_context():
        drawer = _Drawer(data)
        _gif(drawer, writer, p, data)
    return p


def _in_time(data: dict[str, Any]) -> list[int]:
    """The postures in the order the drive reaches them: falling θ2 when ω2 is cw."""
    order = list(range(data["n"]))
    return order[::-1] if data.get("sense", 1) == -1 else order


def _gif(drawer: _Drawer, writer: Any, p: Path, data: dict[str, Any]) -> None:
    with writer.saving(drawer.fig, str(p), dpi=80):
        for i in _in_time(data):
            if data["valid"][i] == "1":
                drawer.draw(i)
                writer.grab_frame()
