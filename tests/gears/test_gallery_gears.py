"""The gallery's Chapter 7 folder: every gear and train file drawn, the book's numbers compared.

The book values are the ones printed in Examples 7.1-7.11 (page of Sec. 7.4-7.16);
the rows are read by the gallery's own comparison (:func:`graphkin.render.gallery._rows`).
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from graphkin.errors import InputError
from graphkin.gears.file import loads
from graphkin.render.gallery import Entry, _rows, discover

GALLERY = Path(__file__).resolve().parents[2] / "gallery"
GEARS = GALLERY / "gears"


def _entry(name: str) -> Entry:
    for e in discover(GALLERY):
        if e.folder == "gears" and e.path.stem == name:
            return e
    raise AssertionError(f"no gallery/gears/{name}.toml")


def test_every_example_of_chapter_7_has_a_file():
    names = {p.stem for p in GEARS.glob("*.toml")}
    assert {f"ex7_{i}" for i in range(1, 12)} <= names
    assert {"fig7_18", "fig7_25", "fig7_10"} <= names   # fig7_10: the pinion and a rack
    figures = " ".join(str(e.meta.get("figure", "")) for e in discover(GALLERY)
                       if e.folder == "gears")
    for fig in ("7.8-7.9", "7.17", "7.18", "7.25", "7.40", "7.41"):
        assert fig in figures


def test_a_pair_is_drawn_and_every_book_value_agrees_or_says_why():
    from graphkin.render.gallery_gears import render_entry

    e = _entry("ex7_3")
    drawings, info = render_entry(e)
    assert list(drawings) == ["gears-ex7_3-gears.svg"]
    ids = {el.get("id") for el in ET.fromstring(drawings["gears-ex7_3-gears.svg"]).iter()}
    assert {"action-step-14-C", "action-step-15-D", "action-path-of-contact"} <= ids
    rows = _rows(e, info["solution"])
    assert len(rows) == 16
    assert all(r["verdict"] == "agrees" for r in rows), rows
    # Example 7.3 by hand: e = 1 - 6 sin²20° (Eq. 7.21) = 0.298133 in
    sol = info["solution"]
    assert sol["gears"]["pinion"]["offset_for_no_undercut"] == pytest.approx(
        1 - 6 * math.sin(math.radians(20)) ** 2, rel=1e-12)


def test_the_books_misprint_is_flagged_with_its_evidence():
    from graphkin.render.gallery_gears import render_entry

    e = _entry("fig7_25")
    _, info = render_entry(e)
    rows = {r["quantity"]: r for r in _rows(e, info["solution"])}
    # Eq. (7.9) by hand: CP = √(21² − (20 cos 20°)²) − 20 sin 20°, PD likewise, p_b = π cos 20°
    c, s = math.cos(math.radians(20)), math.sin(math.radians(20))
    cp = math.sqrt(21 ** 2 - (20 * c) ** 2) - 20 * s
    pd = math.sqrt(7 ** 2 - (6 * c) ** 2) - 6 * s
    assert info["solution"]["mesh"]["contact_ratio"] == pytest.approx(
        (cp + pd) / (math.pi * c), rel=1e-9)
    assert rows["m_c"]["verdict"] == "**differs**" and "1.405" in rows["m_c"]["why"]
    # from A (CP replaced by R2 sin φ): the book's 1.41
    assert rows["m_c from A (the involute part)"]["verdict"] == "agrees"
    assert info["solution"]["mesh"]["involute_contact_ratio"] == pytest.approx(
        (6 * s + pd) / (math.pi * c), rel=1e-9)


def test_a_train_is_drawn_as_the_books_table():
    from graphkin.render.gallery_gears import render_entry

    e = _entry("ex7_10")
    drawings, info = render_entry(e)
    svg = drawings["gears-ex7_10-train.svg"]
    root = ET.fromstring(svg)
    ids = {el.get("id") for el in root.iter()}
    assert {"members-table", "tabular-table", "row-step-2-3"} <= ids
    rows = _rows(e, info["solution"])
    assert [r["verdict"] for r in rows] == ["agrees"] * 3
    # Ferguson's paradox by hand: Δθ4 = 1 − 100/101, Δθ5 = 1 − 100/99 (rev)
    m = info["solution"]["members"]
    assert m["4"]["omega"] == pytest.approx(1 / 101, rel=1e-12)
    assert m["5"]["omega"] == pytest.approx(-1 / 99, rel=1e-12)


def test_a_gear_file_takes_the_gallery_table_but_refuses_unknown_keys():
    text = (GEARS / "ex7_1.toml").read_text(encoding="utf-8")
    assert loads(text, "ex7_1.toml").driver.teeth == 20
    with pytest.raises(InputError) as info:
        loads(text.replace("[gallery]\n", "[gallery]\nfigures = 1\n"), "x.toml")
    assert info.value.key == "gallery.figures"
    with pytest.raises(InputError) as info:
        loads("center_distanse = 3\n" + text, "x.toml")
    assert info.value.key == "center_distanse"


def test_example_11_7_gear_forces_beside_the_book():
    """Sec. 11.11 in the gallery: every printed force agrees to the book's rounding but
    the output torque, where the book carries its rounded 200 lb (T13 = 218.75 in·lb by
    moments and by power, test_gear_forces.py)."""
    from graphkin.render.gallery_gears import render_entry

    e = _entry("ex11_7")
    drawings, info = render_entry(e)
    assert list(drawings) == ["gears-ex11_7-forces.svg"]
    rows = {r["quantity"]: r for r in _rows(e, info["solution"])}
    assert rows.pop("T13 (output)")["verdict"] == "**differs**"
    assert all(r["verdict"] == "agrees" for r in rows.values()), rows
    assert info["solution"]["forces"]["drives"]["3"]["torque"] == pytest.approx(-218.75)
