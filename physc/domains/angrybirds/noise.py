"""The noise model of the angrybirds domain: how a replay of a solution may differ.

The same model serves the generator's robustness replays and the evaluation's
noisy replays: release angle σ = 0.1°, positions of the dynamic bodies (blocks, pigs, TNT)
σ = 0.005 units (platforms stay where they are).
"""

from __future__ import annotations

import random

import attrs

from physc.domains.angrybirds.level import Level

ANGLE_SIGMA = 0.1  # degrees
POSITION_SIGMA = 0.005  # units
ROBUSTNESS_REPLAYS = 6  # noisy replays of a solution while generating (the evaluation runs 10)


def jitter(level: Level, rng: random.Random) -> Level:
    """The level with every block, pig and TNT box moved by Gaussian noise."""
    objects = tuple(
        attrs.evolve(o, x=o.x + rng.gauss(0.0, POSITION_SIGMA), y=o.y + rng.gauss(0.0, POSITION_SIGMA))
        if o.element in ("Block", "Pig", "TNT")
        else o
        for o in level.objects
    )
    return attrs.evolve(level, objects=objects)
