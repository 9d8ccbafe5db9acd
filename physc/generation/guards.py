"""Obstacles against what a task must not allow: forbidden direct hits and shortcuts.

`cannotHit(p, b, d)` of the player's object `p` asks for `pathObstructed`: once the search
has a robust solution, every action the domain aims at `b` (`actions_at`) that hits `b`
from a forbidden side is blocked by an obstacle (the domain's `blocker`, a static bar)
across the flight before the hit, a little further back each time, kept only when the
solution still realises the sequence. Then the shortcut guard does the same for actions
at other objects that solve the task without the sequence, at most `shortcuts` of them.
An obstacle is a placed object of the layout like any other, role "obstacle".
"""

from __future__ import annotations

import math

import attrs

from physc.compiler.concrete_layout import PlacedObject
from physc.generation import placing
from physc.generation.attempt import Attempt

BACKS = (0.9, 1.3, 1.8, 2.4, 3.0, 3.7, 4.5)  # layout units back along the flight from the hit, tried in turn
SHORTCUT_BACKS = (0.9, 1.3, 1.8)


def breaks(attempt: Attempt, restriction) -> bool:
    """Whether `attempt`'s play breaks `restriction`."""
    return any(v.restriction == restriction.text for v in attempt.trace.violations)


class Guards:
    """The search's obstacles and distractors (mixed into physc.generation.search.Search):
    each step takes a layout and returns the layout it makes, with what it added."""

    def obstruct(self, layout, solution: Attempt) -> tuple[object, list[str]] | None:
        """`layout` with every action at a restricted object that breaks its cannotHit
        blocked, and the obstacles' descriptions; None when one cannot be blocked."""
        added: list[str] = []
        for restriction in self.scenario.restrictions:
            if restriction.name != "cannotHit" or restriction.objects[0] not in self.players:
                continue
            for _ in range(self.settings.obstacles):
                offending = self.offending(layout, restriction)
                if offending is None:
                    break
                blocked = self.block(layout, offending, restriction.objects[0], solution, BACKS, lambda a: breaks(a, restriction), len(added))
                if blocked is None:
                    return None
                layout, note = blocked
                added.append(note)
            if self.offending(layout, restriction) is not None:
                return None
        return layout, added

    def offending(self, layout, restriction) -> Attempt | None:
        """An action at the restricted object that breaks the restriction in `layout`."""
        for label, action in self.domain.actions_at(self.level_of(layout), restriction.objects[1]):
            attempt = attrs.evolve(self.simulate(layout, action), label=label)
            if breaks(attempt, restriction):
                return attempt
        return None

    def block(self, layout, offending: Attempt, actor: str, solution: Attempt, backs, bad, count: int):
        """(`layout` with an obstacle across `actor`'s flight in `offending` after which the
        solution still works and `bad` no longer holds of the offending action, its
        description), or None."""
        blocker = self.domain.blocker
        if blocker is None or actor not in offending.trace.names:
            return None
        trace = offending.trace
        contact = next((c.time for c in trace.contacts if actor in (c.a, c.b)), None)
        end = int(contact / trace.dt) if contact is not None else trace.states.shape[0]
        path = trace.states[:end, trace.index(actor), :]
        name = f"obstacle{count + 1}"
        for back in backs:
            at = self.back_along(path, back)
            if at is None:
                continue
            x, y, vx, vy = at
            angle = (math.degrees(math.atan2(vy, vx)) + 180.0) % 180.0 - 90.0  # across the flight
            obstacle = PlacedObject(name, "obstacle", blocker, None, round(x, 5), round(y, 5), round(angle, 3), self.domain.blocker_length, self.domain.blocker_thickness)
            candidate = attrs.evolve(layout, objects=layout.objects + (obstacle,))
            if not placing.consistent(candidate, self.parameters, {name}):
                continue
            if not self.simulate(candidate, solution.action).fidelity.valid:
                continue
            if bad(self.simulate(candidate, offending.action)):
                continue
            return candidate, f"{name} across the flight of {offending.label}, {back:g} back"
        return None

    def back_along(self, path, distance: float):
        """(x, y, vx, vy) in layout units `distance` back along `path` from its end."""
        travelled = 0.0
        rows = [row for row in path if not math.isnan(row[0])]
        for later, earlier in zip(reversed(rows), list(reversed(rows))[1:]):
            travelled += math.hypot(later[0] - earlier[0], later[1] - earlier[1]) * self.scale
            if travelled >= distance:
                return earlier[0] * self.scale, earlier[1] * self.scale, earlier[3], earlier[4]
        return None

    def guard(self, layout, solution: Attempt, count: int) -> tuple[object, list[str]]:
        """`layout` with shortcuts blocked (actions at other objects than the first target
        that solve the task), each by an obstacle that keeps the solution holding up, at most
        `shortcuts` tried; and the obstacles' descriptions. `count`: obstacles so far."""
        first = self.interactions[0].objects[1] if len(self.interactions[0].objects) > 1 else None
        actor = next((o.name for o in self.scenario.objects if o.name in self.players), None)
        added: list[str] = []
        if self.domain.blocker is None or actor is None:
            return layout, added
        left = self.settings.shortcuts
        for obj in layout.objects:
            if left <= 0:
                break
            if obj.name == first or obj.name in self.frame.fixed:
                continue
            for label, action in self.domain.actions_at(self.level_of(layout), obj.name):
                attempt = attrs.evolve(self.simulate(layout, action), label=label)
                if not attempt.trace.solved or attempt.fidelity.valid:
                    continue
                left -= 1
                shortcut = lambda a: a.trace.solved and not a.fidelity.valid  # noqa: E731
                blocked = self.block(layout, attempt, actor, solution, SHORTCUT_BACKS, shortcut, count + len(added))
                if blocked is not None and self.holds_up(solution, blocked[0]):
                    layout = blocked[0]
                    added.append(blocked[1])
                break
        return layout, added

    def distract(self, layout, solution: Attempt) -> tuple[object, list[str]]:
        """`layout` with the domain's distractors, each kept only if the level still stands,
        the solution still holds up, and it is no way to solve the task; and their names."""
        added: list[str] = []
        for index in range(self.domain.distractor_count(self.rng, self.settings.distractors)):
            for obj in self.domain.distractors(layout, index + 1, self.rng):
                candidate = attrs.evolve(layout, objects=layout.objects + (obj,))
                if not placing.consistent(candidate, self.parameters, {obj.name}):
                    continue
                if not self.domain.valid(self.level_of(candidate), solution.action):  # it covers the player's action
                    continue
                if not self.simulate(candidate, solution.action).fidelity.valid:
                    continue
                if not self.evaluator.run(lambda: self.domain.stability(self.level_of(candidate)))[0]:
                    continue
                if not self.holds_up(solution, candidate):
                    continue
                level = self.level_of(candidate)
                if any(self.play(level, action).trace.solved for _, action in self.domain.actions_at(level, obj.name)):
                    continue
                layout = candidate
                added.append(obj.name)
                break
        return layout, added
