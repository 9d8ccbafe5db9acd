"""Stability of a Science Birds level (physc.simulation.stability): 10 s with no action,
no object moving more than 0.05 units and nothing destroyed, as the paper defines it."""

from __future__ import annotations

from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.level import Level
from physc.simulation.stability import stable

STABLE_LIMIT = 0.05  # units an object may move
STABLE_SECONDS = 10.0


def stability(level: Level) -> tuple[bool, float]:
    """(stable, the largest displacement) over 10 s with no action."""
    return stable(Game(level).simulate(None, STABLE_SECONDS, stop_at_rest=False), STABLE_LIMIT)
