"""Shapes as the layout passes see them: the paper's five-point object.

An object is a box (or the bounding square of a circle) of a given width and
height, rotated counter-clockwise by `rotation` degrees (|rotation| <= 90, as the
paper assumes) about its centre. Its five points are the images of the box's
lower-left, centre, upper-right, upper-left and lower-right corners: ll, c, ur,
ul, lr. Once the shape is fixed, every point is the centre plus a constant
offset, so every QSR over points is a set of difference constraints over centres.
"""

from __future__ import annotations

import itertools
import math

import attrs

POINTS = ("ll", "c", "ur", "ul", "lr")
CORNERS = ("ll", "ur", "ul", "lr")
_UNIT = {"ll": (-1, -1), "c": (0, 0), "ur": (1, 1), "ul": (-1, 1), "lr": (1, -1)}


@attrs.frozen
class Geometry:
    width: float
    height: float
    rotation: float = 0.0  # degrees, counter-clockwise

    def offset(self, point: str) -> tuple[float, float]:
        """The offset (dx, dy) of a point from the centre."""
        ux, uy = _UNIT[point]
        x, y = ux * self.width / 2, uy * self.height / 2
        angle = math.radians(self.rotation)
        cos, sin = math.cos(angle), math.sin(angle)
        return (x * cos - y * sin, x * sin + y * cos)

    def points(self, cx: float, cy: float) -> dict[str, tuple[float, float]]:
        """The five points of the object centred at (cx, cy)."""
        return {p: (cx + dx, cy + dy) for p, (dx, dy) in ((p, self.offset(p)) for p in POINTS)}


def polygon(points: dict[str, tuple[float, float]]) -> list[tuple[float, float]]:
    """The corners in counter-clockwise order."""
    return [points["ll"], points["lr"], points["ur"], points["ul"]]


def overlap_depth(first: list[tuple[float, float]], second: list[tuple[float, float]]) -> float:
    """How deep two convex polygons overlap (0 when they only touch or are apart),
    by the separating axis theorem."""
    depth = math.inf
    for shape in (first, second):
        for index in range(len(shape)):
            x1, y1 = shape[index]
            x2, y2 = shape[(index + 1) % len(shape)]
            nx, ny = y2 - y1, x1 - x2
            norm = math.hypot(nx, ny)
            if norm == 0:
                continue
            nx, ny = nx / norm, ny / norm
            a = [px * nx + py * ny for px, py in first]
            b = [px * nx + py * ny for px, py in second]
            gap = min(max(a), max(b)) - max(min(a), min(b))
            if gap <= 0:
                return 0.0
            depth = min(depth, gap)
    return depth


def overlapping_pair(outlines: dict, tolerance: float, allowed=frozenset()) -> tuple[str, str] | None:
    """The first pair of named outlines (in order) that overlap by more than `tolerance`;
    pairs in `allowed` (frozensets of two names) may overlap."""
    for (a, first), (b, second) in itertools.combinations(outlines.items(), 2):
        if frozenset((a, b)) not in allowed and overlap_depth(first, second) > tolerance:
            return a, b
    return None
