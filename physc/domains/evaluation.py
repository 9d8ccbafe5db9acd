"""A domain's evaluation: the benchmark's rule for keeping a task, the agent that measures how
often a task is solved by accident, agents scored on a dataset, and what its measurements mean;
a part of the domain (physc.domains.part), `domain.evaluation`, which the search's last step,
`physc eval` and `physc generate` ask. Every hook has a default that measures nothing, so a
domain writes a subclass only for what its benchmark has (the PHYRE-like plugin: PHYRE's
acceptance, its random agent and AUCCESS)."""

from __future__ import annotations

import random
from collections.abc import Callable, Sequence
from typing import Protocol

from physc.domains.errors import MissingCapability
from physc.domains.part import Part


class Verdict(Protocol):
    """A benchmark's verdict on keeping a task (what `Evaluation.acceptance` gives)."""

    @property
    def accepted(self) -> bool: ...

    @property
    def reason(self) -> str:
        """Why the task is not kept, in a few words ("" when it is): the search gives the
        layout up under these words (PHYRE's: "random actions solve it too often (TRIVIAL)")."""
        ...

    @property
    def simulations(self) -> int:
        """The plays the verdict cost."""
        ...

    def record(self) -> dict:
        """The figures a task file and `physc eval` keep (`flags`, `solution_stable`, `solve_rate`, …)."""
        ...


class Evaluation(Part):
    """The evaluation of one domain's tasks (module docstring); `self.domain` is the domain bound
    to its world and engine."""

    measures: str = ""
    """What the domain's evaluation measures mean (stability's limit, the noise, the agent), a few
    sentences for the report of `physc eval`."""

    def acceptance(self, level, action, solves: Callable[[object], bool]) -> Verdict | None:
        """The benchmark's verdict on keeping the finished task `level` whose intended action is
        `action` (PHYRE: GOOD_STABLE and not TRIVIAL, from its fixed pool of random actions);
        `solves(candidate)` plays one action within the search's budget. None (the default):
        every task the search finds is kept."""
        return None

    def agent_plays(self, level, scenario) -> Sequence[tuple[str, object]]:
        """The plays, (label, action), of the agent whose share of solving plays is the
        evaluation's accidental solvability, where that agent plays a fixed list (Science Birds:
        the paper's heuristic agent): the search blocks those that solve a task by accident
        (physc.search.accidents). Default: none (the search guards nothing)."""
        return ()

    def accidental(self, level, scenario, solution, rng: random.Random) -> dict:
        """The evaluation's accidental solvability of a task: a dict of figures for its record
        (`accidental`: the fraction of an agent's plays that solve it, None when it found none;
        `agent_plays`; optionally `auccess`). Default: {} (no agent: not measured)."""
        return {}

    def score_agent(self, folder, agent, setup: str, folds, split: str) -> dict:
        """An agent (a Python callable) scored on a dataset of this domain made by `physc
        generate` (`physc eval --agent`; PHYRE: AUCCESS on its folds): a dict for the report,
        with `auccess`, the mean over `folds`. A capability (`score_agent`), declared; the
        default scores no agent."""
        raise MissingCapability(self.domain.name, ("score_agent",), "physc eval --agent")
