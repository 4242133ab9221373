"""The Python API says what happened (issue 25, item 4).

At a dead point the file's rates cannot be carried through the posture:
``sol.velocity('C')`` says so (a toggle or dead-center posture, Sec. 3.5),
not "the file gives no rates", which it does.
"""

from __future__ import annotations

import contextlib
import io
import sys
import tomllib
from pathlib import Path

import pytest

import graphkin
from graphkin.cli import main
from graphkin.examples import names, text

sys.path.insert(0, str(Path(__file__).parent))
from test_mutations import dumps  # noqa: E402


def _slider_crank(position: float, rates: bool = True) -> graphkin.Mechanism:
    # centred slider-crank: crank 50, rod 140 on the line through A; at a travel of 90 the
    # crank lies back along the line (θ2 = 180°) and the rod along it: a dead center
    t = text("slider_crank").replace("S = [0, -20]", "S = [0, 0]").replace(
        "T = [100, -20]", "T = [100, 0]").replace("position = 164", f"position = {position}")
    t = t.replace("B = [35, 35]", "B = [-50, 0.1]")
    if not rates:
        t = t.replace('velocity = "-10 m/s"', "").replace("acceleration = 0", "")
    return graphkin.loads(t)


@pytest.mark.parametrize("ask", [lambda s: s.velocity("C"), lambda s: s.omega(3),
                                 lambda s: s.acceleration("B"), lambda s: s.alpha(2)])
def test_rates_at_a_dead_point_say_it_is_a_dead_point(ask) -> None:
    sol = _slider_crank(90).solve()
    with pytest.raises(ValueError, match="dead-center") as info:
        ask(sol)
    assert "gives no rates" not in str(info.value)


def test_no_rates_in_the_file_says_so() -> None:
    sol = _slider_crank(90, rates=False).solve()
    with pytest.raises(ValueError, match="the file gives no rates"):
        sol.velocity("C")


def test_an_absolute_angle_drive_on_a_floating_link_is_solved() -> None:
    """Example 3.1 driven by its coupler: θ3 = 20.9187° and ω3 = 25.3828 rad/s ccw (the
    book's answers at θ2 = 120°, ω2 = 900 rev/min) give back θ2 = 120° and ω2 = 94.25 rad/s;
    no construction starts from a floating link's angle, so the analytic solver does it."""
    t = text("fourbar").replace("link = 2", "link = 3").replace("angle = 120", "angle = 20.9187")
    t = t.replace('omega = "900 rev/min"', 'omega = "25.3828 rad/s"')
    sol = graphkin.loads(t).solve()
    assert float(sol.angle(2)) == pytest.approx(120.0, abs=1e-3)
    assert float(sol.omega(2)) == pytest.approx(900 * 2 * 3.141592653589793 / 60, rel=1e-4)


def test_a_floating_angle_drive_with_loads_is_refused_with_the_reason() -> None:
    t = text("fourbar").replace("link = 2", "link = 3")
    t += '\n[[loads]]\nlink = 4\npoint = "C"\nforce = "10 lbf at 0 deg"\n'
    with pytest.raises(ValueError, match="not pinned to the frame"):
        graphkin.loads(t)


def test_a_floating_angle_drive_on_every_link_of_every_example_ends_cleanly(tmp_path: Path
                                                                            ) -> None:
    """Each shipped example driven instead by the absolute angle of each other moving link:
    solved, or refused in one line (a rolling planet's own angle: not supported yet)."""
    tmp = tmp_path / "m.toml"
    for name in names():
        d = tomllib.loads(text(name))
        drv = d.get("drive")
        if not isinstance(drv, dict) or "angle" not in drv:
            continue
        for lid in [k for k in d["links"] if k not in ("1", str(drv.get("link")))]:
            tmp.write_text(dumps({**d, "drive": {**drv, "link": int(lid)}}), encoding="utf-8")
            out, err = io.StringIO(), io.StringIO()
            with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
                rc = main(["solve", str(tmp)])
            e = err.getvalue()
            assert rc in (0, 2) and "cannot handle" not in e, (name, lid, e)
            if rc == 2:
                assert len([ln for ln in e.splitlines() if ln.strip()]) == 1, e
