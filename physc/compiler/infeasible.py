"""Failure is an answer: why a well-formed scenario yields no layout or task."""

from __future__ import annotations

import enum
import math
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the CLI imports this module; networkx is not needed to name the type
    from physc.compiler.layout_graph import LayoutEdge


class Exhausted(enum.Enum):
    """What ran out before a task was found (`Infeasible.budget`); the value is the option
    that sets it, where there is one."""

    CLAUSES = "--clause-budget"  # clause choices of the layout search, per shape draw
    LAYOUTS = "--layouts"  # placed layouts that simulation may try
    TIME = "--time-budget"  # seconds for the whole generation
    PLACEMENTS = "placement"  # consistent conjunctions placement may try (no option)
    ALLOWED = "allowed"  # every layout the scenario's constraints allow (for this seed's shapes) was tried
    SIZE = "size"  # the scenario is larger than the layout search takes (E0803)
    VERSION = "version"  # the scenario needs what this version of compile does not generate (E0804)


class Infeasible(Exception):
    """No task can be generated: the constraints conflict (`budget` None) or something
    ran out first (`budget` says what: an Exhausted). `conflicts` are the
    layout edges that cannot hold together, each with the source terms it comes from."""

    def __init__(
        self,
        stage: str,
        message: str,
        conflicts: tuple[LayoutEdge, ...] = (),
        tried: int = 0,
        budget: Exhausted | None = None,
        funnel: dict | None = None,
    ):
        super().__init__(message)
        self.stage = stage
        self.message = message
        self.conflicts = conflicts
        self.tried = tried
        self.budget = budget
        self.funnel = funnel  # where the placed layouts went down the chain (physc.search.funnel), if any were


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
