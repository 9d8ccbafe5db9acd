"""What physc's search asks of Science Birds beyond its levels and shots (`AngryBirds.search`):
the bodies a block or pig may take and their physics in the world (what a body weighs, how it
grips and what destroys it, from the game's prefabs and materials: the facts the search's
choice of a new object's body reads, physc.search.choosing), the shots aimed at an object, the
platform that blocks a forbidden hit, and distractors."""

from __future__ import annotations

import random

import attrs

from physc.domains.angrybirds import prefabs
from physc.domains.angrybirds.actions import candidate_shots
from physc.domains.angrybirds.catalogue import PLATFORM_THICKNESS, shape
from physc.domains.angrybirds.distract import distractors
from physc.domains.search_hooks import SearchHooks

OBSTACLE_LENGTH = 1.4  # an obstacle platform's length
# Phy-Q's templates lay 294 of their 385 platforms level or upright (0° or 90°, 76 %; the rest at
# 27 other angles): walls, roofs and cradles, as an obstacle is laid first.
OBSTACLE_ANGLES = (0.0, 90.0)
SEARCH_SECONDS = 9.0  # a play's simulated time at most while searching (the evaluation's: 10 s)


class ScienceBirdsSearch(SearchHooks):
    """Science Birds' hooks of the search, in the bound domain's world."""

    seconds = SEARCH_SECONDS
    blocker = "flatPlatform"
    blocker_length = OBSTACLE_LENGTH
    blocker_thickness = PLATFORM_THICKNESS
    blocker_angles = OBSTACLE_ANGLES
    priors = "physc.domains.angrybirds.priors"  # phyq.json, rolling.json: benchmarks/link_prior.py

    def actions_at(self, level, name: str) -> list:
        obj = next((o for o in level.objects if o.name == name), None)
        return [] if obj is None else candidate_shots(obj, self.domain.world)

    def bodies(self, placed, scenario) -> list:
        return bodies(placed, scenario)

    def mass(self, placed) -> float:
        return mass(placed, self.domain.world)

    def toughness(self, placed) -> float:
        return toughness(placed, self.domain.world)

    def friction(self, placed) -> float:
        return friction(placed, self.domain.world)

    def distractors(self, layout, index: int, rng: random.Random):
        return distractors(layout, index, rng, self.domain.world)


def bodies(placed, scenario) -> list:
    """Every block or pig `placed`'s scenario object allows (concrete object × material: the
    materials it names, if it names any), as placed objects of its name and place."""
    found = next((o for o in scenario.objects if o.name == placed.name), None)
    allowed = found.concrete if found is not None else ()
    named = getattr(found, "materials", ())
    out = []
    for concrete in allowed:
        catalogue = shape(concrete)
        if catalogue.kind == "pig":
            out.append(
                attrs.evolve(placed, concrete=concrete, material=None, width=catalogue.width, height=catalogue.height)
            )
        if catalogue.kind != "block":
            continue
        for material in [m for m in catalogue.materials if not named or m in named]:
            out.append(
                attrs.evolve(
                    placed, concrete=concrete, material=material, width=catalogue.width, height=catalogue.height
                )
            )
    return out


def _material(placed, world):
    materials = world.bodies.materials
    return materials.get(placed.material or "wood", materials["wood"])


def mass(placed, world) -> float:
    """The body's mass as the game gives it in `world` (`ABGameObject.Start`: density on the
    prefab's first collider; docs/angrybirds.md)."""
    catalogue = shape(placed.concrete)
    model = world.bodies
    if catalogue.kind == "bird":
        return model.bird_mass
    density = model.pig_density if catalogue.kind == "pig" else _material(placed, world).density
    if model.colliders == "game" and catalogue.prefab in prefabs.prefabs():
        return prefabs.body_mass(catalogue.prefab, density, model.circle_colliders)
    return placed.width * placed.height * density


def friction(placed, world) -> float:
    """The body's friction in `world`: its material's (pigs: the game's pig friction)."""
    catalogue = shape(placed.concrete)
    if catalogue.kind == "pig":
        return world.bodies.pig_friction
    return _material(placed, world).friction


def toughness(placed, world) -> float:
    """The damage that destroys the body in `world`: its life and defence (ABGameObject.DealDamage
    destroys at life ≤ 0; every hit takes the defence off first)."""
    catalogue = shape(placed.concrete)
    if catalogue.kind == "pig":
        return catalogue.life[""] + world.rules.pig_defence
    material = _material(placed, world)
    return catalogue.life.get(material.name, 0.0) + material.defence
