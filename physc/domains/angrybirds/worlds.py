"""Science Birds' worlds: Phy-Q's game (`phyq`, the default) and a rolling variant.

`phyq` is the game of the Phy-Q testbed (phy-q/benchmark, the Unity project under
tasks/task_template_designer) as physc models it: Unity's Box2D at the project's settings,
the prefabs' own colliders, masses and drags, the scripts' rules. Each setting cites the
file it is read from (`physc worlds -v`; docs/angrybirds.md has the reasoning).

`rolling` is physc's reading of the paper's unpublished changes ("a modified version of
Science Birds, with adjusted physics parameters"): the same game, except that the circle
colliders Phy-Q ships disabled on Circle, CircleSmall and the pigs are the ones used, and
blocks and pigs have angular drag 0.05, as the original Science Birds' prefabs have. It is
not the paper's own game, whose values were never published; patches/rolling/ makes the
game itself play this way.
"""

from __future__ import annotations

import math

import attrs

from physc.backends.settings import EngineSettings
from physc.domains.angrybirds.frame import Frame
from physc.domains.angrybirds.launch import Launch
from physc.domains.angrybirds.rules import Bodies, Rules
from physc.simulation.recognise import Recogniser
from physc.worlds import Incline, OpenPoint, World

# Unity's 2D physics (Box2D) as Science Birds configures it.
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


OPEN_POINTS = (
    OpenPoint(
        "rules.relative_velocity",
        ("other-minus-this", "this-minus-other"),
        "which way Collision2D.relativeVelocity points",
        "Unity's Collision2D.relativeVelocity: not in the game's files, and Unity does not document its sign",
        "relativeVelocity {value}",
    ),
    OpenPoint(
        "rules.platform_mass",
        (1.0, 0.0),
        "what Rigidbody2D.mass returns for the kinematic platform",
        "Platform.prefab: Rigidbody2D m_BodyType 1 (kinematic), m_Mass 1, m_UseAutoMass 0",
        "platform mass {value:g}",
    ),
    OpenPoint(
        "rules.near_tie",
        ("this", "other"),
        "which body attacks when the two projections tie within rules.tie_band",
        "ABGameObject.OnCollisionEnter2D: projectCollision > projectThis, in float32",
        "near ties: {value} attacks",
    ),
)


@attrs.frozen(kw_only=True)
class ScienceBirdsWorld(World):
    """A Science Birds world: the generic settings, and the game's frame, launch, bodies and rules."""

    frame: Frame = attrs.field(factory=Frame)
    launch: Launch = attrs.field(factory=Launch)
    bodies: Bodies = attrs.field(factory=Bodies)
    rules: Rules = attrs.field(factory=Rules)
    rest_speed: float = attrs.field(
        default=0.02, metadata={"source": "physc: below this (units/s, rad/s) a body counts as at rest"}
    )
    falling_speed: float = attrs.field(
        default=0.5, metadata={"source": "physc: coming down faster (units/s), a body is still falling"}
    )

    def open_points(self) -> tuple[OpenPoint, ...]:
        """What the game's files leave open about its damage rule (docs/angrybirds.md, "Points
        the game's files leave open"): the sign of `Collision2D.relativeVelocity`, the
        kinematic platform's mass, and which body attacks in a near tie. Each decides, in
        `ABGameObject.OnCollisionEnter2D`, whose mass sets a damage. physc's earlier model
        (`attacker="contact"`) reads none of them."""
        if self.rules.attacker != "object":
            return ()
        return OPEN_POINTS

    def reachable(self, x: float, y: float) -> bool:
        """Whether a full-stretch shot can pass through (x, y) in this world."""
        return self.launch.reachable(x, y, self.gravity)


PHYQ = ScienceBirdsWorld(
    name="phyq",
    description="Phy-Q's Science Birds as shipped (phy-q/benchmark): flat-footed circles, angular drag 2",
    engine=SCIENCE_BIRDS_ENGINE,
    gravity=9.81 * 0.48,
    recogniser=Recogniser(
        hit_speed=0.3,
        rehit=0.1,
        moving=0.15,
        roll_slip=0.5,
        slide_spin=1.0,
        motion_time=0.2,
        fall_time=0.2,
        fall_height=0.4,
        bounce_time=0.2,
        bounce_speed=1.0,
        surfaces=("platform", "ground"),
        background=("ground",),
        thrown=("bird",),
        explosive=("tnt",),
        travel=0.22,
        hop_rise=1.0,
        round_slides=False,
        bounce_walls=True,
    ),
    incline=Incline(descending=(10.0, 25.0), other=(15.0, 40.0), ramp=(12.7, 26.8), ramp_length=(5.4, 7.1)),
    sources={
        "engine": "ProjectSettings/Physics2DSettings.asset",
        "engine.dt": "ProjectSettings/TimeManager.asset: Fixed Timestep 0.02",
        "engine.linear_slop": "Physics2DSettings.asset: m_DefaultContactOffset 0.01, halved (Box2D's slop)",
        "engine.max_translation": "Physics2DSettings.asset: m_MaxTranslationSpeed 100 units/s × the step",
        "gravity": "Physics2DSettings.asset m_Gravity 9.81 × the prefabs' gravity scale 0.48",
        "recogniser": "physc's thresholds in level units, kept by the calibration on Phy-Q's levels "
        "(docs/angrybirds.md, 'What the motion words mean')",
        "recogniser.travel": "calibrated on Phy-Q's levels: the smallest block's width, SquareTiny 0.22 "
        "(docs/angrybirds.md, 'What the motion words mean')",
        "recogniser.hop_rise": "calibrated on Phy-Q's levels: a hop rises within the body's own size "
        "(docs/angrybirds.md, 'What the motion words mean')",
        "recogniser.roll_slip": "calibrated on Phy-Q's levels: the spin carries at least half the speed, more "
        "rolling than skidding (docs/angrybirds.md, 'What the motion words mean')",
        "recogniser.slide_spin": "calibrated on Phy-Q's levels: a slide rocks, a tumble turns (docs/angrybirds.md, "
        "'What the motion words mean')",
        "recogniser.bounce_walls": "Phy-Q's bouncing templates 2_4_1, 2_4_2 and 2_4_4: the bird bounces off walls "
        "and ceilings to reach a sheltered pig (docs/angrybirds.md, 'What the motion words mean')",
        "recogniser.round_slides": "the object grammar: a round body rolls, a block slides (docs/angrybirds.md, "
        "'What the motion words mean')",
        "incline.ramp": "Phy-Q's roll templates 2_1_3 (rotation 347.3: 12.7°), 2_1_6 and 2_1_9 (333.18: 26.8°)",
        "incline.ramp_length": "Phy-Q's roll templates: Platform scaleX 8.39 (2_1_6, 2_1_9) and 11.10 (2_1_3) × 0.64",
    },
)

ROLLING = PHYQ.derive(
    "rolling",
    "Phy-Q's game with its circle colliders enabled and angular drag 0.05: physc's reading of the paper's modified "
    "game",
    "physc's reading of the paper's unpublished 'adjusted physics parameters' (patches/rolling/); its words are the "
    "paper's: a roll or slide is motion in unbroken contact, with no least travel (docs/angrybirds.md, 'What the "
    "motion words mean')",
    # Made for rolling: round bodies that roll, spin kept; its words for a roll, a slide and a
    # bounce (a bounce off walls is not one there) are the paper's.
    concerns=("roll", "slide", "bounce"),
    bodies=attrs.evolve(PHYQ.bodies, circle_colliders=True, angular_drag=0.05),
    recogniser=attrs.evolve(
        PHYQ.recogniser, roll_slip=0.3, slide_spin=0.3, travel=0.0, hop_rise=0.0, round_slides=True, bounce_walls=False
    ),
)

WORLDS = (PHYQ, ROLLING)


def catalogue_model(colliders: str) -> ScienceBirdsWorld:
    """Phy-Q's game with the bodies of physc's earlier catalogue model ("round": Circle and
    CircleSmall as true circles; "phyq": regular polygons with the game's flat foot; masses
    density × area), for the benchmarks that compare them with the game's own ("game": PHYQ)."""
    if colliders == "game":
        return PHYQ
    model = PHYQ.derive(
        f"phyq-{colliders}",
        f"Phy-Q's game with physc's '{colliders}' catalogue bodies",
        "physc's catalogue model (benchmarks only)",
        bodies=attrs.evolve(PHYQ.bodies, colliders=colliders),
    )
    assert isinstance(model, ScienceBirdsWorld)  # a variant keeps its parent's class (attrs.evolve)
    return model
