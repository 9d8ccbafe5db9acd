"""Where else a scenario may hold: the best play of a run that gave no task, replayed in the domain's other worlds.

A scenario that gives no task in one world may give one in another (Science Birds: the paper's
roll chains need circles that roll, which Phy-Q's game does not ship and `rolling` has). Exit 3
should say so only when it is measured: the plays that came furthest (of the PLAYS best layouts)
are replayed in each other world the domain has, and a world is named when it realises more of the
declared sequence there, or the whole of it with a stronger weakest link: the play's own action
first, then the domain's candidate actions for that level (a shot lands elsewhere in another
world's physics), then the chain built there by the search's stages from the layout as placed
(the layout was built for this world's physics: later objects stand where its actor went). The
replays take a slice of the time budget kept for them (`reserve`), and stop when it is spent,
so that the budget stays a promise.
"""

from __future__ import annotations

from typing import cast

import attrs

from physc import budget
from physc.compiler.concrete_layout import ConcreteLayout
from physc.domains.simulated import SimulatedDomain
from physc.dsl.scenario import ScenarioIR
from physc.search.chain import Node, chain
from physc.search.problem import Ledger, Problem, search_seconds
from physc.simulation.fidelity import fidelity
from physc.simulation.margin import Margin
from physc.simulation.trace import Trace

RESERVE_SHARE = 0.1  # of the time budget, kept for the replays elsewhere
RESERVE_MOST = 5.0  # seconds at most
PLAYS = 3  # the furthest plays replayed, each of another layout


@attrs.frozen
class Elsewhere:
    world: str
    matched: int
    total: int
    weakest: Margin | None  # the weakest link of the replay there
    built: bool = False  # whether the chain was built there by the search's stages (else: a play replayed)


def reserve(domain: SimulatedDomain, time_budget: float) -> float:
    """Seconds of the budget kept for replays elsewhere: none for a domain of one world."""
    return min(RESERVE_MOST, RESERVE_SHARE * time_budget) if len(domain.worlds) > 1 else 0.0


def elsewhere(
    domain: SimulatedDomain,
    scenario: ScenarioIR,
    furthest: list[tuple[tuple, object, object, ConcreteLayout | None]],
    best: int,
    weakest: Margin | None,
    accept: int = 1,
) -> Elsewhere | None:
    """The first other world of `domain` where a play of `furthest` ((score, level, action,
    the layout as placed), the furthest first) gets further than `best` interactions here, or
    realises the whole sequence with every link held where here its weakest link (`weakest`)
    failed; None when none does or the time is out. Each layout is tried in turn: its play and
    the domain's candidate actions replayed there, then the chain built there stage by stage
    from the layout as placed (physc.search.chain: later objects placed where that world's
    physics sends their actor)."""
    total = len(scenario.interactions)
    here = -1.0 if weakest is None else weakest.share
    for world in domain.worlds:
        if world.name == domain.world.name:
            continue
        there = cast(SimulatedDomain, domain.at(world.name))  # a copy of `domain` (Domain.at): its class
        try:
            for _, level, action, placed in furthest:
                for tried in [action] + [a for a in _candidates(there, level, scenario) if a != action]:
                    found = _judged(
                        there, scenario, there.play(level, tried, scenario, search_seconds(there)), best, total, here
                    )
                    if found is not None:
                        return found
                built = _built(there, scenario, placed, accept)
                if built is not None:
                    found = _judged(there, scenario, built, best, total, here, built=True)
                    if found is not None:
                        return found
        except budget.OutOfTime:
            return None
    return None


def _judged(
    there: SimulatedDomain,
    scenario: ScenarioIR,
    trace: Trace,
    best: int,
    total: int,
    here: float,
    built: bool = False,
) -> Elsewhere | None:
    """The world `there` named by `trace` if it gets further than `best`, or realises the
    whole sequence with a weakest link stronger than `here` (and held)."""
    check = fidelity(scenario, trace)
    margins = there.margins(scenario, trace) if hasattr(there, "margins") else None
    link = None if margins is None else margins.weakest
    whole = check.valid and (link is None or (link.held and link.share > max(here, 0.0)))
    if check.matched > best or (best >= total and whole):
        return Elsewhere(there.world.name, check.matched, total, link, built)
    return None


def _built(there: SimulatedDomain, scenario: ScenarioIR, placed: ConcreteLayout | None, accept: int) -> Trace | None:
    """The trace of the chain the search builds in the world `there` from the layout as
    placed: the whole sequence's best attempt, else the furthest play it made; None for a
    domain the search cannot run in."""
    if placed is None or "satisfy" not in there.capabilities:
        return None
    problem = Problem.of(there, scenario, placed, accept)
    ledger = Ledger()
    node = chain(problem, ledger, Node(problem.placed, (), -1), 0)
    if node is not None and node.attempts:
        return node.attempts[0].trace
    return None if ledger.furthest is None else ledger.furthest.trace


def _candidates(domain: SimulatedDomain, level: object, scenario: ScenarioIR) -> list[object]:
    """The domain's candidate actions for the level (the search's first stage), without their labels."""
    return [action for _, action in domain.actions.candidates(level, scenario)]
