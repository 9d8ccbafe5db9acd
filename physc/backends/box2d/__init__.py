"""The Box2D backend (pybox2d, Box2D 2.3): the engine of both target worlds, Science Birds
(Unity's 2D physics) and PHYRE, run with the target world's own settings."""

try:
    import Box2D  # noqa: F401
except ImportError as error:  # pragma: no cover - box2d is a dependency of physc
    raise ImportError("Box2D is not installed (pip install box2d)") from error

from physc.backends import Backend  # noqa: E402
from physc.backends.box2d.world import HONOURS, Box2DWorld  # noqa: E402

BACKEND = Backend(
    "box2d",
    "Box2D 2.3 (pybox2d): the engine of Science Birds and PHYRE, with the target world's settings",
    Box2DWorld,
    package="box2d",
    honours=HONOURS,
)
