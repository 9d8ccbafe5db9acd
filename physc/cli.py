"""The `physc` command line.

Exit statuses (spec section 7): 0 success; 1 the input has errors; 2 usage error
or unreadable file; 3 no task could be generated. An internal error (a bug in
physc) exits with 70 and asks for a report; `--traceback` shows the Python
traceback for developers.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
from typing import Sequence

from physc import __version__, diagnostics
from physc.compiler.stages import STAGES, StageError, Unit, stage
from physc.diagnostics import Diagnostic
from physc.files import write_atomic
from physc.suggest import did_you_mean

EXIT_OK, EXIT_INPUT, EXIT_USAGE, EXIT_INFEASIBLE, EXIT_INTERNAL = 0, 1, 2, 3, 70


class UsageError(Exception):
    pass


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # argparse's own errors: usage, exit 2
        self.print_usage(sys.stderr)
        print(f"{self.prog}: error: {message}", file=sys.stderr)
        raise SystemExit(EXIT_USAGE)


def _reporter(args):
    def use_color() -> bool:
        if args.color == "always":
            return True
        if args.color == "never" or os.environ.get("NO_COLOR"):
            return False
        return sys.stderr.isatty()

    color = use_color()

    def report(analysis_path: str, source, found: Sequence[Diagnostic]) -> None:
        for diagnostic in found:
            print(diagnostics.render(diagnostic, source, analysis_path, color=color), file=sys.stderr)

    return report


def _summary(errors: int, warnings: int, files: int) -> str:
    def plural(n, word):
        return f"{n} {word}{'' if n == 1 else 's'}"

    return f"{plural(errors, 'error')}, {plural(warnings, 'warning')} in {plural(files, 'file')}"


# ---- physc check ---------------------------------------------------------------
def cmd_check(args) -> int:
    from physc.dsl.frontend import analyze

    status = EXIT_OK
    errors = warnings = 0
    as_json = []
    report = _reporter(args)
    for path in args.files:
        analysis = analyze(path)
        found = analysis.diagnostics
        status = max(status, diagnostics.exit_status(found))
        errors += sum(d.is_error for d in found)
        warnings += sum(not d.is_error for d in found)
        if args.format == "json":
            as_json += [diagnostics.to_json(d, path) for d in found]
        else:
            report(path, analysis.source, found)
    if args.format == "json":
        print(json.dumps(as_json, indent=2, ensure_ascii=False))
    elif not args.quiet:
        print(_summary(errors, warnings, len(args.files)), file=sys.stderr)
    return status


# ---- physc fmt -----------------------------------------------------------------
def cmd_fmt(args) -> int:
    from physc.dsl.fmt import format_file
    from physc.dsl.frontend import analyze

    if args.write and "-" in args.files:
        raise UsageError("--write cannot rewrite standard input")
    status = EXIT_OK
    report = _reporter(args)
    changed = []
    for path in args.files:
        analysis = analyze(path, check=False)
        if analysis.file is None or any(d.is_error for d in analysis.syntax):
            report(path, analysis.source, analysis.diagnostics)
            status = max(status, diagnostics.exit_status(analysis.diagnostics))
            continue
        formatted = format_file(analysis.file, analysis.source)
        if args.check:
            if formatted != analysis.source.text:
                changed.append(path)
                print(f"would reformat {path}", file=sys.stderr)
        elif args.write:
            if formatted != analysis.source.text:
                write_atomic(path, formatted)
                changed.append(path)
                print(f"reformatted {path}", file=sys.stderr)
        else:
            sys.stdout.write(formatted)
    if args.check and changed:
        status = max(status, EXIT_INPUT)
    return status


# ---- physc compile ----------------------------------------------------------------
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
    report = _reporter(args)
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


# ---- physc domains -----------------------------------------------------------------
def cmd_domains(args) -> int:
    from physc.domains import DomainError, installed_domains, load_domain

    names = list(installed_domains())
    if args.name:
        unknown = [n for n in args.name if n not in names]
        if unknown:
            hint = did_you_mean(unknown[0], names) or "installed domains: " + (", ".join(names) or "none")
            raise UsageError(f"the domain '{unknown[0]}' is not installed; {hint}")
        names = args.name
    loaded = []
    for name in names:
        try:
            loaded.append(load_domain(name))
        except DomainError as error:
            print(f"physc: error[{error.code}]: {error.message}", file=sys.stderr)
            return EXIT_USAGE
    if args.json:
        from physc.serialize import to_data

        data = [{"name": d.name, "description": d.description, "vocabulary": to_data(d.vocabulary)} for d in loaded]
        print(json.dumps(data, indent=2, ensure_ascii=False))
        return EXIT_OK
    if not loaded:
        print("no domains installed (physc.domains entry points)")
    for index, domain in enumerate(loaded):
        if index:
            print()
        print(_describe_domain(domain))
    return EXIT_OK


def _describe_domain(domain) -> str:
    vocabulary = domain.vocabulary
    lines = [f"{domain.name}: {domain.description}", "  object terms:"]
    for term in vocabulary.object_terms:
        label = term.name + (f" ({term.abbreviation})" if term.abbreviation else "")
        lines.append(f"    {label:<34} {' | '.join(term.concrete)}")
    for kind in ("interaction", "restriction"):
        lines.append(f"  {kind} terms:")
        for term in vocabulary.terms:
            if term.kind == kind:
                lines.append(f"    {term.usage():<58} {term.description}")
    statics = [c.name for c in vocabulary.concrete_objects if c.static]
    lines.append(f"  static objects: {', '.join(statics)}")
    aliases = "; ".join(f"{a} = {' | '.join(v)}" for a, v in vocabulary.direction_aliases.items())
    lines.append(f"  directions: {', '.join(vocabulary.directions)}" + (f" ({aliases})" if aliases else ""))
    lines.append(f"  the player moves: {vocabulary.player}; goals (all must be destroyed): {vocabulary.goal}")
    return "\n".join(lines)


# ---- the parser -----------------------------------------------------------------------
def build_parser() -> argparse.ArgumentParser:
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--color", choices=("auto", "always", "never"), default="auto", help="colour diagnostics")
    common.add_argument("--traceback", action="store_true", help="show Python tracebacks of internal errors")

    parser = _Parser(
        prog="physc",
        description="Compile physical scenarios (.phys) into physics tasks.",
        epilog="exit status: 0 ok, 1 input errors, 2 usage or unreadable file, 3 no task could be generated",
        parents=[common],
    )
    parser.add_argument("--version", action="version", version=f"physc {__version__}")
    commands = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    check = commands.add_parser("check", parents=[common], help="check .phys files and report every problem")
    check.add_argument("files", nargs="+", metavar="FILE", help="files to check ('-' reads standard input)")
    check.add_argument("--format", choices=("text", "json"), default="text", help="diagnostic format")
    check.add_argument("-q", "--quiet", action="store_true", help="no summary line")
    check.set_defaults(run=cmd_check)

    fmt = commands.add_parser("fmt", parents=[common], help="print files in the canonical block form")
    fmt.add_argument("files", nargs="+", metavar="FILE", help="files to format ('-' reads standard input)")
    mode = fmt.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="exit 1 if a file is not canonical; change nothing")
    mode.add_argument("--write", action="store_true", help="rewrite the files in place")
    fmt.set_defaults(run=cmd_fmt)

    stage_names = ", ".join(s.name for s in STAGES)
    compile_ = commands.add_parser("compile", parents=[common], help="compile a scenario (--emit a stage's IR)")
    compile_.add_argument("file", metavar="FILE")
    compile_.add_argument(
        "-s", "--scenario", action="append", metavar="NAME", help="a scenario of the file (repeatable; default all)"
    )
    compile_.add_argument("--emit", metavar="STAGE", default="level", help=f"the stage to print: {stage_names}")
    compile_.add_argument("-o", "--output", metavar="PATH", help="write the output here instead of stdout")
    compile_.add_argument("--seed", type=int, default=0, metavar="N", help="the random seed (default 0)")
    compile_.add_argument(
        "--budget", type=int, default=50_000, metavar="N", help="clause choices the layout search may try (default 50000)"
    )
    compile_.add_argument("--format", choices=("json", "dot"), default="json", help="dot: Graphviz, for graph stages")
    compile_.add_argument("--png", metavar="PATH", help="with --emit layout: draw the layout (.png or .svg)")
    compile_.set_defaults(run=cmd_compile)

    domains = commands.add_parser("domains", parents=[common], help="list installed domains and their vocabulary")
    domains.add_argument("name", nargs="*", help="only these domains")
    domains.add_argument("--json", action="store_true", help="machine-readable output")
    domains.set_defaults(run=cmd_domains)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if args.command is None:
        parser.print_help(sys.stderr)
        return EXIT_USAGE
    try:
        return args.run(args)
    except UsageError as error:
        print(f"physc {args.command}: error: {error}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        # The reader went away (`physc … | head`): not an error of ours.
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return EXIT_OK
    except Exception as error:  # a bug in physc: never a bare traceback for users
        if args.traceback:
            raise
        print(
            f"physc: internal error: {type(error).__name__}: {error}\n"
            "This is a bug in physc. Please report it with the input that caused it; "
            "run again with --traceback for the details.",
            file=sys.stderr,
        )
        return EXIT_INTERNAL
