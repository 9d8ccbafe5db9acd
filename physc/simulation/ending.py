"""How a play of a level ends: what is read of a play decides how soon it may stop.

One value names it from the callers (the search, `physc verify`, `physc simulate`, acceptance,
stability) down to a domain's rules, which alone know what stopping early means in their world
(physc.domains.simulated.SimulatedDomain.simulation).
"""

from __future__ import annotations

import enum


class Ending(enum.Enum):
    """How a play of a level ends, which a domain's rules may read (what is read of the play
    decides how soon it may stop). A generic domain's rules end its runs as they say in every
    case but `STILL`."""

    READ = "read"
    """Once the outcome and the chain the scenario declares can be read from it (the search's
    plays and replays, `physc verify`'s, the evaluation's): interactions recognised."""
    OUTCOME = "outcome"
    """Once the outcome is known, with every state up to it (no interaction recognised)."""
    SETTLED = "settled"
    """The moment the outcome can no longer change (RunRules.settled): an outcome playout whose
    last states are that step's (acceptance, the random agent)."""
    WHOLE = "whole"
    """As the target world plays it, to its end (`physc simulate`, agents' environments)."""
    STILL = "still"
    """Left alone for all of its seconds, never ending early: the level's stability (something
    that starts to tip slowly must not pass for standing)."""

    @property
    def recognised(self) -> bool:
        """Whether a play that ends so has its interactions recognised."""
        return self in (Ending.READ, Ending.WHOLE)
