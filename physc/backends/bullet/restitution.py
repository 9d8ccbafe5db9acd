"""Box2D's restitution of two dynamic bodies, from Bullet's per-body restitutions.

Box2D (and physc's pymunk backend) bounce a pair with the larger of the two bodies'
bounciness; Bullet multiplies the two bodies' restitutions, and pybullet has no per-pair
setting. Against the static world the product is made exact: static bodies have
restitution 1, a dynamic body its own bounciness. Between two dynamic bodies the product
is smaller: the bird (0.43) hitting a wood block (0) would not bounce at all, and would push
the block a third less hard than in the game.

So a game step in which two dynamic bodies of different bounciness begin touching, coming
together faster than the restitution threshold, is taken again from the bodies' poses and
velocities at its start, with the bouncier body's restitution raised for that step so that the pair's product is the
larger bounciness (`raised`). That body must touch nothing else in that step (the raised
value would bounce it off that too); otherwise the step keeps Bullet's product. In the
game this is the bird (and a thrown block) striking a block in flight: the case that
matters.
"""

from __future__ import annotations

FLOOR = 0.1  # a restitution of 0 cannot be multiplied up: the other body's counts as this at least


def raised(bouncier: float, other: float) -> tuple[float, float]:
    """(the bouncier body's restitution, the other's) for one step, whose product is the
    larger bounciness, `bouncier`: the other keeps its own, or FLOOR if lower (for that step
    it bounces off the static world with FLOOR, a small error where it rests on one)."""
    kept = max(other, FLOOR)
    return bouncier / kept, kept
