"""The Box2D backend (pybox2d, Box2D 2.3): the engine of both target worlds, Science Birds
(Unity's 2D physics) and PHYRE, run with the target world's own settings."""

from physc.backends import Backend

try:
    from physc.backends.box2d.world import HONOURS, Box2DWorld
except ModuleNotFoundError as error:  # pragma: no cover - box2d is a dependency of physc
    if error.name != "Box2D":
        raise
    raise ImportError("Box2D is not installed (pip install box2d)") from error

BACKEND = Backend(
    "box2d",
    "Box2D 2.3 (pybox2d): the engine of Science Birds and PHYRE, with the target world's settings",
    Box2DWorld,
    package="box2d",
    honours=HONOURS,
)
