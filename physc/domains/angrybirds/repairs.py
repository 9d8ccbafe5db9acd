"""The satisfier's repair proposals: where objects go for an interaction to happen.

At the first declared interaction that no candidate shot realises, `proposals` offers
changed levels, each a guess at what kept it from happening; a stage of the sequential
search (build.py, `AngryBirdsChain.repairs`) simulates them on the stage's scene. The proposals here move objects:

* `liesOnPath(b, a)` (from `hit(a, b, d)` and `fall(a, b)`): b is moved to where
  the simulated paths of a pass most often, placed so that a arrives from an
  allowed side, with its own support if it has one; every QSR of the chosen
  conjunction is re-checked there (the paper: "on failure the next best place");
* a block that a fall should set rolling or sliding: the fall is moved to end behind
  its centre (`land_off_centre`; dead centre, it does not move);
* `bounce`: the surface is turned a little (or over, when the bounce went away
  from the next target);
* a mover that stopped short of what it should hit or move on: the world
  beyond it comes closer (`close_gap`); a first target shielded by its own
  support: the support gets shorter (`expose`); a chain of rolling or sliding
  blocks that ran out of speed: an earlier leg of it gets shorter (`shorten_legs`).

The proposals that give a destroy, a roll, a slide or a fall more force are in
impetus.py; the platform across the bird's flight when it breaks a cannotHit or knocks
a chain member out of turn (`obstruct_flight`) in obstruct.py; the moves themselves in
placing.py.
"""

from __future__ import annotations

import math
from collections import Counter

import attrs
import numpy as np

from physc.domains.angrybirds.attempt import Attempt, _along, _span
from physc.domains.angrybirds.catalogue import PLATFORM_BASE, by_prefab, extent
from physc.domains.angrybirds.game import BIRD
from physc.compiler.layout_rules import last_hit_on
from physc.domains.angrybirds.level import level_number
from physc.domains.angrybirds.obstruct import OBSTACLES
from physc.domains.angrybirds.placing import MIN_PLATFORM

PLACES = 14  # places tried per liesOnPath repair
CELL = 0.25  # grid of path counting
LANDING_SHARES = (0.45, 0.3, 0.6)  # a fall onto a block that is to move next ends this far behind its centre (of their half-widths)
LEG_CUTS = (0.5, 1.0)  # units an earlier leg of a chain of rolling or sliding blocks is tried shorter
MIN_LEG = 0.6  # a block rolls or slides at least this far before it strikes the next
SETTLE_MOTION = 0.3  # a roll, slide or fall lasts this long before its target may stand in the way


class Repairs:
    """The satisfier's repair proposals that move objects (mixed into `Satisfier`):
    each yields (description, level) alternatives."""

    def proposals(self, attempts: list[Attempt]):
        """(description, level) alternatives that might get past the first unmet interaction."""
        best = max(attempts, key=lambda a: a.fidelity.score)
        index = best.fidelity.matched
        if index >= len(self.scenario.interactions):
            return
        declared = self.scenario.interactions[index]
        previous = [a for a in attempts if a.fidelity.matched >= index]
        if len(self.obstacles) < OBSTACLES:
            yield from self.obstruct_flight(best)
        if declared.name == "fall" and not any(
            i.name == "fall" and i.objects[0] == declared.objects[0] for i in best.trace.interactions
        ):
            yield from self.push_off(declared, index)
        elif declared.name == "hit" and index == 0:
            yield from self.expose(declared)
        elif declared.name in ("hit", "fall") and index > 0:
            before = self.scenario.interactions[index - 1]
            if declared.name == "hit":
                yield from self.close_gap(declared.objects[0], declared.objects[1], best, index)
            else:
                yield from self.drop_over(declared, best, index)
            yield from self.lie_on_path(declared, previous, index)
            if before.name in ("roll", "slide") and before.objects[0] == declared.objects[0]:
                yield from self.land_off_centre(declared.objects[0], index, best)  # it moved, but not far enough
            if before.name == "bounce" and before.objects[0] == declared.objects[0]:
                yield from self.turn(before.objects[1], mirror=True)  # it bounced, but away from the target
            yield from self.shorten_legs(index)
        elif declared.name == "destroy":
            yield from self.strengthen(declared, index, best)
            yield from self.shorten_legs(index)
        elif declared.name in ("roll", "slide"):
            yield from self.close_gap(declared.objects[0], declared.objects[1], best, index)
            yield from self.set_moving(declared, index)
            yield from self.land_off_centre(declared.objects[0], index, best)
            yield from self.shorten_legs(index)
        elif declared.name == "bounce":
            yield from self.turn(declared.objects[1])

    def lie_on_path(self, declared, attempts: list[Attempt], index: int):
        actor, target = declared.objects
        objects = self.objects
        if target not in objects:
            return
        counts: Counter = Counter()
        for attempt in attempts:
            trace = attempt.trace
            if actor not in trace.names:
                continue
            since = attempt.fidelity.times[index - 1] if index else 0.0
            if self.scenario.interactions[index - 1].name in ("roll", "slide", "fall"):
                since += SETTLE_MOTION  # let the motion before it be recognisable
            rows = trace.states[int(since / trace.dt) :, trace.index(actor), :2]
            cells = {(round(x / CELL), round(y / CELL)) for x, y in rows if not math.isnan(x)}
            counts.update(cells)
        sides = declared.directions if declared.name == "hit" else ("above",)
        obj = objects[target]
        width, height = extent(obj)
        offered = 0
        for (cx, cy), _ in sorted(counts.items(), key=lambda item: (-item[1], item[0])):
            px, py = cx * CELL, cy * CELL
            for approach in sides:
                offsets = {"left": (width / 2, 0.0), "right": (-width / 2, 0.0), "above": (0.0, -height / 2), "below": (0.0, height / 2)}
                dx, dy = offsets.get(approach, (0.0, 0.0))
                moved = self.move_structure(target, px + dx, py + dy, actor) or self.move(target, px + dx, py + dy)
                if moved is None:
                    continue
                candidate = self.with_objects(moved)
                if self.consistent(candidate, frozenset(moved)):
                    offered += 1
                    yield f"liesOnPath({target}, {actor}): {target} to ({moved[target].x:.2f}, {moved[target].y:.2f})", candidate
                    if offered >= PLACES:
                        return

    def close_gap(self, mover: str, goal: str, attempt: Attempt, index: int):
        """`mover` came to rest short of `goal` (the object it should hit, the surface it
        should move on): the world ahead of it comes closer. Everything beyond a cut between
        the two shifts towards the mover, and the flat platforms across the cut get shorter,
        so joints and supports stay as they were. Offered so that the goal begins a little
        before where the mover stopped (it arrives still moving)."""
        objects = self.objects
        trace = attempt.trace
        heading = self.heading_of(mover, index)
        if mover not in objects or goal not in objects or mover not in trace.names or heading is None:
            return
        sign = 1.0 if heading == "right" else -1.0
        since = attempt.fidelity.times[index - 1] if index else 0.0
        path = trace.states[int(since / trace.dt) :, trace.index(mover), 0]
        path = path[~np.isnan(path)]
        if not len(path):
            return
        # How far it got, along the heading: its front, which meets a block it should hit and
        # touches a surface next to its own; but a ball touches a surface only under its
        # centre, so for a surface to roll on its centre must get there.
        rolls_onto = self.scenario.interactions[index].name in ("roll", "slide") and by_prefab(objects[mover].type).round
        reach = float(np.max(sign * path)) + (0.0 if rolls_onto else extent(objects[mover])[0] / 2)
        start = _along(objects[goal], sign)[0]  # the goal's near end
        gap = start - reach
        if gap < -extent(objects[goal])[0] / 2:
            return  # it got there (too slowly, or from the wrong side): not a matter of distance
        # (a round mover may overlap a round goal's box and still stop short of its outline)
        cut = min(reach + max(gap, 0.0) / 2, start - 1e-3)
        for overlap in (0.3, 0.8):
            distance = gap + overlap
            back = self.brought_back(goal, cut, distance, sign)
            if back is not None:
                whole_world, candidate = back
                what = "the world beyond" if whole_world else goal
                yield f"{mover} stopped short of {goal}: {what} {distance:.2f} closer", candidate

    def expose(self, declared):
        """The first hit did not happen from an allowed side: the target's own support
        reaches out beyond it on that side and shields it from the bird, so it gets shorter."""
        target = declared.objects[1]
        objects = self.objects
        support = self.own_support.get(target)
        if target not in objects or support not in objects or objects[support].rotation:
            return
        left, right = _span(objects[target])
        s_left, s_right = _span(objects[support])
        for side in declared.directions:
            if side == "left" and s_left < left - 0.1:
                new_left, new_right = left - 0.05, s_right
            elif side == "right" and s_right > right + 0.1:
                new_left, new_right = s_left, right + 0.05
            else:
                continue
            if new_right - new_left < MIN_PLATFORM:
                continue
            platform = objects[support]
            changed = {support: attrs.evolve(platform, x=level_number((new_left + new_right) / 2), scale_x=level_number((new_right - new_left) / PLATFORM_BASE))}
            candidate = self.with_objects(changed)
            if self.consistent(candidate, frozenset({target, support})):
                yield f"hit({BIRD}, {target}, {side}): {support} no longer shields {target}", candidate

    def drop_over(self, declared, attempt: Attempt, index: int):
        """fall(a, b) happened, but a came down away from b (or, proposed by
        `land_off_centre`, on b but without setting it moving): a's structure (a, its
        support and what is joined to them) moves so that the same fall ends on b, or else
        b's structure moves the other way, under the fall. The fall path is read where a
        comes down to b's top. When b is to roll or slide next, a comes down on b's
        shoulder behind that heading: a block landing on the top of a ball at rest does not
        move it, and one landing 0.3 to 0.6 of their half-widths behind its centre moves it
        furthest (docs/generation.md, "Falls aimed to set a block moving")."""
        faller, target = declared.objects
        objects = self.objects
        trace = attempt.trace
        if faller not in objects or target not in objects or faller not in trace.names:
            return
        since = attempt.fidelity.times[index - 1] if index else 0.0
        rows = trace.states[int(since / trace.dt) :, trace.index(faller), :]
        level = objects[target].y + extent(objects[target])[1] / 2 + extent(objects[faller])[1] / 2
        landing = next((x for x, y, _, _, vy, _ in rows if not math.isnan(x) and vy < 0 and y <= level), None)
        if landing is None:
            return
        reach = (extent(objects[target])[0] + extent(objects[faller])[0]) / 2
        # Off centre by up to about half their widths, a still comes down on b: the nudges
        # reach the places where the layout edges hold (locatedFar keeps a "far" distance on
        # both axes of a diagonal tile). Behind b's centre first if b is to move next.
        nudges = sorted({round(k * 0.15, 2) for k in range(-4, 5) if abs(k * 0.15) < reach}, key=lambda n: (abs(n), n))
        heading = self.heading_after(target, index)
        if heading is not None:
            behind = 1.0 if heading == "left" else -1.0
            nudges = [round(behind * share * reach, 3) for share in LANDING_SHARES] + nudges
        for moving, other, sign in ((faller, target, 1.0), (target, faller, -1.0)):
            members = self.structure(moving)
            if other in members:
                continue
            offered = 0
            for nudge in nudges:
                dx = round(sign * (objects[target].x - landing + nudge), 3)
                changed = self.shift(members, dx, 0.0)
                if changed is None:
                    continue
                candidate = self.with_objects(changed)
                if self.consistent(candidate, frozenset(changed)):
                    yield f"fall({faller}, {target}): {moving} moved {dx:+.2f} for {faller} to come down on {target}", candidate
                    offered += 1
                    if offered >= 2:
                        break

    def land_off_centre(self, mover: str, index: int, attempt: Attempt):
        """`mover`, set moving by a block that fell on it, did not roll or slide (far enough):
        the fall is moved to end on its shoulder (`drop_over`)."""
        hit = last_hit_on(self.scenario.interactions[:index], mover)
        if hit is None:
            return
        falls = [j for j, t in enumerate(self.scenario.interactions[:index]) if t.name == "fall" and tuple(t.objects) == (hit.objects[0], mover)]
        if falls and attempt.fidelity.matched > falls[-1]:
            yield from self.drop_over(self.scenario.interactions[falls[-1]], attempt, falls[-1])

    def shorten_legs(self, index: int):
        """A chain of blocks rolling or sliding into one another ran out of speed before
        interaction `index`: an earlier leg of it (a block that rolls or slides, then hits
        the next) gets shorter, the latest first. The world beyond the gap between the two
        blocks comes LEG_CUTS nearer, the platforms across the gap shorter (`world_beyond`),
        and the blocks after it arrive faster: a rolling block loses speed in proportion
        to the distance it rolls (angular drag), whatever its speed."""
        interactions = self.scenario.interactions
        objects = self.objects
        for j in range(index - 2, -1, -1):
            motion, hit = interactions[j], interactions[j + 1]
            if motion.name not in ("roll", "slide") or hit.name != "hit" or hit.objects[0] != motion.objects[0]:
                continue
            mover, struck = hit.objects
            heading = motion.directions[0]
            if heading not in ("left", "right") or mover not in objects or struck not in objects:
                continue
            sign = 1.0 if heading == "right" else -1.0
            end, start = _along(objects[mover], sign)[1], _along(objects[struck], sign)[0]
            for distance in LEG_CUTS:
                if start - end - distance < MIN_LEG:
                    continue
                candidate = self.world_beyond((end + start) / 2, distance, sign)
                if candidate is not None:
                    yield f"{mover} {motion.name}s {distance:.2f} less before it hits {struck}", candidate

    def turn(self, name: str, mirror: bool = False):
        """The bounce surface turned a little either way (and, with `mirror`, tilted the
        other way: a bounce off its underside then goes the other way)."""
        obj = self.objects.get(name)
        if obj is None or obj.element != "Platform":
            return
        rotation = obj.rotation or 0.0
        for angle in [rotation + step for step in (-8.0, 8.0, -15.0, 15.0)] + ([-rotation] if mirror else []):
            if not 5 <= abs(angle) <= 60:
                continue
            candidate = self.with_objects({name: attrs.evolve(obj, rotation=round(angle, 3))})
            if self.consistent(candidate):
                yield f"bounce: {name} turned to {angle:.1f}°", candidate
