"""Stability of a Science Birds level (physc.simulation.stability): 10 s with no action,
no object moving more than 0.05 units and nothing destroyed, as the paper defines it."""

from __future__ import annotations

from physc.domains.angrybirds.game import Game
from physc.simulation.stability import stable

STABLE_LIMIT = 0.05  # units an object may move
STABLE_SECONDS = 10.0


def stability(game: Game) -> tuple[bool, float]:
    """(stable, the largest displacement) of the game's level over 10 s with no action."""
    return stable(game.simulate(None, STABLE_SECONDS, stop_at_rest=False), STABLE_LIMIT)
