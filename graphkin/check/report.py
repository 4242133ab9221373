"""Checking a set of answers: one row per answer, a verdict, and the likely mistake.

References
----------
Uicker, Pennock & Shigley, 5th ed., Examples 3.1 and 4.2 (graphic answers
checked against the analytic ones: "in good agreement with, but [less]
accurate than" the analytic results).
"""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from dataclasses import dataclass, field

from graphkin.check.answers import Answers, CheckTolerance, Given
from graphkin.check.compare import compare, show_exact, show_given
from graphkin.check.diagnose import Diagnoser, Mistake
from graphkin.check.exact import Evaluator
from graphkin.kinematics.solution import Solution
from graphkin.text import table

__all__ = ["Row", "Report", "check", "check_given", "marks_csv"]

OK, WRONG, FIT = "ok", "WRONG", "fit"


@dataclass
class Row:
    """One checked answer.

    Attributes
    ----------
    key : str
    given, exact, error : str
        As shown (the exact value in the unit the answer was given in).
    verdict : str
        ``ok``, ``WRONG``, or ``fit`` (a drawn point used to fit the drawing's
        scale and orientation, right by construction).
    mistake : Mistake or None
        The likely mistake, for a wrong answer that one explains.
    note : str
    """

    key: str
    given: str
    exact: str
    error: str
    verdict: str
    mistake: Mistake | None = None
    note: str = ""

    @property
    def ok(self) -> bool:
        """Within tolerance (or a fitted point)."""
        return self.verdict != WRONG


@dataclass
class Report:
    """The rows of one answers file (or drawing) and its tolerance."""

    rows: list[Row]
    tolerance: CheckTolerance
    source: str = ""
    student: str = ""
    title: str = ""
    notes: list[str] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        """Every answer within tolerance."""
        return all(r.ok for r in self.rows)

    @property
    def counted(self) -> list[Row]:
        """The rows that count as answers (fitted points do not)."""
        return [r for r in self.rows if r.verdict != FIT]

    def text(self) -> str:
        """The report as a table, a hint under each wrong answer, and a summary line."""
        head = ("answer", "given", "exact", "error", "verdict")
        aligned = table([head] + [(r.key, r.given, r.exact, r.error, r.verdict)
                                  for r in self.rows])
        lines = []
        if self.title:
            lines.append(self.title)
        tol = self.tolerance
        lines.append(f"tolerance: {tol.relative * 100:g} % of magnitude, {tol.angle:g}° of "
                     "direction")
        lines.append(aligned[0])
        for r, t in zip(self.rows, aligned[1:]):
            lines.append(t)
            if r.verdict == WRONG:
                hint = (f"likely mistake: {r.mistake.text}" if r.mistake
                        else "no usual mistake explains it")
                lines.append(f"    {hint}")
            if r.note:
                lines.append(f"    {r.note}")
        for n in self.notes:
            lines.append(f"note: {n}")
        good = sum(r.ok for r in self.counted)
        lines.append(f"{good} of {len(self.counted)} within tolerance")
        return "\n".join(lines) + "\n"


def check_given(ev: Evaluator, diag: Diagnoser, given: Given, tol: CheckTolerance) -> Row:
    """Check one measured value; diagnose it when it is wrong."""
    exact = ev.value(given.key)
    floor = ev.floor(given.key.quantity)
    ref = ev.reference_length(exact.xy) if given.key.shape == "point" \
        and exact.xy is not None and not exact.ideal else None
    c = compare(given, exact, tol, floor=floor, reference=ref)
    row = Row(given.key.text, show_given(given), show_exact(given, exact), c.error,
              OK if c.ok else WRONG, note=given.note)
    if not c.ok:
        row.mistake = diag.diagnose(given, tol)
    return row


def check(sol: Solution, answers: Answers, tolerance: CheckTolerance | None = None) -> Report:
    """Check answers against a solved mechanism.

    Parameters
    ----------
    sol : Solution
        From :func:`graphkin.solve`.
    answers : Answers
        From :func:`graphkin.check.load_answers`.
    tolerance : CheckTolerance, optional
        Overrides the answers file's own.

    Returns
    -------
    Report

    Raises
    ------
    InputError
        An answer whose quantity does not exist for the mechanism.

    Examples
    --------
    Example 3.1's crank: V_B = ω2 R_BA = 94.25 × 4/12 = 31.42 ft/s, at 120° − 90°
    turned by 180° (ccw ω2), i.e. at −150°.

    >>> import graphkin
    >>> from graphkin.check import loads_answers
    >>> mech = graphkin.loads('''
    ... units = { length = "in" }
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [4, 0]
    ... [drive]
    ... link = 2
    ... angle = 120
    ... omega = "900 rev/min"
    ... alpha = 0
    ... ''')
    >>> rep = check(mech.solve(), loads_answers('V_B = "31.4 ft/s at -150 deg"', mech))
    >>> rep.ok, rep.rows[0].exact
    (True, '31.42 ft/s at -150.00°')
    """
    from graphkin.errors import InputError

    tol = tolerance or answers.tolerance
    ev = Evaluator(sol)
    diag = Diagnoser(ev)
    rows = []
    for g in answers.given:
        try:
            rows.append(check_given(ev, diag, g, tol))
        except InputError as exc:
            raise InputError(exc.message, key=g.key.text, file=answers.source or None) from None
    return Report(rows, tol, answers.source, answers.student)


def marks_csv(reports: Sequence[tuple[str, Report | None, str]]) -> str:
    """One CSV row per answers file: file, student, status, counts, score, each answer's verdict.

    Parameters
    ----------
    reports : sequence of (file, report or None, error)
        ``None`` and the error message for a file that could not be read.
    """
    keys: list[str] = []
    for _, rep, _ in reports:
        for r in rep.counted if rep else ():
            if r.key not in keys:
                keys.append(r.key)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["file", "student", "status", "answers", "within_tolerance", "score_percent",
                *keys, "mistakes"])
    for name, rep, err in reports:
        if rep is None:
            w.writerow([name, "", f"unreadable: {err}", 0, 0, "", *[""] * len(keys), ""])
            continue
        rows = {r.key: r for r in rep.counted}
        n = len(rows)
        good = sum(r.ok for r in rows.values())
        cells = []
        for k in keys:
            row = rows.get(k)
            cells.append("" if row is None else row.verdict)
        mistakes = "; ".join(f"{r.key}: {r.mistake.text}" for r in rows.values()
                             if r.mistake is not None)
        w.writerow([name, rep.student, "ok" if rep.ok else "wrong", n, good,
                    f"{100.0 * good / n:.0f}" if n else "", *cells, mistakes])
    return buf.getvalue()
