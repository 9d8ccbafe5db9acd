"""What `physc generate` and `physc eval` share on the command line: where the jobs run
(`--jobs`, `--scheduler`, `--dask-workers`) and the progress bar fed as jobs complete."""

from __future__ import annotations

import shlex

from physc import diagnostics
from physc.commands import arguments
from physc.commands.common import UsageError, check_backends, check_min_robustness, reporter
from physc.execution import Executor, ExecutorError, executor_for
from physc.files import check_output


def add_executor(parser) -> None:
    where = parser.add_mutually_exclusive_group()
    where.add_argument(
        "--jobs",
        type=arguments.jobs,
        default=1,
        metavar="N",
        help="local processes (default 1); results do not depend on it",
    )
    where.add_argument(
        "--scheduler",
        metavar="ADDRESS",
        help="run on an existing Dask cluster, e.g. tcp://host:8786 (needs the dask extra: pip install -e '.[dask]')",
    )
    where.add_argument(
        "--dask-workers",
        type=arguments.jobs,
        metavar="N",
        help="start a Dask cluster of N worker processes here (needs the dask extra: pip install -e '.[dask]')",
    )


def check_batch(args) -> None:
    """What a batch command refuses before reading its files: unknown backends, seeds past the
    largest, an output folder that cannot be written."""
    check_backends(args)
    if args.seed + args.tasks - 1 > arguments.MAX_SEED:
        raise UsageError(f"--seed {args.seed} with --tasks {args.tasks} runs past the largest seed, 2**63 - 1")
    check_output(args.out, folder=True)


def selected_jobs(args, jobs: list, problems: list) -> tuple[list, int | None]:
    """The jobs of the scenarios `-s` names (all by default); or, for files with errors, their
    diagnostics reported and the exit status."""
    if problems:
        report = reporter(args)
        for path, analysis, errors in problems:
            report(path, analysis.source, errors)
        return [], max(diagnostics.exit_status(errors) for _, _, errors in problems)
    if args.scenario:
        jobs = [j for j in jobs if j.scenario in args.scenario]
        if not jobs:
            raise UsageError("no scenario of the files is named " + ", ".join(args.scenario))
    return jobs, None


def refused_domains(args, jobs: list, needs: tuple[str, ...], command: str) -> int | None:
    """The exit status when a domain of the jobs lacks a capability in `needs` (E0703, reported
    before any work), else None; `--min-robustness` is checked against each domain too."""
    from physc.diagnostics import Diagnostic
    from physc.domains import MissingCapability, load_domain
    from physc.domains.base import require

    for name in sorted({job.domain for job in jobs}):
        domain = load_domain(name)
        try:
            require(domain, needs, command)
        except MissingCapability as error:
            found = [Diagnostic(error.code, error.message, None, help=error.help)]
            reporter(args)(next(job.path for job in jobs if job.domain == name), None, found)
            return diagnostics.exit_status(found)
        check_min_robustness(args.min_robustness, domain)
    return None


def executor_from(args) -> Executor:
    """The executor the options ask for; a usage error when it cannot be had."""
    try:
        return executor_for(args.jobs, args.scheduler, args.dask_workers)
    except ExecutorError as error:
        raise UsageError(str(error)) from error


# Options that change where and how visibly a run goes, not what it makes: left out of the command
# a dataset's README records, so that the README is the same on any executor.
_WHERE = {
    "--jobs": 1,
    "--scheduler": 1,
    "--dask-workers": 1,
    "--color": 1,
    "-q": 0,
    "--quiet": 0,
    "--traceback": 0,
    "--format": 1,
    "--json": 0,
}


def command_arguments(command: str, fallback: list[str]) -> list[str]:
    """The arguments after `command` on this process's command line (top-level options such as
    --color may come before it); `fallback` when physc was not run from a command line."""
    import sys

    words = sys.argv[1:]
    while words and words[0] != command:  # only physc's top-level options may come before it
        if words[0] == "--color" and len(words) > 1:
            words = words[2:]
        elif words[0] == "--traceback" or words[0].startswith("--color="):
            words = words[1:]
        else:
            return fallback
    return words[1:] if words else fallback


def _portable(argument: str) -> str:
    """An argument as a README may show it: an absolute path (this machine's folders) by its
    name alone, as in `--out /home/me/data/set` → `--out set`."""
    import os

    option, equals, value = argument.partition("=") if argument.startswith("-") else ("", "", argument)
    if os.path.isabs(value):
        value = os.path.basename(value.rstrip("/")) or value
    return f"{option}{equals}{value}" if option else value


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
        kept.append(_portable(argument))
    return " ".join(["physc", command] + [shlex.quote(a) for a in kept])
