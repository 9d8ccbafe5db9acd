"""PHYRE's jars: their plates as PHYRE's creator builds them, and in the vocabulary a ball
lying in a gray jar (one object of the scenario, two bodies of the scene) and a jar turned
upside down."""

from __future__ import annotations

import math

import pytest
from physc_phyre import DOMAIN, PhyreLevel, SceneBody
from physc_phyre.level import HELD_RADIUS, JAR_SUFFIX, held, outline_box
from physc_phyre.world import PIXELS_PER_METRE, SCENE, jar_height, jar_parts, jar_thickness

from physc.simulation.ending import Ending

FLOOR_BAR = SceneBody("target", "bar", 128.0, 2.56, 0.0, 256.0, "purple", False)


def test_a_held_ball_lies_on_its_jars_base_and_stays_there():
    jar, ball = held("blue", 128.0, 5.12 + 2.56, 0.0, 60.0, "blue", "gray")
    assert (jar.name, jar.shape, jar.color, jar.dynamic) == ("blue" + JAR_SUFFIX, "jar", "gray", True)
    assert (ball.name, ball.shape, ball.color) == ("blue", "ball", "blue")
    assert ball.size == int(HELD_RADIUS * 60.0 - 0.5) + 0.5
    assert 0 <= ball.y - jar.y - (jar_thickness(60.0) / 2 + ball.size) < 1e-3  # resting on the base plate
    level = PhyreLevel((FLOOR_BAR, jar, ball), ("blue", "target"))
    trace = DOMAIN.play(level, None, ending=Ending.OUTCOME)
    end = trace.states[-1, trace.index("blue"), :2] * PIXELS_PER_METRE
    assert abs(end[0] - 128.0) < 1.0 and abs(end[1] - ball.y) < 1.0  # left alone, it stays in its jar


def test_the_vocabularys_jars_become_bodies_of_the_right_shape_and_turn():
    from physc_phyre.level import level_from_layout

    from physc.compiler.concrete_layout import PlacedObject

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
    assert (
        cover.shape == "jar" and math.isclose(cover.angle, math.pi, abs_tol=1e-6) and cover.y > 30.0
    )  # its base on top


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


# A jar of PHYRE's own task 00021:002 (data/generated_tasks/tasks.bin.lzma, body 10): its
# diameter and its three polygons, as PHYRE's creator wrote them.
PHYRE_JAR_DIAMETER = 48.0
PHYRE_JAR = (
    [(12.8, 2.151252445042382), (-12.8, 2.151252445042382), (-12.8, -2.151252445042382), (12.8, -2.151252445042382)],
    [
        (-16.0, 36.24874755495762),
        (-12.8, -2.151252445042382),
        (-8.512357001958177, -1.7939488618722301),
        (-11.682581703360665, 36.24874755495762),
    ],
    [
        (16.0, 36.24874755495762),
        (11.682581703360665, 36.24874755495762),
        (8.512357001958177, -1.7939488618722301),
        (12.8, -2.151252445042382),
    ],
)


def _flat(points) -> list[float]:
    return [c for point in points for c in point]


def test_a_jars_plates_are_phyres_polygons():
    """The jar of a diameter is PHYRE's (shapes.py's Jar): the same vertices in the same order."""
    parts = jar_parts(jar_height(PHYRE_JAR_DIAMETER))
    assert len(parts) == len(PHYRE_JAR)
    for part, phyre in zip(parts, PHYRE_JAR, strict=True):
        assert _flat(part.points) == pytest.approx(_flat(phyre), abs=1e-12)


def test_a_jars_plates_follow_phyres_formula():
    """Jar._build for a height h: base 0.8 · h/1.2 wide, plates log(h) / log(76.8) · 5.12 thick,
    walls as thick across their length, from the base's ends to the opening's edges at h - t/2."""
    height = 50.0
    t = math.log(height) / math.log(0.3 * SCENE) * SCENE / 50
    assert jar_thickness(height) == t and jar_thickness(0.3 * SCENE) == pytest.approx(SCENE / 50)
    width, base_width = height / 1.2, height / 1.2 * 0.8
    hypotenuse = math.hypot(height, (width - base_width) / 2)
    sin, cos = height / hypotenuse, (width - base_width) / 2 / hypotenuse
    base, left, right = jar_parts(height)
    assert _flat(base.points) == pytest.approx(
        _flat([(base_width / 2, t / 2), (-base_width / 2, t / 2), (-base_width / 2, -t / 2), (base_width / 2, -t / 2)])
    )
    top = height - t / 2
    outer_top, outer_bottom, inner_bottom, inner_top = left.points
    assert _flat(left.points) == pytest.approx(
        _flat(
            [
                (-width / 2, top),
                (-base_width / 2, -t / 2),
                (-base_width / 2 + t * sin, t * cos - t / 2),
                (-width / 2 + t / sin, top),
            ]
        )
    )
    assert _flat(right.points) == pytest.approx(
        _flat([(-x, y) for x, y in (outer_top, inner_top, inner_bottom, outer_bottom)])
    )  # mirrored, counter-clockwise
    assert jar_height(math.hypot(0.9 * width, height)) == pytest.approx(height)  # shapes.py's Jar._diameter, inverted


@pytest.mark.parametrize("angle", [0.0, math.pi])
def test_a_jars_outline_box_is_its_plates_bounds(angle):
    jar = SceneBody("jar", "jar", 100.0, 50.0, angle, 45.0, "gray", True)
    c, s = math.cos(angle), math.sin(angle)
    points = [(jar.x + x * c - y * s, jar.y + x * s + y * c) for part in jar_parts(jar.size) for x, y in part.points]
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    assert outline_box(jar) == pytest.approx((min(xs), min(ys), max(xs), max(ys)))


def test_a_jar_is_written_as_phyres_creator_writes_it():
    """The task file's jar (task_file.py): PHYRE's polygons about its origin, and its diameter."""
    import json

    from physc_phyre.task_file import task_json

    jar = SceneBody("target", "jar", 137.69, 4.836, 0.0, jar_height(PHYRE_JAR_DIAMETER), "purple", False)
    green = SceneBody("green", "ball", 40.0, 100.0, 0.0, 6.5, "green", True)
    body = json.loads(task_json(PhyreLevel((jar, green), ("green", "target"))))["scene"]["bodies"][4]
    assert body["diameter"] == pytest.approx(PHYRE_JAR_DIAMETER, abs=1e-6) and body["shapeType"] == 3
    for shape, phyre in zip(body["shapes"], PHYRE_JAR, strict=True):
        assert [c for v in shape["polygon"]["vertices"] for c in (v["x"], v["y"])] == pytest.approx(
            _flat(phyre), abs=1e-6
        )


def test_a_jars_features_sit_at_phyres_centre_of_mass():
    """observation.jar_offset is PHYRE's Jar.center_of_mass(diameter=...): 8.2196 px above the
    base's middle at diameter 32 (PHYRE's triangle sums give the same to 1e-14)."""
    from physc_phyre.observation import jar_offset

    assert jar_offset(32.0) == pytest.approx(8.219627971808107, abs=1e-9)
    assert jar_offset(96.0) == pytest.approx(26.964287504654486, abs=1e-9)
