"""`physc eval`: generate tasks for scenarios and measure them like the paper, and more."""

from __future__ import annotations

import shlex
import sys
import time
from pathlib import Path

from physc.commands import arguments
from physc.commands.common import EXIT_INPUT, EXIT_OK, UsageError, add_format, print_json
from physc.commands.options import add_generation, add_target, generation_settings
from physc.commands.progress import Progress
from physc.commands.running import (
    add_executor,
    check_batch,
    command_arguments,
    executor_from,
    refused_domains,
    selected_jobs,
)
from physc.files import check_output, ensure_folder


def _described(record: dict) -> str:
    return f"{record['scenario']} seed {record['seed']}: {'ok' if record.get('generated') else 'no task'}"


def cmd_agent(args) -> int:
    """`physc eval --agent MODULE:NAME DATASET`: an agent scored on a generated dataset."""
    import json

    from physc.domains import load_domain
    from physc.domains.base import DomainError
    from physc.evaluation.agent import AgentError, load
    from physc.files import read_json_lines, write_atomic

    if len(args.files) != 1 or not Path(args.files[0]).is_dir():
        raise UsageError("with --agent, physc eval takes one dataset folder (made by physc generate)")
    folder = Path(args.files[0])
    rows = read_json_lines(folder / "manifest.jsonl")
    domains = sorted({row["domain"] for row in rows if isinstance(row, dict) and row.get("level")})
    if len(domains) != 1:
        raise UsageError(
            f"{folder} holds no generated tasks of one domain (manifest.jsonl: {', '.join(domains) or 'none'})"
        )
    check_output(args.out, folder=True)
    try:
        domain = load_domain(domains[0])
        if "score_agent" not in domain.capabilities:
            raise UsageError(
                f"the domain '{domain.name}' scores no agent (it has no score_agent);"
                " the PHYRE-like plugin's datasets can be scored"
            )
    except DomainError as error:
        raise UsageError(f"{folder}: {error.message}") from None
    try:
        agent = load(args.agent)
        scored = domain.evaluation.score_agent(folder, agent, args.setup, range(args.folds), args.split)
    except AgentError as error:
        print(f"physc eval: error: {error}", file=sys.stderr)
        return EXIT_INPUT
    except DomainError as error:  # what the dataset does not hold (a --setup it has no folds for)
        raise UsageError(f"{folder}: {error.message}" + (f" ({error.help})" if error.help else "")) from None
    except (
        OSError,
        ValueError,
        KeyError,
    ) as error:  # a dataset whose benchmark files are missing, unreadable or damaged
        raise UsageError(
            f"cannot read the dataset {folder} (generated to its end by physc generate?): {error}"
        ) from None
    out = Path(args.out)
    ensure_folder(out)
    record = {"agent": args.agent, "dataset": str(folder), **scored}
    write_atomic(out / "agent.json", json.dumps(record, indent=2) + "\n")
    if args.format == "json":
        print_json(record)
    elif not args.quiet:
        print(
            f"{args.agent}: AUCCESS {scored['auccess']} on the {args.split} split of {args.setup},"
            f" folds 0-{args.folds - 1}; {out / 'agent.json'}",
            file=sys.stderr,
        )
    return EXIT_OK


def cmd_eval(args) -> int:
    from physc.evaluation.report import write

    if args.agent:
        return cmd_agent(args)
    from physc.api.datasets import evaluation_needs
    from physc.driver.job import jobs_for
    from physc.evaluation.run import run

    check_batch(args)
    # Generation's final validation is skipped, as in the paper's evaluation.
    jobs, problems = jobs_for(args.files, args.tasks, args.seed, **generation_settings(args, validate=False))
    jobs, status = selected_jobs(args, jobs, problems)
    if status is None:  # generation needs the domain's capabilities, and so do its replays and measurements
        status = refused_domains(args, jobs, evaluation_needs(), "physc eval")
    if status is not None:
        return status
    folder = Path(args.out)
    started = time.perf_counter()
    with executor_from(args) as executor:
        records = run(jobs, folder, executor, Progress("eval", args.quiet, _described))
    argv = command_arguments("eval", [])
    command = "physc eval " + " ".join(shlex.quote(a) for a in argv) if argv else "physc eval …"
    summary = write(records, folder, command, time.perf_counter() - started)
    if args.format == "json":
        import json

        print_json({"report": str(folder / "results.md"), **json.loads((folder / "results.json").read_text())})
    elif not args.quiet:
        counts = summary["interactions"]
        made = sum(c["generated"] for c in counts.values())
        print(f"{made} of {len(records)} tasks generated; report in {folder / 'results.md'}", file=sys.stderr)
    return EXIT_OK


def add_command(commands, common) -> None:
    parser = commands.add_parser(
        "eval", parents=[common], help="generate tasks and measure them like the paper's results table"
    )
    parser.add_argument(
        "files",
        nargs="+",
        metavar="FILE",
        help=".phys files; every scenario of each is evaluated (with --agent: a dataset folder)",
    )
    parser.add_argument("-s", "--scenario", action="append", metavar="NAME", help="only these scenarios (repeatable)")
    parser.add_argument(
        "--tasks", type=arguments.tasks, default=30, metavar="N", help="tasks per scenario (default 30)"
    )
    add_executor(parser)
    parser.add_argument(
        "--seed", type=arguments.seed, default=0, metavar="S", help="seed of the first task (task i uses S + i)"
    )
    add_generation(parser, validate=False)
    add_target(parser)
    parser.add_argument("--out", required=True, metavar="DIR", help="where records and the report go; a rerun resumes")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    add_format(parser, "the summary (or an agent's scores)")
    agent = parser.add_argument_group("scoring an agent on a generated dataset (a PHYRE-like benchmark)")
    agent.add_argument(
        "--agent",
        metavar="MODULE:NAME",
        help="a Python callable: a task's observation in, actions in [0, 1]^3 out, best first"
        " (physc_phyre.agents:random_agent)",
    )
    agent.add_argument(
        "--setup",
        default="ball_cross_template",
        metavar="NAME",
        help="PHYRE's evaluation setup, as the dataset's phyre/folds.json names them (ball_cross_template,"
        " ball_within_template, two_balls_…; default ball_cross_template)",
    )
    agent.add_argument(
        "--folds",
        type=int,
        choices=range(1, 11),
        default=10,
        metavar="N",
        help="folds 0 .. N-1, N from 1 to 10 (default 10, as PHYRE reports)",
    )
    agent.add_argument(
        "--split",
        choices=("test", "dev"),
        default="test",
        help="the split scored (default test; the agent's fit sees train and dev)",
    )
    parser.set_defaults(run=cmd_eval)
