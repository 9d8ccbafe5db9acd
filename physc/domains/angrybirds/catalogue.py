"""The object catalogue of the angrybirds domain: shapes, sizes, materials, life.

Sizes are in Science Birds units (100 sprite pixels = 1 unit). Where the sources
disagree (docs/angrybirds.md has the full reasoning):

* rectangles use the Phy-Q collider boxes (smaller than the sprites), so real
  levels, which were built with those colliders, rest as built;
* Circle and CircleSmall are true circles whose radius is the distance from the
  centre to the flat bottom of the Phy-Q collider (0.375 and 0.21): they rest at
  the heights real levels give them, and, unlike the flat-bottomed Phy-Q polygon,
  they roll — rolling is central to the paper's scenarios;
* pigs are 12-gon ellipses of the Phy-Q pig collider's width and height;
* SquareHole and TriangleHole ignore their holes (a convex outline).
"""

from __future__ import annotations

import math

import attrs

PLATFORM_BASE = 0.64  # side of an unscaled Platform prefab
PHYQ_CIRCLES = {"circle": (24, 0.40), "circleSmall": (15, 0.225)}  # sides, sprite radius
PLATFORM_THICKNESS = 0.32  # every generated platform: scaleY = 0.5

MATERIALS = ("wood", "stone", "ice")


@attrs.frozen
class Material:
    name: str
    friction: float
    bounciness: float
    density: float
    defence: float


MATERIAL = {
    "wood": Material("wood", 4.0, 0.0, 1.5, 2.5),
    "stone": Material("stone", 4.0, 0.1, 4.0, 15.0),
    "ice": Material("ice", 0.7, 0.2, 0.75, 2.0),
}


@attrs.frozen
class Shape:
    """A catalogue entry: a concrete object of the object grammar, or a prefab of a real level."""

    name: str  # the object grammar's name (circle, pigSmall, …) or the prefab name
    prefab: str  # Science Birds type attribute (Circle, BasicSmall, …)
    kind: str  # "bird" | "pig" | "block" | "platform" | "tnt" | "ground"
    width: float
    height: float
    outline: str = "box"  # "box" | "circle" | "ellipse" | "polygon"
    points: tuple[tuple[float, float], ...] = ()  # the outline of a polygon, centred
    static: bool = False
    materials: tuple[str, ...] = ()
    life: dict = attrs.field(factory=dict)  # material (or "") → life

    @property
    def round(self) -> bool:
        return self.outline == "circle"

    def phyq_circle_points(self) -> tuple[tuple[float, float], ...]:
        """The Phy-Q collider of Circle / CircleSmall: a regular polygon on the sprite's
        circle (24 sides for Circle, 15 for CircleSmall) cut by a flat bottom chord at
        −width/2 (the rolling radius of the round model)."""
        sides, radius = PHYQ_CIRCLES[self.name]
        bottom = -self.width / 2
        points = []
        for k in range(sides):
            angle = 2 * math.pi * k / sides
            x, y = radius * math.cos(angle), radius * math.sin(angle)
            if y >= bottom:
                points.append((x, y))
        chord = math.sqrt(radius**2 - bottom**2)
        points += [(-chord, bottom), (chord, bottom)]
        return tuple(sorted(points, key=lambda p: math.atan2(p[1], p[0])))

    def outline_points(self) -> tuple[tuple[float, float], ...]:
        """The convex outline (for polygons and ellipses), centred on the object."""
        if self.outline == "polygon":
            return self.points
        if self.outline == "ellipse":
            # A 12-gon turned half a step, so that it stands on a flat edge (a pointed
            # bottom would rock), stretched so its flat edges lie at ±width/2, ±height/2.
            stretch = 1 / math.cos(math.pi / 12)
            return tuple(
                (
                    self.width / 2 * stretch * math.cos(math.pi / 12 + 2 * math.pi * k / 12),
                    self.height / 2 * stretch * math.sin(math.pi / 12 + 2 * math.pi * k / 12),
                )
                for k in range(12)
            )
        w, h = self.width / 2, self.height / 2
        return ((-w, -h), (w, -h), (w, h), (-w, h))


def _block(name, prefab, width, height, life, outline="box", points=()):
    return Shape(
        name,
        prefab,
        "block",
        width,
        height,
        outline,
        points,
        materials=MATERIALS,
        life=dict(zip(MATERIALS, life, strict=False)),
    )


_SHAPES = (
    # Birds: one circle each (Science Birds: r 0.17 for the red bird; birds.py has the rest).
    Shape("redBird", "BirdRed", "bird", 0.34, 0.34, "circle"),
    Shape("blueBird", "BirdBlue", "bird", 0.36, 0.36, "circle"),
    Shape("yellowBird", "BirdYellow", "bird", 0.32, 0.32, "circle"),
    Shape("blackBird", "BirdBlack", "bird", 0.40, 0.40, "circle"),
    Shape("whiteBird", "BirdWhite", "bird", 0.52, 0.52, "circle"),
    # Pigs: the object grammar's two, and BasicBig for real levels.
    Shape("pigSmall", "BasicSmall", "pig", 0.464, 0.45, "ellipse", life={"": 1}),
    Shape("pigMedium", "BasicMedium", "pig", 0.779, 0.756, "ellipse", life={"": 15}),
    Shape("pigBig", "BasicBig", "pig", 0.992, 0.963, "ellipse", life={"": 80}),
    # Blocks of the object grammar.
    _block("circleSmall", "CircleSmall", 0.42, 0.42, (150, 300, 100), "circle"),
    _block("circle", "Circle", 0.75, 0.75, (200, 600, 125), "circle"),
    _block("squareHole", "SquareHole", 0.7636, 0.7636, (120, 160, 70)),
    _block(
        "triangleHole",
        "TriangleHole",
        0.80,
        0.783,
        (70, 140, 48),
        "polygon",
        ((-0.40, -0.386), (0.40, -0.386), (0.0, 0.397)),
    ),
    # The other blocks of real levels.
    _block("rectFat", "RectFat", 0.7636, 0.3772, (80, 140, 53)),
    _block("squareSmall", "SquareSmall", 0.3772, 0.3772, (60, 100, 40)),
    _block("squareTiny", "SquareTiny", 0.184, 0.184, (20, 30, 13)),
    _block("rectTiny", "RectTiny", 0.3772, 0.184, (40, 60, 26)),
    _block("rectSmall", "RectSmall", 0.7636, 0.184, (50, 80, 33)),
    _block("rectMedium", "RectMedium", 1.5456, 0.184, (70, 120, 47)),
    _block("rectBig", "RectBig", 1.886, 0.184, (100, 140, 65)),
    _block(
        "triangle",
        "Triangle",
        0.75,
        0.75,
        (80, 140, 53),
        "polygon",
        ((-0.375, -0.375), (0.375, -0.375), (-0.375, 0.375)),
    ),
    # Static things.
    Shape("flatPlatform", "Platform", "platform", PLATFORM_BASE, PLATFORM_THICKNESS, static=True),
    Shape("inclinedPlatform", "Platform", "platform", PLATFORM_BASE, PLATFORM_THICKNESS, static=True),
    Shape("tnt", "TNT", "tnt", 0.64, 0.64, life={"": 3}),
    Shape("ground", "", "ground", 35.0, 1.0, static=True),
)

SHAPES = {s.name: s for s in _SHAPES}
BY_PREFAB = {}
for _shape in _SHAPES:
    BY_PREFAB.setdefault(_shape.prefab, _shape)  # Platform → flatPlatform
BIRD_PREFABS = ("BirdRed", "BirdBlue", "BirdYellow", "BirdBlack", "BirdWhite")


def shape(name: str) -> Shape:
    return SHAPES[name]


def by_prefab(prefab: str) -> Shape | None:
    return BY_PREFAB.get(prefab)


def extent(obj) -> tuple[float, float]:
    """Width and height of a level object: a platform's from its scales, any other's
    from the catalogue."""
    catalogue = BY_PREFAB[obj.type]
    if catalogue.kind == "platform":
        scale_x = 1.0 if obj.scale_x is None else obj.scale_x
        scale_y = 1.0 if obj.scale_y is None else obj.scale_y
        return PLATFORM_BASE * scale_x, PLATFORM_BASE * scale_y
    return catalogue.width, catalogue.height
