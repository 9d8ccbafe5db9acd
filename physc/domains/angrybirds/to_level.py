"""From a concrete layout to a Science Birds level (the emit step's model)."""

from __future__ import annotations

from physc.compiler.concrete_layout import ConcreteLayout
from physc.domains.angrybirds.catalogue import PLATFORM_BASE, shape
from physc.domains.angrybirds.level import Level, LevelObject

DECIMALS = 5  # as the Phy-Q level editor writes them


def _round(value: float) -> float:
    return round(value, DECIMALS) + 0.0  # no "-0"


def level_from_layout(layout: ConcreteLayout) -> Level:
    objects = []
    for placed in layout.objects:
        catalogue = shape(placed.concrete)
        if catalogue.kind in ("bird", "ground"):
            continue
        rotation = _round(placed.rotation)
        if catalogue.kind == "platform":
            objects.append(
                LevelObject(
                    "Platform",
                    "Platform",
                    _round(placed.x),
                    _round(placed.y),
                    rotation,
                    scale_x=_round(placed.width / PLATFORM_BASE),
                    scale_y=_round(placed.height / PLATFORM_BASE),
                    name=placed.name,
                )
            )
        elif catalogue.kind == "pig":
            objects.append(LevelObject("Pig", catalogue.prefab, _round(placed.x), _round(placed.y), rotation, name=placed.name))
        else:
            objects.append(
                LevelObject("Block", catalogue.prefab, _round(placed.x), _round(placed.y), rotation, placed.material, name=placed.name)
            )
    return Level(objects=tuple(objects))
