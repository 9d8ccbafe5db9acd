"""Precision: the finished level's solution holds for every action the target world's agents
may send for it.

A task records its solution as the domain's action and, where the target world's players send
something else, as what they send (`actions.played_as`; Science Birds: the whole-pixel drag
Phy-Q's agents send). An agent does not send exactly that: the domain says what else it may send
for the same solution (`actions.agent_variants`; Science Birds: the 8 pixels around each shot's
drag, Phy-Q's trajectory planner's release for its angle, a tap 20 ms early or late). This step
plays each of them exactly on the finished level, in every reading of the world that can change
its play (physc.worlds.under_readings), each play counted by the ledger's evaluator; one that
does not solve the level and realise the sequence gives the layout up. It is deterministic,
beside the noise model (the noisy replays judge robustness; this judges the agents' grid).
`physc verify` plays the same actions (physc.search.verify).
"""

from __future__ import annotations

import attrs

from physc.search import settings
from physc.search.attempt import Attempt
from physc.search.problem import Ledger, Problem, play_in, simulate
from physc.search.strengthen import holds_up
from physc.search.verify import failing_reading

NUDGES = (1, -1, 2, -2, 3, -3, 4, -4, 5, -5, 6, -6, 8, -8)  # steps along the domain's `nudged` line, nearest first


def precise(problem: Problem, ledger: Ledger, layout, attempt: Attempt) -> tuple[str | None, tuple[str, ...], Attempt]:
    """(why the layout is given up, or None; a note when the domain's agents' actions hold; the
    solution that holds). Where an agent's action beside the solution's fails, the solution is
    moved along the domain's `nudged` line (Science Birds: its last shot turned 0.05° a step),
    nearest first, to the first place where it and every action the agents may send for it
    hold, and it still passes the noisy replays it must: the agents' grid then lies inside the
    window of actions that work."""
    domain = problem.domain
    level = problem.level_of(layout)
    for step in (0, *NUDGES):
        action = attempt.action if step == 0 else domain.actions.nudged(attempt.action, step)
        if action is None:
            continue
        solution = domain.actions.played_as(level, domain.actions.solution(attempt.label, action))
        variants = domain.actions.agent_variants(level, solution)
        if not variants:
            return None, (), attempt
        if not all(holds(problem, ledger, level, variant) for _, variant in variants):
            continue
        moved = attempt if step == 0 else moved_to(problem, ledger, layout, attempt, action)
        if moved is None:
            continue
        note = f"precision: the {len(variants)} actions agents may send beside the solution's solve it"
        return None, (note + (f" (the solution moved {step:+d} steps to hold so)" if step else ""),), moved
    return settings.IMPRECISE, (), attempt


def moved_to(problem: Problem, ledger: Ledger, layout, attempt: Attempt, action) -> Attempt | None:
    """`attempt` with `action` instead, if that holds (solves and realises the sequence in every
    reading) and passes as many noisy replays as the solution must, in both noise streams."""
    if not holds(problem, ledger, problem.level_of(layout), action):
        return None
    moved = attrs.evolve(simulate(problem, ledger, layout, action), label=attempt.label)
    return moved if holds_up(problem, ledger, moved, layout) else None


def holds(problem: Problem, ledger: Ledger, level: object, action: object) -> bool:
    """Whether `action` solves `level` and realises the sequence in every reading of the world
    that can change its play, each play counted by the ledger's evaluator."""
    run = play_in(problem, ledger, level, action, problem.scenario)
    return failing_reading(problem.domain.world, problem.scenario, run) is None
