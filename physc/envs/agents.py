"""Agents for physc's environments, and their evaluation: the same loop for every domain.

An agent is a callable `agent(env, observation, attempt) -> action`: `attempt` counts the
invalid actions already tried in this episode (an invalid action is not played, so an agent
can try another). `random_agent` samples the action space; each domain's `heuristic_agent`
(`Playing.heuristic`) is its own simple strategy. `evaluate_agent` plays episodes and reports
the solved share, the mean reward and how often the task's own sequence was realised.
"""

from __future__ import annotations

import statistics
from collections import defaultdict


def random_agent(env, observation, attempt: int):
    """A uniform action of the environment's action space (its own generator:
    `env.action_space.seed(…)`, which `evaluate_agent` seeds)."""
    return env.action_space.sample()


def heuristic_agent(env, observation, attempt: int):
    """The domain's heuristic (`Playing.heuristic`): angrybirds shoots at the pigs, nearest
    first, on the low then the high trajectory; PHYRE-like drops a ball on the green object."""
    playing = env.unwrapped.playing
    if playing.heuristic is None:
        which = env.unwrapped.spec.id if env.unwrapped.spec else "this environment"
        raise ValueError(f"the domain of {which} has no heuristic agent")
    return playing.heuristic(env.unwrapped, observation, attempt)


def play_episode(env, agent, seed: int | None = None, options: dict | None = None) -> dict:
    """One episode: the agent acts until a valid action has been played or the episode is
    truncated (the environment's limit on attempts)."""
    observation, info = env.reset(seed=seed, options=options)
    attempt = 0
    while True:
        observation, reward, terminated, truncated, step_info = env.step(agent(env, observation, attempt))
        if terminated or truncated:
            return {
                "task_id": info["task_id"],
                "reward": reward,
                "solved": bool(step_info.get("solved")),
                "realised": bool(step_info.get("realised")),
                "attempts": attempt + 1,
                "valid": bool(step_info.get("valid")),
            }
        attempt += 1


def evaluate_agent(env, agent, episodes_per_task: int = 1, seed: int = 0) -> dict:
    """Each task of the environment played `episodes_per_task` times (seeds `seed` …): the
    share solved, the mean reward, the share realising the task's sequence, per scenario and
    over all, and the plays that ended without a valid action."""
    by_scenario = defaultdict(list)
    env.action_space.seed(seed)  # the random agent's draws, so that an evaluation is the same each time
    for index, task_id in enumerate(env.unwrapped.task_ids):
        for episode in range(episodes_per_task):
            played = play_episode(env, agent, seed=seed + episode * 100_003 + index, options={"task": task_id})
            by_scenario[task_id.rsplit("/", 1)[0]].append(played)

    def summary(plays: list[dict]) -> dict:
        return {
            "plays": len(plays),
            "solved": round(sum(p["solved"] for p in plays) / len(plays), 4),
            "reward": round(statistics.fmean(p["reward"] for p in plays), 4),
            "realised": round(sum(p["realised"] for p in plays) / len(plays), 4),
            "no_valid_action": sum(not p["valid"] for p in plays),
        }

    every = [p for plays in by_scenario.values() for p in plays]
    return {"all": summary(every), "scenarios": {name: summary(plays) for name, plays in sorted(by_scenario.items())}}
