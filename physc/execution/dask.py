"""Jobs on a Dask cluster: an existing one (`--scheduler`) or one started here (`--dask-workers`).

Dask's scheduler hands the jobs to the workers and runs a job again when its worker dies (up to
Dask's `distributed.scheduler.allowed-failures`, 3 by default; then the run stops with an error).
Results come back here as their futures complete. physc's time budgets are kept per process
(physc.budget), so a worker process runs one job at a time: workers started here have one thread,
and `run_job` holds a lock while it runs, so a worker started with more threads does no harm.
"""

from __future__ import annotations

import importlib
import logging
import threading
from collections.abc import Callable, Iterable
from typing import Any, cast

from physc import budget
from physc.execution import Executor, ExecutorError, J, Keep, R

CONNECT_SECONDS = 5  # how long to try to reach a scheduler before giving up
WORKER_WAIT = 60.0  # seconds to wait for the first worker of a scheduler that has none
# Settings of a cluster started here: physc's jobs are seconds of pure Python each, so the workers'
# sampling profiler and their frequent event-loop ticks and system checks only take time from them.
LOCAL_SETTINGS = {
    "distributed.worker.profile.enabled": False,
    "distributed.admin.tick.interval": "1s",
    "distributed.admin.system-monitor.interval": "5s",
}
_one_at_a_time = threading.Lock()


def _dashboard() -> str | None:
    """Where a cluster started here serves its dashboard: a free port when bokeh (the `dask`
    extra) is installed, else none (Dask would serve a placeholder page)."""
    try:
        importlib.import_module("bokeh")
    except ImportError:
        return None
    return "127.0.0.1:0"


def physc_code() -> str:
    """The fingerprint of the physc source a process runs (what a worker is asked on connecting)."""
    from physc.fingerprint import code_fingerprint

    return code_fingerprint("")


def run_job(function, job):
    """What a worker runs: the job, alone in its process."""
    with _one_at_a_time:
        return function(job)


class DaskCluster(Executor):
    """A Dask client: connected to `scheduler` (an address such as tcp://host:8786), or to a
    LocalCluster of `workers` single-threaded worker processes started here."""

    name = "Dask"

    def __init__(self, scheduler: str | None = None, workers: int | None = None):
        try:
            import dask.config
            from distributed import Client, LocalCluster
        except ImportError as error:
            raise ExecutorError(
                f"--scheduler and --dask-workers need Dask ({error.name} is missing):"
                " pip install -e '.[dask]' in physc's checkout"
            ) from error
        self.cluster = None
        self.address = scheduler
        if scheduler is not None:
            try:
                self.client = Client(scheduler, timeout=CONNECT_SECONDS)
            except (OSError, TimeoutError, ValueError) as error:
                raise ExecutorError(f"cannot reach the Dask scheduler at {scheduler}: {error}") from error
            self.workers = len(self.client.scheduler_info().get("workers", {})) or self._first_worker(scheduler)
            self._same_code(scheduler)
        else:
            self.workers = max(1, workers or 1)
            # dashboard_address None: no dashboard (as distributed documents it; its signature is unannotated)
            dashboard: dict[str, Any] = {"dashboard_address": _dashboard()}
            with dask.config.set(LOCAL_SETTINGS):  # the workers are handed the settings when they start
                self.cluster = LocalCluster(
                    n_workers=self.workers,
                    threads_per_worker=1,
                    processes=True,
                    silence_logs=logging.ERROR,
                    **dashboard,
                )
            self.client = Client(self.cluster)

    def _first_worker(self, scheduler: str) -> int:
        """A scheduler with no workers: say so, wait WORKER_WAIT s for one, else stop."""
        import sys

        print(
            f"physc: the Dask scheduler at {scheduler} has no workers; waiting up to {WORKER_WAIT:g} s for one"
            f" (dask worker {scheduler})",
            file=sys.stderr,
        )
        try:
            self.client.wait_for_workers(1, timeout=WORKER_WAIT)
        except TimeoutError:
            self.client.close()
            raise ExecutorError(
                f"the Dask scheduler at {scheduler} has no workers (none joined in {WORKER_WAIT:g} s):"
                f" start some with `dask worker {scheduler}`"
            ) from None
        except BaseException:  # Ctrl-C while waiting, a lost connection: the client goes too
            self.client.close()
            raise
        return len(self.client.scheduler_info().get("workers", {}))

    def _same_code(self, scheduler: str) -> None:
        """Refuse workers that run other physc code than this process: their tasks would differ
        from what the manifest's code fingerprint says."""
        try:
            # a synchronous client: {worker address: what it returned}
            theirs = cast("dict[str, str]", self.client.run(physc_code))
        except Exception as error:  # a worker that cannot even import physc
            self.client.close()
            raise ExecutorError(
                f"the workers of {scheduler} cannot run physc ({type(error).__name__}: {error});"
                " install it on every machine"
            ) from None
        mine = physc_code()
        others = sorted(worker for worker, code in theirs.items() if code != mine)
        if others:
            self.client.close()
            raise ExecutorError(
                f"{len(others)} of the workers of {scheduler} ({', '.join(others[:3])}) run other physc code"
                " than this machine: "
                "install the same physc (and domain plugins) on every machine"
            )

    def describe(self) -> str:
        where = f"the Dask cluster at {self.address}" if self.address else "a local Dask cluster"
        link = self.client.dashboard_link if self.cluster is not None and self.cluster.dashboard_link else None
        return f"{where} ({self.workers} worker{'s' if self.workers != 1 else ''}" + (
            f"; dashboard {link})" if link else ")"
        )

    def map(self, function: Callable[[J], R], jobs: Iterable[J], keep: Keep[R]) -> None:
        from distributed import KilledWorker, wait

        futures = [self.client.submit(run_job, function, job, pure=False) for job in jobs]
        pending = set(futures)
        try:
            while pending:
                try:
                    # a synchronous client: the futures (done, not done), not a coroutine
                    done, pending = cast("tuple[set, set]", wait(pending, timeout=0.2, return_when="FIRST_COMPLETED"))
                except TimeoutError:  # none completed meanwhile
                    done = set()
                for future in done:
                    try:
                        result = future.result()
                    except KilledWorker as error:  # its workers died allowed-failures times
                        raise ExecutorError(f"Dask lost the workers running a job too often: {error}") from None
                    keep(result)
                    future.release()
                budget.check()
        except BaseException:
            self.client.cancel(list(pending))
            raise

    def close(self) -> None:
        try:
            self.client.close()
        finally:
            if self.cluster is not None:
                self.cluster.close()
