"""Free-body diagrams and force polygons, laid out as the book's Fig. 11.5.

(a) the mechanism with its loads, to a length scale; (b-d) the free-body
diagram of each moving link, to the same length scale, every force drawn on
its line of action (dashed), with the concurrency point of a three-force
member (Fig. 11.5e) and the drive's torque; then the force polygon of each
link, to one stated force scale, each closing (Σ F = 0, Fig. 11.5f).  With
several loaded links the polygons of each partial analysis (Sec. 12.5) come
first, then those of the totals.

Every panel has a gid (``panel-forces-mechanism``, ``panel-fbd-3``,
``panel-polygon-3``) and every force one too: ``fbd-3-F₂₃`` (its arrow on
the free body), ``polygon-3-F₂₃`` (tail to head at the force scale),
``concurrency-3``, ``fbd-3-torque``, ``fbd-3-h``; the line stating both
scales is ``force-scale`` (on a free sheet; a handout page, ``--sheet
a4|letter``, states them in its title block, ``title-block``, and reads the
forces and the drive's torque off the drawing into its compact table,
``results``).  The scene is built by :mod:`graphkin.render.forces_sheet`.

References
----------
Uicker, Pennock & Shigley, 5th ed., Figs. 11.5, 11.8, 12.8, 12.10.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from graphkin.render.scale import fmt
from graphkin.render.stepper import PAGER_JS, frame_section

if TYPE_CHECKING:
    from graphkin.forces.solve import ForceSolution
    from graphkin.render.mpl import Drawing

__all__ = ["draw_forces", "force_name"]

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def force_name(label: str) -> str:
    """A construction label as the book writes it: ``F_34′`` -> ``F₃₄′``.

    Examples
    --------
    >>> force_name("F_34′"), force_name("-m3A_G3"), force_name("T_12")
    ('F₃₄′', '−m₃A_G₃', 'T₁₂')
    """
    head, sep, rest = label.partition("_")
    if label.startswith("-m"):
        body = label[2:]
        k = body.index("A_")
        return "−m" + body[:k].translate(_SUB) + "A_" + body[k + 2:].translate(_SUB)
    if not sep:
        return label.replace("$", r"\$")
    digits = "".join(ch for ch in rest if ch.isdigit())
    tail = rest[len(digits):]
    return (head + digits.translate(_SUB) + tail).replace("$", r"\$")


def load_name(fs: ForceSolution, ld: Any) -> str:
    """The book's name of a given load (``P₄``; ``P`` when the construction has none)."""
    from graphkin.forces.graphic import applied_labels

    for label, _, src in applied_labels(fs.mechanism, fs.dynamic).get(ld.link, []):
        if src is ld:
            return force_name(label)
    return "P"


def draw_forces(obj: Any, *, table: bool = True, upto: int | None = None,
                sheet: str | None = None) -> Drawing:
    """Draw the mechanism with its loads, each link's free body and force polygon.

    The layout is the book's Fig. 11.5: (a) the mechanism and its loads, (b...)
    each link's free body (lines of action dashed, the concurrency point of a
    three-force member, h of an inertia force, the drive's torque), then each
    link's force polygon to one stated force scale.  Labels are placed by
    :func:`graphkin.render.labels.place_labels`, clear of every line and label.

    Parameters
    ----------
    obj : Mechanism, Solution or ForceSolution
    table : bool
        Add the results table: each joint force and the drive's torque read
        off the construction beside the matrix method's (Sec. 11.9).
    upto : int, optional
        Draw only what the force construction has found up to step ``upto``
        (inclusive), the newest step's forces in the highlight colour: a
        started drawing to hand out, or one frame of ``graphkin steps -d forces``.
    sheet : str, optional
        ``a4`` or ``letter``: a handout page as every other diagram's
        (:mod:`graphkin.render.handout`): 1-2-5 scales, portrait or
        landscape, a band with the compact table (F_ij and T₁₂ in the force
        scale's unit), the legend of the forces' colours and the title block
        naming the mechanism, "forces" and both scales.

    Returns
    -------
    Drawing
        Label -> artist (``fbd-3-F₂₃``-style keys), with ``.figure``,
        ``.texts`` (``force-scale``: the line stating both scales, free sheet only) and
        ``.vectors`` (polygon -> [(label, tail, head)] in force units).

    Raises
    ------
    DiagramUnavailable
        The file has no loads and no mass properties.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Figs. 11.5, 11.8, 12.8; Secs. 11.6-11.8, 12.5.
    """
    from graphkin.forces.report import forces_report
    from graphkin.forces.solve import ForceSolution
    from graphkin.render.forces_page import paper_forces_sheet
    from graphkin.render.forces_sheet import SCALES_H, build_forces_sheet
    from graphkin.render.mpl import render_sheet
    from graphkin.render.sources import DiagramUnavailable
    from graphkin.render.style import SMALL_PT, rc_context

    if isinstance(obj, ForceSolution):
        fs = obj
    else:
        sol = obj.solve() if hasattr(obj, "pins") else obj
        got = forces_report(sol)
        if got is None:
            raise DiagramUnavailable("no forces diagram: the file has no [[loads]] and no "
                                     "[inertia.N] (docs/forces.md)", diagram="forces")
        fs = got
    laid = (paper_forces_sheet(fs, sheet, upto=upto, table=table) if sheet is not None
            else build_forces_sheet(fs, upto=upto, table=table))
    drawing = render_sheet(laid.sheet)
    drawing.vectors = laid.vectors  # type: ignore[attr-defined]
    if sheet is not None:  # a handout page: the title block states the scales, the table T₁₂
        return drawing
    mech = fs.mechanism
    line = laid.scales
    if upto is None:
        bits = []
        for lid, (what, val) in fs.drives.items():
            if what == "torque":
                sense = fs.sense(val)
                bits.append(f"T{'1' + lid}".translate(_SUB) + f" = {fmt(abs(val), 4)} "
                            f"{mech.force_unit}·{mech.length_unit} {sense}")
            else:
                bits.append(f"input force on {lid} = {fmt(val, 4)} {mech.force_unit}")
        line += ("   " + ";  ".join(bits)) if bits else ""
    W, H = laid.sheet.size
    left, top = (0.0, H)
    assert drawing.figure is not None
    with rc_context():
        st = drawing.figure.text((left + 0.12) / W, (top - 0.22 - SCALES_H) / H, line,
                                 fontsize=SMALL_PT + 1, ha="left", va="center")
    st.set_gid("force-scale")
    drawing.texts["force-scale"] = st
    return drawing


def forces_frames(obj: Any) -> list[tuple[Any, str]]:
    """One drawing per step of the force construction: (step, SVG text).

    Raises
    ------
    DiagramUnavailable
        No loads and no masses, or the forces were solved by the matrix method.
    """
    from graphkin.forces.report import forces_report
    from graphkin.render.sources import DiagramUnavailable
    from graphkin.render.svg import to_svg

    sol = obj.solve() if hasattr(obj, "pins") else obj
    fs = forces_report(sol)
    if fs is None or fs.construction is None:
        why = ("the file has no [[loads]] and no [inertia.N]" if fs is None else
               "the forces were solved by the matrix method (no graphic order)")
        raise DiagramUnavailable(f"no force construction: {why}", diagram="forces")
    out = []
    for k, step in enumerate(fs.construction):
        d = draw_forces(fs, upto=k)
        out.append((step, to_svg(d.figure)))
    return out


def forces_steps_html(obj: Any, title: str | None = None) -> str:
    """The force construction step by step as one self-contained HTML page.

    Each step: its number, the vector equation with its ✓/? marks, one
    sentence in the book's words, and the drawing with what the construction
    has found so far (the newest step in the highlight colour).  Previous/next
    buttons and the arrow keys walk through it.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 11.6-11.8, 12.5.
    """
    import html

    frames = forces_frames(obj)
    sol = obj.solve() if hasattr(obj, "pins") else obj
    head = html.escape(title or sol.mechanism.title or sol.mechanism.source)
    parts = []
    n = len(frames)
    for k, (step, svg) in enumerate(frames):
        eq = "" if step.equation is None else \
            f"<p class='eq'>{html.escape(str(step.equation))}</p>"
        parts.append(frame_section(k, n, step.label, f"{eq}<p>{html.escape(step.note)}</p>",
                                   svg))
    script = PAGER_JS
    return ("<!DOCTYPE html><html><head><meta charset='utf-8'>"
            f"<title>Forces: {head}</title><style>body{{font-family:sans-serif;margin:1em}}"
            ".eq{font-family:monospace}.fig svg{max-width:100%;height:auto}</style></head>"
            f"<body><h1>Force analysis: {head}</h1><p><button id='prev'>◀ previous</button> "
            "<button id='next'>next ▶</button> (or the arrow keys)</p>"
            + "".join(parts) + f"<script>{script}</script></body></html>\n")
