"""The game's five birds and their powers, as its prefabs and scripts give them.

Each bird is a circle whose mass is its collider's area times its script's `_density`
(ABGameObject.Start turns auto mass on); all five share the launch (10 units/s at full
stretch, ABBird.LaunchBird), gravity scale 0.48, angular drag 2 and the 20-s lifetime. What
sets them apart is their size, material, the damage they deal each material (ABBlock: the
bird's `_woodDamageMultiplier` etc.) and the power a tap sets off (HUD.cs: once, while the
bird is the current one, past the slingshot and has struck nothing yet; the black bird also
after it struck):

* blue (ABBBirdBlue.SpecialAttack): three copies of itself at its place and speed, turned
  +15°, +5° and −5° from its heading (`_angleBetweenBirds` 10 apart from half the fan);
* yellow (ABBirdYellow): an impulse of 4 along its heading;
* black (ABBirdBlack): a blast (ABTNT.Explode) where it is, at the tap or 0.6 s after it
  first struck something (bird_black_explode.anim's event);
* white (ABBirdWhite): an egg dropped at an impulse of 6 (on the egg's stored mass of 1),
  the bird pushed up at 10; the egg (ABEgg) blasts at its first contact.

Birds never collide with birds (the layer matrix: Birds × Birds off), nor the egg with them.
Sources: docs/angrybirds.md, "The birds and their powers".
"""

from __future__ import annotations

import math

import attrs


def _cited(default, source: str):
    return attrs.field(default=default, metadata={"source": source})


@attrs.frozen
class Blast:
    """ABTNT.Explode's arguments: within `radius` of the centre, every body but the birds
    takes `damage` and an impulse of `power` away from it, both × max(1 − d/radius, 0)."""

    radius: float
    power: float
    damage: float


@attrs.frozen
class Bird:
    """One bird: its body and its power (`power`: "" none, "split", "boost", "blast", "egg")."""

    name: str  # the vocabulary's concrete object
    prefab: str
    radius: float  # the collider's, in the world (local radius × the prefab's scale)
    offset: tuple[float, float]  # the collider's offset from the bird's position, in the world
    density: float
    friction: float
    bounciness: float
    multipliers: dict  # material → ABBlock's damage multiplier for a bird
    power: str = ""

    @property
    def mass(self) -> float:
        """ABGameObject.Start: the collider's area × `_density` (auto mass)."""
        return math.pi * self.radius**2 * self.density


def _multipliers(wood: float, stone: float, ice: float) -> dict:
    return {"wood": wood, "stone": stone, "ice": ice, "": 1.0}


@attrs.frozen
class Powers:
    """The powers' numbers (the birds' prefabs, the egg's, their scripts)."""

    split_angles: tuple[float, ...] = _cited(
        (15.0, 5.0, -5.0), "BirdBlue.prefab `_childrenAmount` 3, `_angleBetweenBirds` 10; ABBBirdBlue.SpecialAttack"
    )
    boost: float = _cited(4.0, "BirdYellow.prefab `_specialAttackForce` (an impulse along the heading)")
    black_blast: Blast = _cited(
        Blast(3.0, 4.0, 20.0), "BirdBlack.prefab `_explosionArea`, `_explosionPower`, `_explosionDamage`"
    )
    black_fuse: float = _cited(0.6, "bird_black_explode.anim: the event calling Explode at 0.6 s")
    egg_blast: Blast = _cited(
        Blast(2.0, 2.0, 200.0), "Egg.prefab `_explosionArea`, `_explosionPower`, `_explosionDamage`"
    )
    egg_drop: float = _cited(
        6.0, "BirdWhite.prefab `_eggForce`, on the egg's stored Rigidbody2D mass 1 (auto mass comes at its Start)"
    )
    egg_stored_mass: float = _cited(
        1.0, "Egg.prefab Rigidbody2D m_Mass 1, m_UseAutoMass 0: the mass the drop's impulse meets"
    )
    egg_push_up: float = _cited(10.0, "BirdWhite.prefab `_pushUpForce` (an impulse on the bird)")
    egg_outline: tuple = _cited(
        (
            (0.105, 0.29),
            (-0.115, 0.29),
            (-0.205, 0.22),
            (-0.225, 0.15),
            (-0.225, -0.25),
            (-0.165, -0.29),
            (0.135, -0.29),
            (0.225, -0.22),
            (0.225, 0.2),
            (0.215, 0.25),
        ),
        "Egg.prefab PolygonCollider2D points",
    )
    egg_density: float = _cited(1.0, "Egg.prefab ABEgg `_density`")
    egg_gravity_scale: float = _cited(
        1 / 0.48, "Egg.prefab Rigidbody2D m_GravityScale 1: the full 9.81, where the world's is 9.81 × the birds' 0.48"
    )
    egg_friction: float = _cited(0.4, "Egg.prefab names no material: Unity's default")
    past_slingshot: float = _cited(2.0, "ABBird.IsInFrontOfSlingshot: x + diameter > rest x + 2 × `_dragRadius`")


BIRDS = (
    Bird("redBird", "BirdRed", 0.17, (0.05, -0.03), 6.0, 0.3, 0.43, _multipliers(1.0, 1.0, 1.0)),
    Bird("blueBird", "BirdBlue", 0.18, (0.03, -0.015), 4.5, 0.3, 0.25, _multipliers(1.0, 1.0, 4.0), "split"),
    Bird("yellowBird", "BirdYellow", 0.16, (0.03, -0.06), 6.0, 0.4, 0.16, _multipliers(2.4, 1.0, 1.2), "boost"),
    Bird("blackBird", "BirdBlack", 0.20, (0.03, -0.15), 6.0, 0.3, 0.03, _multipliers(1.0, 2.5, 1.0), "blast"),
    Bird("whiteBird", "BirdWhite", 0.26, (0.09, -0.16), 4.0, 0.3, 0.23, _multipliers(0.8, 1.0, 0.8), "egg"),
)
BIRD_SOURCES = (
    "Resources/Prefabs/GameWorld/Characters/Birds/Bird*.prefab: CircleCollider2D m_Radius and m_Offset × m_LocalScale, "
    "`_density`, the `_woodDamageMultiplier`, `_stoneDamageMultiplier`, `_iceDamageMultiplier`; "
    "Resources/Materials/*Bird.physicsMaterial2D"
)
BY_PREFAB = {bird.prefab: bird for bird in BIRDS}
BY_NAME = {bird.name: bird for bird in BIRDS}
POWERS = Powers()


def bird(prefab: str) -> Bird:
    """The bird of a level's <Bird type=…> (the red bird for a type the game does not have)."""
    return BY_PREFAB.get(prefab, BIRDS[0])
