"""`physc verify LEVEL --task TASK.json`: a generated task's solution replayed, in any backend.

The task file (`physc compile --task`) holds the scenario as written, the level with the
scenario's object names, and the intended solution; LEVEL is the level file given to
players, which must be that level. The solution is replayed once as recorded and under
the domain's noise (`--replays`), in `--backend` (bullet: a second engine), with each action
the domain's agents may send beside it (Science Birds: the 8 pixels around each drag, the
trajectory planner's release, a tap 20 ms early or late), and the command says whether it
solves the level and realises the declared sequence, with the interactions it realised and
the agents' actions that failed. Exit 0 when it passes, 1 when it does not.
"""

from __future__ import annotations

from physc import budget
from physc.commands.common import EXIT_INPUT, EXIT_OK, UsageError, add_format, aimed_at, print_json
from physc.diagnostics import safe
from physc.files import read_input


def read_task(path: str) -> dict:
    """A task file's JSON (physc.api.tasks.read_task), a usage error when it is not one."""
    from physc.api.errors import FileError
    from physc.api.tasks import read_task as read

    try:
        return read(path)
    except FileError as error:
        raise UsageError(str(error)) from None


def _normalised(text: str) -> str:
    """A level file's text as compared: line ends and the ends of the text do not count."""
    return text.replace("\r\n", "\n").strip()


def cmd_verify(args) -> int:
    from physc.api.errors import FileError
    from physc.api.tasks import task_parts
    from physc.commands.options import replaying
    from physc.search.verify import noisy_replays, verify

    task = read_task(args.task)
    try:
        domain, scenario, level, level_text, solution = task_parts(task, args.task)
    except FileError as error:
        raise UsageError(str(error)) from None
    domain = replaying(domain, task, args, "verify")
    from physc.api.tasks import MAX_TASK_BYTES

    data, problem = read_input(args.level, "the level", limit=MAX_TASK_BYTES + 1)
    if data is None:
        raise UsageError(problem)
    if _normalised(data.decode("utf-8-sig", "replace")) != _normalised(level_text):
        raise UsageError(
            f"{args.level} is not the level of {args.task}: the task file holds another level "
            "(verify the level file `physc compile` wrote beside it)"
        )
    replays = args.replays if args.replays is not None else noisy_replays(domain)
    try:
        with budget.interruptible():
            result = verify(domain, scenario, level, solution, domain.backend.name, noisy=replays)
    except ValueError as error:  # the file's solution cannot be played (angrybirds: a target out of reach)
        raise UsageError(f"{args.task}: its solution cannot be played: {error}") from None
    if args.format == "json":
        print_json(
            {
                "level": args.level,
                "task": args.task,
                "scenario": scenario.name,
                "world": domain.world.name,
                "backend": result.backend,
                "solved": result.solved,
                "realised": result.realised,
                "noisy_passed": result.noisy_passed,
                "noisy_run": result.noisy_run,
                "passes": result.passes(replays),
                "readings": result.readings,
                "failed_readings": list(result.failed),
                "agent_variants": result.variants,
                "failed_variants": list(result.imprecise),
                "trace": result.trace,
                "why": result.why,
                "sent": domain.actions.sent_record(solution),
            }
        )
    else:
        verdict = "passes" if result.passes(replays) else "fails"
        print(
            f"{safe(args.level)}: scenario {scenario.name}, solution {aimed_at(solution)}: {verdict} {result.summary()}"
        )
        if result.why:
            print(f"  why: {result.why}")
        for name in result.failed:
            print(f"  fails in the reading: {name}")
        for label in result.imprecise:
            print(f"  fails as an agent may send it: {label}")
        print(f"  realised: {result.trace or '(nothing)'}")
        sent = domain.actions.sent_text(solution)
        if sent is not None:
            print(f"  {sent}")
    return EXIT_OK if result.passes(replays) else EXIT_INPUT


def add_command(commands, common) -> None:
    from physc.commands import arguments
    from physc.commands.options import add_target

    parser = commands.add_parser(
        "verify",
        parents=[common],
        help="replay a task's solution (in any backend): does it solve the level and realise the sequence?",
    )
    parser.add_argument("level", metavar="LEVEL", help="the task's level file ('-' reads standard input)")
    parser.add_argument("--task", required=True, metavar="TASK.json", help="the task file `physc compile --task` wrote")
    add_target(parser, verify=False, replay=True)
    parser.add_argument(
        "--replays",
        type=arguments.replays,
        metavar="N",
        help="noisy replays that must realise the sequence too (default: the domain's, 6 in angrybirds; 0: none)",
    )
    add_format(parser, "the verdict")
    parser.set_defaults(run=cmd_verify)
