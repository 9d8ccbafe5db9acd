"""PHYRE's goal as the run's rules: the two goal bodies touching for 180 steps in a row.

Touching is decided as PHYRE's `isTaskInSolvedState` decides it (src/simulator/
task_validation.cpp): two goal bodies that are each one circle touch while their centres are
closer than r1 + r2 + a tenth of a pixel (PHYRE's check "to improve stability", computed in
single precision as PHYRE computes it); any other pair (a jar, a bar, sticks, static or
dynamic alike) touches while the engine has a contact between them.

The run ends as soon as the goal has held that long (PHYRE stops there too), or once
nothing moves and the goal does not hold (nothing will change any more), or after
1,000 steps. Also here: the recognition of interactions in PHYRE's units (metres).
"""

from __future__ import annotations

import math

import numpy as np

from physc.simulation.recognise import Recogniser
from physc.simulation.run import RunRules
from physc_phyre.world import FPS, GOAL_STEPS, PIXELS_PER_METRE

STILL_SPEED = 0.01  # m/s and rad/s: slower is at rest
STILL_STEPS = FPS // 2  # at rest this long without the goal: the run is over
BALL_TOUCHING_THRESHOLD = 0.1 / PIXELS_PER_METRE  # PHYRE's kBallTouchingThreshold, a tenth of a pixel, in metres

RECOGNISER = Recogniser(
    hit_speed=0.5,
    rehit=0.1,
    moving=0.3,
    roll_slip=0.3,
    slide_spin=0.3,
    motion_time=0.2,
    fall_time=0.25,
    fall_height=1.0,
    bounce_time=0.2,
    bounce_speed=1.0,
    surfaces=("surface", "floor"),
    background=("wall", "floor"),
    touch_time=GOAL_STEPS / FPS,
)


EXACT_WITHIN = 1e-4  # metres: nearer the limit than this, two balls are judged in PHYRE's float arithmetic


def balls_touch(a, b, r1: float, r2: float) -> bool:
    """Whether balls of radii `r1`, `r2` centred at `a` and `b` (metres) touch, in PHYRE's
    float arithmetic: sqrt(dx² + dy²) < r1 + r2 + BALL_TOUCHING_THRESHOLD. Judged in doubles
    unless the distance is within EXACT_WITHIN of the limit (single precision errs by
    a few micrometres at most at the scene's size), where PHYRE's floats decide."""
    gap = math.hypot(a[0] - b[0], a[1] - b[1]) - (r1 + r2 + BALL_TOUCHING_THRESHOLD)
    if abs(gap) > EXACT_WITHIN:
        return gap < 0
    f = np.float32
    dx, dy = f(a[0]) - f(b[0]), f(a[1]) - f(b[1])
    return bool(np.sqrt(dx * dx + dy * dy) < f(r1) + f(r2) + f(BALL_TOUCHING_THRESHOLD))


class GoalRules(RunRules):
    """The rules of one run: `goal` is (green body, the body it must touch); `balls` the radius
    in metres of the bodies that are one circle. When both goal bodies are balls, PHYRE's
    distance rule decides whether they touch; otherwise the engine's contacts do. They ask
    the world what they need (who touches whom, whether anything moves) rather than read
    every state."""

    reads_states = False

    def __init__(self, goal: tuple[str, str], balls: dict[str, float] | None = None):
        self.goal = goal
        self.radii = tuple(balls[n] for n in goal) if all(goal) and balls and set(goal) <= set(balls) else None
        self.held = 0  # steps in a row that the goal has held
        self.still = 0  # steps in a row that nothing moved
        self.met_at: float | None = None  # when the goal had held for GOAL_STEPS (None: not met)

    @classmethod
    def of(cls, level) -> GoalRules:
        """A level's rules; PHYRE's ball rule is the relation TOUCHING's (physc's only one)."""
        touching = level.relation == "TOUCHING"
        return cls(
            level.goal, {b.name: b.size / PIXELS_PER_METRE for b in level.bodies if b.shape == "ball" and touching}
        )

    def on_start(self, engine) -> None:
        self.engine = engine
        self._touches, self._moving = engine.touches, engine.moving

    def touching(self) -> bool:
        green, target = self.goal
        if self.radii:
            return balls_touch(self.engine.state(green), self.engine.state(target), *self.radii)
        return bool(green) and self._touches(green, target)

    def finished(self, values, alive: set, time: float) -> bool:
        self.held = self.held + 1 if self.touching() else 0
        if self.held >= GOAL_STEPS:
            self.met_at = time
            return True
        self.still = 0 if self.held or self._moving(alive, STILL_SPEED) else self.still + 1
        return self.still >= STILL_STEPS

    def resume(self, engine, snapshot) -> None:
        """Going on from a snapshot: the steps in a row up to it that the goal held. Balls: the
        rows in which they were within reach (a body the snapshot lacks, or a static one, stood
        where it stands now); other bodies: since they last began touching, if they touch then."""
        if self.radii:
            rows = [
                snapshot.states[:, snapshot.names.index(n), :2]
                if n in snapshot.names
                else [engine.state(n)[:2]] * snapshot.step
                for n in self.goal
            ]
            pairs = list(zip(*rows, strict=False))[::-1]
            self.held = next((k for k, (a, b) in enumerate(pairs) if not balls_touch(a, b, *self.radii)), len(pairs))
            return
        pair = frozenset(self.goal)
        if pair in snapshot.touching:
            since = max(c.time for c in snapshot.contacts if frozenset((c.a, c.b)) == pair)
            self.held = int(round((snapshot.time - since) / snapshot.dt)) + 1

    def settled(self, time: float, end: float) -> bool:
        """Not solved, whatever happens: too few steps are left for the goal to hold its 180."""
        return self.met_at is None and self.held + round((end - time) * FPS) < GOAL_STEPS

    def solved(self, recording) -> bool:
        return self.met_at is not None

    def goal_met(self, recording) -> float | None:
        """The time the goal had held for 3 s: the recogniser's `touch(green, target)`."""
        return self.met_at
