"""The options several commands share, each declared once with one default.

`add_target`: where a command simulates (--world, --backend, and --verify-backend where a
task is made); `add_generation`: the budgets and rules of making a task (compile, generate
and eval). A command adds the groups it needs, so an option means the same, and defaults
to the same, in every command.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from physc.backends import DEFAULT_BACKEND
from physc.commands import arguments
from physc.driver.run_settings import CLAUSE_BUDGET, LAYOUT_BUDGET, MIN_ROBUSTNESS, TIME_BUDGET, RunSettings

if TYPE_CHECKING:
    from physc.api.datasets import JobSettings


def add_target(parser, verify: bool = True, replay: bool = False) -> None:
    """--world and --backend; with `verify`, --verify-backend. With `replay` (a command that
    replays a task: the task's own world and engine are the defaults, so none is set here)."""
    default = None if replay else DEFAULT_BACKEND
    where = "the task's world" if replay else "the domain's default world; physc worlds lists them"
    parser.add_argument(
        "--world",
        type=arguments.world,
        metavar="NAME",
        help=f"the world that is simulated: its engine settings, bodies and rules (default {where})",
    )
    parser.add_argument(
        "--backend",
        type=arguments.backend,
        default=default,
        metavar="NAME",
        help="the physics engine that simulates (default "
        + ("the task's, else " if replay else "")
        + f"{DEFAULT_BACKEND}, the game's; "
        "pymunk and bullet are built in too: physc backends)",
    )
    if verify:
        parser.add_argument(
            "--verify-backend",
            type=arguments.backend,
            metavar="NAME",
            help="a second physics backend (e.g. bullet) in which the task's solution must also solve the level and "
            "realise the sequence, in its noisy replays too",
        )


def add_generation(parser, validate: bool = True) -> None:
    """The budgets and rules of making a task; with `validate`, --no-validate (eval never
    validates, as the paper's evaluation)."""
    parser.add_argument(
        "--layouts",
        type=arguments.count,
        default=LAYOUT_BUDGET,
        metavar="N",
        help=f"layouts simulation may try per task (default {LAYOUT_BUDGET})",
    )
    parser.add_argument(
        "--time-budget",
        type=arguments.time_budget,
        default=TIME_BUDGET,
        metavar="S",
        help=f"seconds per task at most (default {TIME_BUDGET:g})",
    )
    parser.add_argument(
        "--min-robustness",
        type=arguments.count,
        default=MIN_ROBUSTNESS,
        metavar="K",
        help="make fallbacks: when no layout within the budget gives a solution that passes every noisy replay of "
        "the generator (6 in angrybirds), use the most robust one that passes at least K of them, and K of physc "
        "verify's (default: none; a task must pass all); the task JSON and the manifest mark a fallback",
    )
    parser.add_argument(
        "--no-acceptance",
        action="store_true",
        help="keep tasks without the domain's acceptance rule (PHYRE's GOOD_STABLE, not TRIVIAL): quicker, for drafts",
    )
    parser.add_argument(
        "--clause-budget",
        "--budget",
        dest="clause_budget",
        type=arguments.count,
        default=CLAUSE_BUDGET,
        metavar="N",
        help=f"clause choices the layout search may try per shape draw (default {CLAUSE_BUDGET};"
        " --budget is its old name)",
    )
    parser.add_argument(
        "--workers",
        type=arguments.count,
        default=1,
        metavar="W",
        help="processes that satisfy each task's placed layouts side by side (default 1): the same task "
        "for any number, only sooner (generate and eval with --jobs J: J × W processes in all)",
    )
    if validate:
        parser.add_argument(
            "--no-validate", action="store_true", help="skip the final validation of each generated task"
        )


def run_settings(args, validate: bool | None = None) -> RunSettings:
    """The run's settings (physc.driver.run_settings.RunSettings) that `add_generation` and
    `add_target` parsed, under the options' own names; `validate` where the command decides it
    (eval: never, as the paper's evaluation)."""
    return RunSettings(
        time_budget=args.time_budget,
        layouts=args.layouts,
        clause_budget=args.clause_budget,
        min_robustness=args.min_robustness,
        validate=(not args.no_validate) if validate is None else validate,
        acceptance=not args.no_acceptance,
        verify_backend=args.verify_backend,
        workers=args.workers,
    )


def generation_settings(args, validate: bool | None = None) -> JobSettings:
    """The fields of a job (physc.driver.job.Job) that `add_generation` and `add_target` set:
    the world, the engine and the run's settings."""
    from physc.api.datasets import job_settings

    return job_settings(args.world, args.backend, run_settings(args, validate))


def replaying(domain, recorded: dict, args, command: str):
    """`domain` in the world and engine a task is replayed in: --world and --backend where
    given, else the ones the task file records (a task file from before worlds were named:
    the domain's default world, and box2d). Says so on stderr when that is not where the task
    was made, since its solution was found there."""
    import sys

    made_world, made_backend = recorded.get("world") or None, recorded.get("backend") or None
    bound = domain.at(args.world or made_world, args.backend or made_backend)
    for what, made, now, flag in (
        ("world", made_world, bound.world.name, "--world"),
        ("engine", made_backend, bound.backend.name, "--backend"),
    ):
        if made and made != now:
            print(
                f"physc {command}: note: the task was made in the {what} '{made}'; replaying it in '{now}' ({flag})",
                file=sys.stderr,
            )
    return bound
