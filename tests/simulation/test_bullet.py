"""The pybullet backend: bodies stay in the plane, runs repeat exactly, and the game's
physics means the same as in pymunk where a task depends on it (benchmarks/backends.py
measures the rest)."""

from __future__ import annotations

import math

import numpy as np
import pybullet
import pytest

from physc.backends import BodySpec, Polygon, load_backend
from physc.domains.angrybirds.game import BIRD, GROUND, Game
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import PHYQ

BOX2D = load_backend("box2d")

GROUND_TOP = PHYQ.frame.ground_top

BULLET = load_backend("bullet")
SQUARE = 0.3772  # SquareSmall


def towers() -> Level:
    """Two towers of wood, ice and stone with pigs between them, and a circle on a platform."""
    objects = []
    for tower, x in enumerate((-2.0, 1.5)):
        for floor in range(4):
            material = ("wood", "ice", "stone")[(tower + floor) % 3]
            objects.append(LevelObject("Block", "SquareSmall", x, GROUND_TOP + SQUARE / 2 + 0.015 + floor * (SQUARE + 0.015), 0.0, material, name=f"b{tower}{floor}"))
    objects.append(LevelObject("Pig", "BasicSmall", -0.25, GROUND_TOP + 0.236, 0.0, name="pig1"))
    objects.append(LevelObject("Platform", "Platform", 4.0, -1.0, 0.0, scale_x=3.0, scale_y=0.5, name="shelf"))
    objects.append(LevelObject("Block", "Circle", 4.0, -1.0 + 0.16 + 0.375 + 0.015, 0.0, "wood", name="wheel"))
    return Level(objects=tuple(objects))


def run_steps(backend, level: Level, shot: Shot | None, steps: int, check=None):
    game = Game(level, PHYQ, backend)
    world = game.build()
    if shot is not None:
        game.launch(world, shot)
    names = [n for n in world.names if n in game.kinds and game.kinds[n] not in ("platform", "ground")]
    rows, events = [], []
    for step in range(steps):
        world.step(PHYQ.engine.dt)
        events += [(step, e.a, e.b, e.point, e.relative_velocity) for e in world.begun()]
        events += [(step, a, b) for a, b in world.ended()]
        rows.append(world.states(names).copy())
        if check is not None:
            check(world, step)
    return np.array(rows), events, names


def test_bodies_never_leave_the_plane_or_turn_out_of_it_in_a_ten_second_shot():
    worst = [0.0, 0.0]

    def check(world, step):
        for name in world.names:
            body = world._id[name]
            if name in world._dynamic:
                (_, _, z), (qx, qy, _, _) = pybullet.getLinkState(body, 2, physicsClientId=world.client)[:2]
            else:
                (_, _, z), (qx, qy, _, _) = pybullet.getBasePositionAndOrientation(body, physicsClientId=world.client)
            worst[0] = max(worst[0], abs(z))
            worst[1] = max(worst[1], abs(qx), abs(qy))

    rows, events, _ = run_steps(BULLET, towers(), Shot(target=(-2.0, -3.0)), 500, check)
    assert worst == [0.0, 0.0]
    assert any(BIRD in e[1:3] for e in events)  # the shot did strike the towers
    assert np.nanmax(np.abs(rows[:, :, 3])) > 1.0


def test_the_same_level_and_shot_give_the_same_run_byte_for_byte():
    first = run_steps(BULLET, towers(), Shot(target=(-2.0, -3.0)), 300)
    second = run_steps(BULLET, towers(), Shot(target=(-2.0, -3.0)), 300)
    assert first[0].tobytes() == second[0].tobytes()
    assert first[1] == second[1] and first[1]
    trace = Game(towers(), PHYQ, BULLET).play(Shot(target=(-2.0, -3.0)), 6.0)
    again = Game(towers(), PHYQ, BULLET).play(Shot(target=(-2.0, -3.0)), 6.0)
    assert trace.states.tobytes() == again.states.tobytes() and trace.sequence() == again.sequence()


def test_a_fall_and_a_flight_take_as_long_and_go_as_far_as_in_pymunk():
    def landing(backend, level, shot, name):
        game = Game(level, PHYQ, backend)
        world = game.build()
        if shot is not None:
            game.launch(world, shot)
        for step in range(500):
            world.step(PHYQ.engine.dt)
            for event in world.begun():
                if {event.a, event.b} == {name, GROUND}:
                    return (step + 1) * PHYQ.engine.dt, world.state(name)[0]
            world.ended()
        raise AssertionError("never landed")

    dropped = Level(objects=(LevelObject("Block", "SquareSmall", 0.0, GROUND_TOP + SQUARE / 2 + 3.0, 0.0, "wood", name="square"),))
    fall = {b: landing(load_backend(b), dropped, None, "square")[0] for b in ("pymunk", "bullet")}
    assert fall["bullet"] == pytest.approx(fall["pymunk"], abs=0.021)
    assert fall["bullet"] == pytest.approx(math.sqrt(2 * 3.0 / PHYQ.gravity), abs=0.03)
    for angle in (30, 45, 60):
        x = {b: landing(load_backend(b), Level(objects=()), Shot(angle=angle), BIRD)[1] for b in ("pymunk", "bullet")}
        assert x["bullet"] == pytest.approx(x["pymunk"], abs=0.15), angle


def test_contacts_begin_with_the_speed_before_the_collision_and_end():
    world = BULLET.create_world(PHYQ.gravity)
    world.add(BodySpec("floor", Polygon(((-5, -0.5), (5, -0.5), (5, 0.5), (-5, 0.5))), 0.0, -0.5, static=True))
    world.add(BodySpec("box", Polygon(((-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2))), 0.0, 1.23, bounciness=0.5))
    begun, ended = [], []
    for step in range(150):
        world.step(PHYQ.engine.dt)
        begun += [(step, e) for e in world.begun()]
        ended += [(step, pair) for pair in world.ended()]
    first = begun[0][1]
    assert {first.a, first.b} == {"box", "floor"}
    speed = math.sqrt(2 * PHYQ.gravity * 1.0)  # a fall of 1 unit
    assert abs(first.relative_velocity[1]) == pytest.approx(speed, rel=0.05)
    assert ended and ended[0][0] > begun[0][0]  # it bounced off (bounciness 0.5 against the static world)
    assert "floor" in world.touching("box")  # and came to rest on the floor at last


def test_bodies_that_start_overlapping_are_pushed_apart_without_flying():
    overlap = 0.04
    objects = (
        LevelObject("Block", "SquareSmall", 0.0, GROUND_TOP + SQUARE / 2 + 0.015, 0.0, "wood", name="low"),
        LevelObject("Block", "SquareSmall", 0.0, GROUND_TOP + 1.5 * SQUARE + 0.015 - overlap, 0.0, "wood", name="high"),
    )
    rows, _, _ = run_steps(BULLET, Level(objects=objects), None, 100)
    assert np.abs(rows[-1, :, 3:]).max() < 0.05  # at rest
    assert np.abs(rows[-1, :, 0] - rows[0, :, 0]).max() < 0.02  # and where they were


def test_a_bird_striking_a_block_bounces_as_in_pymunk():
    # Box2D bounces the pair with the larger bounciness (the bird's 0.43); Bullet would multiply.
    level = Level(objects=(LevelObject("Block", "Circle", -6.0, GROUND_TOP + 0.375, 0.0, "wood", name="wheel"),))
    speeds = {}
    for name in ("pymunk", "bullet"):
        rows, events, names = run_steps(load_backend(name), level, Shot(target=(-6.0, GROUND_TOP + 0.375)), 40)
        hit = next(e[0] for e in events if len(e) == 5 and {e[1], e[2]} == {BIRD, "wheel"})
        speeds[name] = rows[hit + 1, names.index("wheel"), 3]  # the wheel's speed just after the hit
    assert speeds["bullet"] == pytest.approx(speeds["pymunk"], rel=0.15)


def test_the_backend_a_caller_binds_is_the_one_the_game_uses():
    from physc.domains import load_domain

    domain = load_domain("angrybirds")
    assert domain.backend.name == "box2d"  # the default: the game's own engine
    there = domain.at(backend="bullet")
    assert there.backend.name == "bullet" and there.game(towers()).backend.name == "bullet"
    assert domain.backend.name == "box2d"  # binding makes a copy


def test_pybullet_missing_is_a_clear_usage_error(monkeypatch):
    import sys

    from conftest import EXAMPLES, run_physc

    from physc import backends

    for module in [m for m in sys.modules if m.startswith("physc.backends.bullet")]:
        monkeypatch.delitem(sys.modules, module)
    monkeypatch.setitem(sys.modules, "pybullet", None)  # as if it were not installed
    backends.load_backend.cache_clear()
    try:
        level = EXAMPLES.parent / "tests" / "data" / "sciencebirds" / "phyq-templates" / "2_2_1_1.xml"
        run = run_physc("simulate", level, "--backend", "bullet")
        assert run.status == 2 and "Traceback" not in run.stderr
        assert "backend 'bullet'" in run.stderr and "pybullet is not installed (pip install pybullet)" in run.stderr
    finally:
        backends.load_backend.cache_clear()


def test_an_off_centre_polygon_has_its_mass_at_its_centroid():
    # Science Birds' Triangle has its points about a corner's side, its centroid at (-0.125, -0.125):
    # with its centroid on a ledge and a corner over the edge it stays, as in pymunk.
    ledge = LevelObject("Platform", "Platform", 0.0, -1.0, 0.0, scale_x=3.0, scale_y=0.5, name="ledge")
    triangle = LevelObject("Block", "Triangle", 0.96 - 0.3, -1.0 + 0.16 + 0.375 + 0.015, 0.0, "wood", name="triangle")
    rows, _, _ = run_steps(BULLET, Level(objects=(ledge, triangle)), None, 250)
    assert np.abs(rows[-1, 0, :2] - rows[0, 0, :2]).max() < 0.02


def test_a_body_set_moving_after_resting_moves_and_a_heavier_gravity_does_not_spin_it():
    box = LevelObject("Block", "SquareSmall", 0.0, GROUND_TOP + SQUARE / 2, 0.0, "wood", name="box")
    world = Game(Level(objects=(box,)), PHYQ, BULLET).build()
    for _ in range(250):  # 5 s at rest
        world.step(PHYQ.engine.dt)
    start = world.state("box")[0]
    world.set_velocity("box", 3.0, 0.0)
    for _ in range(50):
        world.step(PHYQ.engine.dt)
    assert world.state("box")[0] - start > 0.5  # pymunk: 0.78
    # TNT falls at the full 9.81 (its gravity scale): the extra pull acts at its centre of mass
    world = Game(Level(objects=(LevelObject("TNT", "TNT", -5.0, 2.0, 0.0, name="tnt"),)), PHYQ, BULLET).build()
    world.set_velocity("tnt", 10.0, 0.0)
    for _ in range(25):
        world.step(PHYQ.engine.dt)
    assert abs(world.state("tnt")[2]) < 1e-6
    assert world.state("tnt")[4] == pytest.approx(-9.81 * 0.5, abs=0.2)  # set moving: 0.15 units/s of lag (set_velocity)


def test_a_removed_body_ends_its_contacts_at_once():
    world = BULLET.create_world(PHYQ.gravity)
    world.add(BodySpec("floor", Polygon(((-5, -0.5), (5, -0.5), (5, 0.5), (-5, 0.5))), 0.0, -0.5, static=True))
    world.add(BodySpec("box", Polygon(((-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2))), 0.0, 0.2))
    for _ in range(20):
        world.step(PHYQ.engine.dt)
    assert "floor" in world.touching("box")
    world.begun(), world.ended()
    world.remove("box")
    assert {frozenset(pair) for pair in world.ended()} == {frozenset(("box", "floor"))}  # at once, and once
    assert world.touching("floor") == set()
    world.add(BodySpec("ball", Polygon(((-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2))), 3.0, 3.0))
    world.step(PHYQ.engine.dt)  # the new body may get the removed one's id: no stale contact is named after it
    assert world.ended() == [] and world.begun() == []
