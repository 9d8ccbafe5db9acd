"""Bodies with fixed shapes, and the Concrete Layout IR (`--emit layout`)."""

from __future__ import annotations

import attrs

from physc.compiler.geometry import Geometry


@attrs.frozen
class Body:
    """A layout node made concrete: which game object, its material and shape.
    `fixed` is the centre for bodies the domain puts in a fixed place (the bird)."""

    name: str
    role: str  # player | object | support
    concrete: str
    geometry: Geometry
    material: str | None = None
    fixed: tuple[float, float] | None = None


@attrs.frozen
class PlacedObject:
    name: str
    role: str
    concrete: str
    material: str | None
    x: float  # centre
    y: float
    rotation: float  # degrees, counter-clockwise
    width: float
    height: float

    @property
    def geometry(self) -> Geometry:
        return Geometry(self.width, self.height, self.rotation)

    def points(self) -> dict[str, tuple[float, float]]:
        return self.geometry.points(self.x, self.y)


@attrs.frozen
class ChosenRelation:
    """One QSR of the chosen conjunction, with the layout edge it realises."""

    relation: str
    a: str
    b: str
    edge: str  # the layout edge, e.g. "inDirection(rBlock, surface, left)"
    alternatives: tuple[str, ...] = ()  # every QSR of the edge's clause (any one realises the edge)


@attrs.frozen
class ConcreteLayout:
    scenario: str
    domain: str
    seed: int
    objects: tuple[PlacedObject, ...]
    conjunction: tuple[ChosenRelation, ...]
    separations: tuple[ChosenRelation, ...]  # added by placement to keep objects apart
    deferred: tuple[str, ...]  # layout edges left to simulation
    conjunctions_tried: int
    conjunctions_rejected: int
    shape_draws: int

    def object(self, name: str) -> PlacedObject:
        return next(o for o in self.objects if o.name == name)
