"""The `.phys` vocabulary of the angrybirds domain (spec sections 3 and 4; the
paper's tables "Object grammar", "Interaction grammar", "Restriction grammar")."""

from physc.domains.vocabulary import (
    INTERACTION,
    OBJECT,
    SIDES,
    ConcreteObject,
    ObjectTerm,
    Parameter,
    TermSignature,
    Vocabulary,
    paper_terms,
    property_terms,
    structure_terms,
)

MATERIALS = ("wood", "stone", "ice")  # a block's (catalogue.MATERIALS)

CONCRETE_OBJECTS = (
    ConcreteObject("redBird", description="the red bird (Science Birds BirdRed)"),
    # Version 2: the game's other birds and their powers, set off by a tap (`tap(bird)`).
    ConcreteObject(
        "blueBird", description="the blue bird (BirdBlue): a tap splits it into three, fanned +15°, +5° and −5°"
    ),
    ConcreteObject("yellowBird", description="the yellow bird (BirdYellow): a tap speeds it up along its flight"),
    ConcreteObject(
        "blackBird", description="the black bird (BirdBlack): it blasts at a tap, or 0.6 s after it strikes"
    ),
    ConcreteObject(
        "whiteBird", description="the white bird (BirdWhite): a tap drops an egg that blasts where it lands"
    ),
    ConcreteObject("pigSmall", description="a small pig (BasicSmall)"),
    ConcreteObject("pigMedium", description="a medium pig (BasicMedium)"),
    ConcreteObject("circleSmall", description="a small circular block (CircleSmall)", materials=MATERIALS),
    ConcreteObject("circle", description="a circular block (Circle)", materials=MATERIALS),
    ConcreteObject("squareHole", description="a square block with a hole (SquareHole)", materials=MATERIALS),
    ConcreteObject("triangleHole", description="a triangular block with a hole (TriangleHole)", materials=MATERIALS),
    # Version 2: the game's other bodies, which a declaration may pin (`fBlock: fallableBlock = rectFat`).
    ConcreteObject("pigBig", description="a big pig (BasicBig)"),
    ConcreteObject("rectFat", description="a fat rectangle, 0.76 × 0.38 (RectFat)", materials=MATERIALS),
    ConcreteObject("rectBig", description="a long thin rectangle, 1.89 × 0.18 (RectBig)", materials=MATERIALS),
    ConcreteObject("rectMedium", description="a thin rectangle, 1.55 × 0.18 (RectMedium)", materials=MATERIALS),
    ConcreteObject("rectSmall", description="a short thin rectangle, 0.76 × 0.18 (RectSmall)", materials=MATERIALS),
    ConcreteObject("rectTiny", description="a tiny rectangle, 0.38 × 0.18 (RectTiny)", materials=MATERIALS),
    ConcreteObject("squareSmall", description="a small square, 0.38 (SquareSmall)", materials=MATERIALS),
    ConcreteObject("squareTiny", description="a tiny square, 0.18 (SquareTiny)", materials=MATERIALS),
    ConcreteObject("triangle", description="a right triangle, 0.75 (Triangle)", materials=MATERIALS),
    ConcreteObject(
        "tnt",
        description="a TNT box (TNT): any blow destroys it, and its blast damages and pushes what lies within 2.5 "
        "units",
    ),
    ConcreteObject("flatPlatform", static=True, description="a horizontal platform (Platform)"),
    ConcreteObject("inclinedPlatform", static=True, description="a rotated platform (Platform)"),
    ConcreteObject(
        "ground",
        static=True,
        description="the level's ground, under everything (every level has it; it is not written)",
    ),
)

SQUARED = (
    "rectFat",
    "rectBig",
    "rectMedium",
    "rectSmall",
    "rectTiny",
    "squareSmall",
    "squareTiny",
)  # flat-bottomed: they fall and slide

OBJECT_TERMS = (
    ObjectTerm("bird", ("redBird",), noun="a bird", pinnable=("blueBird", "yellowBird", "blackBird", "whiteBird")),
    ObjectTerm("pig", ("pigSmall", "pigMedium"), noun="a pig", pinnable=("pigBig",)),
    ObjectTerm("rollableBlock", ("circleSmall", "circle"), "rBlock", noun="a rollable object"),
    ObjectTerm(
        "fallableBlock",
        ("circleSmall", "circle", "squareHole", "triangleHole"),
        "fBlock",
        noun="a fallable object",
        pinnable=SQUARED + ("triangle",),
    ),
    ObjectTerm("slidableBlock", ("squareHole", "triangleHole"), "sBlock", noun="a slidable object", pinnable=SQUARED),
    ObjectTerm("horizontalSurface", ("flatPlatform",), "hSurface", noun="a horizontal surface"),
    ObjectTerm("inclinedSurface", ("inclinedPlatform",), "iSurface", noun="an inclined surface"),
    ObjectTerm("surface", ("flatPlatform", "inclinedPlatform"), noun="a surface"),
    ObjectTerm("tnt", ("tnt",), noun="a TNT box"),  # version 2
    # The level's own ground, as traces name it: a scenario may name it too (`bounce(bird, ground, right)`).
    ObjectTerm("ground", ("ground",), noun="the ground", fits_as=("horizontalSurface", "surface")),
)


PAPER, RESTRICTIONS = paper_terms(rollable="rollableBlock", slidable="slidableBlock", surface="surface")
CONTRAST, ON = structure_terms()
NON_GREEDY, BLOCKS, TIMED = property_terms(player="bird", goal="pig")
TERMS = (
    (
        PAPER["hit"],
        PAPER["roll"],
        PAPER["fall"],
        PAPER["slide"],
        PAPER["bounce"],
        TermSignature(
            "explode",
            INTERACTION,
            (Parameter("a", OBJECT, fits="tnt", acts=True),),
            "a TNT box a is destroyed by a blow, and its blast damages and pushes what lies near it (version 2)",
        ),
        TermSignature(
            "tap",
            INTERACTION,
            (Parameter("a", OBJECT, fits="bird", acts=True),),
            "the player taps bird a in flight, setting off its power: a blue bird splits in three, a yellow one "
            "speeds up, "
            "a black one blasts, a white one drops an egg (version 2)",
        ),
        TermSignature(
            "destroy",
            INTERACTION,
            (
                Parameter("a", OBJECT, dynamic=True, acts=True),
                Parameter("b", OBJECT, fits="pig", destroys=True, completes=True),
            ),
            "a destroys b in the collision (or, after explode(a), in a's blast)",
            requires="hit",
            enabled_by="explode",
        ),
    )
    + RESTRICTIONS
    + (CONTRAST, ON, NON_GREEDY, BLOCKS, TIMED)
)

VOCABULARY = Vocabulary(
    object_terms=OBJECT_TERMS,
    concrete_objects=CONCRETE_OBJECTS,
    terms=TERMS,
    direction_aliases={"any": SIDES},
    player="bird",
    players=None,  # version 2: one shot per bird, in the order the sequence first names them (docs/language.md)
    goal="pig",
    goal_unmet="is never destroyed",
    goal_rule="a task is solved when every pig is destroyed",
)
