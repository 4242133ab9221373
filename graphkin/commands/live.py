"""``graphkin live FILE -o page.html``: drag the crank or a frame pivot and the polygons redraw.

Write one self-contained HTML file (no network) where the mechanism's posture, velocity and
acceleration constructions are re-solved in the page on every pointer move: drag the crank's
moving pin, a frame pivot or the drive slider; a posture that cannot be assembled is shown as
such; undo, reset, and save the edited mechanism as a TOML file.  A cam file opens as its
cam turning with its follower, a gear pair file as its gears rolling on fixed centers (a
rack: sliding under its pinion), a gear-train file laid out as its gears on their axes and
arms, a synthesis file as the linkage ``graphkin synthesize -o`` writes (docs/how-to/live.md).
"""

from __future__ import annotations

import argparse
import sys

from graphkin.commands._args import about, command, write_text

__all__ = ["add_parser", "run"]

HELP = ("write a self-contained HTML page where dragging the crank or a frame pivot "
        "re-solves the posture and the velocity and acceleration polygons")
DESCRIPTION = about(__doc__)


def add_parser(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    """Register the sub-command."""
    p = command(sub, "live", help=HELP, description=DESCRIPTION)
    p.add_argument("-o", "--output", required=True, help="the HTML file to write")
    return p


def run(args: argparse.Namespace) -> int:
    """Run the sub-command."""
    import graphkin
    from graphkin.files import load_toml
    from graphkin.keys import design_file
    from graphkin.render.live import live_html

    data = load_toml(args.file)
    kind = design_file(data)
    if kind is not None and kind[1] == "vector":  # C = A + B, its construction: live_vector.py
        from graphkin.kinematics.vector_file import load
        from graphkin.render.live_vector import vector_live_html

        text = vector_live_html(load(args.file), data)
        print(f"wrote {write_text(args.output, text, '--output')} "
              f"({len(text.encode('utf-8')) / 1024:.0f} KiB)", file=sys.stderr)
        return 0
    if kind is not None and kind[1] == "cam":
        # a cam file: the mechanism it means (cam 2 on O2, follower 4), its turning page
        from graphkin.cams.as_mechanism import cam_mechanism
        from graphkin.cams.parse import load_cam

        data = cam_mechanism(load_cam(args.file).cam, args.file)
        mech = graphkin.from_dict(data, source=str(args.file))
    elif kind is not None and kind[1] == "gears":
        data = _gear_mechanism(args.file)
        mech = graphkin.from_dict(data, source=str(args.file))
    elif kind is not None and kind[1] == "synthesize":
        # a synthesis file: the mechanism 'graphkin synthesize FILE -o' writes (the first
        # candidate passing every check, else the first), parsed from that very text
        from graphkin.files import parse_toml
        from graphkin.synthesis.run import synthesize
        from graphkin.synthesis.spec import load_spec

        data = parse_toml(synthesize(load_spec(args.file)).mechanism_toml(), str(args.file))
        mech = graphkin.from_dict(data, source=str(args.file))
        print(f"{args.file}: the page of the synthesized linkage 'graphkin synthesize -o' "
              "writes (the first candidate passing every check, else the first)",
              file=sys.stderr)
    else:
        mech = graphkin.load(args.file)
    text = live_html(mech, data, str(args.file))
    out = write_text(args.output, text, "--output")
    print(f"wrote {out} ({len(text.encode('utf-8')) / 1024:.0f} KiB)", file=sys.stderr)
    return 0


def _gear_mechanism(path: str) -> dict:
    """A gear file as its mechanism: a pair on fixed centers, a pinion on a rack, a train laid out.

    What the layout chose (a nominal module, operating pitch circles where the
    center distances cannot close) is said on stderr, one line each.
    """
    from graphkin.gears.as_mechanism import pair_mechanism, train_mechanism
    from graphkin.gears.file import gear_kind, load
    from graphkin.gears.train_file import load_train

    found = gear_kind(path)
    if found is not None and found[0] == "pair":
        return pair_mechanism(load(path), path)
    train = load_train(path)
    lay = train_mechanism(train, path)
    size = []
    if train.by_teeth and train.module is None:
        size = ["[teeth]: the gears drawn with a nominal module of 1 mm (R = N/2 mm; give "
                "module or diametral_pitch for their size): only the ratios of the teeth "
                "count (Eq. 7.24)"]
    elif not train.by_teeth and (found is None or "units" not in found[1]):
        size = ["[radii]: taken in mm (the file gives no units)"]
    for note in (*size, *lay.notes):
        print(f"{path}: {note}", file=sys.stderr)
    return lay.data
