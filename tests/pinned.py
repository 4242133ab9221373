"""Mechanisms found by Hypothesis and pinned as ``@example`` cases, in one registry.

The property tests use them as explicit examples; ``tests/test_round_off.py`` perturbs
every one of them by round-off and requires the same verdicts (issue 23: a verdict taken
on a value at round-off of its scale flips on another CPU).
"""

from __future__ import annotations

import copy
from typing import Any

from strategies import RandomMechanism

__all__ = ["LOADED_DRIVE", "SELF_LOCKING", "BALL_FAR", "BALL_FARTHER", "PINNED", "with_friction"]

# found by Hypothesis: a load on the drive slider itself, taken by the drive, leaves every
# joint force at round-off (1e-17 N); the tolerance is the load's scale then.  On another
# CPU the sense of that round-off decided a self-locking verdict (issue 23).
LOADED_DRIVE = RandomMechanism(
    kind="slider-crank, slider-driven",
    data={"title": "random slider-crank, slider-driven", "units": {"length": "mm"},
          "links": {"1": {"O2": [-1.5, 0.0]}, "2": {"A": [0.375, 0.0], "O2": [-0.375, 0.0]},
                    "3": {"A": [0.6797308402774871, -0.3169636963055246],
                          "C": [-0.6797308402774875, 0.3169636963055246],
                          "D": [-2.220446049250313e-16, 0.0]},
                    "4": {"C": [0.0, 0.0]}},
          "drive": {"link": 4, "position": 0.0, "velocity": -1.5},
          "assembly": {"A": [-0.75, 0.0], "C": [-2.1094616805549746, 0.6339273926110492],
                       "D": [-1.4297308402774873, 0.3169636963055246]},
          "sliders": [{"link": 4, "on": 1, "point": "C",
                       "line": [[-2.1094616805549746, 0.6339273926110492],
                                [-0.6094616805549746, 0.6339273926110492]]}]},
    truth={"2": (-1.125, 0.0, 0.0), "3": (-1.429730840277487, 0.3169636963055246, 0.0),
           "4": (-2.1094616805549746, 0.6339273926110492, 0.0)},
    omega={"2": 4.289013841019115, "3": 2.3662015831524985, "4": 0.0})

SELF_LOCKING = RandomMechanism(
    # found by Hypothesis: the coupler AC stands 26.0° from the guide's normal, inside the
    # friction angle of μ = 0.5 (26.57°): the block cannot be slid (self-locking)
    kind="slider-crank, crank-driven",
    data={"title": "random slider-crank, crank-driven", "units": {"length": "mm"},
          "links": {"1": {"O2": [0.0, 0.0]}, "2": {"A": [0.25, 0.0], "O2": [-0.25, 0.0]},
                    "3": {"A": [-0.27015115293406977, -0.4207354924039482],
                          "C": [0.27015115293407, 0.4207354924039483],
                          "D": [1.1102230246251565e-16, 5.551115123125783e-17]},
                    "4": {"C": [0.0, 0.0]}},
          "drive": {"link": 2, "angle": 0.0, "omega": "1.0 rad/s cw"},
          "assembly": {"A": [0.5, 0.0], "C": [1.0403023058681398, 0.8414709848078965],
                       "D": [0.7701511529340699, 0.42073549240394825]},
          "sliders": [{"link": 4, "on": 1, "point": "C",
                       "line": [[1.0403023058681398, 0.8414709848078965],
                                [2.0334643585831733, 0.724727089691873]]}]},
    truth={"2": (0.25, 0.0, 0.0), "3": (0.7701511529340698, 0.4207354924039482, 0.0),
           "4": (1.0403023058681398, 0.8414709848078965, -0.11701072127637085)},
    omega={"2": -1.0, "3": 1.1327867492986414, "4": 0.0})

# found by Hypothesis on another machine: ω₃/ω₂ = -0.16, Ball's point 0.34 sizes from I with
# the inflection diameter 110 sizes; the plain stencil at h = 1e-4 gave |dκ/dφ|·size = 2e-6
BALL_FAR = RandomMechanism(
    kind="fourbar",
    data={"title": "random fourbar", "units": {"length": "mm"},
          "links": {"1": {"O2": [0.0, 0.0], "O4": [0.19312040518988316, -0.7218543337926775]},
                    "2": {"A": [-0.20028590388673342, -0.14961803602598914],
                          "O2": [0.20028590388673342, 0.14961803602598914]},
                    "3": {"A": [-0.5, 0.0], "B": [1.0, 0.0], "E": [-0.5, 0.0]},
                    "4": {"B": [0.453153893518325, 0.21130913087034958],
                          "O4": [-0.453153893518325, -0.21130913087034964]}},
          "drive": {"link": 2, "angle": 0.0, "omega": "1.0 rad/s cw"},
          "assembly": {"A": [-0.40057180777346685, -0.2992360720519783],
                       "B": [1.0994281922265332, -0.2992360720519783],
                       "E": [-0.40057180777346685, -0.2992360720519783]}},
    truth={"2": (-0.20028590388673342, -0.14961803602598914, 0.0),
           "3": (0.0994281922265332, -0.2992360720519783, 0.0),
           "4": (0.6462742987082082, -0.5105452029223279, 0.0)},
    omega={"2": -1.0, "3": 0.16076134640539858, "4": 0.7080528674257266},
)


# and a coupler turning slower still (ω₃/ω₂ = 0.032, inflection diameter 1160 sizes)
BALL_FARTHER = RandomMechanism(
    kind="fourbar",
    data={"title": "random fourbar", "units": {"length": "mm"},
          "links": {"1": {"O2": [0.0, 0.0], "O4": [0.3883703158530488, -1.081225240597619]},
                    "2": {"A": [-0.10109557266292571, -0.04174417100572378],
                          "O2": [0.10109557266292571, 0.04174417100572378]},
                    "3": {"A": [-0.33790129979384087, 0.24379053039185933],
                          "B": [0.6758025995876816, -0.48758106078371855],
                          "E": [-0.33790129979384087, 0.24379053039185933]},
                    "4": {"B": [0.21157121910131105, 0.1331826537052968],
                          "O4": [-0.21157121910131116, -0.1331826537052968]}},
          "drive": {"link": 2, "angle": 0.0, "omega": "1.0 rad/s cw"},
          "assembly": {"A": [-0.20219114532585142, -0.08348834201144756],
                       "B": [0.811512754055671, -0.8148599331870254],
                       "E": [-0.20219114532585142, -0.08348834201144756]}},
    truth={"2": (-0.10109557266292571, -0.04174417100572378, 0.0),
           "3": (0.13571015446798942, -0.3272788724033069, 0.0),
           "4": (0.59994153495436, -0.9480425868923222, 0.0)},
    omega={"2": -1.0, "3": -0.03197509687242704, "4": 0.4012310031211568},
)


def with_friction(rm: RandomMechanism, mu: float, mag: float, ang: float) -> dict[str, Any]:
    """The file of ``test_friction_is_coulomb``: rough sliders and a load on the last link."""
    data = copy.deepcopy(rm.data)
    for s in data.get("sliders", []):
        s["friction"] = mu
    moving = [lid for lid in data["links"] if str(lid) != "1"]
    lid = moving[-1]
    point = next(iter(data["links"][lid]))
    data["loads"] = [{"link": int(lid), "point": point, "force": f"{mag} N at {ang} deg"}]
    return data


PINNED: dict[str, dict[str, Any]] = {
    "loaded drive slider, rough (forces)": with_friction(LOADED_DRIVE, 0.5, 1.0, 0.0),
    "self-locking slider-crank (forces)": with_friction(SELF_LOCKING, 0.5, 1.0, 0.0),
    "Ball's point far (curvature)": BALL_FAR.data,
    "Ball's point farther (curvature)": BALL_FARTHER.data,
}
"""Name -> mechanism-file dict of every pinned case (the property tests register theirs)."""
