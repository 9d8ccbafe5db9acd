"""Failure is an answer: why a well-formed scenario yields no layout or task."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the CLI imports this module; networkx is not needed to name the type
    from physc.compiler.layout_graph import LayoutEdge

# The budgets a search can run out of, by the option that sets each (`Infeasible.budget`).
CLAUSE_BUDGET = "--budget"  # clause choices of the layout search, per shape draw
LAYOUT_BUDGET = "--layouts"  # placed layouts that simulation may try
TIME_BUDGET = "--time-budget"  # seconds for the whole generation
PLACEMENT_BUDGET = "placement"  # consistent conjunctions placement may try (no option)
SIZE_LIMIT = "size"  # the scenario is larger than the layout search takes (E0803)


class Infeasible(Exception):
    """No task can be generated: the constraints conflict (`budget` None) or a budget ran
    out first (`budget` names it: one of the *_BUDGET names above). `conflicts` are the
    layout edges that cannot hold together, each with the source terms it comes from."""

    def __init__(self, stage: str, message: str, conflicts: tuple[LayoutEdge, ...] = (), tried: int = 0, budget: str | None = None):
        super().__init__(message)
        self.stage = stage
        self.message = message
        self.conflicts = conflicts
        self.tried = tried
        self.budget = budget


def readable(count: int) -> str:
    """A count as a person reads it: 12,345, or ≈ 3.3 × 10⁹³ past a billion (exact counts
    of conjunctions grow exponentially with the scenario and reach a hundred digits)."""
    if count < 10**9:
        return f"{count:,}"
    exponent = int(math.log10(count))  # log10 takes ints of any size; str() stops at 4,300 digits
    while 10**exponent > count:
        exponent -= 1
    while 10 ** (exponent + 1) <= count:
        exponent += 1
    mantissa = count / 10**exponent
    if mantissa >= 9.95:
        mantissa, exponent = 1.0, exponent + 1
    superscript = str(exponent).translate(str.maketrans("0123456789", "⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return f"≈ {mantissa:.1f} × 10{superscript}"
