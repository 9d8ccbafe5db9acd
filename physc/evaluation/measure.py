"""The measurements of one generated task (the paper's evaluation, and more).

* physical stability: 10 s with no action; stable when no object moves more than
  0.05 units and nothing is destroyed;
* intended solvability: the recorded solution replayed exactly, and 10 times with
  noise (release angle σ = 0.1°, positions of blocks and pigs σ = 0.005 units);
* sequence fidelity: the replay realises the declared sequence and breaks no
  restriction (docs/generation.md);
* accidental solvability: the paper's heuristic agent shoots at every dynamic
  object except the solution's target, at its points of interest, on both
  trajectories; the task's value is the fraction of those plays that solve it.

Every random draw comes from a generator seeded by the task's own seed, so a
measurement does not depend on which process made it, or in what order.
"""

from __future__ import annotations

import random

from physc.domains.angrybirds.actions import agent_targets, points_of_interest
from physc.simulation.fidelity import fidelity
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level
from physc.domains.angrybirds.stability import stability  # noqa: F401  (the evaluation's metric)
from physc.domains.angrybirds import REPLAY_SECONDS
from physc.domains.angrybirds.world import reachable

NOISY_REPLAYS = 10
AGENT_POINTS = ("ll", "ul", "ur", "lr", "c")
SECONDS = REPLAY_SECONDS  # a play's simulated time at most, the replays' too


def intended(domain, level, solution, scenario, rng: random.Random) -> dict:
    """Exact and noisy replays of the recorded solution (the domain's `replay`, in the
    backend the caller selected)."""
    exact = domain.replay(level, solution, scenario)
    exact_fidelity = fidelity(scenario, exact)
    solved = faithful = 0
    for _ in range(NOISY_REPLAYS):
        trace = domain.replay(level, solution, scenario, rng)
        solved += trace.solved
        faithful += fidelity(scenario, trace).valid
    return {
        "exact_solved": exact.solved,
        "exact_faithful": exact_fidelity.valid,
        "noisy_solved": solved / NOISY_REPLAYS,
        "noisy_faithful": faithful / NOISY_REPLAYS,
        "trace": exact.sequence(),
    }


def accidental(level: Level, solution_target: str) -> tuple[float | None, int]:
    """The paper's AS for one level: the fraction of the heuristic agent's plays that solve it,
    and the number of plays. None when the agent found no play (no point of interest within
    reach): a fraction of nothing is not 0, and must not pull a mean down."""
    plays = solved = 0
    for obj in agent_targets(level, solution_target):
        points = points_of_interest(obj)
        for name in AGENT_POINTS:
            x, y = points[name]
            if not reachable(x, y):
                continue
            for trajectory in ("low", "high"):
                plays += 1
                trace = Game(level).simulate(Shot(target=(x, y), trajectory=trajectory), SECONDS, settle_after_solved=0.0)
                solved += trace.solved
    return (solved / plays if plays else None), plays
