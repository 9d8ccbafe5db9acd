"""The pybullet backend: Bullet's solver, confined to the level's plane, as a second engine
that checks a task's solution with a different contact solver than pymunk's."""

import importlib
import os
import sys

from physc.backends import Backend


def _import_quietly():
    """Import pybullet without the line its C code prints to standard error on import
    ("pybullet build time: …"), which reads like a diagnostic of physc's."""
    try:
        sys.stderr.flush()
        saved = os.dup(2)
    except (OSError, ValueError):  # no real standard error (captured): nothing to keep clean
        importlib.import_module("pybullet")
        return
    try:
        with open(os.devnull, "w") as null:
            os.dup2(null.fileno(), 2)
            importlib.import_module("pybullet")
    finally:
        os.dup2(saved, 2)
        os.close(saved)


try:
    _import_quietly()
except ImportError as error:  # pragma: no cover - pybullet is a dependency of physc
    raise ImportError("pybullet is not installed (pip install pybullet)") from error

from physc.backends.bullet.world import HONOURS, BulletWorld  # noqa: E402 - after pybullet's quiet import

BACKEND = Backend(
    "bullet",
    "pybullet 3 (Bullet), bodies kept in the plane by planar joints: a second verifier",
    BulletWorld,
    package="pybullet",
    honours=HONOURS,
)
