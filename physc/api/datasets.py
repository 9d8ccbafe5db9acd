"""Datasets and evaluations from Python: what `physc generate` and `physc eval` do.

`generate` makes a dataset folder exactly as `physc generate` does (a task's level, task file
and picture per scenario and seed, the manifest in JSON Lines and Parquet, a README that
Hugging Face reads, and the domain's own benchmark files), resuming a folder already there;
`load_dataset` reads one back. `evaluate` runs `physc eval`'s measurements and returns its
records and summary.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, TypedDict

import attrs

from physc.api.errors import FileError, ScenarioError
from physc.compiler.task import Task
from physc.driver.run_settings import RunSettings, overridden

if TYPE_CHECKING:
    from physc.driver.job import Job

__all__ = ["Dataset", "Evaluation", "evaluate", "generate", "load_dataset"]


@attrs.frozen
class Dataset:
    """A dataset folder made by `physc generate`: its manifest's rows (one per scenario and
    seed, with `outcome` "ok", "fallback" or "no task"), in the manifest's order."""

    folder: Path
    rows: tuple[dict, ...] = attrs.field(repr=False)

    def __len__(self) -> int:
        return len(self.rows)

    def __iter__(self) -> Iterator[dict]:
        return iter(self.rows)

    @property
    def made(self) -> tuple[dict, ...]:
        """The rows of the tasks that were made (a level and a task file)."""
        return tuple(row for row in self.rows if row.get("task"))

    def task_paths(self) -> list[Path]:
        """The task files of the tasks made, in the manifest's order."""
        return [self.folder / row["task"] for row in self.made]

    def tasks(self) -> Iterator[Task]:
        """The tasks made, read from their task files (physc.api.tasks.load_task)."""
        from physc.api.tasks import load_task

        for path in self.task_paths():
            yield load_task(path)


def load_dataset(folder: str | os.PathLike) -> Dataset:
    """The dataset in `folder` (FileError when it holds no manifest)."""
    from physc.dataset.manifest import JSONL
    from physc.files import read_json_lines

    root = Path(folder)
    path = root / JSONL
    if not path.is_file():
        raise FileError(f"{root} is not a dataset: it has no {JSONL} (make one with physc generate)")
    rows = [row for row in read_json_lines(path) if isinstance(row, dict) and "scenario" in row]
    return Dataset(root, tuple(rows))


def _jobs(
    files: str | os.PathLike | Sequence[str | os.PathLike],
    tasks: int,
    seed: int,
    scenarios: Sequence[str] | None,
    needs: tuple[str, ...],
    settings: RunSettings,
    **fields: object,
) -> list[Job]:
    """The jobs of `files` made under the run's `settings`, with the jobs' other `fields`
    (physc.driver.job.Job: where they are made, what else they do); ScenarioError for files with
    errors, or a scenario not there; physc.domains.base.MissingCapability for a domain that
    lacks a hook in `needs`, ValueError for a `min_robustness` the domain cannot count."""
    from physc.api.compiling import check_min_robustness
    from physc.domains import load_domain
    from physc.domains.base import require
    from physc.driver.job import jobs_for

    paths = [os.fspath(f) for f in ([files] if isinstance(files, (str, os.PathLike)) else files)]
    jobs, problems = jobs_for(paths, tasks, seed, settings=settings, **fields)
    if problems:
        path, analysis, found = problems[0]
        raise ScenarioError(tuple(found), analysis.source if analysis else None, path)
    if scenarios:
        missing = sorted(set(scenarios) - {job.scenario for job in jobs})
        if missing:
            raise ScenarioError((), None, ", ".join(paths), f"no scenario named {', '.join(missing)} in the files")
        jobs = [job for job in jobs if job.scenario in scenarios]
    for name in sorted({job.domain for job in jobs}):
        domain = load_domain(name)
        require(domain, needs, "this run")
        check_min_robustness(settings.min_robustness, domain)
    return jobs


def clashes(jobs: Iterable[Job]) -> str | None:
    """What stops the jobs from making one dataset, in words, or None: a dataset names its
    folders after scenarios, so two files may not have a scenario of one name."""
    files_of: dict[str, set] = {}
    for job in jobs:
        files_of.setdefault(job.scenario, set()).add(job.path)
    both = sorted(name for name, paths in files_of.items() if len(paths) > 1)
    if not both:
        return None
    where = ", ".join(f"'{name}' ({' and '.join(sorted(files_of[name]))})" for name in both)
    return (
        f"a dataset names its folders after scenarios, and two files have a scenario named {where};"
        " pick one with -s or rename"
    )


class JobSettings(TypedDict):
    """The fields of a job (physc.driver.job.Job) that generation's options set."""

    world: str
    backend: str
    settings: RunSettings


def job_settings(world: str | None, backend: str | None, settings: RunSettings) -> JobSettings:
    """The fields of a job (physc.driver.job.Job) that generation's options set: where it
    is made (None: the default world, box2d) and the run's settings."""
    from physc.backends import DEFAULT_BACKEND

    return JobSettings(world=world or "", backend=backend or DEFAULT_BACKEND, settings=settings)


def generation_needs(png: bool, verify_backend: str | None) -> tuple[str, ...]:
    """What a domain must be able to do for a dataset of its tasks (with pictures, verified in
    a second engine)."""
    from physc.driver.stages import NEEDS

    return NEEDS["level"] + (("picture",) if png else ()) + (("replay",) if verify_backend else ())


def evaluation_needs() -> tuple[str, ...]:
    """What a domain must be able to do for its tasks to be measured: generation, the replays
    and the measurements."""
    from physc.driver.stages import NEEDS

    return NEEDS["task"] + ("replay", "stability")


def generate(
    files: str | os.PathLike | Sequence[str | os.PathLike],
    out: str | os.PathLike,
    *,
    tasks: int = 1,
    seed: int = 0,
    scenarios: Sequence[str] | None = None,
    jobs: int = 1,
    world: str | None = None,
    backend: str | None = None,
    settings: RunSettings | None = None,
    png: bool = False,
    accidental: bool = False,
    dask_workers: int | None = None,
    scheduler: str | None = None,
    wave: int | None = None,
    **overrides,
) -> Dataset:
    """`physc generate FILES --tasks N --out OUT`: `tasks` tasks (seeds `seed` …) of every
    scenario of `files` (or of `scenarios`), into the folder `out`: on `jobs` local processes,
    or on a Dask cluster of `dask_workers` started here, or on the one at `scheduler` (an
    address; `pip install -e '.[dask]'`); a scenario's tasks in waves of `wave` (None:
    physc.dataset.waves.WAVE; 0: each on its own), each learning from the waves before. The bytes
    written depend on the scenarios, seeds, settings and wave only, never on where they were
    made."""
    from physc.dataset.build import build
    from physc.dataset.waves import WAVE
    from physc.execution import executor_for

    settings = overridden(settings, "generate", **overrides)
    made = _jobs(
        files,
        tasks,
        seed,
        scenarios,
        generation_needs(png, settings.verify_backend),
        picture=png,
        accidental=accidental,
        **job_settings(world, backend, settings),
    )
    problem = clashes(made)
    if problem:
        raise ScenarioError((), None, ", ".join(sorted({job.path for job in made})), problem)
    with executor_for(jobs, scheduler, dask_workers) as executor:
        rows = build(made, Path(out), executor, command="physc.generate(…)", wave=WAVE if wave is None else wave)
    return Dataset(Path(out), tuple(rows))


@attrs.frozen
class Evaluation:
    """What `physc eval` measured: a record per scenario and seed, and the summary its report
    (results.md, .json, .csv in `folder`) is made of."""

    folder: Path
    records: tuple[dict, ...] = attrs.field(repr=False)
    summary: dict = attrs.field(repr=False)


def evaluate(
    files: str | os.PathLike | Sequence[str | os.PathLike],
    out: str | os.PathLike,
    *,
    tasks: int = 30,
    seed: int = 0,
    scenarios: Sequence[str] | None = None,
    jobs: int = 1,
    world: str | None = None,
    backend: str | None = None,
    settings: RunSettings | None = None,
    dask_workers: int | None = None,
    scheduler: str | None = None,
    **overrides,
) -> Evaluation:
    """`physc eval FILES --tasks N --out OUT`: generate and measure `tasks` tasks of every
    scenario (stability, intended and accidental solvability, fidelity, cost), resuming the
    records already in `out`, and write the report there; where the work runs as in
    `generate`."""
    import time

    from physc.evaluation.report import write
    from physc.evaluation.run import run
    from physc.execution import executor_for

    # the paper's evaluation skips the final validation
    settings = attrs.evolve(overridden(settings, "evaluate", **overrides), validate=False)
    made = _jobs(files, tasks, seed, scenarios, evaluation_needs(), **job_settings(world, backend, settings))
    started = time.perf_counter()
    with executor_for(jobs, scheduler, dask_workers) as executor:
        records = run(made, Path(out), executor)
    summary = write(records, Path(out), "physc.evaluate(…)", time.perf_counter() - started)
    return Evaluation(Path(out), tuple(records), summary)
