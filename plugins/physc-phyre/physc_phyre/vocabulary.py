"""The `.phys` vocabulary of PHYRE-like tasks: PHYRE's objects in its colours, the
interactions of the paper (physc's `paper_terms`), and PHYRE's goal as a term,
`touch(green, target)`.

PHYRE colours its objects by role (docs/phyre-facts.md §4): the agent's ball red, the
goal object green, the object it must touch blue when dynamic and purple when static,
other dynamic objects gray and static ones black.
"""

from physc.domains.vocabulary import (
    INTERACTION,
    OBJECT,
    RESTRICTION,
    SIDES,
    ConcreteObject,
    ObjectTerm,
    Parameter,
    TermSignature,
    Vocabulary,
    paper_terms,
    structure_terms,
)

CONCRETE_OBJECTS = (
    ConcreteObject("redBall", description="the agent's red ball, placed by the action"),
    ConcreteObject("greenBall", description="the green goal ball"),
    ConcreteObject("greenBar", description="the green goal bar"),
    ConcreteObject("greenStick", description="the green goal bar, standing upright"),
    ConcreteObject("blueBall", description="a blue ball, the dynamic object the green one must touch"),
    ConcreteObject("blueBar", description="a blue bar, the dynamic object the green one must touch"),
    ConcreteObject(
        "purpleBall", static=True, description="a purple static ball, the static object the green one must touch"
    ),
    ConcreteObject(
        "purpleJar", static=True, description="a purple static jar, the static object the green one must touch"
    ),
    ConcreteObject(
        "purpleWall",
        static=True,
        description="a purple upright bar the scene's height against its left or right edge, the static object the "
        "green one must touch",
    ),
    ConcreteObject("blackBall", static=True, description="a black static ball (a peg, a fulcrum)"),
    ConcreteObject("verticalBar", static=True, description="a black static bar, upright (a post)"),
    ConcreteObject("grayStick", description="a gray bar, standing upright"),
    ConcreteObject("blueJar", description="a blue jar, the dynamic object the green one must touch"),
    ConcreteObject(
        "blueBallInJar",
        description="a blue ball lying in a gray jar (PHYRE's templates 00018, 00022, 00023), the dynamic object the "
        "green one must touch",
    ),
    ConcreteObject(
        "greenBallInJar", description="the green goal ball lying in a gray jar (PHYRE's templates 00005, 00010)"
    ),
    ConcreteObject("upsideDownJar", description="a gray jar turned upside down (PHYRE's templates 00006, 00018)"),
    ConcreteObject(
        "purplePad",
        static=True,
        description="a purple bar 0.1-0.2 of the scene long lying on the floor (PHYRE's templates 00007, 00019), the "
        "static object the green one must touch",
    ),
    ConcreteObject(
        "purpleBar", static=True, description="a purple static bar, the static object the green one must touch"
    ),
    ConcreteObject(
        "purpleFloor",
        static=True,
        description="a purple bar over the whole floor, the static object the green one must touch",
    ),
    ConcreteObject("ball", description="a gray ball"),
    ConcreteObject("bar", description="a gray bar"),
    ConcreteObject("jar", description="a gray jar"),
    ConcreteObject("sticks", description="gray standing sticks: two crossed sticks, nearly upright"),
    ConcreteObject("blackBar", static=True, description="a black static bar, level"),
    ConcreteObject("ramp", static=True, description="a black static bar, inclined"),
    ConcreteObject("floor", static=True, description="the scene's floor (its bottom wall)"),
    # Furniture (furniture.py): several bodies as one object, or a bar at an angle of its own.
    ConcreteObject(
        "seesaw", description="a gray bar balanced on a black static fulcrum ball under its middle (a see-saw)"
    ),
    ConcreteObject(
        "blueSeesaw",
        description="a blue bar balanced on a black static fulcrum ball (PHYRE's template 00004), the dynamic object "
        "the green one must touch",
    ),
    ConcreteObject(
        "teeter",
        description="a gray bar lying level on two black static fulcrum balls, under its middle and its right end: "
        "it tips when its left half is weighed down (PHYRE's template 00021)",
    ),
    ConcreteObject(
        "cradle",
        static=True,
        description="two short black static bars tilted 5° into a shallow V, which holds a ball (PHYRE's template "
        "00015)",
    ),
    ConcreteObject(
        "pegRow",
        static=True,
        description="small black static balls (pegs) in a level row, which a ball rests and rolls on (PHYRE's "
        "templates 00012, 00013)",
    ),
    ConcreteObject(
        "purpleRamp",
        static=True,
        description="a purple static bar, a slope rising towards where its toucher comes from (PHYRE's templates "
        "00010, 00011), the static object the green one must touch",
    ),
)

OBJECT_TERMS = (
    ObjectTerm("redBall", ("redBall",), "red", noun="the agent's ball"),
    ObjectTerm(
        "greenObject", ("greenBall", "greenBar", "greenStick", "greenBallInJar"), "green", noun="the green object"
    ),
    ObjectTerm(
        "targetObject",
        (
            "purpleFloor",
            "purpleBar",
            "purplePad",
            "purpleWall",
            "purpleBall",
            "purpleJar",
            "purpleRamp",
            "blueBall",
            "blueBar",
            "blueJar",
            "blueBallInJar",
            "blueSeesaw",
        ),
        "target",
        noun="the object the green one must touch",
    ),
    ObjectTerm(
        "rollableObject",
        ("ball", "greenBall", "greenBallInJar", "blueBall", "redBall"),
        "rObj",
        noun="a rollable object",
    ),
    ObjectTerm(
        "fallableObject",
        (
            "ball",
            "bar",
            "grayStick",
            "jar",
            "sticks",
            "greenBall",
            "greenBar",
            "greenStick",
            "greenBallInJar",
            "blueBall",
            "blueBar",
            "blueJar",
            "upsideDownJar",
            "seesaw",
            "teeter",
            "redBall",
        ),
        "fObj",
        noun="a fallable object",
    ),
    ObjectTerm("slidableObject", ("bar", "greenBar", "blueBar"), "sObj", noun="a slidable object"),
    ObjectTerm("obstacle", ("verticalBar", "blackBall", "blackBar"), "obstacle", noun="a static obstacle"),
    ObjectTerm("standingSticks", ("sticks",), "stick", noun="standing sticks"),
    ObjectTerm("container", ("jar", "blueJar", "upsideDownJar"), "jarObj", noun="a jar"),
    ObjectTerm("horizontalSurface", ("blackBar",), "hSurface", noun="a horizontal surface"),
    ObjectTerm("inclinedSurface", ("ramp",), "iSurface", noun="an inclined surface"),
    ObjectTerm("surface", ("blackBar", "ramp", "floor"), noun="a surface"),
    ObjectTerm("floor", ("floor",), noun="the floor"),
)


PAPER, RESTRICTIONS = paper_terms(rollable="rollableObject", slidable="slidableObject", surface="surface")
TERMS = (
    tuple(PAPER.values())
    + (
        TermSignature(
            "touch",
            INTERACTION,
            (Parameter("a", OBJECT, fits="greenObject", completes=True), Parameter("b", OBJECT, fits="targetObject")),
            "the green object a touches b, and keeps touching it for 3 s (PHYRE's goal)",
        ),
    )
    + RESTRICTIONS
    + (
        TermSignature(
            "dropped",
            RESTRICTION,
            (Parameter("a", OBJECT, fits="fallableObject"),),
            "a starts in the air above where it rests and falls there as the scene starts, before the action "
            "(PHYRE's templates drop their objects)",
        ),
        TermSignature(
            "mayBeTrivial",
            RESTRICTION,
            (),
            "PHYRE's acceptance keeps the task even when random actions solve it trivially often (its templates that "
            "do not exclude BALL:TRIVIAL)",
        ),
        TermSignature(
            "inside",
            RESTRICTION,
            (Parameter("a", OBJECT, fits="fallableObject"), Parameter("b", OBJECT, fits="container")),
            "a starts inside the jar b: on its base if b is upright (a ball in a jar), under it if b is upside down "
            "(PHYRE's cover jar)",
            carries=True,  # a moves once the jar does
        ),
        TermSignature(
            "cradled",
            RESTRICTION,
            (Parameter("a", OBJECT, fits="rollableObject"),),
            "a rests in a cradle, two short bars tilted into a shallow V, which a sideways strike knocks it out of "
            "(PHYRE's template 00015)",
        ),
        TermSignature(
            "pegged",
            RESTRICTION,
            (Parameter("a", OBJECT, fits="rollableObject"),),
            "a rests on a row of pegs, small black static balls, which it rolls along or is knocked off (PHYRE's "
            "templates 00012, 00013)",
        ),
        structure_terms()[1],  # on(a, b): a rests on b (version 2)
    )
)

VOCABULARY = Vocabulary(
    object_terms=OBJECT_TERMS,
    concrete_objects=CONCRETE_OBJECTS,
    terms=TERMS,
    direction_aliases={"any": SIDES},
    player="redBall",
    players=2,  # PHYRE's actions place one ball or two (its BALL and TWO_BALLS tiers)
    goal="greenObject",
    goal_unmet="never touches its target",
    goal_rule="a task is solved when the green object touches the target for 3 s",
)
