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

from typing import cast

from physc.domains.simulated import SimulatedDomain
from physc.search import settings
from physc.search.problem import Ledger, Problem
from physc.search.verify import failing_reading


def precise(problem: Problem, ledger: Ledger, layout, attempt) -> tuple[str | None, tuple[str, ...]]:
    """(why the layout is given up, or None; a note when the domain's agents' actions hold)."""
    domain = problem.domain
    level = problem.level_of(layout)
    solution = domain.actions.played_as(level, domain.actions.solution(attempt.label, attempt.action))
    variants = domain.actions.agent_variants(level, solution)
    if not variants:
        return None, ()
    for _, action in variants:
        if not holds(problem, ledger, level, action):
            return settings.IMPRECISE, ()
    return None, (f"precision: the {len(variants)} actions agents may send beside the solution's solve it",)


def holds(problem: Problem, ledger: Ledger, level: object, action: object) -> bool:
    """Whether `action` solves `level` and realises the sequence in every reading of the world
    that can change its play, each play counted by the ledger's evaluator."""

    def run(reading):
        there = cast(SimulatedDomain, problem.domain.at(reading))  # a copy of the domain (Domain.at): its class
        return ledger.evaluator.run(lambda: there.play(level, action, problem.scenario, problem.seconds))

    return failing_reading(problem.domain.world, problem.scenario, run) is None
