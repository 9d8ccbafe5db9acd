"""Contrasts (language version 2): `contrast(a, b)`, an object that rests as its counterpart
does but, acted on as the solution acts on the counterpart, must not solve the task.

Phy-Q's relative weight, height and shape scenarios offer two objects of which only one
works: the task's point is the one that does not. The layout puts the contrast on its
counterpart's support (physc.compiler.layout_rules); this step, on the finished level, has
the domain aim the solution's action at the contrast as it is aimed at the counterpart
(`SimulatedDomain.contrasted`) and plays it, exactly and in the domain's noisy replays: a
play that solves the task gives the layout up.
"""

from __future__ import annotations

import random

from physc.search import settings
from physc.search.problem import Ledger, Problem, replayed


def contrasts(problem: Problem, ledger: Ledger, layout, attempt) -> tuple[str | None, tuple[str, ...]]:
    """(why the layout is given up, or None; a note per contrast that holds)."""
    terms = [t for t in problem.scenario.restrictions if t.name == "contrast"]
    if not terms:
        return None, ()
    domain = problem.domain
    level = problem.level_of(layout)
    notes = []
    for term in terms:
        contrast, counterpart = term.objects
        action = domain.actions.contrasted(level, attempt.action, counterpart, contrast)
        if action is None:
            return settings.CONTRAST_UNAIMED, ()
        plays = [replayed(problem, ledger, level, action)]
        for r in range(domain.robustness_replays or 0):
            noisy_level, noisy_action = domain.actions.noisy(level, action, random.Random(f"contrast/{contrast}/{r}"))
            plays.append(replayed(problem, ledger, noisy_level, noisy_action))
        solved = sum(bool(p.trace.solved) for p in plays)
        if solved:
            return settings.CONTRAST_SOLVES, ()
        named = term.text or f"contrast({contrast}, {counterpart})"
        notes.append(f"{named}: {contrast} acted on as {counterpart} solves 0 of {len(plays)} plays")
    return None, tuple(notes)
