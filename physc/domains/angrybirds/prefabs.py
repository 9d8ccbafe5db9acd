"""Science Birds' own colliders and masses, as its prefabs give them.

`prefabs.json` beside this module is read from the game's Unity project by
tools/extract_prefabs.py (docs/angrybirds.md, "The game's colliders"): each prefab's
colliders in component order, its Rigidbody2D and its script's fields. The game's bodies
follow from two rules of Unity and one line of the game:

* a Rigidbody2D with auto mass weighs the sum over its *enabled* colliders of area × the
  collider's density;
* a PolygonCollider2D's paths are filled even-odd: a path inside another is a hole
  (TriangleHole's and SquareHole's; the saved masses confirm it);
* `ABGameObject.Start` sets `GetComponent<Collider2D>().density = _density`, and
  `GetComponent` returns the *first* collider in component order, enabled or not. Circle,
  CircleSmall and the pigs list a disabled CircleCollider2D first, so their polygon keeps
  density 1 whatever the material: a stone Circle weighs what a wood one does, and a pig
  half of what density 2 would give. SquareHole's box gets the material's density and its
  holed polygon keeps 1.

`body_shape` and `body_mass` give a level object's collision shape (convex parts,
physc.backends.convex) and its mass under those rules. With `circle_colliders` (a world's
body model: the `rolling` world) a prefab whose first collider is a disabled circle before an
enabled polygon (`circle_first`) collides as that circle instead, and, being first, the
circle takes the script's density.
"""

from __future__ import annotations

import functools
import json
import math
from pathlib import Path

from physc.backends import Circle, Compound, Polygon
from physc.backends.convex import convex_parts, signed_area

DATA = Path(__file__).with_name("prefabs.json")


@functools.cache
def prefabs() -> dict:
    """The prefabs as tools/extract_prefabs.py wrote them (name → colliders, rigidbody, script)."""
    return json.loads(DATA.read_text(encoding="utf-8"))["prefabs"]


def _rings(collider: dict) -> tuple[tuple[tuple[float, float], ...], list]:
    """A polygon collider's outline and holes: the largest path is the outline, the others
    (inside it, even-odd) holes."""
    dx, dy = collider["offset"]
    paths = [tuple((x + dx, y + dy) for x, y in path) for path in collider["paths"]]
    paths.sort(key=lambda p: -abs(signed_area(p)))
    return paths[0], paths[1:]


def _collider_parts(collider: dict) -> tuple[Polygon | Circle, ...]:
    if collider["type"] == "box":
        (w, h), (dx, dy) = collider["size"], collider["offset"]
        return (
            Polygon(
                ((dx - w / 2, dy - h / 2), (dx + w / 2, dy - h / 2), (dx + w / 2, dy + h / 2), (dx - w / 2, dy + h / 2))
            ),
        )
    if collider["type"] == "circle":
        if collider["offset"] != [0.0, 0.0]:
            raise ValueError("an off-centre circle collider is not a physc shape")
        return (Circle(collider["radius"]),)
    outline, holes = _rings(collider)
    return tuple(Polygon(points) for points in convex_parts(outline, holes))


def _area(collider: dict) -> float:
    if collider["type"] == "box":
        return collider["size"][0] * collider["size"][1]
    if collider["type"] == "circle":
        return math.pi * collider["radius"] ** 2
    outline, holes = _rings(collider)
    return abs(signed_area(outline)) - sum(abs(signed_area(h)) for h in holes)


def circle_first(prefab: str) -> bool:
    """Whether the prefab's first collider is a disabled circle listed before an enabled
    polygon (Phy-Q's Circle, CircleSmall and pigs)."""
    colliders = prefabs()[prefab]["colliders"]
    return (
        len(colliders) >= 2
        and colliders[0]["type"] == "circle"
        and not colliders[0]["enabled"]
        and any(c["type"] == "polygon" and c["enabled"] for c in colliders[1:])
    )


def colliders(prefab: str, circle_colliders: bool = False) -> list[tuple[int, dict]]:
    """(index, collider) of the colliders the body collides with: the enabled ones, or with
    `circle_colliders` and a `circle_first` prefab, its first circle alone."""
    listed = prefabs()[prefab]["colliders"]
    if circle_colliders and circle_first(prefab):
        return [(0, listed[0])]
    return [(index, c) for index, c in enumerate(listed) if c["enabled"]]


def enabled(prefab: str) -> list[dict]:
    return [c for _, c in colliders(prefab)]


@functools.cache
def body_shape(prefab: str, circle_colliders: bool = False) -> Circle | Polygon | Compound:
    """The prefab's colliders (`colliders`) as one body's shape (convex parts about its origin,
    each naming its collider: the game hears of a contact once per pair of colliders)."""
    pieces = [
        (index, part) for index, collider in colliders(prefab, circle_colliders) for part in _collider_parts(collider)
    ]
    parts = tuple(part for _, part in pieces)
    return parts[0] if len(parts) == 1 else Compound(parts, tuple(index for index, _ in pieces))


@functools.cache
def body_mass(prefab: str, density: float, circle_colliders: bool = False) -> float:
    """The prefab's mass when its script's density is `density`: the first collider (enabled
    or not) takes that density, every other keeps its own; only those it collides with weigh."""
    return sum(_area(c) * (density if index == 0 else c["density"]) for index, c in colliders(prefab, circle_colliders))


def circle_radius(prefab: str, circle_colliders: bool = False) -> float | None:
    """The radius of the prefab's body when it collides as one circle, else None."""
    shape = body_shape(prefab, circle_colliders)
    return shape.radius if isinstance(shape, Circle) else None


def lifetime(prefab: str) -> float:
    """How long the prefab's object stays in the world once it dies, before its Destroy
    (its ABParticleSystem's `_systemLifetime`; 0 when it has none)."""
    return float(prefabs()[prefab]["script"].get("_systemLifetime", 0.0))


def first_collider_enabled(prefab: str, circle_colliders: bool = False) -> bool:
    """Whether the body collides with the prefab's first collider, the one a dying object
    disables (ABGameObject.Die: GetComponent<Collider2D>())."""
    return any(index == 0 for index, _ in colliders(prefab, circle_colliders))
