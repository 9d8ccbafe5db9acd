"""The satisfier's repair proposals for an interaction that lacked force.

An attacker that did not destroy its target, a block that did not roll, slide or fall:
what was there happened, too weakly. The proposals here change what the objects are or
where the motion starts, within the concrete objects and materials the scenario allows:

* `destroy(a, b)`: the attacker is made stronger or the target weaker (a smaller pig,
  a stone block, a larger circle), or a falling attacker starts higher, or the target
  comes back to where the attacker moves fastest (`strengthen`, `meet_sooner`);
* `slide`: a block that slides (an ice square for a triangle, a wooden triangle for
  a square; a wooden square tips over), or the slider of ice; `roll` and `slide`: a
  lighter mover, a heavier hitter, the mover next to its surface (`set_moving`);
* `fall`: a lighter faller, a heavier or faster hitter, the faller at the edge of its
  support, or the support ending at it (`push_off`, `to_the_edge`).

Offered by `Repairs.proposals` (repairs.py) and judged, like every proposal, by
simulation in a stage of the sequential search (build.py).
"""

from __future__ import annotations

import attrs
import numpy as np

from physc.domains.angrybirds.attempt import Attempt, _along, _span
from physc.domains.angrybirds.catalogue import extent, shape
from physc.domains.angrybirds.game import BIRD
from physc.compiler.layout_rules import OPPOSITE, last_hit_on
from physc.domains.angrybirds.level import level_number
from physc.domains.angrybirds.repairs import SETTLE_MOTION

STRIKE_AFTER = (1.6, 1.0)  # units a rolling or sliding hitter travels before it strikes a block to push off


class Impetus:
    """The satisfier's repair proposals that make an interaction forceful enough (mixed
    into `Satisfier`): each yields (description, level) alternatives."""

    def strengthen(self, declared, index: int, attempt: Attempt):
        """destroy(a, b) did not happen: a smaller pig, a heavier or larger attacker, a
        falling attacker from higher; an attacker set moving by a block (not the bird),
        struck harder (its hitter of stone, or falling from higher), or meeting b sooner,
        where it moves fastest (`meet_sooner`)."""
        attacker, target = declared.objects
        yield from self.swap(target, "pigSmall", f"destroy({attacker}, {target}): a small pig")
        yield from self.material(attacker, "stone", f"destroy({attacker}, {target}): {attacker} of stone")
        yield from self.swap(attacker, "circle", f"destroy({attacker}, {target}): a larger circle")
        yield from self.raised(attacker, f"destroy({attacker}, {target}): {attacker} falls from higher")
        hitter = self.hitter_of(attacker, index)
        if hitter is not None and hitter != BIRD:
            yield from self.material(hitter, "stone", f"destroy({attacker}, {target}): its hitter {hitter} of stone, striking harder")
            yield from self.raised(hitter, f"destroy({attacker}, {target}): its hitter {hitter} falls from higher")
        yield from self.meet_sooner(attacker, target, attempt, index)

    def raised(self, name: str, why: str):
        """`name`, a block that falls in the sequence, a unit higher (with its own support)."""
        block = self.objects.get(name)
        if block is None or not any(t.name == "fall" and t.objects[0] == name for t in self.scenario.interactions):
            return
        candidate = self.moved_level(name, block.x, block.y + 1.0)
        if candidate is not None:
            yield why, candidate

    def meet_sooner(self, attacker: str, target: str, attempt: Attempt, index: int):
        """A rolling or sliding attacker reached its target too slowly to destroy it: the
        target (and the world beyond it, or else it alone) comes back along the attacker's
        path to where the attacker moved fastest, once its roll or slide was under way."""
        heading = self.heading_of(attacker, index)
        objects = self.objects
        trace = attempt.trace
        if heading is None or attacker not in objects or target not in objects or attacker not in trace.names:
            return
        motion = self.last_motion(attacker, index)
        if motion is None or len(attempt.fidelity.times) < index:
            return
        sign = 1.0 if heading == "right" else -1.0
        since = attempt.fidelity.times[motion[0]] + SETTLE_MOTION
        until = attempt.fidelity.times[index - 1]  # when it hit the target
        rows = trace.states[int(since / trace.dt) : int(until / trace.dt) + 1, trace.index(attacker), :]
        rows = rows[~np.isnan(rows[:, 0])]
        if not len(rows):
            return
        fastest = rows[int(np.argmax(sign * rows[:, 3]))]
        front = sign * fastest[0] + extent(objects[attacker])[0] / 2
        start = _along(objects[target], sign)[0]
        distance = start - front
        if distance < 0.2:
            return
        back = self.brought_back(target, front + distance / 2, distance, sign)
        if back is not None:
            whole_world, candidate = back
            with_it = " (the world beyond with it)" if whole_world else ""
            yield f"destroy({attacker}, {target}): {target} {distance:.2f} nearer, where {attacker} moves fastest{with_it}", candidate

    def set_moving(self, declared, index: int):
        """roll/slide(a, s, d) did not happen: a block that slides, more speed, or a closer to s."""
        mover, surface = declared.objects
        if declared.name == "slide":
            # Only an ice square slides: wood and stone grip a platform harder than a
            # square's width over its height, so it tips over its leading edge. A wooden
            # triangle, struck low, slides (about a unit, hit by the bird) but tips when
            # struck high. (docs/generation.md, "Which blocks slide")
            yield from self.swap(mover, "squareHole", f"slide({mover}): an ice square (a triangle tips when struck high)", "ice")
            yield from self.swap(mover, "triangleHole", f"slide({mover}): a wooden triangle (a square tips unless it is ice)", "wood")
        yield from self.material(mover, "ice", f"{declared.name}({mover}): of ice, lighter")
        if not (declared.name == "slide" and self.concrete_of(mover) == "squareHole"):
            yield from self.material(mover, "wood", f"{declared.name}({mover}): of wood, lighter than stone, tougher than ice")
        hitter = self.hitter_of(mover, index)
        if hitter:
            yield from self.material(hitter, "stone", f"{declared.name}({mover}): its hitter {hitter} of stone")
            yield from self.swap(hitter, "circle", f"{declared.name}({mover}): its hitter {hitter} a larger circle")
        yield from self.bring_closer(mover, surface, declared.directions[0])

    def bring_closer(self, mover: str, surface: str, heading: str):
        """`mover` along its support to just before the start of `surface`."""
        objects = self.objects
        if mover not in objects or surface not in objects:
            return
        obj, target = objects[mover], objects[surface]
        width = extent(obj)[0]
        left, right = _span(target)
        gap = self.parameters.clearance + 0.02
        x = left - width / 2 - gap if heading == "right" else right + width / 2 + gap
        candidate = self.moved_level(mover, x, obj.y)
        if candidate is not None:
            yield f"{mover} next to {surface}", candidate

    def push_off(self, declared, index: int):
        """fall(a, b) did not happen: a lighter faller; a heavier hitter, or a faster one
        (an ice square for a slider, a larger circle for a ball); a at the edge; the edge
        brought to a (`to_the_edge`)."""
        faller = declared.objects[0]
        yield from self.material(faller, "ice", f"fall({faller}): of ice, lighter")
        yield from self.material(faller, "wood", f"fall({faller}): of wood, lighter than stone, tougher than ice")
        hit = last_hit_on(self.scenario.interactions[:index], faller)
        if hit:
            hitter = hit.objects[0]
            yield from self.material(hitter, "stone", f"fall({faller}): its hitter {hitter} of stone")
            # A hitter that slides or rolls into the faller may arrive too slowly to push it
            # off: an ice square slides faster and further than a wooden triangle, and a
            # large circle carries more than a small one.
            motion = (self.last_motion(hitter, index) or (None, None))[1]
            if motion == "slide":
                yield from self.swap(hitter, "squareHole", f"fall({faller}): its hitter {hitter} an ice square, sliding faster", "ice")
            elif motion == "roll":
                yield from self.swap(hitter, "circle", f"fall({faller}): its hitter {hitter} a larger circle")
        objects = self.objects
        block, support = objects.get(faller), self.support_of.get(faller)
        if block is None or support not in objects or hit is None:
            return
        for pushed in [d for d in ("left", "right") if OPPOSITE[d] in hit.directions]:
            left, right = _span(objects[support])
            width = extent(block)[0]
            x = right - width / 2 - 0.02 if pushed == "right" else left + width / 2 + 0.02
            if abs(x - block.x) < 0.05:
                continue
            candidate = self.with_objects({faller: attrs.evolve(block, x=level_number(x))})
            if self.consistent(candidate, frozenset({faller})):
                yield f"fall({faller}): at the {pushed} edge of {support}", candidate
            yield from self.to_the_edge(faller, hit.objects[0], support, pushed, index)

    def to_the_edge(self, faller: str, hitter: str, support: str, pushed: str, index: int):
        """The faller's support ends at it (`ledge_ends_at`), where it is or, when its
        hitter rolls or slides a long way to it and arrives too slowly to push it off,
        nearer the hitter, so that it is struck after STRIKE_AFTER units of motion (enough
        to tell the roll or slide), at more speed; the fall then comes down elsewhere, and
        what it should land on is brought under it in turn (`drop_over`)."""
        objects = self.objects
        sign = 1.0 if pushed == "right" else -1.0
        shifts = [0.0]
        if hitter in objects and self.last_motion(hitter, index) is not None:
            gap = _along(objects[faller], sign)[0] - _along(objects[hitter], sign)[1]
            shifts += [-sign * (gap - travel) for travel in STRIKE_AFTER if gap - travel >= 0.2]
        for dx in shifts:
            changed = self.ledge_ends_at(faller, support, pushed, dx)
            if changed is None:
                continue
            candidate = self.with_objects(changed)
            if self.consistent(candidate, frozenset(changed)):
                where = f"{faller} {abs(dx):.2f} nearer {hitter}, " if dx else ""
                yield f"fall({faller}): {where}{support} ends at {faller}", candidate

    def material(self, name: str, material: str, why: str):
        obj = self.objects.get(name)
        if obj is not None and obj.element == "Block" and obj.material != material:
            yield why, self.with_objects({name: attrs.evolve(obj, material=material)})

    def swap(self, name: str, concrete: str, why: str, material: str | None = None):
        """`name` as another concrete object (and of `material`, if given)."""
        obj = self.objects.get(name)
        if obj is None or concrete not in self.allowed.get(name, ()) or self.concrete_of(name) == concrete:
            return
        old = extent(obj)
        new_shape = shape(concrete)
        y = obj.y - old[1] / 2 + new_shape.height / 2  # keep the bottom where it rests
        candidate = self.with_objects({name: attrs.evolve(obj, type=new_shape.prefab, y=level_number(y), material=material or obj.material)})
        if self.consistent(candidate):
            yield why, candidate
