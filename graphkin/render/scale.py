"""Drawing scales, units and numbers, the way a draftsman writes them on a sheet.

A diagram is drawn *to scale*: one paper unit (an inch for files in inches or
feet, a centimetre otherwise) stands for a round number of the diagram's
quantity, ``1 in = 20 ft/s``.  The round numbers are 1, 2, 2.5 and 5 times a
power of ten, as on a draftsman's scale.  Nothing here imports matplotlib.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity scale of a
polygon, Fig. 3.5) and Sec. 4.3 (the acceleration scale, Fig. 4.4).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from graphkin.text import fmt, fmt_angle

__all__ = ["NICE", "SERIES_125", "nice_ceil", "paper_unit", "Scale", "choose_scale",
           "quantity_unit", "fmt", "fmt_angle", "CM"]

NICE = (1.0, 2.0, 2.5, 5.0)
"""The round numbers of a draftsman's scale (times a power of ten)."""

SERIES_125 = (1.0, 2.0, 5.0)
"""The 1-2-5 series a handout page uses (``1 cm = 50 mm/s``, ``1 in = 20 ft/s``)."""

CM = 1 / 2.54
"""One centimetre in inches."""

_IMPERIAL = {"in", "inch", "inches", "ft", "foot", "feet", "yd", "yard", "mil", "thou"}

# a larger unit to state a scale in when the numbers grow big: (unit, factor, threshold)
_BIGGER = {"mm": ("m", 1000.0, 1000.0), "cm": ("m", 100.0, 100.0),
           "in": ("ft", 12.0, 120.0), "inch": ("ft", 12.0, 120.0)}


def nice_ceil(x: float, series: tuple[float, ...] = NICE) -> float:
    """The smallest round number (1, 2, 2.5, 5 × 10^k) not below ``x``.

    ``series`` gives the mantissas (:data:`SERIES_125` for a handout page).

    Examples
    --------
    >>> nice_ceil(3.2), nice_ceil(0.021), nice_ceil(250), nice_ceil(1)
    (5.0, 0.025, 250.0, 1.0)
    >>> nice_ceil(0.021, SERIES_125), nice_ceil(250, SERIES_125)
    (0.05, 500.0)

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (choosing a velocity scale).
    """
    if not math.isfinite(x) or x <= 0:
        return 1.0
    k = math.floor(math.log10(x))
    for _ in range(3):
        for n in series:
            v = n * 10.0**k
            if v >= x * (1 - 1e-12):
                return float(f"{v:.12g}")
        k += 1
    return float(f"{10.0 ** k:.12g}")  # pragma: no cover - the loop always returns


def paper_unit(length_unit: str) -> str:
    """The paper unit of a sheet: ``"in"`` for inch/foot files, ``"cm"`` for metric ones.

    Examples
    --------
    >>> paper_unit("ft"), paper_unit("mm")
    ('in', 'cm')
    """
    return "in" if length_unit.strip().lower() in _IMPERIAL else "cm"


def quantity_unit(length_unit: str, plane: str) -> str:
    """The unit of a diagram's plane: ``in``, ``in/s`` or ``in/s²``.

    Examples
    --------
    >>> quantity_unit("mm", "acceleration")
    'mm/s²'
    """
    return {"velocity": f"{length_unit}/s",
            "acceleration": f"{length_unit}/s²"}.get(plane, length_unit)


@dataclass(frozen=True, slots=True)
class Scale:
    """A drawing scale: ``1 paper = value unit``.

    Attributes
    ----------
    per_inch : float
        Data units (the file's units) per inch of paper: the factor the
        drawing uses.
    paper : str
        ``"in"`` or ``"cm"``.
    value : float
        The round number written on the sheet, in ``unit``.
    unit : str
        The unit the scale is written in (maybe larger than the data's).
    factor : float
        Data units per ``unit`` (1000 for mm written as m).

    Examples
    --------
    >>> s = choose_scale(376.99, 2.0, "in", "in/s")
    >>> s.text, round(s.per_inch, 6)
    ('1 in = 20 ft/s', 240.0)
    """

    per_inch: float
    paper: str
    value: float
    unit: str
    factor: float = 1.0

    @property
    def paper_inches(self) -> float:
        """One paper unit in inches."""
        return 1.0 if self.paper == "in" else CM

    @property
    def text(self) -> str:
        """The scale as written on the sheet: ``1 in = 20 ft/s``."""
        return f"1 {self.paper} = {fmt(self.value, 4)} {self.unit}"


def choose_scale(extent: float, max_inches: float, paper: str, unit: str,
                 series: tuple[float, ...] = NICE) -> Scale:
    """The round scale that fits ``extent`` data units into ``max_inches`` of paper.

    Parameters
    ----------
    extent : float
        The largest span of the diagram, in data units.
    max_inches : float
        The room on the sheet (inches).
    paper : str
        ``"in"`` or ``"cm"``.
    unit : str
        The data unit (``"in/s"``); a larger unit is used for the text when the
        numbers grow big (mm/s written as m/s, in/s as ft/s).
    series : tuple of float
        The round mantissas (:data:`NICE`, or :data:`SERIES_125` on a handout).

    Returns
    -------
    Scale

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.4.
    """
    base, _, rest = unit.partition("/")
    big = _BIGGER.get(base)
    paper_in = 1.0 if paper == "in" else CM
    need = max(extent, 1e-300) / max_inches * paper_in  # data units per paper unit
    factor, shown = 1.0, unit
    value = nice_ceil(need, series)
    if big is not None and value >= big[2]:
        shown = big[0] + ("/" + rest if rest else "")
        factor = big[1]
        value = nice_ceil(need / factor, series)
    return Scale(per_inch=value * factor / paper_in, paper=paper, value=value, unit=shown,
                 factor=factor)
