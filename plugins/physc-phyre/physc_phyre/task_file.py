"""A level written as PHYRE's task structure (src/if/task.thrift), in JSON.

The fields and enum values are PHYRE's: `scene` with `width`, `height` and `bodies`
(the four walls first, as PHYRE's task creator adds them, then the objects), each body
with `position`, `bodyType` (1 static, 2 dynamic), `angle` (radians), `shapes` (convex
polygons with vertices relative to the position, counter-clockwise, or circles),
`color` (1 red, 2 green, 3 blue, 4 purple, 5 gray, 6 black), `shapeType` (1 ball, 2 bar,
3 jar, 4 standing sticks; 0 for walls) and `diameter`; the goal as `bodyId1`, `bodyId2`
(indices into the bodies) and `relationships` ([6]: TOUCHING); the scene's
`user_input_status` (0, as in PHYRE's own task files); `tier` ("BALL", or "TWO_BALLS");
`description` as PHYRE writes it; and `solutions`, PHYRE's UserInput: the red ball (or
balls) of the intended action. `physc` adds the bodies' names, so a reader can map a task back to
its scenario. Numbers are rounded to 1e-6 px: the same level gives the same bytes.
"""

from __future__ import annotations

import json
import math

from physc.backends import Circle, parts
from physc_phyre.level import PhyreLevel, SceneBody
from physc_phyre.world import SCENE, WALL, outline, rectangle

COLORS = {"red": 1, "green": 2, "blue": 3, "purple": 4, "gray": 5, "black": 6}
SHAPE_TYPES = {"ball": 1, "bar": 2, "jar": 3, "standingsticks": 4}
BODY_TYPE = {False: 1, True: 2}
TOUCHING = 6


def _number(value: float) -> float:
    return round(float(value), 6) + 0.0


def _vector(x: float, y: float) -> dict:
    return {"x": _number(x), "y": _number(y)}


def _shapes(shape) -> list[dict]:
    out = []
    for part in parts(shape):
        if isinstance(part, Circle):
            out.append({"circle": {"radius": _number(part.radius)}})
        else:
            out.append({"polygon": {"vertices": [_vector(x, y) for x, y in part.points]}})
    return out


def _diameter(body: SceneBody) -> float:
    """PHYRE's `diameter` of a body (shapes.py): a ball's 2r, a bar's diagonal, a jar's
    from its base to its top corner, standing sticks' their width."""
    if body.shape == "ball":
        return 2 * body.size
    if body.shape == "bar":
        return math.hypot(body.size, SCENE / 50)
    if body.shape == "jar":
        width = body.size / 1.2
        base = 0.8 * width
        return math.hypot((width - base) / 2 + base, body.size)
    return body.size


def _body(body: SceneBody) -> dict:
    return {
        "position": _vector(body.x, body.y),
        "bodyType": BODY_TYPE[body.dynamic],
        "angle": _number(body.angle),
        "shapes": _shapes(outline(body.shape, body.size)),
        "color": COLORS[body.color],
        "shapeType": SHAPE_TYPES[body.shape],
        "diameter": _number(_diameter(body)),
    }


def written(body: SceneBody) -> dict:
    """`body` as its task file gives it to PHYRE (numbers rounded to 1e-6 px): `position`,
    `angle` and `shapes`, what PHYRE's occlusion test reads (actions.py)."""
    return _body(body)


def _walls() -> list[dict]:
    half = SCENE / 2
    places = (
        (half, -WALL / 2, SCENE, WALL),
        (-WALL / 2, half, WALL, SCENE),
        (half, SCENE + WALL / 2, SCENE, WALL),
        (SCENE + WALL / 2, half, WALL, SCENE),
    )
    return [
        {
            "position": _vector(x, y),
            "bodyType": 1,
            "angle": 0.0,
            "shapes": _shapes(rectangle(0.0, 0.0, w, h)),
            "color": COLORS["black"],
            "shapeType": 0,
            "diameter": _number(math.hypot(w, h)),
        }
        for x, y, w, h in places
    ]


def describe(level: PhyreLevel) -> str:
    """PHYRE's description: "Make sure the green ball is touching the purple bar."."""
    green, target = (level.body(name) for name in level.goal)
    return f"Make sure the {green.color} {green.shape} is touching the {target.color} {target.shape}."


def task_json(level: PhyreLevel) -> str:
    names = ["wall_bottom", "wall_left", "wall_top", "wall_right"] + [b.name for b in level.bodies]
    data = {
        "scene": {
            "bodies": _walls() + [_body(b) for b in level.bodies],
            "width": SCENE,
            "height": SCENE,
            "user_input_status": 0,
        },
        "bodyId1": names.index(level.goal[0]),
        "bodyId2": names.index(level.goal[1]),
        "relationships": [TOUCHING],
        "description": describe(level),
        "solutions": [
            {"balls": [{"position": _vector(b.x, b.y), "radius": _number(b.radius)} for b in a.balls]}
            for a in level.solutions
        ],
        "tier": level.tier,
        "physc": {"names": names, "actions": [list(a.unit()) for a in level.solutions]},
    }
    return json.dumps(data, indent=2) + "\n"
