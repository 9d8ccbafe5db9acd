"""The pymunk backend (Chipmunk2D), the default physics engine of physc."""

from physc.backends import Backend
from physc.backends.pymunk.world import HONOURS, PymunkWorld

BACKEND = Backend("pymunk", "pymunk 7 (Chipmunk2D): fast, deterministic", PymunkWorld, package="pymunk", honours=HONOURS)
