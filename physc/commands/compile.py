"""`physc compile`: run the compiler to a stage and print its IR."""

from __future__ import annotations

import json
import sys

from physc import diagnostics
from physc.commands.common import (
    EXIT_INFEASIBLE,
    EXIT_OK,
    UsageError,
    reporter,
)
from physc.compiler.stages import StageError, Unit, stage
from physc.diagnostics import Diagnostic
from physc.files import write_atomic
from physc.suggest import did_you_mean


def _infeasible(error, scenario) -> Diagnostic:
    """An Infeasible answer as a diagnostic that points back at the source."""
    from physc.diagnostics import Label

    notes = []
    for edge in error.conflicts:
        for why in edge.provenance:
            if why.span is not None:
                notes.append(Label(why.span, f"{edge.text()} comes from {why.rule} `{why.text}`"))
            else:
                notes.append(Label(scenario.name.span, f"{edge.text()} comes from the {why.rule} rule: {why.text}"))
    code = "E0802" if error.budget else "E0801"
    tried = f"; {error.tried} conjunctions tried" if error.tried else ""
    help_text = (
        "these layout constraints cannot all hold: change or remove one of the terms they come from"
        if error.conflicts
        else "try another --seed or a larger --budget, or simplify the scenario"
    )
    return Diagnostic(
        code,
        f"no task for scenario '{scenario.name.text}': {error.message} (stage {error.stage}{tried})",
        scenario.name.span,
        help=help_text,
        notes=tuple(notes),
    )


def cmd_compile(args) -> int:
    from physc.compiler.infeasible import Infeasible
    from physc.compiler.pipeline import Pipeline
    from physc.domains import load_domain
    from physc.dsl.frontend import analyze
    from physc.serialize import to_data

    try:
        chosen = stage(args.emit)
    except StageError as error:
        raise UsageError(str(error)) from None
    if args.format not in chosen.formats:
        raise UsageError(f"the stage '{chosen.name}' can be printed as {' or '.join(chosen.formats)}, not {args.format}")
    if args.png and chosen.name != "layout":
        raise UsageError("--png draws a layout: use it with --emit layout")
    report = reporter(args)
    analysis = analyze(args.file)
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
    if args.png and len(selected) != 1:
        raise UsageError("--png draws one scenario: name it with -s NAME")
    spans = [s.span for s in selected]

    def concerns_selection(d: Diagnostic) -> bool:
        return d.span is None or any(s.start <= d.span.start < s.end for s in spans)

    relevant = [d for d in analysis.diagnostics if concerns_selection(d)]
    report(args.file, analysis.source, relevant)
    status = diagnostics.exit_status(relevant)
    if status:
        return status
    checked = {s.name: s for s in analysis.scenarios}
    outputs, failures = [], []
    for scenario in selected:
        ir = checked[scenario.name.text]
        pipeline = Pipeline(load_domain(ir.domain), ir, args.seed, args.budget)
        try:
            outputs.append(chosen.run(Unit(scenario, ir), pipeline))
        except Infeasible as error:
            failures.append(_infeasible(error, scenario))
    if failures:
        report(args.file, analysis.source, failures)
        return EXIT_INFEASIBLE
    if args.format == "dot":
        text = "".join(value.to_dot() for value in outputs)
    else:
        data = [to_data(value) for value in outputs]
        text = json.dumps(data[0] if len(data) == 1 else data, indent=2, ensure_ascii=False) + "\n"
    if args.png:
        from physc.domains.angrybirds.picture import render

        fmt = "svg" if args.png.lower().endswith(".svg") else "png"
        write_atomic(args.png, render(outputs[0], fmt))
    if args.output:
        write_atomic(args.output, text)
    else:
        sys.stdout.write(text)
    return EXIT_OK
