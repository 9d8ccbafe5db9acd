"""The pymunk backend (Chipmunk2D): a fast engine that is told the target world's settings and
honours what Chipmunk can (Box2D is physc's default)."""

from physc.backends import Backend
from physc.backends.pymunk.world import HONOURS, PymunkWorld

BACKEND = Backend(
    "pymunk", "pymunk 7 (Chipmunk2D): fast, deterministic", PymunkWorld, package="pymunk", honours=HONOURS
)
