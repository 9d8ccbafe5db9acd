"""Distractions (the paper's step 5): objects that play no part in the solution.

A random number of blocks (0 to MAX_DISTRACTORS), of random types and materials,
each resting on a support: the ground, or the free part of a horizontal
platform. None may overlap anything, the level must still stand (nothing moves
when left alone), and the intended solution must still realise the declared
sequence with every distractor in place, exactly and in the noisy replays of the
robustness check and of its confirmation; a distractor that breaks any of this is taken away again. Pigs are never distractors: every pig must be
destroyed for the task to be solved.
"""

from __future__ import annotations

import random

import attrs

from physc.domains.angrybirds.catalogue import extent, shape
from physc.domains.angrybirds.level import LevelObject, level_number
from physc.domains.angrybirds.stability import stability
from physc.domains.angrybirds.world import GROUND_TOP, PLACEMENT_AREA

MAX_DISTRACTORS = 3
KINDS = ("squareSmall", "rectFat", "rectSmall", "rectTiny", "squareHole", "circleSmall", "triangle")
SKIN = 0.015  # objects rest this far above their support, as in Science Birds


def _resting_places(level, width: float, rng: random.Random):
    """(x range, top) of surfaces an object of this width can rest on."""
    places = [((PLACEMENT_AREA.left + 1.5 + width / 2, PLACEMENT_AREA.right - width / 2), GROUND_TOP)]
    for obj in level.objects:
        if obj.element == "Platform" and abs(obj.rotation or 0.0) < 1e-6:
            length, thickness = extent(obj)
            if length >= width + 0.2:
                places.append(((obj.x - length / 2 + width / 2, obj.x + length / 2 - width / 2), obj.y + thickness / 2))
    rng.shuffle(places)
    return places


def distract(satisfier, solution, rng: random.Random) -> list[str]:
    """Add distractors to the satisfier's level; keep those that leave the solution intact."""
    added = []
    for index in range(rng.randint(0, MAX_DISTRACTORS)):
        kind = shape(rng.choice(KINDS))
        material = rng.choice(kind.materials)
        for (low, high), top in _resting_places(satisfier.level, kind.width, rng)[:4]:
            if high < low:
                continue
            x = rng.uniform(low, high)
            y = top + kind.height / 2 + SKIN
            name = f"distractor{index + 1}"
            obj = LevelObject("Block", kind.prefab, level_number(x), level_number(y), 0.0, material, name=name)
            candidate = attrs.evolve(satisfier.level, objects=satisfier.level.objects + (obj,))
            if not satisfier.consistent(candidate):
                continue
            if not satisfier.simulate(solution.shot, candidate).fidelity.valid:
                continue
            if not stability(candidate)[0]:
                continue  # it would roll or topple on its own
            if not satisfier.holds_up(solution, candidate):
                continue  # it makes the solution fragile under noise
            if satisfier.solving_shot(obj, candidate) is not None:
                continue  # a distraction must not be a way to solve the task
            satisfier.level = candidate
            satisfier.roles[name] = "distractor"
            added.append(name)
            break
    return added
