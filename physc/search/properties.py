"""Properties (language version 2): what must fail for a task to test what its scenario says.

Phy-Q's non-greedy, clearing-path and timing scenarios are defined by what does not work: the
greedy order, the direct shot before the path is clear, the shot at another time. A scenario
declares it with a restriction, and this step checks it on the finished level against every
action the player could send (the domain's `actions.sweep`: Science Birds' every release angle
half a degree apart, and the search's candidates), not only the solution's, in every reading
of the world that can change a play (physc.worlds.under_readings):

* `nonGreedy(a, b)`: once b is taken first (by the first actions of the sweep that take b and
  not a, at most GREEDY_FIRSTS of them), no next action takes a.
* `blocks(a, b)`: in the level as laid out, no first action takes b. The first action that does
  is barred by a roof over b where one bars it (physc.search.guards.roof: the shelter Phy-Q's
  levels build), each other by an obstacle in its flight (the cannotHit guard's), each kept only
  where the solution still holds up; at most the settings' `obstacles` of them.
* `timed(a)`: a's part of the solution (its `wait`) solves the task only within TIMING_WINDOW
  seconds of its own time: taken once the level rests, or at any wait on a TIMING_STEP grid up
  to TIMING_HORIZON more than TIMING_WINDOW away from it that the world can take it at (the
  domain's `retimed` says where it takes it instead), it does not solve the task.

A layout whose property fails is given up (settings.PROPERTY_BROKEN), and the note that says
which action broke it is the search's; one that holds adds a note to the task's repairs.
"""

from __future__ import annotations

from itertools import islice

import attrs

from physc.compiler.concrete_layout import ConcreteLayout
from physc.dsl.scenario import TermIR
from physc.search import guards, settings
from physc.search.attempt import Attempt
from physc.search.problem import Ledger, Problem, play_in, simulate
from physc.search.strengthen import holds_up
from physc.simulation.ending import Ending
from physc.simulation.trace import Trace
from physc.worlds import under_readings

TIMING_WINDOW = 0.5  # seconds either side of a timed action's own time within which it may work (issue 73)
TIMING_STEP = 0.25  # seconds between the other times a timed action is tried at
TIMING_HORIZON = 4.0  # seconds after the action before: the latest other time tried (then: once the level rests)
GREEDY_FIRSTS = 2  # first actions that take the later target first, each followed by a whole sweep


@attrs.frozen
class Checked:
    """What the properties' step found: why the layout is given up (None: every property
    holds), a note per property that holds, and the layout with any obstacles it added."""

    why: str | None
    notes: tuple[str, ...]
    layout: ConcreteLayout
    obstacles: tuple[str, ...] = ()


def properties(problem: Problem, ledger: Ledger, layout: ConcreteLayout, solution: Attempt) -> Checked:
    """Every property restriction of the scenario checked in `layout` (module docstring)."""
    notes: list[str] = []
    obstacles: list[str] = []
    for term in problem.scenario.restrictions:
        named = term.text or f"{term.name}({', '.join(term.objects)})"
        if term.name == "blocks":
            why, note, layout, added = blocks(problem, ledger, layout, solution, term, obstacles)
            obstacles += added
        elif term.name == "nonGreedy":
            why, note = non_greedy(problem, ledger, problem.level_of(layout), term)
        elif term.name == "timed":
            why, note = timed(problem, ledger, problem.level_of(layout), solution, term)
        else:
            continue
        if why is not None:
            return Checked(why, (f"{named}: {note}",), layout)
        notes.append(f"{named}: {note}")
    return Checked(None, tuple(notes), layout, tuple(obstacles))


def plays(problem: Problem, ledger: Ledger, level: object, action: object) -> list[Trace]:
    """`action` played in `level` to its outcome, in every reading of the world that can change it."""
    run = play_in(problem, ledger, level, action, ending=Ending.OUTCOME)
    return [trace for _, trace in under_readings(problem.domain.world, run)]


def taking(problem: Problem, ledger: Ledger, level: object, actions, target: str, spare: str | None = None):
    """(label, action, its world's own trace) of each of `actions`, in turn, that destroys
    `target` in some reading (with `spare`: and leaves `spare` standing there)."""
    for label, action in actions:
        traces = plays(problem, ledger, level, action)
        if any(target in t.destroyed and (spare is None or spare not in t.destroyed) for t in traces):
            yield label, action, traces[0]


def first_taking(problem: Problem, ledger: Ledger, level: object, actions, target: str, spare: str | None = None):
    """The first of `taking`'s (label, action, trace); None if no action destroys `target`."""
    return next(taking(problem, ledger, level, actions, target, spare), None)


def blocks(
    problem: Problem, ledger: Ledger, layout: ConcreteLayout, solution: Attempt, term: TermIR, so_far: list[str]
) -> tuple[str | None, str, ConcreteLayout, list[str]]:
    """`blocks(a, b)`: (why given up or None, the note, the layout, the obstacles added)."""
    actions, a, b = problem.domain.actions, term.objects[0], term.objects[1]
    added: list[str] = []
    roofed = False
    for _ in range(problem.settings.obstacles + 1):
        level = problem.level_of(layout)
        swept = actions.sweep(level, problem.scenario, at=b)
        if not swept:
            return settings.PROPERTY_UNCHECKED, "the domain cannot sweep the first action", layout, added
        found = first_taking(problem, ledger, level, swept, b)
        if found is None:
            barred = f", {len(added)} obstacle(s) barring the others" if added else ""
            return None, f"no first action of {len(swept)} swept takes {b}{barred}", layout, added
        label, action, _ = found
        offending = attrs.evolve(simulate(problem, ledger, layout, action), label=label)
        actor = next((c.a if c.a in problem.players else c.b for c in offending.trace.contacts), None)
        actor = actor if actor in problem.players else next(iter(sorted(problem.players)), "")
        taken = lambda attempt: b in attempt.trace.destroyed  # noqa: E731 (the one test both obstacles use)
        count = len(so_far) + len(added)
        blocked = None if roofed else guards.roof(problem, ledger, layout, b, solution, offending, taken, count)
        roofed = True  # first a shelter, then a bar in the flight
        if blocked is None or not holds_up(problem, ledger, solution, blocked[0]):
            blocked = guards.block(problem, ledger, layout, offending, actor, solution, guards.BACKS, taken, count)
            if blocked is None or not holds_up(problem, ledger, solution, blocked[0]):
                return settings.PROPERTY_BROKEN, f"{label} takes {b} while {a} still bars the way", layout, added
        layout = blocked[0]
        added.append(blocked[1])
    return settings.PROPERTY_BROKEN, f"{b} is still taken by a first action after {len(added)} obstacles", layout, added


def non_greedy(problem: Problem, ledger: Ledger, level: object, term: TermIR) -> tuple[str | None, str]:
    """`nonGreedy(a, b)`: (why given up or None, the note)."""
    actions, a, b = problem.domain.actions, term.objects[0], term.objects[1]
    firsts = actions.sweep(level, problem.scenario, at=b)
    if not firsts:
        return settings.PROPERTY_UNCHECKED, "the domain cannot sweep the first action"
    greedy = list(islice(taking(problem, ledger, level, firsts, b, spare=a), GREEDY_FIRSTS))
    if not greedy:
        return None, f"no first action takes {b} and spares {a}"
    for label, action, trace in greedy:
        after = actions.sweep(level, problem.scenario, before=action, after=trace, at=a)
        taken = first_taking(problem, ledger, level, after, a)
        if taken is not None:
            return settings.PROPERTY_BROKEN, f"once {b} is taken first ({label}), {taken[0]} takes {a}"
    return None, f"once {b} is taken first ({len(greedy)} ways tried), no next action takes {a}"


def timed(problem: Problem, ledger: Ledger, level: object, solution: Attempt, term: TermIR) -> tuple[str | None, str]:
    """`timed(a)`: (why given up or None, the note)."""
    actions, actor = problem.domain.actions, term.objects[0]
    own = actions.timing(solution.action, actor)
    if own is None:
        return settings.PROPERTY_BROKEN, f"{actor}'s action is not timed"
    grid = [k * TIMING_STEP for k in range(int(TIMING_HORIZON / TIMING_STEP) + 1)]
    others = sorted((w for w in grid if abs(w - own) > TIMING_WINDOW + 1e-9), key=lambda w: abs(w - own))
    tried = 0
    for wait in [None, *others]:
        action = actions.retimed(solution.action, actor, wait)
        if action is None:
            return settings.PROPERTY_UNCHECKED, f"the domain cannot retime {actor}'s action"
        if wait is not None and actions.timing(action, actor) != wait:
            continue  # a time the world cannot take it at (it takes it at another, in the grid or the window)
        tried += 1
        if any(trace.solved for trace in plays(problem, ledger, level, action)):
            when = "once the level rests" if wait is None else f"after {wait:g} s"
            return settings.PROPERTY_BROKEN, f"{actor}'s action taken {when} solves the task too (its own: {own:g} s)"
    return None, (
        f"{actor}'s action solves the task only within {TIMING_WINDOW:g} s of {own:g} s "
        f"({tried} other times fail, once the level rests among them)"
    )
