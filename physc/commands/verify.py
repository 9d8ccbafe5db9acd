"""`physc verify LEVEL --task TASK.json`: a generated task's solution replayed, in any backend.

The task file (`physc compile --task`) holds the scenario as written, the level with the
scenario's object names, and the intended solution; LEVEL is the level file given to
players, which must be that level. The solution is replayed once as recorded and under
the domain's noise (`--replays`), in `--backend` (bullet: a second engine), and the
command says whether it solves the level and realises the declared sequence, with the
interactions it realised. Exit 0 when it passes, 1 when it does not.
"""

from __future__ import annotations

import json
import math

from physc import budget
from physc.commands.common import EXIT_INPUT, EXIT_OK, UsageError, add_format, print_json
from physc.diagnostics import safe
from physc.files import read_input

MAX_TASK_BYTES = 50_000_000


def read_task(path: str) -> dict:
    """A task file's JSON, checked to be one (UsageError otherwise)."""
    data, problem = read_input(path, "the task file", limit=MAX_TASK_BYTES + 1)
    if data is None:
        raise UsageError(problem)
    if len(data) > MAX_TASK_BYTES:
        raise UsageError(f"{path}: the task file is larger than physc reads ({MAX_TASK_BYTES:,} bytes)")
    try:
        task = json.loads(data.decode("utf-8-sig"))
    except (UnicodeDecodeError, json.JSONDecodeError) as error:
        raise UsageError(f"{path} is not a task file (JSON): {error}") from None
    except RecursionError:
        raise UsageError(f"{path} is not a task file: its JSON is nested too deeply") from None
    fields = ("domain", "scenario", "source", "level", "solution")
    if not isinstance(task, dict) or task.get("node") != "Task" or not all(field in task for field in fields):
        raise UsageError(f"{path} is not a task file: write one with `physc compile FILE --task {path}`")
    return task


def _parts(task: dict, path: str):
    """(domain, scenario, level, the level as the domain writes it, solution) of a task file."""
    from physc.domains import load_domain
    from physc.domains.base import DomainError, require, solution_classes
    from physc.domains.words import INSTALLED
    from physc.dsl.frontend import analyze_text
    from physc.serialize import from_data

    try:
        domain = load_domain(str(task["domain"]))
        require(domain, ("replay", "emit_level"), "physc verify")
    except DomainError as error:
        raise UsageError(f"{path}: {error.message}") from None
    if not domain.level_classes:
        raise UsageError(f"{path}: the domain '{domain.name}' cannot read its levels back from a task file (it has no level_classes)")
    analysis = analyze_text(f"{path} (source)", str(task["source"]), INSTALLED)
    scenario = next((s for s in analysis.scenarios if s.name == task["scenario"]), None)
    if scenario is None or any(d.is_error for d in analysis.diagnostics):
        raise UsageError(f"{path}: its source does not hold a valid scenario '{task['scenario']}'")
    try:
        level = from_data(task["level"], {cls.__name__: cls for cls in domain.level_classes})
        if not isinstance(level, domain.level_classes[0]):
            raise ValueError(f"the level is not a {domain.level_classes[0].__name__}")
        kinds = solution_classes(domain)
        solution = _solution(from_data(task["solution"], kinds), tuple(kinds.values()))
        level_text = domain.emit_level(level)  # also checks that the level is one the domain can write
    except (TypeError, ValueError, AttributeError, KeyError, RecursionError) as error:
        raise UsageError(f"{path}: its level or solution cannot be read: {error or type(error).__name__}") from None
    return domain, scenario, level, level_text, solution


def _solution(solution, kind: tuple[type, ...]):
    """The task file's solution, if it is one of the classes `kind` and, for angrybirds' Solution, its fields
    are what a shot holds (ValueError if not; another domain's class checks its own fields
    when it is made)."""
    from physc.compiler.task import Solution

    if not isinstance(solution, kind):
        raise ValueError(f"the solution is not a {' or a '.join(k.__name__ for k in kind)}")
    if not isinstance(solution, Solution):
        return solution
    target = solution.target
    numbers = (*target, solution.release_angle) if isinstance(target, tuple) and len(target) == 2 else None
    if numbers is None or not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in numbers):
        raise ValueError("the solution's target and release angle must be finite numbers")
    if solution.trajectory not in ("low", "high"):
        raise ValueError(f"the solution's trajectory is 'low' or 'high', not {solution.trajectory!r}")
    return solution


def _normalised(text: str) -> str:
    """A level file's text as compared: line ends and the ends of the text do not count."""
    return text.replace("\r\n", "\n").strip()


def cmd_verify(args) -> int:
    from physc.commands.options import replaying
    from physc.generation.verify import noisy_replays, verify

    task = read_task(args.task)
    domain, scenario, level, level_text, solution = _parts(task, args.task)
    domain = replaying(domain, task, args, "verify")
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
                "trace": result.trace,
                "why": result.why,
            }
        )
    else:
        verdict = "passes" if result.passes(replays) else "fails"
        print(f"{safe(args.level)}: scenario {scenario.name}, solution {solution.aimed_at}: {verdict} {result.summary()}")
        if result.why:
            print(f"  why: {result.why}")
        print(f"  realised: {result.trace or '(nothing)'}")
    return EXIT_OK if result.passes(replays) else EXIT_INPUT


def add_command(commands, common) -> None:
    from physc.commands import arguments
    from physc.commands.options import add_target

    parser = commands.add_parser(
        "verify", parents=[common], help="replay a task's solution (in any backend): does it solve the level and realise the sequence?"
    )
    parser.add_argument("level", metavar="LEVEL", help="the task's level file ('-' reads standard input)")
    parser.add_argument("--task", required=True, metavar="TASK.json", help="the task file `physc compile --task` wrote")
    add_target(parser, verify=False, replay=True)
    parser.add_argument(
        "--replays", type=arguments.replays, metavar="N",
        help="noisy replays that must realise the sequence too (default: the domain's, 6 in angrybirds; 0: none)",
    )
    add_format(parser, "the verdict")
    parser.set_defaults(run=cmd_verify)
