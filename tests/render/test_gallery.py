"""The gallery: rebuilt by one command, checked structurally or byte for byte."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest
from spec_data import EXAMPLES

from graphkin.cli import main
from graphkin.render.gallery import build, check, compact_svg, discover, structure

GALLERY = Path(__file__).resolve().parents[2] / "gallery"


@pytest.fixture(scope="module")
def small_gallery(tmp_path_factory) -> Path:
    root = tmp_path_factory.mktemp("gallery")
    (root / "mechanisms").mkdir()
    text = (EXAMPLES / "ex2_5_open.toml").read_text(encoding="utf-8")
    text += ('\n[gallery]\nfigure = "Fig. 2.24"\ndiagrams = ["posture"]\n'
             '[[gallery.book]]\nquantity = "θ3"\npath = "links.3.angle"\nvalue = 59.46\n'
             'unit = "deg"\nsource = "analytic"\n'
             '[[gallery.book]]\nquantity = "θ4"\npath = "links.4.angle"\nvalue = 97\n'
             'unit = "deg"\nsource = "graphic"\n')
    (root / "mechanisms" / "fig2_24_open.toml").write_text(text, encoding="utf-8")
    build(root)
    return root


def test_build_writes_drawings_manifest_and_index(small_gallery):
    svg = small_gallery / "drawings" / "fig2_24_open-posture.svg"
    assert svg.exists()
    manifest = json.loads((small_gallery / "drawings" / "MANIFEST.json").read_text())
    assert "fig2_24_open-posture.svg" in manifest["drawings"]
    readme = (small_gallery / "README.md").read_text(encoding="utf-8")
    assert "drawings/fig2_24_open-posture.svg" in readme
    # Example 2.5: θ3 = 59.46° (analytic) and θ4 = 97° (graphic) agree with the construction
    assert "| θ3 | 59.46 | analytic | 59.459 |" in readme
    assert "differs" not in readme
    assert check(small_gallery) == []


def test_check_finds_a_stale_drawing(small_gallery, tmp_path):
    root = tmp_path / "g"
    shutil.copytree(small_gallery, root)
    svg = root / "drawings" / "fig2_24_open-posture.svg"
    svg.write_bytes(svg.read_bytes().replace(b">B</text>", b">X</text>"))
    problems = check(root)
    assert problems and "fig2_24_open-posture.svg" in problems[0]
    assert main(["gallery", "--dir", str(root), "--check"]) == 1


def test_structure_ignores_coordinates_but_not_labels():
    a = b'<svg xmlns="http://www.w3.org/2000/svg"><g id="step-01-B"><path d="M 1.234 5"/>' \
        b'<text>B</text></g></svg>'
    moved = a.replace(b"1.234", b"1.236")
    relabelled = a.replace(b">B<", b">C<")
    assert structure(a) == structure(moved)
    assert structure(a) != structure(relabelled)
    assert compact_svg(b'<path d="M 1.23456 2"/>') == b'<path d="M 1.23 2"/>'


def test_committed_gallery_has_enough_figures():
    if not (GALLERY / "mechanisms").is_dir():
        pytest.skip("no gallery in this checkout")
    entries = discover(GALLERY)
    assert len(entries) >= 25
    drawings = GALLERY / "drawings"
    for e in entries:
        assert list(drawings.glob(f"{e.stem}-*.svg")), e.stem


def test_build_deletes_only_its_own_drawings(small_gallery, tmp_path):
    root = tmp_path / "g"
    shutil.copytree(small_gallery, root)
    mine = root / "drawings" / "my-own-figure.svg"
    mine.write_text("<svg/>", encoding="utf-8")
    # a drawing graphkin wrote earlier, whose mechanism file is gone, is removed
    (root / "drawings" / "fig2_24_open-posture.svg").rename(root / "drawings" / "old-posture.svg")
    man = root / "drawings" / "MANIFEST.json"
    data = json.loads(man.read_text())
    data["drawings"]["old-posture.svg"] = data["drawings"].pop("fig2_24_open-posture.svg")
    man.write_text(json.dumps(data))
    build(root)
    assert mine.read_text(encoding="utf-8") == "<svg/>"
    assert not (root / "drawings" / "old-posture.svg").exists()


def test_build_never_follows_a_symlink_out_of_its_folder(small_gallery, tmp_path):
    from graphkin.errors import InputError

    outside = tmp_path / "outside"
    outside.mkdir()
    victim = outside / "fig2_24_open-posture.svg"
    victim.write_text("keep me", encoding="utf-8")
    root = tmp_path / "g"
    shutil.copytree(small_gallery, root)
    shutil.rmtree(root / "drawings")
    (root / "drawings").symlink_to(outside, target_is_directory=True)
    with pytest.raises(InputError, match="out of the gallery"):
        build(root)
    assert victim.read_text(encoding="utf-8") == "keep me"
    # a drawing that is a link to a file outside is not written through either
    (root / "drawings").unlink()
    (root / "drawings").mkdir()
    (root / "drawings" / "fig2_24_open-posture.svg").symlink_to(victim)
    with pytest.raises(InputError, match="link"):
        build(root)
    assert victim.read_text(encoding="utf-8") == "keep me"
    # a mechanism file linked from outside is not read
    (root / "drawings" / "fig2_24_open-posture.svg").unlink()
    (root / "mechanisms" / "x.toml").symlink_to(EXAMPLES / "ex3_1_fourbar.toml")
    with pytest.raises(InputError, match="out of the gallery"):
        discover(root)


def test_a_malformed_file_in_the_gallery_is_one_line(small_gallery, tmp_path, capsys):
    root = tmp_path / "g"
    shutil.copytree(small_gallery, root)
    (root / "mechanisms" / "bad.toml").write_text("[links.1\nA = [0, 0]\n", encoding="utf-8")
    assert main(["gallery", "--dir", str(root), "--check"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "bad.toml" in err[0] and "TOML" in err[0]
