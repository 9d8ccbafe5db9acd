"""A PHYRE-like dataset as PHYRE's own benchmark: what `physc generate` writes under `phyre/`.

* `tasks50.bin.lzma`: the tasks as PHYRE's `TaskCollection` (phyre_format.py), which PHYRE's
  loader reads as it is, without their `solutions` (PHYRE's never carry them);
* `observations.npy`: each task's first observation, PHYRE's 256 × 256 picture of colour
  indices (observation.py), stacked in task id order (uint8, N × 256 × 256);
* `tasks.parquet`: one row per task, in task id order: `task_id`, `template`, `instance`, the
  `scenario` and `seed` it came from, its `level` and `task` files, its `tier`, the intended
  `action` in PHYRE's [0, 1]³ (BALL) or [0, 1]⁶ (TWO_BALLS), the `description`, and `features` (PHYRE's 14
  numbers per object);
* `folds.json`: PHYRE's folds 0-9 of the cross- and within-template setups (folds.py).

A scenario is a template, numbered in the order the dataset names them from physc's own
range (50000, 50001, …: phyre_format.FIRST_TEMPLATE); its generated tasks are its instances,
numbered in seed order (000, 001, …), as PHYRE numbers the parameter sets of a template that
were not skipped.
"""

from __future__ import annotations

import io
import json

import numpy as np

from physc.domains.base import DomainError
from physc_phyre import folds, observation, phyre_format

FOLDER = "phyre"


def identified(tasks: list[tuple[dict, str]]) -> list[tuple[str, dict, dict]]:
    """(task id, manifest row, task structure with its `taskId`) of every task, by task id."""
    templates: dict[str, int] = {}
    for row, _ in tasks:
        templates.setdefault(row["scenario"], len(templates))
    if len(templates) > phyre_format.TEMPLATES:
        raise DomainError(
            "E0703",
            f"the dataset has {len(templates)} scenarios, but physc's range of PHYRE templates holds "
            f"{phyre_format.TEMPLATES}",
            help="generate fewer scenarios into one dataset",
        )
    out = []
    for scenario, template in templates.items():
        mine = sorted(((row, text) for row, text in tasks if row["scenario"] == scenario), key=lambda t: t[0]["seed"])
        if len(mine) > phyre_format.INSTANCES:
            raise DomainError(
                "E0703",
                f"scenario '{scenario}' has {len(mine)} tasks, but a PHYRE template holds {phyre_format.INSTANCES} "
                "at most (its instance ids have three digits)",
                help="generate fewer --tasks per scenario",
            )
        for instance, (row, text) in enumerate(mine):
            task = json.loads(text)
            task.pop("physc", None)
            task["taskId"] = phyre_format.task_id(phyre_format.FIRST_TEMPLATE + template, instance)
            out.append((task["taskId"], row, task))
    return sorted(out, key=lambda t: t[0])


def _npy(array: np.ndarray) -> bytes:
    buffer = io.BytesIO()
    np.save(buffer, array, allow_pickle=False)
    return buffer.getvalue()


def _parquet(entries) -> bytes:
    import pyarrow as pa
    import pyarrow.parquet as pq

    feature = pa.list_(pa.float32(), observation.FEATURES)
    columns = {
        "task_id": pa.array([t for t, _, _ in entries], pa.string()),
        "template": pa.array([t.split(":")[0] for t, _, _ in entries], pa.string()),
        "instance": pa.array([t.split(":")[1] for t, _, _ in entries], pa.string()),
        "scenario": pa.array([row["scenario"] for _, row, _ in entries], pa.string()),
        "seed": pa.array([row["seed"] for _, row, _ in entries], pa.int64()),
        "level": pa.array([row["level"] for _, row, _ in entries], pa.string()),
        "task": pa.array([row["task"] for _, row, _ in entries], pa.string()),
        "tier": pa.array([task["tier"] for _, _, task in entries], pa.string()),
        "action": pa.array([_action(task) for _, _, task in entries], pa.list_(pa.float64())),
        "description": pa.array([task.get("description") for _, _, task in entries], pa.string()),
        "features": pa.array([observation.features(task).tolist() for _, _, task in entries], pa.list_(feature)),
    }
    buffer = io.BytesIO()
    pq.write_table(pa.table(columns), buffer)
    return buffer.getvalue()


def _action(task: dict) -> list[float] | None:
    """The intended action in PHYRE's [0, 1]³, or [0, 1]⁶ in the two-ball tier (the task's
    first solution's balls)."""
    from physc_phyre.level import BallAction

    solutions = task.get("solutions") or ()
    if not solutions:
        return None
    balls = solutions[0].get("balls", ())
    return [
        v for ball in balls for v in BallAction(ball["position"]["x"], ball["position"]["y"], ball["radius"]).unit()
    ] or None


def benchmark_files(tasks: list[tuple[dict, str]]) -> dict[str, bytes]:
    """The files of `phyre/` (module docstring) for the generated tasks."""
    entries = identified(tasks)
    files: dict[str, bytes] = {}
    by_file: dict[str, list[dict]] = {}
    for task_id, _, task in entries:
        # PHYRE's tasks never carry their solutions: an agent that reads the task must not
        # read the answer. The intended action stays in physc's files and tasks.parquet.
        shown = {k: v for k, v in task.items() if k != "solutions"}
        by_file.setdefault(phyre_format.collection_file(task_id), []).append(shown)
    for name, collection in by_file.items():
        files[f"{FOLDER}/{name}"] = phyre_format.collection_bytes(collection)
    files[f"{FOLDER}/observations.npy"] = _npy(np.stack([observation.raster(task) for _, _, task in entries]))
    files[f"{FOLDER}/tasks.parquet"] = _parquet(entries)
    tiers = {t: task["tier"] for t, _, task in entries}
    files[f"{FOLDER}/folds.json"] = (json.dumps(folds.folds(list(tiers), tiers=tiers), indent=1) + "\n").encode()
    return files
