"""What the platform-mass readings do to a block that slides onto a kinematic platform (issue 71,
point 3): the damage the game's formula deals there, worked out by hand below from the game's
C#, against physc's rule (physc.domains.angrybirds.damage.Strike, and Game._damage, which
builds the Strike from a contact), under each of the four readings sign × platform mass.

The game (phy-q/benchmark 514491c, tasks/task_template_designer/Assets):

* Scripts/GameWorld/ABBlock.cs 145-147, 239-242: a block struck by anything but a bird runs
  ABGameObject.OnCollisionEnter2D (base.OnCollisionEnter2D).
* Scripts/GameWorld/ABGameObject.cs 124-157, OnCollisionEnter2D:
      relativeSpeed = collision.relativeVelocity.magnitude                                   (132)
      attackerRB = _rigidBody                                                                  (135)
      collisionRB = collision.gameObject.GetComponent<Rigidbody2D>()                           (138)
      if collisionRB != null:                                                                  (141)
          projectCollision = cos(Vector2.Angle(relVel, collisionRB.velocity)·Deg2Rad)·|collisionRB.velocity|   (144)
          projectThis      = cos(Vector2.Angle(relVel, this.velocity)·Deg2Rad)·|this.velocity|                 (145)
          if projectCollision > projectThis: attackerRB = collisionRB                          (147-150)
      damage = max(relativeSpeed · attackerRB.mass · DAMAGE_CONSTANT_MULTIPLIER · 0.5 − _defense, 0)           (154)
* Scripts/Utils/ABConstants.cs 96: DAMAGE_CONSTANT_MULTIPLIER 11.22; 100-106: densities wood
  1.5, ice 0.75; defences wood 2.5, ice 2.
* Resources/Prefabs/GameWorld/Platform.prefab: components Transform, SpriteRenderer,
  Rigidbody2D, BoxCollider2D (lines 10-14: no ABGameObject script, so ABGameObject.Start's
  `useAutoMass = true` never runs on it); Rigidbody2D m_BodyType 1 (kinematic, line 94),
  m_UseAutoMass 0 (97), m_Mass 1 (98). `attackerRB.mass` for it is the stored 1 or Box2D's 0
  for a kinematic body: Unity's, not in the game's files (physc's open point
  rules.platform_mass). The platform never moves: its velocity is 0.
* Vector2.Angle (Unity's UnityCsReference Runtime/Export/Math/Vector2.cs, not the game's):
  0 when |from|·|to| < 1e-15, else acos(clamp(from·to / (|from||to|), −1, 1)) in degrees. So
  projectCollision is 0 for the still platform.
* collision.relativeVelocity's sign is Unity's (physc's open point rules.relative_velocity):
  "this-minus-other" (the block's velocity less the platform's) or "other-minus-this".

A block sliding onto a platform (its velocity along the platform, a little downwards) touches
it in a new contact whose relative velocity is almost all tangential; after the step it still
slides on. Read this-minus-other, its own projection is +|v| > 0: it attacks itself with its own
mass. Read other-minus-this, its projection is −|v| < 0 = projectCollision: the platform attacks
with the mass read for it, 1 (a unit mass's damage, whatever the block weighs) or 0 (nothing).
"""

from __future__ import annotations

import math

import pytest

from physc.backends import load_backend
from physc.domains.angrybirds import prefabs
from physc.domains.angrybirds.catalogue import MATERIAL
from physc.domains.angrybirds.damage import Party, Strike
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import OPEN_POINTS, PHYQ
from physc.simulation.trace import ContactRecord

# The game's constants, as ABConstants.cs has them (lines 96, 100-106).
DAMAGE_CONSTANT_MULTIPLIER = 11.22
DENSITY = {"wood": 1.5, "ice": 0.75}
DEFENSE = {"wood": 2.5, "ice": 2.0}
PLATFORM_STORED_MASS = 1.0  # Platform.prefab m_Mass (kinematic, no auto mass)

# The masses the game gives the two blocks (ABGameObject.Start 73-75: the first collider takes
# the script's density, auto mass on). SquareHole.prefab: a box 0.7636² (first) and a holed
# polygon, m_Mass 0.98760074 at density 1 for both, so the polygon's area is 0.98760074 − 0.7636²
# and it keeps density 1. RectSmall: one box 0.7636 × 0.184.
MASS = {
    ("SquareHole", "wood"): 0.7636**2 * DENSITY["wood"] + (0.98760074 - 0.7636**2),
    ("RectSmall", "ice"): 0.7636 * 0.184 * DENSITY["ice"],
}
LIFE = {("SquareHole", "wood"): 120.0, ("RectSmall", "ice"): 33.0}  # the prefabs' _woodLife, _iceLife

SIGNS = ("this-minus-other", "other-minus-this")
PLATFORM_MASSES = (1.0, 0.0)

# The slide: 2 units/s along the platform and 0.05 down as the contact begins (the velocities
# before the step, from which relativeVelocity is taken); after the step it slides on at 1.98,
# no longer going down. The platform is still.
BEFORE = (2.0, -0.05)
AFTER = (1.98, 0.0)
STILL = (0.0, 0.0)


def unity_angle(a, b) -> float:
    """Vector2.Angle(a, b), in degrees."""
    denominator = math.sqrt((a[0] ** 2 + a[1] ** 2) * (b[0] ** 2 + b[1] ** 2))
    if denominator < 1e-15:
        return 0.0
    dot = max(-1.0, min(1.0, (a[0] * b[0] + a[1] * b[1]) / denominator))
    return math.degrees(math.acos(dot))


def game_damage(sign: str, platform_mass: float, block_mass: float, defense: float) -> tuple[float, str]:
    """ABGameObject.OnCollisionEnter2D (lines 124-157) on the block, the platform being the
    collision's other body: (damage, "block" or "platform" as attackerRB)."""
    this_minus_other = (BEFORE[0] - STILL[0], BEFORE[1] - STILL[1])
    relative_velocity = this_minus_other if sign == "this-minus-other" else (-this_minus_other[0], -this_minus_other[1])
    relative_speed = math.hypot(*relative_velocity)  # line 132
    project_collision = math.cos(math.radians(unity_angle(relative_velocity, STILL))) * math.hypot(*STILL)  # line 144
    project_this = math.cos(math.radians(unity_angle(relative_velocity, AFTER))) * math.hypot(*AFTER)  # line 145
    attacker, mass = ("platform", platform_mass) if project_collision > project_this else ("block", block_mass)  # 147-150
    return max(relative_speed * mass * DAMAGE_CONSTANT_MULTIPLIER * 0.5 - defense, 0.0), attacker  # line 154


BLOCKS = (("SquareHole", "wood"), ("RectSmall", "ice"))


def test_physcs_readings_and_constants_are_the_games():
    """The open points' readings are the two of each left open, and physc's constants and
    masses for these blocks are the game's."""
    readings = {p.setting: p.readings for p in OPEN_POINTS}
    assert set(readings["rules.relative_velocity"]) == set(SIGNS)
    assert set(readings["rules.platform_mass"]) == set(PLATFORM_MASSES)
    assert PHYQ.rules.platform_mass == PLATFORM_STORED_MASS  # the world's own reading: the stored mass
    assert (PHYQ.rules.damage_factor, PHYQ.rules.block_damage_share) == (DAMAGE_CONSTANT_MULTIPLIER, 0.5)
    for (prefab, material), mass in MASS.items():
        assert (MATERIAL[material].density, MATERIAL[material].defence) == (DENSITY[material], DEFENSE[material])
        assert prefabs.body_mass(prefab, DENSITY[material]) == pytest.approx(mass, rel=1e-6)


def test_the_hand_worked_damage_of_a_wood_squarehole_sliding_at_2():
    """The numbers of the report: a wood SquareHole (1.2791) sliding at 2 units/s onto a platform."""
    mass, defense = MASS["SquareHole", "wood"], DEFENSE["wood"]
    speed = math.hypot(*BEFORE)
    assert mass == pytest.approx(1.27914, abs=1e-5) and speed == pytest.approx(2.000625, abs=1e-6)
    assert game_damage("this-minus-other", 1.0, mass, defense) == (pytest.approx(speed * mass * 5.61 - 2.5), "block")
    assert game_damage("this-minus-other", 1.0, mass, defense)[0] == pytest.approx(11.8565, abs=1e-4)
    assert game_damage("other-minus-this", 1.0, mass, defense) == (pytest.approx(8.7235, abs=1e-4), "platform")
    assert game_damage("other-minus-this", 0.0, mass, defense) == (0.0, "platform")


@pytest.mark.parametrize("block", BLOCKS, ids=lambda b: f"{b[1]} {b[0]}")
@pytest.mark.parametrize("sign", SIGNS)
@pytest.mark.parametrize("platform_mass", PLATFORM_MASSES)
def test_strike_deals_the_games_damage_to_a_block_sliding_onto_a_platform(block, sign, platform_mass):
    """Strike.dealt, the rule physc runs, against the game's formula worked by hand, in each
    reading (and both near-tie readings: the projections are 4 units/s apart, no tie)."""
    prefab, material = block
    mass, defense = MASS[block], DEFENSE[material]
    expected, attacker = game_damage(sign, platform_mass, mass, defense)
    # As Game._party reads the two bodies: the block's velocity after the step, the platform
    # still (its mass is the reading's); relative: the block's velocity less the platform's.
    strike = Strike(
        Party("block", "block", mass, AFTER), Party("platform", "platform", 0.0, STILL),
        math.hypot(*BEFORE), BEFORE, defense, material,
    )
    for near_tie in ("this", "other"):
        amount, by, _ = strike.dealt(PHYQ.rules, relative_velocity=sign, platform_mass=platform_mass, near_tie=near_tie)
        assert amount == pytest.approx(expected, rel=1e-9, abs=1e-12)
        assert by == {"block": "block", "platform": "platform"}[attacker]


@pytest.mark.parametrize("block", BLOCKS, ids=lambda b: f"{b[1]} {b[0]}")
@pytest.mark.parametrize("sign", SIGNS)
@pytest.mark.parametrize("platform_mass", PLATFORM_MASSES)
def test_the_games_damage_hook_deals_it_from_the_contact(block, sign, platform_mass):
    """One level up: Game._damage, handed the contact as a run records it (either order of the
    two bodies) with the block sliding on after the step, deals the same damage, and its
    record's least and most over every reading are those of the hand-worked four."""
    prefab, material = block
    platform = LevelObject("Platform", "Platform", 0.0, PHYQ.frame.ground_top + 1.0, 0.0, scale_x=8.0, name="ledge")
    obj = LevelObject("Block", prefab, 0.0, PHYQ.frame.ground_top + 3.0, 0.0, material, name="block")
    world = PHYQ.read_as((sign, platform_mass, PHYQ.rules.near_tie))  # OPEN_POINTS' order
    assert (world.rules.relative_velocity, world.rules.platform_mass) == (sign, platform_mass)
    expected, attacker = game_damage(sign, platform_mass, MASS[block], DEFENSE[material])
    every = [game_damage(s, m, MASS[block], DEFENSE[material])[0] for s in SIGNS for m in PLATFORM_MASSES]
    minus = (-BEFORE[0], -BEFORE[1])
    for a, b, relative in (("block", "ledge", BEFORE), ("ledge", "block", minus)):
        game = Game(Level(objects=(platform, obj)), world, load_backend("box2d"))
        engine = game.build()
        assert engine.mass("block") == pytest.approx(MASS[block], rel=1e-6)
        engine.set_velocity("block", *AFTER, 0.0)
        game.life["block"] = LIFE[block]
        velocities = (BEFORE, STILL) if a == "block" else (STILL, BEFORE)
        contact = ContactRecord(3.0, a, b, (0.0, 0.0), (0.0, -1.0) if a == "block" else (0.0, 1.0), relative, *velocities)
        out = []
        game._damage(engine, contact, out, 3.0)
        (record,) = out  # recorded even where this reading deals nothing: another would deal some
        assert record.target == "block" and record.amount == pytest.approx(expected, rel=1e-6)
        if expected > 0:
            assert record.attacker == {"block": "block", "platform": "ledge"}[attacker]
            assert record.life == pytest.approx(LIFE[block] - expected, rel=1e-6)
        assert (record.least, record.most) == (pytest.approx(min(every), abs=1e-9), pytest.approx(max(every), rel=1e-6))
