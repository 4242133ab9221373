"""No two elements of a drawing share a gid (an SVG id must be unique, and a test or a
reader that looks an element up by gid must find the one it means).

Defect noticed at the session-9 stop: Example 11.7's forces sheet (a compound planet,
4-5, with two pitch circles and two points of contact on one link, Fig. 11.17) had two
``roller-4`` groups, two ``fbd-4-circles-label-P`` labels, and every force arrow carried
its group's gid (``fbd-2-F₁₂`` inside ``fbd-2-F₁₂``).
"""

from __future__ import annotations

import collections
import xml.etree.ElementTree as ET
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st
from strategies import examples, fourbars, mechanisms, slider_cranks

import graphkin
from graphkin.render import draw
from graphkin.render.style import rc_context
from graphkin.render.svg import to_bytes

ROOT = Path(__file__).resolve().parents[2]


def shared_ids(svg: bytes) -> list[str]:
    """The ids that more than one element of ``svg`` carries."""
    ids = collections.Counter(e.get("id") for e in ET.fromstring(svg).iter() if e.get("id"))
    return sorted(str(k) for k, n in ids.items() if n > 1)


def _svg(sol: graphkin.Solution, diagram: str) -> bytes:
    with rc_context():
        return to_bytes(draw(sol, diagram).figure)


def test_a_compound_planets_forces_sheet_has_unique_ids() -> None:
    sol = graphkin.load(ROOT / "gallery/gears/ex11_7.toml").solve()
    svg = _svg(sol, "forces")
    assert shared_ids(svg) == []
    ids = {e.get("id") for e in ET.fromstring(svg).iter()}
    # both pitch circles of the planet drawn, both points of contact lettered
    assert {"roller-4", "roller-4-2", "fbd-4-circles-label-P",
            "fbd-4-circles-label-P-2"} <= ids


def test_the_check_sees_a_shared_id() -> None:
    assert shared_ids(b'<svg xmlns="http://www.w3.org/2000/svg"><g id="a"/><g><g id="a"/>'
                      b'</g><g id="b"/></svg>') == ["a"]


@given(rm=st.one_of(fourbars(), slider_cranks(), mechanisms()))
@examples(3)
def test_a_random_mechanisms_whole_sheet_has_unique_ids(rm) -> None:  # type: ignore[no-untyped-def]
    assert shared_ids(_svg(rm.mechanism().solve(), "all")) == []


def test_every_gallery_drawing_has_unique_ids() -> None:
    # the gallery's drawings are the code's own (`graphkin gallery --check` keeps them so):
    # forces sheets of friction (F₁₄-n inside F₁₄-n) and the four-posture synthesis
    # (the selection's steps numbered from 1 again: step-14-P12 twice) had shared ids
    shared = {p.name: shared_ids(p.read_bytes())
              for p in sorted((ROOT / "gallery").rglob("*.svg"))}
    assert len(shared) > 50
    assert {k: v for k, v in shared.items() if v} == {}
