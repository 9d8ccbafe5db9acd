"""What a body of the level weighs and how it grips: the facts the search's choice of a
new object's body reads (physc.generation.choosing), from the game's prefabs and materials."""

from __future__ import annotations

import attrs

from physc.domains.angrybirds import prefabs
from physc.domains.angrybirds.catalogue import MATERIAL, shape
from physc.domains.angrybirds.rules import RULES


def bodies(placed, scenario) -> list:
    """Every block `placed`'s scenario object allows (concrete object × material), as
    placed objects of its name and place."""
    allowed = next((o.concrete for o in scenario.objects if o.name == placed.name), ())
    out = []
    for concrete in allowed:
        catalogue = shape(concrete)
        if catalogue.kind != "block":
            continue
        for material in catalogue.materials:
            out.append(attrs.evolve(placed, concrete=concrete, material=material, width=catalogue.width, height=catalogue.height))
    return out


def mass(placed) -> float:
    """The body's mass as the game gives it (`ABGameObject.Start`: density on the prefab's first
    collider; docs/angrybirds.md)."""
    catalogue = shape(placed.concrete)
    if catalogue.kind == "bird":
        return RULES.bird_mass
    density = RULES.pig_density if catalogue.kind == "pig" else MATERIAL.get(placed.material or "wood", MATERIAL["wood"]).density
    if RULES.colliders == "game" and catalogue.prefab in prefabs.prefabs():
        return prefabs.body_mass(catalogue.prefab, density)
    return placed.width * placed.height * density


def friction(placed) -> float:
    """The body's friction: its material's (pigs: the game's pig friction)."""
    catalogue = shape(placed.concrete)
    if catalogue.kind == "pig":
        return RULES.pig_friction
    return MATERIAL.get(placed.material or "wood", MATERIAL["wood"]).friction
