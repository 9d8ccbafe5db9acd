"""Scene furniture (physc_phyre.furniture): see-saws, teeters, cradles, purple ramps, peg rows, and an
object inside or under a jar; each becomes the bodies PHYRE's templates build it from, and
behaves as they do."""

from __future__ import annotations

import math
import random
from pathlib import Path

import pytest
from physc_phyre import DOMAIN, PhyreLevel, SceneBody
from physc_phyre.furniture import COVER_FIT, KINDS, PEG, PEG_SPACING, bodies, geometry, inside
from physc_phyre.level import held, level_from_layout, outline_box
from physc_phyre.world import BAR_HEIGHT, PIXELS_PER_METRE

from physc.compiler.concrete_layout import PlacedObject
from physc.simulation.ending import Ending

FLOOR_BAR = SceneBody("target", "bar", 128.0, 2.56, 0.0, 256.0, "purple", False)


def placed(concrete: str, x: float, bottom: float, seed: int = 0, heading=None, name: str = "it") -> PlacedObject:
    g = geometry(concrete, random.Random(seed), heading)
    return PlacedObject(name, "object", concrete, None, x, bottom + g.height / 2, g.rotation, g.width, g.height)


def end_of(level: PhyreLevel, name: str):
    trace = DOMAIN.play(level, None, ending=Ending.OUTCOME)
    return trace.states[-1, trace.index(name), :3] * (PIXELS_PER_METRE, PIXELS_PER_METRE, 1.0)


@pytest.mark.parametrize("concrete", sorted(set(KINDS) - {"purpleRamp"}))
def test_furniture_fills_its_outline_box_and_names_its_parts_after_itself(concrete):
    box = placed(concrete, 128.0, 40.0)
    parts = bodies(box, SceneBody)
    assert parts[0].name == "it" and all(p.name.startswith("it") for p in parts)
    edges = [outline_box(p) for p in parts]
    assert min(e[0] for e in edges) == pytest.approx(box.x - box.width / 2, abs=0.6)
    assert max(e[2] for e in edges) == pytest.approx(box.x + box.width / 2, abs=0.6)
    assert min(e[1] for e in edges) >= 40.0 - 0.6 and max(e[3] for e in edges) == pytest.approx(
        40.0 + box.height, abs=0.6
    )


def test_a_purple_ramp_is_one_bar_turned_as_the_layout_placed_it():
    box = placed("purpleRamp", 128.0, 40.0, heading="right")
    (bar,) = bodies(box, SceneBody)
    assert (bar.x, bar.y, bar.size, bar.color) == (box.x, box.y, box.width, "purple")
    assert bar.angle == pytest.approx(math.radians(box.rotation)) and 10 <= box.rotation <= 30


def test_a_seesaw_balances_its_beam_on_a_fulcrum_under_its_middle():
    beam, fulcrum = bodies(placed("blueSeesaw", 128.0, 0.0), SceneBody)
    assert (beam.shape, beam.color, beam.dynamic) == ("bar", "blue", True)
    assert (fulcrum.shape, fulcrum.color, fulcrum.dynamic) == ("ball", "black", False)
    assert beam.x == fulcrum.x and beam.y - BAR_HEIGHT / 2 == pytest.approx(fulcrum.y + fulcrum.size)


def test_a_teeter_holds_until_its_free_half_is_weighed_down():
    parts = bodies(placed("teeter", 128.0, 0.0), SceneBody)
    beam = parts[0]
    alone = end_of(PhyreLevel(tuple(parts), ("", "")), beam.name)
    assert abs(alone[2]) < 0.01 and abs(alone[1] - beam.y) < 0.5  # left alone it stays level
    left = beam.x - beam.size / 2 + 6.0
    weight = SceneBody("weight", "ball", left, beam.y + BAR_HEIGHT / 2 + 10.5, 0.0, 10.5, "gray", True)
    tipped = end_of(PhyreLevel(tuple(parts) + (weight,), ("", "")), beam.name)
    assert tipped[2] > 0.1  # counter-clockwise: its left end went down


def test_a_cradle_holds_a_ball_in_its_v_and_a_purple_ramp_rises_towards_its_toucher():
    left, right = bodies(placed("cradle", 128.0, 50.0, seed=2), SceneBody)
    assert left.angle == pytest.approx(-math.radians(5), abs=1e-6) and right.angle == pytest.approx(
        math.radians(5), abs=1e-6
    )
    ball = SceneBody("green", "ball", 128.0, 50.0 + 20.0, 0.0, 12.5, "green", True)
    end = end_of(PhyreLevel((left, right, ball), ("", "")), "green")
    assert abs(end[0] - 128.0) < 1.0 and 50.0 < end[1] < 50.0 + 12.5 + BAR_HEIGHT + 1.0
    assert geometry("purpleRamp", random.Random(0), "right").rotation > 0  # right end up
    assert geometry("purpleRamp", random.Random(0), "left").rotation < 0


def test_a_cover_jar_comes_over_the_ball_and_a_ball_goes_into_an_upright_jar():
    shelf = SceneBody("shelf", "bar", 128.0, 100.0, 0.0, 120.0, "black", False)
    ball = SceneBody("green", "ball", 100.0, 100.0 + BAR_HEIGHT / 2 + 12.5, 0.0, 12.5, "green", True)
    cover = SceneBody("cover", "jar", 40.0, 200.0, math.pi, 40.0, "gray", True)
    stray = SceneBody("support_cover", "bar", 40.0, 150.0, 0.0, 40.0, "black", False)
    out = {b.name: b for b in inside([shelf, ball, cover, stray], [("green", "cover")], held)}
    assert "support_cover" not in out and out["green"] == ball
    jar = out["cover"]
    assert jar.x == ball.x and jar.size >= ball.size / COVER_FIT - 0.1
    low = outline_box(jar)[1]
    assert low == pytest.approx(shelf.y + BAR_HEIGHT / 2, abs=0.01)  # its rim on the shelf
    end = end_of(PhyreLevel(tuple(out.values()), ("", "")), "green")
    assert abs(end[0] - ball.x) < 1.0 and abs(end[1] - ball.y) < 1.0  # the ball stays under it
    upright = SceneBody("jar", "jar", 180.0, 2.56, 0.0, 60.0, "gray", True)
    moved = {b.name: b for b in inside([FLOOR_BAR, upright, ball], [("green", "jar")], held)}
    _, expected = held("green", upright.x, upright.y, 0.0, 60.0, "green", "gray")
    assert (moved["green"].x, moved["green"].y) == (expected.x, expected.y) and moved["jar"] == upright


def test_an_upright_jar_comes_to_a_ball_the_layout_put_on_a_support_of_its_own():
    """PHYRE's 00005 and 00010: the ball's place (where its path starts) wins; the jar stands
    there on the ball's support, the ball on its base, and the jar's own support goes."""
    shelf = SceneBody("support_green", "bar", 100.0, 80.0, 0.0, 90.0, "black", False)
    ball = SceneBody("green", "ball", 110.0, 80.0 + BAR_HEIGHT / 2 + 9.5, 0.0, 9.5, "green", True)
    upright = SceneBody("jar", "jar", 200.0, 30.0, 0.0, 50.0, "gray", True)
    stray = SceneBody("support_jar", "bar", 200.0, 20.0, 0.0, 60.0, "black", False)
    out = {b.name: b for b in inside([shelf, ball, upright, stray], [("green", "jar")], held)}
    assert "support_jar" not in out and "support_green" in out
    jar = out["jar"]
    assert jar.x == ball.x and outline_box(jar)[1] == pytest.approx(shelf.y + BAR_HEIGHT / 2, abs=1e-3)
    _, expected = held("green", jar.x, jar.y, 0.0, 50.0, "green", "gray")
    assert (out["green"].x, out["green"].y) == (expected.x, expected.y)
    end = end_of(PhyreLevel(tuple(out.values()), ("", "")), "green")
    assert abs(end[0] - jar.x) < 1.0  # it stays in the jar


def test_a_ledge_carries_a_see_saw_with_its_centre_over_an_outer_third():
    """A load rests in a ledge's left, middle or right third; a see-saw, as wide as a ledge,
    needs a ledge of one and a half of its widths, not three (PHYRE's 00023 lays its catapult
    on a step shorter than the bar)."""
    from physc.domains import load_domain
    from physc.domains.words import INSTALLED
    from physc.driver.pipeline import Pipeline
    from physc.dsl.frontend import analyze

    path = Path(__file__).resolve().parents[1] / "examples" / "phyre" / "task00023.phys"
    (scenario,) = analyze(str(path), INSTALLED).scenarios
    layout = {o.name: o for o in Pipeline(load_domain("phyre"), scenario, 0).placed.layout.objects}
    lever, ledge = layout["lever"], layout["support_lever"]
    assert ledge.concrete == "blackBar" and 1.5 * lever.width + 6.0 <= ledge.width + 1e-6 < 3 * lever.width
    assert abs(lever.y - lever.height / 2 - (ledge.y + ledge.height / 2)) < 1e-3


def test_the_layouts_furniture_and_restrictions_reach_the_level():
    class Scenario:
        name = "T"
        objects = ()
        interactions = ()
        restrictions = ()

    class Layout:
        objects = (
            placed("blueSeesaw", 100.0, 0.0, name="target"),
            PlacedObject("green", "object", "greenBall", None, 100.0, 150.0, 0.0, 25.0, 25.0),
        )

    level = level_from_layout(Layout, None)
    assert {b.name for b in level.bodies} == {"target", "target_fulcrum", "green"}
    assert level.goal == ("green", "target")


def test_a_purple_pad_lies_on_the_floor_against_the_edge_and_the_ball_stays_on_it():
    """PHYRE's 00019 (and 00007): the target is a short purple bar lying on the floor; the
    layout puts it against an edge, and a ball come down onto it stays on it."""
    from physc_phyre.concretize import PAD_LENGTH

    from physc.domains import load_domain
    from physc.domains.words import INSTALLED
    from physc.driver.pipeline import Pipeline
    from physc.dsl.frontend import analyze

    path = Path(__file__).resolve().parents[1] / "examples" / "phyre" / "task00019.phys"
    (scenario,) = analyze(str(path), INSTALLED).scenarios
    for seed in range(3):
        layout = Pipeline(load_domain("phyre"), scenario, seed).placed.layout
        pad = level_from_layout(layout, scenario).body("target")
        assert (pad.shape, pad.color, pad.dynamic, pad.angle) == ("bar", "purple", False, 0.0)
        assert PAD_LENGTH[0] <= pad.size <= PAD_LENGTH[1] and pad.y == pytest.approx(BAR_HEIGHT / 2)
        assert min(pad.x - pad.size / 2, 256 - pad.x - pad.size / 2) == pytest.approx(0.0, abs=1e-3)
    ball = SceneBody("green", "ball", pad.x, BAR_HEIGHT + 40.0, 0.0, 12.5, "green", True)
    end = end_of(PhyreLevel((pad, ball), ("", "")), "green")
    assert abs(end[0] - pad.x) < pad.size / 2 + 12.5 and end[1] == pytest.approx(BAR_HEIGHT + 12.5, abs=0.5)


PEGGED = """scenario Pegged "Green ball knocked off the pegs" {
    domain phyre
    objects {
        green: greenObject = greenBall
        target: targetObject = purpleFloor
    }
    interactions {
        hit(red, green, above) > fall(green, target) > touch(green, target)
    }
    restrictions {
        pegged(green)
    }
}
"""


def test_a_peg_row_spreads_small_black_balls_over_its_box_and_holds_a_ball(tmp_path):
    """PHYRE's 00012 and 00013: a ball comes down onto small static black balls and rests
    there; `pegged(a)` makes a's support such a row."""
    pegs = bodies(placed("pegRow", 128.0, 60.0, seed=3), SceneBody)
    assert len(pegs) >= 3 and all((p.shape, p.color, p.dynamic, p.size) == ("ball", "black", False, PEG) for p in pegs)
    steps = [b.x - a.x for a, b in zip(pegs, pegs[1:], strict=False)]
    assert max(steps) <= PEG_SPACING + 1e-3 and max(steps) - min(steps) < 0.01
    ball = SceneBody("green", "ball", 128.0, 60.0 + 2 * PEG + 12.5 + 20.0, 0.0, 12.5, "green", True)
    end = end_of(PhyreLevel(tuple(pegs) + (ball,), ("", "")), "green")
    assert abs(end[0] - 128.0) < PEG_SPACING and 60.0 + PEG < end[1] - 12.5 < 60.0 + 2 * PEG

    from physc.domains import load_domain
    from physc.domains.words import INSTALLED
    from physc.driver.pipeline import Pipeline
    from physc.dsl.frontend import analyze

    path = tmp_path / "pegged.phys"
    path.write_text(PEGGED)
    (scenario,) = analyze(str(path), INSTALLED).scenarios
    layout = Pipeline(load_domain("phyre"), scenario, 0).placed.layout
    row = [o for o in layout.objects if o.concrete == "pegRow"]
    green = next(o for o in layout.objects if o.name == "green")
    assert len(row) == 1 and row[0].width >= 3 * green.width
    level = level_from_layout(layout, scenario)
    assert sum(b.name.startswith(row[0].name) for b in level.bodies) >= 3
