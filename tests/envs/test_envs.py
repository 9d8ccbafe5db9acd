"""Agents play physc's tasks (issue 55, point 2): physc/AngryBirds-v0 passes Gymnasium's
checker in each action mode and observation, plays as the task says, is reproducible from
its seed; the ActionSimulator answers PHYRE's way; the agents run."""

from __future__ import annotations

import warnings

import gymnasium
import numpy as np
import pytest
from conftest import GOLDEN
from gymnasium.utils.env_checker import check_env

import physc
import physc.envs
from physc.envs.agents import evaluate_agent, heuristic_agent, play_episode, random_agent

TASKS = [GOLDEN / "task" / name for name in ("05_F.json", "06_S.json", "01_SF.json")]


@pytest.fixture(autouse=True)
def _quiet():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # Gymnasium's advice on unnormalised spaces
        yield


def test_registered():
    assert {"physc/AngryBirds-v0", "physc/PhyreLike-v0"} <= set(physc.envs.register_envs())
    assert "physc/AngryBirds-v0" in gymnasium.registry


@pytest.mark.parametrize(("action", "observation"), [("angle", "features"), ("point", "both"), ("angle", "picture")])
def test_the_checker_passes(action, observation):
    env = gymnasium.make("physc/AngryBirds-v0", tasks=TASKS[:1], action=action, observation=observation, render_mode="rgb_array")
    check_env(env.unwrapped, skip_render_check=False)
    env.reset(seed=0)
    assert env.render().shape == env.unwrapped.playing.picture_shape


def test_the_solution_scores_one_and_realises_the_sequence():
    env = gymnasium.make("physc/AngryBirds-v0", tasks=TASKS, noise=False)
    task = physc.load_task(TASKS[0])
    observation, info = env.reset(options={"task": "F/0"})
    assert info["task_id"] == "F/0"
    rows = observation[observation.any(axis=1)]
    assert len(rows) == len(task.level.objects)
    pig = env.unwrapped.playing.feature_names.index("is_pig")
    assert rows[:, pig].sum() == 1
    after, reward, terminated, truncated, info = env.step(np.array([task.solution.release_angle], np.float32))
    assert (reward, terminated, truncated) == (1.0, True, False)
    assert info["solved"] and info["realised"] and info["pigs_destroyed"] == 1
    # The last observation is the level at rest: the pig's row is gone, the falling block has fallen.
    assert after[:, pig].sum() == 0 and len(after[after.any(axis=1)]) == len(rows) - 1
    block = next(i for i, o in enumerate(task.level.objects) if o.name == "fBlock")
    assert after[block, 1] < observation[block, 1] - 2


def test_an_unreachable_point_is_not_played_and_the_episode_goes_on():
    env = gymnasium.make("physc/AngryBirds-v0", tasks=TASKS[0], action="point")
    env.reset(seed=0)
    _, reward, terminated, _, info = env.step({"target": np.array([17.0, 7.0], np.float32), "trajectory": 0})
    assert (reward, terminated, info["valid"]) == (0.0, False, False)


def test_same_seed_same_episodes():
    def run():
        env = gymnasium.make("physc/AngryBirds-v0", tasks=TASKS)
        env.action_space.seed(5)
        return [play_episode(env, random_agent, seed=seed) for seed in range(4)]

    assert run() == run()


def test_the_simulator_answers_phyres_way():
    sim = physc.ActionSimulator(TASKS)
    assert sim.task_ids == ["F/0", "S/0", "SF/0"]
    assert len(sim.initial_featurized_objects) == 3
    for index, task in enumerate(sim.tasks):
        result = sim.simulate_action(index, [task.solution.release_angle])
        assert result.status is physc.SimulationStatus.SOLVED and result.status.is_solved() and result.reward == 1.0
    point = physc.ActionSimulator(TASKS, mode="point")
    assert point.simulate_action("F/0", {"target": (17.0, 7.0), "trajectory": 0}).status.is_invalid()
    twice = physc.ActionSimulator([TASKS[0], TASKS[0]])
    assert twice.task_ids == ["F/0", "F/0~2"]
    with pytest.raises(KeyError, match="no task 'G/0'"):
        sim.simulate_action("G/0", [10.0])
    with pytest.raises(ValueError, match="action mode"):
        physc.ActionSimulator(TASKS, mode="drag")


def test_the_simulator_gives_phyres_frames():
    sim = physc.ActionSimulator(TASKS[0])
    solution = [sim.tasks[0].solution.release_angle]
    played = sim.simulate_action(0, solution, need_images=True, need_featurized_objects=True)
    frames = len(played.images)
    assert frames == played.trace.steps // 50 + 1  # one a simulated second (0.02 s steps), and the last
    assert played.images.shape[1:] == sim.playing.picture_shape and played.images.dtype == np.uint8
    assert played.featurized_objects.shape == (frames, len(sim.tasks[0].level.objects), len(sim.playing.feature_names))
    # After the first step: the bodies have settled by hundredths of a unit and tenths of a degree.
    assert np.allclose(played.featurized_objects[0][:, :2], sim.features(0)[:, :2], atol=0.05)
    assert np.allclose(played.featurized_objects[0][:, 2], sim.features(0)[:, 2], atol=0.5)
    assert np.array_equal(played.featurized_objects[0][:, 3:], sim.features(0)[:, 3:])
    assert not np.array_equal(played.images[0], played.images[-1])
    assert len(sim.simulate_action(0, solution, need_featurized_objects=True, stride=10).featurized_objects) > frames


def test_the_agents_are_evaluated():
    env = gymnasium.make("physc/AngryBirds-v0", tasks=TASKS, noise=False)
    heuristic = evaluate_agent(env, heuristic_agent)
    random = evaluate_agent(env, random_agent, episodes_per_task=2)
    assert random == evaluate_agent(env, random_agent, episodes_per_task=2)  # the same evaluation each time
    random = evaluate_agent(env, random_agent)
    assert heuristic["all"]["plays"] == random["all"]["plays"] == 3
    assert set(heuristic["scenarios"]) == {"F", "S", "SF"}


def test_tasks_of_another_domain_are_refused():
    with pytest.raises(ValueError, match="not of phyre"):
        gymnasium.make("physc/PhyreLike-v0", tasks=TASKS)
