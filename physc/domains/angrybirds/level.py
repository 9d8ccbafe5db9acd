"""A Science Birds level, as its XML file says it (docs/angrybirds.md, "Level files").

The model keeps what a file says and nothing else: an attribute that is absent
stays `None` (so `material=""` and no material at all are told apart), and
numbers are floats. Import → emit → import gives an equal model. The one
reading that is not literal is the game's own: a <TNT> or <Platform> is its
prefab whatever its `type` says, so `<TNT type="">` has the type TNT here.

A level physc writes also names the world it was made for and the physc that made it, as
attributes of <Level> (`world="rolling" generator="physc 0.1.0"`): the game's loader reads
<Level> by attribute name (only `width`, LevelLoader.cs `LoadXmlLevel`) and passes over any
other, so the file still loads as it is (docs/angrybirds.md, "A level names its world").
"""

from __future__ import annotations

import attrs

ELEMENTS = ("Block", "Pig", "TNT", "Platform")
DECIMALS = 5  # as the Phy-Q level editor writes them


def level_number(value: float) -> float:
    """`value` as a level holds it: a Python float (not numpy's) to DECIMALS places, never -0."""
    return round(float(value), DECIMALS) + 0.0


@attrs.frozen
class LevelObject:
    element: str  # Block | Pig | TNT | Platform
    type: str  # the prefab name: Circle, BasicSmall, Platform, TNT, …
    x: float
    y: float
    rotation: float | None = None  # degrees, counter-clockwise
    material: str | None = None
    scale_x: float | None = None
    scale_y: float | None = None
    name: str = attrs.field(default="", eq=False)  # how physc refers to it (pig1, circle2, …)


@attrs.frozen
class Camera:
    x: float = 0.0
    y: float = -1.0
    min_width: float = 25.0
    max_width: float = 35.0


@attrs.frozen
class Level:
    width: float = 2.0
    camera: Camera = Camera()
    high_score: float | None = 0.0
    birds: tuple[str, ...] = ("BirdRed",)
    slingshot: tuple[float, float] = (-12.0, -2.5)
    objects: tuple[LevelObject, ...] = ()
    world: str | None = None  # the world it was made for (physc worlds); None: a level that names none
    generator: str | None = None  # what wrote it ("physc 0.1.0"); None: not said

    @property
    def has_birds(self) -> bool:
        """Whether there is a bird to shoot (a level without one can still be watched standing)."""
        return bool(self.birds)
