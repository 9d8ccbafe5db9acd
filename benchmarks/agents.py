"""Agents playing physc's tasks through its Gymnasium environments, and what a step costs.

For each dataset given (made by `physc generate`): a random and a heuristic agent
(physc.envs.agents) play every task `--episodes` times through the dataset's environment
(physc/AngryBirds-v0 in both action modes; physc/PhyreLike-v0 per PHYRE tier); and the
wall time of `env.step` (one action played to rest) is measured on one core over the random
agent's steps: median, 90th percentile, max.

    physc generate examples/paper/01_SF.phys examples/paper/02_SFTB.phys examples/paper/03_SFLB.phys \\
        examples/paper/05_F.phys examples/paper/06_S.phys examples/paper/07_B.phys --tasks 5 --out /tmp/ab-ds
    python benchmarks/agents.py /tmp/ab-ds [PHYRE-DATASET] --episodes 10 --json /tmp/agents.json

Results of a run are in docs/results.md ("Agents playing physc's tasks").
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
import warnings

import gymnasium

import physc.envs  # noqa: F401 - registers the environments
from physc.envs.agents import evaluate_agent, heuristic_agent, random_agent
from physc.envs.sources import gather

AGENTS = {"random": random_agent, "heuristic": heuristic_agent}


def environments(dataset: str) -> list[tuple[str, gymnasium.Env]]:
    """(a name, the environment) for each way the dataset's tasks are played."""
    tasks = gather(dataset)
    domain = tasks[0].domain
    if domain == "angrybirds":
        return [(f"AngryBirds-v0 {mode}", gymnasium.make("physc/AngryBirds-v0", tasks=tasks, action=mode)) for mode in ("angle", "point")]
    tiers: dict[str, list] = {}
    for task in tasks:
        tiers.setdefault(task.level.tier, []).append(task)
    return [(f"PhyreLike-v0 {tier.lower()}", gymnasium.make("physc/PhyreLike-v0", tasks=group)) for tier, group in sorted(tiers.items())]


def step_seconds(env, steps: int, seed: int = 0) -> list[float]:
    """Wall seconds of `steps` steps of random actions (valid ones: those are played)."""
    times = []
    env.reset(seed=seed)
    while len(times) < steps:
        action = env.action_space.sample()
        started = time.perf_counter()
        _, _, terminated, truncated, info = env.step(action)
        elapsed = time.perf_counter() - started
        if info.get("valid"):
            times.append(elapsed)
        if terminated or truncated:
            env.reset()
    return times


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("datasets", nargs="+")
    parser.add_argument("--episodes", type=int, default=10, help="episodes per task and agent (default 10)")
    parser.add_argument("--steps", type=int, default=300, help="steps timed per environment (default 300)")
    parser.add_argument("--json", help="write the results here too")
    args = parser.parse_args()
    warnings.simplefilter("ignore")  # Gymnasium's advice on unnormalised spaces
    results = []
    for dataset in args.datasets:
        for name, env in environments(dataset):
            row = {"dataset": dataset, "env": name, "tasks": len(env.unwrapped.task_ids)}
            for agent_name, agent in AGENTS.items():
                started = time.perf_counter()
                row[agent_name] = evaluate_agent(env, agent, args.episodes)
                row[f"{agent_name}_seconds"] = round(time.perf_counter() - started, 2)
            times = sorted(step_seconds(env, args.steps))
            row["step"] = {"median": round(statistics.median(times), 5), "p90": round(times[int(0.9 * len(times))], 5), "max": round(times[-1], 5), "steps": len(times)}
            results.append(row)
            every = {a: row[a]["all"] for a in AGENTS}
            print(f"{name} ({row['tasks']} tasks): " + "; ".join(f"{a} solved {s['solved']:.1%}, realised {s['realised']:.1%}, no valid action {s['no_valid_action']}" for a, s in every.items())
                  + f"; step median {row['step']['median'] * 1000:.1f} ms, p90 {row['step']['p90'] * 1000:.1f} ms, max {row['step']['max'] * 1000:.1f} ms", flush=True)
    if args.json:
        with open(args.json, "w", encoding="utf-8") as out:
            json.dump(results, out, indent=2)


if __name__ == "__main__":
    main()
