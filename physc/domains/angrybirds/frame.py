"""The Science Birds level's frame: its bounds, the ground, the slingshot, where objects go.

Facts cited in docs/angrybirds.md ("Level files", "The frame"): a `width="2"` level spans x in
[-17.5, 17.5] (objects beyond are destroyed, ABGameWorld.cs); the ground's top is at
y = -3.5; the slingshot stands at (-12, -2.5). A world holds one `Frame`
(physc.domains.angrybirds.worlds).
"""

from __future__ import annotations

import attrs


@attrs.frozen
class Area:
    """Where generated objects may be placed."""

    left: float = attrs.field(default=-10.0, metadata={"source": "physc: clear of the slingshot"})
    right: float = attrs.field(default=17.0, metadata={"source": "physc: inside the level's right edge"})
    bottom: float = attrs.field(default=-3.5, metadata={"source": "the ground's top"})
    top: float = attrs.field(default=7.0, metadata={"source": "physc: inside the camera's view"})


@attrs.frozen
class Frame:
    """The level's bounds and fixed furniture, in level units."""

    left: float = attrs.field(default=-17.5, metadata={"source": "ABGameWorld.cs: objects beyond ±17.5 are destroyed"})
    right: float = attrs.field(default=17.5, metadata={"source": "ABGameWorld.cs: objects beyond ±17.5 are destroyed"})
    ground_top: float = attrs.field(
        default=-3.5, metadata={"source": "Phy-Q's generator: GROUND_LEVEL -3.5 (docs/angrybirds.md, 'Level files')"}
    )
    slingshot: tuple[float, float] = attrs.field(
        default=(-12.0, -2.5),
        metadata={"source": "Phy-Q's templates: <Slingshot x=-12.0 y=-2.5> (docs/angrybirds.md, 'Level files')"},
    )
    placement: Area = attrs.field(factory=Area)
