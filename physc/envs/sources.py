"""The tasks an environment or an ActionSimulator plays: from a task, a task file, a dataset
folder (`physc generate`'s), or a list of these, each with an id."""

from __future__ import annotations

import os
from pathlib import Path

from physc.api.errors import FileError
from physc.compiler.task import Task


def task_id(task: Task) -> str:
    """A task's id: its scenario and seed, as a dataset names its task file."""
    return f"{task.scenario}/{task.seed}"


def task_ids(tasks: list[Task]) -> list[str]:
    """Each task's id, made unique: a scenario and seed met again (two datasets of one
    scenario, made with other settings) is `SCENARIO/SEED~2`, `~3`, … in order."""
    seen: dict[str, int] = {}
    ids = []
    for task in tasks:
        base = task_id(task)
        seen[base] = seen.get(base, 0) + 1
        ids.append(base if seen[base] == 1 else f"{base}~{seen[base]}")
    return ids


def gather(source) -> list[Task]:
    """Every task of `source`, in order (FileError for a path that is neither a task file nor a
    dataset; ValueError for no task at all)."""
    from physc.api.datasets import load_dataset
    from physc.api.tasks import load_task

    if isinstance(source, Task):
        return [source]
    if isinstance(source, (str, os.PathLike)):
        path = Path(source)
        if path.is_dir():
            return list(load_dataset(path).tasks())
        return [load_task(path)]
    if isinstance(source, (list, tuple)):
        tasks = [task for item in source for task in gather(item)]
        if not tasks:
            raise ValueError("no tasks to play")
        return tasks
    raise TypeError(f"tasks are a Task, a task file, a dataset folder or a list of them, not a {type(source).__name__}")


def of_domain(tasks: list[Task], domain: str) -> list[Task]:
    """The tasks, checked to be of `domain` and at least one."""
    if not tasks:
        raise FileError("no tasks to play (a dataset with no task made?)")
    others = sorted({t.domain for t in tasks} - {domain})
    if others:
        raise ValueError(f"these are tasks of the domain {', '.join(others)}, not of {domain}")
    return tasks
