"""The `.phys` vocabulary of the angrybirds domain (spec sections 3 and 4; the
paper's tables "Object grammar", "Interaction grammar", "Restriction grammar")."""

from physc.domains.vocabulary import (
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

SIDES = ("left", "right", "above", "below")
HIT_DIRECTIONS = SIDES + ("any",)

CONCRETE_OBJECTS = (
    ConcreteObject("redBird", description="the red bird (Science Birds BirdRed)"),
    ConcreteObject("pigSmall", description="a small pig (BasicSmall)"),
    ConcreteObject("pigMedium", description="a medium pig (BasicMedium)"),
    ConcreteObject("circleSmall", description="a small circular block (CircleSmall)"),
    ConcreteObject("circle", description="a circular block (Circle)"),
    ConcreteObject("squareHole", description="a square block with a hole (SquareHole)"),
    ConcreteObject("triangleHole", description="a triangular block with a hole (TriangleHole)"),
    ConcreteObject("flatPlatform", static=True, description="a horizontal platform (Platform)"),
    ConcreteObject("inclinedPlatform", static=True, description="a rotated platform (Platform)"),
)

OBJECT_TERMS = (
    ObjectTerm("bird", ("redBird",), noun="a bird"),
    ObjectTerm("pig", ("pigSmall", "pigMedium"), noun="a pig"),
    ObjectTerm("rollableBlock", ("circleSmall", "circle"), "rBlock", noun="a rollable object"),
    ObjectTerm(
        "fallableBlock",
        ("circleSmall", "circle", "squareHole", "triangleHole"),
        "fBlock",
        noun="a fallable object",
    ),
    ObjectTerm("slidableBlock", ("squareHole", "triangleHole"), "sBlock", noun="a slidable object"),
    ObjectTerm("horizontalSurface", ("flatPlatform",), "hSurface", noun="a horizontal surface"),
    ObjectTerm("inclinedSurface", ("inclinedPlatform",), "iSurface", noun="an inclined surface"),
    ObjectTerm("surface", ("flatPlatform", "inclinedPlatform"), noun="a surface"),
)


def _actor(fits=None):
    return Parameter("a", OBJECT, fits=fits, dynamic=True, acts=True)


TERMS = (
    TermSignature(
        "hit",
        INTERACTION,
        (_actor(), Parameter("b", OBJECT, moves=True), Parameter("d", DIRECTION, directions=HIT_DIRECTIONS)),
        "a collides with b from direction d of b",
    ),
    TermSignature(
        "roll",
        INTERACTION,
        (_actor("rollableBlock"), Parameter("b", OBJECT, fits="surface"), Parameter("d", DIRECTION, directions=("left", "right"))),
        "a rolls on b towards d",
    ),
    TermSignature(
        "fall",
        INTERACTION,
        (
            _actor(),
            Parameter("b", OBJECT),
            Parameter("d", DIRECTION, directions=("above", "left", "right"), default=("above",)),
        ),
        "a falls towards b (a starts far from b in direction d of b)",
    ),
    TermSignature(
        "slide",
        INTERACTION,
        (_actor("slidableBlock"), Parameter("b", OBJECT, fits="surface"), Parameter("d", DIRECTION, directions=("left", "right"))),
        "a slides on b towards d",
    ),
    TermSignature(
        "bounce",
        INTERACTION,
        (
            Parameter("a", OBJECT, dynamic=True, acts=True, redirects=True),
            Parameter("b", OBJECT, fits="surface"),
            Parameter("d", DIRECTION, directions=SIDES),
        ),
        "a bounces off b towards d",
    ),
    TermSignature(
        "destroy",
        INTERACTION,
        (_actor(), Parameter("b", OBJECT, fits="pig", destroys=True, completes=True)),
        "a destroys b in the collision",
        requires="hit",
    ),
    TermSignature(
        "cannotHit",
        RESTRICTION,
        (
            Parameter("a", OBJECT, dynamic=True),
            Parameter("b", OBJECT),
            Parameter("d", DIRECTION, directions=HIT_DIRECTIONS),
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

VOCABULARY = Vocabulary(
    object_terms=OBJECT_TERMS,
    concrete_objects=CONCRETE_OBJECTS,
    terms=TERMS,
    direction_aliases={"any": SIDES},
    player="bird",
    goal="pig",
    goal_unmet="is never destroyed",
    goal_rule="a task is solved when every pig is destroyed",
)
