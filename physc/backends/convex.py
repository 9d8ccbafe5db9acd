"""Concave outlines (and outlines with holes) as convex parts an engine can collide.

Box2D collides convex polygons of at most `b2_maxPolygonVertices` corners (8 in Unity's
build). A game collider that is concave (Science Birds' TriangleHole, its pigs' ears), has a
hole, or has more corners than that (Circle's 24-gon) is split as Unity splits a
PolygonCollider2D: triangulated (mapbox's earcut), then the triangles merged across their
shared edges while the union stays convex and within the corner limit (Hertel and
Mehlhorn's greedy merge). Mass, area and centroid are the outline's, whatever the split.
"""

from __future__ import annotations

from collections.abc import Sequence

import mapbox_earcut
import numpy as np

Point = tuple[float, float]
MAX_CORNERS = 8  # Unity's Box2D: b2_maxPolygonVertices
EPSILON = 1e-9


def signed_area(points: Sequence[Point]) -> float:
    """The signed area of an outline (positive when counter-clockwise)."""
    total = 0.0
    for (x0, y0), (x1, y1) in zip(points, [*points[1:], points[0]], strict=False):
        total += x0 * y1 - x1 * y0
    return total / 2


def counter_clockwise(points: Sequence[Point]) -> tuple[Point, ...]:
    points = tuple((float(x), float(y)) for x, y in points)
    return points if signed_area(points) >= 0 else points[::-1]


def is_convex(points: Sequence[Point]) -> bool:
    """Whether a counter-clockwise outline is convex (collinear corners allowed)."""
    n = len(points)
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = points[i - 1], points[i], points[(i + 1) % n]
        if (bx - ax) * (cy - by) - (by - ay) * (cx - bx) < -EPSILON:
            return False
    return True


def convex_parts(
    outline: Sequence[Point], holes: Sequence[Sequence[Point]] = (), max_corners: int = MAX_CORNERS
) -> tuple[tuple[Point, ...], ...]:
    """`outline` less its `holes` as convex counter-clockwise parts of at most `max_corners`
    corners each (the outline itself when it already is one)."""
    outer = counter_clockwise(outline)
    if not holes and len(outer) <= max_corners and is_convex(outer):
        return (outer,)
    rings = [outer] + [counter_clockwise(h)[::-1] for h in holes]
    vertices = np.array([p for ring in rings for p in ring], dtype=np.float64)
    ends = np.cumsum([len(r) for r in rings]).astype(np.uint32)
    corners = mapbox_earcut.triangulate_float64(vertices, ends).reshape(-1, 3)
    parts = [list(counter_clockwise([tuple(vertices[i]) for i in triangle])) for triangle in corners]
    parts = [p for p in parts if abs(signed_area(p)) > EPSILON]
    return tuple(tuple(p) for p in _merged(parts, max_corners))


def _merged(parts: list[list[Point]], max_corners: int) -> list[list[Point]]:
    """Merge parts across shared edges while the union stays convex and small enough;
    deterministic: the first mergeable pair in order, again until none is."""
    merged = True
    while merged:
        merged = False
        for i in range(len(parts)):
            for j in range(i + 1, len(parts)):
                union = _union(parts[i], parts[j])
                if union is not None and len(union) <= max_corners and is_convex(union):
                    parts[i] = union
                    del parts[j]
                    merged = True
                    break
            if merged:
                break
    return parts


def _union(a: list[Point], b: list[Point]) -> list[Point] | None:
    """Two counter-clockwise parts joined along an edge they share (b runs it the other
    way), with collinear corners dropped; None if they share no edge."""
    for i in range(len(a)):
        p, q = a[i], a[(i + 1) % len(a)]
        for j in range(len(b)):
            if b[j] == q and b[(j + 1) % len(b)] == p:
                # a from q round to p, then b from p round to q (exclusive of both ends).
                ring = [a[(i + 1 + k) % len(a)] for k in range(len(a))]  # q … p
                ring += [b[(j + 2 + k) % len(b)] for k in range(len(b) - 2)]  # after p … before q
                return _without_collinear(ring)
    return None


def _without_collinear(ring: list[Point]) -> list[Point]:
    out = []
    n = len(ring)
    for i in range(n):
        (ax, ay), (bx, by), (cx, cy) = ring[i - 1], ring[i], ring[(i + 1) % n]
        if abs((bx - ax) * (cy - by) - (by - ay) * (cx - bx)) > EPSILON:
            out.append(ring[i])
    return out


def hull(points: Sequence[Point]) -> tuple[Point, ...]:
    """The convex hull of `points`, counter-clockwise (Andrew's monotone chain)."""
    unique = sorted(set((float(x), float(y)) for x, y in points))
    if len(unique) < 3:
        return tuple(unique)

    def half(sequence):
        out: list[Point] = []
        for p in sequence:
            while (
                len(out) >= 2
                and (out[-1][0] - out[-2][0]) * (p[1] - out[-2][1]) - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])
                <= EPSILON
            ):
                out.pop()
            out.append(p)
        return out

    lower, upper = half(unique), half(reversed(unique))
    return tuple(lower[:-1] + upper[:-1])
