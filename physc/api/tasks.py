"""Tasks from Python: read and write task files and level files, and find the
domain, world and engine a task was made in.

A task file is what `physc compile --task` and `physc generate` write: the task
(physc.compiler.task.Task) as JSON, with its scenario as written, its level and its solution.
`physc verify`, `simulate --task` and the environments read task files through `read_task`.
"""

from __future__ import annotations

import json
import os

from physc.api.errors import FileError
from physc.compiler.task import Task

__all__ = ["domain_of", "level_text", "load_task", "save_level", "save_task", "scenario_of"]

MAX_TASK_BYTES = 50_000_000
FIELDS = ("domain", "scenario", "source", "level", "solution")


def read_task(path: str | os.PathLike) -> dict:
    """A task file's JSON, checked to be one (FileError otherwise); '-' reads standard input."""
    from physc.files import read_input

    path = os.fspath(path)
    data, problem = read_input(path, "the task file", limit=MAX_TASK_BYTES + 1)
    if data is None:
        raise FileError(problem)
    if len(data) > MAX_TASK_BYTES:
        raise FileError(f"{path}: the task file is larger than physc reads ({MAX_TASK_BYTES:,} bytes)")
    try:
        task = json.loads(data.decode("utf-8-sig"))
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        raise FileError(f"{path} is not a task file (JSON): {error}") from None
    except RecursionError:
        raise FileError(f"{path} is not a task file: its JSON is nested too deeply") from None
    if not isinstance(task, dict) or task.get("node") != "Task" or not all(field in task for field in FIELDS):
        raise FileError(f"{path} is not a task file: write one with `physc compile FILE --task {path}`")
    return task


def task_parts(task: dict, path: str):
    """(domain, scenario IR, level, the level as the domain writes it, solution) of a task
    file's JSON (FileError for a part that cannot be read)."""
    from physc.domains import load_domain
    from physc.domains.base import DomainError, require, solution_classes
    from physc.domains.words import INSTALLED
    from physc.dsl.frontend import analyze_text
    from physc.serialize import from_data

    try:
        domain = load_domain(str(task["domain"]))
        require(domain, ("replay", "emit_level"), "reading a task file")
    except DomainError as error:
        raise FileError(f"{path}: {error.message}") from None
    if not domain.files.level_classes:
        raise FileError(
            f"{path}: the domain '{domain.name}' cannot read its levels back from a task file (it has no level_classes)"
        )
    analysis = analyze_text(f"{path} (source)", str(task["source"]), INSTALLED)
    scenario = next((s for s in analysis.scenarios if s.name == task["scenario"]), None)
    if scenario is None or any(d.is_error for d in analysis.diagnostics):
        raise FileError(f"{path}: its source does not hold a valid scenario '{task['scenario']}'")
    try:
        level = from_data(task["level"], {cls.__name__: cls for cls in domain.files.level_classes})
        if not isinstance(level, domain.files.level_classes[0]):
            raise ValueError(f"the level is not a {domain.files.level_classes[0].__name__}")
        kinds = solution_classes(domain)
        solution = _solution(from_data(task["solution"], kinds), tuple(kinds.values()))
        level_text = domain.files.emit_level(level)  # also checks that the level is one the domain can write
    except (TypeError, ValueError, AttributeError, KeyError, RecursionError) as error:
        raise FileError(f"{path}: its level or solution cannot be read: {error or type(error).__name__}") from None
    return domain, scenario, level, level_text, solution


def _solution(solution, kind: tuple[type, ...]):
    """The task file's solution, if it is one of the domain's classes `kind` (ValueError if not;
    each class checks its own fields when it is made)."""
    if not kind or not isinstance(solution, kind):
        raise ValueError(
            f"the solution is not a {' or a '.join(k.__name__ for k in kind) or 'record this domain reads'}"
        )
    return solution


def load_task(path: str | os.PathLike) -> Task:
    """The task of a task file (`physc compile --task`, or a dataset's `<scenario>/<seed>.json`).
    A dataset's task files leave out the seconds (the manifest has them): they read as {}."""
    import attrs

    data = read_task(path)
    _, _, level, _, solution = task_parts(data, os.fspath(path))
    fields = {f.name for f in attrs.fields(Task)}
    unknown = sorted(set(data) - fields - {"node"})
    if unknown:
        raise FileError(
            f"{os.fspath(path)}: a task has no field {', '.join(map(repr, unknown))} (a file of another physc version?)"
        )
    values = {k: v for k, v in data.items() if k in fields}
    values.update(level=level, solution=solution, seconds=data.get("seconds") or {})
    for name in ("robustness", "repairs", "obstacles", "distractors"):
        if name in values and isinstance(values[name], list):
            values[name] = tuple(values[name])
    try:
        return Task(**values)
    except TypeError as error:
        raise FileError(f"{os.fspath(path)}: not a whole task: {error}") from None


def domain_of(task: Task, world: str | None = None, backend: str | None = None):
    """The domain of `task`, simulating in the world and engine the task was made in (or in
    `world`, `backend` where given)."""
    from physc.domains import bound, load_domain

    return bound(load_domain(task.domain), world or task.world or None, backend or task.backend or None)


def scenario_of(task: Task):
    """The checked scenario (IR) the task was made of, read from its source."""
    from physc.domains.words import INSTALLED
    from physc.dsl.frontend import scenario_in

    return scenario_in(f"{task.scenario} (source)", task.source, task.scenario, INSTALLED)


def level_text(task: Task) -> str:
    """The task's level as its domain's level file (angrybirds: Science Birds XML)."""
    return domain_of(task).files.emit_level(task.level)


def save_task(task: Task, path: str | os.PathLike) -> None:
    """Write the task file (`physc compile --task`'s bytes), whole or not at all."""
    from physc.files import write_atomic
    from physc.serialize import to_data

    write_atomic(path, json.dumps(to_data(task), indent=2, ensure_ascii=False) + "\n")


def save_level(task: Task, path: str | os.PathLike) -> None:
    """Write the task's level file (`physc compile -o`), whole or not at all."""
    from physc.files import write_atomic

    write_atomic(path, level_text(task))
