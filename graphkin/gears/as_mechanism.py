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
from graphkin.gears.train_layout import TrainLayout, train_mechanism

__all__ = ["pair_mechanism", "rack_mechanism", "train_mechanism", "TrainLayout"]


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
        ``gears.<name>.kind``: a rack given first (a rack second is
        :func:`rack_mechanism`).

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
    if g3.rack:
        return rack_mechanism(pair, path)
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


def rack_mechanism(pair: GearPair, path: str | Path) -> dict[str, Any]:
    """The mechanism file (as a dict) of a pinion driving a rack: the rack slides on the frame.

    The pinion (link 2) turns on ``O2`` at the origin; the rack (link 3) slides
    on the frame along x (a slider through its point ``R3`` on the frame's line
    ``S1``-``S2``, along the rack's back ``B3``-``R3``, ``R2/2`` below its pitch line), its
    pitch line ``L3a``-``L3b`` the tangent to the pinion's
    pitch circle at ``P`` below the center (Sec. 7.5, Fig. 7.10: the rack's
    pitch line touches the pinion's *standard* pitch circle, whatever the
    pinion's offset).  The pitch circle rolls on the pitch line (a
    ``[[rolling]]`` line contact, the circle on its left), so the rack moves
    ``V = ω2 R2`` along x (Sec. 3.7); the pinion is turned at 1 rad/s
    counterclockwise from 0°.

    Examples
    --------
    >>> from graphkin.gears.file import loads
    >>> p = loads(chr(10).join(['diametral_pitch = 10', 'pressure_angle = 20',
    ...                         '[gears.pinion]', 'teeth = 20',
    ...                         '[gears.rack]', 'kind = "rack"']))
    >>> d = rack_mechanism(p, "rack.toml")
    >>> d["links"]["3"]["L3a"], d["rolling"][0]["side"]
    ([-3.0, -1.0], 'left')
    """
    src = str(path)
    r2 = float(pair.driver.pitch_radius)
    half = 3.0 * r2   # the rack drawn 6 R2 long, centered under the pinion
    back = 1.5 * r2   # its guide along its back, half a radius below the pitch line
    return {
        "title": pair.title or Path(src).stem,
        "units": pair.units,
        "links": {"1": {"O2": [0.0, 0.0], "S1": [-half, -back], "S2": [half, -back]},
                  "2": {"O2": [0.0, 0.0], "A2": [r2, 0.0]},
                  "3": {"L3a": [-half, -r2], "L3b": [half, -r2], "R3": [half, -back],
                        "B3": [-half, -back]}},
        "sliders": [{"link": 3, "on": 1, "point": "R3", "line": ["S1", "S2"]}],
        "rolling": [{"link": 2, "on": 3, "circle": {"center": "O2", "radius": r2},
                     "line": ["L3a", "L3b"], "side": "left"}],
        "drive": {"link": 2, "angle": 0.0, "omega": 1.0},
    }
