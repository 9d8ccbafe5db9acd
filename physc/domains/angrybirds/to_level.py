"""From a concrete layout to a Science Birds level (the emit step's model)."""

from __future__ import annotations

from physc.compiler.concrete_layout import ConcreteLayout
from physc.domains.angrybirds.catalogue import PLATFORM_BASE, shape
from physc.domains.angrybirds.level import Level, LevelObject, level_number


def level_from_layout(layout: ConcreteLayout) -> Level:
    objects = []
    for placed in layout.objects:
        catalogue = shape(placed.concrete)
        if catalogue.kind in ("bird", "ground"):
            continue
        rotation = level_number(placed.rotation)
        if catalogue.kind == "platform":
            objects.append(
                LevelObject(
                    "Platform",
                    "Platform",
                    level_number(placed.x),
                    level_number(placed.y),
                    rotation,
                    scale_x=level_number(placed.width / PLATFORM_BASE),
                    scale_y=level_number(placed.height / PLATFORM_BASE),
                    name=placed.name,
                )
            )
        elif catalogue.kind == "pig":
            objects.append(
                LevelObject(
                    "Pig", catalogue.prefab, level_number(placed.x), level_number(placed.y), rotation, name=placed.name
                )
            )
        elif catalogue.kind == "tnt":  # the game's <TNT> element (LevelLoader.cs), its own prefab
            objects.append(
                LevelObject(
                    "TNT", catalogue.prefab, level_number(placed.x), level_number(placed.y), rotation, name=placed.name
                )
            )
        else:
            objects.append(
                LevelObject(
                    "Block",
                    catalogue.prefab,
                    level_number(placed.x),
                    level_number(placed.y),
                    rotation,
                    placed.material,
                    name=placed.name,
                )
            )
    return Level(objects=tuple(objects))
