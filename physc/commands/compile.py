"""`physc compile`: run the compiler to a stage and print its IR."""

from __future__ import annotations

import contextlib
import json
import os
import sys

from physc import budget, diagnostics
from physc.api.compiling import no_task, pipeline
from physc.commands.common import (
    EXIT_INFEASIBLE,
    EXIT_OK,
    UsageError,
    check_backends,
    check_min_robustness,
    reporter,
)
from physc.commands.options import run_settings
from physc.commands.progress import Heartbeat
from physc.compiler.task import given_up_summary
from physc.diagnostics import Diagnostic
from physc.domains.base import DomainError
from physc.driver.stages import BY_NAME, StageError, Unit, stage
from physc.files import check_output, ensure_folder, write_atomic
from physc.suggest import did_you_mean

FILE_SUFFIXES = {"-o": (".xml", ".json", ".dot"), "--task": (".json",), "--png": (".png", ".svg")}


def _destination(path: str | None, many: bool, name: str, suffix: str) -> str | None:
    """A file path; with several scenarios, `path` is a folder and the file is NAME.suffix."""
    if path is None:
        return None
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
    from physc.compiler.infeasible import Infeasible
    from physc.domains import bound, load_domain
    from physc.domains.words import INSTALLED
    from physc.dsl.frontend import analyze
    from physc.serialize import to_data

    check_backends(args)
    try:
        chosen = stage(args.emit)
    except StageError as error:
        raise UsageError(str(error)) from None
    fmt = args.format or chosen.formats[0]
    if fmt not in chosen.formats:
        raise UsageError(f"the stage '{chosen.name}' can be printed as {' or '.join(chosen.formats)}, not {fmt}")
    generating = chosen.simulates
    if args.png and not chosen.drawn:
        raise UsageError("--png draws a layout or a task: use it with --emit layout, task or level")
    if args.task and not generating:
        raise UsageError("--task writes the generated task: use it with --emit level or task")
    report = reporter(args)
    analysis = analyze(args.file, vocabularies=INSTALLED)
    if analysis.file is None or any(d.is_error for d in analysis.syntax):
        report(args.file, analysis.source, analysis.diagnostics)
        return diagnostics.exit_status(analysis.diagnostics)
    available = [s.name.text for s in analysis.file.scenarios]
    names = args.scenario or available
    for name in names:
        if name not in available:
            hint = did_you_mean(name, available) or "scenarios: " + ", ".join(available)
            raise UsageError(f"{args.file} has no scenario named '{name}'; {hint}")
    selected = [s for s in analysis.file.scenarios if s.name.text in names]
    many = len(selected) > 1
    spans = [s.span for s in selected]

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
    domains = {}
    for scenario in selected:
        name = checked[scenario.name.text].domain
        if name not in domains:
            # The domain in the world and engine asked for: they pass down with it to every simulation.
            domains[name] = bound(load_domain(name), args.world, args.backend)
            check_min_robustness(args.min_robustness, domains[name])
    lacking = _lacking(args, chosen.name, selected, checked, domains)
    if lacking:
        report(args.file, analysis.source, lacking)
        return diagnostics.exit_status(lacking)
    outputs, failures, refused = [], [], []
    for index, scenario in enumerate(selected, 1):
        ir = checked[scenario.name.text]
        domain = domains[ir.domain]
        heartbeat = Heartbeat(f"[{index}/{len(selected)}] {ir.name}") if generating and not args.quiet else None
        generation = pipeline(
            scenario,
            ir,
            domain,
            args.seed,
            run_settings(args),
            progress=None if heartbeat is None else heartbeat.update,
        )
        if generating and not args.quiet:
            print(f"[{index}/{len(selected)}] {ir.name} (seed {args.seed}): generating…", file=sys.stderr, flush=True)
        try:
            # The picture (a simulation of the solution's paths) is part of the work: within
            # the time budget, and where Ctrl-C stops it safely.
            with budget.interruptible(), generation.within_budget(chosen.name), heartbeat or contextlib.nullcontext():
                value = chosen.run(Unit(scenario, ir), generation)
                picture = _picture(value, domain, args.png) if args.png else None
        except Infeasible as error:
            failures.append(no_task(error, scenario))
            continue
        except DomainError as error:  # the domain cannot do what was asked (a picture format it lacks)
            span = scenario.domain.span if scenario.domain else scenario.name.span
            refused.append(Diagnostic(error.code, error.message, span, help=error.help))
            continue
        outputs.append((ir.name, domain, value))
        if generating and not args.quiet:
            checked_text = "validated" if value.validated else "not validated (--no-validate)"
            print(
                f"[{index}/{len(selected)}] {ir.name}: {checked_text}; solution {value.solution.aimed_at}; "
                f"{_robustness(value.robustness)}; "
                f"{_layouts(value)}, {value.simulations} simulations, {value.seconds['total']:.2f} s",
                file=sys.stderr,
                flush=True,
            )
        if picture is not None:
            write_atomic(_destination(args.png, many, ir.name, _picture_format(args.png)), picture)
        if args.task:
            write_atomic(
                _destination(args.task, many, ir.name, "json"),
                json.dumps(to_data(value), indent=2, ensure_ascii=False) + "\n",
            )
    if failures or refused:
        report(args.file, analysis.source, failures + refused)
    done = diagnostics.exit_status(refused) if refused else EXIT_INFEASIBLE if failures else EXIT_OK
    if chosen.name == "level":
        for name, domain, value in outputs:
            text = domain.files.emit_level(value.level)
            if args.output:
                write_atomic(_destination(args.output, many, name, "xml"), text)
            elif not many:
                sys.stdout.write(text)
        return done
    if fmt == "dot":
        text = "".join(value.to_dot() for _, _, value in outputs)
    else:
        data = [to_data(value) for _, _, value in outputs]
        text = json.dumps(data[0] if len(data) == 1 else data, indent=2, ensure_ascii=False) + "\n"
    if outputs:
        if args.output:
            write_atomic(args.output, text)
        else:
            sys.stdout.write(text)
    return done
