"""Building a body in pybullet: its collision shape (an extrusion of the 2-D shape) and the
body itself, a fixed one or a planar multibody whose joints are x, y and the angle."""

from __future__ import annotations

import math

import pybullet

from physc.backends import BodySpec, Circle, Compound, Polygon
from physc.backends.bullet.shapes import Extent
from physc.backends.convex import hull

DEPTH = 1.0  # the extrusion's depth (out of the plane); mass and inertia do not depend on it
SKIN = 0.01  # polygons grow by this, as pymunk's polygon skin (Box2D's polygon radius)
LINK_MASS = 1e-4  # the two carrier links of a planar body (the joints need a mass)
AXES = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
JOINTS = (0, 1, 2)  # x, y, angle
BODY_LINK = 2  # the link that carries a planar body's shape


def collision_shape(client: int, spec: BodySpec) -> int:
    """A sphere for a circle, a box for a centred rectangle, else the convex hull of the
    polygon grown by SKIN, DEPTH deep; for a compound of circles and rectangles, Bullet's
    compound of spheres and turned boxes; for any other compound (a game collider split into
    convex parts: pybullet's compounds take no meshes), the convex hull of all its parts, so
    its concavities and holes are filled in this engine."""
    if isinstance(spec.shape, Compound):
        if all(isinstance(part, Circle) or Extent.turned(part.points) is not None for part in spec.shape.parts):
            return _compound(client, spec.shape)
        polygons = [part for part in spec.shape.parts if isinstance(part, Polygon)]
        if len(polygons) < len(spec.shape.parts):
            raise ValueError(f"{spec.name}: Bullet's hull of a compound is of polygons, not of circles among them")
        points = [point for part in polygons for point in part.points]
        return _mesh(client, hull(points))
    if isinstance(spec.shape, Circle):
        return pybullet.createCollisionShape(pybullet.GEOM_SPHERE, radius=spec.shape.radius, physicsClientId=client)
    box = Extent.of(spec.shape.points)
    if box.rectangle:
        half = [box.width / 2 + SKIN, box.height / 2 + SKIN, DEPTH / 2]
        return pybullet.createCollisionShape(pybullet.GEOM_BOX, halfExtents=half, physicsClientId=client)
    return _mesh(client, spec.shape.points)


def _mesh(client: int, points) -> int:
    """The convex hull of `points` grown by SKIN, DEPTH deep."""
    vertices = [(x, y, z) for x, y in Extent.grown(points, SKIN) for z in (-DEPTH / 2, DEPTH / 2)]
    return pybullet.createCollisionShape(
        pybullet.GEOM_MESH, vertices=vertices, flags=pybullet.URDF_INITIALIZE_SAT_FEATURES, physicsClientId=client
    )


def _compound(client: int, shape: Compound) -> int:
    kinds, radii, halves, positions, turns = [], [], [], [], []
    for part in shape.parts:
        if isinstance(part, Circle):
            kinds.append(pybullet.GEOM_SPHERE)
            radii.append(part.radius)
            halves.append((0.0, 0.0, 0.0))
            positions.append((0.0, 0.0, 0.0))
            turns.append((0.0, 0.0, 0.0, 1.0))
            continue
        box = Extent.turned(part.points)
        if box is None:
            raise ValueError("the bullet backend builds a compound body from circles and rectangles only")
        (cx, cy), angle, width, height = box
        kinds.append(pybullet.GEOM_BOX)
        radii.append(0.0)
        halves.append((width / 2 + SKIN, height / 2 + SKIN, DEPTH / 2))
        positions.append((cx, cy, 0.0))
        turns.append(pybullet.getQuaternionFromEuler((0.0, 0.0, angle)))
    return pybullet.createCollisionShapeArray(
        shapeTypes=kinds,
        radii=radii,
        halfExtents=halves,
        collisionFramePositions=positions,
        collisionFrameOrientations=turns,
        physicsClientId=client,
    )


def friction(spec: BodySpec) -> float:
    """Bullet multiplies two bodies' frictions: the square root makes the product Box2D's
    geometric mean."""
    return math.sqrt(max(spec.friction, 0.0))


def static_body(client: int, spec: BodySpec, shape: int) -> int:
    """A fixed body. Its restitution is 1: Bullet multiplies restitutions, so a dynamic body
    bounces off it with its own bounciness (the larger of the pair, as in Box2D)."""
    quaternion = pybullet.getQuaternionFromEuler((0.0, 0.0, spec.angle))
    body = pybullet.createMultiBody(0.0, shape, -1, (spec.x, spec.y, 0.0), quaternion, physicsClientId=client)
    pybullet.changeDynamics(body, -1, lateralFriction=friction(spec), restitution=1.0, physicsClientId=client)
    return body


def planar_body(client: int, spec: BodySpec, shape: int, mass: float, inertia: float, centre) -> int:
    """A dynamic body: a planar multibody whose joint coordinates are x, y and the angle of
    the body's origin, motors off, no damping of Bullet's own; its mass sits at `centre` in
    the body's frame, with `inertia` about z through it."""
    body = pybullet.createMultiBody(
        0.0,
        -1,
        -1,
        (0.0, 0.0, 0.0),
        linkMasses=(LINK_MASS, LINK_MASS, mass),
        linkCollisionShapeIndices=(-1, -1, shape),
        linkVisualShapeIndices=(-1, -1, -1),
        linkPositions=((0, 0, 0),) * 3,
        linkOrientations=((0, 0, 0, 1),) * 3,
        linkInertialFramePositions=((0, 0, 0), (0, 0, 0), (centre[0], centre[1], 0.0)),
        linkInertialFrameOrientations=((0, 0, 0, 1),) * 3,
        linkParentIndices=(0, 1, 2),
        linkJointTypes=(pybullet.JOINT_PRISMATIC, pybullet.JOINT_PRISMATIC, pybullet.JOINT_REVOLUTE),
        linkJointAxis=AXES,
        physicsClientId=client,
    )
    for joint, value in zip(JOINTS, (spec.x, spec.y, spec.angle), strict=False):
        pybullet.resetJointState(body, joint, value, 0.0, physicsClientId=client)
    pybullet.setJointMotorControlArray(
        body, JOINTS, pybullet.VELOCITY_CONTROL, forces=(0.0, 0.0, 0.0), physicsClientId=client
    )
    pybullet.changeDynamics(body, -1, linearDamping=0.0, angularDamping=0.0, physicsClientId=client)
    pybullet.changeDynamics(
        body,
        BODY_LINK,
        lateralFriction=friction(spec),
        restitution=spec.bounciness,
        localInertiaDiagonal=(inertia, inertia, inertia),
        physicsClientId=client,
    )
    return body
