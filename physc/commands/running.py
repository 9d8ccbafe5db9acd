"""What `physc generate` and `physc eval` share on the command line: where the jobs run
(`--jobs`, `--scheduler`, `--dask-workers`) and the progress bar fed as jobs complete."""

from __future__ import annotations

import shlex

from physc.commands import arguments
from physc.commands.common import UsageError
from physc.execution import Executor, ExecutorError, executor_for


def add_executor(parser) -> None:
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--jobs", type=arguments.jobs, default=1, metavar="N", help="local processes (default 1); results do not depend on it")
    where.add_argument("--scheduler", metavar="ADDRESS", help="run on an existing Dask cluster, e.g. tcp://host:8786 (needs physc[dask])")
    where.add_argument("--dask-workers", type=arguments.jobs, metavar="N", help="start a Dask cluster of N worker processes here (needs physc[dask])")


def executor_from(args) -> Executor:
    """The executor the options ask for; a usage error when it cannot be had."""
    try:
        return executor_for(args.jobs, args.scheduler, args.dask_workers)
    except ExecutorError as error:
        raise UsageError(str(error)) from error


# Options that change where and how visibly a run goes, not what it makes: left out of the command
# a dataset's README records, so that the README is the same on any executor.
_WHERE = {"--jobs": 1, "--scheduler": 1, "--dask-workers": 1, "--color": 1, "-q": 0, "--quiet": 0, "--traceback": 0}


def reproducing_command(command: str, argv: list[str]) -> str:
    """`physc COMMAND ARGS…` as run (`argv`: the arguments after the command), less the options
    of _WHERE."""
    kept, skip = [], 0
    for argument in argv:
        if skip:
            skip -= 1
            continue
        name = argument.split("=", 1)[0]
        if name in _WHERE:
            skip = _WHERE[name] if "=" not in argument else 0
            continue
        kept.append(argument)
    return " ".join(["physc", command] + [shlex.quote(a) for a in kept])


class Progress:
    """A rich progress bar on stderr (plain lines when stderr is not a terminal), advanced by each
    result as it comes back; `describe(result)` says what it was."""

    def __init__(self, label: str, quiet: bool, describe):
        self.label = label
        self.quiet = quiet
        self.describe = describe
        self.bar = None

    def start(self, total: int, done: int, where: str = "") -> None:
        if self.quiet:
            return
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress as Bar, TextColumn, TimeElapsedColumn, TimeRemainingColumn

        console = Console(stderr=True)
        self.bar = Bar(
            TextColumn(f"[bold]{self.label}"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(), TimeRemainingColumn(),
            TextColumn("{task.description}"), console=console, transient=False,
        )
        self.bar.start()
        self.task = self.bar.add_task("", total=total, completed=done)
        if where:
            console.print(f"running on {where}")
        if done:
            console.print(f"resuming: {done} of {total} tasks already done")

    def advance(self, result) -> None:
        if self.bar:
            self.bar.update(self.task, advance=1, description=self.describe(result))

    def stop(self) -> None:
        if self.bar:
            self.bar.stop()
