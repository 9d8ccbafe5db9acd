"""PHYRE's world as physics: units, materials, walls and the shapes of its objects.

Facts from PHYRE's sources (physc's docs/phyre-facts.md): a 256 × 256 scene in pixels,
6 pixels to the metre, gravity 9.8 m/s², 60 steps a second, at most 1,000 steps; every
body has density 0.25 (dynamic ones), friction 0.5, restitution 0.2 and angular damping
0.01; four static walls 5 px thick lie outside the scene. The shapes are our own,
after PHYRE's: a ball; a bar 5.12 px thick; a jar, PHYRE's own three plates (shapes.py's
Jar), whose origin is the middle of its base; standing sticks, two sticks crossed at ±77.5°.

A level is in pixels, as PHYRE's scenes are; `body_spec` turns a body into metres.
"""

from __future__ import annotations

import math

from physc.backends import BodySpec, Circle, Compound, EngineSettings, Polygon

SCENE = 256  # pixels, width and height
PIXELS_PER_METRE = 6.0
GRAVITY = 9.8  # m/s²
FPS = 60
MAX_STEPS = 1000
# PHYRE's Box2D 2.3.2 step: 1/60 s, 15 velocity and 20 position iterations (src/simulator/
# task_utils.h); every other setting is Box2D's compiled-in default (docs/phyre-facts.md).
ENGINE = EngineSettings(dt=1 / FPS, velocity_iterations=15, position_iterations=20)
GOAL_STEPS = 180  # the goal must hold this many steps in a row (3 s)
DENSITY, FRICTION, RESTITUTION, ANGULAR_DAMPING = 0.25, 0.5, 0.2, 0.01
WALL = 5.0  # the walls' thickness, outside the scene
BAR_HEIGHT = SCENE / 50  # 5.12 px
STICKS_ANGLE = 77.5  # degrees from the horizontal of each standing stick
# PHYRE's Jar (src/python/phyre/creator/shapes.py): the opening is 1/1.2 of the height wide,
# the base 0.8 of the opening; the plates' thickness grows with the log of the height and is
# BAR_HEIGHT (SCENE / 50) at a height of 0.3 of the scene (JAR_THICKNESS_HEIGHT).
JAR_WIDTH_RATIO, JAR_BASE_RATIO = 1 / 1.2, 0.8
JAR_THICKNESS_HEIGHT = 0.3 * SCENE


def rectangle(cx: float, cy: float, width: float, height: float, angle: float = 0.0) -> Polygon:
    """A width × height rectangle centred on (cx, cy), turned by `angle` radians (counter-clockwise points)."""
    c, s = math.cos(angle), math.sin(angle)
    corners = ((-width / 2, -height / 2), (width / 2, -height / 2), (width / 2, height / 2), (-width / 2, height / 2))
    return Polygon(tuple((cx + x * c - y * s, cy + x * s + y * c) for x, y in corners))


def jar_thickness(height: float) -> float:
    """The thickness of a jar's plates, PHYRE's `Jar.thickness_from_height`: log(height) /
    log(0.3 · 256) · 256 / 50 (4.35 px at 40 px tall, 4.83 px at 60 px)."""
    return math.log(height) / math.log(JAR_THICKNESS_HEIGHT) * BAR_HEIGHT


def jar_parts(height: float) -> tuple[Polygon, ...]:
    """PHYRE's jar `height` tall (`Jar._build`, vertices as it lists them, counter-clockwise,
    about its origin, the middle of its base): a base plate `base_width` wide, and two walls
    slanting from the base's ends out to an opening `height / 1.2` wide, as thick as the base
    across their length and cut level at the top. The jar spans y from -t/2 to height - t/2
    and x from -width/2 to width/2 (t: `jar_thickness`)."""
    width = height * JAR_WIDTH_RATIO
    base_width = width * JAR_BASE_RATIO
    t = jar_thickness(height)
    base = Polygon(
        ((base_width / 2, t / 2), (-base_width / 2, t / 2), (-base_width / 2, -t / 2), (base_width / 2, -t / 2))
    )
    run = (width - base_width) / 2  # how far a wall leans out over its height
    hypotenuse = math.sqrt(height**2 + run**2)
    cos, sin = run / hypotenuse, height / hypotenuse
    x_delta, x_delta_top, y_delta = t * sin, t / sin, t * cos
    top = height - t / 2
    left = Polygon(
        (
            (-width / 2, top),
            (-base_width / 2, -t / 2),
            (-base_width / 2 + x_delta, y_delta - t / 2),
            (-width / 2 + x_delta_top, top),
        )
    )
    right = Polygon(
        (
            (width / 2, top),
            (width / 2 - x_delta_top, top),
            (base_width / 2 - x_delta, y_delta - t / 2),
            (base_width / 2, -t / 2),
        )
    )
    return (base, left, right)


def jar_height(diameter: float) -> float:
    """A jar's height from its `diameter` (PHYRE's `Jar.diameter_to_default_scale`, then
    `default_sizes`: the diameter is the diagonal from the base's end to the far top corner,
    1.25 × the height), with PHYRE's arithmetic."""
    width_to_height = ((1.0 - JAR_BASE_RATIO) / 2.0 + JAR_BASE_RATIO) * JAR_WIDTH_RATIO
    scale = math.sqrt(diameter**2 / (1 + width_to_height**2)) / SCENE
    return (1.0 - scale) * 0.0 + scale * SCENE


def sticks_parts(width: float) -> tuple[Polygon, ...]:
    """Standing sticks `width` wide: two sticks 2/3 of it long, crossed at the origin."""
    length, t = 2 * width / 3, 2 * BAR_HEIGHT / 3
    return tuple(rectangle(0.0, 0.0, length, t, math.radians(side * STICKS_ANGLE)) for side in (-1, 1))


def extent(shape: str, size: float) -> tuple[float, float, float]:
    """(width, height, how far the origin lies below the middle of the outline box) of a
    shape of `size` (ball: radius; bar: length; jar: height; sticks: width)."""
    if shape == "ball":
        return 2 * size, 2 * size, 0.0
    if shape == "bar":
        return size, BAR_HEIGHT, 0.0
    if shape == "jar":
        return size * JAR_WIDTH_RATIO, size, size / 2 - jar_thickness(size) / 2
    if shape == "standingsticks":
        a = math.radians(STICKS_ANGLE)
        length, t = 2 * size / 3, 2 * BAR_HEIGHT / 3
        return (
            2 * (length / 2 * math.cos(a) + t / 2 * math.sin(a)),
            2 * (length / 2 * math.sin(a) + t / 2 * math.cos(a)),
            0.0,
        )
    raise ValueError(f"no PHYRE shape '{shape}'")


def size_of(shape: str, width: float, height: float) -> float:
    """A shape's size from its outline box (the inverse of `extent`)."""
    if shape == "ball":
        return width / 2
    if shape == "bar":
        return width
    if shape == "jar":
        return height
    a = math.radians(STICKS_ANGLE)
    return 3 * (width / 2 - BAR_HEIGHT / 3 * math.sin(a)) / math.cos(a)


def outline(shape: str, size: float) -> Circle | Polygon | Compound:
    """The shape in pixels, about the body's origin."""
    if shape == "ball":
        return Circle(size)
    if shape == "bar":
        return rectangle(0.0, 0.0, size, BAR_HEIGHT)
    if shape == "jar":
        return Compound(jar_parts(size))
    if shape == "standingsticks":
        return Compound(sticks_parts(size))
    raise ValueError(f"no PHYRE shape '{shape}'")


def _metres(shape: Circle | Polygon | Compound) -> Circle | Polygon | Compound:
    """`shape` in metres (PHYRE's shapes are in pixels)."""
    if isinstance(shape, Compound):
        return Compound(tuple(_part_metres(part) for part in shape.parts))
    return _part_metres(shape)


def _part_metres(shape: Circle | Polygon) -> Circle | Polygon:
    """One convex part in metres."""
    m = 1 / PIXELS_PER_METRE
    if isinstance(shape, Circle):
        return Circle(shape.radius * m)
    return Polygon(tuple((x * m, y * m) for x, y in shape.points))


def body_spec(name: str, shape, x: float, y: float, angle: float, dynamic: bool) -> BodySpec:
    """A body of PHYRE's material, from a shape and a position in pixels (angle in radians)."""
    m = 1 / PIXELS_PER_METRE
    return BodySpec(
        name,
        _metres(shape),
        x * m,
        y * m,
        angle,
        static=not dynamic,
        density=DENSITY,
        friction=FRICTION,
        bounciness=RESTITUTION,
        angular_damping=ANGULAR_DAMPING if dynamic else 0.0,
    )


def walls(floor: str = "floor") -> list[BodySpec]:
    """The four static walls outside the scene, bottom first (as PHYRE adds them); the
    bottom one is the floor, named `floor`."""
    half = SCENE / 2
    places = {
        floor: (half, -WALL / 2, SCENE + 2 * WALL, WALL),
        "wall_left": (-WALL / 2, half, WALL, SCENE + 2 * WALL),
        "wall_top": (half, SCENE + WALL / 2, SCENE + 2 * WALL, WALL),
        "wall_right": (SCENE + WALL / 2, half, WALL, SCENE + 2 * WALL),
    }
    return [body_spec(name, rectangle(0.0, 0.0, w, h), x, y, 0.0, False) for name, (x, y, w, h) in places.items()]
