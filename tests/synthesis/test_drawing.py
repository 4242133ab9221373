"""The drawings of a synthesis, read back (issue 28, as tests/render/test_any_mechanism.py).

Random posture sets (two to five postures), a function generator, cognates
and a dwell linkage are drawn; each drawing must keep every coordinate
finite and every text on its page, set no type under 6 pt (read from the
SVG), have no label over another label or over a line of another step (font
metrics, :func:`graphkin.render.labels.collisions`), letter every pole, every
pivot and every posture it draws, and state its scale.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from hypothesis import Phase, assume, given, settings
from hypothesis import strategies as st
from strategies import examples

from graphkin.errors import InputError
from graphkin.render.labels import collisions
from graphkin.render.svg import to_bytes
from graphkin.render.synthesis import draw_synthesis, letter
from graphkin.synthesis import loads_spec, synthesize

SVG = "{http://www.w3.org/2000/svg}"
_NUM = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?|nan|inf", re.IGNORECASE)
_MUST = re.compile(r"(P\d\d|O_[A-Z]|O6|[A-Z]\d|M\d)$")
"""Names that must carry their letter when drawn: poles, pivots, posture points, Burmester
points."""


def _floats(text: str) -> list[float]:
    return [float(x) for x in _NUM.findall(text)]


def check_svg(svg: bytes) -> None:
    """Every coordinate finite and bounded, every text on the page, no type under 6 pt."""
    root = ET.fromstring(svg)
    w, h = _floats(root.get("viewBox", ""))[2:4]
    for el in root.iter():
        for attr in ("x", "y", "d", "transform", "points"):
            v = el.get(attr)
            if v is not None:
                nums = _floats(v)
                assert all(math.isfinite(n) and abs(n) < 1e5 for n in nums), (el.tag, v[:80])
        if el.tag == f"{SVG}text" and el.get("x") is not None:
            x, y = float(el.get("x", 0)), float(el.get("y", 0))
            assert -1 <= x <= w + 1 and -1 <= y <= h + 1, (x, y)
        for size in re.findall(r"font-size:\s*([0-9.]+)px", el.get("style", "")):
            assert float(size) >= 6.0 - 1e-6, size


def check_drawing(res) -> None:
    d = draw_synthesis(res)
    check_svg(to_bytes(d.figure, "svg"))
    assert not collisions(d), collisions(d)[:5]
    texts = " ".join(t.get_text() for t in d.texts.values())
    for p in d.sheet.panels:
        if p.scale is not None:
            assert p.scale.text in " ".join(
                t.get_text() for k, t in d.texts.items()) or any(
                p.scale.text == a.get_text() for g in d.groups.values()
                for a in g.get_children() if hasattr(a, "get_text")), p.name
    panels = tuple(f"{p.name}-" for p in d.sheet.panels)

    def bare(key: str) -> str:   # a step's key carries its panel's name (synthesis-P12)
        return key.split("-", 1)[1] if key.startswith(panels) else key

    lettered = {bare(k) for k in d.texts}
    # every finite pole is lettered: on the figure, or by an arrow at its edge with its
    # distance ("P34, 13.3 in from D1")
    for cx in (res.construction, res.selection):
        if cx is None or res.spec.postures is None:
            continue
        ev = cx.evaluate({"t": np.array(0.0)} if "t" in cx.labels else None, strict=False)
        for step in cx:
            if re.fullmatch(r"P\d\d", step.label) and step.label in ev:
                v = np.asarray(ev[step.label], dtype=float)
                if np.all(np.isfinite(v)) and abs(v[2]) > 1e-12 * np.max(np.abs(v)):
                    assert step.label in lettered, (step.label, "pole not lettered")
    # every Burmester point and pivot of the linkage beyond the panel is named by an arrow at
    # its edge (as a far pole or a far instant center is), not left off with nothing said
    x0, y0, x1, y1 = d.sheet.panels[0].inner
    far = []
    for k, bp in enumerate(res.burmester, 1):
        far += [(f"M{k}", bp.center), (f"m{k}", bp.circle)]
    if res.chosen is not None and res.spec.postures is not None:
        far += [("O_A", res.chosen.o_a), ("O_B", res.chosen.o_b)]
    said = [t.get_text() for t in d.texts.values()]
    for name, z in far:
        if np.isfinite(z) and not (x0 <= z.real <= x1 and y0 <= z.imag <= y1):
            named = {name}
            if res.chosen is not None:   # a Burmester point taken as a pivot of the linkage
                (a, b), (na, nb) = res.chosen.pivots, res.chosen.names
                named |= {f"O_{c}" for c in "AB" if getattr(res.chosen, f"o_{c.lower()}") == z}
                named |= {f"{n}{j + 1}" for n, q in ((na, a), (nb, b))
                          for j in range(len(q)) if abs(q[j] - z) <= 1e-9 * abs(z)}
            assert any(letter(n) in t for n in named for t in said), (name, z, said[-5:])
    for key, art in d.items():
        name = bare(key)
        if _MUST.match(name) and hasattr(art, "get_marker") and art.get_marker() not in (
                None, "None", ""):
            assert name in lettered, (key, "unlettered", texts[:200])


def _posture_spec(pts: np.ndarray, ang: np.ndarray, pivots: str) -> str:
    lines = ['title = "random postures"', 'units = "in"']
    for (x, y), a in zip(pts, ang):
        lines += ["[[postures]]", f"point = [{float(x)!r}, {float(y)!r}]",
                  f"angle = {float(a)!r}"]
    return "\n".join(lines) + "\n" + pivots


@st.composite
def posture_sets(draw: st.DrawFn, n: int) -> tuple[np.ndarray, np.ndarray]:
    # a body moving on: each posture a step of 0.6-1.6 in and a turn of 10-40° from the last
    step = draw(st.lists(st.floats(0.6, 1.6), min_size=n - 1, max_size=n - 1))
    heading = draw(st.lists(st.floats(-60, 60), min_size=n - 1, max_size=n - 1))
    turn = draw(st.lists(st.floats(10, 40), min_size=n - 1, max_size=n - 1))
    z = np.cumsum([0j] + [s * np.exp(1j * math.radians(h)) for s, h in zip(step, heading)])
    ang = np.cumsum([0.0, *turn])
    return np.stack([z.real, z.imag], axis=-1), ang


@given(data=st.data(), n=st.sampled_from([2, 3, 4, 5]))
@settings(examples(8), phases=[Phase.explicit, Phase.reuse, Phase.generate])
def test_random_posture_sets_draw_cleanly(data: st.DataObject, n: int) -> None:
    pts, ang = data.draw(posture_sets(n))
    c = pts.mean(axis=0)
    pivots = {2: f"[pivots]\ncircle_points = [[{c[0] - 0.5}, {c[1] - 1.0}], "
                 f"[{c[0] + 0.5}, {c[1] - 1.0}]]\ncenter_points = [[{c[0] - 1}, {c[1] - 3}], "
                 f"[{c[0] + 1}, {c[1] - 3}]]\n",
              3: f"[pivots]\ncircle_points = [[{c[0] - 0.5}, {c[1] - 1.0}], "
                 f"[{c[0] + 0.5}, {c[1] - 1.0}]]\n",
              4: f"[pivots]\ncenter_points = [[{c[0] - 2}, {c[1] - 3}], "
                 f"[{c[0] + 2}, {c[1] - 3}]]\n",
              5: ""}[n]
    try:
        res = synthesize(loads_spec(_posture_spec(pts, ang, pivots)))
    except InputError:
        assume(False)
        return
    check_drawing(res)


@pytest.mark.parametrize("text", [
    '[function]\nexpression = "1/x"\nrange = [1, 2]\n',
    '[function]\nexpression = "log10(x)"\nrange = [1, 10]\npoints = 3\n',
    '[cognates]\nO_A = [0, 0]\nA = [1.1473, 0.9663]\nB = [4.24983, 3.49112]\nO_B = [4, 0]\n'
    'P = [0.56317, 3.58526]\n',
    '[dwell]\nO_A = [0, 0]\nA = [1.31637, 0.71914]\nB = [4.19693, 3.49446]\nO_B = [4, 0]\n'
    'C = [4.97691, -0.19765]\nspan = 60\n',
    '[path]\npoints = [[0.26795, 0], [2.0, 0], [3.73205, 0]]\ncrank = [-6, -45, -84]\n'
    'coupler = [0, -20, -50]\nrocker_pin = 0.5\n',
    '[overlay]\npoints = [[13.4225, 11.2416], [14.0171, 12.1315], [14.2844, 12.9072], '
    '[14.2330, 13.5651], [13.9009, 14.0943], [13.3389, 14.4792], [12.6013, 14.7041], '
    '[11.7421, 14.7581], [10.8131, 14.6370], [9.8628, 14.3445]]\n',
    '[coupler_curve]\npoints = [[0, 0], [1, 0.6], [2, 0.7], [3, 0.2]]\nO4 = [1.5, -2]\n'
    'O2 = [-1, -1.5]\nR = 2.0\nr = 1.5\n',
    '[crank_rocker]\nO4 = [0, 0]\nB1 = [0, 4]\nswing = 45\nQ = 2.0\nx_angle = 68\n',
    '[dwell]\nO_A = [0, 0]\nA = [1.31637, 0.71914]\nB = [4.19693, 3.49446]\nO_B = [4, 0]\n'
    'C = [2.75665, 2.10680]\nspan = 60\nslider = true\n',
])
def test_function_cognates_dwell_path_and_overlay_draw_cleanly(text: str) -> None:
    check_drawing(synthesize(loads_spec('title = "t"\nunits = "in"\n' + text)))


def test_every_step_is_a_group_with_its_step_id_and_the_poles_carry_the_books_letters() -> None:
    # Example 9.1's pole triangle: P12 at (2, 0), P31 at the origin, φ12 = 53.13°,
    # φ31 = 36.87° (the postures built as in tests/synthesis/test_book.py)
    phi12, phi31 = math.radians(53.13), math.radians(36.87)
    d1 = 1 - 1.5j
    d2 = 2 + np.exp(2j * phi12) * (d1 - 2)
    d3 = np.exp(-2j * phi31) * d1
    pts = np.array([[z.real, z.imag] for z in (d1, d2, d3)])
    ang = np.degrees([0.0, 2 * phi12, -2 * phi31])
    res = synthesize(loads_spec(_posture_spec(pts, ang, "[pivots]\ncircle_points = "
                                              "[[1.0, -1.5], [1.6, -0.4]]\n")))
    d = draw_synthesis(res)
    gids = set(d.groups)
    assert res.construction is not None
    for s in res.construction:
        if s.label in ("P12", "P23", "P31", "O_A", "O_B", "A2", "A3"):
            assert f"synthesis-{s.step_id}" in gids, s.step_id
    shown = {t.get_text() for t in d.texts.values()}
    assert {"P₁₂", "P₂₃", "P₃₁", "A₁", "A₂", "A₃"} <= shown
    assert any("O_{A}" in t for t in shown)
    check_drawing(res)



# Five postures whose second Burmester point (the center point M2, chosen as the pivot O_B)
# lies 19.6 in from D1, far above the figure (found by the random posture sets above)
FIVE_FAR = """
title = "five postures, a Burmester point far away"
units = "in"
[[postures]]
point = [0.0, 0.0]
angle = 0.0
[[postures]]
point = [1.2259, 0.0]
angle = 10.0
[[postures]]
point = [1.8257, 0.0136]
angle = 20.373
[[postures]]
point = [3.1257, 0.0136]
angle = 56.373
[[postures]]
point = [4.1848, 0.0247]
angle = 85.735
"""


def test_a_far_burmester_point_is_named_at_the_edge() -> None:
    res = synthesize(loads_spec(FIVE_FAR))
    assert res.chosen is not None
    far = res.chosen.o_b
    x0, y0, x1, y1 = draw_synthesis(res).sheet.panels[0].inner
    assert not (x0 <= far.real <= x1 and y0 <= far.imag <= y1)   # it is off the figure
    check_drawing(res)
    d = draw_synthesis(res)
    # its name and its distance from D1 = (0, 0), to three figures
    said = [t.get_text() for t in d.texts.values() if letter("O_B") in t.get_text()]
    assert said and f"{abs(far):.3g} in" in said[0], said
