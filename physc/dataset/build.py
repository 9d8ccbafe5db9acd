"""Running a dataset: make the tasks not made yet on an executor, write each as it comes back.

Each task's files are written whole (physc.files.write_atomic), then its row is appended to the
manifest, so a run killed at any moment resumes where it stopped: a task whose row and files are
there, made with the same settings, is not made again; one without is made again, to the same
bytes. A scenario's tasks are made in waves, each learning from the waves before
(physc.dataset.waves). At the end the manifest (JSON Lines and Parquet) and the README are
written whole.
"""

from __future__ import annotations

from pathlib import Path

from physc import budget
from physc.dataset import manifest, readme, waves
from physc.dataset.worker import make, scenario_file
from physc.domains import load_domain
from physc.driver.job import Job
from physc.execution import Executor
from physc.files import OutputError, ensure_folder, write_atomic

README = "README.md"


def _finished(folder: Path, job: Job, row: dict | None) -> bool:
    """Whether the task's row was made with the job's settings and its files are all there."""
    if row is None or row.get("settings") != job.recorded:
        return False
    return all((folder / row[name]).is_file() for name in ("level", "task", "picture", "examples") if row.get(name))


def benchmark_files(folder: Path, rows: list[dict]) -> dict[str, bytes]:
    """Each domain's files in its target world's own format (its files' benchmark_files), from
    the tasks generated."""
    files: dict[str, bytes] = {}
    for name in dict.fromkeys(row["domain"] for row in rows):
        tasks = [
            (row, (folder / row["level"]).read_text(encoding="utf-8"))
            for row in rows
            if row["domain"] == name and row.get("level")
        ]
        if tasks:
            files.update(load_domain(name).files.benchmark_files(tasks))
    return files


def build(
    jobs: list[Job],
    folder: Path,
    executor: Executor,
    progress=None,
    command: str = "physc generate …",
    wave: int = waves.WAVE,
) -> list[dict]:
    """Make the dataset of `jobs` in `folder`, a scenario's tasks in waves of `wave` (each wave
    learning from those before: physc.dataset.waves; 0: each task on its own); every job's row,
    in the order of `jobs`."""
    folder = ensure_folder(folder)
    jobs = waves.assigned(jobs, wave)
    rows = manifest.read(folder)
    todo = [job for job in jobs if not _finished(folder, job, rows.get(job.key))]
    if rows:  # written whole first, so that a torn last line of a killed run cannot stay in the middle
        manifest.write_jsonl(folder, [rows[k] for k in sorted(rows)])
    for scenario, source in {
        job.scenario: job.source for job in jobs
    }.items():  # each scenario as written, beside its tasks
        ensure_folder(folder / scenario)
        copy = folder / scenario_file(scenario)
        if not copy.is_file() or copy.read_text(encoding="utf-8") != source:
            write_atomic(copy, source)
    if progress:
        progress.start(len(jobs), len(jobs) - len(todo), executor.describe())
    kept = 0
    path = folder / manifest.JSONL
    try:
        with path.open("a", encoding="utf-8") as out, budget.interruptible():

            def keep(result: dict) -> None:
                nonlocal kept
                for name, content in result["files"].items():
                    write_atomic(folder / name, content)
                row = result["row"]
                try:
                    out.write(manifest.line(row))
                    out.flush()
                except OSError as error:
                    raise OutputError(path, error) from None
                rows[manifest.key(row)] = row
                kept += 1
                if progress:
                    progress.advance(row)

            for group in waves.in_waves(todo, folder, rows):
                executor.map(make, group, keep)
    except OSError as error:  # opening the manifest
        raise OutputError(path, error) from None
    except OutputError as error:
        done = len(jobs) - len(todo) + kept
        error.args = (f"{error}; the {done} tasks finished so far are kept: run the same command again to go on",)
        raise
    finally:
        if progress:
            progress.stop()
    final = [rows[job.key] for job in jobs]
    manifest.write_jsonl(folder, final)
    manifest.write_parquet(folder, final)
    write_atomic(folder / README, readme.render(folder, jobs, final, command))
    for name, content in benchmark_files(folder, final).items():  # last: a domain may refuse (DomainError)
        ensure_folder((folder / name).parent)
        write_atomic(folder / name, content)
    return final
