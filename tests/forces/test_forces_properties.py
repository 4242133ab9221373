"""Random mechanisms with random loads and masses: the graphic method against two
independent checks.

1. The matrix method (:func:`graphkin.forces.solve_matrix`): Σ F = 0, Σ M = 0 of
   every moving link as one linear system, with none of the graphic decisions.
2. The power balance (virtual work, Sec. 11.11): Σ F·V + Σ T·ω = 0 over the loads,
   inertia forces and drives, from the velocity solution alone (no joint forces).
"""

from __future__ import annotations

import copy
from typing import Any

import numpy as np
from hypothesis import HealthCheck, example, given, settings
from hypothesis import strategies as st
from pinned import LOADED_DRIVE, SELF_LOCKING, with_friction
from strategies import (
    fourbars,
    inverted_slider_cranks,
    six_bars,
    slider_cranks,
    slotted,
)

from graphkin.errors import InputError
from graphkin.forces import power_balance, solve_forces
from graphkin.mechanisms import from_dict

FAMILIES = st.one_of(fourbars(other_rates=False), slider_cranks(), inverted_slider_cranks(),
                     six_bars(), slotted())


@st.composite
def loaded(draw: Any) -> tuple[Any, dict[str, Any]]:
    """A random mechanism with a force, a couple or mass properties on random links."""
    rm = draw(FAMILIES)
    data = copy.deepcopy(rm.data)
    s = rm.scale()
    moving = [lid for lid in data["links"] if str(lid) != "1"]
    loads, inertia = [], {}
    chosen = draw(st.lists(st.sampled_from(moving), min_size=1, max_size=len(moving),
                           unique=True))
    num = st.floats(-1.0, 1.0, allow_nan=False)
    def new_point(lid: str, name: str) -> str:
        pts = list(data["links"][lid].values())
        if all(p == pts[0] for p in pts):
            # a block whose named points coincide: the kinematics cannot place a new point
            # from them (the image of a third point needs two distinct ones), so load one
            return next(iter(data["links"][lid]))
        data["links"][lid][name] = [draw(num) * s, draw(num) * s]
        return name

    for lid in chosen:
        what = draw(st.sampled_from(["force", "couple", "inertia", "force+inertia"]))
        if "force" in what:
            name = new_point(lid, f"Q{lid}")
            mag = draw(st.floats(1.0, 1000.0))
            ang = draw(st.floats(-180.0, 180.0))
            loads.append({"link": int(lid) if str(lid).isdigit() else lid, "point": name,
                          "force": f"{mag} N at {ang} deg"})
        if what == "couple":
            loads.append({"link": int(lid) if str(lid).isdigit() else lid,
                          "torque": draw(st.floats(1.0, 1000.0)) * s
                          * draw(st.sampled_from([-1, 1]))})
        if "inertia" in what:
            name = new_point(lid, f"G{lid}")
            inertia[str(lid)] = {"center": name, "mass": f"{draw(st.floats(0.01, 10.0))} kg",
                                 "moment": f"{draw(st.floats(0.0, 1.0))} kg*m^2"}
    data["loads"] = loads
    if inertia:
        data["inertia"] = inertia
        if draw(st.booleans()):
            data["gravity"] = {"acceleration": "9.80665 m/s^2 at -90 deg"}
    data.setdefault("units", {})["force"] = "N"
    return rm, data


def _check(data: dict[str, Any], kind: str) -> None:
    mech = from_dict(data, source=f"<random {kind}>")
    sol = mech.solve()
    graphic = solve_forces(sol)
    assert graphic.method == "construction", graphic.notes
    matrix = solve_forces(sol, method="analytic")
    big = max([float(np.hypot(*w[:2])) for w in matrix.forces.values()] + [1.0])
    arm = mech.scale
    for key, w in matrix.forces.items():
        g = graphic.forces[key]
        assert np.all(np.abs(g[:2] - w[:2]) <= 1e-9 * big), (key, g, w)
        # the same line of action: moments about the origin agree to the forces' scale
        assert abs(g[2] - w[2]) <= 1e-9 * big * arm, (key, g, w)
    for lid, (_, t) in matrix.drives.items():
        tg = graphic.drives[lid][1]
        size = big * arm if graphic.drives[lid][0] == "torque" else big
        assert abs(tg - t) <= 1e-9 * size, (lid, tg, t)
    residual, size = power_balance(sol, graphic.dynamic,
                                   {k: v for k, (_, v) in graphic.drives.items()})
    # near a dead point every power is tiny while the velocities' round-off is not: it is
    # about eps · |ω| · (the mechanism's size), so the powers are judged against the
    # largest force times that speed too (a random inverted slider-crank at θ = 0 had
    # powers of 5e-16 and a residual of 6e-17 with forces and speeds of order 1)
    speed = max([abs(float(sol.omega(lid))) for lid in mech.moving] + [0.0]) * arm
    assert abs(residual) <= 1e-9 * max(size, big * speed, 1e-300), (residual, size)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(loaded())
def test_graphic_agrees_with_matrix_method_and_power(case: tuple[Any, dict[str, Any]]) -> None:
    rm, data = case
    _check(data, rm.kind)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(loaded())
def test_static_without_rates(case: tuple[Any, dict[str, Any]]) -> None:
    """The same files with no rates: a static analysis (inertia ignored, weights kept)."""
    rm, data = case
    data = copy.deepcopy(data)
    drives = data["drive"] if isinstance(data["drive"], list) else [data["drive"]]
    for d in drives:
        for k in ("omega", "alpha", "velocity", "acceleration"):
            d.pop(k, None)
    data.pop("rates", None)
    mech = from_dict(data, source="<random>")
    sol = mech.solve()
    graphic = solve_forces(sol)
    assert not graphic.dynamic and graphic.method == "construction"
    matrix = solve_forces(sol, method="analytic")
    big = max([float(np.hypot(*w[:2])) for w in matrix.forces.values()] + [1.0])
    for key, w in matrix.forces.items():
        assert np.all(np.abs(graphic.forces[key][:2] - w[:2]) <= 1e-9 * big)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(slider_cranks(), st.floats(0.05, 0.6), st.floats(1.0, 500.0), st.floats(-180, 180))
@example(LOADED_DRIVE, 0.5, 1.0, 0.0)
@example(SELF_LOCKING, 0.5, 1.0, 0.0)
def test_friction_is_coulomb(rm: Any, mu: float, mag: float, ang: float) -> None:
    """Rough sliders (Sec. 11.10): the graphic method agrees with the matrix method, and
    the force on each slider obeys Coulomb's law against its sliding velocity."""
    data = with_friction(rm, mu, mag, ang)
    mech = from_dict(data, source="<random slider-crank>")
    sol = mech.solve()
    try:
        graphic = solve_forces(sol)
    except InputError as exc:
        # Self-locking (Sec. 11.10): the unloaded coupler AC is a two-force member, so the
        # force on the block acts along AC; when AC lies within φ = atan μ of the guide's
        # normal, no force along it slides the block (found by Hypothesis: AC 26.0° from the
        # normal, φ = 26.57°, and the force on the block turned over once friction leant it).
        assert "self-locking" in str(exc)
        sl = mech.sliders[0]
        u = np.subtract(sl.p1, sl.p0) / np.hypot(*np.subtract(sl.p1, sl.p0))
        ac = np.subtract(sol.position("C"), sol.position("A"))
        off_normal = np.degrees(np.arccos(min(abs(float(ac @ np.array([-u[1], u[0]])))
                                              / float(np.hypot(*ac)), 1.0)))
        assert off_normal < np.degrees(np.arctan(mu)) + 1e-6
        return
    matrix = solve_forces(sol, method="analytic")
    # the joint forces' scale, or the load's when the drive takes the load directly
    big = max([float(np.hypot(*w[:2])) for w in matrix.forces.values()] + [mag])
    for key, w in matrix.forces.items():
        assert np.all(np.abs(graphic.forces[key][:2] - w[:2]) <= 1e-9 * big)
    for j in graphic.joints:
        if j.kind != "slide":
            continue
        sl = j.source
        f = graphic.force(sl.on, sl.link)
        st_on = sol.links[sl.on]
        u = st_on._r(np.subtract(sl.p1, sl.p0))
        u = u / np.hypot(*u)
        n = np.array([-u[1], u[0]])
        v = np.asarray(sol.velocity(sl.point, sl.link))  # the guide is the frame here
        tangential, normal = float(f @ u), float(f @ n)
        assert abs(abs(tangential) - mu * abs(normal)) <= 1e-9 * big
        # friction opposes the sliding (round-off aside)
        assert tangential * float(v @ u) <= 1e-9 * big * abs(float(v @ u))


def test_a_load_on_the_drive_slider_is_taken_by_the_drive() -> None:
    """Issue 23: 1 N along +x on the driving block C itself (μ = 0.5 at its guide).

    By hand: the block's free body has the load, the drive's force along the guide (+x)
    and the joint forces of AC and the guide.  Links 2 and 3 carry no load and no inertia,
    so AC and the crank's pins carry nothing (a two-force member with nothing at its other
    end); the guide's normal force is then 0 and so is its friction, and the drive takes
    the load: F = -1 N along the guide.  Every joint force is zero (at round-off of 1 N),
    and no friction or self-locking verdict may be taken from the sense of that round-off.
    """
    data = with_friction(LOADED_DRIVE, 0.5, 1.0, 0.0)
    sol = from_dict(data, source="<loaded drive>").solve()
    fs = solve_forces(sol)
    for key, w in fs.forces.items():
        assert np.hypot(*w[:2]) <= 1e-12, key
    kind, value = fs.drives["4"]
    assert kind == "force" and abs(value - (-1.0)) <= 1e-12
    matrix = solve_forces(sol, method="analytic")
    for key, w in matrix.forces.items():
        assert np.hypot(*w[:2]) <= 1e-12, key
    assert any("no normal force" in n for n in fs.notes)
    from graphkin.forces.report import forces_json, forces_text

    assert all(j["force"] == [0.0, 0.0] for j in forces_json(fs)["joints"].values())
    assert "∠" not in "".join(line for line in forces_text(fs).splitlines() if "F" in line
                              and "=" in line and "drive" not in line)
