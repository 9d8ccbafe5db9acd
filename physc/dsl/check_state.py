"""What the checks of one scenario share: the scenario, its vocabulary, the objects known so far, and
the diagnostics with the help texts that wait for the whole scenario.

`ScenarioState` is the base of the scenario checker's parts (physc/dsl/check.py: the terms;
objects.py: declarations and object arguments; sequence.py: causality, goals and restrictions),
so each part reads and writes the same state, and reports through the same `error`.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import NamedTuple

import attrs

from physc.diagnostics import Diagnostic, Fix, Label, Span
from physc.dsl import ast
from physc.dsl.fixes import Advice, Use
from physc.dsl.vocabularies import Parameter, TermSignature, Vocabulary


@attrs.define
class KnownObject:
    """An object of the scenario as the checks know it: declared, or typed by its name."""

    name: str
    term: str
    concrete: tuple[str, ...]
    static: bool
    declared: bool
    span: Span
    used: bool = False
    declaration: Span | None = None  # the whole declaration, for a quick fix that rewrites it
    materials: tuple[str, ...] = ()  # the materials declared (version 2; none: any it may be made of)


@attrs.define
class Resolved:
    """A term whose arguments all resolved: ready for the causal checks."""

    node: ast.Term
    signature: TermSignature
    objects: tuple[str, ...]
    object_spans: tuple[Span, ...]
    directions: tuple[str, ...]
    direction_span: Span | None


class Immobile(NamedTuple):
    """An E0203 for a static object where one that moves is needed; its help names an object in
    motion at that point of the sequence, so it is written once the sequence is known."""

    diagnostic: int  # its index
    position: int | None  # of the interaction in the sequence (None: a restriction)
    parameter: Parameter
    name: str  # the static object


class ScenarioState:
    """The state of the checks of one scenario, and how they report an error."""

    def __init__(self, scenario: ast.Scenario, domain: str, vocabulary: Vocabulary, path: str):
        self.scenario = scenario
        self.domain = domain
        self.vocabulary = vocabulary
        self.path = path
        self.diagnostics: list[Diagnostic] = []
        self.objects: dict[str, KnownObject] = {}
        self.unknown: set[str] = set()
        self.uses: dict[str, list[Use]] = {}  # every (term, parameter) an object appears as
        # E0203 for a parameter's object term: (diagnostic index, object, term asked for); the help
        # is written once every use of the object is known (fixes.fit_help).
        self.misfits: list[tuple[int, KnownObject, str]] = []
        self.immobile: list[Immobile] = []
        self.position: int | None = None  # of the interaction being resolved
        self.helps: dict[int, Advice] = {}
        self.fresh_names: dict[str, str] = {}
        # E0301: (diagnostic index, first use, the names it may be a misspelling of) by name; its
        # quick fixes rename every use, found in the tree once the scenario is resolved.
        self.misspelt: dict[str, tuple[int, ast.Name, list[str]]] = {}
        self.comparisons = 0

    def error(
        self,
        code: str,
        message: str,
        span: Span | None,
        help: str | None = None,
        notes: Iterable[Label] = (),
        fixes: Iterable[Fix] = (),
    ) -> None:
        self.diagnostics.append(Diagnostic(code, message, span, help=help, notes=tuple(notes), fixes=tuple(fixes)))

    def advise(self, code: str, message: str, span: Span | None, advice: Advice, term: ast.Term | None = None) -> None:
        """An error whose help is `advice`, with its proposals as quick fixes; `term` is the term
        the error is about (where `advice.before` goes)."""
        self.error(code, message, span, help=advice.text, fixes=self.fixes(advice, span, term))

    def fixes(
        self, advice: Advice, span: Span | None, term: ast.Term | None = None, declaration: Span | None = None
    ) -> tuple[Fix, ...]:
        interactions = self.scenario.interactions
        return advice.fixes(span, term, declaration, interactions[-1] if interactions else None)
