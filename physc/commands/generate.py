"""`physc generate`: a dataset of tasks for scenarios, on local processes or a Dask cluster."""

from __future__ import annotations

import sys
from pathlib import Path

from physc.commands import arguments
from physc.commands.common import EXIT_INFEASIBLE, EXIT_OK, UsageError, add_format, print_json
from physc.commands.options import add_generation, add_target, generation_settings
from physc.commands.progress import Progress
from physc.commands.running import (
    add_executor,
    check_batch,
    command_arguments,
    executor_from,
    refused_domains,
    reproducing_command,
    selected_jobs,
)
from physc.dataset.waves import WAVE


def _described(row: dict) -> str:
    return f"{row['scenario']} seed {row['seed']}: {row['outcome']}"


def cmd_generate(args) -> int:
    from physc.api.datasets import clashes, generation_needs
    from physc.dataset.build import build
    from physc.dataset.worker import NO_TASK
    from physc.driver.job import jobs_for

    check_batch(args)
    jobs, problems = jobs_for(
        args.files,
        args.tasks,
        args.seed,
        **generation_settings(args),
        picture=args.png,
        accidental=args.accidental,
    )
    jobs, status = selected_jobs(args, jobs, problems)
    if status is not None:
        return status
    problem = clashes(jobs)
    if problem:
        raise UsageError(problem)
    status = refused_domains(args, jobs, generation_needs(args.png, args.verify_backend), "physc generate")
    if status is not None:
        return status
    command = reproducing_command(
        "generate", command_arguments("generate", [*args.files, "--tasks", str(args.tasks), "--out", args.out])
    )
    from physc.domains.base import DomainError

    with executor_from(args) as executor:
        try:
            rows = build(
                jobs, Path(args.out), executor, Progress("generate", args.quiet, _described), command, args.wave
            )
        except DomainError as error:  # the domain's own benchmark files refused (the tasks are kept)
            raise UsageError(
                f"the tasks are in {args.out}, but not the domain's own benchmark files: {error.message}"
            ) from None
    made = sum(row["outcome"] != NO_TASK for row in rows)
    if args.format == "json":
        print_json(
            {
                "dataset": args.out,
                "generated": made,
                "tasks": len(rows),
                "rows": [{"scenario": row["scenario"], "seed": row["seed"], "outcome": row["outcome"]} for row in rows],
            }
        )
    elif not args.quiet:
        print(
            f"{made} of {len(rows)} tasks generated; dataset in {args.out} (README.md, manifest.parquet)",
            file=sys.stderr,
        )
    return EXIT_OK if made else EXIT_INFEASIBLE


def add_command(commands, common) -> None:
    parser = commands.add_parser(
        "generate", parents=[common], help="generate a dataset of tasks (locally or on a Dask cluster)"
    )
    parser.add_argument("files", nargs="+", metavar="FILE", help=".phys files; every scenario of each gets tasks")
    parser.add_argument("-s", "--scenario", action="append", metavar="NAME", help="only these scenarios (repeatable)")
    parser.add_argument(
        "--tasks", type=arguments.tasks, default=100, metavar="N", help="tasks per scenario (default 100)"
    )
    parser.add_argument(
        "--seed", type=arguments.seed, default=0, metavar="S", help="seed of the first task (task i uses S + i)"
    )
    parser.add_argument("--out", required=True, metavar="DIR", help="the dataset folder; a rerun resumes")
    parser.add_argument("--png", action="store_true", help="also draw each task (<seed>.png)")
    parser.add_argument(
        "--accidental", action="store_true", help="also measure accidental solvability (the domain's agent; slower)"
    )
    parser.add_argument(
        "--wave",
        type=arguments.wave,
        default=WAVE,
        metavar="N",
        help=f"a scenario's tasks made side by side before later ones learn from what their searches "
        f"simulated (default {WAVE}; 0: each task on its own, as physc compile makes it)",
    )
    add_generation(parser)
    add_target(parser)
    add_executor(parser)
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    add_format(parser, "the summary (each task's outcome)")
    parser.set_defaults(run=cmd_generate)
