"""Obstacles against random shots: a task that the evaluation's agent solves by accident too often
gets bars across the flights of the plays that solve it, and not across the intended one's.

Accidental solvability is the paper's measure: the share of an agent's plays that solve the task
(Science Birds: the paper's heuristic agent, which shoots at every object but the solution's
first target; the domain's `evaluation.agent_plays`). A chain made robust in a scene with few
bodies is easy to set off by such a shot. So, once the level has its distractors, the search
plays the agent's plays; while more than `accidental` of them solve the task, the first that
does is blocked (guards.block: the domain's bar across its flight, a little further back each
time, kept only where the intended solution still holds up), and the plays are played again.
At most `accident_guards` bars. The task file records the measure before and after
(`accidental`); a domain whose agent plays no fixed list (PHYRE: random actions, judged by the
benchmark's own acceptance rule) is not guarded here.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import attrs

from physc.compiler.concrete_layout import ConcreteLayout
from physc.search.attempt import Attempt
from physc.search.guards import BACKS, block, first_player, roof
from physc.search.problem import Ledger, Problem, simulate
from physc.search.strengthen import holds_up


@attrs.frozen
class Accidents:
    """What the guard did: the layout, its bars' descriptions, and the task file's record."""

    layout: ConcreteLayout
    obstacles: tuple[str, ...] = ()
    record: dict | None = None  # plays, solved before and after (shares), bars added


def solving(problem: Problem, ledger: Ledger, layout: ConcreteLayout, plays: Sequence) -> list[Attempt]:
    """The agent's plays that solve the task in `layout`, as attempts (in the plays' order)."""
    found = []
    for label, action in plays:
        attempt = simulate(problem, ledger, layout, action)
        if attempt.trace.solved:
            found.append(attrs.evolve(attempt, label=label))
    return found


def stopper(
    problem: Problem,
    ledger: Ledger,
    layout: ConcreteLayout,
    culprit: Attempt,
    actor: str,
    solution: Attempt,
    count: int,
) -> tuple[ConcreteLayout, str] | None:
    """`layout` with a bar that stops `culprit` solving the task while the solution holds up in
    its noisy replays, and its description: a bar across the culprit's flight, each of guards'
    BACKS back from where it first strikes, then a roof over what it first strikes; or None."""

    def solves(attempt: Attempt) -> bool:
        return attempt.trace.solved

    contact = next((c for c in culprit.trace.contacts if actor in (c.a, c.b)), None)
    struck = None if contact is None else (contact.b if contact.a == actor else contact.a)

    def across(back: float) -> Callable[[], tuple[ConcreteLayout, str] | None]:
        return lambda: block(problem, ledger, layout, culprit, actor, solution, (back,), solves, count)

    tries = [across(back) for back in BACKS]
    if struck is not None:
        tries.append(lambda: roof(problem, ledger, layout, struck, solution, culprit, solves, count))
    for attempt in tries:
        blocked = attempt()
        if blocked is not None and holds_up(problem, ledger, solution, blocked[0]):
            return blocked
    return None


def guard(problem: Problem, ledger: Ledger, layout: ConcreteLayout, solution: Attempt, count: int) -> Accidents:
    """`layout` with the agent's accidental solutions blocked (module docstring). `count`:
    obstacles so far (the bars are named after them)."""
    domain = problem.domain
    plays = list(domain.evaluation.agent_plays(problem.level_of(layout), problem.scenario))
    actor = first_player(problem)
    if not plays or actor is None:
        return Accidents(layout)
    limit = problem.settings.accidental
    solved = solving(problem, ledger, layout, plays)
    before, added, tried = len(solved) / len(plays), [], set()
    left = problem.settings.accident_guards if domain.search.blocker is not None else 0
    while left > 0 and len(solved) / len(plays) > limit:
        culprit = next((a for a in solved if a.label not in tried), None)
        if culprit is None:
            break
        tried.add(culprit.label)
        left -= 1
        blocked = stopper(problem, ledger, layout, culprit, actor, solution, count + len(added))
        if blocked is not None:
            layout = blocked[0]
            added.append(f"accidental: {blocked[1]}")
            solved = solving(problem, ledger, layout, plays)  # one bar may stop several
    record = {
        "plays": len(plays),
        "solved_before": round(before, 4),
        "solved": round(len(solved) / len(plays), 4),
        "obstacles": len(added),
    }
    return Accidents(layout, tuple(added), record)
