"""The agent's action, PHYRE's ball tier: where the red ball is placed, and how big it is (the
two-ball tier places two at once, under PHYRE's rule that they lie r1 + r2 + 1 px apart).

Candidate actions follow the paper's points of interest: the ball is dropped onto the
first target's upper corners, the middle of its top and the quarters between, in three sizes, from just above
and from higher up (a fall gathers speed); for a first hit, also on the target's shoulders (half a
radius beyond an upper corner) and from the top of the scene, so that the drop pushes it across. Like PHYRE, an
action places the ball at whole
pixels with a whole radius from 2 to 32, inside the scene, occluding nothing (touching is
allowed). The random agent draws actions as PHYRE's evaluation does, uniformly in
[0, 1]³ (two balls: [0, 1]⁶) scaled to the scene. Noise, for the robustness replays and the evaluation, moves
the ball by σ = 0.5 px: PHYRE's own test of a stable solution moves it by half a pixel.
"""

from __future__ import annotations

import functools
import math
import random

import numpy as np

from physc_phyre.level import BallAction, PhyreLevel, SceneBody, TwoBallAction, outline_box
from physc_phyre.task_file import written
from physc_phyre.world import SCENE

RADII = (8, 16, 26)  # pixels
GAPS = (4, 70)  # pixels between the ball and the target's top when dropped
FALL_GAPS = (40, 100)  # for a first interaction that is a fall: from higher up
NOISE = 0.5  # pixels, σ of the ball's position in a noisy replay
MIN_RADIUS, MAX_RADIUS = 2, 32


def drops(level: PhyreLevel, first) -> list[tuple[str, BallAction]]:
    """(label, ball) for every valid drop onto the points of interest of the target of
    `first`, a red ball's first interaction."""
    names = {b.name: b for b in level.bodies}
    if len(first.objects) < 2 or first.objects[1] not in names:
        return []
    target = names[first.objects[1]]
    left, _, right, top = outline_box(target)
    width = right - left
    points = {
        "upper left": left,
        "left of top": left + width / 4,
        "top": left + width / 2,
        "right of top": right - width / 4,
        "upper right": right,
    }
    gaps = FALL_GAPS if first.name == "fall" else GAPS
    sides = _sides(first)
    out, seen = [], set()
    for point, x in points.items():
        for radius in RADII:
            shoulders = _shoulders(point, x, radius, sides)
            for gap in gaps + ((SCENE,) if shoulders else ()):  # a sideways push: also from the top, the fastest fall
                for at, x_ in shoulders or ((point, x),):
                    # As high as asked, or as high as the scene allows (a target near the top).
                    y = min(int(top + radius + gap), SCENE - radius)
                    action = BallAction(
                        int(x_), y, radius, f"{target.name} {at}, r {radius}, {y - top - radius:.0f} px above"
                    )
                    if (action.x, action.y, radius) not in seen and placeable(level, action):
                        seen.add((action.x, action.y, radius))
                        out.append((action.aimed_at, action))
    return out


def _sides(first) -> list[str]:
    """The target's sides a first hit may strike from a drop: those it names, or both for a
    hit from above (a ball dropped on the target's shoulder hits it from above, pushing it
    across)."""
    if first.name != "hit":
        return []
    named = [d for d in first.directions if d in ("left", "right")]
    return named or (["left", "right"] if "above" in first.directions else [])


SHOULDER = (0.0, 0.5)  # of the ball's radius, outwards from the target's upper corner


def _shoulders(point: str, x: float, radius: int, sides: list[str]) -> list[tuple[str, float]]:
    """For a hit on the target's left or right side: drops at that upper corner and up to half
    the ball's radius beyond it, so the ball strikes the target's shoulder and pushes it across
    (the other way) rather than landing on its top."""
    corner = {"left": "upper left", "right": "upper right"}
    out = []
    for side in sides:
        if point == corner[side]:
            outward = -1 if side == "left" else 1
            out += [(point if f == 0 else f"{point}, {f:g} r out", x + outward * f * radius) for f in SHOULDER]
    return out


def valid(level: PhyreLevel, action: BallAction | TwoBallAction) -> bool:
    """An action of the level's tier, or of the ball tier (PHYRE judges a two-ball task by
    one ball too); each ball inside the scene, of a radius PHYRE allows, occluding no body
    (touching is fine). Whether two balls lie apart is PHYRE's mapper's test, made before
    it rounds them to pixels (`from_unit`), not again here: after rounding, a pair it
    placed may lie closer, and PHYRE simulates it."""
    balls = getattr(action, "balls", ())
    if not 1 <= len(balls) <= len(level.players):
        return False
    return all(placeable(level, ball) for ball in balls)


def placeable(level: PhyreLevel, ball: BallAction) -> bool:
    """One ball inside the scene, of a radius PHYRE allows, occluding no body of `level`."""
    r = ball.radius
    if not MIN_RADIUS <= r <= MAX_RADIUS or not (r <= ball.x <= SCENE - r and r <= ball.y <= SCENE - r):
        return False
    return not any(_overlaps(body, ball.x, ball.y, r) for body in level.bodies)


def apart(a, b) -> bool:
    """PHYRE's two-ball rule: the centres at least r1 + r2 + 1 px apart."""
    return math.hypot(a.x - b.x, a.y - b.y) >= a.radius + b.radius + 1


def from_unit(action) -> BallAction | TwoBallAction | None:
    """An action in [0, 1]³ (ball tier) or [0, 1]⁶ (two-ball tier) as PHYRE reads it
    (action_mappers.py: x = int(a·255), y likewise, r = round(2 + a·30); the inverse of
    `unit`); None when PHYRE calls it invalid before placing it (a value outside [0, 1], a
    ball not inside the scene, or two balls too close, tested before quantising)."""
    try:
        values = [float(v) for v in action]
    except (TypeError, ValueError):
        return None
    if len(values) not in (3, 6) or not all(0.0 <= v <= 1.0 for v in values):
        return None
    balls = []  # as PHYRE scales them, before quantising
    for a, b, c in zip(values[0::3], values[1::3], values[2::3], strict=False):
        x, y, r = a * (SCENE - 1), b * (SCENE - 1), MIN_RADIUS + c * (MAX_RADIUS - MIN_RADIUS)
        if not (r <= x <= SCENE - r and r <= y <= SCENE - r):
            return None
        balls.append(BallAction(x, y, r))
    if len(balls) == 2 and not apart(*balls):
        return None
    placed = [BallAction(int(ball.x), int(ball.y), round(ball.radius)) for ball in balls]
    return placed[0] if len(placed) == 1 else TwoBallAction(placed[0], placed[1])


def random_action(level: PhyreLevel, rng: random.Random) -> BallAction | TwoBallAction:
    """A draw of PHYRE's random agent in the level's tier: uniform in [0, 1]³ (or ⁶) until
    PHYRE's mapper accepts it (its `sample(valid_only=True)`), read as `from_unit` reads it.
    Whether it occludes a body is `valid`'s to say, as PHYRE counts such an action as an
    invalid attempt."""
    while True:
        placed = from_unit([rng.random() for _ in range(3 * len(level.players))])
        if placed is not None:
            return placed


NEIGHBOUR_SHIFT = 0.5  # pixels: PHYRE's test of a stable solution moves the ball this far each way


def neighbours(action: BallAction | TwoBallAction) -> list:
    """The 8 actions PHYRE judges a solution's stability by: every ball moved together
    ±NEIGHBOUR_SHIFT px along x, y or both (action_simulator.py's
    `_yield_user_input_neighborhood`), the radii kept."""
    d = NEIGHBOUR_SHIFT
    return [
        moved(action, lambda ball, dx=dx, dy=dy: (dx, dy)) for dx in (-d, 0.0, d) for dy in (-d, 0.0, d) if dx or dy
    ]


def noisy(action: BallAction | TwoBallAction, rng: random.Random):
    """The action with each ball moved by σ = NOISE pixels along each axis."""
    return moved(action, lambda ball: (rng.gauss(0.0, NOISE), rng.gauss(0.0, NOISE)))


def moved(action, shift):
    """`action` with each ball moved by `shift(ball)` = (dx, dy) pixels."""
    balls = []
    for ball in action.balls:
        dx, dy = shift(ball)
        balls.append(BallAction(ball.x + dx, ball.y + dy, ball.radius, ball.aimed_at))
    return balls[0] if len(balls) == 1 else TwoBallAction(balls[0], balls[1], action.aimed_at)


# PHYRE's occlusion test, the one `simulate_action` makes before it simulates (an occluding ball:
# INVALID_INPUT): src/simulator/image_to_box2d.cpp's doesBallOccludeBody (lines 210-228) with
# src/simulator/geometry.h's helpers (lines 19-163), in the C++ float arithmetic PHYRE computes
# it in; docs/phyre-facts.md, "Invalid actions".
INSIDENESS_EPS = np.float32(1e-5)  # px, kInsidenessEps (geometry.h:20): a ball may sink this far into a body, a touch
ZERO_LENGTH_EDGE_EPS = np.float32(
    1e-4
)  # px², kZeroLengthEdgeEps (geometry.h:19): a polygon's edge this short (squared) is a point
EXACT_WITHIN = (
    1e-3  # px: a ball this near a touch is judged in PHYRE's float arithmetic (its rounding is under 1e-4 px here)
)
F32 = np.float32
_EPS = float(INSIDENESS_EPS)  # the same, for the test in doubles


def _overlaps(body: SceneBody, x: float, y: float, radius: float) -> bool:
    """Whether a ball at (x, y) occludes `body` by PHYRE's rule (doesBallOccludeBody), against
    the body as its task file gives it to PHYRE (numbers rounded to 1e-6 px): a circle when the
    centres lie closer than the radii's sum less INSIDENESS_EPS; a convex polygon when the
    ball's centre is strictly inside it (its vertices counter-clockwise) or nearer its edges
    than the radius less INSIDENESS_EPS. Touching is fine. The test runs in doubles; a ball
    within EXACT_WITHIN of a touch is judged again in PHYRE's float32 arithmetic, which
    settles it."""
    return _occludes(_as_phyre_reads(body), x, y, radius)


def _occludes(body: tuple, x: float, y: float, radius: float) -> bool:
    """`_overlaps` on a body as PHYRE reads it: (x, y, angle, shapes), `_as_phyre_reads`."""
    px, py, angle, shapes = body
    dx, dy = x - px, y - py
    c, s = math.cos(angle), math.sin(angle)
    lx, ly = dx * c + dy * s, -dx * s + dy * c  # the ball's centre in the body's frame
    for shape in shapes:
        if isinstance(shape, float):  # a circle about the body's position (PHYRE ignores any offset)
            margin = math.hypot(dx, dy) + _EPS - (radius + shape)
            exact = _phyre_circle
        else:
            if _strictly_inside(shape, lx, ly):
                return True
            margin = _edge_distance(shape, lx, ly) + _EPS - radius
            exact = _phyre_polygon
        if margin < -EXACT_WITHIN or (margin <= EXACT_WITHIN and exact(shape, px, py, angle, x, y, radius)):
            return True
    return False


@functools.lru_cache(maxsize=4096)
def _as_phyre_reads(body: SceneBody) -> tuple:
    """(x, y, angle, shapes) of `body` as its task file writes them (task_file.written): each
    shape a circle's radius (a float) or a polygon's vertices about the position."""
    return _reads(written(body))


def _reads(data: dict) -> tuple:
    """(x, y, angle, shapes) of a body of a task file (task_file.py's structure)."""
    shapes = tuple(
        float(shape["circle"]["radius"])
        if "circle" in shape
        else tuple((v["x"], v["y"]) for v in shape["polygon"]["vertices"])
        for shape in data["shapes"]
    )
    return data["position"]["x"], data["position"]["y"], data["angle"], shapes


def _strictly_inside(points, x: float, y: float) -> bool:
    """geometry.h's isInsidePolygon (lines 131-142): (x, y) left of every edge, none on it
    (a polygon listed clockwise has no inside)."""
    for (x0, y0), (x1, y1) in zip(points[-1:] + points[:-1], points, strict=False):
        if (x1 - x0) * (y - y0) - (y1 - y0) * (x - x0) <= 0:
            return False
    return True


def _edge_distance(points, x: float, y: float) -> float:
    """The distance from (x, y) to a polygon's nearest edge."""
    nearest = math.inf
    for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=False):
        ex, ey = x1 - x0, y1 - y0
        t = max(0.0, min(1.0, ((x - x0) * ex + (y - y0) * ey) / (ex * ex + ey * ey)))
        nearest = min(nearest, math.hypot(x - x0 - t * ex, y - y0 - t * ey))
    return nearest


def _phyre_circle(circle_radius: float, px: float, py: float, angle: float, x: float, y: float, radius: float) -> bool:
    """geometry.h's isPointInsideCircle(ball, body position, r + circle radius) (lines 158-163),
    in its float arithmetic."""
    return bool(F32(np.sqrt(_square_distance(x, y, px, py))) + INSIDENESS_EPS < F32(radius + circle_radius))


def _phyre_polygon(points, px: float, py: float, angle: float, x: float, y: float, radius: float) -> bool:
    """geometry.h's doesBallOccludePolygon (lines 144-156) on the ball's centre in the body's
    frame (reverseTranslatePoint, lines 57-62: the angle a float, its cosine and sine floats,
    the rest doubles), in PHYRE's float arithmetic."""
    a = -float(F32(angle))
    c, s = float(F32(math.cos(a))), float(F32(math.sin(a)))
    tx, ty = x - px, y - py
    qx, qy = tx * c - ty * s, tx * s + ty * c
    if all(
        F32((x1 - x0) * (qy - y0) - (y1 - y0) * (qx - x0)) > 0
        for (x0, y0), (x1, y1) in zip(points[-1:] + points[:-1], points, strict=False)
    ):
        return True
    best = min(
        _square_distance_to_segment(p0, p1, qx, qy) for p0, p1 in zip(points[-1:] + points[:-1], points, strict=False)
    )
    return bool(F32(np.sqrt(best)) + INSIDENESS_EPS < F32(radius))


def _square_distance(x0: float, y0: float, x1: float, y1: float):
    """geometry.h's squareDistance (lines 73-78): the differences as floats, squared and summed in floats."""
    dx, dy = F32(x0 - x1), F32(y0 - y1)
    return dx * dx + dy * dy


def _square_distance_to_segment(left, right, x: float, y: float):
    """geometry.h's squareDistanceToSegment (lines 101-116), in its float arithmetic."""
    (lx, ly), (rx, ry) = left, right
    ex, ey = rx - lx, ry - ly
    projection = F32(ex * (x - lx) + ey * (y - ly))
    length2 = _square_distance(lx, ly, rx, ry)
    if projection < 0 or length2 < ZERO_LENGTH_EDGE_EPS:
        return _square_distance(lx, ly, x, y)
    if projection > length2:
        return _square_distance(rx, ry, x, y)
    num = F32(ey * x - ex * y + rx * ly - ry * lx)
    return num * num / length2
