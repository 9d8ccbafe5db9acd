"""Platforms against what a level must not allow: pathObstructed and the shortcut guard.

`pathObstructed(a, b, d)` (from `cannotHit`): once a candidate realises the whole
sequence, `obstruct` adds platforms across the paths of shots that would hit b from a
forbidden side, each verified by simulation not to disturb the solution. During repair,
`obstruct_flight` proposes one across the bird's flight where the best candidate's bird
breaks a cannotHit, or knocks a chain member out of turn. Then `guard_accidents` does the
same for shots at other objects that solve the level (shortcuts): a platform across their
flight, or a roof, kept only if the solution still holds up under noise
(`Robustness.holds_up`, robustness.py). A mixin of `Satisfier` (satisfy.py), which also
uses `adopt` and `restore` to make a level (and the obstacles it adds) current.
"""

from __future__ import annotations

import math
from collections.abc import Collection

import attrs

from physc.compiler.qsr_evaluate import five_points
from physc.domains.angrybirds.actions import agent_targets, candidate_shots
from physc.domains.angrybirds.attempt import SECONDS, Attempt, _span
from physc.domains.angrybirds.catalogue import PLATFORM_BASE, PLATFORM_THICKNESS, extent
from physc.domains.angrybirds.game import BIRD, GROUND, Game
from physc.domains.angrybirds.level import Level, LevelObject, level_number
from physc.simulation.trace import Trace

OBSTACLES = 6
OBSTACLE_LENGTH = 1.4
SHORT_OBSTACLE = 0.9  # tried last, when no obstacle of the full length leaves the solution working
BACKS = (0.9, 1.3, 1.8, 2.4, 3.0)  # how far back along the bird's flight an obstacle goes
FURTHER_BACKS = (3.7, 4.5)  # tried next, for the obstruction of restricted targets only
ACCIDENT_OBSTACLES = 3  # platforms that may block shortcuts (solving shots at other objects)
SHORTCUTS_LEFT = 3  # shortcuts no platform stops, after which the guard ends
GUARD_LIFTS = (0.0, 0.45)  # units a shortcut's platform is also tried raised along its length (of OBSTACLE_LENGTH)
ROOF_GAPS = (0.3, 0.15)  # a roof against shortcuts from above is this far clear of the block under it (nearer only where 0.3 does not fit)
GUARDED_TOUCHES = 3  # a shortcut is blocked before one of the first this many objects the bird touches


def touched(trace) -> list[str]:
    """What the bird touches, other than the ground, in the order of first touch."""
    contacts = trace.contacts
    return list(dict.fromkeys(c.b if c.a == BIRD else c.a for c in contacts if BIRD in (c.a, c.b) and GROUND not in (c.a, c.b)))


class Obstruction:
    """The satisfier's obstacles: against forbidden hits and against shortcuts (mixed
    into `Satisfier`)."""

    # ---- forbidden hits ----------------------------------------------------------------------
    def obstruct(self, solution: Attempt) -> bool:
        """Block the shots that would hit a restricted object from a forbidden side."""
        for restriction in self.scenario.restrictions:
            if restriction.name != "cannotHit" or restriction.objects[0] != BIRD:
                continue
            target = restriction.objects[1]
            for _ in range(OBSTACLES):
                offending = self.offending_shot(restriction)
                if offending is None:
                    break
                if not self.block(offending, target, solution):
                    return False
            if self.offending_shot(restriction) is not None:
                return False
        return True

    def offending_shot(self, restriction) -> Attempt | None:
        """A shot at the restricted object that breaks the restriction, judged exactly as
        validation judges it (recognised hits, declared bounces), over the whole flight (a
        high shot at a far target is in the air for more than 4 s)."""
        obj = self.objects.get(restriction.objects[1])
        if obj is None:
            return None
        for label, shot in candidate_shots(obj):
            trace = Game(self.level).judged(self.flight(self.level, shot), (restriction,), self.redirects)
            if trace.violations:
                return Attempt(label, shot, trace, None)
        return None

    def block(self, offending: Attempt, target: str, solution: Attempt) -> bool:
        """Put a platform across the offending flight, a little before it reaches the target;
        if no such platform leaves the solution working, further back, then shorter ones."""
        for backs, length in ((BACKS, OBSTACLE_LENGTH), (FURTHER_BACKS, OBSTACLE_LENGTH), (BACKS + FURTHER_BACKS, SHORT_OBSTACLE)):
            for name, candidate in self.obstacles_across(offending.trace, target, backs=backs, length=length):
                check = self.simulate(solution.shot, candidate)
                if not check.fidelity.valid:
                    continue
                self.adopt(candidate)
                return True
        return False

    def obstacles_across(self, trace: Trace, target: str, before: float | None = None, backs=BACKS, length: float = OBSTACLE_LENGTH, lifts=(0.0,), flat: bool = False):
        """(name, level) with a platform across the bird's flight, a little before it first
        touches `target` (after `before`, if given): further back at each try (`backs`:
        how far along the flight, in units), and at each place centred on the flight or
        raised along its own length by each of `lifts` (units; the flight still crosses it,
        and its lower end stays out of the way of what moves below). `flat`: level instead
        of square to the flight, where the bird comes down (a lid over where it lands, whose
        ends do not reach down into what moves below)."""
        bird = trace.states[:, trace.index(BIRD), :]
        hit_time = next((c.time for c in trace.contacts if {c.a, c.b} == {BIRD, target} and (before is None or c.time >= before)), None)
        if hit_time is None:
            return
        hit_step = min(int(round(hit_time / trace.dt)) - 1, len(bird) - 1)
        for back in backs:
            # walk back along the flight by about `back` units
            step, travelled = hit_step, 0.0
            while step > 1 and travelled < back:
                travelled += math.hypot(*(bird[step, :2] - bird[step - 1, :2]))
                step -= 1
            x, y, _, vx, vy, _ = bird[step]
            if math.isnan(x):
                continue
            if flat and vy >= 0.0:
                continue  # a level platform stops only a bird that comes down on it
            angle = 0.0 if flat else math.degrees(math.atan2(vy, vx)) + 90.0  # across the flight
            angle = (angle + 90) % 180 - 90
            up = (math.cos(math.radians(angle)), math.sin(math.radians(angle)))
            if up[1] < 0:
                up = (-up[0], -up[1])
            name = f"obstacle{len(self.obstacles) + 1}"
            for lift in lifts:
                candidate = self.with_platform(name, x + lift * up[0], y + lift * up[1], angle, length)
                if candidate is not None:
                    yield name, candidate

    def with_platform(self, name: str, x: float, y: float, angle: float, length: float) -> Level | None:
        """The level with a platform `name` added (centre, angle in degrees, length), if
        every layout edge still holds and nothing overlaps."""
        platform = LevelObject("Platform", "Platform", level_number(x), level_number(y), round(angle, 3), scale_x=level_number(length / PLATFORM_BASE), scale_y=level_number(PLATFORM_THICKNESS / PLATFORM_BASE), name=name)
        candidate = attrs.evolve(self.level, objects=self.level.objects + (platform,))
        return candidate if self.consistent(candidate) else None

    def adopt(self, level: Level) -> None:
        """Make `level` the current one, registering any obstacle it adds."""
        for obj in level.objects:
            if obj.name not in self.roles:
                self.roles[obj.name] = "obstacle"
                self.obstacles.append(obj.name)
        self.level = level

    def restore(self, level: Level, obstacles: int) -> None:
        """Make `level` (an earlier one) the current one again, forgetting the obstacles
        registered after the first `obstacles`."""
        for name in self.obstacles[obstacles:]:
            self.roles.pop(name, None)
        del self.obstacles[obstacles:]
        self.level = level

    def bird_intrusions(self, attempt: Attempt):
        """The bird's hits, while the sequence runs, that break a cannotHit restriction or
        touch a block or pig the sequence never has the bird touch (after its own work the
        bird hops on along the chain and knocks its members out of turn), earliest first."""
        declared = {o for t in self.scenario.interactions if t.objects[0] == BIRD for o in t.objects[1:]}
        objects = self.objects
        fidelity = attempt.fidelity
        until = fidelity.times[-1] if fidelity.complete else math.inf
        broken = {
            (v.interaction.objects, v.interaction.time)
            for v in attempt.trace.violations
            if v.interaction.objects[0] == BIRD and v.restriction.startswith("cannotHit")
        }
        return [
            hit
            for hit in attempt.trace.interactions
            if hit.name == "hit"
            and hit.objects[0] == BIRD
            and hit.time <= until
            and (
                (hit.objects, hit.time) in broken
                or (hit.objects[1] not in declared and hit.objects[1] in objects and objects[hit.objects[1]].element != "Platform")
            )
        ]

    def obstruct_flight(self, attempt: Attempt):
        """pathObstructed during repair: the best candidate's bird breaks a cannotHit, or
        knocks a member of the chain out of turn, so a platform goes across that flight
        (the chain ahead must still happen)."""
        for hit in self.bird_intrusions(attempt)[:1]:
            target = hit.objects[1]
            for name, candidate in self.obstacles_across(attempt.trace, target, before=hit.time - 0.05):
                yield f"pathObstructed(bird, {target}): {name} across the bird's flight", candidate

    # ---- accidental solutions ----------------------------------------------------------------
    def shortcuts(self, target: str, skip: Collection[str] = ()):
        """The shots at points of interest of blocks and pigs other than the solution's
        target that solve the level as it is (the paper's heuristic agent, on all eight
        points), in the agent's order, other than those labelled in `skip`; lazily."""
        level = self.level
        for obj in agent_targets(level, target):
            yield from self.solving_shots(obj, level, skip)

    def guard_accidents(self, solution: Attempt) -> None:
        """pathObstructed for shortcuts: for each shot that solves the level without being the
        solution, a platform that stops it (`shortcut_blocks`: across its flight, or a roof;
        with it the shot no longer solves the level: `stops`), kept only if the solution
        still realises the sequence and survives the noisy replays of both streams as often
        as it must (`holds_up`); then the search starts again on the level with it. A
        shortcut that cannot be blocked stays, and the next one is tried; the guard ends
        after ACCIDENT_OBSTACLES platforms, or after SHORTCUTS_LEFT shortcuts it cannot block
        that do not go through the solution's target first (those that do are variants of
        the solution itself, which a platform rarely stops without stopping the solution;
        they are tried, but do not end the search for the others)."""
        first = self.first_target()
        if first is None:
            return
        unblocked: list[str] = []  # the shortcuts no platform stops (by the shot's label)
        given_up = 0  # of them, those that do not touch the solution's target first
        placed = 0
        while placed < ACCIDENT_OBSTACLES:
            for accident in self.shortcuts(first.name, tuple(unblocked)):
                if self.block_shortcut(accident, solution):
                    placed += 1
                    break  # a new level: its shortcuts are looked for from the start
                unblocked.append(accident.label)
                if touched(accident.trace)[:1] != [first.name]:
                    given_up += 1
                    if given_up >= SHORTCUTS_LEFT:
                        return
            else:
                return

    def block_shortcut(self, accident: Attempt, solution: Attempt) -> bool:
        """Adopt the first platform of `shortcut_blocks` that stops the shortcut and leaves
        the solution working and holding up under noise; whether there was one."""
        for _, candidate in self.shortcut_blocks(accident):
            if not self.stops(accident, candidate):
                continue  # the shortcut goes round it, or through
            if self.simulate(solution.shot, candidate).fidelity.valid and self.holds_up(solution, candidate):
                self.adopt(candidate)
                return True
        return False

    def stops(self, accident: Attempt, level: Level) -> bool:
        """Whether the shortcut's shot no longer solves `level`."""
        return not self.evaluator.run(lambda: Game(level).simulate(accident.shot, SECONDS, settle_after_solved=0.0)).solved

    def shortcut_blocks(self, accident: Attempt):
        """(name, level) with a platform that might stop a shortcut: across its flight
        before the first thing the bird touches, or else before the next ones (a shot that
        grazes the solution's own target on its way, a high shot over a sliding block into
        the block it should push, is blocked only further on); after the platforms across
        the flight to each, a roof over it (a high shot that knocks a block off its ledge
        comes down on it from above), then level platforms across a flight that comes down
        (a high shot that lands on the ledge a block slides along and pushes the next block
        off: square to that flight, a platform reaches down into the slide)."""
        for name in touched(accident.trace)[:GUARDED_TOUCHES]:
            yield from self.obstacles_across(accident.trace, name, lifts=GUARD_LIFTS)
            yield from self.roof_over(name)
            yield from self.obstacles_across(accident.trace, name, flat=True)

    def roof_over(self, name: str):
        """(name, level) with a flat platform just above `name` (0.3 clear of its top, or
        else 0.15: a block near the top of the placement area leaves no room for more),
        reaching 0.3 beyond it on both sides and at least OBSTACLE_LENGTH long."""
        obj = self.objects.get(name)
        if obj is None or obj.element == "Platform":
            return
        points = five_points(obj.x, obj.y, *extent(obj), obj.rotation or 0.0)
        top = max(p.imag for k, p in points.items() if k != "c")
        left, right = _span(obj)
        length = max(OBSTACLE_LENGTH, right - left + 0.6)
        roof = f"obstacle{len(self.obstacles) + 1}"
        for gap in ROOF_GAPS:
            candidate = self.with_platform(roof, (left + right) / 2, top + gap + PLATFORM_THICKNESS / 2, 0.0, length)
            if candidate is not None:
                yield roof, candidate
                return
