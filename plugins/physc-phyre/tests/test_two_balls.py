"""PHYRE's two-ball tier: a scenario with two red balls is a TWO_BALLS task whose action
places both (action_mappers.py's TwoBallsActionMapper), judged, written and scored as PHYRE's."""

from __future__ import annotations

import json
import random

import attrs
import pytest
from physc_phyre import DOMAIN, PhyreLevel, SceneBody, TwoBallAction, actions, benchmark, folds, phyre_format
from physc_phyre.level import BallAction
from physc_phyre.task_file import task_json

from physc.simulation.ending import Ending

TARGET = SceneBody("target", "bar", 128.0, 2.56, 0.0, 256.0, "purple", False)
LEDGE = SceneBody("ledge", "bar", 128.0, 60.0, 0.0, 60.0, "black", False)
GREEN = SceneBody("green", "ball", 128.0, 72.7, 0.0, 10.0, "green", True)
TWO = PhyreLevel((LEDGE, TARGET, GREEN), ("green", "target"), players=("first", "second"))
ONE = PhyreLevel((LEDGE, TARGET, GREEN), ("green", "target"))


def test_the_tier_is_the_number_of_red_balls():
    assert (ONE.tier, TWO.tier) == ("BALL", "TWO_BALLS")
    with pytest.raises(ValueError, match="one or two"):
        PhyreLevel((TARGET, GREEN), ("green", "target"), players=("a", "b", "c"))


def test_six_numbers_are_read_as_phyres_two_ball_mapper_reads_them():
    """x = int(a·255), y likewise, r = round(2 + a·30) for each ball; invalid when the centres
    are closer than r1 + r2 + 1 px (tested before quantising), or a ball leaves the scene."""
    pair = actions.from_unit((0.2, 0.5, 0.1, 0.8, 0.5, 0.1))
    assert pair == TwoBallAction(BallAction(51, 127, 5), BallAction(204, 127, 5))
    assert actions.from_unit(pair.unit()) == pair
    r = 2 + 0.1 * 30
    touching = 0.5 + (2 * r + 1) / 255  # the centres exactly r1 + r2 + 1 px apart: valid
    assert actions.from_unit((0.5, 0.5, 0.1, touching, 0.5, 0.1)) is not None
    assert actions.from_unit((0.5, 0.5, 0.1, touching - 1e-6, 0.5, 0.1)) is None
    assert actions.from_unit((0.5, 0.5, 0.1, 0.0, 0.5, 0.1)) is None  # the second ball sticks out of the scene
    assert actions.from_unit((0.5, 0.5, 0.1, 0.5)) is None  # neither three numbers nor six


def test_an_action_must_be_of_the_levels_tier_and_keep_the_balls_apart():
    far = TwoBallAction(BallAction(40, 200, 8), BallAction(200, 200, 8))
    assert DOMAIN.actions.valid(TWO, far) and not DOMAIN.actions.valid(ONE, far)
    assert DOMAIN.actions.valid(ONE, far.first)
    assert DOMAIN.actions.valid(TWO, far.first)  # the ball tier's action: PHYRE judges a two-ball task by one ball too
    # Apart is PHYRE's mapper's test, before it rounds to pixels: a pair that close is never
    # placed (from_unit), and one placed and then rounded closer is simulated as PHYRE does.
    assert (
        actions.from_unit((40 / 255, 200 / 255, 6 / 30, 56 / 255, 200 / 255, 6 / 30)) is None
    )  # 16 px apart, 17 needed
    assert DOMAIN.actions.valid(TWO, TwoBallAction(BallAction(40, 200, 8), BallAction(56, 200, 8)))
    on_the_ledge = TwoBallAction(BallAction(40, 200, 8), BallAction(128, 62, 8))
    assert not DOMAIN.actions.valid(TWO, on_the_ledge)  # the second ball occludes the ledge
    with pytest.raises(ValueError, match="places 1 red balls"):
        DOMAIN.scene(ONE, far)  # more balls than the level's tier places are refused, not cut
    assert (
        len(DOMAIN.scene(TWO, far.first).bodies) == len(DOMAIN.scene(TWO, far).bodies) - 1
    )  # one ball: the ball tier's play


def test_random_actions_and_neighbours_are_phyres_for_two_balls():
    rng = random.Random(0)
    drawn = [DOMAIN.actions.random_action(TWO, rng) for _ in range(200)]
    assert all(isinstance(a, TwoBallAction) and actions.apart(*a.balls) for a in drawn)
    assert all(isinstance(DOMAIN.actions.random_action(ONE, rng), BallAction) for _ in range(20))
    pair = drawn[0]
    moved = DOMAIN.actions.neighbours(pair)
    assert len(moved) == 8
    for n in moved:  # both balls moved together, by half a pixel (_yield_user_input_neighborhood)
        (dx1, dy1), (dx2, dy2) = ((b.x - a.x, b.y - a.y) for a, b in zip(pair.balls, n.balls, strict=True))
        assert (dx1, dy1) == (dx2, dy2) != (0, 0) and {abs(dx1), abs(dy1)} <= {0.0, 0.5}


def test_the_acceptance_rule_is_the_tiers():
    """PHYRE's SOLVABILITY_THRESHOLD_PROBS by tier, its pool and stopping constants, and its
    two-ball templates' `reject_ball_solvable`."""
    ball, two = DOMAIN.evaluation.rule(ONE), DOMAIN.evaluation.rule(TWO)
    assert (ball.threshold, ball.tier, ball.unsolvable_in) == (1e-5, "ball", ())
    assert (two.threshold, two.tier, two.unsolvable_in) == (1e-6, "two_balls", (attrs.evolve(ball, max_chunks=30),))
    assert (ball.min_valid, ball.min_solutions, ball.chunk, ball.p_value, ball.trivial) == (
        10_000,
        3,
        10_000,
        0.05,
        0.1,
    )
    # PHYRE's pool: a two-ball task is judged by one ball too (valid there), in PHYRE's order
    first = DOMAIN.evaluation.action_pool(TWO, "ball", 0, 10)[:3]
    assert (
        all(isinstance(a, BallAction) for a in first)
        and DOMAIN.evaluation.action_pool(TWO, "two_balls", 1, 10)[0]
        != DOMAIN.evaluation.action_pool(TWO, "two_balls", 0, 10)[0]
    )
    assert any(DOMAIN.actions.valid(TWO, a) for a in first)
    # `mayBeTrivial()`: the template's search_params exclude no flag (PHYRE's 00000, 00003, …)
    assert (
        ball.excluded == ("TRIVIAL",) and DOMAIN.evaluation.rule(attrs.evolve(ONE, may_be_trivial=True)).excluded == ()
    )


def test_both_balls_play_and_the_task_is_written_in_phyres_two_ball_tier():
    pair = TwoBallAction(BallAction(120, 120, 8), BallAction(200, 200, 12))
    trace = DOMAIN.play(TWO, pair, ending=Ending.OUTCOME)
    assert {"first", "second"} <= set(trace.names)
    task = json.loads(task_json(DOMAIN.files.with_solution(TWO, pair)))
    assert task["tier"] == "TWO_BALLS"
    assert [b["radius"] for b in task["solutions"][0]["balls"]] == [8.0, 12.0]
    assert task["physc"]["actions"] == [list(pair.unit())]
    task.pop("physc")
    task["taskId"] = "00100:000"
    (back,) = phyre_format.read_collection(phyre_format.collection_bytes([task]))
    assert back == task


def test_the_benchmark_keeps_six_numbers_and_splits_each_tier_on_its_own():
    one = json.loads(task_json(DOMAIN.files.with_solution(ONE, BallAction(120, 120, 8))))
    two = json.loads(
        task_json(DOMAIN.files.with_solution(TWO, TwoBallAction(BallAction(120, 120, 8), BallAction(200, 200, 12))))
    )
    assert len(benchmark._action(one)) == 3 and len(benchmark._action(two)) == 6
    ids = [f"{t:05d}:{i:03d}" for t in range(10) for i in range(5)]
    tiers = {task: "BALL" if task < "00005" else "TWO_BALLS" for task in ids}
    split = folds.folds(ids, seeds=3, tiers=tiers)
    assert list(split) == list(folds.SETUPS)  # PHYRE's names: ball_cross_template, …, two_balls_within_template
    for tier in ("BALL", "TWO_BALLS"):
        mine = [t for t in ids if tiers[t] == tier]
        for kind in folds.KINDS:
            for seed in range(3):
                parts = split[folds.setup(tier, kind)][str(seed)]
                assert [parts[k] for k in ("train", "dev", "test")] == [list(p) for p in folds.fold(kind, mine, seed)]


def test_phyres_random_agent_draws_six_numbers_for_a_two_ball_task():
    import numpy as np
    from physc_phyre.agents import Observation, random_agent

    seen = Observation(
        "00100:000", np.zeros((256, 256), np.uint8), np.zeros((0, 14), np.float32), {"tier": "TWO_BALLS"}
    )
    first = next(iter(random_agent(seen)))
    assert len(first) == 6 and all(0 <= v < 1 for v in first)


def test_the_two_ball_example_compiles_to_a_two_ball_task_that_verifies(tmp_path):
    from test_phyre_plugin import EXAMPLES, physc

    level, task = tmp_path / "level.json", tmp_path / "task.json"
    status, _, err = physc(
        "compile", EXAMPLES / "07_two_balls.phys", "--seed", "2", "-q", "--no-acceptance", "-o", level, "--task", task
    )
    assert status == 0, err
    written = json.loads(level.read_text())
    assert written["tier"] == "TWO_BALLS" and len(written["solutions"][0]["balls"]) == 2
    assert json.loads(task.read_text())["solution"]["node"] == "TwoBallAction"
    status, out, err = physc("verify", "--task", task, level)
    assert status == 0, out + err
