"""PHYRE's goal as the run's rules: the two goal bodies touching for 180 steps in a row.

The run ends as soon as the goal has held that long (PHYRE stops there too), or once
nothing moves and the goal does not hold (nothing will change any more), or after
1,000 steps. Also here: the recognition of interactions in PHYRE's units (metres).
"""

from __future__ import annotations

from physc.simulation.recognise import Recogniser
from physc.simulation.run import RunRules

from physc_phyre.world import FPS, GOAL_STEPS

STILL_SPEED = 0.01  # m/s and rad/s: slower is at rest
STILL_STEPS = FPS // 2  # at rest this long without the goal: the run is over

RECOGNISER = Recogniser(
    hit_speed=0.5, rehit=0.1, moving=0.3, roll_slip=0.3, slide_spin=0.3, motion_time=0.2, fall_time=0.25,
    fall_height=1.0, bounce_time=0.2, bounce_speed=1.0,
    surfaces=("surface", "floor"), background=("wall", "floor"), touch_time=GOAL_STEPS / FPS,
)


class GoalRules(RunRules):
    """The rules of one run: `goal` is (green body, the body it must touch)."""

    def __init__(self, goal: tuple[str, str]):
        self.goal = goal
        self.held = 0  # steps in a row that the goal has held
        self.still = 0  # steps in a row that nothing moved
        self.met = False

    def on_start(self, world) -> None:
        self.world = world

    def finished(self, values: list, alive: set, time: float) -> bool:
        green, target = self.goal
        self.held = self.held + 1 if green and target in self.world.touching(green) else 0
        if self.held >= GOAL_STEPS:
            self.met = True
            return True
        moving = any(abs(v[3]) + abs(v[4]) + abs(v[5]) > STILL_SPEED for v in values)
        self.still = 0 if moving or self.held else self.still + 1
        return self.still >= STILL_STEPS

    def resume(self, world, snapshot) -> None:
        """Going on from a snapshot: the goal has held since the goal bodies last began
        touching, if they touch then (a snapshot is cut while something still moves)."""
        pair = frozenset(self.goal)
        if pair in snapshot.touching:
            since = max(c.time for c in snapshot.contacts if frozenset((c.a, c.b)) == pair)
            self.held = int(round((snapshot.time - since) / snapshot.dt)) + 1

    def solved(self, recording) -> bool:
        return self.met
