"""A PHYRE-like task's level: its scene's bodies, its goal and tier, in PHYRE's terms.

It holds what PHYRE's Task holds (src/if/task.thrift): bodies with a shape, a position
and angle, a colour and whether they move; the two goal bodies and their relation
(TOUCHING); the action tier (BALL for one red ball, TWO_BALLS for two); and, once generated,
the intended solution (PHYRE's `solutions`). Positions are in the scene's pixels. The walls are not bodies here: every
scene has them (world.walls).
"""

from __future__ import annotations

import math
import random

import attrs

from physc.domains.base import DomainError
from physc_phyre import furniture
from physc_phyre.world import SCENE, extent, jar_thickness, size_of

# The shape and colour of each concrete object of the vocabulary (the floor is the bottom wall).
KINDS = {
    "greenBall": ("ball", "green", True),
    "greenBar": ("bar", "green", True),
    "greenStick": ("bar", "green", True),  # standing upright
    "blueBar": ("bar", "blue", True),
    "purpleBall": ("ball", "purple", False),
    "purpleJar": ("jar", "purple", False),
    "purpleWall": ("bar", "purple", False),  # upright, the scene's height, against its left or right edge
    "blackBall": ("ball", "black", False),
    "verticalBar": ("bar", "black", False),  # upright
    "grayStick": ("bar", "gray", True),  # standing upright
    "blueBall": ("ball", "blue", True),
    "blueJar": ("jar", "blue", True),
    "blueBallInJar": ("jar", "blue", True),  # the ball's colour; its jar is gray (HELD)
    "greenBallInJar": ("jar", "green", True),
    "upsideDownJar": ("jar", "gray", True),  # turned 180°
    "purpleBar": ("bar", "purple", False),
    "purpleFloor": ("bar", "purple", False),
    "purplePad": ("bar", "purple", False),  # a short bar lying on the floor
    "ball": ("ball", "gray", True),
    "bar": ("bar", "gray", True),
    "jar": ("jar", "gray", True),
    "sticks": ("standingsticks", "gray", True),
    "blackBar": ("bar", "black", False),
    "ramp": ("bar", "black", False),
}
# A ball lying in a jar, one object of the scenario: the ball bears the object's name, its jar
# is a gray dynamic body named after it (PHYRE's templates put the blue ball, or the green
# one, in a gray jar). The ball's radius is a share of the jar's height, so that it lies on
# the jar's base between its walls.
HELD = {"blueBallInJar": "gray", "greenBallInJar": "gray"}
# Of the jar's height at most: the widest ball that lies on the base of PHYRE's jar between its
# walls is 0.2625 of it at 45 px (concretize.HOLDING_HEIGHT's least), more in a taller jar.
HELD_RADIUS = 0.245
JAR_SUFFIX = "_jar"
# How far above where it rests an object of `dropped(a)` starts, in pixels (PHYRE's template
# 00001 drops its green ball from 0-40 px above the shelf; a lift under 10 px hardly falls).
DROP_HEIGHT = (10.0, 40.0)
GOAL_COLOURS = ("green",)
TARGET_COLOURS = ("blue", "purple")


SHAPES = ("ball", "bar", "jar", "standingsticks")
COLORS = ("red", "green", "blue", "purple", "gray", "black")


def _finite(instance, attribute, value) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ValueError(f"{attribute.name} must be a finite number, not {value!r}")


def _positive(instance, attribute, value) -> None:
    _finite(instance, attribute, value)
    if value <= 0:
        raise ValueError(f"{attribute.name} must be more than 0, not {value!r}")


def _radius(instance, attribute, value) -> None:
    _finite(instance, attribute, value)
    if not 2 <= value <= 32:
        raise ValueError(f"radius must be from 2 to 32 px (PHYRE's ball tier), not {value!r}")


@attrs.frozen
class BallAction:
    """PHYRE's ball tier: the red ball's centre and radius in pixels (its action, quantised
    as PHYRE does: integer position, whole radius 2 to 32)."""

    x: float = attrs.field(validator=_finite)
    y: float = attrs.field(validator=_finite)
    radius: float = attrs.field(validator=_radius)
    aimed_at: str = ""  # the candidate it came from (a point of interest of the first target)

    @property
    def balls(self) -> tuple[BallAction, ...]:
        return (self,)

    def unit(self) -> tuple[float, float, float]:
        """The action as PHYRE's agents give it, in [0, 1]³ (action_mappers.py's BallScaler:
        x = int(a·255), y likewise, r = round(2 + a·30)): for each whole pixel p the least
        double a whose a·255 is p, so that PHYRE's truncation gives p back and its bounds test
        (on a·255 before truncating) sees p itself. p/255 rounded, as before, came back a
        pixel low for 125 of the 256 values."""
        return (unit_of(self.x, SCENE - 1), unit_of(self.y, SCENE - 1), (self.radius - 2) / 30)


def unit_of(pixel: float, scale: int) -> float:
    """The least double a with int(a · scale) == pixel (a whole pixel, 0 ≤ pixel ≤ scale)."""
    a = pixel / scale
    while int(a * scale) < pixel:
        a = math.nextafter(a, math.inf)
    while a > 0 and int(math.nextafter(a, -math.inf) * scale) >= pixel:
        a = math.nextafter(a, -math.inf)
    return a


@attrs.frozen
class TwoBallAction:
    """PHYRE's two-ball tier: two red balls placed at once (a 6-D action, x1, y1, r1, x2, y2,
    r2); invalid when their centres are closer than r1 + r2 + 1 px (action_mappers.py's
    TwoBallsActionMapper)."""

    first: BallAction = attrs.field(validator=attrs.validators.instance_of(BallAction))
    second: BallAction = attrs.field(validator=attrs.validators.instance_of(BallAction))
    aimed_at: str = ""

    @property
    def balls(self) -> tuple[BallAction, BallAction]:
        return (self.first, self.second)

    def unit(self) -> tuple[float, ...]:
        return self.first.unit() + self.second.unit()


TIERS = {1: "BALL", 2: "TWO_BALLS"}  # PHYRE's SolutionTier, by the number of red balls


@attrs.frozen
class SceneBody:
    name: str
    shape: str = attrs.field(validator=attrs.validators.in_(SHAPES))  # ball | bar | jar | standingsticks
    x: float = attrs.field(validator=_finite)  # the body's origin, pixels (a jar's: the middle of its base)
    y: float = attrs.field(validator=_finite)
    angle: float = attrs.field(validator=_finite)  # radians, counter-clockwise
    size: float = attrs.field(validator=_positive)  # ball: radius; bar: length; jar: height; sticks: width
    color: str = attrs.field(validator=attrs.validators.in_(COLORS))
    dynamic: bool = attrs.field(validator=attrs.validators.instance_of(bool))


@attrs.frozen
class PhyreLevel:
    bodies: tuple[SceneBody, ...]
    goal: tuple[str, str]  # the green body and the one it must touch (PHYRE's bodyId1, bodyId2)
    players: tuple[str, ...] = (
        "redBall",
    )  # what the scenario calls the agent's balls, in the order the action places them
    floor: str = "floor"  # what the scenario calls the floor (the bottom wall)
    relation: str = "TOUCHING"
    solutions: tuple[BallAction | TwoBallAction, ...] = ()
    may_be_trivial: bool = (
        False  # `mayBeTrivial()`: PHYRE's acceptance does not exclude TRIVIAL (the template's search_params)
    )

    def __attrs_post_init__(self):
        names = {b.name for b in self.bodies}
        if len(self.goal) != 2 or not (set(self.goal) <= names or self.goal == ("", "")):
            raise ValueError(f"the goal must name two of the level's bodies, not {list(self.goal)!r}")
        if len(self.players) not in TIERS:
            raise ValueError(f"a task places one or two red balls, not {len(self.players)}")

    @property
    def tier(self) -> str:
        """PHYRE's action tier: BALL or TWO_BALLS, by how many red balls the action places."""
        return TIERS[len(self.players)]

    def body(self, name: str) -> SceneBody:
        for body in self.bodies:
            if body.name == name:
                return body
        raise KeyError(name)


def level_from_layout(layout, scenario) -> PhyreLevel:
    """The placed layout as a level: each object with the shape and colour of its concrete
    object, its origin where its outline box's middle was placed; the scenario's names for
    the agent's ball and the floor (None: the defaults)."""
    bodies = []
    for placed in layout.objects:
        if placed.concrete in furniture.KINDS:  # several bodies, or a bar at an angle of its own
            bodies += furniture.bodies(placed, SceneBody)
            continue
        if placed.concrete not in KINDS:  # the floor: the bottom wall every scene has
            continue
        shape, color, dynamic = KINDS[placed.concrete]
        size = size_of(shape, placed.width, placed.height)
        below = extent(shape, size)[2]
        angle = math.radians(placed.rotation)
        x = placed.x + below * math.sin(angle)
        y = placed.y - below * math.cos(angle)
        if placed.concrete in HELD:
            bodies += held(placed.name, x, y, angle, size, color, HELD[placed.concrete])
            continue
        bodies.append(
            SceneBody(placed.name, shape, round(x, 3), round(y, 3), round(angle, 6), round(size, 3), color, dynamic)
        )
    # The goal pair is the scenario's `touch(green, target)`; without a scenario (a placed
    # layout's picture), the first green body and the first blue or purple one.
    touch = (
        next((t.objects for t in scenario.interactions if t.name == "touch"), None) if scenario is not None else None
    )
    names = {b.name for b in bodies}
    if touch is not None and set(touch[:2]) <= names:
        green, target = touch[:2]
    else:
        green = next((b.name for b in bodies if b.color in GOAL_COLOURS), "")
        target = next((b.name for b in bodies if b.color in TARGET_COLOURS), "")
        if not (green and target):
            green = target = ""
    floor = next((o.name for o in layout.objects if o.concrete == "floor"), "floor")
    pairs = [t.objects[:2] for t in scenario.restrictions if t.name == "inside"] if scenario is not None else []
    if pairs:
        bodies = furniture.inside(bodies, pairs, held)
    lifted = {t.objects[0] for t in scenario.restrictions if t.name == "dropped"} if scenario is not None else set()
    if lifted:
        bodies = dropped(bodies, lifted, getattr(layout, "seed", 0))
    trivial = scenario is not None and any(t.name == "mayBeTrivial" for t in scenario.restrictions)
    return PhyreLevel(tuple(bodies), (green, target), players(scenario), floor, may_be_trivial=trivial)


def outline_box(body: SceneBody) -> tuple[float, float, float, float]:
    """(left, bottom, right, top) of a body's turned outline box, in pixels."""
    width, height, below = extent(body.shape, body.size)
    c, s = math.cos(body.angle), math.sin(body.angle)
    cx, cy = body.x - below * s, body.y + below * c
    corners = [
        (cx + dx * c - dy * s, cy + dx * s + dy * c)
        for dx in (-width / 2, width / 2)
        for dy in (-height / 2, height / 2)
    ]
    xs, ys = [p[0] for p in corners], [p[1] for p in corners]
    return min(xs), min(ys), max(xs), max(ys)


def dropped(bodies: list[SceneBody], names: set[str], seed: int) -> list[SceneBody]:
    """`bodies` with those of the objects in `names` (a `dropped(a)` of the scenario; a held
    ball with its jar) lifted by a height drawn from DROP_HEIGHT for the layout's `seed`, less
    where a body above leaves less room (or the scene's top): they fall as the scene starts,
    as PHYRE's templates drop theirs."""
    out = list(bodies)
    for name in sorted(names):
        parts = [k for k, b in enumerate(out) if b.name in (name, name + JAR_SUFFIX) and b.dynamic]
        if not parts:
            continue
        boxes = [outline_box(out[k]) for k in parts]
        left, right, top = min(b[0] for b in boxes), max(b[2] for b in boxes), max(b[3] for b in boxes)
        others = [outline_box(b) for j, b in enumerate(out) if j not in parts]
        room = min([SCENE] + [bottom for lo, bottom, hi, _ in others if lo < right and hi > left and bottom >= top])
        lift = min(random.Random(f"dropped/{seed}/{name}").uniform(*DROP_HEIGHT), room - top - 1.0)
        if lift >= 1.0:
            for k in parts:
                out[k] = attrs.evolve(out[k], y=round(out[k].y + lift, 3))
    return out


def held(name: str, x: float, y: float, angle: float, height: float, color: str, jar_color: str) -> list[SceneBody]:
    """A ball named `name` lying on the base of a jar `height` tall whose base's middle is at
    (x, y): the jar, then the ball."""
    radius = int(HELD_RADIUS * height - 0.5) + 0.5
    # From the base's middle line to the ball's centre, up to the level's 1e-3 px, so that the
    # rounded ball never sinks into the base.
    lift = math.ceil((jar_thickness(height) / 2 + radius) * 1000) / 1000
    x, y = round(x, 3), round(y, 3)
    bx, by = x - lift * math.sin(angle), y + lift * math.cos(angle)
    return [
        SceneBody(name + JAR_SUFFIX, "jar", x, y, round(angle, 6), round(height, 3), jar_color, True),
        SceneBody(name, "ball", round(bx, 3), round(by, 3), 0.0, radius, color, True),
    ]


def players(scenario) -> tuple[str, ...]:
    """The scenario's red balls, in the order they first act (one: PHYRE's ball tier; two:
    its two-ball tier); the default name without a scenario."""
    if scenario is None:
        return ("redBall",)
    red = {o.name for o in scenario.objects if o.term == "redBall"}
    if len(red) > max(TIERS):
        message = f"scenario '{scenario.name}' names {len(red)} red balls, but PHYRE's tiers place one or two"
        raise DomainError("E0703", message, help="keep one red ball (the ball tier) or two (the two-ball tier)")
    order = [name for term in scenario.interactions for name in term.objects if name in red]
    return tuple(dict.fromkeys(order + sorted(red))) or ("redBall",)
