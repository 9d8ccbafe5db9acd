"""Science Birds' rules and body models, as named parameters of a world.

`Rules`: the game's rules (damage, TNT, the bird's removal, invulnerability); `Bodies`: how
its objects are bodies (colliders, drags, masses, materials). Each field's source is its
metadata (`physc worlds -v` lists them); the choices where sources disagree are argued in
docs/angrybirds.md. A world (physc.domains.angrybirds.worlds) holds one of each.
"""

from __future__ import annotations

import attrs

from physc.domains.angrybirds.catalogue import MATERIAL


def _cited(default, source: str, **options):
    return attrs.field(default=default, metadata={"source": source}, **options)


@attrs.frozen
class Rules:
    """Science Birds' rules. The defaults are the game's; another value is a deliberate departure."""

    # ABGameObject.OnCollisionEnter2D: |v_rel| · m_attacker · 11.22 · 0.5 − defence. Only
    # ABBlock overrides it for a bird (the full amount × the bird's multiplier), so a pig or
    # TNT struck by a bird takes the 0.5 formula too.
    damage_factor: float = _cited(11.22, "ABConstants.DAMAGE_CONSTANT_MULTIPLIER")
    block_damage_share: float = _cited(0.5, "ABGameObject.OnCollisionEnter2D")
    bird_multiplier: dict = attrs.field(
        factory=lambda: {"wood": 1.0, "stone": 1.0, "ice": 1.0, "": 1.0},
        metadata={"source": "BirdRed.prefab `_woodDamageMultiplier` etc."},
    )
    # Who attacks in a contact. "object": as the game's scripts do, each object in its own
    # OnCollisionEnter2D (called after the step) takes as attacker whichever of itself and the
    # other body has the larger velocity (after the step) along `Collision2D.relativeVelocity`;
    # "contact": physc's earlier model, one attacker per contact from the velocities before it.
    attacker: str = _cited("object", "ABGameObject.OnCollisionEnter2D: projectCollision > projectThis")
    # Which way `Collision2D.relativeVelocity` points, which the game's files leave open (Unity's
    # 2D physics computes it): "this-minus-other" (this object's velocity less the other's) or
    # "other-minus-this". A task must hold under both (ScienceBirdsWorld.readings).
    relative_velocity: str = _cited(
        "other-minus-this", "open: Unity's Collision2D.relativeVelocity (not in the game's files)"
    )
    # The platform's mass as the attacker's in a block's or pig's OnCollisionEnter2D. Platform.prefab
    # is a kinematic Rigidbody2D (`m_BodyType: 1`) with `m_Mass: 1` and no auto mass; what
    # `Rigidbody2D.mass` returns for a kinematic body (the stored 1, or Box2D's 0) is not in the
    # game's files. The platform never moves, so it attacks whenever the object's own velocity
    # after the step projects below 0 on relativeVelocity. A task must hold under both.
    platform_mass: float = _cited(1.0, "open: Platform.prefab Rigidbody2D m_BodyType 1 (kinematic), m_Mass 1")
    # Near ties of the attacker choice (`projectCollision > projectThis`, in Unity's float32):
    # projections closer than `tie_band` units/s are decided by rounding, which the files cannot
    # say; "this" (the comparison as written: an exact tie is not `>`): the object attacks
    # itself, "other": the other body attacks. A task must hold under both.
    near_tie: str = _cited(
        "this", "open: ABGameObject.OnCollisionEnter2D compares projectCollision > projectThis in float32"
    )
    # The band of a near tie: float32's resolution at the game's speeds (2⁻²³ of 16 units/s is
    # 2·10⁻⁶) times the few roundings of a projection, with room for the solver's order of
    # bodies (head-on pushes tie within 2·10⁻⁷ to 7·10⁻⁶ units/s, docs/angrybirds.md).
    tie_band: float = _cited(1e-4, "physc: float32 resolution of the projections at the game's speeds")
    pig_defence: float = _cited(1.0, "the pigs' prefabs `_defense`")
    invulnerable_seconds: float = _cited(2.0, "ABConstants.LEVEL_IMMORTAL_TIME: damage discarded for the first 2 s")
    # ABBird.cs: from its first collision on, the bird is checked 3 s later and then every
    # second, and removed once slower than 0.001 units/s; it never lives more than 20 s.
    bird_still_after: float = _cited(3.0, "ABBird.OnCollisionEnter2D: InvokeRepeating after 3 s")
    bird_still_every: float = _cited(1.0, "ABBird.OnCollisionEnter2D: InvokeRepeating every 1 s")
    bird_still_speed: float = _cited(0.001, "ABBird.CheckVelocityToDie")
    bird_lifetime: float = _cited(20.0, "BirdRed.prefab `lifeTime`")
    # A shot the agent sends is released `drag_seconds` after the game gets it (HUD.cs drags the
    # bird that long first), and the game takes none before the bird is on the slingshot, where
    # it jumps once the bird before struck something (ABGameWorld.KillBird; ABBird
    # SetBirdOnSlingshot at BirdRed.prefab's `_dragSpeed` 15 units/s over the 1 to 2 units from
    # where it waits): a timed shot leaves no sooner than `earliest_wait` after its turn began.
    drag_seconds: float = _cited(1.0, "HUD.cs `_simulateDragTime`")
    onto_slingshot_seconds: float = _cited(0.2, "ABBird.SetBirdOnSlingshot, BirdRed.prefab `_dragSpeed`")

    @property
    def earliest_wait(self) -> float:
        """The least `Shot.wait` the game can play (above)."""
        return self.onto_slingshot_seconds + self.drag_seconds

    # ABGameObject.Die: a dying object stops (velocity zeroed), disables GetComponent<Collider2D>()
    # (the first collider, which Unity returns enabled or not) and is destroyed after its
    # ABParticleSystem's `_systemLifetime` (prefabs.lifetime); until then what colliders it has
    # left stay solid, and every contact it begins stops it again (OnCollisionEnter2D →
    # DealDamage → Die). False: it leaves the world at once (physc's earlier model).
    dying_lingers: bool = _cited(True, "ABGameObject.Die, DealDamage; the prefabs' ABParticleSystem `_systemLifetime`")
    # ABTNT.cs: within the radius, damage and impulse fall off linearly with the distance
    # between the two objects' positions; birds are not affected.
    tnt_radius: float = _cited(2.5, "TNT.prefab `_explosionArea`")
    tnt_damage: float = _cited(100.0, "TNT.prefab `_explosionDamage`")
    tnt_impulse: float = _cited(4.0, "TNT.prefab `_explosionPower`")


@attrs.frozen
class Bodies:
    """How the game's objects are bodies: colliders, drags, masses and materials."""

    # "game": each prefab's own enabled colliders and the masses the game gives them
    # (physc.domains.angrybirds.prefabs); or physc's catalogue model with Circle and
    # CircleSmall as "round" (true circles) or "phyq" (regular polygons with the game's flat
    # foot) and density × area masses (benchmarks of the catalogue model).
    colliders: str = _cited("game", "the prefabs under Assets/Resources/Prefabs/GameWorld (tools/extract_prefabs.py)")
    # Whether a prefab whose first collider is a disabled circle before an enabled polygon
    # (Circle, CircleSmall, the pigs) collides as that circle instead (and the game's density
    # rule lands on it): False in Phy-Q's game.
    circle_colliders: bool = _cited(
        False, "Circle.prefab, CircleSmall.prefab, the pigs: the CircleCollider2D is disabled"
    )
    angular_drag: float = _cited(2.0, "the blocks' and pigs' prefabs: Rigidbody2D m_AngularDrag")
    bird_angular_drag: float = _cited(2.0, "BirdRed.prefab: Rigidbody2D m_AngularDrag")
    tnt_angular_drag: float = _cited(0.05, "TNT.prefab: Rigidbody2D m_AngularDrag")
    tnt_gravity_scale: float = _cited(1 / 0.48, "TNT.prefab: gravity scale 1, so it falls at the full 9.81")
    tnt_friction: float = _cited(0.4, "TNT.prefab names no material: Unity's default (0.4, bounciness 0)")
    tnt_density: float = _cited(1.0, "TNT.prefab `_density` (Start turns auto mass on: 0.64² × 1)")
    pig_density: float = _cited(2.0, "the pigs' prefabs `_density` (it lands on their first collider)")
    pig_friction: float = _cited(0.7, "PigMedium.physicsMaterial2D")
    pig_bounciness: float = _cited(0.05, "PigMedium.physicsMaterial2D")
    bird_mass: float = _cited(0.545, "BirdRed.prefab: circle r 0.17 × `_density` 6")
    bird_friction: float = _cited(0.3, "RedBird.physicsMaterial2D")
    bird_bounciness: float = _cited(0.43, "RedBird.physicsMaterial2D")
    platform_friction: float = _cited(0.4, "Platform.prefab names no material: Unity's default")
    ground_friction: float = _cited(0.4, "the ground names no material: Unity's default")
    materials: dict = attrs.field(
        factory=lambda: dict(MATERIAL),
        metadata={"source": "Wood, Stone, Ice .physicsMaterial2D; densities and defences: the blocks' scripts"},
    )
