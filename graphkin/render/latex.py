r"""Labels in LaTeX: graphkin's text (Unicode letters, matplotlib mathtext) as LaTeX source.

The drawings' labels are written for matplotlib: ``ω₃`` in Unicode,
``$A^{n}_{CB}$`` in mathtext, a user's letters escaped by
:func:`graphkin.render.text.plain` (``\$``).  A TikZ picture
(:mod:`graphkin.render.tikz`) needs the same labels as LaTeX that pdflatex
reads without any Unicode set-up: ``$\omega_{3}$``, ``$A^{n}_{CB}$``,
``$\checkmark$``.  A character with no LaTeX spelling here is printed as
``?`` (never a compile error).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.6 (lettering), Sec. 3.4 (the
book's notation of relative velocities and accelerations).
"""

from __future__ import annotations

import re

__all__ = ["to_latex", "MATH_CHARS"]

_GREEK = ("alpha beta gamma delta epsilon zeta eta theta iota kappa lambda mu nu xi o pi rho "
          "varsigma sigma tau upsilon phi chi psi omega").split()
MATH_CHARS: dict[str, str] = {}
"""Unicode characters written as LaTeX math (without the dollars)."""
for _k, _name in enumerate(_GREEK):
    MATH_CHARS[chr(0x3B1 + _k)] = "o" if _name == "o" else "\\" + _name
for _k, _name in enumerate(("Alpha Beta Gamma Delta Epsilon Zeta Eta Theta Iota Kappa Lambda "
                            "Mu Nu Xi O Pi Rho - Sigma Tau Upsilon Phi Chi Psi Omega").split()):
    if _name == "-":
        continue
    cmd = "\\" + _name
    if _name in ("Alpha", "Beta", "Epsilon", "Zeta", "Eta", "Iota", "Kappa", "Mu", "Nu", "O",
                 "Rho", "Tau", "Chi"):
        cmd = "\\mathrm{" + ("O" if _name == "O" else _name[0]) + "}"
    MATH_CHARS[chr(0x391 + _k)] = cmd
for _k in range(10):
    MATH_CHARS[chr(0x2080 + _k)] = f"_{{{_k}}}"
MATH_CHARS.update({
    "°": "^{\\circ}", "−": "-", "×": "\\times", "·": "\\cdot", "⊥": "\\perp",
    "∥": "\\parallel", "→": "\\rightarrow", "←": "\\leftarrow", "↔": "\\leftrightarrow",
    "≈": "\\approx", "≤": "\\leq", "≥": "\\geq", "≠": "\\neq", "∞": "\\infty", "±": "\\pm",
    "✓": "\\checkmark", "✔": "\\checkmark", "′": "\\prime", "″": "\\prime\\prime",
    "²": "^{2}", "³": "^{3}", "¹": "^{1}", "∠": "\\angle", "Δ": "\\Delta", "∑": "\\sum",
    "√": "\\surd", "⁻": "^{-}", "ⁿ": "^{n}", "ᵗ": "^{t}", "ᶜ": "^{c}", "ϕ": "\\phi",
    "ϑ": "\\vartheta", "ε": "\\varepsilon", "ℓ": "\\ell", "∘": "\\circ", "⋅": "\\cdot",
    "↻": "\\circlearrowright", "↺": "\\circlearrowleft", "⟂": "\\perp",
})
_TEXT_CHARS = {
    "\\": "\\textbackslash{}", "#": "\\#", "$": "\\$", "%": "\\%", "&": "\\&", "_": "\\_",
    "{": "\\{", "}": "\\}", "~": "\\textasciitilde{}", "^": "\\textasciicircum{}",
    "<": "\\textless{}", ">": "\\textgreater{}", "|": "\\textbar{}", "–": "--", "—": "---",
    "…": "\\dots{}", "“": "``", "”": "''", "‘": "`", "’": "'", "\u00a0": "~", "é": "\\'e",
    "è": "\\`e", "ü": '\\"u', "ö": '\\"o', "ä": '\\"a', "ß": "\\ss{}", "◀": "<", "▶": ">",
}


def _split(text: str) -> list[tuple[bool, str]]:
    r"""Mathtext's reading of ``text``: (is_math, part), an escaped ``\$`` kept in text."""
    n = text.count("$") - text.count(r"\$")
    if n == 0 or n % 2:  # matplotlib reads it as plain text
        return [(False, text.replace(r"\$", "$"))]
    parts: list[tuple[bool, str]] = []
    buf, math, i = "", False, 0
    while i < len(text):
        ch = text[i]
        if ch == "\\" and i + 1 < len(text) and text[i + 1] == "$":
            buf += "\\$" if math else "$"
            i += 2
            continue
        if ch == "$":
            parts.append((math, buf))
            buf, math = "", not math
        else:
            buf += ch
        i += 1
    parts.append((math, buf))
    return [p for p in parts if p[1]]


def _math(body: str) -> str:
    r"""A mathtext body with its Unicode spelled out (``Q_{Γ}`` -> ``Q_{\Gamma}``)."""
    out = []
    for ch in body:
        if ord(ch) < 128:
            out.append(ch)
        elif ch in MATH_CHARS:
            cmd = MATH_CHARS[ch]
            out.append(cmd + (" " if cmd[-1].isalpha() else ""))
        else:
            out.append("?")
    return _tidy("".join(out))


def _tidy(s: str) -> str:
    r"""No space after a command where a non-letter follows (``\omega _{3}`` -> ``\omega_{3}``)."""
    s = re.sub(r"(\\[A-Za-z]+) (?=[^A-Za-z]|$)", r"\1", s)
    while True:  # a run of Unicode subscripts (or superscripts) is one: I₁₂ -> I_{12}
        t = re.sub(r"([_^])\{([^{}]*)\}\1\{([^{}]*)\}", r"\1{\2\3}", s)
        if t == s:
            return s
        s = t


def _text(body: str) -> str:
    """Plain text for LaTeX: specials escaped, Greek, subscripts and marks as math."""
    out: list[str] = []
    math: list[str] = []

    def flush() -> None:
        if math:
            out.append("$" + _tidy("".join(math)) + "$")
            math.clear()

    for ch in body:
        if ch in MATH_CHARS:
            cmd = MATH_CHARS[ch]
            math.append(cmd + (" " if cmd[-1].isalpha() else ""))
            continue
        flush()
        if ch in _TEXT_CHARS:
            out.append(_TEXT_CHARS[ch])
        elif ord(ch) < 32:
            out.append(" ")
        elif ord(ch) < 128:
            out.append(ch)
        else:
            out.append("?")
    flush()
    return "".join(out)


def to_latex(text: str) -> str:
    r"""One label or line of graphkin's text as LaTeX source (one line; no newline handling).

    Parameters
    ----------
    text : str
        A label as the matplotlib drawing shows it: Unicode (``ω₃``), mathtext
        between dollars (``$A^{n}_{CB}$``), ``\$`` for a literal dollar.

    Examples
    --------
    >>> to_latex("ω₃ = 2 rad/s")
    '$\\omega_{3}$ = 2 rad/s'
    >>> to_latex("$A^{n}_{CB}$"), to_latex("$Q_{Γ}$"), to_latex("O₂")
    ('$A^{n}_{CB}$', '$Q_{\\Gamma}$', 'O$_{2}$')
    >>> to_latex("I₁₂"), to_latex("ω₃/₄")
    ('I$_{12}$', '$\\omega_{3}$/$_{4}$')
    >>> to_latex("50% of \\$5 ✓"), to_latex("-180.00°")
    ('50\\% of \\$5 $\\checkmark$', '-180.00$^{\\circ}$')
    """
    parts = []
    for math, body in _split(text):
        parts.append("$" + _math(body) + "$" if math else _text(body))
    return "".join(parts)
