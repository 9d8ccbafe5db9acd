"""Moving and reshaping the objects of the satisfier's level, as its repairs do.

The primitives that the repair proposals (repairs.py, impetus.py), the firming of a
fragile solution (robustness.py) and the sequential builder (build.py) change a level
with: an object put elsewhere with its own support (`move`); a structure, what rests on
what and the platforms joined to them, shifted as one (`structure`, `shift`); the world
beyond a cut brought nearer, the flat platforms across the cut shorter so that joints and
supports stay as they were (`world_beyond`, `brought_back`); a ledge cut to end at the
block on it (`ledge_ends_at`). And what the declared sequence says of an object: which way
it rolls or slides, what last hit it. A mixin of `Satisfier` (satisfy.py), whose level,
layout edges and supports it reads; a changed level is offered only where
`Satisfier.consistent` holds.
"""

from __future__ import annotations

import attrs
import networkx as nx

from physc.domains.angrybirds.attempt import _along, _span
from physc.domains.angrybirds.catalogue import PLATFORM_BASE, by_prefab, extent
from physc.domains.angrybirds.game import BIRD
from physc.compiler.layout_rules import last_hit_on
from physc.domains.angrybirds.level import Level, LevelObject, level_number
from physc.domains.angrybirds.world import GROUND_TOP

MIN_PLATFORM = 0.64  # a platform the close-the-gap repair shortens stays at least this long


class Placing:
    """How the satisfier moves, shifts and shortens objects (mixed into `Satisfier`)."""

    # ---- moving objects ----------------------------------------------------------------------
    def with_objects(self, changed: dict[str, LevelObject]) -> Level:
        return attrs.evolve(self.level, objects=tuple(changed.get(o.name, o) for o in self.level.objects))

    def move(self, name: str, x: float, y: float) -> dict[str, LevelObject] | None:
        """The objects changed by putting `name`'s centre at (x, y): with its own support;
        on the ground or a shared surface only sideways; a static object alone."""
        objects = self.objects
        obj = objects[name]
        if name in self.on_ground or (name in self.support_of and name not in self.own_support):
            y = obj.y  # it rests on the ground or on a surface others use: slide it along
        dx, dy = x - obj.x, y - obj.y
        if abs(dx) < 1e-6 and abs(dy) < 1e-6:
            return None
        changed = {name: attrs.evolve(obj, x=level_number(x), y=level_number(y))}
        support = self.own_support.get(name)
        if support is not None and support in objects:
            s = objects[support]
            if s.y + dy < GROUND_TOP:
                return None
            changed[support] = attrs.evolve(s, x=level_number(s.x + dx), y=level_number(s.y + dy))
        return changed

    def moved_level(self, name: str, x: float, y: float) -> Level | None:
        """The level with `name` put at (x, y) as `move` does, if every layout edge still
        holds there (what moved judged as moved)."""
        moved = self.move(name, x, y)
        if moved is None:
            return None
        candidate = self.with_objects(moved)
        return candidate if self.consistent(candidate, frozenset(moved)) else None

    def structure(self, name: str) -> set[str]:
        """`name` with everything joined to it by resting and touching: its supports, the
        platforms joined to them, and what rests on any of those (not the ground)."""
        if name not in self.joints:
            return {name}
        return set(nx.node_connected_component(self.joints, name)) & set(self.objects)  # of the scene (a stage's holds less)

    def move_structure(self, name: str, x: float, y: float, actor: str) -> dict[str, LevelObject] | None:
        """The objects changed by putting `name`'s centre at (x, y) together with its whole
        structure (a support joined to further platforms cannot move alone), if `actor`,
        which must reach `name`, is not part of it. Only sideways if any of it rests on the ground."""
        members = self.structure(name)
        objects = self.objects
        if actor in members or len(members) <= 1 + (name in self.own_support):
            return None
        obj = objects[name]
        return self.shift(members, x - obj.x, y - obj.y)

    def shift(self, members: set[str], dx: float, dy: float, objects: dict | None = None) -> dict[str, LevelObject] | None:
        """The objects changed by moving `members` together by (dx, dy): only sideways if
        any of them rests on the ground; None if that leaves nothing to do or sinks one.
        Of `objects` (by name) if given, else of the current level."""
        objects = self.objects if objects is None else objects
        if members & self.on_ground:
            dy = 0.0
        if abs(dx) < 1e-6 and abs(dy) < 1e-6:
            return None
        changed = {m: attrs.evolve(objects[m], x=level_number(objects[m].x + dx), y=level_number(objects[m].y + dy)) for m in sorted(members)}
        if min(o.y - extent(o)[1] / 2 for o in changed.values()) < GROUND_TOP - 1e-6:
            return None
        return changed

    def world_beyond(self, cut: float, distance: float, sign: float) -> Level | None:
        """The level with everything beyond `cut` (along the heading `sign`) shifted
        `distance` back towards it, the flat platforms across the cut shorter by as much;
        None if a platform would get too short or something else spans the cut, or the
        result breaks a layout edge."""
        changed = {}
        for name, obj in self.objects.items():
            near, far = _along(obj, sign)
            if name == BIRD or far <= cut:
                continue
            if near >= cut:
                changed[name] = attrs.evolve(obj, x=level_number(obj.x - sign * distance))
            elif obj.element == "Platform" and not obj.rotation and extent(obj)[0] - distance >= MIN_PLATFORM:
                length = extent(obj)[0] - distance
                changed[name] = attrs.evolve(obj, x=level_number(obj.x - sign * distance / 2), scale_x=level_number(length / PLATFORM_BASE))
            else:
                return None
        if not changed:
            return None
        candidate = self.with_objects(changed)
        return candidate if self.consistent(candidate, frozenset(changed)) else None

    def brought_back(self, goal: str, cut: float, distance: float, sign: float) -> tuple[bool, Level] | None:
        """`goal` `distance` nearer, against the heading `sign`: with the world beyond `cut`
        (`world_beyond`), or else, when the world cannot come that far (a surface under the
        cut would get too short), the goal alone, along its surface or with its own support
        (what came after it is then repaired in its turn). (whether the world came, the
        level), or None."""
        candidate = self.world_beyond(cut, distance, sign)
        if candidate is not None:
            return True, candidate
        candidate = self.moved_level(goal, self.objects[goal].x - sign * distance, self.objects[goal].y)
        return None if candidate is None else (False, candidate)

    def ledge_ends_at(self, faller: str, support: str, pushed: str, dx: float = 0.0):
        """The changed objects for `faller` moved `dx` along its support, and the support
        ending just beyond it on the side it is pushed to (the platform shorter at that end
        only), or None: a smaller push then takes it over the edge. Nothing else may rest
        beyond it there."""
        objects = self.objects
        platform, block = objects[support], objects[faller]
        if platform.element != "Platform" or platform.rotation:
            return None
        left, right = _span(platform)
        b_left, b_right = (end + dx for end in _span(block))
        if any(self.support_of.get(n) == support and n != faller and (_span(o)[0] > b_right if pushed == "right" else _span(o)[1] < b_left) for n, o in objects.items()):
            return None
        new_left, new_right = (left, b_right + 0.02) if pushed == "right" else (b_left - 0.02, right)
        if new_right - new_left < MIN_PLATFORM or b_left < left or b_right > right or (right - new_right) + (new_left - left) < 0.1:
            return None
        changed = {support: attrs.evolve(platform, x=level_number((new_left + new_right) / 2), scale_x=level_number((new_right - new_left) / PLATFORM_BASE))}
        if dx:
            changed[faller] = attrs.evolve(block, x=level_number(block.x + dx))
        return changed

    # ---- what the declared sequence says of an object ----------------------------------------
    def heading_of(self, mover: str, index: int) -> str | None:
        """The direction `mover` last rolled or slid in, up to interaction `index` (itself included)."""
        motion = self.last_motion(mover, index + 1)
        heading = None if motion is None else self.scenario.interactions[motion[0]].directions[0]
        return heading if heading in ("left", "right") else None

    def heading_after(self, name: str, index: int) -> str | None:
        """The direction `name` first rolls or slides in, from interaction `index` on."""
        return next(
            (t.directions[0] for t in self.scenario.interactions[index:] if t.name in ("roll", "slide") and t.objects[0] == name and t.directions[0] in ("left", "right")),
            None,
        )

    def last_motion(self, name: str, index: int) -> tuple[int, str] | None:
        """Where in the sequence and how (roll or slide) `name` last moved before
        interaction `index`, if it did."""
        moves = [(j, t.name) for j, t in enumerate(self.scenario.interactions[:index]) if t.name in ("roll", "slide") and t.objects[0] == name]
        return moves[-1] if moves else None

    def hitter_of(self, name: str, index: int) -> str | None:
        """The actor of the latest declared hit on `name` before interaction `index`."""
        hit = last_hit_on(self.scenario.interactions[:index], name)
        return hit.objects[0] if hit else None

    def concrete_of(self, name: str) -> str | None:
        """The concrete object (`squareHole`, `circle`, …) that `name` is now."""
        obj = self.objects.get(name)
        return None if obj is None else by_prefab(obj.type).name
