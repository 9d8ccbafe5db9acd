"""The measurements of one generated task (the paper's evaluation, and more), for any
domain: each is the domain's own hook, or made from its `replay`.

* physical stability: the domain's `stability` (angrybirds: 10 s with no action, no
  object moves more than 0.05 units and nothing is destroyed);
* intended solvability: the recorded solution replayed exactly, and 10 times with the
  domain's noise (angrybirds: release angle σ = 0.1°, positions of blocks and pigs
  σ = 0.005 units);
* sequence fidelity: the replay realises the declared sequence and breaks no
  restriction (docs/generation.md);
* accidental solvability: the domain's agent (`accidental`; angrybirds: the paper's
  heuristic agent; a simulated domain: the random agent, with its AUCCESS).

Every random draw comes from a generator seeded by the task's own seed, so a
measurement does not depend on which process made it, or in what order.
"""

from __future__ import annotations

import random

from physc.simulation.fidelity import fidelity

NOISY_REPLAYS = 10


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
