"""Jobs in this process, or in a pool of local processes."""

from __future__ import annotations

import multiprocessing
from collections.abc import Callable, Iterable
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool

from physc import budget
from physc.execution import Executor, ExecutorError, J, Keep, R

RUNS = 3  # how often a job may be under way in a pool that breaks before the run stops


class LocalProcesses(Executor):
    """`workers` local processes (1: this process, one job after another)."""

    name = "local"

    def __init__(self, workers: int = 1):
        self.workers = max(1, workers)

    def map(self, function: Callable[[J], R], jobs: Iterable[J], keep: Keep[R]) -> None:
        jobs = list(jobs)
        if self.workers == 1 or len(jobs) <= 1:
            for job in jobs:
                keep(function(job))
                budget.check()
            return
        left = dict.fromkeys(range(len(jobs)))  # unfinished, in the order submitted
        breaks = [0] * len(jobs)  # how often a pool broke while the job was under way
        while left:
            running: set[int] = set()
            try:
                self._pool(function, jobs, left, running, keep)
            except BrokenProcessPool:
                # A worker died (killed, out of memory). Its pool's unfinished jobs run again in a
                # new one; the jobs that were under way (seen running, else the first in line) are
                # suspects, and one that was under way in RUNS broken pools stops the run.
                suspects = [i for i in left if i in running] or list(left)[: self.workers]
                for index in suspects:
                    breaks[index] += 1
                lost = [i for i in suspects if breaks[i] >= RUNS]
                if lost:
                    job = jobs[lost[0]]
                    raise ExecutorError(
                        f"a worker process died {RUNS} times while running the job {getattr(job, 'key', job)}"
                    ) from None

    def _pool(
        self, function: Callable[[J], R], jobs: list[J], left: dict[int, None], running: set[int], keep: Keep[R]
    ) -> None:
        """Run the jobs `left` in one pool, removing each from `left` once kept and noting in
        `running` those seen under way. Workers ignore Ctrl-C; on an interrupt (or any error)
        here they are ended at once: only this process writes, so nothing is left half-written."""
        pool = ProcessPoolExecutor(max_workers=min(self.workers, len(left)), initializer=budget.ignore_in_workers)
        try:
            pending = {pool.submit(function, jobs[index]): index for index in left}
            while pending:
                done, _ = wait(pending, timeout=0.2, return_when=FIRST_COMPLETED)
                running.update(index for future, index in pending.items() if future.running())
                for future in done:
                    index = pending.pop(future)
                    keep(future.result())
                    del left[index]
                budget.check()
        except BaseException:
            for process in multiprocessing.active_children():
                process.terminate()
            pool.shutdown(wait=True, cancel_futures=True)
            raise
        pool.shutdown()
