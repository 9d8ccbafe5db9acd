"""PHYRE's goal: two goal balls touch by the distance of their centres (task_validation.cpp's
kBallTouchingThreshold, a tenth of a pixel), every other pair by the engine's contact."""

from __future__ import annotations

import pytest
from physc_phyre import DOMAIN, PhyreLevel, SceneBody
from physc_phyre.rules import BALL_TOUCHING_THRESHOLD, RECOGNISER, GoalRules, balls_touch
from physc_phyre.world import GOAL_STEPS, PIXELS_PER_METRE

from physc.simulation.scene import play_scene
from physc.simulation.snapshot import Snapshot

FLOOR_BAR = SceneBody("target_floor", "bar", 128.0, 2.56, 0.0, 256.0, "purple", False)
RADIUS = 10.5  # px


def _balls(gap: float) -> PhyreLevel:
    """A green and a blue ball resting on a purple bar, `gap` pixels apart."""
    green = SceneBody("green", "ball", 100.0, 5.12 + RADIUS, 0.0, RADIUS, "green", True)
    blue = SceneBody("blue", "ball", 100.0 + 2 * RADIUS + gap, 5.12 + RADIUS, 0.0, RADIUS, "blue", True)
    return PhyreLevel((FLOOR_BAR, green, blue), ("green", "blue"))


def _run(level: PhyreLevel, resume=None):
    return play_scene(
        DOMAIN.scene(level, None),
        DOMAIN.backend,
        GoalRules.of(level),
        DOMAIN.seconds,
        RECOGNISER,
        recognise=False,
        resume=resume,
    )


def test_the_threshold_is_a_tenth_of_a_pixel_in_metres():
    assert BALL_TOUCHING_THRESHOLD * PIXELS_PER_METRE == pytest.approx(0.1)
    r = RADIUS / PIXELS_PER_METRE
    for gap, touching in ((0.0, True), (0.05, True), (0.09, True), (0.11, False), (0.2, False)):
        centre = (2 * RADIUS + gap) / PIXELS_PER_METRE
        assert balls_touch((0.0, 0.0), (centre, 0.0), r, r) is touching, gap


def test_balls_near_the_limit_are_judged_in_phyres_float_arithmetic():
    """Judged in doubles away from the limit, in float32 within EXACT_WITHIN of it: the same
    answer as PHYRE's float32 test everywhere, on a sweep across the limit and at its edges."""
    import numpy as np
    from physc_phyre.rules import EXACT_WITHIN

    f = np.float32
    r1, r2 = RADIUS / PIXELS_PER_METRE, 12.5 / PIXELS_PER_METRE
    limit = r1 + r2 + BALL_TOUCHING_THRESHOLD
    for offset in np.concatenate(
        [np.linspace(-3 * EXACT_WITHIN, 3 * EXACT_WITHIN, 601), [-EXACT_WITHIN, EXACT_WITHIN]]
    ):
        a, b = (3.1, 7.3), (3.1 + (limit + offset) * 0.6, 7.3 + (limit + offset) * 0.8)
        dx, dy = f(a[0]) - f(b[0]), f(a[1]) - f(b[1])
        phyre = bool(np.sqrt(dx * dx + dy * dy) < f(r1) + f(r2) + f(BALL_TOUCHING_THRESHOLD))
        assert balls_touch(a, b, r1, r2) is phyre, offset


@pytest.mark.parametrize(("gap", "solved"), [(0.05, True), (0.2, False)])
def test_two_balls_a_twentieth_of_a_pixel_apart_touch_and_a_fifth_do_not(gap, solved):
    """Neither pair is in contact in Box2D (circles collide only when they overlap); PHYRE's
    rule counts the nearer one as touching, and it holds for 3 s."""
    trace = _run(_balls(gap))
    assert trace.solved is solved
    if solved:
        assert trace.steps == GOAL_STEPS  # from the first step on
    assert not any({c.a, c.b} == {"green", "blue"} for c in trace.contacts)


def test_a_ball_and_a_bar_still_touch_by_contact():
    green = SceneBody("green", "ball", 100.0, 5.12 + RADIUS, 0.0, RADIUS, "green", True)
    level = PhyreLevel((FLOOR_BAR, green), ("green", "target_floor"))
    assert GoalRules.of(level).radii is None
    assert GoalRules.of(_balls(0.05)).radii == (RADIUS / PIXELS_PER_METRE,) * 2
    assert _run(level).solved


def test_going_on_from_a_snapshot_counts_the_steps_the_balls_were_within_reach():
    level = _balls(0.05)
    full = _run(level)
    snapshot = Snapshot.of(full, 100)
    resumed = _run(level, resume=snapshot)
    assert resumed.solved and resumed.steps == full.steps == GOAL_STEPS  # the 100 steps before it counted


def test_the_recognised_touch_is_the_rules_verdict():
    """Balls within PHYRE's tenth of a pixel never make a Box2D contact, yet the goal holds:
    the recognised `touch(green, blue)` is the rules' own, at the time it had held 3 s, so a
    task whose goal PHYRE's rule meets realises its declared `touch`."""
    level = _balls(0.05)
    trace = play_scene(DOMAIN.scene(level, None), DOMAIN.backend, GoalRules.of(level), DOMAIN.seconds, RECOGNISER)
    assert trace.solved and trace.goal_met == pytest.approx(GOAL_STEPS / 60)
    assert [(i.name, i.objects, i.time) for i in trace.interactions if i.name == "touch"] == [
        ("touch", ("green", "blue"), trace.goal_met)
    ]
    assert _run(_balls(0.2)).goal_met is None
