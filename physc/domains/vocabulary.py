"""The vocabulary a domain brings to the `.phys` language.

The grammar knows no domain words. A domain declares:

* its **object terms** (`rollableBlock`, abbreviation `rBlock`, …) and the
  **concrete objects** each may become (`circle`, `circleSmall`, …), some of
  them static (platforms);
* its **term signatures**: interaction and restriction terms with typed
  parameters and the causal role of each parameter (acts, is set in motion, is
  destroyed), so the static checks of the language stay domain-agnostic;
* its **directions**, with aliases such as `any`;
* which object term the player sets in motion (the shot) and which objects are
  goals, with how the goal is met (angrybirds: every pig must be destroyed; a PHYRE-like
  domain: the green object must touch the target): an interaction with a `completes`
  parameter meets it for that parameter's object.
"""

from __future__ import annotations

# A vocabulary's classes and its kinds are the front end's (physc.dsl.vocabularies: it reads them,
# and the domains import it); a plugin imports them from here, with the paper's terms.
from physc.dsl.vocabularies import (
    DIRECTION,
    INTERACTION,
    OBJECT,
    RESTRICTION,
    ConcreteObject,
    ObjectTerm,
    Parameter,
    TermSignature,
    Vocabulary,
)

__all__ = (
    "DIRECTION",
    "INTERACTION",
    "OBJECT",
    "RESTRICTION",
    "SIDES",
    "ConcreteObject",
    "ObjectTerm",
    "Parameter",
    "TermSignature",
    "Vocabulary",
    "paper_terms",
    "property_terms",
    "structure_terms",
)


SIDES = ("left", "right", "above", "below")


def paper_terms(
    rollable: str, slidable: str, surface: str
) -> tuple[dict[str, TermSignature], tuple[TermSignature, ...]]:
    """The paper's interaction terms (hit, roll, fall, slide, bounce, by name) and its
    restrictions (cannotHit, cannotFall), with the object terms a domain calls rollable,
    slidable and a surface. Recognition (physc.simulation.recognise) and the layout rules
    (physc.compiler.layout_rules) read these terms; a domain adds its goal term."""

    def actor(fits=None):
        return Parameter("a", OBJECT, fits=fits, dynamic=True, acts=True)

    hit_directions = SIDES + ("any",)
    along = ("left", "right")
    interactions = (
        TermSignature(
            "hit",
            INTERACTION,
            (actor(), Parameter("b", OBJECT, moves=True), Parameter("d", DIRECTION, directions=hit_directions)),
            "a collides with b from direction d of b",
        ),
        TermSignature(
            "roll",
            INTERACTION,
            (actor(rollable), Parameter("b", OBJECT, fits=surface), Parameter("d", DIRECTION, directions=along)),
            "a rolls on b towards d",
        ),
        TermSignature(
            "fall",
            INTERACTION,
            (
                actor(),
                Parameter("b", OBJECT),
                Parameter("d", DIRECTION, directions=("above", "left", "right"), default=("above",)),
            ),
            "a falls towards b (a starts far from b in direction d of b)",
        ),
        TermSignature(
            "slide",
            INTERACTION,
            (actor(slidable), Parameter("b", OBJECT, fits=surface), Parameter("d", DIRECTION, directions=along)),
            "a slides on b towards d",
        ),
        TermSignature(
            "bounce",
            INTERACTION,
            (
                Parameter("a", OBJECT, dynamic=True, acts=True, redirects=True),
                Parameter("b", OBJECT, fits=surface),
                Parameter("d", DIRECTION, directions=SIDES),
            ),
            "a bounces off b towards d (where a goes after the bounce)",
        ),
    )
    restrictions = (
        TermSignature(
            "cannotHit",
            RESTRICTION,
            (
                Parameter("a", OBJECT, dynamic=True),
                Parameter("b", OBJECT),
                Parameter("d", DIRECTION, directions=hit_directions),
            ),
            "during the solution, a must not collide with b from d",
            narrows="hit",
        ),
        TermSignature(
            "cannotFall",
            RESTRICTION,
            (Parameter("a", OBJECT, dynamic=True),),
            "during the solution, a must not fall",
            forbids="fall",
        ),
    )
    return {t.name: t for t in interactions}, restrictions


def structure_terms() -> tuple[TermSignature, TermSignature]:
    """Language version 2's restrictions on a level's make-up, which the layout rules read
    (physc.compiler.layout_rules) and the search checks (physc.search.contrasts):
    `contrast(a, b)` (a domain that has it writes `SimulatedDomain.contrasted`) and `on(a, b)`."""
    contrast = TermSignature(
        "contrast",
        RESTRICTION,
        (Parameter("a", OBJECT, dynamic=True), Parameter("b", OBJECT, dynamic=True)),
        "a rests as b does, but the action that sets b going, aimed at a instead, does not solve the task (version 2: "
        "the heavier circle, the block on the taller pillar)",
    )
    on = TermSignature(
        "on",
        RESTRICTION,
        (Parameter("a", OBJECT, dynamic=True), Parameter("b", OBJECT, dynamic=True)),
        "a rests on b in the level: a structure of several bodies, whose weak point is what the chain knocks out "
        "(version 2)",
        carries=True,
    )
    return contrast, on


def property_terms(player: str, goal: str) -> tuple[TermSignature, TermSignature, TermSignature]:
    """Language version 2's restrictions on what must fail (Phy-Q's defining properties), which
    the search checks in simulation against every action the player could send, not only the
    solution's (physc.search.properties): `nonGreedy(a, b)`, `blocks(a, b)` and `timed(a)`."""
    non_greedy = TermSignature(
        "nonGreedy",
        RESTRICTION,
        (Parameter("a", OBJECT, fits=goal), Parameter("b", OBJECT, fits=goal)),
        "the solution takes a before b; once b is taken first, no action the player could send next takes a "
        "(version 2: Phy-Q's non-greedy actions)",
    )
    blocks = TermSignature(
        "blocks",
        RESTRICTION,
        (Parameter("a", OBJECT, dynamic=True), Parameter("b", OBJECT, fits=goal)),
        "a bars the way to b: in the level as laid out, no action the player could send first takes b "
        "(version 2: Phy-Q's clearing paths)",
    )
    timed = TermSignature(
        "timed",
        RESTRICTION,
        (Parameter("a", OBJECT, fits=player),),
        "a's action is timed: taken while what the earlier actions set going still moves, it solves the task only "
        "within half a second of its time, and not once the level rests (version 2: Phy-Q's adequate timing)",
    )
    return non_greedy, blocks, timed
