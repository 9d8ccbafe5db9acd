"""Distractions (the paper's step 5): objects that play no part in the solution.

A random number of blocks (0 to the search's `distractors`), of random types and
materials, each resting on a support: the ground, or the free part of a horizontal
platform. The search (physc.search.guards) keeps one only if nothing overlaps, the
level still stands, the intended solution still holds up in the noisy replays, and no
shot at it solves the task. Pigs are never distractors: every pig must be destroyed for
the task to be solved.
"""

from __future__ import annotations

import random

from physc.compiler.concrete_layout import PlacedObject
from physc.domains.angrybirds.catalogue import shape

KINDS = ("squareSmall", "rectFat", "rectSmall", "rectTiny", "squareHole", "circleSmall", "triangle")
SKIN = 0.015  # objects rest this far above their support, as in Science Birds
PLACES = 4  # resting places tried per distractor


def _resting_places(layout, width: float, rng: random.Random, frame):
    """(x range, top) of surfaces an object of this width can rest on."""
    area = frame.placement
    places = [((area.left + 1.5 + width / 2, area.right - width / 2), frame.ground_top)]
    for obj in layout.objects:
        if shape(obj.concrete).kind == "platform" and abs(obj.rotation or 0.0) < 1e-6 and obj.width >= width + 0.2:
            places.append(
                ((obj.x - obj.width / 2 + width / 2, obj.x + obj.width / 2 - width / 2), obj.y + obj.height / 2)
            )
    rng.shuffle(places)
    return places


def distractors(layout, index: int, rng: random.Random, world):
    """Candidates for distractor number `index`: one random kind and material, on up to
    PLACES resting places."""
    kind = shape(rng.choice(KINDS))
    material = rng.choice(kind.materials)
    for (low, high), top in _resting_places(layout, kind.width, rng, world.frame)[:PLACES]:
        if high < low:
            continue
        x = rng.uniform(low, high)
        y = top + kind.height / 2 + SKIN
        yield PlacedObject(
            f"distractor{index}",
            "distractor",
            kind.name,
            material,
            round(x, 5),
            round(y, 5),
            0.0,
            kind.width,
            kind.height,
        )
