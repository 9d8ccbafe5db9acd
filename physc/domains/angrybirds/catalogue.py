"""The concrete game objects of the angrybirds domain: shapes, sizes, materials.

Sizes are in Science Birds units (100 sprite pixels = 1 unit). The layout passes
use the sprite sizes (what a player sees and what every Python level generator
uses); the rolling blocks are true circles (the Phy-Q colliders of Circle and
CircleSmall have a flat bottom chord that stops them rolling: see
docs/angrybirds.md). Platforms are boxes of 0.64 × 0.64 scaled by scaleX/scaleY.
"""

from __future__ import annotations

import attrs

PLATFORM_BASE = 0.64  # side of an unscaled Platform prefab
PLATFORM_THICKNESS = 0.32  # every generated platform: scaleY = 0.5

MATERIALS = ("wood", "stone", "ice")


@attrs.frozen
class Shape:
    """The catalogue entry of a concrete object."""

    name: str  # the object grammar's name (circle, pigSmall, …)
    prefab: str  # Science Birds type attribute (Circle, BasicSmall, …)
    kind: str  # "bird" | "pig" | "block" | "platform" | "ground"
    width: float
    height: float
    round: bool = False  # a circle (width = height = diameter)
    static: bool = False
    materials: tuple[str, ...] = ()


SHAPES = {
    s.name: s
    for s in (
        Shape("redBird", "BirdRed", "bird", 0.34, 0.34, round=True),
        Shape("pigSmall", "BasicSmall", "pig", 0.464, 0.45),
        Shape("pigMedium", "BasicMedium", "pig", 0.779, 0.756),
        Shape("circleSmall", "CircleSmall", "block", 0.45, 0.45, round=True, materials=MATERIALS),
        Shape("circle", "Circle", "block", 0.80, 0.80, round=True, materials=MATERIALS),
        Shape("squareHole", "SquareHole", "block", 0.84, 0.84, materials=MATERIALS),
        Shape("triangleHole", "TriangleHole", "block", 0.82, 0.82, materials=MATERIALS),
        Shape("flatPlatform", "Platform", "platform", PLATFORM_BASE, PLATFORM_THICKNESS, static=True),
        Shape("inclinedPlatform", "Platform", "platform", PLATFORM_BASE, PLATFORM_THICKNESS, static=True),
        Shape("ground", "", "ground", 35.0, 1.0, static=True),
    )
}


def shape(name: str) -> Shape:
    return SHAPES[name]
