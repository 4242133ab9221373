"""A gear file of a pair in mesh as a mechanism: two gears rolling on fixed centers.

A pair file (docs/formats/gears.md) gives two spur gears and their center
distance; the mechanism it stands for is the driver (link 2) turning on
``O2`` and the driven gear (link 3) on ``O3``, their operating pitch circles
rolling without slip (Sec. 7.9: the pitch circles at the operating center
distance ``C`` divide it in the ratio of the tooth numbers, ``R2' = C N2 /
(N3 ± N2)``, Eq. 7.2, Fig. 7.21), written as one ``[[rolling]]`` contact
(docs/formats/mechanism.md#rolling-contact-rolling), so ``graphkin live``
opens it as a page of gears rolling on fixed centers.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 3.7, 7.4, 7.9 (Fig. 7.21).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from graphkin.errors import InputError
from graphkin.gears.mesh import GearPair

__all__ = ["pair_mechanism"]


def pair_mechanism(pair: GearPair, path: str | Path) -> dict[str, Any]:
    """The mechanism file (as a dict) of a pair in mesh: driver 2 on O2, driven 3 on O3.

    Parameters
    ----------
    pair : GearPair
        The pair file's gears (:func:`graphkin.gears.file.load`).
    path : str or Path
        The gear file, for messages.

    Returns
    -------
    dict
        ``O2`` at the origin and ``O3`` at ``C`` along x (an internal gear, the
        ring round the pinion: at ``-C``, so the pitch circles touch at ``R2'``
        along x), each gear a link with its center and a point ``A2``/``A3`` on its operating pitch
        circle, the driver rolling on the driven gear (``contact`` outside, or
        inside a ring), and ``[drive]`` turning the driver at 1 rad/s from 0°.

    Raises
    ------
    InputError
        ``gears.<name>.kind``: a rack (its pitch line slides; no fixed center).

    Examples
    --------
    >>> from graphkin.gears.file import loads
    >>> p = loads(chr(10).join(['diametral_pitch = 10', 'pressure_angle = 20',
    ...                         '[gears.pinion]', 'teeth = 20',
    ...                         '[gears.gear]', 'teeth = 50']))
    >>> d = pair_mechanism(p, "pair.toml")
    >>> d["links"]["1"]["O3"], d["rolling"][0]["circle"]["radius"]
    ([3.5, 0.0], 1.0)
    """
    g2, g3 = pair.driver, pair.driven
    src = str(path)
    for g in (g2, g3):
        if g.rack:
            raise InputError("no live page for a rack: its pitch line slides on the frame, "
                             "there are no two fixed centers to roll on; write it as a "
                             "mechanism with a [[rolling]] line and a slider "
                             "(docs/formats/mechanism.md)", key=f"gears.{g.name}.kind",
                             file=src)
    if g2.internal:
        raise InputError("the driver is an internal gear: give the pinion first",
                         key=f"gears.{g2.name}", file=src)
    c = float(pair.center)
    inside = g3.internal
    # operating pitch radii: C divided in the ratio of the teeth (Sec. 7.9, Eq. 7.2)
    r2 = c * g2.teeth / ((g3.teeth - g2.teeth) if inside else (g3.teeth + g2.teeth))
    r3 = r2 * g3.teeth / g2.teeth
    # outside: O3 at +C; inside: the ring's center O3 at -C, so the pinion's pitch circle
    # touches the ring's at +r2 along x, as outside gears touch between the centers
    o3 = -c if inside else c
    return {
        "title": pair.title or Path(src).stem,
        "units": pair.units,
        "links": {"1": {"O2": [0.0, 0.0], "O3": [o3, 0.0]},
                  "2": {"O2": [0.0, 0.0], "A2": [r2, 0.0]},
                  "3": {"O3": [0.0, 0.0], "A3": [r3, 0.0]}},
        "rolling": [{"link": 2, "on": 3, "circle": {"center": "O2", "radius": r2},
                     "on_circle": {"center": "O3", "radius": r3},
                     "contact": "inside" if inside else "outside"}],
        "drive": {"link": 2, "angle": 0.0, "omega": 1.0},
    }
