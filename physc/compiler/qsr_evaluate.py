"""Deciding whether a QSR holds between two placed objects, from coordinates.

This is the reference reading of the definitions in `physc.compiler.qsr` and
docs/qsr.md, written independently of the constraint machinery (it shares only
the table naming each tile's state per axis): it computes the five points of each
object from its pose (with complex-number rotation, not the solver's offsets) and
tests each relation's formula directly. The tests use it
to check every placed layout; validation can use it on any layout.
"""

from __future__ import annotations

import cmath
import math

from physc.compiler.qsr import FAR, TILES

TOLERANCE = 1e-5


def five_points(x: float, y: float, width: float, height: float, rotation: float) -> dict[str, complex]:
    turn = cmath.exp(1j * math.radians(rotation))
    centre = complex(x, y)
    half = complex(width / 2, 0), complex(0, height / 2)
    return {
        "c": centre,
        "ll": centre + (-half[0] - half[1]) * turn,
        "lr": centre + (half[0] - half[1]) * turn,
        "ur": centre + (half[0] + half[1]) * turn,
        "ul": centre + (-half[0] + half[1]) * turn,
    }


class _Object:
    def __init__(self, placed):
        self.p = five_points(placed.x, placed.y, placed.width, placed.height, placed.rotation)
        corners = [self.p[k] for k in ("ll", "lr", "ur", "ul")]
        self.left = min(c.real for c in corners)
        self.right = max(c.real for c in corners)
        self.bottom = min(c.imag for c in corners)
        self.top = max(c.imag for c in corners)
        self.width = self.right - self.left


def _le(a: float, b: float) -> bool:
    return a <= b + TOLERANCE


def _eq(a: complex, b: complex) -> bool:
    return abs(a - b) <= TOLERANCE


def _axis_is(state: str, a_low, a_high, b_low, b_high, gap: float) -> bool:
    """On one axis: a before b (by at least gap), after it, or overlapping it."""
    if state == "before":
        return _le(a_high, b_low - gap)
    if state == "after":
        return _le(b_high + gap, a_low)
    return _le(a_low, b_high) and _le(b_low, a_high)


def holds(relation: str, first, second, clearance: float, far: float) -> bool:
    """Whether `relation(first, second)` holds; the objects have x, y, width, height, rotation."""
    a, b = _Object(first), _Object(second)
    far_relation = relation.startswith(FAR)
    tile = relation[len(FAR) :] if far_relation else relation
    if tile in TILES:
        gap = far if far_relation else clearance
        horizontal, vertical = TILES[tile]
        return _axis_is(horizontal, a.left, a.right, b.left, b.right, gap) and _axis_is(
            vertical, a.bottom, a.top, b.bottom, b.top, gap
        )
    on_top = abs(a.bottom - b.top) <= TOLERANCE and _le(b.left, a.left) and _le(a.right, b.right)
    centre = a.p["c"].real
    if relation == "MeetN":
        return on_top and _le(b.left + b.width / 3, centre) and _le(centre, b.right - b.width / 3)
    if relation == "MeetDuringW":
        return on_top and _le(centre, b.left + b.width / 3)
    if relation == "MeetDuringE":
        return on_top and _le(b.right - b.width / 3, centre)
    if relation == "MeetOver":
        return abs(a.bottom - b.top) <= TOLERANCE and _le(b.left, centre) and _le(centre, b.right)
    if relation == "MeetNW":
        return _eq(a.p["ur"], b.p["ul"])
    if relation == "MeetW":
        return _eq((a.p["ur"] + a.p["lr"]) / 2, (b.p["ul"] + b.p["ll"]) / 2)
    if relation == "MeetSW":
        return _eq(a.p["lr"], b.p["ll"])
    raise ValueError(f"unknown relation {relation}")
