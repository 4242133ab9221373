"""The slide frames of ``animate --frames`` / ``--gif`` (issue 24): ``draw``'s letter sizes,
no letter over another, read back from the SVG of random mechanisms' frames."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

from hypothesis import Phase, given, settings
from hypothesis import strategies as st
from strategies import examples, six_bars, slider_cranks
from strategies_quick import quick_returns

from graphkin.render.cycle_frames import write_cycle_frames
from graphkin.render.labels import _PAD, text_size
from graphkin.render.style import STYLES

SVG = "{http://www.w3.org/2000/svg}"
MIN_PT = 6.0


def text_boxes(svg: bytes) -> list[tuple[str, float, list[float]]]:
    """Every text of a matplotlib SVG (real text, 1 unit = 1 pt) with its box on the page.

    The box from the glyphs' advance widths (matplotlib's font metrics) and DejaVu Sans'
    ascent and descent (0.93 and 0.24 of the size) about the baseline at ``y``.
    """
    out = []
    for el in ET.fromstring(svg).iter(f"{SVG}text"):
        style = el.get("style", "")
        size = float(re.search(r"font-size:\s*([0-9.]+)px", style).group(1))
        text = "".join(el.itertext())
        w = (text_size(text, size)[0] - 2 * _PAD) * 72
        x, y = float(el.get("x")), float(el.get("y"))
        if "text-anchor: middle" in style:
            x -= w / 2
        elif "text-anchor: end" in style:
            x -= w
        out.append((text, size, [x, y - 0.93 * size, x + w, y + 0.24 * size]))
    return out


def overlaps(boxes, slack: float = 0.5) -> list[tuple[str, str]]:
    """Pairs of texts whose boxes overlap by more than ``slack`` pt both ways."""
    bad = []
    for k, (t, _s, a) in enumerate(boxes):
        for u, _z, b in boxes[k + 1:]:
            if min(a[2], b[2]) - max(a[0], b[0]) > slack and \
                    min(a[3], b[3]) - max(a[1], b[1]) > slack:
                bad.append((t, u))
    return bad


@given(rm=st.one_of(slider_cranks(), quick_returns(), six_bars()))
@settings(examples(3), phases=[Phase.explicit, Phase.reuse, Phase.generate])
def test_frames_letter_at_draws_size_with_no_letter_over_another(rm, tmp_path_factory):
    mech = rm.mechanism()
    paths = write_cycle_frames(mech, tmp_path_factory.mktemp("frames"), count=3)
    assert len(paths) == 3
    names = set(mech.point_names) - set(mech.helper_points)
    for p in paths:
        boxes = text_boxes(p.read_bytes())
        sizes = {t: s for t, s, _b in boxes}
        assert min(sizes.values()) >= MIN_PT
        # a point's letter at draw's size (render/style.py), not a size of its own
        lettered = names & set(sizes)
        assembled = not any("cannot be assembled" in t for t in sizes)
        assert lettered or not assembled, sorted(sizes)
        assert all(sizes[n] == STYLES["label"]["size"] for n in lettered)
        assert not overlaps(boxes), (p.name, overlaps(boxes)[:5])


def test_the_readback_sees_an_overlap():
    # the check can fail: two letters at one place overlap, two apart do not
    a = b'<svg xmlns="http://www.w3.org/2000/svg">' \
        b'<text style="font-size: 9px; text-anchor: start" x="10" y="10">B</text>' \
        b'<text style="font-size: 9px; text-anchor: start" x="13" y="11">C</text>' \
        b'<text style="font-size: 9px; text-anchor: start" x="40" y="11">D</text></svg>'
    assert overlaps(text_boxes(a)) == [("B", "C")]
