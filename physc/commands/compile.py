"""`physc compile`: run the compiler to a stage and print its IR."""

from __future__ import annotations

import contextlib
import json
import os
import sys
from typing import TYPE_CHECKING, Protocol, cast

from physc import budget, diagnostics
from physc.api.compiling import no_task, pipeline
from physc.commands.common import (
    EXIT_INFEASIBLE,
    EXIT_OK,
    UsageError,
    aimed_at,
    check_backends,
    check_min_robustness,
    reporter,
)
from physc.commands.options import run_settings
from physc.commands.progress import Heartbeat
from physc.compiler.infeasible import Infeasible
from physc.compiler.task import Task, given_up_summary
from physc.diagnostics import Diagnostic, Span
from physc.domains import bound, load_domain
from physc.domains.base import DomainError
from physc.domains.words import INSTALLED
from physc.driver.stages import BY_NAME, Stage, StageError, Unit, stage
from physc.dsl import ast
from physc.dsl.frontend import analyze
from physc.files import check_output, ensure_folder, write_atomic
from physc.serialize import to_data
from physc.suggest import did_you_mean

if TYPE_CHECKING:
    from physc.domains.base import Domain
    from physc.driver.stages import Run
    from physc.dsl.scenario import ScenarioIR


class Graph(Protocol):
    """A graph stage's IR (the layout graph, the dimension graphs): what `--format dot` prints."""

    def to_dot(self) -> str: ...


FILE_SUFFIXES = {"-o": (".xml", ".json", ".dot"), "--task": (".json",), "--png": (".png", ".svg")}


def _in_place(path: str, many: bool, name: str, suffix: str) -> str:
    """A file path; with several scenarios, `path` is a folder and the file is NAME.suffix."""
    if not many:
        return path
    return str(ensure_folder(path) / f"{name}.{suffix}")


def _check_outputs(args, many: bool, level_files: bool) -> None:
    """Every output path is checked before the work starts. With several scenarios, each
    of -o (levels), --task and --png names a folder that gets one NAME.xml/.json/.png per
    scenario; a file's name there is a mistake, not a folder to make."""
    for option, path in (("-o", args.output), ("--task", args.task), ("--png", args.png)):
        if path is None:
            continue
        folder = many and (option != "-o" or level_files)
        if folder and (
            os.path.isfile(path) or (not os.path.exists(path) and path.lower().endswith(FILE_SUFFIXES[option]))
        ):
            raise UsageError(
                f"several scenarios make several files: {option} must name a folder (each file is named after its "
                f"scenario), not the file '{path}'; or choose one scenario with -s NAME"
            )
        check_output(path, folder=folder)


def _layouts(task) -> str:
    """How many layouts were tried, and why those before the one used were given up."""
    tried = f"{task.layouts_tried} {'layout' if task.layouts_tried == 1 else 'layouts'}"
    return f"{tried} (given up: {given_up_summary(task.given_up)})" if task.given_up else tried


def _robustness(robustness) -> str:
    passed, total = robustness
    if not total:
        return "no noisy replays (the domain makes none)"
    text = f"{passed} of {total} noisy replays"
    return text if passed == total else text + " (a fallback: --min-robustness)"


def _picture_format(path: str) -> str:
    """svg for a path ending .svg; png otherwise (and for a folder of several scenarios)."""
    return "svg" if path.lower().endswith(".svg") else "png"


def _picture(value, domain, path: str) -> bytes:
    """The picture of a layout or a task, as --png asks: the domain's own drawing."""
    return domain.files.picture(value, _picture_format(path))


def _lacking(args, stage_name: str, selected, checked, domains) -> list[Diagnostic]:
    """E0703 for each scenario whose domain lacks a hook that the stage (and --png of a
    task) needs: refused before any work, at the scenario's `domain` line."""
    from physc.domains.base import MissingCapability, require
    from physc.driver.stages import NEEDS

    picture = ("picture",) if args.png and BY_NAME[stage_name].drawn else ()
    verifying = ("replay",) if args.verify_backend and BY_NAME[stage_name].simulates else ()
    asked = f"--emit {stage_name}" + (" --png" if picture else "") + (" --verify-backend" if verifying else "")
    found = []
    for scenario in selected:
        try:
            require(domains[checked[scenario.name.text].domain], NEEDS[stage_name] + picture + verifying, asked)
        except MissingCapability as error:
            span = scenario.domain.span if scenario.domain else scenario.name.span
            found.append(Diagnostic(error.code, error.message, span, help=error.help))
    return found


def cmd_compile(args) -> int:
    """`physc compile`: the stage asked for, of each scenario selected, printed or written."""
    check_backends(args)
    chosen, fmt = _chosen_stage(args)
    report = reporter(args)
    analysis = analyze(args.file, vocabularies=INSTALLED)
    if analysis.file is None or any(d.is_error for d in analysis.syntax):
        report(args.file, analysis.source, analysis.diagnostics)
        return diagnostics.exit_status(analysis.diagnostics)
    selected = _selected(args, analysis.file)
    many = len(selected) > 1
    spans = [_span(s) for s in selected]

    def concerns_selection(d: Diagnostic) -> bool:
        return d.span is None or any(s.start <= d.span.start < s.end for s in spans)

    relevant = [d for d in analysis.diagnostics if concerns_selection(d)]
    report(args.file, analysis.source, relevant)
    status = diagnostics.exit_status(relevant)
    if status:
        return status
    checked = {s.name: s for s in analysis.scenarios}
    if chosen.name == "level" and many and not args.output:
        raise UsageError("several scenarios make several levels: name a folder with -o")
    _check_outputs(args, many, chosen.name == "level")
    domains = _domains(args, [checked[s.name.text] for s in selected])
    lacking = _lacking(args, chosen.name, selected, checked, domains)
    if lacking:
        report(args.file, analysis.source, lacking)
        return diagnostics.exit_status(lacking)
    outputs, failures, refused = [], [], []
    for index, scenario in enumerate(selected, 1):
        ir = checked[scenario.name.text]
        try:
            value = _compiled(args, chosen, Unit(scenario, ir), domains[ir.domain], f"[{index}/{len(selected)}]", many)
        except Infeasible as error:
            failures.append(no_task(error, scenario))
            continue
        except DomainError as error:  # the domain cannot do what was asked (a picture format it lacks)
            span = scenario.domain.span if scenario.domain else scenario.name.span
            refused.append(Diagnostic(error.code, error.message, span, help=error.help))
            continue
        outputs.append((ir.name, domains[ir.domain], value))
    if failures or refused:
        report(args.file, analysis.source, failures + refused)
    _print_outputs(args, chosen, fmt, outputs, many)
    return diagnostics.exit_status(refused) if refused else EXIT_INFEASIBLE if failures else EXIT_OK


def _span(scenario: ast.Scenario) -> Span:
    """Where a scenario of a parsed file is written (the parser gives every node its span)."""
    assert scenario.span is not None, "a parsed scenario has its span"
    return scenario.span


def _chosen_stage(args) -> tuple[Stage, str]:
    """The stage --emit names and the format it is printed in, with the options that go with it
    checked (--png draws, --task writes, only what a stage makes)."""
    try:
        chosen = stage(args.emit)
    except StageError as error:
        raise UsageError(str(error)) from None
    fmt = args.format or chosen.formats[0]
    if fmt not in chosen.formats:
        raise UsageError(f"the stage '{chosen.name}' can be printed as {' or '.join(chosen.formats)}, not {fmt}")
    if args.png and not chosen.drawn:
        raise UsageError("--png draws a layout or a task: use it with --emit layout, task or level")
    if args.task and not chosen.simulates:
        raise UsageError("--task writes the generated task: use it with --emit level or task")
    return chosen, fmt


def _selected(args, file: ast.File) -> list[ast.Scenario]:
    """The scenarios of the file that -s names (all of them by default); a name the file lacks
    is a usage error with a did-you-mean."""
    available = [s.name.text for s in file.scenarios]
    names = args.scenario or available
    for name in names:
        if name not in available:
            hint = did_you_mean(name, available) or "scenarios: " + ", ".join(available)
            raise UsageError(f"{args.file} has no scenario named '{name}'; {hint}")
    return [s for s in file.scenarios if s.name.text in names]


def _domains(args, scenarios: list[ScenarioIR]) -> dict[str, Domain]:
    """Each domain the scenarios name, in the world and engine asked for: they pass down with it
    to every simulation. --min-robustness is checked against each."""
    domains: dict[str, Domain] = {}
    for ir in scenarios:
        if ir.domain not in domains:
            domains[ir.domain] = bound(load_domain(ir.domain), args.world, args.backend)
            check_min_robustness(args.min_robustness, domains[ir.domain])
    return domains


def _compiled(args, chosen: Stage, unit: Unit, domain: Domain, counter: str, many: bool) -> object:
    """One scenario run to the chosen stage (with a heartbeat and a summary line on stderr when
    it generates a task), its picture written where --png asks, and its task where --task asks.
    Infeasible or DomainError when it makes none."""
    ir = unit.scenario
    generating = chosen.simulates
    heartbeat = Heartbeat(f"{counter} {ir.name}") if generating and not args.quiet else None
    generation = pipeline(
        unit.ast, ir, domain, args.seed, run_settings(args), progress=None if heartbeat is None else heartbeat.update
    )
    if generating and not args.quiet:
        print(f"{counter} {ir.name} (seed {args.seed}): generating…", file=sys.stderr, flush=True)
    assert chosen.run is not None, "stage() hands out only the stages that run"
    # The picture (a simulation of the solution's paths) is part of the work: within the time
    # budget, and where Ctrl-C stops it safely.
    with budget.interruptible(), generation.within_budget(chosen.name), heartbeat or contextlib.nullcontext():
        # Pipeline's cached properties are Run's properties (pyright matches no cached_property to a
        # protocol's property: microsoft/pyright#4343)
        value = chosen.run(unit, cast("Run", generation))
        picture = _picture(value, domain, args.png) if args.png else None
    if generating and not args.quiet:
        assert isinstance(value, Task), "a stage that simulates makes a task"
        print(f"{counter} {ir.name}: {_generated(value)}", file=sys.stderr, flush=True)
    if picture is not None:
        write_atomic(_in_place(args.png, many, ir.name, _picture_format(args.png)), picture)
    if args.task:
        text = json.dumps(to_data(value), indent=2, ensure_ascii=False) + "\n"
        write_atomic(_in_place(args.task, many, ir.name, "json"), text)
    return value


def _generated(task: Task) -> str:
    """What the summary line on stderr says of a generated task: checked, aimed at, robust, cost."""
    checked_text = "validated" if task.validated else "not validated (--no-validate)"
    return (
        f"{checked_text}; solution {aimed_at(task.solution)}; "
        f"{_robustness(task.robustness)}; "
        f"{_layouts(task)}, {task.simulations} simulations, {task.seconds['total']:.2f} s"
    )


def _print_outputs(args, chosen: Stage, fmt: str, outputs: list[tuple[str, Domain, object]], many: bool) -> None:
    """The stage's values, in order: levels as the domain's level files (one per scenario in the
    -o folder), the other stages as one JSON (or dot) text on stdout or in -o."""
    if chosen.name == "level":
        for name, domain, value in outputs:
            assert isinstance(value, Task), "the level stage makes a task"
            text = domain.files.emit_level(value.level)
            if args.output:
                write_atomic(_in_place(args.output, many, name, "xml"), text)
            elif not many:
                sys.stdout.write(text)
        return
    if fmt == "dot":
        text = "".join(cast(Graph, value).to_dot() for _, _, value in outputs)
    else:
        data = [to_data(value) for _, _, value in outputs]
        text = json.dumps(data[0] if len(data) == 1 else data, indent=2, ensure_ascii=False) + "\n"
    if outputs:
        if args.output:
            write_atomic(args.output, text)
        else:
            sys.stdout.write(text)
