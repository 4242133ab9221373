"""The result of a sweep: its columns, its report lines and its CSV.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Secs. 2.8, 3.4-3.6, 4.2-4.6.
"""

from __future__ import annotations

import csv
import io
import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import IO, Any

import numpy as np

from graphkin.kinematics.solution import Solution
from graphkin.kinematics.sweep.columns import _concat_solutions, _solution_of_block
from graphkin.kinematics.sweep.engine import _Block, _Engine
from graphkin.kinematics.sweep.singular import SingularPosture, _singular, time_ratios
from graphkin.mechanisms.model import Drive, Mechanism
from graphkin.text import ROUND_OFF

Array = np.ndarray


@dataclass
class Sweep:
    """A mechanism solved over many drive values at once.

    Attributes
    ----------
    mechanism : Mechanism
    drive : Drive
        The swept drive (the first one; the others are held at the file's values).
    values : ndarray, shape (N,)
        The drive values: radians for an angle, the file's length unit for a slider.
    columns : dict
        CSV column name (``docs/formats/sweep-csv.md``) -> 1-D array of length N; NaN
        where the posture cannot be assembled (and, for the rates only,
        where they are not defined).
    valid : ndarray of bool
        Postures that assemble and whose rates are finite.
    assembled : ndarray of bool
        Postures that assemble.
    method : str
        ``"construction"``, or ``"analytic"`` when the mechanism cannot be solved
        one group at a time (``notes`` says why).
    notes : list of str
    branches : dict
        Step label -> the branch kept through the sweep.

    Notes
    -----
    ``solution`` (the sweep as a :class:`Solution`), ``singular`` (ranges,
    dead centers, limit positions) and ``unassembled`` are computed when first
    asked for.  The evaluated constructions keep only the values the sweep
    reports (named points, link angles, rates and their images).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 2.8, 3.4-3.6, 4.2-4.6.

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.examples.crank_rocker()
    >>> sw = mech.sweep(count=8)
    >>> sw.columns["drive"]
    array([ 60., 105., 150., 195., 240., 285., 330., 375.])
    >>> bool(sw.valid.all()), list(sw.columns)[:5]
    (True, ['drive', 'angle_1', 'omega_1', 'alpha_1', 'angle_2'])
    """

    mechanism: Mechanism
    drive: Drive
    values: Array
    columns: dict[str, Array]
    valid: Array
    assembled: Array
    method: str = "construction"
    notes: list[str] = field(default_factory=list)
    branches: dict[str, str] = field(default_factory=dict)
    _engine: _Engine | None = field(default=None, repr=False, compare=False)
    _parts: list[_Block] = field(default_factory=list, repr=False, compare=False)
    _cyclic: bool = field(default=False, repr=False, compare=False)
    _released: bool = field(default=False, repr=False, compare=False)

    @property
    def _blocks(self) -> list[_Block]:
        """The evaluated blocks; a long sweep let their values go and replays them here."""
        if self._released:
            eng = self._engine
            assert eng is not None
            for i, b in enumerate(self._parts):
                if b.ev is None and b.analytic is None:
                    again = eng.solve(b.dv)
                    again.user = b.user
                    self._parts[i] = again
            self._released = False
        return self._parts

    def __len__(self) -> int:
        return len(self.values)

    def __repr__(self) -> str:
        """A short summary: size, drive range, how many postures assemble, the columns.

        >>> import graphkin
        >>> graphkin.examples.crank_rocker().sweep(count=8)  # doctest: +ELLIPSIS
        <Sweep of 'Crank-rocker...': 8 postures, drive 60 to 375, 8 valid, ... columns: drive, ...>
        """
        try:
            cols = list(self.columns)
            shown = ", ".join(cols[:6]) + (", ..." if len(cols) > 6 else "")
            d = self.drive_values
            title = self.mechanism.title or self.mechanism.source
            return (f"<Sweep of {title!r}: {len(self)} postures, drive {d[0]:g} to {d[-1]:g}, "
                    f"{int(np.count_nonzero(self.valid))} valid, {len(cols)} columns: {shown}>")
        except Exception:  # noqa: BLE001 - a repr never raises
            return f"<Sweep at {id(self):#x}>"

    def _repr_html_(self) -> str:
        """Jupyter: a small table, the size, the columns and the first and last postures.

        The values are the CSV's (``docs/formats/sweep-csv.md``); ``sw.columns`` holds all.
        """
        import html

        from graphkin.text import fmt

        cols = list(self.columns)
        n = len(self)
        rows = list(range(min(n, 3))) + ([-1] if n > 4 else []) + list(range(max(3, n - 2), n))
        head = "".join(f"<th>{html.escape(c)}</th>" for c in cols)
        body = []
        for r in rows:
            if r < 0:
                body.append(f"<tr><td colspan='{len(cols)}'>… {n - 5} more …</td></tr>")
                continue
            body.append("<tr>" + "".join(
                f"<td>{html.escape(fmt(float(self.columns[c][r]), 6))}</td>" for c in cols)
                + "</tr>")
        title = html.escape(self.mechanism.title or self.mechanism.source)
        return (f"<div><p><b>Sweep</b> of {title}: {n} postures × {len(cols)} columns, "
                f"{int(np.count_nonzero(self.valid))} valid ({html.escape(self.method)})</p>"
                "<div style='overflow-x:auto'><table><thead><tr>" + head + "</tr></thead>"
                "<tbody>" + "".join(body) + "</tbody></table></div></div>")

    @property
    def drive_values(self) -> Array:
        """The drive values as written in the CSV: degrees, or the slider's travel."""
        return self.columns["drive"]

    @cached_property
    def solution(self) -> Solution:
        """The sweep as a :class:`Solution` whose arrays have the leading shape (N,)."""
        assert self._engine is not None
        sols = [_solution_of_block(self._engine, b) for b in self._blocks]
        if len(sols) == 1:
            return sols[0]
        return _concat_solutions(sols)

    @cached_property
    def singular(self) -> list[SingularPosture]:
        """Ranges that cannot be assembled, dead centers and limit positions, in drive order.

        Boundaries are refined by bisection on the drive (to well below 0.01°).
        """
        return _singular(self)

    @property
    def unassembled(self) -> list[tuple[float, float]]:
        """Drive ranges (degrees or travel) where the mechanism cannot be assembled."""
        return [(s.drive, s.end if s.end is not None else s.drive) for s in self.singular
                if s.kind == "cannot-assemble"]

    def report(self, events: bool = False) -> list[str]:
        """Lines for standard error: notes, unassemblable ranges (and, with ``events``, the rest).

        Dead centers inside an assembled range (a change point, where the
        named branch may stop being the continuous one) are always reported.
        """
        out = list(self.notes)
        for s in self.singular:
            if s.kind == "cannot-assemble" or events:
                out.append(s.note)
            elif s.change_point:
                out.append(s.note)
        if events:
            out += time_ratios(self)
        return out

    def to_csv(self, file: str | IO[str], *, columns: dict[str, Array] | None = None,
               units_row: Sequence[str] | None = None) -> None:
        """Write the columns as CSV: one row per posture; empty cells where not defined.

        ``columns`` replaces :attr:`columns` (the same columns in other units,
        :func:`graphkin.output.csv.convert_columns`); ``units_row`` is written
        as a second header line, one unit per column.
        """
        if isinstance(file, str):
            with open(file, "w", newline="", encoding="utf-8") as fh:
                self._write(fh, columns, units_row)
        else:
            self._write(file, columns, units_row)

    def csv_text(self) -> str:
        """The CSV as a string."""
        buf = io.StringIO()
        self._write(buf)
        return buf.getvalue()

    def _write(self, fh: IO[str], columns: dict[str, Array] | None = None,
               units_row: Sequence[str] | None = None) -> None:
        columns = self.columns if columns is None else columns
        w = csv.writer(fh, lineterminator="\n")
        names = list(columns)
        w.writerow(names)
        if units_row is not None:
            w.writerow(units_row)
        cols = []
        rounded = _rounded_at_round_off(columns)
        for name in names:
            c = rounded[name]
            lst: list[Any] = c.tolist()
            if not np.isfinite(c).all():
                lst = ["" if not math.isfinite(v) else v for v in lst]
            cols.append(lst)
        w.writerows(zip(*cols))


def _kind(name: str) -> str:
    """The quantity a CSV column holds: ``angle``, ``omega``, …, ``x``/``y`` → ``position``."""
    head = name.split("_", 1)[0]
    return {"x": "position", "y": "position", "vx": "velocity", "vy": "velocity",
            "ax": "acceleration", "ay": "acceleration"}.get(head, head)


def _rounded_at_round_off(columns: dict[str, Array]) -> dict[str, np.ndarray]:
    """Every column rounded at :data:`~graphkin.text.ROUND_OFF` of its quantity's scale.

    The scale of a quantity is its largest value over all its columns (every
    point's x and y, every link's ω, ...), or 360° for angles; a value is
    rounded to the decimal place of ``ROUND_OFF`` × scale, so what the
    arithmetic left (a slider's line at 149.99999999998744° that solve prints
    150) is written as the value meant, consistently in every column.  The
    drive column is written as the sweep made it (docs/formats/sweep-csv.md).
    """
    arrays = {n: np.asarray(c, dtype=float) for n, c in columns.items()}
    scale: dict[str, float] = {}
    for n, c in arrays.items():
        finite = np.abs(c[np.isfinite(c)])
        top = float(finite.max()) if finite.size else 0.0
        k = _kind(n)
        scale[k] = max(scale.get(k, 360.0 if k == "angle" else 0.0), top)
    out: dict[str, np.ndarray] = {}
    for n, c in arrays.items():
        s = scale[_kind(n)]
        if n == "drive" or not s > 0 or not math.isfinite(s):
            out[n] = c
            continue
        places = -math.floor(math.log10(s * ROUND_OFF))
        out[n] = np.round(c, places) + 0.0          # + 0.0: never -0.0
    return out
