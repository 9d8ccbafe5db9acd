"""The angrybirds game in its default engine (Box2D at the game's settings): hand-made cases with known outcomes, rules, determinism."""

from __future__ import annotations

import numpy as np
import pytest

from physc.backends import installed_backends, load_backend
from physc.domains.angrybirds.game import Game
from physc.domains.angrybirds.launch import Shot, Unreachable
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import PHYQ, catalogue_model
from physc.simulation.recognise import contact_intervals

LAUNCH, GRAVITY = PHYQ.launch, PHYQ.gravity
BIRD_REST, BIRD_COLLIDER_OFFSET, DRAG_RADIUS = LAUNCH.bird_rest, LAUNCH.collider_offset, LAUNCH.drag_radius


BOX2D = load_backend("box2d")

def launch_point(angle, stretch=1.0):
    return LAUNCH.point(angle, stretch)


def reachable(x, y):
    return PHYQ.reachable(x, y)

PIG_ON_GROUND = LevelObject("Pig", "BasicSmall", 0.0, -3.5 + 0.236, 0.0, name="pig")


def play(objects, shot, seconds=8.0, rules=PHYQ, **options):
    return Game(Level(objects=tuple(objects)), rules, BOX2D).play(shot, seconds, **options)


def test_bird_destroys_a_small_pig_on_the_ground():
    trace = play([PIG_ON_GROUND], Shot(target=(0.0, -3.27)))
    assert trace.solved
    assert trace.sequence().startswith("hit(bird, pig, left) > destroy(bird, pig)")


def test_a_true_circle_hit_from_the_left_rolls_right_where_the_games_circle_hops():
    platform = LevelObject("Platform", "Platform", 2.0, -1.0, 0.0, scale_x=10 / 0.64, scale_y=0.5, name="platform")
    circle = LevelObject("Block", "Circle", -1.5, -1.0 + 0.16 + 0.385, 0.0, "wood", name="circle")
    shot = Shot(target=(-1.5, -0.46))
    trace = play([platform, circle], shot, rules=catalogue_model("round"))  # physc's earlier model
    texts = [i.text() for i in trace.interactions]
    assert texts[:2] == ["hit(bird, circle, left)", "roll(circle, platform, right)"]
    x = trace.states[:, trace.index("circle"), 0]
    assert np.nanmax(x) > -1.5 + 2.0  # it rolled well to the right
    # The game's Circle is a polygon with a flat foot: struck from the left it tips over its
    # front corner, leaves the platform and goes on in hops, each lower than its radius; in
    # `phyq` a travel joins them, so it rolls, as Phy-Q's rolling levels mean (no bounce).
    game = play([platform, circle], shot)
    texts = [i.text() for i in game.interactions]
    circle_moves = [t for t in texts if t.startswith(("roll(circle", "bounce(circle"))]
    assert texts[0] == "hit(bird, circle, left)" and circle_moves[0] == "roll(circle, platform, right)"
    roll = next(i for i in game.interactions if i.text() == "roll(circle, platform, right)")
    touches = [span for span in contact_intervals(game)[frozenset(("circle", "platform"))] if span[0] >= roll.time - 1e-9]
    assert len(touches) > 1  # the roll is made of several touches: it hops


def test_block_dropped_on_a_pig_kills_it():
    # From 8, it lands after the level's 2 s of invulnerability (a fall of 11.3 units: 2.2 s).
    block = LevelObject("Block", "SquareHole", 0.0, 8.0, 0.0, "stone", name="block")
    trace = play([PIG_ON_GROUND, block], None)
    assert trace.solved
    texts = [i.text() for i in trace.interactions]
    assert texts[0] == "fall(block, pig)" and "hit(block, pig, above)" in texts and "destroy(block, pig)" in texts
    destroyed = next(d for d in trace.destructions if d.name == "pig")
    assert destroyed.by == "block" and destroyed.cause == "damage"


def test_a_platform_in_the_way_blocks_the_shot():
    wall = LevelObject("Platform", "Platform", -4.0, -1.5, 90.0, scale_x=8 / 0.64, scale_y=0.5, name="wall")
    trace = play([PIG_ON_GROUND, wall], Shot(target=(0.0, -3.27)))
    assert not trace.solved
    assert trace.interactions[0].text() == "hit(bird, wall, left)"
    assert not any(i.name == "hit" and i.objects == ("bird", "pig") for i in trace.interactions)


def test_same_level_same_trace():
    objects = [PIG_ON_GROUND, LevelObject("Block", "Circle", -2.0, -3.5 + 0.385, 0.0, "ice", name="circle")]
    first = play(objects, Shot(target=(-2.0, -3.0), trajectory="high"))
    second = play(objects, Shot(target=(-2.0, -3.0), trajectory="high"))
    assert np.array_equal(first.states, second.states, equal_nan=True)
    assert first.interactions == second.interactions


def test_objects_leaving_the_level_are_destroyed():
    ramp = LevelObject("Platform", "Platform", 15.5, -2.0, -15.0, scale_x=6 / 0.64, scale_y=0.5, name="ramp")
    circle = LevelObject("Block", "Circle", 13.2, -0.6, 0.0, "wood", name="circle")
    trace = Game(Level(objects=(ramp, circle)), PHYQ, BOX2D).simulate(None, seconds=8.0)
    (gone,) = trace.destructions
    assert (gone.name, gone.cause) == ("circle", "out of world")
    assert not trace.solved  # no pigs: nothing to solve


def test_damage_formula_and_invulnerability():
    game = Game(Level(objects=(PIG_ON_GROUND,)), PHYQ, BOX2D)
    world = game.build()
    from physc.simulation.trace import ContactRecord

    contact = ContactRecord(1.0, "pig", "ground", (0, -3.5), (0, -1), (0.0, -2.0), (0.0, -2.0), (0.0, 0.0))
    out = []
    game._damage(world, contact, out, 1.0)
    mass = world.mass("pig")
    (record,) = out
    assert record.amount == pytest.approx(2.0 * mass * 11.22 * 0.5 - 1.0)
    assert record.by == "ground"
    # The level's first 2 s are invulnerable when nothing is shot.
    block = LevelObject("Block", "SquareHole", 0.0, 3.0, 0.0, "stone", name="block")
    early = Game(Level(objects=(PIG_ON_GROUND, LevelObject("Block", "SquareHole", 0.0, -2.0, 0.0, "stone", name="block"))), PHYQ, BOX2D).simulate(None, 3.0)
    assert not early.destructions
    del block


def test_launch_model():
    shot = Shot(target=(0.0, -3.0))
    low, high = shot.release_angle(PHYQ), Shot(target=(0.0, -3.0), trajectory="high").release_angle(PHYQ)
    assert 0 < low < 45 < high < 90
    vx, vy = shot.velocity(PHYQ)
    assert np.hypot(vx, vy) == pytest.approx(10.0)
    # The game launches the bird where it was dragged to: the rest point pulled back a drag
    # radius along the shot, plus its collider's offset (ABBird.LaunchBird, BirdRed.prefab).
    x0, y0 = shot.origin(PHYQ)
    theta = np.radians(low)
    assert (x0, y0) == pytest.approx((BIRD_REST[0] - DRAG_RADIUS * np.cos(theta) + BIRD_COLLIDER_OFFSET[0], BIRD_REST[1] - DRAG_RADIUS * np.sin(theta) + BIRD_COLLIDER_OFFSET[1]))
    assert launch_point(45.0) == pytest.approx((-12.15 - 0.7071 + 0.05, -1.7 - 0.7071 - 0.03), abs=1e-4)
    # The flight from there passes through the target (no air drag, g = 4.7088).
    t = (0.0 - x0) / vx
    assert y0 + vy * t - GRAVITY * t * t / 2 == pytest.approx(-3.0, abs=1e-9)
    assert not reachable(15.0, 5.0)
    with pytest.raises(Unreachable):
        Shot(target=(15.0, 5.0)).release_angle(PHYQ)
    assert PHYQ.gravity == pytest.approx(9.81 * 0.48)


@pytest.mark.parametrize("turn", [-2.34, -0.05, 0.05, 0.68])
def test_a_shot_turned_to_another_angle_names_itself_by_a_point_it_aims_at_again(turn):
    """The raising of margins turns a shot along its release angle (domain.nudged): the turned
    shot, recorded as a target point and a trajectory, must aim at that angle again, on the low
    branch or the high one, whichever passes the point at that angle."""
    # (0.59, 3.92) low and (-9.58, 5.63) high lie near the top of their flights: turned by a
    # few degrees, the flight passes above the same x on the other branch.
    for target, trajectory in (((2.0, 0.0), "low"), ((2.0, 0.0), "high"), ((0.59, 3.92), "low"), ((-9.58, 5.63), "high")):
        shot = Shot(target=target, trajectory=trajectory)
        angle = shot.release_angle(PHYQ) + turn
        turned = shot.at_angle(angle, PHYQ)
        assert turned is not None and turned.release_angle(PHYQ) == pytest.approx(angle, abs=1e-3)  # the point rounded to 6 decimals


def test_the_bird_is_launched_from_the_dragged_to_point_in_the_world():
    game = Game(Level(objects=()), PHYQ, BOX2D)
    world = game.build()
    shot = Shot(angle=30.0)
    game.launch(world, shot)
    x, y, _, vx, vy, _ = world.state("bird")
    assert (x, y) == pytest.approx(launch_point(30.0), abs=1e-6)
    assert (vx, vy) == pytest.approx((10 * np.cos(np.radians(30)), 10 * np.sin(np.radians(30))), abs=1e-5)


def test_backend_is_a_plugin():
    assert "pymunk" in installed_backends()
    assert load_backend("pymunk").name == "pymunk"


def test_batched_states_match_one_by_one_reads_awake_asleep_and_gone():
    """`states` is one batched read; its rows must equal `state` per body, whatever
    order the engine keeps them in as bodies fall asleep, and NaN for removed ones."""
    from physc.backends import BodySpec, Circle, Polygon

    world = load_backend("pymunk").create_world(GRAVITY)
    world.add(BodySpec("ground", Polygon(((-20, -0.5), (20, -0.5), (20, 0.5), (-20, 0.5))), 0.0, -4.0, static=True))
    names = [f"ball{k}" for k in range(4)]
    for k, name in enumerate(names):
        world.add(BodySpec(name, Circle(0.3), -3.0 + 2.0 * k, -3.0 + 0.5 * k, angular_damping=0.1))
    world.set_velocity("ball3", 2.0, 0.0)
    asleep = set()
    for step in range(400):
        world.step(PHYQ.engine.dt)
        if step == 250:
            world.remove("ball1")
        rows = world.states(["ball3", *names])
        into = np.zeros((len(names) + 1, 6))
        world.states(("ball3", *names), out=into)  # another sequence of the same names, into an array
        assert np.array_equal(rows, into, equal_nan=True)
        for name, row in zip(["ball3", *names], rows):
            if name in world.bodies:
                assert tuple(row) == world.state(name)
                asleep |= {name} if world.bodies[name].is_sleeping else set()
            else:
                assert np.isnan(row).all()
    assert asleep  # the read was also checked while bodies slept


def test_direct_steps_equal_pymunks_own_steps():
    """The world steps Chipmunk directly once nothing was added or removed since the last
    step; pymunk's own `Space.step` throughout must give the very same run."""
    from physc.backends import BodySpec, Circle, Polygon

    def run(own_steps: bool):
        world = load_backend("pymunk").create_world(GRAVITY)
        world.add(BodySpec("ground", Polygon(((-20, -0.5), (20, -0.5), (20, 0.5), (-20, 0.5))), 0.0, -4.0, static=True))
        names = [f"box{k}" for k in range(5)]
        for k, name in enumerate(names):
            world.add(BodySpec(name, Polygon(((-0.4, -0.4), (0.4, -0.4), (0.4, 0.4), (-0.4, 0.4))), -3.0 + 0.9 * k, -3.0 + 0.4 * k, angular_damping=0.1))
        world.set_velocity("box0", 6.0, 1.0)
        rows, contacts = [], []
        for step in range(300):
            world.space.step(PHYQ.engine.dt) if own_steps else world.step(PHYQ.engine.dt)
            if step == 120:
                world.remove("box2")
            if step == 150:
                world.add(BodySpec("late", Circle(0.3), 0.0, 2.0))
            rows.append(world.states([*names, "late"]))
            contacts.extend((e.a, e.b, e.point) for e in world.begun())
        return np.array(rows), contacts

    direct, own = run(False), run(True)
    assert np.array_equal(direct[0], own[0], equal_nan=True)
    assert direct[1] == own[1] and len(direct[1]) > 5
