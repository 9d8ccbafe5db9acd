"""The game's five birds, several shots and the powers a tap sets off (physc.domains.angrybirds
birds.py and flight.py; docs/angrybirds.md, "The birds and their powers")."""

from __future__ import annotations

import math

import attrs
import numpy as np
import pytest

from physc.backends import BodySpec, Circle, Polygon, load_backend
from physc.domains.angrybirds.birds import BIRDS, BY_PREFAB, POWERS
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.launch import Shot, Shots
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import PHYQ

BOX2D = load_backend("box2d")
GROUND_TOP = PHYQ.frame.ground_top
PIG = LevelObject("Pig", "BasicSmall", -4.0, GROUND_TOP + 0.236, 0.0, name="pig")
FAR_PIG = LevelObject("Pig", "BasicSmall", 3.0, GROUND_TOP + 0.236, 0.0, name="pig2")


def test_each_birds_body_and_damage_are_its_prefabs():
    """Radius (the collider's × the prefab's scale), density, material and the damage
    multipliers, as BirdRed … BirdWhite.prefab give them; mass is area × density (auto mass)."""
    table = {b.prefab: (b.radius, b.density, b.friction, b.bounciness, b.multipliers["wood"], b.multipliers["stone"], b.multipliers["ice"], b.power) for b in BIRDS}
    assert table == {
        "BirdRed": (0.17, 6.0, 0.3, 0.43, 1.0, 1.0, 1.0, ""),
        "BirdBlue": (0.18, 4.5, 0.3, 0.25, 1.0, 1.0, 4.0, "split"),
        "BirdYellow": (0.16, 6.0, 0.4, 0.16, 2.4, 1.0, 1.2, "boost"),
        "BirdBlack": (0.20, 6.0, 0.3, 0.03, 1.0, 2.5, 1.0, "blast"),
        "BirdWhite": (0.26, 4.0, 0.3, 0.23, 0.8, 1.0, 0.8, "egg"),
    }
    assert BY_PREFAB["BirdRed"].mass == pytest.approx(PHYQ.bodies.bird_mass, abs=1e-3)
    assert BY_PREFAB["BirdBlue"].mass == pytest.approx(math.pi * 0.18**2 * 4.5)
    assert POWERS.split_angles == (15.0, 5.0, -5.0) and POWERS.boost == 4.0 and POWERS.black_fuse == 0.6
    assert (POWERS.black_blast.radius, POWERS.black_blast.power, POWERS.black_blast.damage) == (3.0, 4.0, 20.0)
    assert (POWERS.egg_blast.radius, POWERS.egg_blast.power, POWERS.egg_blast.damage) == (2.0, 2.0, 200.0)


@pytest.mark.parametrize("backend", ["box2d", "pymunk", "bullet"])
def test_bodies_of_one_group_pass_through_each_other(backend):
    """Unity's layer matrix: Birds never collide with Birds (BodySpec.group), in every engine."""
    engine = load_backend(backend)
    world = engine.create_world(PHYQ.gravity, PHYQ.engine)
    world.add(BodySpec("floor", Polygon(((-5, -0.5), (5, -0.5), (5, 0.5), (-5, 0.5))), 0.0, -0.5, static=True))
    for name, x, group in (("a", 0.0, "birds"), ("b", 0.1, "birds"), ("c", 3.0, ""), ("d", 3.1, "")):
        world.add(BodySpec(name, Circle(0.2), x, 0.2, group=group))
    for _ in range(25):
        world.step(0.02)
    apart = {name: world.state(name)[0] for name in "abcd"}
    assert abs(apart["b"] - apart["a"] - 0.1) < 0.02  # overlapping, and left so
    assert apart["d"] - apart["c"] > 0.3  # pushed apart


def played(level, action, seconds=9.0, **options):
    return Game(level, PHYQ, BOX2D).play(action, seconds, **options)


def test_the_next_bird_is_shot_once_the_level_rests():
    """Phy-Q's agents wait for the level to be static before each shot (safe mode)."""
    level = Level(objects=(PIG, FAR_PIG), birds=("BirdRed", "BirdRed"))
    first, second = Shot(target=(PIG.x, PIG.y)), Shot(target=(FAR_PIG.x, FAR_PIG.y), trajectory="high", bird="bird2")
    trace = played(level, Shots((first, second)))
    assert trace.names[:2] == ("bird", "bird2") and trace.kinds["bird2"] == "bird"
    column = trace.names.index("bird2")
    row = int(next(i for i in range(trace.steps) if not math.isnan(trace.states[i, column, 0])))
    before = trace.states[row - 2, [trace.names.index(n) for n in ("bird", "pig")], 3:6]
    assert np.nanmax(np.abs(before)) <= PHYQ.rest_speed  # static, the first bird too, when the second is shot
    assert row * trace.dt > min(c.time for c in trace.contacts if "bird" in (c.a, c.b)) + 1.0
    assert {d.name for d in trace.destructions if d.cause == "damage"} == {"pig", "pig2"} and trace.solved
    texts = [i.text() for i in trace.interactions]
    assert "hit(bird, pig, left)" in texts and "destroy(bird2, pig2)" in texts


def test_a_timed_shot_comes_its_wait_after_the_bird_before_struck():
    """ABGameWorld.KillBird at the bird's first collision brings the next onto the slingshot;
    a timed shot (`wait`) is taken that long after, while things still move."""
    level = Level(objects=(PIG, FAR_PIG), birds=("BirdRed", "BirdRed"))
    first, second = (
        Shot(target=(PIG.x, PIG.y)),
        Shot(target=(FAR_PIG.x, FAR_PIG.y), trajectory="high", bird="bird2", wait=1.5),
    )
    trace = played(level, Shots((first, second)))
    struck = min(c.time for c in trace.contacts if "bird" in (c.a, c.b))
    assert launched(trace, "bird2") == pytest.approx(struck + 1.5 + trace.dt, abs=1.5 * trace.dt)


def test_a_timed_shot_leaves_no_sooner_than_the_game_can_release_it():
    """HUD.cs drags the bird `_simulateDragTime` (1 s) before it releases a shot, and takes none
    before the bird is on the slingshot (0.2 s): a wait below 1.2 s is played at 1.2 s, as in the game."""
    level = Level(objects=(PIG, FAR_PIG), birds=("BirdRed", "BirdRed"))
    first = Shot(target=(PIG.x, PIG.y))
    second = Shot(target=(FAR_PIG.x, FAR_PIG.y), trajectory="high", bird="bird2", wait=0.3)
    soon = played(level, Shots((first, second)))
    earliest = played(level, Shots((first, attrs.evolve(second, wait=PHYQ.rules.earliest_wait))))
    assert PHYQ.rules.earliest_wait == pytest.approx(1.2)
    assert launched(soon, "bird2") == launched(earliest, "bird2")


def launched(trace, name: str) -> float:
    """When `name` entered the run (its first step with a state, the step after its launch)."""
    column = trace.names.index(name)
    return (int(next(i for i in range(trace.steps) if not math.isnan(trace.states[i, column, 0]))) + 1) * trace.dt


def launched_speed(trace, name, after):
    column = trace.names.index(name)
    row = int(round(after / trace.dt))
    return math.hypot(*trace.states[row, column, 3:5])


def test_a_tap_speeds_the_yellow_bird_up_along_its_flight():
    level = Level(objects=(FAR_PIG,), birds=("BirdYellow",))
    plain = played(level, Shot(angle=30.0), 3.0)
    tapped = played(level, Shot(angle=30.0, tap=0.5), 3.0)
    before, after = launched_speed(plain, "bird", 0.6), launched_speed(tapped, "bird", 0.6)
    assert after - before == pytest.approx(POWERS.boost / BY_PREFAB["BirdYellow"].mass, rel=0.02)
    assert [i.text() for i in tapped.interactions][0] == "tap(bird)"


def test_a_tap_splits_the_blue_bird_into_three_fanned_birds():
    level = Level(objects=(FAR_PIG,), birds=("BirdBlue",))
    trace = played(level, Shot(angle=30.0, tap=0.5), 3.0)
    row = int(round(0.56 / trace.dt))
    headings = sorted(math.degrees(math.atan2(trace.states[row, trace.names.index(n), 4], trace.states[row, trace.names.index(n), 3])) for n in ("bird", "bird~1", "bird~2"))
    assert headings[2] - headings[1] == pytest.approx(10.0, abs=0.5) and headings[1] - headings[0] == pytest.approx(10.0, abs=0.5)
    assert trace.parts == {"bird~1": "bird", "bird~2": "bird"}


def test_a_tap_too_soon_is_lost():
    """HUD.cs fires the power only once the bird is past the slingshot."""
    level = Level(objects=(FAR_PIG,), birds=("BirdYellow",))
    trace = played(level, Shot(angle=30.0, tap=0.001), 3.0)
    assert not any(i.name == "tap" for i in trace.interactions)


def test_the_black_birds_blast_at_a_tap_destroys_the_pig_near_it():
    level = Level(objects=(PIG,), birds=("BirdBlack",))
    shot = Shot(target=(PIG.x, PIG.y + 1.2), trajectory="low")
    fly = shot.start(PHYQ)[0]
    tap = (PIG.x - 0.6 - fly[0]) / shot.start(PHYQ)[1][0]  # a little before it reaches the pig
    trace = played(level, Shot(target=shot.target, tap=round(tap, 3)), 4.0)
    blasted = [d for d in trace.damage if d.target == "pig" and d.by == "bird"]
    assert blasted and any(d.name == "pig" and d.cause == "damage" for d in trace.destructions)
    assert any(d.name == "bird" and d.cause == "removed" for d in trace.destructions)


def test_the_white_birds_egg_drops_and_blasts_where_it_lands():
    level = Level(objects=(PIG,), birds=("BirdWhite",))
    shot = Shot(target=(PIG.x, PIG.y + 2.0), trajectory="high")
    (x0, _), (vx, _) = shot.start(PHYQ)
    trace = played(level, Shot(target=shot.target, trajectory="high", tap=round((PIG.x - x0) / vx, 3)), 5.0)
    assert "bird~egg" in trace.names and trace.kinds["bird~egg"] == "egg"
    assert any(d.name == "pig" and d.cause == "damage" and d.by == "bird~egg" for d in trace.destructions)
    assert "destroy(bird, pig)" in [i.text() for i in trace.interactions]  # the egg is its bird's
