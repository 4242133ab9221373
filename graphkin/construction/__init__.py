"""Named, replayable construction steps (knows names and order, nothing of mechanisms)."""

from graphkin.construction.ops import OPS
from graphkin.construction.protocol import Construction, Evaluation
from graphkin.construction.step import Along, Mark, Role, Side, Step, Term, VectorEquation

__all__ = ["OPS", "Construction", "Evaluation", "Along", "Mark", "Role", "Side", "Step", "Term",
           "VectorEquation"]
