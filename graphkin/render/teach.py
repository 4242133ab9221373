"""The teaching page: one self-contained HTML file that walks through a construction step by step.

For every step the page shows the vector equation it solves with the book's
✓/? marks over each vector, the one sentence that says what the draftsman
does, and the drawing up to that step with the new elements in colour.
Previous/next buttons and the arrow keys move through the steps.  The page
needs no network: the drawings are inline SVG, the script and style inline.

Each frame's SVG ids are prefixed (``f07-step-07-C``) so that the frames can
live in one document; the frame itself is a ``<section data-step="7">``.
Opening the page with ``#selftest`` runs a small self-test: it presses
"next" through every step and the left arrow back, and writes what it saw
into ``<pre id="selftest-result">`` (used by the tests, in a headless browser).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Eq. 2.16 and the ✓/? marks of
Table 2.2), Sec. 3.4 and Sec. 4.3 (the polygons built step by step).
"""

from __future__ import annotations

import html
import re
from pathlib import Path
from typing import Any

from graphkin.construction import Construction, Step, Term, VectorEquation
from graphkin.render.sources import DIAGRAMS, DiagramUnavailable, as_source, optional_modules

__all__ = ["steps_html", "step_frames", "write_frames", "equation_html"]

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
    return svg[start:] if start >= 0 else svg


def _vec_html(name: str) -> str:
    base, _, rest = name.partition("_")
    sub, _, sup = rest.partition("^")
    out = html.escape(base)
    if sup:
        out += f"<sup>{html.escape(sup)}</sup>"
    if sub:
        out += f"<sub>{html.escape(sub)}</sub>"
    return out


def _term_html(t: Term) -> str:
    marks = f"{t.magnitude}{t.direction}"
    return (f'<span class="term"><span class="marks" title="magnitude, direction">'
            f"{html.escape(marks)}</span><span class=\"vec\">{_vec_html(t.name)}</span></span>")


def equation_html(eq: VectorEquation) -> str:
    """A vector equation in HTML, each vector with its two marks above it (✓ known, ? unknown).

    Examples
    --------
    >>> from graphkin.construction import Mark
    >>> eq = VectorEquation((Term("V_C", Mark.UNKNOWN, Mark.UNKNOWN),),
    ...                     (Term("V_B"), Term("V_CB", Mark.UNKNOWN, Mark.KNOWN)), case=3)
    >>> s = equation_html(eq)
    >>> "V<sub>CB</sub>" in s and "?✓" in s and "case 3" in s
    True

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Eq. 2.16).
    """

    def side(terms: tuple[Term, ...]) -> str:
        parts = []
        for i, t in enumerate(terms):
            if i == 0:
                op = "−&nbsp;" if t.sign < 0 else ""
            else:
                op = '<span class="op">−</span>' if t.sign < 0 else '<span class="op">+</span>'
            parts.append(op + _term_html(t))
        return "".join(parts)

    case = f' <span class="case">(case {eq.case})</span>' if eq.case else ""
    return (f'<div class="equation">{side(eq.lhs)}<span class="op">=</span>'
            f"{side(eq.rhs)}{case}</div>")


def _construction(obj: Any, diagram: str, link: str | None) -> tuple[Any, Construction]:
    if diagram not in DIAGRAMS:
        raise DiagramUnavailable(f"a teaching page shows one diagram; valid: {', '.join(DIAGRAMS)}",
                                 diagram=diagram)
    wanted = (diagram,) if diagram in optional_modules else ()
    src = as_source(obj, diagrams=wanted, link=link)
    cx = src.construction(diagram)
    if cx is None or not len(cx):
        raise DiagramUnavailable(f"no {diagram} construction to walk through (the mechanism "
                                 "was solved analytically)", diagram=diagram)
    return src, cx


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
                            max_inches=max_inches, title="")
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


_CSS = """
:root { --ink: #111; --muted: #666; --accent: #c62828; --rule: #ddd; }
* { box-sizing: border-box; }
body { margin: 0; font: 15px/1.45 "DejaVu Sans", Verdana, sans-serif; color: var(--ink);
       background: #fafafa; }
header { padding: 12px 20px; background: #fff; border-bottom: 1px solid var(--rule); }
header h1 { font-size: 18px; margin: 0 0 4px; }
header p { margin: 0; color: var(--muted); font-size: 13px; }
nav { display: flex; align-items: center; gap: 10px; padding: 10px 20px; background: #fff;
      border-bottom: 1px solid var(--rule); position: sticky; top: 0; z-index: 2; }
nav button { font: inherit; padding: 4px 14px; border: 1px solid #999; border-radius: 4px;
             background: #fff; cursor: pointer; }
nav button:disabled { opacity: 0.4; cursor: default; }
#counter { color: var(--muted); min-width: 9em; }
main { padding: 12px 20px 40px; }
section.step { background: #fff; border: 1px solid var(--rule); border-radius: 6px;
               padding: 14px 18px; }
section.step[hidden] { display: none; }
section.step h2 { font-size: 16px; margin: 0 0 6px; }
section.step h2 .label { color: var(--accent); }
.meta { color: var(--muted); font-size: 12px; margin-bottom: 8px; }
.note { margin: 8px 0 10px; }
.equation { font-size: 18px; margin: 10px 0 4px; line-height: 2.4; }
.term { display: inline-flex; flex-direction: column; align-items: center;
        vertical-align: middle; margin: 0 2px; }
.term .marks { font-size: 12px; line-height: 1; color: var(--accent); letter-spacing: 1px; }
.term .vec { font-style: italic; line-height: 1.1; }
.op { margin: 0 8px; }
.case { font-size: 13px; color: var(--muted); }
.drawing svg { max-width: 100%; height: auto; }
table.results { border-collapse: collapse; font-size: 13px; margin-top: 12px; }
table.results td, table.results th { padding: 2px 10px; border-bottom: 1px solid var(--rule);
                                     text-align: left; }
.keys { font-size: 12px; color: var(--muted); margin-left: auto; }
"""

_JS = """
(function () {
  var errors = [];
  window.addEventListener('error', function (e) { errors.push(String(e.message)); });
  var steps = Array.prototype.slice.call(document.querySelectorAll('section.step'));
  var prev = document.getElementById('prev'), next = document.getElementById('next');
  var counter = document.getElementById('counter');
  var current = 0;
  function show(k) {
    k = Math.max(0, Math.min(steps.length - 1, k));
    steps.forEach(function (s, i) { s.hidden = (i !== k); });
    current = k;
    counter.textContent = 'Step ' + (k + 1) + ' of ' + steps.length;
    prev.disabled = (k === 0);
    next.disabled = (k === steps.length - 1);
    document.body.setAttribute('data-current', steps[k].getAttribute('data-step'));
    if (location.hash !== '#selftest') {
      history.replaceState(null, '', '#step-' + steps[k].getAttribute('data-step'));
    }
  }
  prev.addEventListener('click', function () { show(current - 1); });
  next.addEventListener('click', function () { show(current + 1); });
  document.addEventListener('keydown', function (e) {
    if (e.key === 'ArrowRight' || e.key === 'PageDown') { show(current + 1); e.preventDefault(); }
    else if (e.key === 'ArrowLeft' || e.key === 'PageUp') { show(current - 1); e.preventDefault(); }
    else if (e.key === 'Home') { show(0); }
    else if (e.key === 'End') { show(steps.length - 1); }
  });
  var start = 0;
  var m = /^#step-(\\d+)$/.exec(location.hash);
  if (m) {
    steps.forEach(function (s, i) { if (s.getAttribute('data-step') === m[1]) { start = i; } });
  }
  show(start);
  if (location.hash === '#selftest') {
    var visible = function () {
      var v = steps.filter(function (s) { return !s.hidden; });
      return v.length === 1 ? Number(v[0].getAttribute('data-step')) : -1;
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


def steps_html(obj: Any, diagram: str = "posture", *, link: str | None = None,
               title: str | None = None) -> str:
    """The teaching page of a construction, as one self-contained HTML document.

    Parameters
    ----------
    obj : Mechanism, Solution or Construction
    diagram : str
        ``posture``, ``velocity``, ``acceleration``, ``centers`` or ``curvature``.
    link : str, optional
        The link of a curvature construction.
    title : str, optional

    Returns
    -------
    str
        HTML with one ``<section class="step" data-step="k">`` per step.

    Raises
    ------
    DiagramUnavailable
        The diagram has no construction for this object.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, 3.4, 4.3.
    """
    src, cx = _construction(obj, diagram, link)
    frames = step_frames(obj if src.solution is None else src.solution, diagram, link=link)
    mech = src.mechanism
    name = title or (mech.title if mech is not None and mech.title else cx.title or diagram)
    width = max(2, len(str(len(frames) - 1)))
    parts = []
    n = len(frames)
    for step, svg in frames:
        fid = f"f{step.index:0{width}d}-"
        eq = equation_html(step.equation) if step.equation is not None else ""
        note = html.escape(step.note) if step.note else ""
        meta = (f"{html.escape(step.op)} · {html.escape(str(step.role))}"
                + (f" · branch {html.escape(step.branch)}" if step.branch else ""))
        extra = _results_html(src, diagram) if step.index == frames[-1][0].index else ""
        parts.append(
            f'<section class="step" id="step-{step.index}" data-step="{step.index}" '
            f'data-step-id="{html.escape(step.step_id)}" data-label="{html.escape(step.label)}"'
            f'{" hidden" if step.index != frames[0][0].index else ""}>\n'
            f'<h2>Step {step.index + 1} of {n}: <span class="label">'
            f"{html.escape(step.label)}</span></h2>\n"
            f'<div class="meta">{meta}</div>\n{eq}\n<p class="note">{note}</p>\n'
            f'<div class="drawing">{_inline(_prefix_ids(svg, fid))}</div>\n{extra}</section>')
    body = "\n".join(parts)
    return (
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        f"<title>{html.escape(name)}: {html.escape(diagram)}, step by step</title>\n"
        f"<style>{_CSS}</style>\n</head>\n<body>\n"
        f"<header><h1>{html.escape(name)}</h1><p>The {html.escape(diagram)} construction, "
        f"step by step ({n} steps). ✓ known, ? unknown: magnitude first, then direction "
        "(Uicker, Pennock &amp; Shigley, Sec. 2.8).</p></header>\n"
        '<nav><button id="prev" type="button">◀ Previous</button>'
        '<span id="counter"></span>'
        '<button id="next" type="button">Next ▶</button>'
        '<span class="keys">← → keys, Home, End</span></nav>\n'
        f"<main>\n{body}\n</main>\n<script>{_JS}</script>\n</body>\n</html>\n")


def _results_html(src: Any, diagram: str) -> str:
    """The results table (drawn and analytic values) after the last step."""
    from graphkin.render.results import diff_text, result_rows

    if src.solution is None:
        return ""
    rows = result_rows(src, [diagram])
    if not rows:
        return ""
    cells = "".join(
        f"<tr><td>{html.escape(r.quantity)}</td><td>{html.escape(r.drawn)}</td>"
        f"<td>{html.escape(r.exact)}</td>"
        f"<td>{diff_text(r.diff)}</td><td>{html.escape(r.unit)}</td>"
        "</tr>" for r in rows)
    return ('<table class="results"><caption>Read off the construction, and the analytic '
            "solution</caption><tr><th>quantity</th><th>drawn</th><th>analytic</th>"
            f"<th>rel. diff.</th><th>unit</th></tr>{cells}</table>")
