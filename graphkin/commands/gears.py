"""``graphkin gears FILE [--json] [--steps]``: a pair of spur gears in mesh, Chapter 7.

Lay out a pair of spur gears in mesh as the book does (Figs. 7.8-7.9) and
report every quantity with its unit: the pitch, base, addendum and dedendum
circles, the tooth thickness (Eqs. 7.16-7.17), the operating pressure angle
at the center distance (Sec. 7.9), the path of contact with its approach and
recess, the contact ratio by construction and by Eq. (7.9), and
interference and undercutting (Sec. 7.7). The file format is
docs/formats/gears.md; draw the pair with graphkin draw FILE -d gears. A
gear-train file (its [[mesh]] tables) gives every member's angular velocity
by the formula method (Eq. 7.25) and the book's table (Sec. 7.16); so does a
mechanism file whose [[rolling]] contacts are gears on a frame or an arm (a
planetary train), checked against its rolling-contact kinematics.
"""

from __future__ import annotations

import argparse
import json
import sys

from graphkin.commands._args import about, command

__all__ = ["add_parser", "run", "report"]

HELP = "a pair of spur gears in mesh: contact ratio, interference, tooth thickness (Ch. 7)"


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "gears", help=HELP, description=about(__doc__),
                file="gear file (TOML, docs/formats/gears.md)")
    p.add_argument("--json", action="store_true", help="print the report as JSON")
    p.add_argument("--steps", action="store_true",
                   help="also list every step of the layout's construction")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    from graphkin.gears.file import gear_kind

    found = gear_kind(args.file)
    if found is None:
        return _mechanism(args)
    return report(found[0], found[1], args.file, as_json=args.json, steps=args.steps)


def report(kind: str, data: dict, source: str, *, as_json: bool = False,
           steps: bool = False) -> int:
    """Print the report of a parsed gear file (``kind`` "pair") or gear-train file ("train")."""
    from graphkin.gears import layout
    from graphkin.gears.file import from_dict
    from graphkin.gears.train_file import train_from_dict
    from graphkin.output.gears import gears_json, gears_text

    if kind == "train":
        return _train(train_from_dict(data, source), source, as_json, steps)
    lay = layout(from_dict(data, source))
    if as_json:
        out = gears_json(lay)
        if steps:
            out["construction"] = lay.construction.to_dict()
        sys.stdout.write(json.dumps(out, ensure_ascii=False, indent=1, allow_nan=False))
        sys.stdout.write("\n")
        return 0
    sys.stdout.write(gears_text(lay))
    if steps:
        sys.stdout.write(f"\nLayout construction\n{lay.construction.table()}\n")
    return 0


def _mechanism(args: argparse.Namespace) -> int:
    """A mechanism file whose rolling contacts are gears: its train (Secs. 7.15-7.16)."""
    import graphkin
    from graphkin.errors import InputError
    from graphkin.files import load_toml
    from graphkin.output.trains import mechanism_train_json, mechanism_train_text

    not_gears = ("not a gear file: a pair in mesh has [gears.<name>] tables, a train [[mesh]] "
                 "tables, a mechanism [[rolling]] circles on circles (docs/formats/gears.md)")
    if "links" not in load_toml(args.file) or args.steps:
        raise InputError(not_gears, key="--steps" if args.steps else None, file=args.file)
    mech = graphkin.load(args.file)
    if not any(not r.on_line for r in mech.rolling):
        raise InputError(not_gears, key="rolling" if mech.rolling else None, file=args.file)
    if not mech.has_rates:
        raise InputError("the train's speeds are multiples of the drive's: give its omega "
                         "(e.g. omega = \"10 rad/s\")", key="drive.omega", file=args.file)
    sol = mech.solve()
    data: dict | str | None = mechanism_train_json(sol) if args.json else \
        mechanism_train_text(sol)
    if data is None:
        raise InputError("its rolling contacts are not a gear train graphkin reads: every "
                         "contact a circle on a circle, both centers on one link (the frame or "
                         "an arm), each drive on a gear or an arm", key="rolling",
                         file=args.file)
    if isinstance(data, str):
        sys.stdout.write(data)
    else:
        sys.stdout.write(json.dumps(data, ensure_ascii=False, indent=1, allow_nan=False) + "\n")
    return 0


def _train(train: object, source: str, as_json: bool, steps: bool) -> int:
    """A gear train (Secs. 7.12-7.16)."""
    from graphkin.errors import InputError
    from graphkin.gears.train import Train
    from graphkin.output.trains import train_json, train_text

    assert isinstance(train, Train)
    if steps:
        raise InputError("--steps lists the construction of a pair in mesh; a train file has "
                         "none", key="--steps", file=source)
    if as_json:
        sys.stdout.write(json.dumps(train_json(train), ensure_ascii=False, indent=1,
                                    allow_nan=False))
        sys.stdout.write("\n")
        return 0
    sys.stdout.write(train_text(train))
    return 0
