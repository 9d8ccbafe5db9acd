"""Physical stability: left alone, nothing moves and nothing breaks.

The paper's definition, for any domain: a run with no action for some seconds is stable
when no body moves more than a limit (in the domain's units) and nothing is destroyed.
The generator uses it (a task must stand before it is kept; a distractor must not
move) and so does the evaluation; the domain runs the world and says the limit.
"""

from __future__ import annotations

import numpy as np

from physc.simulation.trace import Trace


def largest_shift(trace: Trace) -> float:
    """How far the body that moved most got from where it started (0 with no body)."""
    states = trace.states
    if not states.shape[1]:
        return 0.0
    return float(np.nanmax(np.hypot(states[:, :, 0] - states[0, :, 0], states[:, :, 1] - states[0, :, 1])))


def stable(trace: Trace, limit: float) -> tuple[bool, float]:
    """(stable, the largest shift) of a run with no action."""
    shift = largest_shift(trace)
    return shift <= limit and not trace.destructions, shift
