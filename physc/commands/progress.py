"""What a long command says while it works, on stderr: a progress bar on a terminal, plain
lines elsewhere (CI, nohup, a cluster's log), and a line every few seconds of one long task
whatever stage it is in.

- `Progress`: a batch of tasks (generate, eval), advanced by each result as it comes back.
- `Heartbeat`: one task (compile): a line every PROGRESS_EVERY seconds, saying what the work
  last reported (layouts tried, simulations, how far the best simulation got) or, before its
  first report, that the layout search is still going.
"""

from __future__ import annotations

import sys
import threading
import time

PROGRESS_EVERY = 5.0  # seconds between progress lines


class Progress:
    """A rich progress bar on stderr, or plain lines, one per result, when stderr is not a
    terminal; `describe(result)` says what each result was."""

    def __init__(self, label: str, quiet: bool, describe):
        self.label = label
        self.quiet = quiet
        self.describe = describe
        self.bar = None
        self.plain = False

    def start(self, total: int, done: int, where: str = "") -> None:
        if self.quiet:
            return
        from rich.console import Console

        console = Console(stderr=True)
        self.total, self.done, self.started = total, done, time.monotonic()
        if not console.is_terminal:  # a log: a line per result, written as it comes
            self.plain = True
            self._line(f"{total} tasks" + (f" on {where}" if where else ""))
            if done:
                self._line(f"resuming: {done} of {total} tasks already done")
            return
        from rich.progress import (
            BarColumn,
            MofNCompleteColumn,
            TextColumn,
            TimeElapsedColumn,
            TimeRemainingColumn,
        )
        from rich.progress import (
            Progress as Bar,
        )

        self.bar = Bar(
            TextColumn(f"[bold]{self.label}"),
            BarColumn(),
            MofNCompleteColumn(),
            TimeElapsedColumn(),
            TimeRemainingColumn(),
            TextColumn("{task.description}"),
            console=console,
            transient=False,
        )
        self.bar.start()
        self.task = self.bar.add_task("", total=total, completed=done)
        if where:
            console.print(f"running on {where}")
        if done:
            console.print(f"resuming: {done} of {total} tasks already done")

    def advance(self, result) -> None:
        if self.plain:
            self.done += 1
            self._line(f"{self.done}/{self.total}, {time.monotonic() - self.started:.0f} s: {self.describe(result)}")
        elif self.bar:
            self.bar.update(self.task, advance=1, description=self.describe(result))

    def stop(self) -> None:
        if self.bar:
            self.bar.stop()

    def _line(self, text: str) -> None:
        print(f"{self.label}: {text}", file=sys.stderr, flush=True)


class Heartbeat:
    """A line on stderr every `every` seconds while one task is made (a context manager); its
    generation reports through `update` (a layout loop's Progress)."""

    def __init__(self, prefix: str, every: float | None = None):
        self.prefix = prefix
        self.every = every if every is not None else PROGRESS_EVERY
        self.state = "the layout search is still going (no layout placed yet)"
        self._stopped = threading.Event()
        self._thread = threading.Thread(target=self._beat, name="physc-progress", daemon=True)

    def update(self, progress) -> None:
        self.state = (
            f"{progress.layouts} layouts tried, {progress.simulations} simulations; "
            f"best so far: {progress.best} of {progress.interactions} interactions in order"
        )

    def _beat(self) -> None:
        started = time.monotonic()
        while not self._stopped.wait(self.every):
            print(f"{self.prefix}: {time.monotonic() - started:.0f} s; {self.state}", file=sys.stderr, flush=True)

    def __enter__(self) -> Heartbeat:
        self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._stopped.set()
        self._thread.join()
