"""Obstacles against what a task must not allow: forbidden direct hits and shortcuts.

`cannotHit(p, b, d)` of the player's object `p` asks for `pathObstructed`: once the search
has a robust solution, every action the domain aims at `b` (`search.actions_at`) that hits `b`
from a forbidden side is blocked by an obstacle (the domain's `search.blocker`, a static bar)
in the flight before the hit, a little further back each time, kept only when the solution
still realises the sequence. The bar lies at an angle the domain's own levels lay one at
(`search.blocker_angles`: Science Birds' walls and roofs) where that crosses the flight, else
square across it. Then the shortcut guard does the same for actions
at other objects that solve the task without the sequence, at most `shortcuts` of them.
An obstacle is a placed object of the layout like any other, role "obstacle". A cannotHit of
what a later action of the player hits (a second shot at the pig the first must not hit) is
judged in the solution's play, not guarded: a bar would stop that action too.
"""

from __future__ import annotations

import math
import random
from collections.abc import Callable, Sequence

import attrs
import numpy as np

from physc.compiler.concrete_layout import ConcreteLayout, PlacedObject
from physc.dsl.scenario import TermIR
from physc.search import placing
from physc.search.attempt import Attempt
from physc.search.problem import Ledger, Problem, replayed, simulate
from physc.search.strengthen import holds_up

BACKS = (0.9, 1.3, 1.8, 2.4, 3.0, 3.7, 4.5)  # layout units back along the flight from the hit, tried in turn
SHORTCUT_BACKS = (0.9, 1.3, 1.8)


def breaks(attempt: Attempt, restriction: TermIR) -> bool:
    """Whether `attempt`'s play breaks `restriction`."""
    return any(v.restriction == restriction.text for v in attempt.trace.violations)


def obstruct(
    problem: Problem, ledger: Ledger, layout: ConcreteLayout, solution: Attempt
) -> tuple[ConcreteLayout, list[str]] | None:
    """`layout` with every action at a restricted object that breaks its cannotHit
    blocked, and the obstacles' descriptions; None when one cannot be blocked."""
    added: list[str] = []
    for restriction in problem.scenario.restrictions:
        if restriction.name != "cannotHit" or restriction.objects[0] not in problem.players:
            continue
        if struck_later(problem, restriction):
            continue
        for _ in range(problem.settings.obstacles):
            culprit = offending(problem, ledger, layout, restriction)
            if culprit is None:
                break
            blocked = block(
                problem,
                ledger,
                layout,
                culprit,
                restriction.objects[0],
                solution,
                BACKS,
                lambda a, restriction=restriction: breaks(a, restriction),
                len(added),
            )
            if blocked is None:
                return None
            layout, note = blocked
            added.append(note)
        if offending(problem, ledger, layout, restriction) is not None:
            return None
    return layout, added


def struck_later(problem: Problem, restriction: TermIR) -> bool:
    """Whether another of the player's objects hits what `restriction` (a cannotHit) shields in
    the sequence (a later shot at it, as when a first one clears its way): a bar against the
    restricted object's direct hits would bar that one's too, so the restriction is judged in
    the solution's play and not guarded (the `blocks` property says what stands in the way)."""
    actor, shielded = restriction.objects[0], restriction.objects[1]
    return any(
        t.name == "hit" and t.objects[1:2] == (shielded,) and t.objects[0] in problem.players - {actor}
        for t in problem.interactions
    )


def offending(problem: Problem, ledger: Ledger, layout: ConcreteLayout, restriction: TermIR) -> Attempt | None:
    """An action at the restricted object that breaks the restriction in `layout`."""
    for label, action in problem.domain.search.actions_at(problem.level_of(layout), restriction.objects[1]):
        attempt = attrs.evolve(simulate(problem, ledger, layout, action), label=label)
        if breaks(attempt, restriction):
            return attempt
    return None


def block(
    problem: Problem,
    ledger: Ledger,
    layout: ConcreteLayout,
    offending: Attempt,
    actor: str,
    solution: Attempt,
    backs: Sequence[float],
    bad: Callable[[Attempt], bool],
    count: int,
) -> tuple[ConcreteLayout, str] | None:
    """(`layout` with an obstacle across `actor`'s flight in `offending` after which the
    solution still works and `bad` no longer holds of the offending action, its
    description), or None."""
    blocker = problem.domain.search.blocker
    if blocker is None or actor not in offending.trace.names:
        return None
    trace = offending.trace
    contact = next((c.time for c in trace.contacts if actor in (c.a, c.b)), None)
    end = int(contact / trace.dt) if contact is not None else trace.states.shape[0]
    path = trace.states[:end, trace.index(actor), :]
    name = f"obstacle{count + 1}"
    for back in backs:
        at = back_along(path, back, problem.scale)
        if at is None:
            continue
        x, y, vx, vy = at
        for angle in angles(math.degrees(math.atan2(vy, vx)), problem.domain.search.blocker_angles):
            obstacle = PlacedObject(
                name,
                "obstacle",
                blocker,
                None,
                round(x, 5),
                round(y, 5),
                round(angle, 3),
                problem.domain.search.blocker_length,
                problem.domain.search.blocker_thickness,
            )
            candidate = barred(problem, ledger, layout, obstacle, solution, offending, bad)
            if candidate is not None:
                return candidate, f"{name} at {angle:g}° in the flight of {offending.label}, {back:g} back"
    return None


def barred(
    problem: Problem,
    ledger: Ledger,
    layout: ConcreteLayout,
    obstacle: PlacedObject,
    solution: Attempt,
    offending: Attempt,
    bad: Callable[[Attempt], bool],
) -> ConcreteLayout | None:
    """`layout` with `obstacle`, where it fits the layout's QSRs, the solution still realises the
    sequence and `bad` no longer holds of the offending action's play; else None."""
    candidate = attrs.evolve(layout, objects=layout.objects + (obstacle,))
    if not placing.consistent(candidate, problem.parameters, {obstacle.name}):
        return None
    if not simulate(problem, ledger, candidate, solution.action).fidelity.valid:
        return None
    if bad(simulate(problem, ledger, candidate, offending.action)):
        return None
    return candidate


ROOF_GAPS = (1.0, 3.0, 6.0)  # the layout's clearances between a shielded object's top and a roof, tried in turn


def roof(
    problem: Problem,
    ledger: Ledger,
    layout: ConcreteLayout,
    name: str,
    solution: Attempt,
    offending: Attempt,
    bad: Callable[[Attempt], bool],
    count: int,
) -> tuple[ConcreteLayout, str] | None:
    """(`layout` with a bar laid level over `name`, a roof, the shelter Phy-Q's levels build over
    a pig that only one way reaches, after which the solution still works and `bad` no longer
    holds of `offending`; its description), or None. A roof bars every shot that comes down on
    `name`, where a bar in one flight bars that one."""
    blocker = problem.domain.search.blocker
    placed = next((o for o in layout.objects if o.name == name), None)
    if blocker is None or placed is None:
        return None
    left, _, right, top = placing.box(placed)
    thickness = problem.domain.search.blocker_thickness
    length = max(problem.domain.search.blocker_length, right - left)
    label = f"obstacle{count + 1}"
    for gap in ROOF_GAPS:
        y = top + gap * problem.parameters.clearance + thickness / 2
        bar = PlacedObject(
            label, "obstacle", blocker, None, round((left + right) / 2, 5), round(y, 5), 0.0, length, thickness
        )
        candidate = barred(problem, ledger, layout, bar, solution, offending, bad)
        if candidate is not None:
            return candidate, f"{label} a roof over {name}, {gap:g} clearances above it"
    return None


ACROSS = 0.5  # the least share of a bar's length that lies across the flight, |sin| of the angle between them


def angles(heading: float, preferred: Sequence[float]) -> list[float]:
    """The angles a bar across a flight heading `heading` degrees is tried at: the domain's own
    (`preferred`) that lie across it by ACROSS at least, the nearest to square first, then square
    across it, in (−90°, 90°]."""
    across = (heading + 180.0) % 180.0 - 90.0
    crossing = [a for a in preferred if abs(math.sin(math.radians(a - heading))) >= ACROSS]
    crossing.sort(key=lambda a: -abs(math.sin(math.radians(a - heading))))
    return [*crossing, *([] if any(abs(math.sin(math.radians(a - across))) < 1e-6 for a in crossing) else [across])]


def back_along(path: np.ndarray, distance: float, scale: float) -> tuple[float, float, float, float] | None:
    """(x, y, vx, vy) in layout units `distance` back along `path` from its end."""
    travelled = 0.0
    rows = [row for row in path if not math.isnan(row[0])]
    for later, earlier in zip(reversed(rows), list(reversed(rows))[1:], strict=False):  # each row and the one before
        travelled += math.hypot(later[0] - earlier[0], later[1] - earlier[1]) * scale
        if travelled >= distance:
            return earlier[0] * scale, earlier[1] * scale, earlier[3], earlier[4]
    return None


def _shortcut(attempt: Attempt) -> bool:
    """Whether `attempt` solves the task without the sequence (a shortcut the guard blocks)."""
    return attempt.trace.solved and not attempt.fidelity.valid


def first_player(problem: Problem) -> str | None:
    """The first of the player's objects the scenario declares: whose flight a guard bars."""
    return next((o.name for o in problem.scenario.objects if o.name in problem.players), None)


def guard(
    problem: Problem, ledger: Ledger, layout: ConcreteLayout, solution: Attempt, count: int
) -> tuple[ConcreteLayout, list[str]]:
    """`layout` with shortcuts blocked (actions at other objects than the first target
    that solve the task), each by an obstacle that keeps the solution holding up, at most
    `shortcuts` tried; and the obstacles' descriptions. `count`: obstacles so far."""
    lead = problem.interactions[0].objects
    first = (
        lead[1] if len(lead) > 1 else next(iter(problem.domain.reach_targets(problem.scenario)), None)
    )  # (after a tap: what the bird hits)
    actor = first_player(problem)
    added: list[str] = []
    if problem.domain.search.blocker is None or actor is None:
        return layout, added
    left = problem.settings.shortcuts
    for obj in layout.objects:
        if left <= 0:
            break
        if obj.name == first or obj.name in problem.supports.fixed:
            continue
        for label, action in problem.domain.search.actions_at(problem.level_of(layout), obj.name):
            attempt = attrs.evolve(simulate(problem, ledger, layout, action), label=label)
            if not attempt.trace.solved or attempt.fidelity.valid:
                continue
            left -= 1
            blocked = block(
                problem, ledger, layout, attempt, actor, solution, SHORTCUT_BACKS, _shortcut, count + len(added)
            )
            if blocked is not None and holds_up(problem, ledger, solution, blocked[0]):
                layout = blocked[0]
                added.append(blocked[1])
            break
    return layout, added


def distract(
    problem: Problem, ledger: Ledger, rng: random.Random, layout: ConcreteLayout, solution: Attempt
) -> tuple[ConcreteLayout, list[str]]:
    """`layout` with the domain's distractors, each kept only if the level still stands,
    the solution still holds up, and it is no way to solve the task; and their names."""
    added: list[str] = []
    for index in range(problem.domain.search.distractor_count(rng, problem.settings.distractors)):
        for obj in problem.domain.search.distractors(layout, index + 1, rng):
            candidate = attrs.evolve(layout, objects=layout.objects + (obj,))
            if not placing.consistent(candidate, problem.parameters, {obj.name}):
                continue
            if not problem.domain.actions.valid(
                problem.level_of(candidate), solution.action
            ):  # it covers the player's action
                continue
            if not simulate(problem, ledger, candidate, solution.action).fidelity.valid:
                continue
            if not ledger.evaluator.run(
                lambda candidate=candidate: problem.domain.stability(problem.level_of(candidate))
            )[0]:
                continue
            if not holds_up(problem, ledger, solution, candidate):
                continue
            level = problem.level_of(candidate)
            if any(
                replayed(problem, ledger, level, action).trace.solved
                for _, action in problem.domain.search.actions_at(level, obj.name)
            ):
                continue
            layout = candidate
            added.append(obj.name)
            break
    return layout, added
