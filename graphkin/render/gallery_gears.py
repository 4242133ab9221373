"""The gallery's Chapter 7 folder (``gallery/gears/``): gear pairs and gear trains.

Each file of the folder is a gear file (a pair in mesh) or a gear-train file
(docs/formats/gears.md) with a ``[gallery]`` table; :func:`render_entry`
solves it and draws it as :mod:`graphkin.render.gallery` asks:

* a pair: the drawing of ``graphkin draw FILE -d gears`` (Figs. 7.8-7.9,
  7.17, 7.18, 7.21), and as the solution the object of
  ``graphkin gears FILE --json``;
* a train: the tables of the book's analysis (:mod:`graphkin.render.gears_train`),
  and as the solution the object of ``graphkin gears TRAINFILE --json``, with
  ``formula_by`` added: each train value keyed ``"L-F"`` (last and first gear)
  so that a ``[[gallery.book]]`` path can name it (``formula_by.6-2.train_value``).

References
----------
Uicker, Pennock & Shigley, 5th ed., Chapter 7.
"""

from __future__ import annotations

from typing import Any

__all__ = ["render_entry"]


def render_entry(entry: Any) -> tuple[dict[str, bytes], dict[str, Any]]:
    """The drawings of a gallery entry (name -> compact SVG bytes) and its solution data.

    Raises
    ------
    InputError
        A file that is neither a gear file nor a gear-train file, or whose
        gears cannot mesh (one line naming the file and the key).
    """
    from graphkin.errors import InputError
    from graphkin.gears.file import from_dict, gear_kind
    from graphkin.gears.train_file import train_from_dict
    from graphkin.render.gallery import compact_svg
    from graphkin.render.svg import to_bytes

    source = str(entry.path)
    found = gear_kind(entry.path)
    if found is None:
        from graphkin.files import load_toml

        if "links" in load_toml(entry.path):
            return _mechanism(entry)
        raise InputError("not a gear file: a pair in mesh has [gears.<name>] tables, a train "
                         "[[mesh]] tables (docs/formats/gears.md)", file=source)
    kind, data = found
    if kind == "train":
        from graphkin.output.trains import train_json
        from graphkin.render.gears_train import train_figure

        train = train_from_dict(data, source)
        sol = train_json(train)
        sol["formula_by"] = {f"{f['last']}-{f['first']}": f for f in sol["formula"]}
        fig = train_figure(train, sol)
        return ({f"{entry.stem}-train.svg": compact_svg(to_bytes(fig))},
                {"title": train.title, "solution": sol})
    from graphkin.gears import layout
    from graphkin.output.gears import gears_json
    from graphkin.render.gears import draw_gears

    lay = layout(from_dict(data, source))
    fig = draw_gears(lay).figure
    return ({f"{entry.stem}-gears.svg": compact_svg(to_bytes(fig))},
            {"title": lay.pair.title, "solution": gears_json(lay)})


def _mechanism(entry: Any) -> tuple[dict[str, bytes], dict[str, Any]]:
    """A geared mechanism (a planetary train with loads, Sec. 11.11): its force drawing.

    The solution is ``graphkin solve --json``'s object (with ``forces.gears``,
    each tooth force's transmitted and radial parts) and ``train``, the train
    read off its rolling circles (:func:`graphkin.output.trains.mechanism_train_json`).
    """
    import graphkin
    from graphkin.errors import GraphkinError, InputError
    from graphkin.output import solution_to_dict
    from graphkin.output.trains import mechanism_train_json
    from graphkin.render.gallery import compact_svg
    from graphkin.render.mpl import draw
    from graphkin.render.svg import to_bytes

    mech = graphkin.load(entry.path)
    try:
        sol = mech.solve()
    except GraphkinError as exc:
        raise InputError(f"cannot solve it: {exc}", file=str(entry.path)) from None
    data = solution_to_dict(sol)
    data["train"] = mechanism_train_json(sol)
    drawings = {}
    for d in entry.diagrams(mech.has_rates) if "diagrams" in entry.meta else ["forces"]:
        fig = draw(sol, d).figure
        drawings[f"{entry.stem}-{d}.svg"] = compact_svg(to_bytes(fig))
    return drawings, {"title": mech.title, "solution": data}
