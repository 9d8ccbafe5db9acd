"""The game rules of Science Birds (Phy-Q version), as named parameters.

Facts from shared/design/sciencebirds-facts.md §2–3; the choices where sources
disagree are argued in docs/angrybirds.md.
"""

from __future__ import annotations

import math

import attrs

from physc.backends.settings import EngineSettings
from physc.domains.angrybirds.world import GRAVITY, LEVEL_LEFT, LEVEL_RIGHT

# Unity's 2D physics (Box2D) as Science Birds configures it: ProjectSettings/Physics2DSettings.asset
# (100 velocity and 100 position iterations, velocity threshold 1, Baumgarte 0.2 / TOI 0.75,
# max linear correction 0.2, max angular correction 8°, max translation speed 100 units/s,
# sleeping after 0.5 s below 0.01 units/s and 2°/s, contact offset 0.01) and
# ProjectSettings/TimeManager.asset (fixed step 0.02 s). docs/angrybirds.md cites each.
SCIENCE_BIRDS_ENGINE = EngineSettings(
    dt=0.02,
    velocity_iterations=100,
    position_iterations=100,
    restitution_threshold=1.0,
    linear_slop=0.005,  # half the contact offset 0.01
    baumgarte=0.2,
    toi_baumgarte=0.75,
    max_linear_correction=0.2,
    max_angular_correction=math.radians(8.0),
    max_translation=100 * 0.02,  # m_MaxTranslationSpeed per step
    time_to_sleep=0.5,
    linear_sleep_tolerance=0.01,
    angular_sleep_tolerance=math.radians(2.0),
)


@attrs.frozen
class Rules:
    """Science Birds' rules, each a named parameter (docs/angrybirds.md cites the game file
    of each). The defaults are the game's; another value is a deliberate departure."""

    gravity: float = GRAVITY  # 9.81 × gravity scale 0.48: blocks, pigs and birds
    # The bodies' collision shapes and masses: "game" (each prefab's own colliders and the
    # masses the game gives them, physc.domains.angrybirds.prefabs; the default), or physc's
    # catalogue model with Circle and CircleSmall as "round" (true circles that roll) or
    # "phyq" (regular polygons with the game's flat foot) and density × area masses.
    colliders: str = "game"
    tnt_gravity_scale: float = 1 / 0.48  # TNT.prefab: gravity scale 1, so it falls at the full 9.81
    engine: EngineSettings = SCIENCE_BIRDS_ENGINE
    angular_drag: float = 2.0  # blocks', pigs' and birds' prefabs
    tnt_angular_drag: float = 0.05  # TNT.prefab
    tnt_friction: float = 0.4  # TNT.prefab names no material: Unity's default (0.4, bounciness 0)
    tnt_density: float = 1.0  # TNT.prefab `_density` (Start turns auto mass on: 0.64² × 1)
    damage_factor: float = 11.22  # ABConstants.DAMAGE_CONSTANT_MULTIPLIER
    # ABGameObject.OnCollisionEnter2D: |v_rel| · m_attacker · 11.22 · 0.5 − defence. Only
    # ABBlock overrides it for a bird (the full amount × the bird's multiplier), so a pig or
    # TNT struck by a bird takes the 0.5 formula too.
    block_damage_share: float = 0.5
    bird_multiplier: dict = attrs.field(factory=lambda: {"wood": 1.0, "stone": 1.0, "ice": 1.0, "": 1.0})  # BirdRed.prefab
    pig_defence: float = 1.0
    pig_density: float = 2.0  # the pigs' `_density`; with colliders "game" it lands on their disabled circle
    pig_friction: float = 0.7
    pig_bounciness: float = 0.05
    bird_mass: float = 0.545  # BirdRed: circle r 0.17 × density 6
    bird_friction: float = 0.3
    bird_bounciness: float = 0.43
    platform_friction: float = 0.4  # Platform.prefab names no material: Unity's default
    ground_friction: float = 0.4
    invulnerable_seconds: float = 2.0  # ABConstants.LEVEL_IMMORTAL_TIME: damage discarded for the first 2 s
    # ABBird.cs: from its first collision on, the bird is checked 3 s later and then every
    # second, and removed once slower than 0.001 units/s; it never lives more than 20 s.
    bird_still_after: float = 3.0
    bird_still_every: float = 1.0
    bird_still_speed: float = 0.001
    bird_lifetime: float = 20.0
    world_left: float = LEVEL_LEFT  # objects leaving [left, right] are destroyed
    world_right: float = LEVEL_RIGHT
    # ABTNT.cs: within the radius, damage and impulse fall off linearly with the distance
    # between the two objects' positions; birds are not affected.
    tnt_radius: float = 2.5
    tnt_damage: float = 100.0
    tnt_impulse: float = 4.0

    @property
    def dt(self) -> float:
        """The seconds of one step (Unity's fixed timestep)."""
        return self.engine.dt


RULES = Rules()
