"""The 2-D geometry a 3-D engine needs from a planar body: area, moment about z, whether a
polygon is a centred axis-aligned rectangle (a box shape is exact and cheaper than a hull)
or a turned one (a compound's part), and a polygon grown by a skin. A compound's area,
centroid and moment are its parts', its mass spread over them by area."""

from __future__ import annotations

import math

import attrs

from physc.backends import Circle, Compound, Polygon


def area(shape: Circle | Polygon | Compound, skin: float = 0.0) -> float:
    """The shape's area; a polygon's with its outline grown by `skin` (rounded corners), as
    pymunk counts a polygon's area, and so its mass, with its radius."""
    if isinstance(shape, Compound):
        return sum(area(part, skin) for part in shape.parts)
    if isinstance(shape, Circle):
        return math.pi * shape.radius**2
    points = shape.points
    pairs = list(zip(points, points[1:] + points[:1], strict=False))
    inner = abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1) in pairs)) / 2
    perimeter = sum(math.hypot(x1 - x0, y1 - y0) for (x0, y0), (x1, y1) in pairs)
    return inner + perimeter * skin + math.pi * skin * skin


def centroid(shape: Circle | Polygon | Compound, skin: float = 0.0) -> tuple[float, float]:
    """The shape's centre of mass in its own frame (the origin of its points): a polygon's
    points need not be centred on it (Science Birds' triangles are not)."""
    if isinstance(shape, Compound):
        weights = [area(part, skin) for part in shape.parts]
        centres = [centroid(part) for part in shape.parts]
        total = sum(weights)
        return (
            sum(w * c[0] for w, c in zip(weights, centres, strict=False)) / total,
            sum(w * c[1] for w, c in zip(weights, centres, strict=False)) / total,
        )
    if isinstance(shape, Circle):
        return (0.0, 0.0)
    points = shape.points
    total = sx = sy = 0.0
    for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=False):
        cross = x0 * y1 - x1 * y0
        total += cross
        sx += (x0 + x1) * cross
        sy += (y0 + y1) * cross
    return (sx / (3 * total), sy / (3 * total)) if total else (0.0, 0.0)


def polar_moment(shape: Circle | Polygon | Compound, mass: float, skin: float = 0.0) -> float:
    """The moment of inertia about the origin of the points (not the centroid), for `mass`
    spread evenly over the shape (signed triangles from the origin: it may lie outside)."""
    if isinstance(shape, Compound):
        total = area(shape, skin)
        return sum(polar_moment(part, mass * area(part, skin) / total) for part in shape.parts)
    if isinstance(shape, Circle):
        return mass * shape.radius**2 / 2
    points = shape.points
    numerator = denominator = 0.0
    for (x0, y0), (x1, y1) in zip(points, points[1:] + points[:1], strict=False):
        cross = x0 * y1 - x1 * y0
        numerator += cross * (x0 * x0 + x0 * x1 + x1 * x1 + y0 * y0 + y0 * y1 + y1 * y1)
        denominator += cross
    return mass * numerator / (6 * denominator) if denominator else 0.0


@attrs.frozen
class Extent:
    width: float
    height: float
    rectangle: bool  # the points are exactly the centred rectangle width × height

    @classmethod
    def of(cls, points) -> Extent:
        xs, ys = [x for x, _ in points], [y for _, y in points]
        width, height = max(xs) - min(xs), max(ys) - min(ys)
        corners = {(sx * width / 2, sy * height / 2) for sx in (-1, 1) for sy in (-1, 1)}
        exact = len(points) == 4 and all(
            any(math.isclose(x, cx, abs_tol=1e-9) and math.isclose(y, cy, abs_tol=1e-9) for cx, cy in corners)
            for x, y in points
        )
        return cls(width, height, exact)

    @staticmethod
    def turned(points) -> tuple[tuple[float, float], float, float, float] | None:
        """(centre, angle, width, height) of a rectangle given as four points in any turn,
        or None if the points are no rectangle."""
        if len(points) != 4:
            return None
        (x0, y0), (x1, y1), (x2, y2), (x3, y3) = points
        ex, ey, fx, fy = x1 - x0, y1 - y0, x3 - x0, y3 - y0
        width, height = math.hypot(ex, ey), math.hypot(fx, fy)
        closes = math.isclose(x2, x1 + fx, abs_tol=1e-9) and math.isclose(y2, y1 + fy, abs_tol=1e-9)
        if not closes or width == 0 or height == 0 or abs(ex * fx + ey * fy) > 1e-9 * width * height:
            return None
        return ((x0 + x2) / 2, (y0 + y2) / 2), math.atan2(ey, ex), width, height

    @staticmethod
    def grown(points, skin: float) -> list[tuple[float, float]]:
        """The polygon's vertices pushed out by `skin` along their bisectors (its outline
        offset by about `skin`: exact for the edges' distance at right angles)."""
        grown = []
        n = len(points)
        for i, (x, y) in enumerate(points):
            (px, py), (nx, ny) = points[i - 1], points[(i + 1) % n]
            normals = []
            for (ax, ay), (bx, by) in (((px, py), (x, y)), ((x, y), (nx, ny))):
                ex, ey = bx - ax, by - ay
                length = math.hypot(ex, ey) or 1.0
                normals.append((ey / length, -ex / length))  # outward for counter-clockwise points
            mx, my = normals[0][0] + normals[1][0], normals[0][1] + normals[1][1]
            scale = skin / max((mx * normals[0][0] + my * normals[0][1]), 1e-9)
            grown.append((x + mx * scale, y + my * scale))
        return grown
