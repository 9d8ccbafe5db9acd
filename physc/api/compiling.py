"""Compiling a scenario to a task from Python: what `physc check` and `physc compile` do.

A scenario is given as a path (a `pathlib.Path`, or a `str` without a newline or a brace)
or as its text. `check` gives its diagnostics; `compile` makes a task of one of its
scenarios, in a chosen world and physics engine, and returns the task (physc.compiler.task.Task:
its level, intended solution, the interactions that solution realises, and the seconds each
stage took). `physc compile` runs the same functions (`pipeline`, `no_task`).
"""

from __future__ import annotations

import os
from pathlib import Path

from physc.api.errors import NoTask, ScenarioError
from physc.compiler.infeasible import Exhausted, Infeasible, readable
from physc.compiler.task import Task
from physc.diagnostics import Diagnostic, Label
from physc.driver.run_settings import RunSettings, overridden

__all__ = ["check", "compile", "scenarios"]

# What would help when a budget ran out (Infeasible.budget names it).
BUDGET_HELP = {
    Exhausted.CLAUSES: "the layout search's clause choices ran out: try a larger --clause-budget or another --seed, or"
    " simplify the scenario",
    Exhausted.LAYOUTS: "every layout allowed was tried: allow more with --layouts (and a larger --time-budget), or try"
    " another --seed",
    Exhausted.TIME: "the time ran out before every layout allowed was tried: more time may help (--time-budget), or"
    " another --seed",
    Exhausted.ALLOWED: "every layout the scenario's constraints allow was tried: more time or layouts cannot help;"
    " another --seed draws other shapes, or change the scenario (or the world, where one is named above)",
    Exhausted.PLACEMENTS: "no placement of the consistent conjunctions worked: try another --seed, or simplify the"
    " scenario",
    Exhausted.SIZE: "split the chain into shorter scenarios; the earlier stages (--emit layout-graph, qsr) still work",
    Exhausted.VERSION: "physc check warns of it (W0302); the earlier stages (--emit layout-graph, qsr) still work",
}


def _analysis(source: str | os.PathLike):
    """The analysis of a scenario path or text (physc.dsl.frontend.Analysis)."""
    from physc.domains.words import INSTALLED
    from physc.dsl.frontend import analyze, analyze_text

    if isinstance(source, os.PathLike) or (isinstance(source, str) and not any(c in source for c in "\n{")):
        path = os.fspath(source)
        if not Path(path).is_file():
            raise ScenarioError((), None, path, f"{path}: no such scenario file (a scenario's text holds a '{{')")
        return analyze(path, INSTALLED)
    if not isinstance(source, str):
        raise TypeError(f"a scenario is a path or its text, not a {type(source).__name__}")
    return analyze_text("<scenario>", source, INSTALLED)


def check(source: str | os.PathLike) -> list[Diagnostic]:
    """Every error and warning of the scenario file or text, as `physc check` reports them
    (physc.diagnostics.Diagnostic: code, message, span, help), in source order."""
    return list(_analysis(source).diagnostics)


def scenarios(source: str | os.PathLike) -> list[str]:
    """The names of the scenarios of a file or text, in order (ScenarioError if it does not parse)."""
    analysis = _analysis(source)
    if analysis.file is None or any(d.is_error for d in analysis.syntax):
        raise ScenarioError(analysis.diagnostics, analysis.source, analysis.path)
    return [s.name.text for s in analysis.file.scenarios]


def selected(source: str | os.PathLike, scenario: str | None):
    """(the scenario's AST, its checked IR, the analysis) of the one scenario `scenario` names
    (None: the file's only scenario); ScenarioError for errors in it or a name not there."""
    from physc.suggest import did_you_mean

    analysis = _analysis(source)
    if analysis.file is None or any(d.is_error for d in analysis.syntax):
        raise ScenarioError(analysis.diagnostics, analysis.source, analysis.path)
    names = [s.name.text for s in analysis.file.scenarios]
    if scenario is None and len(names) != 1:
        raise ScenarioError(
            (),
            analysis.source,
            analysis.path,
            f"{analysis.path} holds {len(names)} scenarios ({', '.join(names)}): name one",
        )
    name = scenario if scenario is not None else names[0]
    if name not in names:
        hint = did_you_mean(name, names) or "scenarios: " + ", ".join(names)
        raise ScenarioError(
            (), analysis.source, analysis.path, f"{analysis.path} has no scenario named '{name}'; {hint}"
        )
    ast_node = next(s for s in analysis.file.scenarios if s.name.text == name)
    where = ast_node.span
    assert where is not None, "a parsed scenario has its span"
    own = [d for d in analysis.diagnostics if d.span is None or where.start <= d.span.start < where.end]
    if any(d.is_error for d in own):
        raise ScenarioError(tuple(own), analysis.source, analysis.path)
    ir = next(s for s in analysis.scenarios if s.name == name)
    return ast_node, ir, analysis


def check_min_robustness(value: int | None, domain, name: str = "min_robustness") -> None:
    """A fallback's least number of noisy replays passed (`name`: how the caller calls it)
    counts the domain's replays: from 1 to their number (ValueError otherwise)."""
    replays = domain.robustness_replays
    if value is not None and replays is not None and not 1 <= value <= replays:
        raise ValueError(
            f"{name} takes a whole number from 1 to {replays} (the noisy replays of domain '{domain.name}'),"
            f" not {value}"
        )


def pipeline(scenario_ast, ir, domain, seed: int = 0, settings=None, progress=None):
    """The generation pipeline (physc.driver.pipeline.Pipeline) of one checked scenario in
    `domain` (bound to its world and engine) under the run's `settings` (a RunSettings; None:
    the defaults), with the scenario's block form as the task's source."""
    from physc.driver.pipeline import Pipeline
    from physc.dsl import ast
    from physc.dsl.fmt import format_file

    return Pipeline(domain, ir, seed, settings or RunSettings(), format_file(ast.File((scenario_ast,))), progress)


def no_task(error: Infeasible, scenario_ast) -> Diagnostic:
    """An Infeasible answer as a diagnostic that points back at the scenario's source (E0801–E0804)."""
    notes = []
    for edge in error.conflicts:
        for why in edge.provenance:
            if why.span is not None:
                notes.append(Label(why.span, f"{edge.text()} comes from {why.rule} `{why.text}`"))
            else:
                notes.append(Label(scenario_ast.name.span, f"{edge.text()} comes from the {why.rule} rule: {why.text}"))
    codes = {Exhausted.SIZE: "E0803", Exhausted.VERSION: "E0804"}
    code = "E0801" if error.budget is None else codes.get(error.budget, "E0802")
    tried = (
        f"; {readable(error.tried)} conjunctions tried" if error.tried and "conjunctions" not in error.message else ""
    )
    if error.conflicts:
        help_text = "these layout constraints cannot all hold: change or remove one of the terms they come from"
    else:
        fallback = "try another --seed, or simplify the scenario"
        help_text = fallback if error.budget is None else BUDGET_HELP.get(error.budget, fallback)
    return Diagnostic(
        code,
        f"no task for scenario '{scenario_ast.name.text}': {error.message} (stage {error.stage}{tried})",
        scenario_ast.name.span,
        help=help_text,
        notes=tuple(notes),
    )


def compile(  # the library's verb is the command's, though it shadows the builtin
    source: str | os.PathLike,
    scenario: str | None = None,
    *,
    seed: int = 0,
    world: str | None = None,
    backend: str | None = None,
    settings: RunSettings | None = None,
    progress=None,
    **overrides,
) -> Task:
    """The task of a scenario (`physc compile FILE -s NAME --seed S`): `source` is a .phys
    path or a scenario's text, `scenario` the name of one of its scenarios (None: its only
    one). `world` and `backend` name where the task is made (None: the domain's default world,
    and box2d). `settings` is the run's RunSettings (None: the defaults), and any of its fields
    given as a keyword overrides it (`time_budget=60`, `min_robustness=4`: `physc compile`'s
    options of the same names). `progress`, if given, is called with a short text as the
    search advances.

    Raises ScenarioError for a scenario with errors, NoTask when no task comes of it within
    the budgets, physc.domains.base.DomainError (a PhyscError's sibling, with a code) for a
    domain that is not installed or cannot make tasks, physc.worlds.WorldError or
    physc.backends.BackendError for a world or engine that is not there."""
    from physc.domains import bound, load_domain
    from physc.domains.base import require
    from physc.driver.stages import NEEDS

    settings = overridden(settings, "compile", **overrides)
    scenario_ast, ir, _ = selected(source, scenario)
    domain = bound(load_domain(ir.domain), world, backend)
    check_min_robustness(settings.min_robustness, domain)
    require(domain, NEEDS["task"] + (("replay",) if settings.verify_backend else ()), "compile")
    run = pipeline(scenario_ast, ir, domain, seed, settings, progress)
    try:
        with run.within_budget("task"):
            return run.task
    except Infeasible as error:
        raise NoTask(no_task(error, scenario_ast)) from None
