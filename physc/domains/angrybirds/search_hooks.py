"""What physc's search asks of Science Birds beyond its levels and shots (`AngryBirds.search`):
the bodies a block or pig may take and their physics in the world, the shots aimed at an
object, the platform that blocks a forbidden hit, and distractors."""

from __future__ import annotations

import random

from physc.domains.angrybirds.catalogue import PLATFORM_THICKNESS
from physc.domains.search_hooks import SearchHooks

OBSTACLE_LENGTH = 1.4  # an obstacle platform's length
SEARCH_SECONDS = 9.0  # a play's simulated time at most while searching (the evaluation's: 10 s)


class ScienceBirdsSearch(SearchHooks):
    """Science Birds' hooks of the search, in the bound domain's world."""

    seconds = SEARCH_SECONDS
    blocker = "flatPlatform"
    blocker_length = OBSTACLE_LENGTH
    blocker_thickness = PLATFORM_THICKNESS

    def actions_at(self, level, name: str) -> list:
        from physc.domains.angrybirds.actions import candidate_shots

        obj = next((o for o in level.objects if o.name == name), None)
        return [] if obj is None else candidate_shots(obj, self.domain.world)

    def bodies(self, placed, scenario) -> list:
        from physc.domains.angrybirds.bodies import bodies

        return bodies(placed, scenario)

    def mass(self, placed) -> float:
        from physc.domains.angrybirds.bodies import mass

        return mass(placed, self.domain.world)

    def toughness(self, placed) -> float:
        from physc.domains.angrybirds.bodies import toughness

        return toughness(placed, self.domain.world)

    def friction(self, placed) -> float:
        from physc.domains.angrybirds.bodies import friction

        return friction(placed, self.domain.world)

    def distractors(self, layout, index: int, rng: random.Random):
        from physc.domains.angrybirds.distract import distractors

        return distractors(layout, index, rng, self.domain.world)
