"""PHYRE's world as one value (physc.worlds.World): the domain's one world.

Each setting's source is PHYRE's own file (docs/phyre-facts.md has the reasoning).
"""

from __future__ import annotations

from physc.worlds import Incline, World
from physc_phyre.rules import RECOGNISER
from physc_phyre.world import ENGINE, GRAVITY

PHYRE = World(
    name="phyre",
    description="PHYRE's simulator: Box2D 2.3.2 at 60 steps a second, 15 and 20 iterations, in metres",
    engine=ENGINE,
    gravity=GRAVITY,
    recogniser=RECOGNISER,
    incline=Incline(descending=(15.0, 30.0), other=(20.0, 40.0)),
    sources={
        "engine": "src/simulator/task_utils.h (1/60 s, 15 velocity and 20 position iterations); Box2D 2.3.2's "
        "b2Settings.h for the rest",
        "gravity": "src/simulator/task_utils.h: gravity -9.8 m/s²",
        "recogniser": "physc: recognition thresholds in metres (the goal's 3 s: PHYRE's 180 steps)",
    },
)
