"""Mechanisms that cannot be solved one group at a time fall back to the analytic solver."""

from __future__ import annotations

import itertools
import json
from pathlib import Path

import numpy as np

import graphkin
from graphkin.cli import main

FILE = Path(__file__).resolve().parents[2] / "examples" / "stephenson3_fallback.toml"


def test_stephenson_iii_driven_at_the_far_crank_is_solved_and_says_so(capsys):
    mech = graphkin.load(FILE)
    sol = mech.solve()
    assert sol.method == "analytic"
    assert any("cannot be found one group at a time" in n for n in sol.notes)
    # the answer satisfies every pin: the distance between any two points of one link is
    # the distance written in the file (independent of how it was solved)
    for link in mech.links.values():
        for (p, lp), (q, lq) in itertools.combinations(link.points.items(), 2):
            d_file = np.hypot(lq[0] - lp[0], lq[1] - lp[1])
            d = np.hypot(*(sol.position(q) - sol.position(p)))
            assert abs(d - d_file) <= 1e-9 * mech.scale
    assert abs(float(sol.angle_rad("6")) - np.radians(5.0)) <= 1e-12
    assert main(["solve", str(FILE), "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["method"] == "analytic" and out["notes"]
