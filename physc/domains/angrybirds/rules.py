"""The game rules of Science Birds (Phy-Q version), as named parameters.

Facts from shared/design/sciencebirds-facts.md §2–3; the choices where sources
disagree are argued in docs/angrybirds.md.
"""

from __future__ import annotations

import attrs

from physc.domains.angrybirds.world import GRAVITY, LEVEL_LEFT, LEVEL_RIGHT


@attrs.frozen
class Rules:
    gravity: float = GRAVITY  # 9.81 × gravity scale 0.48: blocks, pigs and birds
    # Circle and CircleSmall: "round" (true circles that roll; the default) or "phyq"
    # (the Phy-Q game's polygons with a flat bottom chord, which real levels rely on).
    circles: str = "round"
    tnt_gravity_scale: float = 1 / 0.48  # TNT falls at the full 9.81
    dt: float = 0.02  # Unity's fixed timestep
    angular_drag: float = 2.0
    damage_factor: float = 11.22  # damage = |v_rel| · m_attacker · 11.22 · 0.5 − defence
    block_damage_share: float = 0.5  # the 0.5 of that formula (birds deal the full amount)
    bird_multiplier: dict = attrs.field(factory=lambda: {"wood": 1.0, "stone": 1.0, "ice": 1.0, "": 1.0})
    pig_defence: float = 1.0
    pig_density: float = 2.0
    pig_friction: float = 0.7
    pig_bounciness: float = 0.05
    bird_mass: float = 0.545
    bird_friction: float = 0.3
    bird_bounciness: float = 0.43
    platform_friction: float = 0.4  # Unity's default physics material (the facts name none)
    ground_friction: float = 0.4
    invulnerable_seconds: float = 2.0  # damage is discarded for the first 2 s of a level
    bird_still_after: float = 3.0  # a bird nearly still after 3 s is removed
    bird_still_speed: float = 0.1
    bird_lifetime: float = 20.0
    world_left: float = LEVEL_LEFT  # objects leaving [left, right] are destroyed
    world_right: float = LEVEL_RIGHT
    tnt_radius: float = 2.5
    tnt_damage: float = 100.0
    tnt_impulse: float = 4.0


RULES = Rules()
