"""Hypothesis strategies: random gear-train files whose speeds are known by hand.

Each strategy writes a train file (docs/formats/gears.md, "Gear trains") as
parsed TOML and, beside it, every member's angular velocity derived by hand
from the train formula, not by graphkin:

* ``chain``: gears on fixed axes in a row, each stage simple (an idler) or
  compound (two gears joined on one shaft, Sec. 7.13), external, or a pinion
  alone inside a ring; only chains whose gears clear each other when drawn
  in a straight line (the test of the layout's directions needs that); ω of
  each driven gear is its driver's times ``∓ N_driver / N_driven`` (Eq.
  7.22), the first gear given;
* ``planetary``: a sun 2, an arm 3, a planet 4 (with, sometimes, a second
  planet gear 5 joined to it: the reverted train of Example 7.4) and an
  output gear 6, a ring round the planet or an external gear coaxial with
  the sun; sometimes a gear 7 also in mesh with planet 4 (Ferguson's
  paradox, Example 7.10).  The teeth close the center distances or not
  (random).  Two of 2, 3 and 6 are given (one may be held at 0); Eq. (7.25)
  ``ω_L = ω_A + e (ω_F − ω_A)`` with ``e = (−N2/N4)(± N_p/N6)`` gives the
  others.

* ``arm on arm`` (:func:`arms_on_arms`, not in :func:`gear_trains`): an arm
  carried by another arm.  Arm 2 turns about the frame's axis with two
  central gears 4 and 7 (each a sun or a ring); gears 3 and 5 turn freely on
  one pin of arm 2, 3 in mesh with 4 and 5 with 7; gear 3 is itself the arm
  of the second stage (``arm = 3``, or an arm ``B`` joined to it), carrying
  planet 6 round gear 5.  Eq. (7.25) once per arm, seen from each:
  ``ω3 = ω2 + e1 (ω4 − ω2)``, ``ω5 = ω2 + e2 (ω7 − ω2)``,
  ``ω6 = ω3 + (−N5/N6)(ω5 − ω3)``.  Arm 2, gear 7 and gear 4 or the inner
  arm 3 are given (4 and 7 may be held at 0).  Only trains whose gear 6 clears gears 4
  and 7 drawn in a straight line (as ``chain``).

Sizes are teeth or radii (``[radii]``), speeds in rad/s.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from hypothesis import assume
from hypothesis import strategies as st

__all__ = ["RandomTrain", "gear_trains", "arms_on_arms"]


@dataclass
class RandomTrain:
    """A train file (as parsed TOML) and each member's ω derived by hand (rad/s)."""

    kind: str
    data: dict[str, Any]
    omega: dict[str, float]


_TEETH = st.integers(12, 80)
_SPEED = st.floats(1.0, 50.0).flatmap(lambda v: st.sampled_from([v, -v]))


def _sizes(draw: Any, teeth: dict[str, int]) -> dict[str, Any]:
    if draw(st.booleans()):
        return {"teeth": teeth}
    scale = draw(st.sampled_from([0.5, 1.25, 2.0]))
    return {"radii": {g: n * scale for g, n in teeth.items()}}


@st.composite
def _chain(draw: Any) -> RandomTrain:
    stages = draw(st.integers(1, 4))
    teeth: dict[str, int] = {}
    meshes: list[dict[str, Any]] = []
    joined: list[dict[str, Any]] = []
    name = 2
    first = str(name)
    teeth[first] = draw(_TEETH)
    w = draw(_SPEED)
    omega = {first: w}
    driver = first
    for _ in range(stages):
        name += 1
        driven = str(name)
        # a ring only round a pinion alone: a gear in mesh with the pinion, or driven by the
        # ring or joined to it, cannot always clear the ring's rim or the pinion in one plane
        # (Example 7.5's ring is in the planetary kind)
        internal = stages == 1 and draw(st.booleans())
        n = draw(st.integers(teeth[driver] + 12, 150)) if internal else draw(_TEETH)
        teeth[driven] = n
        mesh: dict[str, Any] = {"gears": [int(driver), int(driven)]}
        if internal:
            mesh["contact"] = "internal"
        meshes.append(mesh)
        sign = 1.0 if internal else -1.0
        omega[driven] = omega[driver] * sign * teeth[driver] / n    # Eq. (7.22)
        if draw(st.booleans()):   # compound: the next driver on the driven gear's shaft
            name += 1
            nxt = str(name)
            teeth[nxt] = draw(_TEETH)
            joined.append({"members": [int(driven), int(nxt)]})
            omega[nxt] = omega[driven]
            driver = nxt
        else:
            driver = driven
    # drawn in a straight line, every two gears on shafts no mesh joins clear each other
    # (else a large gear beside a small one two meshes away overlaps it in any drawing:
    # gears in different planes, which the layout says in one line)
    axis = {first: 0.0}
    shafts = [[first]]
    for mesh in meshes:
        a, b = (str(g) for g in mesh["gears"])
        along = axis[a] + (teeth[b] - teeth[a] if "contact" in mesh else teeth[a] + teeth[b])
        group = next((j["members"] for j in joined if int(b) in j["members"]), [int(b)])
        shafts.append([str(g) for g in group])
        for g in group:
            axis[str(g)] = along
    for i, s in enumerate(shafts):
        for other in shafts[i + 2:]:
            for g in s:
                for h in other:
                    assume(abs(axis[g] - axis[h]) > teeth[g] + teeth[h])
    data: dict[str, Any] = {"title": "random chain", **_sizes(draw, teeth), "mesh": meshes,
                            "speeds": {first: w}}
    if joined:
        data["joined"] = joined
    return RandomTrain("chain", data, omega)


@st.composite
def _planetary(draw: Any) -> RandomTrain:
    ns, np4 = draw(_TEETH), draw(_TEETH)
    compound = draw(st.booleans())
    np5 = draw(_TEETH) if compound else np4
    ring = draw(st.booleans())
    close = draw(st.booleans())
    if ring:
        n6 = ns + np4 + np5 if close else draw(st.integers(np5 + 12, 200))
    else:
        n6 = ns + np4 - np5 if close else draw(_TEETH)
    assume(n6 >= 12 and (not ring or n6 >= np5 + 12))
    teeth = {"2": ns, "4": np4}
    meshes: list[dict[str, Any]] = [{"gears": [2, 4], "arm": 3}]
    planet_out = "4"
    if compound:
        teeth["5"] = np5
        planet_out = "5"
    teeth["6"] = n6
    out: dict[str, Any] = {"gears": [int(planet_out), 6], "arm": 3}
    if ring:
        out["contact"] = "internal"
    meshes.append(out)
    ferguson = not compound and draw(st.integers(0, 3)) == 0
    if ferguson:
        teeth["7"] = draw(_TEETH)
        meshes.append({"gears": [4, 7], "arm": 3})
    # Eq. (7.24): the train value from 2 to 6 seen from the arm
    e = (-ns / np4) * ((np5 / n6) if ring else (-np5 / n6))
    pick = draw(st.sampled_from([("2", "3"), ("2", "6"), ("3", "6")]))
    held = draw(st.sampled_from([None, *pick]))
    given = {m: (0.0 if m == held else draw(_SPEED)) for m in pick}
    if pick == ("2", "3"):
        w2, w3 = given["2"], given["3"]
        w6 = w3 + e * (w2 - w3)
    elif pick == ("2", "6"):
        assume(abs(1.0 - e) > 1e-3)
        w2, w6 = given["2"], given["6"]
        w3 = (w6 - e * w2) / (1.0 - e)
    else:
        w3, w6 = given["3"], given["6"]
        w2 = w3 + (w6 - w3) / e
    omega = {"2": w2, "3": w3, "6": w6, "4": w3 + (-ns / np4) * (w2 - w3)}
    if compound:
        omega["5"] = omega["4"]
    if ferguson:   # 2 -> 4 -> 7 from the arm: (−N2/N4)(−N4/N7)
        omega["7"] = w3 + (ns / teeth["7"]) * (w2 - w3)
    data: dict[str, Any] = {"title": "random planetary train", **_sizes(draw, teeth),
                            "mesh": meshes, "speeds": given}
    if compound:
        data["joined"] = [{"members": [4, 5]}]
    return RandomTrain("planetary" + (", reverted" if compound else "")
                       + (", ring" if ring else "") + (", Ferguson" if ferguson else ""),
                       data, omega)


def gear_trains() -> st.SearchStrategy[RandomTrain]:
    """Random train files of every kind above, with each member's ω by hand."""
    return st.one_of(_chain(), _planetary())


def _clear(d: float, r: float, r_ring: bool, s: float, s_ring: bool) -> bool:
    """Two pitch circles ``d`` apart stand clear: apart, or one wholly inside a ring."""
    return d > r + s or (s_ring and d + r < s) or (r_ring and d + s < r)


@st.composite
def arms_on_arms(draw: Any) -> RandomTrain:
    """Arm 3 (gear 3, or an arm ``B`` joined to it) on a pin of arm 2: see the docstring."""
    n = {g: draw(_TEETH) for g in ("3", "5", "6")}
    ring4, ring7 = draw(st.booleans()), draw(st.booleans())
    n["4"] = draw(st.integers(n["3"] + 12, 160)) if ring4 else draw(_TEETH)
    n["7"] = draw(st.integers(n["5"] + 12, 160)) if ring7 else draw(_TEETH)
    # drawn in a straight line (1 tooth = 1 length unit: only the clearance's sign counts):
    # the pin at d1 from the frame's axis, planet 6 at d1 + d2; 6 clears 4 and 7
    d1 = n["4"] - n["3"] if ring4 else n["4"] + n["3"]
    d2 = n["5"] + n["6"]
    assume(_clear(d1 + d2, n["6"], False, n["4"], ring4))
    assume(_clear(d1 + d2, n["6"], False, n["7"], ring7))
    joined = draw(st.booleans())
    inner = "B" if joined else "3"
    meshes: list[dict[str, Any]] = [{"gears": [4, 3], "arm": 2}, {"gears": [7, 5], "arm": 2},
                                    {"gears": [5, 6], "arm": inner}]
    for mesh, ring in ((meshes[0], ring4), (meshes[1], ring7)):
        if ring:
            mesh["contact"] = "internal"
    e1 = (1.0 if ring4 else -1.0) * n["4"] / n["3"]     # Eq. (7.24), seen from arm 2
    e2 = (1.0 if ring7 else -1.0) * n["7"] / n["5"]
    inner_given = draw(st.booleans())   # the inner arm's motion given, not gear 4's
    third = "3" if inner_given else "4"
    # (a member given 0 is part of the frame: not the inner arm, which turns on a pin)
    given = {"2": draw(_SPEED), third: draw(_SPEED) if inner_given
             else draw(st.sampled_from([0.0, draw(_SPEED)])),
             "7": draw(st.sampled_from([0.0, draw(_SPEED)]))}
    w2, w7 = given["2"], given["7"]
    if inner_given:
        w3 = given["3"]
        w4 = w2 + (w3 - w2) / e1                         # Eq. (7.25) solved for gear 4
    else:
        w4 = given["4"]
        w3 = w2 + e1 * (w4 - w2)                         # Eq. (7.25)
    w5 = w2 + e2 * (w7 - w2)
    w6 = w3 + (-n["5"] / n["6"]) * (w5 - w3)             # Eq. (7.25), seen from arm 3
    omega = {"2": w2, "3": w3, "4": w4, "5": w5, "6": w6, "7": w7}
    data: dict[str, Any] = {"title": "random arm on an arm", **_sizes(draw, n),
                            "mesh": meshes, "speeds": given}
    if joined:
        data["joined"] = [{"members": [3, "B"]}]
        omega["B"] = w3
    return RandomTrain("arm on arm" + (", joined" if joined else "")
                       + (", inner arm given" if inner_given else "") + (", ring 4" if ring4
                       else "") + (", ring 7" if ring7 else ""), data, omega)
