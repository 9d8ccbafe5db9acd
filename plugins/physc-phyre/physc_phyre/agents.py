"""An agent scored on a generated PHYRE-like benchmark, as PHYRE scores its agents.

An agent is any Python callable that takes an `Observation` of a task (its id, PHYRE's
256 × 256 picture of colour indices, its 14-number feature vectors, the task itself in PHYRE's
structure) and yields actions in [0, 1]³ (x, y, radius, as PHYRE's ball tier reads them; six
numbers, two balls, for a task whose `tier` is TWO_BALLS), best first. An agent that learns has a `fit(observations)`
method too: it is called first with the
fold's training tasks (train and dev when the test split is scored, train alone for dev, as
PHYRE's agents/train.py does). Each action is played until the task is solved or 100 valid
attempts are spent; an invalid action (outside the scene, or occluding a body) is not counted,
as in PHYRE's evaluator. The score is PHYRE's AUCCESS over the split's tasks, per fold, per
action tier (PHYRE reports its ball and two-ball tiers apart) and per template (docs/phyre-sources.md, section 4.8).

`random_agent` is PHYRE's random agent: uniform actions, from a generator named after the task.
"""

from __future__ import annotations

import itertools
import json
import math
import random
import statistics
from collections.abc import Callable, Iterable
from pathlib import Path

import attrs
import numpy as np

from physc.domains.base import DomainError
from physc.evaluation.agent import calling
from physc.simulation.ending import Ending
from physc_phyre import observation, phyre_format
from physc_phyre.actions import from_unit

SPLITS = ("dev", "test")
STOP = object()  # the agent's actions have run out


@attrs.frozen
class Observation:
    """What an agent is shown of a task."""

    task_id: str
    image: np.ndarray = attrs.field(
        eq=False, repr=False
    )  # PHYRE's colour indices, (256, 256) uint8, row 0 at the bottom
    features: np.ndarray = attrs.field(eq=False, repr=False)  # (objects, 14) float32
    task: dict = attrs.field(
        eq=False, repr=False
    )  # the task in PHYRE's structure (phyre_format.py), without its solutions


def random_agent(seen: Observation) -> Iterable[tuple[float, ...]]:
    """PHYRE's random agent: uniform actions in [0, 1]³ (two-ball tier: [0, 1]⁶), drawn from a
    generator named after the task."""
    rng = random.Random(f"random-agent/{seen.task_id}")
    size = 6 if seen.task.get("tier") == "TWO_BALLS" else 3
    while True:
        yield tuple(rng.random() for _ in range(size))


def observations(folder: Path) -> dict[str, Observation]:
    """Every task of a generated dataset's `phyre/` folder, by id."""
    files = sorted((folder / "phyre").glob("tasks*.bin.lzma"))
    if not files:
        raise FileNotFoundError(f"no task collection (tasks*.bin.lzma) in {folder / 'phyre'}")
    tasks = [task for path in files for task in phyre_format.read_collection(path.read_bytes())]
    shown = [{k: v for k, v in t.items() if k != "solutions"} for t in tasks]  # not the intended solution
    return {t["taskId"]: Observation(t["taskId"], observation.raster(t), observation.features(t), t) for t in shown}


AGENT_ATTEMPTS = 100  # an agent's valid attempts per task (PHYRE's evaluation)
AGENT_DRAWS = 100_000  # draws it may make to find them (PHYRE samples from 100,000 actions)


def auccess(first_solved: int | None, attempts: int = AGENT_ATTEMPTS) -> float:
    """PHYRE's AUCCESS of one task for an agent that first solved it at attempt
    `first_solved` (1-based; None: never): Σ_k w_k s_k / Σ_k w_k with w_k = ln(k+1) − ln k,
    s_k = 1 from that attempt on. The mean over tasks is the AUCCESS of the set."""
    if first_solved is None or first_solved > attempts:
        return 0.0
    weights = sum(math.log(k + 1) - math.log(k) for k in range(first_solved, attempts + 1))
    return weights / math.log(attempts + 1)


def attempts(domain, level, actions: Iterable, until_solved: bool = False) -> list[bool]:
    """An agent's attempts at `level`, as PHYRE's evaluator counts them: whether each of the first
    AGENT_ATTEMPTS valid actions of `actions` solves it (None or an invalid action is not an
    attempt; AGENT_DRAWS actions are read at most); with `until_solved`, none after the first
    that solves it."""
    outcomes: list[bool] = []
    valid = domain.actions.valid
    for action in itertools.islice(actions, AGENT_DRAWS):
        if len(outcomes) == AGENT_ATTEMPTS:
            break
        if action is None or not valid(level, action):
            continue
        outcomes.append(domain.playout(level, action, ending=Ending.SETTLED).solved)
        if until_solved and outcomes[-1]:
            break
    return outcomes


def random_attempts(domain, level, rng: random.Random) -> dict:
    """PHYRE's random agent on one task: up to AGENT_ATTEMPTS valid actions drawn from `rng`,
    each played; the fraction that solve it, and the task's AUCCESS (the evaluation's
    accidental solvability)."""
    drawn = domain.actions
    outcomes = attempts(domain, level, iter(lambda: drawn.random_action(level, rng), None))
    if not outcomes:
        return {"accidental": None, "agent_plays": 0}
    first = next((k + 1 for k, solved in enumerate(outcomes) if solved), None)
    return {
        "accidental": round(sum(outcomes) / len(outcomes), 5),
        "agent_plays": len(outcomes),
        "auccess": round(auccess(first), 5),
    }


def first_solved(domain, level, seen: Observation, agent: Callable) -> int | None:
    """The valid attempt (1-based) at which `agent`'s actions first solve the task, if any
    (`attempts`, PHYRE's counting); the agent's own failures are its own."""

    def actions():
        with calling(f"on task {seen.task_id}"):
            drawn = iter(agent(seen))
        while True:
            with calling(f"on task {seen.task_id}"):
                action = next(drawn, STOP)
            if action is STOP:
                return
            yield from_unit(action)

    outcomes = attempts(domain, level, actions(), until_solved=True)
    return len(outcomes) if outcomes and outcomes[-1] else None


def score(domain, folder: Path, agent: Callable, setup: str, folds: Iterable[int], split: str) -> dict:
    """`agent`'s AUCCESS on `split` of each fold of `setup` of the dataset in `folder`: per
    fold, its mean and per template; and the mean over folds."""
    from physc.serialize import from_data

    if split not in SPLITS:
        raise ValueError(f"no split '{split}' (PHYRE's: {', '.join(SPLITS)})")
    seen = observations(folder)
    files = {row["task_id"]: row["task"] for row in _rows(folder)}
    classes = {c.__name__: c for c in domain.files.level_classes}
    setups = json.loads((folder / "phyre" / "folds.json").read_text())
    if setup not in setups:
        raise DomainError(
            "E0703",
            f"the dataset has no evaluation setup '{setup}' (its folds.json: {', '.join(setups)})",
            help="name one of them with --setup; PHYRE's setups are per action tier",
        )
    split_of = setups[setup]
    levels: dict = {}  # a task's level, read once though the folds share tasks

    def level_of(task_id: str):
        if task_id not in levels:
            levels[task_id] = from_data(json.loads((folder / files[task_id]).read_text())["level"], classes)
        return levels[task_id]

    results = {}
    for fold in folds:
        parts = split_of[str(fold)]
        trained = parts["train"] + (parts["dev"] if split == "test" else [])
        fit = getattr(agent, "fit", None)
        if fit is not None:
            with calling("in fit"):
                fit([seen[t] for t in trained])
        scores = {}
        for task_id in parts[split]:
            scores[task_id] = auccess(first_solved(domain, level_of(task_id), seen[task_id], agent))
        per_template: dict[str, list[float]] = {}
        per_tier: dict[str, list[float]] = {}
        for task_id, value in scores.items():
            per_template.setdefault(task_id[:5], []).append(value)
            per_tier.setdefault(seen[task_id].task.get("tier", "BALL"), []).append(value)
        results[str(fold)] = {
            "tasks": len(scores),
            "auccess": round(statistics.mean(scores.values()), 5) if scores else None,
            "tiers": {t: round(statistics.mean(v), 5) for t, v in sorted(per_tier.items())},
            "templates": {t: round(statistics.mean(v), 5) for t, v in sorted(per_template.items())},
        }
    means = [r["auccess"] for r in results.values() if r["auccess"] is not None]
    return {
        "setup": setup,
        "split": split,
        "folds": results,
        "auccess": round(statistics.mean(means), 5) if means else None,
    }


def _rows(folder: Path) -> list[dict]:
    import pyarrow.parquet as pq

    return pq.read_table(folder / "phyre" / "tasks.parquet", columns=["task_id", "task"]).to_pylist()
