"""The agent's action, PHYRE's ball tier: where the red ball is placed, and how big it is.

Candidate actions follow the paper's points of interest: the ball is dropped onto the
first target's upper corners, the middle of its top and the quarters between, in three sizes, from just above
and from higher up (a fall gathers speed); for a first hit, also on the target's shoulders (half a
radius beyond an upper corner) and from the top of the scene, so that the drop pushes it across. Like PHYRE, an action places the ball at whole
pixels with a whole radius from 2 to 32, inside the scene, occluding nothing (touching is
allowed). The random agent draws actions as PHYRE's evaluation does, uniformly in
[0, 1]³ scaled to the scene. Noise, for the robustness replays and the evaluation, moves
the ball by σ = 0.5 px: PHYRE's own test of a stable solution moves it by half a pixel.
"""

from __future__ import annotations

import math
import random

from physc.backends import Circle, parts

from physc_phyre.level import BallAction, PhyreLevel, SceneBody
from physc_phyre.world import SCENE, extent, outline

RADII = (8, 16, 26)  # pixels
GAPS = (4, 70)  # pixels between the ball and the target's top when dropped
FALL_GAPS = (40, 100)  # for a first interaction that is a fall: from higher up
NOISE = 0.5  # pixels, σ of the ball's position in a noisy replay
MIN_RADIUS, MAX_RADIUS = 2, 32


def outline_box(body: SceneBody) -> tuple[float, float, float, float]:
    """(left, bottom, right, top) of a body's turned outline box, in pixels."""
    width, height, below = extent(body.shape, body.size)
    c, s = math.cos(body.angle), math.sin(body.angle)
    cx, cy = body.x - below * s, body.y + below * c
    corners = [(cx + dx * c - dy * s, cy + dx * s + dy * c) for dx in (-width / 2, width / 2) for dy in (-height / 2, height / 2)]
    xs, ys = [p[0] for p in corners], [p[1] for p in corners]
    return min(xs), min(ys), max(xs), max(ys)


def candidate_actions(level: PhyreLevel, scenario) -> list[tuple[str, BallAction]]:
    """(label, action) for every valid drop onto the first target's points of interest."""
    first = scenario.interactions[0]
    names = {b.name: b for b in level.bodies}
    if len(first.objects) < 2 or first.objects[1] not in names:
        return []
    target = names[first.objects[1]]
    left, _, right, top = outline_box(target)
    width = right - left
    points = {"upper left": left, "left of top": left + width / 4, "top": left + width / 2, "right of top": right - width / 4, "upper right": right}
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
                    action = BallAction(int(x_), y, radius, f"{target.name} {at}, r {radius}, {y - top - radius:.0f} px above")
                    if (action.x, action.y, radius) not in seen and valid(level, action):
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


def valid(level: PhyreLevel, action: BallAction) -> bool:
    """Inside the scene, a radius PHYRE allows, and no body occluded (touching is fine)."""
    r = action.radius
    if not MIN_RADIUS <= r <= MAX_RADIUS or not (r <= action.x <= SCENE - r and r <= action.y <= SCENE - r):
        return False
    return not any(_overlaps(body, action.x, action.y, r) for body in level.bodies)


def from_unit(action) -> BallAction | None:
    """An action in [0, 1]³ as PHYRE's ball tier reads it (action_mappers.py: x = int(a·255),
    y likewise, r = round(2 + a·30); the inverse of BallAction.unit); None when PHYRE calls it
    invalid before placing it (a value outside [0, 1], or the ball not inside the scene,
    tested before quantising)."""
    try:
        a, b, c = (float(v) for v in action)
    except (TypeError, ValueError):
        return None
    if not all(0.0 <= v <= 1.0 for v in (a, b, c)):
        return None
    x, y, r = a * (SCENE - 1), b * (SCENE - 1), MIN_RADIUS + c * (MAX_RADIUS - MIN_RADIUS)
    if not (r <= x <= SCENE - r and r <= y <= SCENE - r):
        return None
    return BallAction(int(x), int(y), round(r))


def random_action(rng: random.Random) -> BallAction:
    """A draw of PHYRE's random agent: uniform in [0, 1]³ until the ball lies inside the
    scene (PHYRE's `sample(valid_only=True)`), read as PHYRE's ball tier reads it
    (`from_unit`). Whether it occludes a body is `valid`'s to say, as PHYRE counts such an
    action as an invalid attempt."""
    while True:
        placed = from_unit((rng.random(), rng.random(), rng.random()))
        if placed is not None:
            return placed


NEIGHBOUR_SHIFT = 0.5  # pixels: PHYRE's test of a stable solution moves the ball this far each way


def neighbours(action: BallAction) -> list[BallAction]:
    """The 8 balls PHYRE judges a solution's stability by: moved ±NEIGHBOUR_SHIFT px along x,
    y or both (action_simulator.py's `_yield_user_input_neighborhood`), the radius kept."""
    d = NEIGHBOUR_SHIFT
    return [BallAction(action.x + dx, action.y + dy, action.radius, action.aimed_at) for dx in (-d, 0.0, d) for dy in (-d, 0.0, d) if dx or dy]


def noisy(action: BallAction, rng: random.Random) -> BallAction:
    """The action with the ball moved by σ = NOISE pixels along each axis."""
    return BallAction(action.x + rng.gauss(0.0, NOISE), action.y + rng.gauss(0.0, NOISE), action.radius, action.aimed_at)


def _overlaps(body: SceneBody, x: float, y: float, radius: float) -> bool:
    """Whether a ball at (x, y) overlaps `body` by more than a touch (1e-5 px, PHYRE's)."""
    c, s = math.cos(body.angle), math.sin(body.angle)
    dx, dy = x - body.x, y - body.y
    lx, ly = dx * c + dy * s, -dx * s + dy * c  # the ball's centre in the body's frame
    for part in parts(outline(body.shape, body.size)):
        if isinstance(part, Circle):
            if math.hypot(lx, ly) + 1e-5 < part.radius + radius:
                return True
        elif _distance(part.points, lx, ly) + 1e-5 < radius:
            return True
    return False


def _distance(points, x: float, y: float) -> float:
    """The distance from (x, y) to a convex polygon (0 inside)."""
    inside, nearest = True, math.inf
    for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1]):
        ex, ey = x1 - x0, y1 - y0
        if ex * (y - y0) - ey * (x - x0) < 0:
            inside = False
        t = max(0.0, min(1.0, ((x - x0) * ex + (y - y0) * ey) / (ex * ex + ey * ey)))
        nearest = min(nearest, math.hypot(x - x0 - t * ex, y - y0 - t * ey))
    return 0.0 if inside else nearest
