"""Jobs in this process, or in a pool of local processes."""

from __future__ import annotations

import multiprocessing
from concurrent.futures import FIRST_COMPLETED, ProcessPoolExecutor, wait
from concurrent.futures.process import BrokenProcessPool

from physc import budget
from physc.execution import Executor

RUNS = 3  # how often a job may be under way in a pool that breaks before the run stops


class LocalProcesses(Executor):
    """`workers` local processes (1: this process, one job after another)."""

    name = "local"

    def __init__(self, workers: int = 1):
        self.workers = max(1, workers)

    def map(self, function, jobs, keep) -> None:
        jobs = list(jobs)
        if self.workers == 1 or len(jobs) <= 1:
            for job in jobs:
                keep(function(job))
                budget.check()
            return
        runs = [0] * len(jobs)
        left = set(range(len(jobs)))
        while left:
            try:
                self._pool(function, jobs, left, runs, keep)
            except BrokenProcessPool:
                # A worker died (killed, out of memory): the jobs under way in that pool run again
                # in a new one, unless one of them has now been under way in RUNS broken pools.
                if any(runs[i] >= RUNS for i in left):
                    raise

    def _pool(self, function, jobs, left: set, runs: list, keep) -> None:
        """Run the jobs `left` in one pool, removing each from `left` once kept. Workers ignore
        Ctrl-C; on an interrupt (or any error) here they are ended at once: only this process
        writes, so nothing is left half-written."""
        pool = ProcessPoolExecutor(max_workers=min(self.workers, len(left)), initializer=budget.ignore_in_workers)
        try:
            pending = {}
            for index in sorted(left):
                runs[index] += 1
                pending[pool.submit(function, jobs[index])] = index
            while pending:
                done, _ = wait(pending, timeout=0.2, return_when=FIRST_COMPLETED)
                for future in done:
                    index = pending.pop(future)
                    keep(future.result())
                    left.discard(index)
                budget.check()
        except BaseException:
            for process in multiprocessing.active_children():
                process.terminate()
            pool.shutdown(wait=True, cancel_futures=True)
            raise
        pool.shutdown()
