"""Static checks of `.phys` scenarios (spec section 5) against a domain's vocabulary.

`check_file` turns an AST into Scenario IRs and diagnostics. Every error of a
file is reported; a scenario with errors yields no IR. The checks know no
domain words: term signatures say which parameters act, are set in motion or
are destroyed, which restriction narrows which interaction, and so on.
"""

from __future__ import annotations

import attrs

from physc.diagnostics import Diagnostic, Label, Span
from physc.dsl import ast
from physc.dsl.check_state import Resolved
from physc.dsl.fixes import replacements, suggestion
from physc.dsl.fmt import format_term
from physc.dsl.scenario import ObjectIR, ScenarioIR, TermIR
from physc.dsl.sequence import SequenceChecks
from physc.dsl.vocabularies import (
    DIRECTION,
    INTERACTION,
    RESTRICTION,
    Parameter,
    TermSignature,
    Vocabularies,
    VocabularyError,
)
from physc.gc_pause import gc_paused


@attrs.frozen
class CheckResult:
    scenarios: tuple[ScenarioIR, ...]
    diagnostics: tuple[Diagnostic, ...]


def check_file(file: ast.File, path: str = "", *, vocabularies: Vocabularies) -> CheckResult:
    """The scenarios of `file` checked against the `vocabularies` they are handed (the layers
    above build them: `physc.domains.words.INSTALLED`)."""
    with gc_paused():
        return _check_file(file, path, vocabularies)


def _check_file(file: ast.File, path: str, vocabularies: Vocabularies) -> CheckResult:
    diagnostics: list[Diagnostic] = []
    scenarios: list[ScenarioIR] = []
    first_by_name: dict[str, ast.Scenario] = {}
    for scenario in file.scenarios:
        first = first_by_name.setdefault(scenario.name.text, scenario)
        if first is not scenario:
            diagnostics.append(
                Diagnostic(
                    "E0601",
                    f"a scenario named '{scenario.name.text}' is already defined in this file",
                    scenario.name.span,
                    help="give each scenario of a file its own name",
                    notes=(Label(ast.located(first.name.span), "first defined here"),),
                )
            )
        domain_name = scenario.domain.text if scenario.domain else vocabularies.default
        try:
            vocabulary = vocabularies.lookup(domain_name)
        except VocabularyError as error:
            span = scenario.domain.span if scenario.domain else scenario.name.span
            fixes = replacements(scenario.domain, error.suggestions) if scenario.domain else ()
            diagnostics.append(Diagnostic(error.code, error.message, span, help=error.help, fixes=fixes))
            continue
        checker = _ScenarioChecker(scenario, domain_name, vocabulary, path)
        result = checker.run()
        diagnostics.extend(checker.diagnostics)
        if result is not None and first is scenario:
            scenarios.append(result)
    return CheckResult(tuple(scenarios), tuple(diagnostics))


class _ScenarioChecker(SequenceChecks):
    """Checks one scenario: its terms here, its objects in `ObjectChecks`, its sequence in
    `SequenceChecks` (which builds on `ObjectChecks`), on the state of `ScenarioState`."""

    # ---- terms -------------------------------------------------------------
    def resolve_term(self, term: ast.Term, kind: str) -> Resolved | None:
        vocabulary = self.vocabulary
        signature = vocabulary.term(term.name.text)
        if signature is None:
            names = [t.name for t in vocabulary.terms if t.kind == kind]
            asked, fixes = suggestion(term.name, names)
            self.error(
                "E0201",
                f"unknown {kind} term '{term.name.text}'",
                term.name.span,
                help=asked or f"{kind} terms: {', '.join(names)}",
                fixes=fixes,
            )
            return None
        if signature.kind != kind:
            section = "interactions" if signature.kind == INTERACTION else "restrictions"
            self.error(
                "E0208",
                f"'{signature.name}' is {'an' if signature.kind == INTERACTION else 'a'} {signature.kind}, "
                f"not {'an' if kind == INTERACTION else 'a'} {kind}",
                term.name.span,
                help=f"move it to the {section} section",
            )
            return None
        given, total, required = len(term.arguments), len(signature.parameters), signature.required_count
        if not required <= given <= total:
            expected = str(total) if required == total else f"{required} or {total}"
            self.error(
                "E0202",
                f"'{signature.name}' takes {expected} arguments, but {given} {'was' if given == 1 else 'were'} given",
                term.span,
                help=f"write {signature.usage()}",
            )
            return None
        ok = True
        objects: list[str] = []
        spans: list[Span] = []
        directions: tuple[str, ...] = ()
        direction_span: Span | None = None
        for parameter, argument in zip(signature.parameters, term.arguments, strict=False):  # fewer: defaults
            if parameter.kind == DIRECTION:
                resolved = self.resolve_directions(signature, parameter, argument)
                ok = ok and resolved is not None
                directions, direction_span = resolved or (), argument.span
                continue
            name = argument.alternatives[0]
            if len(argument.alternatives) > 1:
                self.error(
                    "E0207",
                    f"the argument '{parameter.name}' of '{signature.name}' is an object and cannot have alternatives",
                    argument.span,
                    help="alternatives (a | b) are for directions; name one object",
                )
                ok = False
                continue
            if name.text in vocabulary.directions and name.text not in self.objects:
                self.error(
                    "E0204",
                    f"'{signature.name}' expects an object as '{parameter.name}', but '{name.text}' is a direction",
                    name.span,
                    help=f"write {signature.usage()}",
                )
                ok = False
                continue
            found = self.resolve_object(name)
            if found is None:
                ok = False
                continue
            if not self.check_fit(signature, parameter, found, name):
                ok = False
            objects.append(found.name)
            spans.append(ast.located(name.span))
        if len(term.arguments) < total:
            parameter = signature.direction_parameter
            if parameter is not None and parameter.default is not None:
                directions = parameter.default
        if not ok:
            return None
        return Resolved(term, signature, tuple(objects), tuple(spans), tuple(directions), direction_span)

    def resolve_directions(
        self, signature: TermSignature, parameter: Parameter, argument: ast.Argument
    ) -> tuple[str, ...] | None:
        vocabulary = self.vocabulary
        chosen: list[str] = []
        ok = True
        for name in argument.alternatives:
            if name.text not in vocabulary.directions:
                if self.is_object_word(name.text):
                    self.error(
                        "E0205",
                        f"'{signature.name}' expects a direction as '{parameter.name}', but '{name.text}' is an object",
                        name.span,
                        help=f"write {signature.usage()}",
                    )
                else:
                    asked, fixes = suggestion(name, parameter.directions)
                    self.error(
                        "E0206",
                        f"unknown direction '{name.text}'",
                        name.span,
                        help=asked or f"'{signature.name}' allows: {', '.join(parameter.directions)}",
                        fixes=fixes,
                    )
                ok = False
                continue
            if name.text not in parameter.directions:
                self.error(
                    "E0206",
                    f"'{signature.name}' does not allow the direction '{name.text}'",
                    name.span,
                    help=f"'{signature.name}' allows: {', '.join(parameter.directions)}",
                    fixes=replacements(name, parameter.directions),
                )
                ok = False
                continue
            chosen.extend(vocabulary.expand(name.text))
        if not ok:
            return None
        order = [d for p in parameter.directions for d in vocabulary.expand(p)]
        return tuple(d for d in dict.fromkeys(order) if d in chosen)

    # ---- the whole scenario ------------------------------------------------
    def run(self) -> ScenarioIR | None:
        for declaration in self.scenario.objects:
            self.declare(declaration)
        interactions: list[Resolved | None] = []
        for position, term in enumerate(self.scenario.interactions):
            self.position = position
            interactions.append(self.resolve_term(term, INTERACTION))
        self.position = None
        restrictions = [self.resolve_term(t, RESTRICTION) for t in self.scenario.restrictions]
        if self.scenario.interactions:
            self.check_causality(interactions, restrictions)
        narrowed = self.apply_restrictions(interactions, restrictions)
        self.explain()
        for obj in self.objects.values():
            if obj.declared and not obj.used:
                self.diagnostics.append(
                    Diagnostic(
                        "W0301",
                        f"the object '{obj.name}' is declared but no term uses it",
                        obj.span,
                        help="remove the declaration, or use the object; it is ignored",
                    )
                )
        self.check_players()
        if any(d.is_error for d in self.diagnostics):
            return None
        return self._scenario_ir(_all_resolved(interactions), _all_resolved(restrictions), narrowed)

    def _scenario_ir(
        self, interactions: list[Resolved], restrictions: list[Resolved], narrowed: dict[int, tuple[str, ...]]
    ) -> ScenarioIR:
        """The IR of a scenario without errors, from its resolved terms and narrowed directions."""
        return ScenarioIR(
            name=self.scenario.name.text,
            title=self.scenario.title.value if self.scenario.title else None,
            domain=self.domain,
            objects=tuple(
                ObjectIR(o.name, o.term, o.concrete, o.static, o.declared, o.span, o.materials)
                for o in self.objects.values()
                if o.used
            ),
            interactions=tuple(self._term_ir(r, narrowed[i]) for i, r in enumerate(interactions)),
            # A restriction says what may not happen: said twice, it says it once (and a
            # thousand copies must not cost the simulation a thousand tests).
            restrictions=tuple(dict.fromkeys(self._term_ir(r, r.directions) for r in restrictions)),
            path=self.path,
        )

    def check_players(self) -> None:
        """W0302: more objects of the player's term than compile places (the vocabulary's
        `players`): the language allows them, this version of compile does not generate them."""
        most = getattr(self.vocabulary, "players", None)
        player = getattr(self.vocabulary, "player", "")
        if most is None or not player:
            return
        used = [o for o in self.objects.values() if o.used and o.term == player]
        if len(used) > most:
            extra = used[most]
            self.diagnostics.append(
                Diagnostic(
                    "W0302",
                    f"'{extra.name}' is a {ordinal(most + 1)} {player}: physc compile places {count(most)} "
                    "in this domain and gives no task for this scenario",
                    extra.span,
                    help=f"the domain's actions place at most {count(most)} "
                    '(docs/language.md, "Static checks"): name fewer, or keep the scenario for another domain',
                )
            )

    @staticmethod
    def _term_ir(resolved: Resolved, directions: tuple[str, ...]) -> TermIR:
        return TermIR(
            name=resolved.signature.name,
            objects=resolved.objects,
            directions=directions,
            written=resolved.directions,
            text=format_term(resolved.node),
            span=resolved.node.span,
        )


def _all_resolved(terms: list[Resolved | None]) -> list[Resolved]:
    """The terms of a scenario without errors: every one resolved (one that did not reported one)."""
    resolved = [t for t in terms if t is not None]
    assert len(resolved) == len(terms), "a term that did not resolve reported no error"
    return resolved


def ordinal(n: int) -> str:
    return {1: "first", 2: "second", 3: "third"}.get(n, f"{n}th")


def count(n: int) -> str:
    return {1: "one", 2: "two", 3: "three"}.get(n, str(n))
