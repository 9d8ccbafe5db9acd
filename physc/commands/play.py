"""`physc simulate`, `physc trace`, `physc render`: playing Science Birds levels.

On the Python API's `physc.simulate` (physc.api.simulating) and the domain's interface
(physc.domains.base.Domain: `read_level`, `draw`, and the Science Birds domain's `shot`), in
the world and engine chosen (--world, --backend, or the task file's with --task).

Each reads a level file (real files as they are: declared utf-16, actually
ASCII), optionally fires one full-stretch shot, and reports what happened: the
outcome, the recognised interactions in `.phys` syntax, or a picture with the
paths of the objects that moved.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import attrs

from physc import budget
from physc.commands import aiming, arguments
from physc.commands.common import EXIT_OK, UsageError, add_format, plural, print_json, reporter
from physc.commands.options import add_target
from physc.diagnostics import Diagnostic, SourceText, safe
from physc.files import check_output, read_input, write_atomic

if TYPE_CHECKING:
    from physc.domains.angrybirds import AngryBirds
    from physc.domains.angrybirds.level import Level
    from physc.domains.base import Domain
    from physc.simulation.trace import Trace

LEVEL_DOMAIN = "angrybirds"  # the domain whose level files these commands play


class Action(Protocol):
    """A Science Birds action as these commands show it: a shot, or several (launch.Shot, Shots)."""

    def text(self) -> str: ...


@attrs.frozen
class Played:
    """A level file played (`_play`): in the domain bound to its world and engine, with the shot
    (None: none) and what happened."""

    domain: AngryBirds
    level: Level
    shot: Action | None
    trace: Trace


def _birds(domain: Domain) -> AngryBirds:
    """The Science Birds domain as the class these commands play its levels with (what
    LEVEL_DOMAIN loads, wherever it is bound)."""
    from physc.domains.angrybirds import AngryBirds

    assert isinstance(domain, AngryBirds), f"the domain '{LEVEL_DOMAIN}' is Science Birds'"
    return domain


def _domain(args, level=None) -> AngryBirds:
    """The Science Birds domain in the world and engine the level is played in: --world and
    --backend where given, else the task file's (--task), else the world the level names
    (`level`, read already), else the defaults."""
    from physc.commands.options import replaying
    from physc.domains import load_domain

    domain = load_domain(LEVEL_DOMAIN)
    named = None if level is None else domain.files.level_world(level)
    if named and not args.world:
        from physc.worlds import WorldError

        try:
            domain.at(named)
        except WorldError as error:
            raise UsageError(f'{safe(args.level)}: <Level world="{safe(named)}">: {error}') from None
    if args.task is None:
        return _noted(domain.at(args.world or named, args.backend), named, args)
    from physc.commands.verify import read_task

    recorded = read_task(args.task)
    if recorded.get("domain") != LEVEL_DOMAIN:
        raise UsageError(
            f"{args.task} is a task of the domain '{recorded.get('domain')}', not of {LEVEL_DOMAIN}'s levels"
        )
    return _noted(replaying(domain, recorded, args, args.command), named, args)


def _noted(bound: Domain, named: str | None, args) -> AngryBirds:
    """`bound`, after a note on stderr when the level names another world than the one it is
    played in (its solution, if it has one, was found there)."""
    import sys

    if named and named != bound.world.name:
        print(
            f"physc {args.command}: note: the level was made for the world '{named}';"
            f" playing it in '{bound.world.name}'",
            file=sys.stderr,
        )
    return _birds(bound)


def _level(args):
    """(the level file read with the Science Birds domain, the exit status): reading does
    not depend on the world, which the level itself may name."""
    from physc.domains import load_domain

    return load_level(args, load_domain(LEVEL_DOMAIN))


def load_level(args, domain):
    """The level of args.level, or None after reporting why not (the exit status is returned too)."""
    from physc.domains.base import LevelError

    limit = domain.files.max_level_bytes
    data, problem = read_input(args.level, "the level", limit=limit + 1)
    if data is None:
        assert problem is not None, "read_input says why it read nothing"
        return None, _fail(args, Diagnostic("E0001", problem))
    if len(data) > limit:
        return None, _fail(args, Diagnostic("E0906", f"the level file is larger than physc reads ({limit:,} bytes)"))
    try:
        return domain.files.read_level(data), 0
    except LevelError as error:
        source = SourceText(
            args.level, domain.files.level_text(data)
        )  # as the level was read, so that lines and columns match
        span = None
        if error.line is not None and error.line <= source.line_count:
            start = source.offset(error.line, error.column or 1)
            span = source.span(start, start + 1)
        help_text = error.help
        if str(args.level).endswith(".phys"):
            help_text = "this is a scenario, not a level: `physc compile FILE -o level.xml --png picture.png` makes one"
        return None, _fail(args, Diagnostic(error.code, error.message, span, help=help_text), source)


def _fail(args, diagnostic: Diagnostic, source=None) -> int:
    from physc import diagnostics

    reporter(args)(args.level, source, [diagnostic])
    return diagnostics.exit_status([diagnostic])


def _scenario(args):
    """(the task file's scenario, its level with the scenario's names, that level's text, its
    solution), or None without --task."""
    if args.task is None:
        return None
    from physc.api.errors import FileError
    from physc.api.tasks import task_parts
    from physc.commands.verify import read_task

    try:
        _, scenario, level, text, solution = task_parts(read_task(args.task), args.task)
    except FileError as error:
        raise UsageError(str(error)) from None
    return scenario, level, text, solution


def _play(args, task=None) -> Played | int:
    """The level file played with the shot (`Played`), in the world _domain picks, or the exit
    status after reporting why it cannot be; with `task` (_scenario's) and the task's own level
    file, the task's level, named as its scenario names its objects, judged against the
    scenario."""
    from physc.api.simulating import simulate
    from physc.commands.verify import _normalised
    from physc.domains.angrybirds.shots import birds

    level, status = _level(args)
    if level is None:
        return status
    domain = _domain(args, level)
    scenario, names, solution = None, (), None
    if task is not None:
        scenario, named, text, solution = task
        data, _ = read_input(args.level, "the level", limit=domain.files.max_level_bytes + 1)
        if data is not None and _normalised(data.decode("utf-8-sig", "replace")) == _normalised(text):
            level, names = named, tuple(birds(scenario, domain.vocabulary.player))  # the scenario's names
        else:
            scenario = None  # another level: its objects have other names
    shot = aiming.shots(args.aims, level, names)
    if shot is None and scenario is not None:
        shot = domain.actions.action_of(solution)  # the task's own solution, all its shots
    if shot is not None and not level.has_birds:
        help_text = 'add <Bird type="BirdRed" /> inside <Birds>, or play the level without --shot, --angle and --action'
        return _fail(args, Diagnostic("E0907", "the level has no bird to shoot", help=help_text))
    try:
        with budget.interruptible():
            trace = simulate(level, shot, domain=domain, seconds=args.seconds, scenario=scenario)
    except ValueError as error:  # a target out of reach of the launch
        raise UsageError(str(error)) from None
    return Played(domain, level, shot, trace)


def _angle(shot, domain) -> float | None:
    """A single shot's release angle (None for several)."""
    return round(shot.release_angle(domain.world), 4) if hasattr(shot, "release_angle") else None


def cmd_simulate(args) -> int:
    played = _play(args, _scenario(args))
    if isinstance(played, int):
        return played
    domain, level, shot, trace = played.domain, played.level, played.shot, played.trace
    pigs = list(trace.goal)
    destroyed = [d for d in trace.destructions if d.name in pigs]
    if args.format == "json":
        print_json(
            {
                "level": args.level,
                "world": domain.world.name,
                "backend": domain.backend.name,
                "shot": None if shot is None else {"text": shot.text(), "release_angle": _angle(shot, domain)},
                "shots": aiming.described(shot, args.aims, domain.world),
                "seconds": round(trace.duration, 4),
                "pigs": pigs,
                "pigs_destroyed": [d.name for d in destroyed],
                "solved": trace.solved,
                "destroyed": [
                    {"name": d.name, "cause": d.cause, "by": d.by, "time": round(d.time, 4)} for d in trace.destructions
                ],
            }
        )
        return EXIT_OK
    what = (
        "no shot"
        if shot is None
        else f"shot {shot.text()}"
        + ("" if _angle(shot, domain) is None else f" (release angle {_angle(shot, domain):.2f}°)")
    )
    sent = [a.sent() for a in aiming.asked(args.aims) if a.sent()]
    what += f", as Phy-Q's agents send it: {', '.join(str(s) for s in sent)}" if sent else ""
    print(
        f"{safe(args.level)}: {plural(len(level.objects), 'object')}, {plural(len(pigs), 'pig')}; {what};"
        f" world {domain.world.name}"
    )
    verdict = "solved" if trace.solved else "not solved"
    print(f"after {trace.duration:.2f} s: {len(destroyed)} of {plural(len(pigs), 'pig')} destroyed: {verdict}")
    for d in trace.destructions:
        by = f", by {d.by}" if d.by else ""
        print(f"  destroyed {d.name} ({d.cause}{by}) at t = {d.time:.2f} s")
    return EXIT_OK


def cmd_trace(args) -> int:
    from physc.simulation.margins import Recognised

    task = _scenario(args)
    played = _play(args, task)
    if isinstance(played, int):
        return played
    domain, level, shot, trace = played.domain, played.level, played.shot, played.trace
    scenario = task[0] if task is not None and level is task[1] else None
    margins = domain.margins(scenario or Recognised.of(trace), trace)
    by_time = {}
    if margins is not None:
        found = [i for i in trace.interactions]
        declared = (scenario or Recognised.of(trace)).interactions
        matched, k = {}, 0
        from physc.simulation.fidelity import matches

        for interaction in found:
            if k < len(declared) and matches(declared[k], interaction):
                matched[k] = interaction
                k += 1
        by_time = {id(matched[m.index]): m for m in margins.links if m.index is not None and m.index in matched}
    restrictions = [m for m in margins.links if m.index is None] if margins is not None else []
    weakest = margins.weakest if margins is not None else None
    if args.format == "json":
        print_json(
            {
                "level": args.level,
                "shot": shot.text() if shot else None,
                "solved": trace.solved,
                "interactions": [
                    {
                        "term": i.text(),
                        "time": round(i.time, 4),
                        "margin": by_time[id(i)].record() if id(i) in by_time else None,
                    }
                    for i in trace.interactions
                ],
                "restrictions": [m.record() for m in restrictions],
                "weakest": None if weakest is None else weakest.record(),
            }
        )
        return EXIT_OK
    print(f"# {safe(args.level)}, shot {shot.text() if shot else 'none'}: {'solved' if trace.solved else 'not solved'}")
    lines = [("> " if index else "") + interaction.text() for index, interaction in enumerate(trace.interactions)]
    width = max((len(line) for line in lines), default=0)
    # the times in one column, whatever the terms' lengths (a line per interaction)
    for line, interaction in zip(lines, trace.interactions, strict=True):
        margin = by_time.get(id(interaction))
        note = f"; margin {margin.value:+.3g} {margin.unit} ({margin.what})" if margin is not None else ""
        print(f"{line:<{width}}  # t = {interaction.time:.2f} s{note}")
    for m in restrictions:
        print(f"# {m.term}: {'kept' if m.held else 'broken'}, margin {m.value:+.3g} {m.unit} ({m.what})")
    if weakest is not None:
        print(
            f"# {weakest.named_weakest()}"
            + ("" if scenario is not None else " (of what happened; --task judges the declared sequence)")
        )
    return EXIT_OK


def cmd_render(args) -> int:
    if not args.output.lower().endswith((".png", ".svg")):
        raise UsageError("-o must name a .png or .svg file")
    check_output(args.output)
    if not args.aims and args.task is None:
        level, status = _level(args)
        if level is None:
            return status
        domain, paths = _domain(args, level), {}
    else:  # a shot, or the task's solution
        played = _play(args, _scenario(args))
        if isinstance(played, int):
            return played
        domain, level, paths = played.domain, played.level, played.trace.paths()
    kind = "svg" if args.output.lower().endswith(".svg") else "png"
    write_atomic(args.output, domain.files.draw(level, args.title or args.level, paths, kind))
    if args.format == "json":
        print_json({"level": args.level, "picture": args.output, "format": kind, "paths": sorted(paths)})
    return EXIT_OK


def add_commands(commands, common) -> None:
    def level_arguments(parser):
        parser.add_argument("level", metavar="LEVEL", help="a Science Birds level file ('-' reads standard input)")
        aiming.add_shot_options(parser)  # one --shot, --angle or --action a bird, in turn; --tap, --wait
        parser.add_argument(
            "--seconds",
            type=arguments.seconds,
            default=10.0,
            metavar="S",
            help=f"simulated time at most (default 10, at most {arguments.MAX_SECONDS:g})",
        )
        parser.add_argument(
            "--task",
            metavar="TASK.json",
            help="the level's task file (`physc compile --task`): the level is played in its world and engine"
            " unless --world or --backend says otherwise",
        )
        add_target(parser, verify=False, replay=True)

    simulate = commands.add_parser(
        "simulate", parents=[common], help="play a level (with a shot or none) and say what happened"
    )
    level_arguments(simulate)
    add_format(simulate, "what happened")
    simulate.set_defaults(run=cmd_simulate)

    trace = commands.add_parser(
        "trace",
        parents=[common],
        help="the interactions a shot causes, in .phys syntax, each with its margin (how far it was from failing)",
    )
    level_arguments(trace)
    add_format(trace, "the interactions")
    trace.set_defaults(run=cmd_trace)

    render = commands.add_parser("render", parents=[common], help="draw a level, with the paths a shot causes")
    level_arguments(render)
    render.add_argument("-o", "--output", required=True, metavar="PATH", help="the picture (.png or .svg)")
    render.add_argument("--title", help="the picture's title (default: the file name)")
    add_format(render, "what was drawn")
    render.set_defaults(run=cmd_render)
