"""Go to definition, find references and document symbols, from the syntax tree.

An object is defined by its declaration, or, when its type comes from its name, by its first use.
Its references are every declaration and argument of its scenario that names it; names are
scenario-local, so the same name in another scenario is another object.
"""

from __future__ import annotations

from lsprotocol import types

from physc.diagnostics import Span
from physc.dsl import ast
from physc.dsl.fmt import format_term


def scenario_at(file: ast.File, offset: int) -> ast.Scenario | None:
    for scenario in file.scenarios:
        if scenario.span is not None and scenario.span.start <= offset <= scenario.span.end:
            return scenario
    return None


def _argument_names(scenario: ast.Scenario):
    for term in scenario.interactions + scenario.restrictions:
        for argument in term.arguments:
            yield from argument.alternatives


def name_at(scenario: ast.Scenario, offset: int) -> ast.Name | None:
    """The object name (a declaration's or an argument's) whose span holds `offset`."""
    names = [d.name for d in scenario.objects] + list(_argument_names(scenario))
    return next((n for n in names if ast.located(n.span).start <= offset <= ast.located(n.span).end), None)


def occurrences(scenario: ast.Scenario, name: str) -> tuple[list[Span], list[Span]]:
    """The spans of the declarations of `name` and of its uses as an argument, in the scenario."""
    declarations = [ast.located(d.name.span) for d in scenario.objects if d.name.text == name]
    uses = [ast.located(n.span) for n in _argument_names(scenario) if n.text == name]
    return declarations, uses


def definition(file: ast.File, offset: int) -> Span | None:
    scenario = scenario_at(file, offset)
    found = None if scenario is None else name_at(scenario, offset)
    if scenario is None or found is None:
        return None
    declarations, uses = occurrences(scenario, found.text)
    return (declarations or uses or [None])[0]


def references(file: ast.File, offset: int, include_declaration: bool) -> list[Span]:
    scenario = scenario_at(file, offset)
    found = None if scenario is None else name_at(scenario, offset)
    if scenario is None or found is None:
        return []
    declarations, uses = occurrences(scenario, found.text)
    return (declarations if include_declaration else []) + uses


def symbols(file: ast.File, to_range) -> list[types.DocumentSymbol]:
    """One symbol per scenario, with its declared objects, interactions and restrictions inside."""
    Kind = types.SymbolKind
    found = []
    for scenario in file.scenarios:
        children = [
            types.DocumentSymbol(
                name=d.name.text,
                detail=d.term.text,
                kind=Kind.Variable,
                range=to_range(d.span),
                selection_range=to_range(d.name.span),
            )
            for d in scenario.objects
        ]
        for kind, terms in ((Kind.Event, scenario.interactions), (Kind.Property, scenario.restrictions)):
            children += [
                types.DocumentSymbol(
                    name=format_term(t), kind=kind, range=to_range(t.span), selection_range=to_range(t.name.span)
                )
                for t in terms
            ]
        found.append(
            types.DocumentSymbol(
                name=scenario.name.text,
                detail=scenario.title.value if scenario.title else None,
                kind=Kind.Module,
                range=to_range(scenario.span),
                selection_range=to_range(scenario.name.span),
                children=children,
            )
        )
    return found
