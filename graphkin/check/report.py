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
from graphkin.check.text import printable, spreadsheet_safe
from graphkin.kinematics.solution import Solution
from graphkin.text import table

__all__ = ["Row", "Report", "check", "check_given", "marks_csv", "printable", "spreadsheet_safe",
           "OK", "WRONG", "FIT", "FOLLOWS", "UNREADABLE"]

OK, WRONG, FIT, FOLLOWS, UNREADABLE = "ok", "WRONG", "fit", "follows", "UNREADABLE"


@dataclass
class Row:
    """One checked answer.

    Attributes
    ----------
    key : str
    given, exact, error : str
        As shown (the exact value in the unit the answer was given in).
    verdict : str
        ``ok``, ``WRONG``, ``follows`` (wrong only because of an earlier
        answer's mistake, carried through exactly), ``UNREADABLE`` (the entry
        could not be read), or ``fit`` (a drawn point used to fit the
        drawing's scale and orientation, right by construction).
    mistake : Mistake or None
        The likely mistake, for a wrong answer that one explains.
    note : str
    rule : str
        Which rule decided the verdict (``within 2 %``, ``within 0.5 mm on
        the drawing``, ``sense reversed`` ...).
    follows : str
        For ``follows``: the key of the earlier answer whose mistake this is.
    """

    key: str
    given: str
    exact: str
    error: str
    verdict: str
    mistake: Mistake | None = None
    note: str = ""
    rule: str = ""
    follows: str = ""
    """For ``follows``: the key of the earlier answer whose mistake this is."""

    @property
    def ok(self) -> bool:
        """Within tolerance (or a fitted point)."""
        return self.verdict in (OK, FIT)

    @property
    def code(self) -> str:
        """The short mistake code (``sense``, ``unit:12``, ``follows:theta3`` ...), or ``""``."""
        if self.verdict == FOLLOWS:
            return f"follows:{self.follows}"
        if self.verdict == UNREADABLE:
            return "unreadable"
        if self.verdict == WRONG:
            return self.mistake.code if self.mistake else "unexplained"
        return ""

    def hint(self) -> str:
        """The line under a wrong answer."""
        if self.verdict == FOLLOWS and self.mistake is not None:
            return f"follows from the mistake in {self.follows}: {self.mistake.text}"
        if self.verdict == WRONG:
            return (f"likely mistake: {self.mistake.text}" if self.mistake
                    else "no usual mistake explains it")
        if self.verdict == UNREADABLE:
            return f"unreadable: {self.error}"
        return ""


@dataclass
class Report:
    """The rows of one answers file (or drawing) and its tolerance."""

    rows: list[Row]
    tolerance: CheckTolerance
    source: str = ""
    student: str = ""
    title: str = ""
    notes: list[str] = field(default_factory=list)
    error: str = ""

    @property
    def ok(self) -> bool:
        """Every answer within tolerance (and nothing unreadable)."""
        return not self.error and all(r.ok for r in self.rows)

    @property
    def unreadable(self) -> bool:
        """Some entry, or the whole file, could not be read (exit status 2)."""
        return bool(self.error) or any(r.verdict == UNREADABLE for r in self.rows)

    @property
    def counted(self) -> list[Row]:
        """The rows that count as answers (fitted points do not)."""
        return [r for r in self.rows if r.verdict != FIT]

    def counts(self) -> dict[str, int]:
        """How many answers are right, follow from an earlier mistake, are wrong, unreadable."""
        rows = self.counted
        return {"correct": sum(r.verdict == OK for r in rows),
                "follows": sum(r.verdict == FOLLOWS for r in rows),
                "wrong": sum(r.verdict == WRONG for r in rows),
                "unreadable": sum(r.verdict == UNREADABLE for r in rows)}

    def summary(self) -> str:
        """One sentence on the whole file.

        Examples
        --------
        >>> rep = Report([Row("omega3", "", "", "", OK), Row("omega4", "", "", "", WRONG,
        ...               Mistake("sense", "sense reversed", "sense"))], CheckTolerance())
        >>> rep.summary()
        '1 of 2 within tolerance, 1 wrong (omega4: sense).'
        """
        if self.error:
            return printable(f"The file could not be read: {self.error}")
        c = self.counts()
        n = len(self.counted)
        parts = [f"{c['correct']} of {n} within tolerance"]
        if c["follows"]:
            roots = sorted({r.follows for r in self.counted if r.verdict == FOLLOWS})
            parts.append(f"{c['follows']} follow{'s' if c['follows'] == 1 else ''} from an "
                         f"earlier mistake (in {', '.join(roots)})")
        if c["wrong"]:
            named = [f"{r.key}: {r.code}" for r in self.counted if r.verdict == WRONG]
            parts.append(f"{c['wrong']} wrong ({'; '.join(named)})")
        if c["unreadable"]:
            keys = [r.key for r in self.counted if r.verdict == UNREADABLE]
            parts.append(f"{c['unreadable']} unreadable ({', '.join(keys)})")
        return printable(", ".join(parts) + ".")

    def text(self) -> str:
        """The report as a table, a hint under each wrong answer, and a summary line."""
        head = ("answer", "given", "exact", "error", "verdict", "decided by")
        aligned = table([head] + [tuple(printable(c) for c in (
            r.key, r.given, r.exact, "" if r.verdict == UNREADABLE else r.error, r.verdict,
            r.rule)) for r in self.rows])
        lines = []
        if self.title:
            lines.append(printable(self.title))
        lines.append(f"tolerance: {self.tolerance.describe()}")
        lines.append(aligned[0])
        for r, t in zip(self.rows, aligned[1:]):
            lines.append(t)
            hint = r.hint()
            if hint:
                lines.append(f"    {printable(hint)}")
            if r.note:
                lines.append(f"    {printable(r.note)}")
        for n in self.notes:
            lines.append(f"note: {printable(n)}")
        lines.append(self.summary())
        return "\n".join(lines) + "\n"


def sheet_allowance(ev: Evaluator, given: Given, tol: CheckTolerance) -> float | None:
    """The drawing tolerance in the answer's own units, when a scale is known.

    ``tol.drawing`` millimetres times the drawing's scale for a vector drawn
    from the pole.  A difference (``V_CB``) is read between two drawn points,
    each within ``tol.drawing`` of its place, so it may be off by twice as
    much; ω and α are such a difference divided by the length of the link's
    longest side (the image side they are best read from: ω = V_PQ / R_PQ,
    Sec. 3.4).
    """
    if tol.drawing is None:
        return None
    key = given.key
    if key.kind in ("omega", "alpha"):
        per = tol.per_mm("velocity" if key.kind == "omega" else "acceleration")
        lid = key.args[0]
        pts = [ev.sol.position(n, lid) for n in ev.mech.links[lid].points
               if n not in ev.mech.helper_points]
        size = max((float(((a - b) ** 2).sum() ** 0.5) for a in pts for b in pts), default=0.0)
        return None if per is None or size <= 0 else 2.0 * tol.drawing * per / size
    if key.kind in ("V", "A", "An", "At", "Ac"):
        per = tol.per_mm("velocity" if key.kind == "V" else "acceleration")
        if per is not None and len(key.args) == 2 and key.kind in ("V", "A"):
            return 2.0 * tol.drawing * per
    elif key.kind in ("R", "I", "rho"):
        per = tol.per_mm("length")
    else:
        return None
    return None if per is None else tol.drawing * per


def check_given(ev: Evaluator, diag: Diagnoser, given: Given, tol: CheckTolerance) -> Row:
    """Check one measured value; diagnose it when it is wrong."""
    exact = ev.value(given.key)
    floor = ev.floor(given.key.quantity)
    ref = ev.reference_length(exact.xy) if given.key.shape == "point" \
        and exact.xy is not None and not exact.ideal else None
    sheet = sheet_allowance(ev, given, tol)
    c = compare(given, exact, tol, floor=floor, reference=ref, sheet=sheet)
    row = Row(given.key.text, show_given(given), show_exact(given, exact), c.error,
              OK if c.ok else WRONG, note=given.note, rule=c.rule)
    if not c.ok:
        row.mistake = diag.diagnose(given, tol, sheet)
        if row.mistake and row.mistake.code == "sense" and given.key.shape == "scalar" \
                and not isinstance(given.raw, str) and (given.value or 0.0) > 0:
            row.mistake = Mistake("sense", "a positive number means counterclockwise; the "
                                           "exact value is clockwise", "sense")
    return row


def follow_through(rows: list[Row], given: list[Given], ev: Evaluator, diag: Diagnoser,
                   tol: CheckTolerance) -> None:
    """Mark answers that are wrong only because of an earlier answer's mistake.

    A mistake made once and carried through the rest of the construction (the
    other assembly, a normal component reversed, the input's rate in the
    wrong unit...) explains several answers.  The first of them (in the
    file's order) is wrong with the mistake named; the others are marked
    ``follows`` (as an instructor gives follow-through credit).  A carried
    mistake that would have spoilt an answer the student got right is not
    the student's: such answers keep their own diagnoses.
    """
    wrong = [i for i, r in enumerate(rows) if r.verdict == WRONG]
    if len(wrong) < 2:
        return
    variants = diag.variants()
    right = [i for i, r in enumerate(rows) if r.verdict == OK]
    explained: dict[int, list[int]] = {}
    for vi in range(len(variants)):
        hits = [i for i in wrong
                if diag.explains(vi, given[i], tol, sheet_allowance(ev, given[i], tol))]
        # a mistake the student did not make: an answer given right that it would spoil
        if len(hits) >= 2 and all(diag.agrees(vi, given[i], tol,
                                              sheet_allowance(ev, given[i], tol))
                                  for i in right):
            explained[vi] = hits
    taken: set[int] = set()
    while explained:
        vi, hits = max(explained.items(),
                       key=lambda kv: (len([i for i in kv[1] if i not in taken]), -kv[0]))
        free = [i for i in hits if i not in taken]
        if len(free) < 2:
            break
        mistake = variants[vi][0]
        root, *rest = free
        rows[root].mistake = mistake
        for i in rest:
            rows[i].verdict = FOLLOWS
            rows[i].follows = rows[root].key
            rows[i].mistake = mistake
        taken.update(free)
        del explained[vi]


def check(sol: Solution, answers: Answers, tolerance: CheckTolerance | None = None, *,
          diagnoser: Diagnoser | None = None) -> Report:
    """Check answers against a solved mechanism.

    Parameters
    ----------
    sol : Solution
        From :func:`graphkin.solve`.
    answers : Answers
        From :func:`graphkin.check.load_answers`.
    tolerance : CheckTolerance, optional
        Overrides the answers file's own.
    diagnoser : Diagnoser, optional
        Shared between the files of a class (its what-if solutions are made once).

    Returns
    -------
    Report
        One row per answer, and an ``UNREADABLE`` row per entry that could
        not be read.

    Examples
    --------
    Example 3.1's crank: V_B = ω2 R_BA = 94.25 × 4/12 = 31.42 ft/s, at 120° − 90°
    turned by 180° (ccw ω2), i.e. at −150°.

    >>> import graphkin
    >>> from graphkin.check import loads_answers
    >>> mech = graphkin.examples.fourbar()
    >>> rep = check(mech.solve(), loads_answers('V_B = "31.4 ft/s at -150 deg"', mech))
    >>> rep.ok, rep.rows[0].exact
    (True, '31.42 ft/s at -150.00°')
    """
    from graphkin.errors import InputError

    tol = tolerance or answers.tolerance
    diag = diagnoser if diagnoser is not None and diagnoser.sol is sol else \
        Diagnoser(Evaluator(sol))
    ev = diag.ev
    rows: list[Row] = []
    given: list[Given] = []
    for g in answers.given:
        try:
            rows.append(check_given(ev, diag, g, tol))
            given.append(g)
        except InputError as exc:
            rows.append(Row(g.key.text, show_given(g), "", exc.message, UNREADABLE))
            given.append(g)
    follow_through(rows, given, ev, diag, tol)
    for bad in answers.unreadable:
        rows.append(Row(bad.key or "(file)", "", "", bad.message, UNREADABLE))
    return Report(rows, tol, answers.source, answers.student)


def marks_csv(reports: Sequence[tuple[str, Report | None, str]]) -> str:
    """One CSV row per answers file: counts, a summary, and each answer in detail.

    Columns: ``file, student, status, answers, correct, follows, wrong,
    unreadable, within_tolerance, score_percent, summary``, then for each key
    ``<key>`` (the verdict), ``<key> given``, ``<key> exact``, ``<key> error``
    and ``<key> mistake`` (a short code: ``sense``, ``unit:12``,
    ``follows:theta3`` ...).  Cells a spreadsheet would run as a formula are
    neutralised.

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
    head = ["file", "student", "status", "answers", "correct", "follows", "wrong",
            "unreadable", "within_tolerance", "score_percent", "summary"]
    for k in keys:
        head += [k, f"{k} given", f"{k} exact", f"{k} error", f"{k} mistake"]
    w.writerow([spreadsheet_safe(c) for c in head])
    for name, rep, err in reports:
        if rep is None or rep.error:
            err = rep.error if rep is not None else err
            row: list[object] = [name, rep.student if rep is not None else "",
                                 "unreadable", 0, 0, 0, 0, 1, 0, "",
                                 f"The file could not be read: {err}"]
            row += [""] * (5 * len(keys))
            w.writerow([spreadsheet_safe(c) for c in row])
            continue
        rows = {r.key: r for r in rep.counted}
        c = rep.counts()
        n = len(rows)
        status = "unreadable" if rep.unreadable else "ok" if rep.ok else "wrong"
        row = [name, rep.student, status, n, c["correct"], c["follows"], c["wrong"],
               c["unreadable"], c["correct"], f"{100.0 * c['correct'] / n:.0f}" if n else "",
               rep.summary()]
        for k in keys:
            one = rows.get(k)
            row += ["", "", "", "", ""] if one is None else \
                [one.verdict, one.given, one.exact, one.error, one.code]
        w.writerow([spreadsheet_safe(c) for c in row])
    return buf.getvalue()
