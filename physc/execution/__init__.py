"""Where the jobs of `physc generate` and `physc eval` run: local processes or a Dask cluster.

An `Executor` runs one function over many jobs and hands each result back to this process as it
completes, in any order. Only this process writes files, so what a run keeps never depends on where
a job ran, and a killed run loses nothing that was handed back. Results depend only on their job,
so the same jobs give the same results on every executor and with any number of workers.

- `LocalProcesses(n)`: this machine; one job at a time in this process when n is 1, else a pool
  of n processes (a pool that breaks because a worker died is started again, and its unfinished
  jobs run again).
- `DaskCluster(...)`: an existing Dask cluster (`--scheduler tcp://HOST:8786`) or one started on
  this machine (`--dask-workers N`); a job whose worker dies is run again by Dask. Needs the `dask`
  extra.
"""

from __future__ import annotations

import abc
from collections.abc import Callable, Iterable
from typing import TypeVar

J = TypeVar("J")  # a job
R = TypeVar("R")  # its result
Keep = Callable[[R], None]  # called here with each job's result, as it completes


class ExecutorError(Exception):
    """An executor cannot be used (Dask not installed, a scheduler that cannot be reached), or
    lost a job's worker too often (a job that kills its process, say by running out of memory).
    The command says so and exits 2; what was kept before stays."""


class Executor(abc.ABC):
    """Runs `function(job)` for each job somewhere, calling `keep(result)` here as each completes.

    `function` and the jobs must be picklable (a module-level function, attrs jobs). Subclasses
    write `map`; `close` ends what the executor started. Use it as a context manager."""

    name: str = "executor"
    workers: int = 1

    @abc.abstractmethod
    def map(self, function: Callable[[J], R], jobs: Iterable[J], keep: Keep[R]) -> None:
        """Run every job; return when all have been kept. Ctrl-C (and the time budget's
        stopping points, physc.budget) stop it between results."""

    def close(self) -> None:
        """End the workers this executor started (nothing by default)."""
        return None

    def describe(self) -> str:
        """Where jobs run, in words, for progress lines and reports."""
        return f"{self.workers} {self.name} worker{'s' if self.workers != 1 else ''}"

    def __enter__(self) -> Executor:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def executor_for(jobs: int = 1, scheduler: str | None = None, dask_workers: int | None = None) -> Executor:
    """The executor the command line asks for: `--scheduler` (an existing Dask cluster),
    `--dask-workers N` (a Dask cluster started here), else `--jobs N` local processes."""
    if scheduler is not None or dask_workers is not None:
        from physc.execution.dask import DaskCluster

        return DaskCluster(scheduler=scheduler, workers=dask_workers)
    from physc.execution.local import LocalProcesses

    return LocalProcesses(jobs)
