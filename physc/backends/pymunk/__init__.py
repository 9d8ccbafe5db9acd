"""The pymunk backend (Chipmunk2D), the default physics engine of physc."""

from physc.backends.pymunk.world import PymunkWorld


class PymunkBackend:
    name = "pymunk"
    description = "pymunk 7 (Chipmunk2D): fast, deterministic, the default"

    def create_world(self, gravity: float) -> PymunkWorld:
        return PymunkWorld(gravity)


BACKEND = PymunkBackend()
