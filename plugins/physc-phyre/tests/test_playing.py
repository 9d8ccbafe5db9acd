"""Agents play PHYRE-like tasks (issue 55): physc/PhyreLike-v0 passes Gymnasium's checker,
takes PHYRE's action, shows PHYRE's features and picture, does not play what PHYRE calls
invalid; the ActionSimulator and the heuristic agent work on both tiers."""

from __future__ import annotations

import warnings
from pathlib import Path

import gymnasium
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import physc
import physc.envs  # noqa: F401 - registers the environments
from physc.envs.agents import evaluate_agent, heuristic_agent

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


@pytest.fixture(scope="module")
def ledge():
    return physc.compile(EXAMPLES / "01_ledge.phys", seed=1, acceptance=False)


@pytest.fixture(scope="module")
def two_balls():
    return physc.compile(EXAMPLES / "07_two_balls.phys", seed=1, acceptance=False)


@pytest.fixture(autouse=True)
def _quiet():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        yield


def test_the_checker_passes(ledge):
    env = gymnasium.make("physc/PhyreLike-v0", tasks=ledge, observation="both", render_mode="rgb_array")
    check_env(env.unwrapped, skip_render_check=False)
    observation, _ = env.reset(seed=0)
    assert observation["picture"].shape == (256, 256) and observation["picture"].dtype == np.uint8
    assert env.action_space.shape == (3,)


def test_the_intended_action_solves_and_an_occluding_one_is_not_played(ledge):
    env = gymnasium.make("physc/PhyreLike-v0", tasks=ledge)
    observation, _ = env.reset(seed=0)
    colours = env.unwrapped.playing.feature_names
    assert observation[observation.any(axis=1)][:, colours.index("color_green")].sum() == 1
    _, reward, terminated, _, info = env.step(np.array(ledge.solution.unit()))
    assert (reward, terminated, info["solved"], info["realised"]) == (1.0, True, True, True)
    green = next(b for b in ledge.level.bodies if b.color == "green")
    over_it = [green.x / 255, green.y / 255, 0.5]
    _, reward, terminated, _, info = env.step(np.array(over_it))
    assert (reward, terminated, info["valid"]) == (0.0, False, False)


def test_frames_as_phyre_gives_them(ledge):
    sim = physc.ActionSimulator(ledge)
    played = sim.simulate_action(0, ledge.solution.unit(), need_images=True, need_featurized_objects=True)
    first, last = played.featurized_objects[0], played.featurized_objects[-1]
    assert len(first) == len(sim.features(0)) + 1  # the scene's bodies, then the agent's ball (PHYRE's order)
    assert first[-1][sim.playing.feature_names.index("color_red")] == 1.0
    assert np.allclose(first[:-1], sim.features(0), atol=1e-3)
    green = sim.playing.feature_names.index("color_green")
    moved = [i for i, row in enumerate(first) if row[green] == 1.0]
    assert not np.allclose(first[moved, :2], last[moved, :2])  # the green object went to the target
    assert played.images.shape[1:] == (256, 256) and (played.images[0] == 1).any()  # the red ball is drawn


def test_the_two_ball_tier_takes_six_numbers(two_balls, ledge):
    sim = physc.ActionSimulator(two_balls)
    assert sim.mode == "two_balls" and sim.action_space.shape == (6,)
    assert sim.simulate_action(0, two_balls.solution.unit()).status.is_solved()
    with pytest.raises(ValueError, match="both of PHYRE's tiers"):
        physc.ActionSimulator([two_balls, ledge])


def test_the_heuristic_agent_plays_both_tiers(ledge, two_balls):
    for task in (ledge, two_balls):
        env = gymnasium.make("physc/PhyreLike-v0", tasks=task)
        assert evaluate_agent(env, heuristic_agent)["all"]["plays"] == 1
