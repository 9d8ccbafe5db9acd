"""Angry Birds' chain builder: the hooks of the sequential strategy for this domain.

The generic search (physc/generation/sequential.py) asks for the stages of a scenario,
for the variants of a stage, and whether a variant realises it. Here:

* **What enters when.** An object enters the scene at the first interaction that names
  it; what it rests on enters with it (or earlier), and platforms joined edge to edge
  enter together, so a shelf that several balls roll along is there from the first of
  them. Objects that no interaction names (none, in the paper's scenarios) enter last.
* **Where the next target goes.** The target of `hit(a, b, d)` goes where the simulated
  prefix says the actor passes, touching it from the declared side, a little further
  along the path each time (`STEP`), no nearer than it took the previous roll or slide
  to be recognised; the target of `fall(a, b)` goes where `a` comes down to its height.
  A target that rests on the ground or on a shared surface only moves along it; one with
  its own support moves with it. No position is offered that the prefix's bodies pass
  through before the moment of the hit, or that breaks a layout edge of what is placed.
* **Then** the layout as placed, and then the repair search's local proposals for the
  first interaction the stage's best attempt missed, on the prefix scene.
* **Realised** means every interaction up to the stage's end in order, with no
  restriction broken before it, by the attempt the variant was made for and then by the
  parent's other attempts (a beam of `BEAM`); at the first stage, by every candidate shot.
"""

from __future__ import annotations

import contextlib
import itertools
import math

import attrs
import numpy as np

from physc.compiler.qsr import joined
from physc.domains.angrybirds.actions import candidate_shots
from physc.domains.angrybirds.attempt import SECONDS
from physc.domains.angrybirds.catalogue import extent, shape
from physc.compiler.layout_rules import OPPOSITE
from physc.domains.angrybirds.level import Level
from physc.domains.angrybirds.repairs import LANDING_SHARES, SETTLE_MOTION
from physc.generation.sequential import ChainBuilder, Stage, State, stages

SCREEN = 4  # shots a change of the first stage is tried with first
STAGE_SECONDS = 6.0  # simulated after the parent's last interaction, for a stage that is not the last
BEAM = 3  # attempts that realise a stage, kept for the next
STEP = 0.3  # units of travel between the places a target is offered along a path
PLACES = 6  # places offered along the path of each of the first two attempts
PROPOSALS = 6  # local repairs offered per stage and repaired scene
REPAIR_DEPTH = 3  # repairs on top of one another
GAP = 0.02  # between a placed target and the actor that is to meet it
MOVING = 0.25  # units/s: an actor slower than this is not offered targets further on
CLEAR = 0.05  # a placed target keeps this far from where the prefix's bodies pass before the hit
LANDINGS = (0.0, 0.15, -0.15, 0.3, -0.3)  # units off where a fall comes down, tried in turn
BIRD = shape("redBird")  # the bird is no object of the level: its size, for placing along its path


class AngryBirdsChain(ChainBuilder):
    """The chain builder over a `Satisfier`'s layout, simulation and layout checks."""

    def __init__(self, satisfier):
        self.s = satisfier
        self.interactions = satisfier.scenario.interactions
        self.introduced = self._introduced()
        self.failed: dict[int, tuple] = {}  # stage index → (the best attempt of a variant that failed, its scene)
        self.screen: list = []  # the first stage's shots that came nearest, as placed: tried first on its changes

    # ---- stages ------------------------------------------------------------------------
    def _introduced(self) -> dict[str, int]:
        """The interaction at which each object enters the scene (module docstring)."""
        s = self.s
        introduced = {name: len(self.interactions) for name in s.objects}
        for k, term in enumerate(self.interactions):
            for name in term.objects:
                if name in introduced:
                    introduced[name] = min(introduced[name], k)
        # (earlier, later): `earlier` enters no later than `later`. A support before what rests
        # on it; two joined platforms together (both ways).
        before = [(support, a) for a, support in s.support_of.items()]
        before += [pair for a, b in map(tuple, joined(s.relations)) for pair in ((a, b), (b, a))]
        before = [(x, y) for x, y in before if x in introduced and y in introduced]
        changed = True
        while changed:
            changed = False
            for earlier, later in before:
                if introduced[earlier] > introduced[later]:
                    introduced[earlier], changed = introduced[later], True
        return introduced

    def stages(self) -> list[Stage]:
        return stages(self.interactions, self.introduced)

    def root(self) -> State:
        return State(self.s.level, (), -1)

    def prefix(self, level: Level, start: int) -> Level:
        """The scene of a stage beginning at interaction `start`: what has entered by then
        (an object added by a repair, an obstacle, is there from when it was added)."""
        return attrs.evolve(level, objects=tuple(o for o in level.objects if self.introduced.get(o.name, 0) <= start))

    # ---- realised ------------------------------------------------------------------------
    def reaches(self, attempt, end: int) -> bool:
        """Whether `attempt` realises the first `end` interactions in order, breaking no
        restriction before the last of them (all of them: its fidelity is valid)."""
        f = attempt.fidelity
        if end >= len(self.interactions):
            return f.valid
        if f.matched < end:
            return False
        until = f.times[end - 1]
        return not any(v.interaction.time <= until for v in attempt.trace.violations)

    def realised(self, scene, parent: State, stage: Stage, lead: int = 0):
        level = self.prefix(scene, stage.start)
        if parent.attempts:  # the attempt the variant was made for, then the rest of the beam
            order = [parent.attempts[lead]] + [a for j, a in enumerate(parent.attempts) if j != lead]
            shots, screen = [(a.label, a.shot) for a in order], 1
        else:  # every candidate shot; for a changed scene, those that came nearest before first
            target = self.s.first_target(level)
            shots = candidate_shots(target) if target is not None else []
            nearest = {a.label for a in self.screen}
            shots = [c for c in shots if c[0] in nearest] + [c for c in shots if c[0] not in nearest]
            screen = len(nearest) or len(shots)
        good, tried = [], []
        seconds = self.horizon(parent, stage)
        for j, (label, shot) in enumerate(shots):
            attempt = attrs.evolve(self.s.simulate(shot, level, seconds), label=label)
            tried.append(attempt)
            if self.reaches(attempt, stage.end):
                good.append(attempt)
            if j + 1 == screen and not good:
                break  # those most likely to missed it: so will the rest, mostly
        failed = [a for a in tried if a not in good]
        if failed:
            best = max(failed, key=lambda a: a.fidelity.score)
            if stage.index not in self.failed or best.fidelity.score > self.failed[stage.index][0].fidelity.score:
                self.failed[stage.index] = (best, scene)
            if not parent.attempts and not self.screen:
                self.screen = sorted(failed, key=lambda a: a.fidelity.score, reverse=True)[:SCREEN]
        good.sort(key=lambda a: (a.fidelity.score[:3], self.promise(a, stage.end)), reverse=True)
        return tuple(good[:BEAM]) or None

    def horizon(self, parent: State, stage: Stage) -> float:
        """How long a stage's scene is simulated: STAGE_SECONDS after the parent's last
        interaction (its actor's path for the next target is all the next stage reads), the
        whole run for the last stage, which must meet the goal."""
        if stage.end >= len(self.interactions):
            return SECONDS
        since = max((a.fidelity.times[-1] for a in parent.attempts if a.fidelity.times), default=0.0)
        return min(SECONDS, since + STAGE_SECONDS)

    def promise(self, attempt, end: int) -> float:
        """How well `attempt` sets up the interaction after the first `end`: how far its actor
        comes down, for a fall, else how fast it moves, after the last of them (the next
        stage's target is not there yet to be neared)."""
        if end >= len(self.interactions) or not end:
            return 0.0
        actor = self.interactions[end].objects[0]
        trace = attempt.trace
        if actor not in trace.names:
            return 0.0
        rows = trace.states[int(attempt.fidelity.times[end - 1] / trace.dt) :, trace.index(actor), :]
        rows = rows[~np.isnan(rows[:, 0])]
        if not len(rows):
            return 0.0
        if self.interactions[end].name == "fall":
            return float(rows[0, 1] - rows[:, 1].min())
        return float(np.hypot(rows[:, 3], rows[:, 4]).max())

    # ---- variants ------------------------------------------------------------------------
    def variants(self, parent: State, stage: Stage):
        """(description, scene, lead): on the path, as placed, then local repairs."""
        seen: set = set()
        full = parent.scene
        candidates = []
        if parent.attempts and stage.start < len(self.interactions):
            declared = self.interactions[stage.start]
            for lead, attempt in enumerate(parent.attempts[:2]):
                candidates.append((lead, itertools.islice(self.on_path(full, declared, stage, attempt), PLACES)))
        candidates.append((0, iter([("", full)])))
        for lead, offered in candidates:
            for description, scene in offered:
                if scene not in seen:
                    seen.add(scene)
                    yield description, scene, lead
        yield from self.repairs(parent, stage, seen)

    def repairs(self, parent: State, stage: Stage, seen: set, depth: int = 0):
        """The repair search's proposals for the first interaction the stage's best failed
        attempt missed, made on the stage's scene and put back into the whole one; a
        proposal that comes nearer, but not all the way, is repaired in turn (up to
        REPAIR_DEPTH proposals on top of one another)."""
        if stage.index not in self.failed:
            return
        best, base = self.failed[stage.index]
        s = self.s
        with self.on_scene(self.prefix(base, stage.start)):
            proposals = list(itertools.islice(s.distinct(s.proposals([best]), s.level), PROPOSALS))
        lead = next((j for j, a in enumerate(parent.attempts) if a.label == best.label), 0)
        for description, proposed in proposals:
            scene = self.merged(base, proposed.objects)
            if scene in seen:
                continue
            seen.add(scene)
            yield description, scene, lead
            if depth < REPAIR_DEPTH and self.failed[stage.index][1] is scene:  # nearer: repair it further
                yield from self.repairs(parent, stage, seen, depth + 1)
                return

    @contextlib.contextmanager
    def on_scene(self, level: Level):
        """The satisfier's proposals and checks made on `level` (a stage's scene) while in it:
        they read the satisfier's current level."""
        saved = self.s.level
        self.s.level = level
        try:
            yield
        finally:
            self.s.level = saved

    @staticmethod
    def merged(full: Level, objects) -> Level:
        """`full` with `objects` (of a stage's scene, changed) in their place by name, and
        those it lacks added."""
        changed = {o.name: o for o in objects}
        names = {o.name for o in full.objects}
        kept = tuple(changed.get(o.name, o) for o in full.objects)
        return attrs.evolve(full, objects=kept + tuple(o for o in changed.values() if o.name not in names))

    # ---- on the path -------------------------------------------------------------------------
    def movers(self, name: str, objects: dict) -> set[str]:
        """`name` with its own support and what rests on it and enters with it: what moves
        when it is placed."""
        s = self.s
        members = {name}
        support = s.own_support.get(name)
        if support in objects:
            members.add(support)
        members |= {a for a, b in s.support_of.items() if b == name and self.introduced.get(a) == self.introduced.get(name)}
        return members

    def sideways_only(self, name: str) -> bool:
        """Whether `name` rests on the ground or on a surface others use (it moves along it)."""
        s = self.s
        return name in s.on_ground or (name in s.support_of and name not in s.own_support)

    def on_path(self, full: Level, declared, stage: Stage, attempt):
        """Scenes with the stage's first new object where `attempt`'s actor meets it."""
        actor, target = (declared.objects + (None,))[:2]
        if declared.name not in ("hit", "fall") or target not in stage.new or actor not in attempt.trace.names:
            return
        objects = {o.name: o for o in full.objects}
        if target not in objects or objects[target].element == "Platform":
            return  # a surface is placed by the layout, with the shelf it belongs to
        trace = attempt.trace
        k = stage.start
        since = attempt.fidelity.times[k - 1] if k else 0.0
        if k and self.interactions[k - 1].name in ("roll", "slide", "fall"):
            since += SETTLE_MOTION
        first = int(since / trace.dt)
        rows = trace.states[first:, trace.index(actor), :]
        members = self.movers(target, objects)
        places = self.hit_places if declared.name == "hit" else self.fall_places
        for step, x, y in places(declared, objects, target, rows, k):
            changed = self.s.shift(members, x - objects[target].x, y - objects[target].y, objects)
            if changed is None or not self.clear(trace, first + step, changed, actor, objects):
                continue
            scene = self.merged(full, changed.values())
            if not self.s.consistent(self.prefix(scene, stage.start), frozenset(changed)):
                continue
            where = f"{declared.text}: {target} on its path, at ({changed[target].x:.2f}, {changed[target].y:.2f})"
            if declared.name == "hit" and self.falls_next(target, k):
                edged = self.at_edge(scene, declared, stage)
                if edged is not None:
                    yield f"{where}, its support ending at it", edged
            yield where, scene

    def falls_next(self, name: str, k: int) -> bool:
        """Whether the next interaction after `k` that `name` acts in is a fall."""
        after = next((t for t in self.interactions[k + 1 :] if t.objects[0] == name), None)
        return after is not None and after.name == "fall"

    def at_edge(self, scene: Level, declared, stage: Stage) -> Level | None:
        """`scene` with the support of the hit's target ending just beyond it on the side it
        is pushed to (the repair search's `ledge_ends_at`), so that the hit pushes it off."""
        target = declared.objects[1]
        support = self.s.support_of.get(target)
        pushed = [d for d in ("left", "right") if OPPOSITE[d] in declared.directions]
        if support is None or not pushed:
            return None
        with self.on_scene(self.prefix(scene, stage.start)):
            changed = self.s.ledge_ends_at(target, support, pushed[0]) if support in self.s.objects else None
        if changed is None:
            return None
        edged = self.merged(scene, changed.values())
        return edged if self.s.consistent(self.prefix(edged, stage.start), frozenset(changed)) else None

    def hit_places(self, declared, objects: dict, target: str, rows, k: int):
        """(row, x, y) of the target touching the actor from a declared side, along its path."""
        actor = declared.objects[0]
        wa, ha = extent(objects[actor]) if actor in objects else (BIRD.width, BIRD.height)
        wb, hb = extent(objects[target])
        sideways = self.sideways_only(target)
        resting_y = objects[target].y
        if sideways and "above" in declared.directions:  # where the actor comes down to it
            yield from self.landings((wa, ha), objects, target, rows, k)
        for step, x, y in self.along(rows):
            for side in declared.directions:
                if side == "left":
                    px, py = x + (wa + wb) / 2 + GAP, y
                elif side == "right":
                    px, py = x - (wa + wb) / 2 - GAP, y
                elif side == "above":
                    px, py = x, y - (ha + hb) / 2 - GAP
                elif side == "below":
                    px, py = x, y + (ha + hb) / 2 + GAP
                else:
                    continue
                if sideways:
                    if side in ("left", "right") and abs(y - resting_y) > (ha + hb) / 2 - 0.05:
                        continue
                    if side in ("above", "below"):
                        continue
                    py = resting_y
                yield step, px, py

    def fall_places(self, declared, objects: dict, target: str, rows, k: int):
        """(row, x, y) of the target under where the faller comes down to its top."""
        faller = declared.objects[0]
        if faller in objects:
            yield from self.landings(extent(objects[faller]), objects, target, rows, k)

    def landings(self, size: tuple[float, float], objects: dict, target: str, rows, k: int):
        """(row, x, y) of the target under where a body of `size` first comes down to its top,
        and a little off it (behind its centre first if the target moves next)."""
        wa, ha = size
        wb, hb = extent(objects[target])
        top = objects[target].y + hb / 2 + ha / 2
        landing = next(
            ((i, x) for i, (x, y, _, _, vy, _) in enumerate(rows) if not math.isnan(x) and vy < -0.1 and y <= top), None
        )
        if landing is None:
            return
        step, x = landing
        reach = (wa + wb) / 2
        heading = self.s.heading_after(target, k + 1)
        nudges = list(LANDINGS)
        if heading is not None:
            behind = 1.0 if heading == "left" else -1.0
            nudges = [behind * share * reach for share in LANDING_SHARES] + nudges
        for nudge in nudges:
            if abs(nudge) < reach:
                yield step, x + nudge, objects[target].y

    @staticmethod
    def along(rows):
        """(row, x, y) every STEP units of travel along a path, while the body still moves."""
        last = None
        for i, (x, y, _, vx, vy, _) in enumerate(rows):
            if math.isnan(x):
                return
            if last is not None and math.hypot(vx, vy) < MOVING:
                return
            if last is None or math.hypot(x - last[0], y - last[1]) >= STEP:
                last = (x, y)
                yield i, x, y

    def clear(self, trace, row: int, changed: dict, actor: str, objects: dict) -> bool:
        """Whether the bodies of the prefix pass clear of the moved objects before `row` (the
        moment the actor is to meet them); the actor's own centre only has to stay out."""
        for index, name in enumerate(trace.names):
            path = trace.states[:row, index, :2]
            path = path[~np.isnan(path[:, 0])]
            if not len(path):
                continue
            if name == actor:
                radius, margin = 0.0, 0.0
            else:
                radius, margin = max(extent(objects[name])) / 2 if name in objects else BIRD.width / 2, CLEAR
            for obj in changed.values():
                w, h = extent(obj)
                dx = np.abs(path[:, 0] - obj.x) - w / 2 - radius - margin
                dy = np.abs(path[:, 1] - obj.y) - h / 2 - radius - margin
                if ((dx < 0) & (dy < 0)).any():
                    return False
        return True
