"""The points of contact of rolling contact are lettered in the drawn polygons (Secs. 3.7, 4.7).

The book letters the image of a point of contact like any point (Fig. 3.14b:
``P2``, "we also label this point ``P3``"): one velocity image for both links
(no slip, Eq. 3.13) and, in the acceleration polygon, each link's own image,
apart by the rolling component ``A^r`` (Eq. 4.19).  A link in two contacts
(the compound planet 4-5 of Example 11.7 meshes with 2 and with 6) names each
of its points of contact by the other link.
"""

from __future__ import annotations

from pathlib import Path

import graphkin
from graphkin.render import draw

ROOT = Path(__file__).resolve().parents[2]


def _texts(path: str, diagram: str) -> dict[str, str]:
    d = draw(graphkin.load(ROOT / path).solve(), diagram)
    return {k: t.get_text() for k, t in d.texts.items()
            if k.startswith(("v(rolling", "a(rolling")) and k.endswith((")", "):r"))}


def test_example_11_7_letters_each_point_of_contact():
    # one velocity image for the coincident points of 4 and 2, lettered with both as in
    # Fig. 3.14b ("P2 ... we also label this point P3"), as the live page letters it
    assert _texts("gallery/gears/ex11_7.toml", "velocity") == {"v(rolling[0]:C@4)": "c₄ = c₂"}
    assert _texts("gallery/gears/ex11_7.toml", "acceleration") == {
        # the second contact is P: C is taken by the first (Sec. 3.7 names it P)
        "a(rolling[0]:C@4)": "c′₄ (4/2)", "a(rolling[1]:P@4)": "p′₄ (4/1)",
        # the sun's own point of contact, A_C2 = A_C4 − A^r_C4/2 (Eq. 4.19)
        "a(rolling[0]:C@2):r": "c′₂"}


def test_the_roller_and_the_follower_face_of_example_4_8():
    # Example 4.8 (Fig. 4.20): the roller 4 on the face of the follower 3, one contact
    assert set(_texts("gallery/mechanisms/fig4_20_roller_follower.toml",
                      "acceleration").values()) == {"c′₃", "c′₄"}
    assert set(_texts("gallery/mechanisms/fig4_20_roller_follower.toml",
                      "velocity").values()) == {"c₄ = c₃"}
