"""`physc eval`: generate tasks for scenarios and measure them like the paper, and more."""

from __future__ import annotations

import shlex
import sys
import time
from pathlib import Path

from physc.commands import arguments
from physc.commands.common import EXIT_OK, add_backend, add_min_robustness
from physc.commands.running import Progress, add_executor, check_batch, executor_from, refused_domains, selected_jobs


def _described(record: dict) -> str:
    return f"{record['scenario']} seed {record['seed']}: {'ok' if record.get('generated') else 'no task'}"


def cmd_eval(args) -> int:
    from physc.evaluation.report import write
    from physc.domains.base import STAGE_NEEDS
    from physc.evaluation.run import jobs_for, run

    check_batch(args)
    jobs, problems = jobs_for(
        args.files, args.tasks, args.seed, args.time_budget, args.min_robustness, args.backend, args.verify_backend, not args.no_acceptance
    )
    jobs, status = selected_jobs(args, jobs, problems)
    if status is None:  # generation needs the domain's capabilities, and so do its replays and measurements
        status = refused_domains(args, jobs, STAGE_NEEDS["task"] + ("replay", "stability"), "physc eval")
    if status is not None:
        return status
    folder = Path(args.out)
    started = time.perf_counter()
    with executor_from(args) as executor:
        records = run(jobs, folder, executor, Progress("eval", args.quiet, _described))
    command = "physc eval " + " ".join(shlex.quote(a) for a in sys.argv[2:]) if sys.argv[1:2] == ["eval"] else "physc eval …"
    summary = write(records, folder, command, time.perf_counter() - started)
    if not args.quiet:
        counts = summary["interactions"]
        made = sum(c["generated"] for c in counts.values())
        print(f"{made} of {len(records)} tasks generated; report in {folder / 'results.md'}", file=sys.stderr)
    return EXIT_OK


def add_command(commands, common) -> None:
    parser = commands.add_parser("eval", parents=[common], help="generate tasks and measure them like the paper's results table")
    parser.add_argument("files", nargs="+", metavar="FILE", help=".phys files; every scenario of each is evaluated")
    parser.add_argument("-s", "--scenario", action="append", metavar="NAME", help="only these scenarios (repeatable)")
    parser.add_argument("--tasks", type=arguments.tasks, default=30, metavar="N", help="tasks per scenario (default 30)")
    add_executor(parser)
    parser.add_argument("--seed", type=arguments.seed, default=0, metavar="S", help="seed of the first task (task i uses S + i)")
    parser.add_argument("--time-budget", type=arguments.time_budget, default=300.0, metavar="S", help="seconds of generation per task at most (default 300; the measurements after it are not counted)")
    add_min_robustness(parser)
    add_backend(parser)
    parser.add_argument(
        "--no-acceptance", action="store_true", help="keep tasks without the domain's acceptance rule (PHYRE's GOOD_STABLE, not TRIVIAL): quicker, for drafts"
    )
    parser.add_argument("--out", required=True, metavar="DIR", help="where records and the report go; a rerun resumes")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    parser.set_defaults(run=cmd_eval)
