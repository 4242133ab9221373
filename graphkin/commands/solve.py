"""``graphkin solve FILE [--json] [--steps] [--units UNITS]``: solve a mechanism at its posture."""

from __future__ import annotations

import argparse
import json
import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from graphkin.construction import Construction
    from graphkin.kinematics.solution import Solution

__all__ = ["add_parser", "run"]


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = sub.add_parser("solve", help="solve a mechanism file by the graphic constructions",
                       description="Solve a mechanism at the file's posture: positions, and "
                                   "velocities and accelerations when the file gives rates.")
    p.add_argument("file", help="mechanism file (TOML, see the README)")
    p.add_argument("--json", action="store_true",
                   help="print the result as JSON (docs/formats/json.md)")
    p.add_argument("--steps", action="store_true",
                   help="also list every construction step with its vector equation")
    p.add_argument("--units", default=None, metavar="UNITS",
                   help="report in these units, e.g. \"ft, ft/s, ft/s^2\" or \"m, rev/min\" "
                        "(a length alone sets the velocity and acceleration units too; "
                        "default: the file's length unit, seconds and rad/s)")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    import graphkin
    from graphkin.gears.file import gear_kind
    from graphkin.output import OutputUnits, solution_to_dict, text_report

    gears = gear_kind(args.file)
    if gears is not None:   # a gear file or a gear-train file (docs/formats/gears.md)
        from graphkin.commands.gears import report
        from graphkin.errors import InputError

        if args.units is not None:
            raise InputError("a gear report is in the file's own units", key="--units",
                             file=args.file)
        return report(*gears, args.file, as_json=args.json, steps=args.steps)
    mech = graphkin.load(args.file)
    units = OutputUnits.of(mech.length_unit, args.units)
    sol = mech.solve()
    constructions = _all_constructions(sol) if args.steps else {}
    if args.json:
        data = solution_to_dict(sol, units)
        if args.steps:
            data["constructions"] = {k: c.to_dict() for k, c in constructions.items()}
        # a mechanism of hundreds of links has hundreds of thousands of instant centers:
        # written without indentation (json's fast encoder), the same JSON
        big = len(data.get("instant_centers") or ()) > 20000
        sys.stdout.write(json.dumps(data, ensure_ascii=False, indent=None if big else 1,
                                    allow_nan=False))
        sys.stdout.write("\n")
        return 0
    sys.stdout.write(text_report(sol, units))
    for name, c in constructions.items():
        sys.stdout.write(f"\n{name.capitalize()} construction\n{c.table()}\n")
    return 0


def _all_constructions(sol: Solution) -> dict[str, Construction]:
    """Posture and polygons, then the instant centers and each link's curvature."""
    from graphkin.kinematics.curvature import curvature_constructions
    from graphkin.kinematics.instant_centers import instant_centers

    out = dict(sol.constructions)
    out["instant centers"] = instant_centers(sol).construction
    if sol.has_rates:
        for lid, cx in curvature_constructions(sol).items():
            if len(cx) > 1:
                out[f"curvature of link {lid}"] = cx
    from graphkin.forces.report import forces_report  # docs/forces.md

    fs = forces_report(sol)
    if fs is not None and fs.construction is not None:
        out["forces"] = fs.construction
    return out
