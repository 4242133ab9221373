"""The teaching page: one self-contained HTML file that walks through a construction step by step.

The construction's steps are told as the book works its examples
(:mod:`graphkin.render.narrate`): each step of the page has a title in words,
the vector equation with the ✓/? marks over each vector (its left side
included), what is drawn and why, the numbers, the book's section, and the
drawing up to that step with the step's own elements in colour.
Previous/next buttons and the arrow keys move through the steps; the
numbers to be found hide behind a "Show answers" toggle; printing gives every
step; without JavaScript every step is shown.  The page needs no network: the
drawings are inline SVG, the script and style inline.

Each frame's SVG ids are prefixed (``f07-step-07-C``) so that the frames can
live in one document; a page step is a ``<section data-step="k">`` whose
``data-steps`` lists the construction steps it covers.  ``window.graphkinSteps``
(``show(k)``, ``count``, ``current()``) lets a browser test drive the page;
opening it with ``#selftest`` presses "next" through every step and the left
arrow back, and writes what it saw into ``<pre id="selftest-result">``.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Eq. 2.16 and the ✓/? marks of
Table 2.2), Sec. 3.4 and Sec. 4.3 (the polygons built step by step).
"""

from __future__ import annotations

import html
import re
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from dataclasses import replace
from pathlib import Path
from typing import Any

from graphkin.construction import Construction, Step, Term, VectorEquation
from graphkin.render.narrate import PageStep, answer_html, helper_steps, narrate, vector_html
from graphkin.render.sources import (
    CURVATURE_PANELS,
    DIAGRAMS,
    DiagramUnavailable,
    as_source,
    optional_modules,
    split_curvature,
)

PANEL_NAMES = {"inflection": "inflection and Bresse circles",
               "bobillier": "inflection circle by Bobillier's construction",
               "hartmann": "conjugate points", "cubic": "cubic of stationary curvature"}
"""The curvature figures as a page's title names them."""

__all__ = ["steps_html", "step_frames", "write_frames", "equation_html", "page_frames",
           "sides_html", "FRAME_INCHES", "PAGE_DIAGRAMS"]

_ID = re.compile(r'(\bid=")([^"]+)(")')
_URL = re.compile(r"url\(#([^)]+)\)")
_HREF = re.compile(r'((?:xlink:)?href=")#([^"]+)(")')


def _prefix_ids(svg: str, prefix: str) -> str:
    """Prefix every id of an SVG document and every reference to one."""
    svg = _ID.sub(lambda m: f"{m.group(1)}{prefix}{m.group(2)}{m.group(3)}", svg)
    svg = _URL.sub(lambda m: f"url(#{prefix}{m.group(1)})", svg)
    return _HREF.sub(lambda m: f"{m.group(1)}#{prefix}{m.group(2)}{m.group(3)}", svg)


def _inline(svg: str) -> str:
    """An SVG document as an element to put inside HTML (no XML declaration or DOCTYPE)."""
    start = svg.find("<svg")
    svg = svg[start:] if start >= 0 else svg
    return svg.replace("<svg ", '<svg preserveAspectRatio="xMidYMin meet" ', 1)


def _term_html(t: Term) -> str:
    marks = f"{t.magnitude}{t.direction}"
    return (f'<span class="term"><span class="marks" title="magnitude, direction">'
            f"{html.escape(marks)}</span><span class=\"vec\">{vector_html(t.name)}</span></span>")


def _side_html(terms: tuple[Term, ...]) -> str:
    """One side of a vector equation in HTML, each term with its sign and ✓/? marks."""
    parts = []
    for i, t in enumerate(terms):
        if i == 0:
            op = "−&nbsp;" if t.sign < 0 else ""
        else:
            op = '<span class="op">−</span>' if t.sign < 0 else '<span class="op">+</span>'
        parts.append(op + _term_html(t))
    return "".join(parts)


def equation_html(eq: VectorEquation) -> str:
    """A vector equation in HTML, each vector with its two marks above it (✓ known, ? unknown).

    Examples
    --------
    >>> from graphkin.construction import Mark
    >>> eq = VectorEquation((Term("V_C", Mark.UNKNOWN, Mark.UNKNOWN),),
    ...                     (Term("V_B"), Term("V_CB", Mark.UNKNOWN, Mark.KNOWN)), case=3)
    >>> s = equation_html(eq)
    >>> "V</i><sub>CB</sub>" in s and "?✓" in s and "case 3" in s
    True

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Eq. 2.16).
    """
    case = f' <span class="case">(case {eq.case})</span>' if eq.case else ""
    return (f'<div class="equation">{_side_html(eq.lhs)}<span class="op">=</span>'
            f"{_side_html(eq.rhs)}{case}</div>")


PAGE_DIAGRAMS = (*DIAGRAMS, *CURVATURE_PANELS)
"""What a teaching page can walk through: a diagram, or one figure of the curvature sheet
(``inflection``, ``bobillier``, ``hartmann``, ``cubic``; Figs. 4.25-4.39)."""


def _construction(obj: Any, diagram: str, link: str | None) -> tuple[Any, Construction]:
    if diagram in CURVATURE_PANELS:
        return _panel(obj, diagram, link)
    if diagram not in DIAGRAMS:
        raise DiagramUnavailable("a teaching page shows one diagram; valid: "
                                 f"{', '.join(PAGE_DIAGRAMS)}", diagram=diagram)
    wanted = (diagram,) if diagram in optional_modules else ()
    src = as_source(obj, diagrams=wanted, link=link)
    cx = src.construction(diagram)
    if cx is None or not len(cx):
        raise DiagramUnavailable(f"no {diagram} construction to walk through (the mechanism "
                                 "was solved analytically)", diagram=diagram)
    return src, cx


def _panel(obj: Any, diagram: str, link: str | None) -> tuple[Any, Construction]:
    """One figure of the curvature sheet: its source and its steps (a ``StepSubset``)."""
    src = as_source(obj, diagrams=("curvature",), link=link)
    cx = src.construction("curvature")  # raises DiagramUnavailable when there is none
    if cx is None or not len(cx):
        raise DiagramUnavailable("no curvature construction to walk through (the mechanism "
                                 "was solved analytically)", diagram=diagram)
    subs = split_curvature(src)
    if diagram not in subs:
        why = "; the link turns about a frame pivot" if not subs else ""
        raise DiagramUnavailable(f"no {diagram} figure for this link's curvature (the "
                                 f"construction did not use it{why}); steps --diagram curvature",
                                 diagram=diagram)
    return src, src.constructions[diagram]


def step_frames(obj: Any, diagram: str = "posture", *, link: str | None = None,
                max_inches: float = 4.2) -> list[tuple[Step, str]]:
    """The drawing after each step, newest step highlighted: ``[(step, svg text), ...]``.

    Parameters
    ----------
    obj : Mechanism, Solution or Construction
    diagram : str
    link : str, optional
        The link of a curvature construction.
    max_inches : float
        The largest side of a panel.
    """
    from graphkin.render.mpl import render_sheet
    from graphkin.render.sheet import build_sheet
    from graphkin.render.svg import to_svg

    src, cx = _construction(obj, diagram, link)
    frames = []
    for step in cx.steps:
        sheet = build_sheet(src, diagram, upto=step.index, highlight=step.index, table=False,
                            legend=False, max_inches=max_inches, title="")
        d = render_sheet(sheet)
        assert d.figure is not None
        frames.append((step, to_svg(d.figure)))
    return frames


def write_frames(obj: Any, diagram: str, directory: str | Path, *,
                 link: str | None = None) -> list[Path]:
    """Write one numbered SVG per step (``step-00.svg``, ...) into ``directory``."""
    out = Path(directory)
    out.mkdir(parents=True, exist_ok=True)
    frames = step_frames(obj, diagram, link=link)
    width = max(2, len(str(len(frames) - 1)))
    paths = []
    for step, svg in frames:
        p = out / f"step-{step.index:0{width}d}.svg"
        p.write_text(svg, encoding="utf-8")
        paths.append(p)
    return paths


FRAME_INCHES = 3.3
"""The largest side of a panel on a teaching page: small enough that the labels, scaled
with the drawing to the window, read at 14 px or more on a 1300 px screen."""


def _scale_of(src: Any, diagram: str, max_inches: float) -> Any:
    """The scale the diagram's construction is drawn at on the page (None for bare ones)."""
    from graphkin.render.sheet import build_sheet
    from graphkin.render.sources import plane_of

    try:
        sheet = build_sheet(src, diagram, table=False, legend=False, max_inches=max_inches,
                            title="")
        name = diagram if plane_of(diagram) != "posture" else sheet.panels[0].name
        return sheet.panel(name).scale
    except (KeyError, IndexError):
        return None


SMALLEST_PT = 8.0
"""The smallest text on a teaching page's drawings (points): the secondary labels
(components, rates, the scale) are raised to it so that they read at 14 px or more
when the drawing fills a 1300 px window."""


@contextmanager
def _classroom_type() -> Iterator[None]:
    """Raise the drawings' secondary text to :data:`SMALLEST_PT` while frames are made."""
    from graphkin.render.style import STYLES

    saved = {k: dict(v) for k, v in STYLES.items() if "size" in v}
    try:
        for v in STYLES.values():
            if "size" in v and v["size"] < SMALLEST_PT:
                v["size"] = SMALLEST_PT
        yield
    finally:
        for k, v in saved.items():
            STYLES[k].clear()
            STYLES[k].update(v)


def page_frames(src: Any, diagram: str, steps: list[PageStep], *,
                max_inches: float = FRAME_INCHES,
                progress: Callable[[float], None] | None = None) -> list[str]:
    """The drawing after each page step, its own construction steps highlighted (SVG texts).

    ``progress`` is told the fraction of the drawings made (a progress bar's callback).
    """
    from graphkin.render.mpl import render_sheet
    from graphkin.render.sheet import build_sheet
    from graphkin.render.svg import to_svg

    # the steps of helper points are drawn no more than told: a source without them
    skip = helper_steps(src, diagram)
    if skip:
        kept = [s for s in src.constructions[diagram].steps if s.index not in skip]
        src = replace(src, constructions={**src.constructions,
                                          diagram: Construction(kept,
                                                                src.constructions[diagram].title)})
    # a curvature page draws each step on its own figure only ((a) to (d), Figs. 4.25-4.39),
    # a size larger: four figures a step made the figure hard to follow, and slow
    owner: dict[int, str] = {}
    if diagram == "curvature":
        for name in split_curvature(src):
            for i in getattr(src.constructions[name], "own", ()):
                owner[i] = name
    out = []
    with _classroom_type():
        for ps in steps:
            fig = next((owner[i] for i in (ps.main, *ps.steps) if i in owner), diagram)
            # the painter draws the steps numbered up to ps.main (steps keep their numbers)
            sheet = build_sheet(src, fig, upto=ps.main, highlight=set(ps.steps),
                                table=False, legend=False, title="",
                                max_inches=max_inches * (1.6 if fig != diagram else 1.0))
            d = render_sheet(sheet)
            assert d.figure is not None
            out.append(to_svg(d.figure))
            if progress is not None:
                progress(len(out) / len(steps))
    return out


def sides_html(steps: PageStep) -> str:
    """The equation of a page step in HTML: every vector with its ✓/? marks, sides joined by =.

    Examples
    --------
    >>> from graphkin.construction import Mark
    >>> ps = PageStep("t", [(Term("V_C", Mark.UNKNOWN, Mark.UNKNOWN),),
    ...                     (Term("V_B"), Term("V_CB", Mark.UNKNOWN, Mark.KNOWN))], case=3)
    >>> s = sides_html(ps)
    >>> "V</i><sub>C</sub>" in s and "??" in s and "?✓" in s and "case 3" in s
    True
    """
    if not steps.sides:
        if steps.formula:
            return f'<div class="equation formula">{answer_html(steps.formula)}</div>'
        return ""
    parts = [_side_html(side) for side in steps.sides]
    case = f' <span class="case">(case {steps.case})</span>' if steps.case else ""
    return ('<div class="equation">' + '<span class="op">=</span>'.join(parts) + case + "</div>")


_CSS = """
:root { --ink: #111; --muted: #555; --accent: #c62828; --rule: #ddd; --nav: 48px; }
* { box-sizing: border-box; }
html, body { margin: 0; }
body { font: 16px/1.4 "DejaVu Sans", Verdana, sans-serif; color: var(--ink); background: #fafafa; }
nav { display: flex; align-items: center; gap: 8px; padding: 6px 14px; background: #fff;
      border-bottom: 1px solid var(--rule); position: sticky; top: 0; z-index: 2;
      height: var(--nav); flex-wrap: nowrap; overflow: hidden; }
nav h1 { font-size: 15px; margin: 0 12px 0 0; flex: 1 1 auto; overflow: hidden;
         text-overflow: ellipsis; white-space: nowrap; max-width: 40vw; }
nav button { font: inherit; font-size: 15px; padding: 3px 12px; border: 1px solid #999;
             border-radius: 4px; background: #fff; cursor: pointer; }
nav button:disabled { opacity: 0.4; cursor: default; }
nav button[aria-pressed="true"] { background: #333; color: #fff; }
#counter { color: var(--muted); min-width: 7.5em; text-align: center; }
.keys { font-size: 12px; color: var(--muted); }
.nojs-note { font-size: 13px; color: var(--muted); padding: 6px 14px; margin: 0; }
.js .nojs-note { display: none; }
main { padding: 8px 14px 6px; }
section.step { background: #fff; border: 1px solid var(--rule); border-radius: 6px;
               padding: 10px 14px; margin-bottom: 14px; display: grid;
               grid-template-columns: minmax(290px, 34%) 1fr; gap: 4px 18px;
               align-items: start; }
.js section.step { display: none; margin-bottom: 0; }
.js section.step.current { display: grid; height: calc(100vh - var(--nav) - 16px); }
section.step h2 { font-size: 19px; line-height: 1.3; margin: 0 0 6px; }
section.step h2 .count { display: block; font-size: 13px; font-weight: normal;
                         color: var(--muted); }
.text { overflow: auto; max-height: 100%; }
.text p { margin: 6px 0; }
.numbers { margin: 6px 0; padding-left: 1.1em; }
.numbers li { margin: 3px 0; }
.refs { color: var(--muted); font-size: 13px; }
.equation { font-size: 19px; margin: 4px 0 6px; line-height: 2.3; }
.equation.formula { line-height: 1.5; font-style: italic; }
.term { display: inline-flex; flex-direction: column; align-items: center;
        vertical-align: middle; margin: 0 1px; }
.term .marks { font-size: 13px; line-height: 1; color: var(--accent); letter-spacing: 1px; }
.term .vec { line-height: 1.1; }
.op { margin: 0 6px; }
.case { font-size: 13px; color: var(--muted); }
sub, sup { font-size: 70%; }
.drawing { margin: 0; height: 100%; min-height: 0; display: flex; align-items: flex-start;
           justify-content: center; }
.drawing svg { width: 100%; height: auto; }
.js .drawing svg { height: 100%; max-height: calc(100vh - var(--nav) - 40px); }
.answer { border-bottom: 1px dotted #999; }
.hide-answers .answer { background: #eee; border-radius: 3px; border-bottom: none; }
.hide-answers .answer .val { visibility: hidden; }
table.results { border-collapse: collapse; font-size: 14px; margin-top: 8px; }
table.results td, table.results th { padding: 2px 10px; border-bottom: 1px solid var(--rule);
                                     text-align: left; }
section.step.wide { grid-template-columns: 1fr; }
.js section.step.wide.current { grid-template-rows: auto minmax(0, 1fr); }
.wide .text h2 { margin-bottom: 2px; }
.wide .numbers { columns: 2; column-gap: 24px; }
.wide .numbers li { break-inside: avoid; }
section.results { display: block; }
.js section.results.current { display: block; height: auto; }
@media (max-width: 1150px) { .keys { display: none; } nav h1 { max-width: 32vw; } }
@media (max-width: 820px) {
  section.step, .js section.step.current { grid-template-columns: 1fr; height: auto; }
  .js .drawing svg { height: auto; }
}
@media print {
  nav, .nojs-note { display: none !important; }
  body { background: #fff; font-size: 12pt; }
  main { padding: 0; }
  section.step, .js section.step, .js section.step.current {
    display: grid !important; height: auto; break-inside: avoid; page-break-inside: avoid;
    border: none; border-bottom: 1px solid #999; border-radius: 0; margin: 0 0 6mm;
    grid-template-columns: 36% 1fr; }
  section.results, .js section.results { display: block !important; }
  .drawing svg, .js .drawing svg { width: 100%; height: auto; max-height: 10.5cm; }
  .text { overflow: visible; max-height: none; }
}
"""

_JS = """
(function () {
  var errors = [];
  window.addEventListener('error', function (e) { errors.push(String(e.message)); });
  var root = document.documentElement;
  root.classList.add('js');
  var steps = Array.prototype.slice.call(document.querySelectorAll('main > section'));
  var prev = document.getElementById('prev'), next = document.getElementById('next');
  var counter = document.getElementById('counter');
  var answers = document.getElementById('answers');
  var current = 0;
  function setAnswers(show) {
    document.body.classList.toggle('hide-answers', !show);
    answers.setAttribute('aria-pressed', show ? 'true' : 'false');
    answers.textContent = show ? 'Hide answers' : 'Show answers';
  }
  setAnswers(false);
  answers.addEventListener('click', function () {
    setAnswers(document.body.classList.contains('hide-answers'));
  });
  function show(k) {
    k = Math.max(0, Math.min(steps.length - 1, k));
    steps.forEach(function (s, i) { s.classList.toggle('current', i === k); });
    current = k;
    window.scrollTo(0, 0);
    counter.textContent = 'Step ' + (k + 1) + ' of ' + steps.length;
    prev.disabled = (k === 0);
    next.disabled = (k === steps.length - 1);
    document.body.setAttribute('data-current', steps[k].getAttribute('data-step'));
    if (location.hash !== '#selftest' && steps[k].id) {
      history.replaceState(null, '', '#' + steps[k].id);
    }
  }
  prev.addEventListener('click', function () { show(current - 1); });
  next.addEventListener('click', function () { show(current + 1); });
  document.addEventListener('keydown', function (e) {
    if (e.key === 'ArrowRight' || e.key === 'PageDown' || e.key === ' ') {
      show(current + 1); e.preventDefault();
    } else if (e.key === 'ArrowLeft' || e.key === 'PageUp') {
      show(current - 1); e.preventDefault();
    }
    else if (e.key === 'Home') { show(0); }
    else if (e.key === 'End') { show(steps.length - 1); }
    else if (e.key === 'a' || e.key === 'A') { answers.click(); }
  });
  var start = 0;
  var m = /^#(.+)$/.exec(location.hash);
  if (m) { steps.forEach(function (s, i) { if (s.id === m[1]) { start = i; } }); }
  show(start);
  window.graphkinSteps = {show: show, count: steps.length, errors: errors,
                          current: function () { return current; }};
  if (location.hash === '#selftest') {
    var visible = function () {
      var v = steps.filter(function (s) { return getComputedStyle(s).display !== 'none'; });
      return v.length === 1 ? steps.indexOf(v[0]) : -1;
    };
    show(0);
    var forward = [visible()];
    for (var i = 1; i < steps.length; i++) { next.click(); forward.push(visible()); }
    var back = [];
    for (var j = 1; j < steps.length; j++) {
      document.dispatchEvent(new KeyboardEvent('keydown', {key: 'ArrowLeft'}));
      back.push(visible());
    }
    var out = document.createElement('pre');
    out.id = 'selftest-result';
    out.textContent = JSON.stringify({steps: steps.length, forward: forward, back: back,
                                      prevDisabled: prev.disabled, errors: errors});
    document.body.appendChild(out);
  }
})();
"""


WIDE = 1.45
"""A drawing this many times wider than tall goes under the text, across the page."""


def _answer_css(labels: set[str]) -> str:
    """Rules that hide the values of found angular rates printed in the drawings."""
    from graphkin.render.scene import safe_id

    sel = [f'.hide-answers [id$="label-{safe_id(lab)}"]' for lab in sorted(labels)]
    return (",\n".join(sel) + " { visibility: hidden; }\n") if sel else ""


def _step_section(ps: PageStep, k: int, n: int, svg: str) -> str:
    eq = sides_html(ps)
    nums = "".join(f"<li>{answer_html(x)}</li>" for x in ps.numbers)
    nums = f'<ul class="numbers">{nums}</ul>' if nums else ""
    refs = f'<p class="refs">{html.escape(ps.refs)}</p>' if ps.refs else ""
    steps = " ".join(str(i) for i in ps.steps)
    m = re.search(r'viewBox="[-\d.]+ [-\d.]+ ([\d.]+) ([\d.]+)"', svg)
    wide = m is not None and float(m.group(1)) >= WIDE * float(m.group(2))
    return (f'<section class="step{" wide" if wide else ""}" id="step-{k + 1}" data-step="{k}" '
            f'data-steps="{steps}" data-vector="{"1" if ps.vector else "0"}">\n'
            f'<div class="text"><h2><span class="count">Step {k + 1} of {n}</span>'
            f"{answer_html(ps.title)}</h2>\n{eq}\n<p class=\"what\">{answer_html(ps.text)}</p>\n"
            f"{nums}\n{refs}</div>\n"
            f'<figure class="drawing">{_inline(_prefix_ids(svg, f"f{k:02d}-"))}</figure>\n'
            "</section>")


def steps_html(obj: Any, diagram: str = "posture", *, link: str | None = None,
               title: str | None = None, max_inches: float = FRAME_INCHES,
               progress: Callable[[float], None] | None = None) -> str:
    """The teaching page of a construction, as one self-contained HTML document.

    Every step has a title in words, the vector equation it solves or uses
    with the ✓/? marks over each vector (its left side included), what is drawn
    and why, the numbers (the known magnitude computed, its length on the
    drawing at the scale, the result read off), the book's section, and the
    drawing up to that step with the step's own elements in colour.  Helper
    points (those that only define a slider's line or a slot) get no step.

    The page works in a classroom: the drawing scales to the window (a
    projector at 1024×768 shows a whole step without scrolling), the numbers to
    be found hide behind a "Show answers" toggle (key ``A``), printing gives
    every step in order, and without JavaScript every step is shown, one
    under the other.  No network is needed.

    Parameters
    ----------
    obj : Mechanism, Solution or Construction
    diagram : str
        ``posture``, ``velocity``, ``acceleration``, ``centers`` or ``curvature``;
        or one figure of the curvature sheet, ``inflection`` (the inflection and
        Bresse circles, Γ), ``bobillier`` (the inflection circle by Bobillier's
        theorem), ``hartmann`` (conjugate points) or ``cubic`` (the cubic of
        stationary curvature and Ball's point).
    link : str, optional
        The link of a curvature construction.
    title : str, optional
    max_inches : float
        The largest side of a panel of the drawings.
    progress : callable, optional
        Told the fraction of the step drawings made (``graphkin steps`` shows a bar).

    Returns
    -------
    str
        HTML with one ``<section class="step" data-step="k">`` per step.

    Raises
    ------
    DiagramUnavailable
        The diagram has no construction for this object (or, for a figure of the
        curvature sheet, this link's curvature does not use it).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, 3.4-3.7, 4.3-4.7, 4.12-4.17.
    """
    src, cx = _construction(obj, diagram, link)
    scale = _scale_of(src, diagram, max_inches)
    told = narrate(src, diagram, scale)
    svgs = page_frames(src, diagram, told, max_inches=max_inches, progress=progress)
    mech = src.mechanism
    name = title or (mech.title if mech is not None and mech.title else cx.title or diagram)
    results = _results_html(src, diagram)
    n = len(told) + (1 if results else 0)
    parts = [_step_section(ps, k, n, svg) for k, (ps, svg) in enumerate(zip(told, svgs))]
    if results:
        parts.append(f'<section class="step results" id="results" data-step="{len(told)}">\n'
                     f'<h2><span class="count">Step {n} of {n}</span>The results</h2>\n'
                     f"{results}</section>")
    answers = {lab for ps in told for lab in ps.answers}
    what = {"velocity": "velocity polygon", "acceleration": "acceleration polygon",
            "posture": "posture", "centers": "instant centers",
            "curvature": "curvature", **PANEL_NAMES}.get(diagram, diagram)
    body = "\n".join(parts)
    return (
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        f"<title>{html.escape(name)}: the {html.escape(what)}, step by step</title>\n"
        f"<style>{_CSS}{_answer_css(answers)}</style>\n</head>\n<body>\n"
        f'<nav><h1 title="{html.escape(name)}">{html.escape(name)}: the '
        f"{html.escape(what)}</h1>"
        '<button id="prev" type="button">◀ Previous</button>'
        '<span id="counter"></span>'
        '<button id="next" type="button">Next ▶</button>'
        '<button id="answers" type="button" aria-pressed="true">Hide answers</button>'
        '<span class="keys">← → keys · A answers</span></nav>\n'
        f'<p class="nojs-note">{n} steps, one under the other. ✓ known, ? unknown: '
        "magnitude first, then direction (Uicker, Pennock &amp; Shigley, Sec. 2.8).</p>\n"
        f"<main>\n{body}\n</main>\n<script>{_JS}</script>\n</body>\n</html>\n")


def _results_html(src: Any, diagram: str) -> str:
    """The results table (drawn and analytic values) after the last step."""
    from graphkin.render.results import diff_text, result_rows

    if src.solution is None:
        return ""
    rows = result_rows(src, ["curvature" if diagram in CURVATURE_PANELS else diagram])
    if not rows:
        return ""
    def ans(text: str) -> str:
        return f'<span class="answer"><span class="val">{html.escape(text)}</span></span>'

    cells = "".join(
        f"<tr><td>{html.escape(r.quantity)}</td><td>{ans(r.drawn)}</td>"
        f"<td>{ans(r.exact)}</td>"
        f"<td>{diff_text(r.diff)}</td><td>{html.escape(r.unit)}</td>"
        "</tr>" for r in rows)
    return ('<table class="results"><caption>Read off the construction, and the analytic '
            "solution</caption><tr><th>quantity</th><th>drawn</th><th>analytic</th>"
            f"<th>rel. diff.</th><th>unit</th></tr>{cells}</table>")
