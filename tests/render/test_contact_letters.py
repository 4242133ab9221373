"""The letters of a contact's images: one rule for ``draw`` and the live page.

Defects noticed at the session-8 stop: a contact named ``C1`` (the file has
points C and P) was lettered ``c1₄`` on the page and ``c₁₄`` / ``c′₁₄`` in
``draw``, the digit of the name running into the link's subscript; and ``draw``
lettered the velocity image of a contact with one link only (``c₄ (4/2)``)
where the book (Fig. 3.14b: "we also label this point P3") and the page letter
both coincident points, ``c₄ = c₂``.
"""

from __future__ import annotations

from pathlib import Path

import graphkin
from graphkin.render import draw
from graphkin.render.live import _pitch_images

ROOT = Path(__file__).resolve().parents[2]

# Example 3.9's wheel (test_rolling_contact_name.py), its pin named C and its center P,
# so the point of rolling contact is C1 (docs/formats/mechanism.md, "Rolling contact")
WHEEL = """
units = "mm"
[links.1]
O2 = [0, 0]
G1 = [0, 0]
G2 = [1, 0]
[links.2]
O2 = [0, 0]
A = [150, 0]
[links.3]
A = [0, 0]
C = [200, 0]
[links.4]
P = [0, 0]
C = [0, 50]
[[rolling]]
link = 4
on = 1
circle = { center = "P", radius = 100 }
line = ["G1", "G2"]
side = "left"
[drive]
link = 2
angle = 90
omega = "10 rad/s"
alpha = 0
[assembly]
C = [200, 150]
"""


def _contact_texts(sol: graphkin.Solution, diagram: str) -> dict[str, str]:
    d = draw(sol, diagram)
    return {k: t.get_text() for k, t in d.texts.items()
            if k.startswith(("v(rolling", "a(rolling")) and k.endswith((")", "):r"))}


def test_a_numbered_contact_keeps_its_digit_apart_from_the_link() -> None:
    mech = graphkin.loads(WHEEL)
    assert [r.contact_name for r in mech.rolling] == ["C1"]
    texts = _contact_texts(mech.solve(), "acceleration")
    # the wheel's point of contact C1: subscript 1 of the name, link 4 apart
    assert texts == {"a(rolling[0]:C1@4)": "c′₁ (4)"}
    page = {e["text"] for e in _pitch_images(mech, {"o_v", "a(rolling[0]:C1@4)"})}
    # on the frame the velocity image is the pole: V_C1 = 0 for both links
    assert page == {"c₁ (4) = c₁ (1)", "c′₁ (4)"}


def test_draw_and_the_page_letter_every_contact_image_alike() -> None:
    for path in ("gallery/gears/ex11_7.toml", "gallery/mechanisms/fig4_20_roller_follower.toml"):
        sol = graphkin.load(ROOT / path).solve()
        drawn = {**_contact_texts(sol, "velocity"), **_contact_texts(sol, "acceleration")}
        made = {o for d in ("velocity", "acceleration") for s in sol.constructions[d].steps
                for o in s.outputs} | {"o_v"}
        page = {e["label"]: e["text"] for e in _pitch_images(sol.mechanism, made)}
        # every image draw letters, the page letters the same way (the page also letters the
        # pole of a contact on the frame, which draw leaves to O_V)
        assert drawn and all(page[k] == t for k, t in drawn.items()), (drawn, page)
