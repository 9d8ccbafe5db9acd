"""Distractors: objects that play no part in the intended solution, as PHYRE's scenes hold
besides the goal's (its templates' obstacles, pegs and posts).

A random number of them (0 to the search's `distractors`): a static black bar, level or
tilted, or a static black ball, somewhere in the scene; or a gray ball resting on the floor.
The search (physc.search.guards) keeps one only if nothing overlaps, the scene still
stands, and the intended solution still holds up in the noisy replays. They are what makes
random actions miss: a bar in the way, a ball where one would be placed (an occluding action
is invalid).
"""

from __future__ import annotations

import random

from physc.compiler.concrete_layout import PlacedObject
from physc_phyre.world import BAR_HEIGHT, SCENE

BAR = (20.0, 60.0)  # length, px
TILT = 30.0  # degrees either way at most
RADIUS = (4.5, 12.5)  # px, as PHYRE's balls: int(scale·128) + 0.5
PLACES = 4  # places tried per distractor
MARGIN = 20.0  # px kept from the scene's edges


def distractors(layout, index: int, rng: random.Random):
    """Candidates for distractor number `index`: one kind, at up to PLACES random places."""
    kind = rng.choice(("blackBar", "blackBall", "ball"))
    name = f"distractor{index}"
    for _ in range(PLACES):
        if kind == "blackBar":
            length = round(rng.uniform(*BAR), 1)
            x, y = rng.uniform(MARGIN + length / 2, SCENE - MARGIN - length / 2), rng.uniform(MARGIN, SCENE - MARGIN)
            yield PlacedObject(
                name,
                "distractor",
                kind,
                None,
                round(x, 3),
                round(y, 3),
                round(rng.uniform(-TILT, TILT), 2),
                length,
                BAR_HEIGHT,
            )
        else:
            radius = int(rng.uniform(*RADIUS)) + 0.5
            x = rng.uniform(MARGIN + radius, SCENE - MARGIN - radius)
            y = radius if kind == "ball" else rng.uniform(MARGIN, SCENE - MARGIN)  # a gray ball rests on the floor
            yield PlacedObject(name, "distractor", kind, None, round(x, 3), round(y, 3), 0.0, 2 * radius, 2 * radius)
