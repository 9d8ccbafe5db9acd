"""PHYRE's jars in the vocabulary: a ball lying in a gray jar (one object of the scenario, two
bodies of the scene) and a jar turned upside down."""

from __future__ import annotations

import math

import pytest

from physc_phyre import DOMAIN, PhyreLevel, SceneBody
from physc_phyre.level import HELD_RADIUS, JAR_SUFFIX, held
from physc_phyre.world import PIXELS_PER_METRE

FLOOR_BAR = SceneBody("target", "bar", 128.0, 2.56, 0.0, 256.0, "purple", False)


def test_a_held_ball_lies_on_its_jars_base_and_stays_there():
    jar, ball = held("blue", 128.0, 5.12 + 2.56, 0.0, 60.0, "blue", "gray")
    assert (jar.name, jar.shape, jar.color, jar.dynamic) == ("blue" + JAR_SUFFIX, "jar", "gray", True)
    assert (ball.name, ball.shape, ball.color) == ("blue", "ball", "blue")
    assert ball.size == int(HELD_RADIUS * 60.0 - 0.5) + 0.5
    assert math.isclose(ball.y - jar.y, 2.56 + ball.size)  # resting on the base plate
    level = PhyreLevel((FLOOR_BAR, jar, ball), ("blue", "target"))
    trace = DOMAIN.play(level, None, recognise=False)
    end = trace.states[-1, trace.index("blue"), :2] * PIXELS_PER_METRE
    assert abs(end[0] - 128.0) < 1.0 and abs(end[1] - ball.y) < 1.0  # left alone, it stays in its jar


def test_the_vocabularys_jars_become_bodies_of_the_right_shape_and_turn():
    from physc.compiler.concrete_layout import PlacedObject
    from physc_phyre.level import level_from_layout

    class Layout:
        objects = (
            PlacedObject("target", "object", "blueBallInJar", None, 100.0, 30.0, 0.0, 50.0, 60.0),
            PlacedObject("cover", "object", "upsideDownJar", None, 200.0, 30.0, 180.0, 50.0, 60.0),
            PlacedObject("green", "object", "greenBall", None, 40.0, 10.0, 0.0, 20.0, 20.0),
        )

    level = level_from_layout(Layout, None)
    names = {b.name: b for b in level.bodies}
    assert set(names) == {"target", "target" + JAR_SUFFIX, "cover", "green"}
    assert names["target"].shape == "ball" and names["target"].y < 30.0  # low in its jar
    cover = names["cover"]
    assert cover.shape == "jar" and math.isclose(cover.angle, math.pi, abs_tol=1e-6) and cover.y > 30.0  # its base on top


def test_a_held_ball_fits_between_its_jars_walls_at_every_height():
    from physc_phyre.actions import placeable
    from physc_phyre.concretize import HOLDING_HEIGHT
    from physc_phyre.level import BallAction

    low, high = HOLDING_HEIGHT
    for tenth in range(int(low * 10), int(high * 10) + 1):
        jar, ball = held("blue", 128.0, 100.0, 0.0, tenth / 10, "blue", "gray")
        assert placeable(PhyreLevel((jar,), ("", "")), BallAction(ball.x, ball.y, ball.size)), tenth / 10


def test_a_dropped_object_starts_in_the_air_below_whatever_is_above_it():
    """`dropped(a)`: the object (a held ball with its jar) is lifted by a seeded height from
    DROP_HEIGHT, less where a body above leaves less room; the rest stays where it was."""
    from physc_phyre.level import DROP_HEIGHT, dropped

    shelf = SceneBody("shelf", "bar", 128.0, 100.0, 0.0, 80.0, "black", False)
    green = SceneBody("green", "ball", 128.0, 112.56, 0.0, 10.0, "green", True)
    lifted = {b.name: b for b in dropped([shelf, green], {"green"}, seed=3)}
    assert lifted["shelf"] == shelf and DROP_HEIGHT[0] <= lifted["green"].y - green.y <= DROP_HEIGHT[1]
    assert lifted == {b.name: b for b in dropped([shelf, green], {"green"}, seed=3)}  # the same seed, the same lift
    roof = SceneBody("roof", "bar", 128.0, 130.0, 0.0, 80.0, "black", False)  # 5 px of room above the ball
    low = {b.name: b for b in dropped([shelf, green, roof], {"green"}, seed=3)}
    assert 0 < low["green"].y - green.y <= 5.0
    jar, ball = held("blue", 40.0, 102.56, 0.0, 50.0, "green", "gray")
    both = {b.name: b for b in dropped([jar, ball], {"blue"}, seed=1)}
    assert both["blue"].y - ball.y == pytest.approx(both["blue" + JAR_SUFFIX].y - jar.y)
    assert both["blue"].y > ball.y
