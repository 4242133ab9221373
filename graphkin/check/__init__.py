"""Checking hand solutions: measured answers, or drawn polygons, against the exact constructions.

``graphkin check FILE ANSWERS`` (``docs/formats/answers.md``): each measured value is
compared with the exact one within drawing accuracy (2 % of magnitude and 2° of
direction by default), and a wrong one is explained by the usual mistake that
reproduces it (sense reversed, a unit factor, an image flipped over, a normal
component drawn away from its center, a Coriolis mistake, the other assembly
branch, a difference taken for an absolute value).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4-3.6 and 4.3-4.6 (the polygons and
images), Examples 3.1 and 4.2 (graphic answers within drawing accuracy).
"""

from graphkin.check.answers import (
    Answers,
    CheckTolerance,
    Given,
    Key,
    answers_from_dict,
    load_answers,
    loads_answers,
    parse_key,
    parse_value,
)
from graphkin.check.diagnose import Diagnoser, Mistake
from graphkin.check.exact import Evaluator, Exact
from graphkin.check.report import Report, Row, check, marks_csv

__all__ = [
    "Answers", "CheckTolerance", "Given", "Key", "answers_from_dict", "load_answers",
    "loads_answers", "parse_key", "parse_value", "Diagnoser", "Mistake", "Evaluator", "Exact",
    "Report", "Row", "check", "marks_csv",
]
