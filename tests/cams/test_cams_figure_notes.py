"""A cam's drawings keep their notes off the curves and off each other (session 8, cosmetic).

Read back from the saved SVG by gid (tests/svg_boxes.py): each note's box from
matplotlib's font metrics, every stroked path and marker as polylines.

* ``cam -d design``: the |φ|max and ρmin notes stood at a fixed offset from their
  markers: across the pressure-angle curve where it climbs past its extreme
  (Ex. 6.4), across the axis and its tick labels where ρmin is at the bottom of
  the plot (Ex. 6.3).
* ``cam`` (the layout by inversion): a station's number stood at a fixed place on
  its ray, on the profile where it runs on the prime circle (Ex. 6.3's 9, 10, 11)
  and on a roller (Ex. 6.7's 2 and 8).
* ``cam -d displacement``: each segment's name stood at the foot of the y'' plot in
  the middle of its span, on y'' (Ex. 6.8's "parabolic" on y'' = -37 and on the jump
  at 255°, Ex. 6.2's "CD" on the trough).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from cam_strategies import cams
from hypothesis import HealthCheck, given, settings
from svg_boxes import page, strokes, texts

from graphkin.cams.parse import load_cam
from graphkin.render.cams import design_figure, displacement_figure, layout_figure
from graphkin.render.style import rc_context
from graphkin.render.svg import to_bytes

ROOT = Path(__file__).resolve().parents[2]
CAMS = [*sorted(ROOT.glob("gallery/cams/*.toml")), ROOT / "examples/cams/fig6_25_undercut.toml"]
TOUCH = 0.4
"""Points taken off each side of a note's box: glyph boxes that only touch a line are clear."""
SETTINGS = settings(max_examples=10, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])


def _svg(fig) -> ET.Element:
    with rc_context():
        return ET.fromstring(to_bytes(fig))


def _own(note: str, line: str) -> bool:
    """A line the note names: its leader, or a station's center line (or arm) for its number."""
    if line in (note, f"{note}-leader"):
        return True
    if note.startswith("station-"):
        i = note.split("-")[1]
        return line in (f"station-{i}-axis", f"station-{i}-arm")
    return False


def clashes(root: ET.Element, is_note) -> list[tuple[str, str]]:
    """Every note (``is_note(gid)``) off the page, on a line not its own, or on another text."""
    sheet = page(root)
    lines = strokes(root)
    boxes = texts(root)
    out = []
    for n in boxes:
        if not is_note(n.gid):
            continue
        b = n.box.buffer(-TOUCH, join_style="mitre")
        if not sheet.contains(n.box):
            out.append((n.gid, "off the page"))
        for gid, ln in lines:
            if not _own(n.gid, gid) and ln.intersects(b):
                out.append((n.gid, gid))
        for m in boxes:
            if m is not n and m.box.intersects(b):
                out.append((n.gid, f"text {m.gid}: {m.text}"))
    return sorted(set(out))


def _design_notes(gid: str) -> bool:
    return gid in ("pressure-max-label", "radius-min-label")


def _station_numbers(gid: str) -> bool:
    return gid.startswith("station-") and gid.endswith("-label")


@pytest.mark.parametrize("path", CAMS, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_the_design_notes_of_every_shipped_cam_are_clear(path):
    root = _svg(design_figure(load_cam(path).cam))
    assert {n.gid for n in texts(root) if _design_notes(n.gid)}, "no note drawn"
    assert not clashes(root, _design_notes)


def _segment_names(gid: str) -> bool:
    return gid.startswith("segment-label-")


@pytest.mark.parametrize("path", CAMS, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_the_segment_names_of_every_shipped_cam_are_clear(path):
    cam = load_cam(path).cam
    root = _svg(displacement_figure(cam))
    names = [n for n in texts(root) if _segment_names(n.gid)]
    assert len(names) == len(cam.program.segments)
    assert not clashes(root, _segment_names)


@pytest.mark.parametrize("path", CAMS, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_the_station_numbers_of_every_shipped_cam_are_clear(path):
    root = _svg(layout_figure(load_cam(path).cam))
    numbers = sorted(n.text for n in texts(root) if _station_numbers(n.gid))
    assert numbers == sorted(str(i) for i in range(12))
    assert not clashes(root, _station_numbers)


def test_a_note_stays_beside_its_marker():
    # Ex. 6.4's |φ|max = 28.1558° at Θ ≈ 219°: its note within 45 pt of the marker (the
    # farthest ring tried is 42 pt), so that it is read as that extreme's
    root = _svg(design_figure(load_cam(ROOT / "gallery/cams/ex6_4_pressure_angle.toml").cam))
    notes = {n.gid: n for n in texts(root)}
    for gid in ("pressure-max", "radius-min"):
        mark = next(ln for g, ln in strokes(root) if g == gid)
        assert notes[f"{gid}-label"].box.distance(mark.centroid) <= 45.0, gid
    assert "28.1558" in notes["pressure-max-label"].text


def test_the_check_sees_a_note_on_a_curve():
    # the measurement itself can fail: a note moved onto the curve's extreme is reported
    fig = design_figure(load_cam(ROOT / "gallery/cams/ex6_4_pressure_angle.toml").cam)
    note = next(t for t in fig.axes[0].texts if t.get_gid() == "pressure-max-label")
    note.set_position((0.0, 0.0))     # the text centred on its marker
    note.set_ha("center")
    note.set_va("center")
    assert ("pressure-max-label", "pressure-angle") in clashes(_svg(fig), _design_notes)


@given(cam=cams())
@SETTINGS
def test_the_design_notes_of_a_random_cam_are_clear(cam):
    root = _svg(design_figure(cam))
    assert not clashes(root, _design_notes)


@given(cam=cams())
@SETTINGS
def test_the_station_numbers_of_a_random_cam_are_clear(cam):
    root = _svg(layout_figure(cam))
    assert not clashes(root, _station_numbers)


@given(cam=cams())
@SETTINGS
def test_the_segment_names_of_a_random_cam_are_clear(cam):
    root = _svg(displacement_figure(cam))
    assert not clashes(root, _segment_names)


def test_a_circular_cam_has_a_zero_pressure_angle_drawn_as_zero():
    # Two dwells: the cam is its prime circle, the knife edge on it; φ = 0 all round (Eq. 6.28
    # with y' = 0).  The analytic φ comes out ~1e-15 rad: drawn as it came, the plot was that
    # noise scaled to fill its axes ("1e-15" over the axis), the note "|φ|max = 8.2e-15°".
    import math

    from graphkin.cams import Cam, Follower, FollowerKind, Motion, Program, Segment, Sense

    cam = Cam(Program((Segment(Motion.DWELL, 0.0, math.pi), Segment(Motion.DWELL, 0.0, math.pi))),
              0.875, Follower(FollowerKind.KNIFE_EDGE), Sense.CCW)
    fig = design_figure(cam)
    curve = next(ln for ln in fig.axes[0].lines if ln.get_gid() == "pressure-angle")
    assert not curve.get_ydata().any()
    lo, hi = fig.axes[0].get_ylim()
    assert hi - lo > 1e-3
    root = _svg(fig)
    note = next(n for n in texts(root) if n.gid == "pressure-max-label")
    assert note.text == "|φ|max = 0°"
    assert not clashes(root, _design_notes)
