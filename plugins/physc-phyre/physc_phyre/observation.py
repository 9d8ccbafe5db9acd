"""What PHYRE's agents see of a task: the 256 × 256 picture of colour indices, and one
feature vector per object.

The picture is PHYRE's `scene_to_raster` (src/simulator/image_to_box2d.cpp, docs/phyre-
sources.md section 3.1): every pixel holds the colour index of the last body drawn over it
(0 white background, 1 red, 2 green, 3 blue, 4 purple, 5 gray, 6 black), the scene's bodies
in order and then the agent's ball; row 0 is the bottom of the scene (y points up) and
nothing is flipped. A convex polygon fills the pixels of each row from round(minY) to
round(maxY) whose span, read at the row's middle line, runs from round(left) to
round(right) (rounding half to even, as C's lrint); a circle fills the pixels whose centre
lies within it, row by row outwards from the column under its centre, as PHYRE's
`draw_circle` does. PHYRE computes in single precision and physc in double, so a pixel
whose centre lies on an edge to within float rounding may differ.

The features are PHYRE's `featurizeBody` (14 numbers): x / 256, y / 256, the angle wrapped to
[0, 2π) over 2π, the diameter / 256, a one-hot shape (ball, bar, jar, standing sticks) and a
one-hot colour (red, green, blue, purple, gray, black), for every body but the walls, the
agent's ball last; a jar's position is moved up along its axis to its centre of mass, as
PHYRE's `finalize_featurized_objects` does.
"""

from __future__ import annotations

import math

import numpy as np

from physc_phyre.world import SCENE, jar_height, jar_parts

SHAPE_TYPES = 4
COLORS = 6
FEATURES = 4 + SHAPE_TYPES + COLORS
RED, DYNAMIC = 1, 2


def _absolute(vertices, position, angle) -> list[tuple[float, float]]:
    c, s = math.cos(angle), math.sin(angle)
    px, py = position["x"], position["y"]
    return [(px + v["x"] * c - v["y"] * s, py + v["x"] * s + v["y"] * c) for v in vertices]


def _fill_polygon(image: np.ndarray, points, color: int) -> None:
    ys = [y for _, y in points]
    height, width = image.shape
    for row in range(max(0, int(np.rint(min(ys)))), min(height, int(np.rint(max(ys))))):
        line = row + 0.5
        xs = []
        for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=False):
            if abs(y1 - y0) < 1e-3 or not min(y0, y1) <= line <= max(y0, y1):
                continue
            xs.append(x0 + (line - y0) * (x1 - x0) / (y1 - y0))
        if len(xs) < 2:
            continue
        left, right = max(0, int(np.rint(min(xs)))), min(width, int(np.rint(max(xs))))
        if left < right:
            image[row, left:right] = color


def _fill_circle(image: np.ndarray, cx: float, cy: float, radius: float, color: int) -> None:
    height, width = image.shape
    cx, cy = cx - 0.5, cy - 0.5
    r2 = radius * radius

    def span(y: int, bounds: list[int]) -> None:
        residual = r2 - (y - cy) ** 2
        while (bounds[0] - cx) ** 2 <= residual:
            bounds[0] -= 1
        while (bounds[1] - cx) ** 2 <= residual:
            bounds[1] += 1
        left, right = max(0, bounds[0] + 1), min(width - 1, bounds[1] - 1)
        if left <= right and 0 <= y < height:
            image[y, left : right + 1] = color

    bounds = [int(cx), int(cx)]
    y = int(cy + radius + 1)
    while y >= cy:
        span(y, bounds)
        y -= 1
    bounds = [int(cx), int(cx)]
    y = int(cy - radius)
    while y < cy:
        span(y, bounds)
        y += 1


def raster(task: dict, *balls: tuple[float, float, float]) -> np.ndarray:
    """The task's scene (task_file.py's structure) as PHYRE's picture of colour indices
    (uint8, 256 × 256, row 0 at the bottom), with the agent's `balls` (x, y, radius in
    pixels) drawn last."""
    scene = task["scene"]
    image = np.zeros((scene["height"], scene["width"]), dtype=np.uint8)
    bodies = list(scene["bodies"])
    for ball in balls:
        bodies.append(
            {
                "position": {"x": ball[0], "y": ball[1]},
                "angle": 0.0,
                "color": RED,
                "shapes": [{"circle": {"radius": ball[2]}}],
            }
        )
    for body in bodies:
        color = body.get("color", 0)
        if not color:
            continue
        for shape in body["shapes"]:
            if "polygon" in shape:
                _fill_polygon(
                    image, _absolute(shape["polygon"]["vertices"], body["position"], body.get("angle", 0.0)), color
                )
            else:
                _fill_circle(image, body["position"]["x"], body["position"]["y"], shape["circle"]["radius"], color)
    return image


def jar_offset(diameter: float) -> float:
    """How far above its origin (the middle of its base) a jar of `diameter` has its centre of
    mass, in pixels, as PHYRE's featurizer finds it (simulation.py's `_get_jar_offset`:
    `Jar.center_of_mass(diameter=...)`): the area-weighted centroid of PHYRE's own plates for
    the height that diameter gives (world.jar_height, world.jar_parts)."""
    area = moment = 0.0
    for part in jar_parts(jar_height(diameter)):
        points = part.points
        a = sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=False)) / 2
        cy = sum(
            (y0 + y1) * (x0 * y1 - x1 * y0) for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=False)
        ) / (6 * a)
        area, moment = area + a, moment + a * cy
    return moment / area


def features(task: dict, *balls: tuple[float, float, float] | tuple[float, float, float, float]) -> np.ndarray:
    """PHYRE's feature vectors (float32, one row of 14 per body with a shape type; the
    agent's `balls` last: x, y, radius in pixels, and the angle where a ball has turned)."""
    rows = []
    bodies = [b for b in task["scene"]["bodies"] if b.get("shapeType", 0)]
    for ball in balls:
        bodies.append(
            {
                "position": {"x": ball[0], "y": ball[1]},
                "angle": ball[3] if len(ball) > 3 else 0.0,
                "diameter": 2 * ball[2],
                "shapeType": 1,
                "color": RED,
            }
        )
    for body in bodies:
        x, y, angle = body["position"]["x"], body["position"]["y"], body.get("angle", 0.0)
        if body["shapeType"] == 3:  # a jar: at its centre of mass
            offset = jar_offset(body["diameter"])
            x, y = x - offset * math.sin(angle), y + offset * math.cos(angle)
        row = [
            x / SCENE,
            y / SCENE,
            math.fmod(angle, 2 * math.pi) % (2 * math.pi) / (2 * math.pi),
            body["diameter"] / SCENE,
        ]
        row += [float(i == body["shapeType"] - 1) for i in range(SHAPE_TYPES)]
        row += [float(i == body["color"] - 1) for i in range(COLORS)]
        rows.append(row)
    return np.array(rows, dtype=np.float32).reshape(len(rows), FEATURES)
