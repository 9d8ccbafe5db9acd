"""The front end as one call: read, parse and check a `.phys` file against the vocabularies it is handed."""

from __future__ import annotations

from collections.abc import Iterable

import attrs

from physc.diagnostics import Diagnostic, SourceText, sort_key
from physc.dsl import ast
from physc.dsl.check import check_file
from physc.dsl.fmt import format_file
from physc.dsl.parser import parse_source, read_source
from physc.dsl.scenario import ScenarioIR
from physc.dsl.vocabularies import Vocabularies


@attrs.frozen
class Analysis:
    path: str
    source: SourceText | None
    file: ast.File | None
    scenarios: tuple[ScenarioIR, ...]
    syntax: tuple[Diagnostic, ...]  # reading and parsing
    semantic: tuple[Diagnostic, ...]  # static checks

    @property
    def diagnostics(self) -> tuple[Diagnostic, ...]:
        return tuple(sorted(self.syntax + self.semantic, key=sort_key))


def analyze(path: str, vocabularies: Vocabularies | None, check: bool = True) -> Analysis:
    """Read and parse `path` ('-' for standard input); with `check`, run the static checks
    against `vocabularies` (the layers above hand them: `physc.domains.words.INSTALLED`; None
    only without `check`, which reads none)."""
    read = read_source(path)
    if read.source is None or read.diagnostics:
        return Analysis(path, read.source, None, (), read.diagnostics, ())
    return _analyzed(path, read.source, check, vocabularies)


def analyze_text(name: str, text: str, vocabularies: Vocabularies) -> Analysis:
    """`analyze` of a scenario held in memory (a task file's `source`), named `name` in
    diagnostics."""
    return _analyzed(name, SourceText(name, text), True, vocabularies)


def scenario_in(name: str, text: str, scenario: str, vocabularies: Vocabularies) -> ScenarioIR:
    """The checked scenario `scenario` of `text` (a batch job's own text, named `name` as its
    file is): a worker reads the scenario it was sent, never a file, which on another machine
    or in another folder is missing or another."""
    return next(s for s in analyze_text(name, text, vocabularies).scenarios if s.name == scenario)


def _analyzed(path: str, source: SourceText, check: bool, vocabularies: Vocabularies | None) -> Analysis:
    parsed = parse_source(source)
    if not check:
        return Analysis(path, parsed.source, parsed.file, (), parsed.diagnostics, ())
    if vocabularies is None:
        raise TypeError("checking needs the vocabularies to check against")
    checked = check_file(parsed.file, path, vocabularies=vocabularies)
    return Analysis(path, parsed.source, parsed.file, checked.scenarios, parsed.diagnostics, checked.diagnostics)


def analyze_files(
    paths: Iterable[str], vocabularies: Vocabularies
) -> tuple[list[tuple[str, ScenarioIR, str]], list[tuple[str, Analysis, list[Diagnostic]]]]:
    """The checked scenarios of several files, each with its file's path and its own text in
    block form (what a worker on another machine is sent), in order; and, for each file with
    errors, (path, its analysis, its errors): a batch command (eval, generate) reports those and
    runs nothing."""
    scenarios: list[tuple[str, ScenarioIR, str]] = []
    problems: list[tuple[str, Analysis, list[Diagnostic]]] = []
    for path in paths:
        analysis = analyze(path, vocabularies)
        errors = [d for d in analysis.diagnostics if d.is_error]
        if errors:
            problems.append((path, analysis, errors))
            continue
        assert analysis.file is not None  # a file without errors was read and parsed
        written = {s.name.text: format_file(ast.File((s,))) for s in analysis.file.scenarios}
        scenarios += [(path, scenario, written[scenario.name]) for scenario in analysis.scenarios]
    return scenarios, problems
