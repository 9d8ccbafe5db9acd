"""Physical stability of a level: left alone, nothing moves and nothing breaks.

The paper's definition, used both by the generator (a task must stand before it is
kept; a distractor must not move) and by the evaluation: 10 s with no action; stable
when no object moves more than 0.05 units and nothing is destroyed.
"""

from __future__ import annotations

import numpy as np

from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.level import Level

STABLE_LIMIT = 0.05  # units an object may move
STABLE_SECONDS = 10.0


def stability(level: Level) -> tuple[bool, float]:
    """(stable, the largest displacement) over 10 s with no action."""
    trace = Game(level).simulate(None, STABLE_SECONDS, stop_at_rest=False)
    states = trace.states
    if not states.shape[1]:
        return True, 0.0
    shift = float(np.nanmax(np.hypot(states[:, :, 0] - states[0, :, 0], states[:, :, 1] - states[0, :, 1])))
    return shift <= STABLE_LIMIT and not trace.destructions, shift
