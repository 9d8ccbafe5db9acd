"""One simulated play of a scene: what every part of the search makes and reads."""

from __future__ import annotations

import attrs

from physc.simulation.fidelity import Fidelity
from physc.simulation.trace import Trace


@attrs.frozen
class Attempt:
    """One candidate action played: its label, the action, the judged trace and its fidelity."""

    label: str
    action: object
    trace: Trace
    fidelity: Fidelity


def reaches(attempt: Attempt, end: int, total: int) -> bool:
    """Whether `attempt` realises the first `end` of the `total` declared interactions in
    order, breaking no restriction before the last of them (all of them: it is valid)."""
    f = attempt.fidelity
    if end >= total:
        return f.valid
    if f.matched < end:
        return False
    until = f.times[end - 1] if end else 0.0
    return not any(v.interaction.time <= until for v in attempt.trace.violations)
