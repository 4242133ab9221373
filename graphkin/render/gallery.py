"""The gallery: textbook figures as mechanism files, their committed drawings and an index.

Every mechanism file under ``gallery/mechanisms/`` (and the instant-center
and curvature files under ``gallery/centers/`` and ``gallery/curvature/``) is
solved and drawn; the drawings go to ``gallery/drawings/`` and the index,
``gallery/README.md``, lists each drawing with the figure it reproduces and
the book's printed numbers beside graphkin's.  A file's optional
``[gallery]`` table says which figure it is and what the book prints::

    [gallery]
    figure = "Fig. 3.7"
    examples = "Examples 3.1, 3.7"
    section = "3.4"
    diagrams = ["velocity"]
    [[gallery.book]]
    quantity = "ω3"
    path = "links.3.omega"       # a path of `graphkin solve --json` ("|" = magnitude)
    value = 25.6
    unit = "rad/s"
    source = "graphic, Fig. 3.7b"
    why = "..."                  # when the book differs beyond its accuracy

With the matplotlib recorded in ``gallery/drawings/MANIFEST.json``, ``--check``
asks each committed drawing for the same text and every number within
:data:`SAME_PT` (the last digits of another machine's sin and solves move
coordinates by less); with another version it compares them structurally (the
ids of every group and the text of every label).

References
----------
Uicker, Pennock & Shigley, 5th ed., Chapters 2-5.
"""

from __future__ import annotations

import hashlib
import json
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from graphkin.files import load_toml
from graphkin.tolerance import VERDICT_REL

__all__ = ["Entry", "discover", "build", "check", "structure", "same_drawing", "compact_svg",
           "FOLDERS", "CHAPTERS"]

FOLDERS = {"mechanisms": None, "centers": "centers", "curvature": "curvature"}
"""Gallery folders of mechanism files, and the diagram drawn by default for each
(None: ``velocity`` and ``acceleration`` when the file gives rates, else ``posture``)."""

CHAPTERS = {"cams": "graphkin.render.gallery_cams", "gears": "graphkin.render.gallery_gears",
            "synthesis": "graphkin.render.gallery_synthesis"}
"""Gallery folders of the design chapters' own files (cam, gear and synthesis files),
and the module that renders each: ``render_entry(entry) -> (drawings, info)`` with
``drawings`` name -> compact SVG bytes and ``info`` holding ``title`` and ``solution``
(the dict the ``[[gallery.book]]`` paths are looked up in). A folder that does not
exist is skipped, and its module is imported only when the folder has files."""

_NUM = re.compile(r"-?\d+\.\d{3,}")
_D = re.compile(r'(\sd=")([^"]*)(")')
_POINTS = re.compile(r'(\s(?:x|y|points)=")([^"]*)(")')


@dataclass
class Entry:
    """One mechanism of the gallery."""

    path: Path
    folder: str
    meta: dict[str, Any] = field(default_factory=dict)

    @property
    def stem(self) -> str:
        """The drawing's base name: the file's stem, prefixed by its folder outside mechanisms/."""
        return self.path.stem if self.folder == "mechanisms" else f"{self.folder}-{self.path.stem}"

    def diagrams(self, has_rates: bool) -> list[str]:
        """The diagrams to draw."""
        if "diagrams" in self.meta:
            return [str(d) for d in self.meta["diagrams"]]
        default = FOLDERS.get(self.folder)
        if default is not None:
            return [default]
        return ["velocity", "acceleration"] if has_rates else ["posture"]


def _within(root: Path, p: Path) -> bool:
    """True when ``p``, with every symlink resolved, lies inside ``root``."""
    try:
        p.resolve().relative_to(root.resolve())
    except ValueError:
        return False
    return True


def discover(root: str | Path) -> list[Entry]:
    """Every mechanism file of the gallery, in folder then name order.

    Raises
    ------
    InputError
        A file that is not valid TOML, or a symlink leading out of the gallery.
    """
    from graphkin.errors import InputError

    root = Path(root)
    out = []
    for folder in [*FOLDERS, *CHAPTERS]:
        for p in sorted((root / folder).glob("*.toml"), key=_natural):
            if not _within(root, p) or not p.is_file():
                raise InputError("a link out of the gallery folder (or not a regular file); "
                                 "the gallery reads only its own files", file=str(p))
            data = load_toml(p)  # bounded; a malformed file is one InputError naming it
            if folder in FOLDERS and "links" not in data:
                continue
            out.append(Entry(p, folder, dict(data.get("gallery", {}))))
    return out


def _natural(p: Path) -> list[Any]:
    """Sort key: fig3_7 before fig3_10."""
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", p.stem)]


def _from_title(title: str) -> dict[str, str]:
    """Figure and examples named in a title, for files without a [gallery] table."""
    out = {}
    m = re.search(r"Examples? [0-9][0-9.,\s\-and]*[0-9]", title)
    if m:
        out["examples"] = m.group(0)
    m = re.search(r"Figs?\. [0-9][0-9.,\s\-]*[0-9]", title)
    if m:
        out["figure"] = m.group(0)
    return out


def compact_svg(data: bytes) -> bytes:
    """Round the coordinates of paths to 1/100 pt: smaller files, the same drawing.

    Only path data and coordinates are touched, never the text.

    Examples
    --------
    >>> compact_svg(b'<path d="M 1.234567 2.5 L 3.000001 4"/>')
    b'<path d="M 1.23 2.5 L 3 4"/>'
    """
    text = data.decode("utf-8")

    def rnd(m: re.Match[str]) -> str:
        v = round(float(m.group(0)), 2)
        s = f"{v:.2f}".rstrip("0").rstrip(".")
        return "0" if s in ("-0", "") else s

    def attr(m: re.Match[str]) -> str:
        return m.group(1) + _NUM.sub(rnd, m.group(2)) + m.group(3)

    text = _D.sub(attr, text)
    text = _POINTS.sub(attr, text)
    return text.encode("utf-8")


_TOKEN = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")
_IDS = re.compile(r"\b[a-z][0-9a-f]{10}\b")
_PATH = re.compile(r'(\sd=")([^"]*)(")')
SAME_PT = 0.02
"""Two drawings are the same when every number in them agrees within this (points)..."""
SAME_PATH_PT = 0.25
"""... or, for a path drawn with other vertices, when each lies within this of the other."""


def same_drawing(a: bytes, b: bytes, tol: float = SAME_PT) -> bool:
    """True when two SVGs draw the same: the same text, the same numbers within ``tol``.

    The same drawing made on another machine differs in the last digits of
    its coordinates (its sin, hypot and solves do), in the hundredths to which
    they are written, in matplotlib's hashed ids, and in the vertices of an
    outline (a link's bar, the union of its pins, has a vertex more or less
    where two arcs meet): a path is the same when each of the two lies within
    :data:`SAME_PATH_PT` of the other.  A label moved, a line added or a value
    changed is not the same drawing.

    Examples
    --------
    >>> same_drawing(b'<path d="M 1.25 3"/>', b'<path d="M 1.26 3"/>')
    True
    >>> same_drawing(b'<path d="M 0 0 L 10 0"/>', b'<path d="M 0 0 L 5 0.01 L 10 0"/>')
    True
    >>> same_drawing(b'<path d="M 0 0 L 10 0"/>', b'<path d="M 0 0 L 5 1 L 10 0"/>')
    False
    >>> same_drawing(b'<text x="1.25">2.5 mm</text>', b'<text x="1.25">2.5 in</text>')
    False
    """
    def split(data: bytes) -> tuple[list[str], list[float], list[str]]:
        text = data.decode("utf-8")
        names: dict[str, str] = {}
        text = _IDS.sub(lambda m: names.setdefault(m.group(0), f"id{len(names)}_"), text)
        paths: list[str] = []

        def keep(m: re.Match[str]) -> str:
            paths.append(m.group(2))
            return m.group(1) + m.group(3)

        text = _PATH.sub(keep, text)
        return _TOKEN.split(text), [float(t) for t in _TOKEN.findall(text)], paths

    (wa, na, pa), (wb, nb, pb) = split(a), split(b)
    return (wa == wb and len(na) == len(nb) and len(pa) == len(pb)
            and all(abs(x - y) <= tol for x, y in zip(na, nb))
            and all(_same_path(x, y, tol) for x, y in zip(pa, pb)))


def _same_path(a: str, b: str, tol: float) -> bool:
    """Two SVG path data the same to ``tol``, or drawing the same line to :data:`SAME_PATH_PT`."""
    wa, wb = _TOKEN.split(a), _TOKEN.split(b)
    na, nb = _TOKEN.findall(a), _TOKEN.findall(b)
    if wa == wb and all(abs(float(x) - float(y)) <= tol for x, y in zip(na, nb)):
        return True
    import shapely

    def lines(d: str) -> Any:
        parts = []
        for sub in re.split(r"(?=M)", d):
            xy = [float(t) for t in _TOKEN.findall(sub)]
            pts = list(zip(xy[0::2], xy[1::2]))
            if pts and sub.rstrip().endswith(("z", "Z")):
                pts.append(pts[0])  # a closed outline, from wherever it starts
            if len(pts) > 1:
                parts.append(shapely.LineString(pts))
            elif pts:
                parts.append(shapely.Point(pts[0]))
        return shapely.GeometryCollection(parts)

    ga, gb = lines(a), lines(b)
    if ga.is_empty or gb.is_empty:
        return ga.is_empty and gb.is_empty
    return bool(ga.hausdorff_distance(gb) <= SAME_PATH_PT)


def structure(data: bytes) -> str:
    """A digest of an SVG's structure: every id, in order, and every text, by id.

    Two drawings with the same digest show the same constructions, labels and
    values; they may differ in the last digits of coordinates or fonts
    (another matplotlib).
    """
    root = ET.fromstring(data)
    items = []
    for el in root.iter():
        i = el.get("id")
        if i is None or re.fullmatch(r"[a-z]+[0-9a-f]{6,}", i) or re.match(
                r"(line2d|patch|text|axes|figure|[mp][0-9a-f]+)_?\d*$", i):
            continue
        texts = "".join(t.text or "" for t in el.iter() if t.tag.endswith(("text", "tspan")))
        items.append(f"{i}\t{' '.join(texts.split())}")
    return hashlib.sha256("\n".join(items).encode("utf-8")).hexdigest()


def _lookup(obj: Any, path: str) -> Any:
    """The value at ``path`` (dotted keys of ``solve --json``; ``|`` at the end: magnitude).

    Raises
    ------
    KeyError
        With a message naming the first part not found and what is there.
    """
    mag = path.endswith("|")
    done: list[str] = []
    for part in path.rstrip("|").split("."):
        try:
            obj = obj[part] if isinstance(obj, dict) else obj[int(part)]
        except (KeyError, TypeError, IndexError, ValueError):
            where = ".".join(done) or "the top"
            there = ", ".join(map(str, list(obj)[:12])) if isinstance(obj, dict) else \
                (f"items 0 to {len(obj) - 1}" if isinstance(obj, list) else "a value")
            raise KeyError(f"no '{part}' at {where} of graphkin solve --json "
                           f"(there: {there})") from None
        done.append(part)
    if mag:
        return math.hypot(*obj)
    return obj


def _render(entry: Entry) -> tuple[dict[str, bytes], dict[str, Any]]:
    """The drawings of an entry (name -> compact SVG bytes) and its solution data."""
    import graphkin
    from graphkin.errors import GraphkinError, InputError
    from graphkin.output import solution_to_dict
    from graphkin.render.mpl import draw
    from graphkin.render.svg import to_bytes

    mech = graphkin.load(entry.path)
    try:
        sol = mech.solve()
    except GraphkinError as exc:
        raise InputError(f"cannot solve it: {exc}", file=str(entry.path)) from None
    data = solution_to_dict(sol)
    drawings = {}
    for d in entry.diagrams(mech.has_rates):
        link = entry.meta.get("link")
        fig = draw(sol, d, link=None if link is None else str(link)).figure
        drawings[f"{entry.stem}-{d}.svg"] = compact_svg(to_bytes(fig))
    return drawings, {"solution": data, "title": mech.title, "method": sol.method,
                      "has_rates": mech.has_rates}


def _fmt(v: Any, scale: float | None = None) -> str:
    """A value (or a vector) to five figures; round-off of ``scale`` written as 0.

    ``scale`` defaults to the value's own size: a component 1e-14 of a vector of
    583 prints as 0 on every machine (its digits are the arithmetic's, not the
    mechanism's, and differ between CPUs).
    """
    from graphkin.render.scale import fmt

    if v is None:
        return "—"
    vals = [float(x) for x in v] if isinstance(v, (list, tuple)) else [float(v)]
    big = max((abs(x) for x in vals if math.isfinite(x)), default=0.0)
    tiny = VERDICT_REL * (big if scale is None else max(scale, big))
    text = [fmt(0.0 if abs(x) <= tiny else x, 5) for x in vals]
    return "(" + ", ".join(text) + ")" if isinstance(v, (list, tuple)) else text[0]


def _last_digit(v: Any) -> float:
    """The place of the last printed digit of a book value: 1.41 -> 0.01, 24625 -> 1."""
    vals = v if isinstance(v, (list, tuple)) else [v]
    places = []
    for x in vals:
        text = repr(float(x)) if isinstance(x, float) else str(int(x))
        if "e" in text:
            return 0.0
        frac = text.split(".")[1].rstrip("0") if "." in text else ""
        places.append(10.0 ** -len(frac))
    return min(places)


def _compare(book: Any, got: Any) -> tuple[str, float, float]:
    """Graphkin's value minus the book's: text, relative size, absolute size."""
    if isinstance(book, (list, tuple)):
        d = [float(g) - float(b) for g, b in zip(got, book)]
        size = math.hypot(*map(float, book))
        return (_fmt(d, max(size, math.hypot(*map(float, got)))),
                math.hypot(*d) / max(size, 1e-12), max(abs(x) for x in d))
    diff = float(got) - float(book)
    return (_fmt(diff, max(abs(float(book)), abs(float(got)))),
            abs(diff) / max(abs(float(book)), 1e-12), abs(diff))


def _rows(entry: Entry, data: dict[str, Any]) -> list[dict[str, str]]:
    rows = []
    from graphkin.errors import InputError

    for i, b in enumerate(entry.meta.get("book", [])):
        if "path" not in b:
            raise InputError("a row of the book's numbers needs the path of graphkin's "
                             "value in graphkin solve --json", key=f"gallery.book[{i}].path",
                             file=str(entry.path))
        try:
            got = _lookup(data, str(b["path"]))
        except KeyError as exc:   # a misspelt path is the file's mistake, not "differs"
            raise InputError(str(exc.args[0]), key=f"gallery.book[{i}].path",
                             file=str(entry.path)) from None
        book = b.get("value")
        diff, rel, dabs = ("—", math.inf, math.inf) if got is None or book is None \
            else _compare(book, got)
        graphic = "graphic" in str(b.get("source", ""))
        # a graphic value agrees within the drawing's accuracy (2 %); a computed one
        # within 0.1 % (the book carries rounded intermediate results) or when
        # graphkin's value rounds to the digits the book prints
        limit = float(b.get("tolerance", 0.02 if graphic else 0.001))
        ok = rel <= limit or (not graphic and dabs <= 0.5 * _last_digit(book) + 1e-12)
        verdict = "agrees" if ok else "**differs**"
        rows.append({"quantity": str(b.get("quantity", b["path"])), "book": _fmt(book),
                     "source": str(b.get("source", "")), "graphkin": _fmt(got),
                     "diff": diff, "unit": str(b.get("unit", "")), "verdict": verdict,
                     "why": str(b.get("why", ""))})
    return rows


def _readme(root: Path, entries: list[Entry], results: dict[str, dict[str, Any]],
            drawings: dict[str, list[str]], mpl_version: str) -> str:
    lines = [
        "# Gallery: the textbook's figures, drawn by graphkin",
        "",
        "Each mechanism file reproduces a figure of Uicker, Pennock & Shigley, *Theory of "
        "Machines and Mechanisms*, 5th ed.; each drawing is made by the construction the "
        "book teaches, to a stated scale, with a table comparing every value read off the "
        "construction with the analytic solution. Below each drawing, the numbers the book "
        "prints beside graphkin's, and why they differ where they do.",
        "",
        "This file and the drawings are generated: `graphkin gallery` rebuilds them, "
        "`graphkin gallery --check` exits non-zero when one is out of date. With matplotlib "
        f"{mpl_version} (recorded in `drawings/MANIFEST.json`) it asks for the same text and "
        "every coordinate within 0.02 pt (another machine's last digits move them by less, "
        "a label moved or a line added by more); with another version it compares their "
        "structure (every step's group id and every label's text).",
        "",
        "The four cases of the planar vector equation (Sec. 2.8, Figs. 2.10-2.13) are vector "
        "files in [`vector/`](vector/): `graphkin vector gallery/vector/case4.toml`.",
        "",
    ]
    lines += _before_after(root, drawings)
    lines += [
        "## Index",
        "",
        "| mechanism | figure | examples | section | drawings |",
        "|---|---|---|---|---|",
    ]
    for e in entries:
        r = results[e.stem]
        rel = e.path.relative_to(root).as_posix()
        links = " ".join(f"[{Path(n).stem.rsplit('-', 1)[-1]}](drawings/{n})"
                         for n in drawings[e.stem])
        lines.append(f"| [{e.path.stem}]({rel}) | {e.meta.get('figure', '')} | "
                     f"{e.meta.get('examples', '')} | {e.meta.get('section', '')} | {links} |")
    lines.append("")
    for e in entries:
        r = results[e.stem]
        rel = e.path.relative_to(root).as_posix()
        lines += [f"## {r['title'] or e.path.stem}", ""]
        facts = [f"File: [`{rel}`]({rel})"]
        if e.meta.get("figure"):
            facts.append(f"reproduces {e.meta['figure']}")
        if e.meta.get("examples"):
            facts.append(str(e.meta["examples"]))
        if e.meta.get("section"):
            facts.append(f"Sec. {e.meta['section']}")
        lines += ["; ".join(facts) + ".", ""]
        if e.meta.get("note"):
            lines += [str(e.meta["note"]).strip(), ""]
        for n in drawings[e.stem]:
            lines += [f"![{Path(n).stem}](drawings/{n})", ""]
        rows = _rows(e, r["solution"])
        if rows:
            lines += ["| quantity | book | source | graphkin | graphkin − book | unit | |",
                      "|---|---|---|---|---|---|---|"]
            for row in rows:
                cells = [row[k].replace("|", "\\|") for k in
                         ("quantity", "book", "source", "graphkin", "diff", "unit", "verdict")]
                lines.append("| " + " | ".join(cells) + " |")
            lines.append("")
            for row in rows:
                if row["why"]:
                    text = " ".join(row["why"].split())
                    lines += [f"* **{row['quantity']}** ({row['source']}): {text}"]
            if any(row["why"] for row in rows):
                lines.append("")
    return "\n".join(lines).rstrip() + "\n"


BEFORE_AFTER = (("curvature", "before/ex4_14_inflection_bresse_curvature.png",
                 "curvature-ex4_14_fourbar-curvature.svg"),
                ("instant centers", "before/ex4_14_inflection_bresse_centers.png",
                 "curvature-ex4_14_fourbar-centers.svg"))
"""Issue 11's before/after pair of Example 4.14: the drawing of the first release (a
committed PNG) beside the drawing the gallery makes now."""


def _before_after(root: Path, drawings: dict[str, list[str]]) -> list[str]:
    made = {n for names in drawings.values() for n in names}
    pairs = [(what, old, new) for what, old, new in BEFORE_AFTER
             if (root / old).is_file() and new in made]
    if not pairs:
        return []
    lines = ["## Before and after: Example 4.14", "",
             "The same file drawn before the figures were reworked (left: one panel with every "
             "construction line, literal underscores, no Kennedy circle, a center at infinity "
             "as huge coordinates) and now (right: the curvature sheet split into the book's "
             "figures with the cubic drawn, the Kennedy circle beside the instant centers).",
             "", "| | before | after |", "|---|---|---|"]
    for what, old, new in pairs:
        lines.append(f"| {what} | ![before]({old}) | ![after](drawings/{new}) |")
    return lines + [""]


def _generate(root: Path) -> tuple[dict[str, bytes], str, dict[str, Any]]:
    import matplotlib

    import graphkin
    from graphkin.progress import track

    entries = discover(root)
    files: dict[str, bytes] = {}
    results: dict[str, dict[str, Any]] = {}
    names: dict[str, list[str]] = {}
    for e in track(entries, "gallery", unit="figure"):
        if e.folder in CHAPTERS:
            import importlib

            drawings, info = importlib.import_module(CHAPTERS[e.folder]).render_entry(e)
        else:
            drawings, info = _render(e)
        for k, v in _from_title(info["title"] or "").items():
            e.meta.setdefault(k, v)
        files.update(drawings)
        results[e.stem] = info
        names[e.stem] = list(drawings)
    readme = _readme(root, entries, results, names, matplotlib.__version__)
    manifest = {"matplotlib": matplotlib.__version__, "graphkin": graphkin.__version__,
                "drawings": {n: {"sha256": hashlib.sha256(b).hexdigest(),
                                 "structure": structure(b)} for n, b in sorted(files.items())}}
    return files, readme, manifest


def _writable(root: Path, p: Path) -> Path:
    """``p`` if the gallery may write it: inside the gallery, not a symlink, not a folder."""
    from graphkin.errors import InputError

    if p.is_symlink() or (p.exists() and not p.is_file()) or not _within(root, p.parent):
        raise InputError("a link, a folder or a path out of the gallery folder; the gallery "
                         "writes only its own files", file=str(p))
    return p


def build(root: str | Path) -> list[Path]:
    """Regenerate every drawing, the manifest and the README; returns the files written.

    Only drawings the previous manifest lists (drawings this command wrote)
    are deleted when no mechanism draws them any more; nothing is written or
    deleted through a symlink or outside the gallery folder.
    """
    root = Path(root)
    files, readme, manifest = _generate(root)
    out = root / "drawings"
    if out.is_symlink():
        _writable(root, out)
    out.mkdir(parents=True, exist_ok=True)
    man_path = _writable(root, out / "MANIFEST.json")
    ours: set[str] = set()
    if man_path.is_file():
        try:
            ours = set(json.loads(man_path.read_text(encoding="utf-8")).get("drawings", {}))
        except (ValueError, AttributeError):
            ours = set()
    written = []
    for name in sorted(ours - set(files)):
        old = out / name
        if "/" not in name and old.suffix == ".svg" and old.is_file() and not old.is_symlink():
            old.unlink()
    for name, data in files.items():
        p = _writable(root, out / name)
        if not p.exists() or p.read_bytes() != data:
            p.write_bytes(data)
        written.append(p)
    man_path.write_text(json.dumps(manifest, indent=1, sort_keys=True) + "\n", encoding="utf-8")
    _writable(root, root / "README.md").write_text(readme, encoding="utf-8")
    return written


def check(root: str | Path) -> list[str]:
    """What is out of date (empty when the gallery is current).

    With the matplotlib the drawings were made with, each committed drawing
    must draw the same as the regenerated one (:func:`same_drawing`); with
    another, its structure (:func:`structure`) must.
    """
    import matplotlib

    root = Path(root)
    files, readme, manifest = _generate(root)
    out = root / "drawings"
    problems = []
    man_path = out / "MANIFEST.json"
    pinned = None
    if man_path.exists():
        pinned = json.loads(man_path.read_text(encoding="utf-8")).get("matplotlib")
    exact = pinned == matplotlib.__version__
    for name, data in files.items():
        p = out / name
        if not p.exists():
            problems.append(f"{p}: missing")
            continue
        old = p.read_bytes()
        if exact and not same_drawing(old, data):
            problems.append(f"{p}: out of date")
        elif not exact and structure(old) != structure(data):
            problems.append(f"{p}: out of date (its structure differs)")
    for p in sorted(out.glob("*.svg")):
        if p.name not in files:
            problems.append(f"{p}: no mechanism file draws it any more")
    readme_path = root / "README.md"
    current = readme_path.read_text(encoding="utf-8") if readme_path.exists() else ""
    if exact and current != readme:
        problems.append(f"{readme_path}: out of date")
    elif not exact and _strip_version(current) != _strip_version(readme):
        problems.append(f"{readme_path}: out of date")
    return problems


def _strip_version(text: str) -> str:
    return re.sub(r"matplotlib \d+\.\d+\.\d+\S*", "matplotlib X", text)
