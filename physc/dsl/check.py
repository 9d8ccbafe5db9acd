"""Static checks of `.phys` scenarios (spec section 5) against a domain's vocabulary.

`check_file` turns an AST into Scenario IRs and diagnostics. Every error of a
file is reported; a scenario with errors yields no IR. The checks know no
domain words: term signatures say which parameters act, are set in motion or
are destroyed, which restriction narrows which interaction, and so on.
"""

from __future__ import annotations

from typing import Callable

import attrs

from physc.diagnostics import Diagnostic, Label, Span
from physc.domains import DEFAULT_DOMAIN, DomainError, load_domain
from physc.domains.vocabulary import (
    DIRECTION,
    INTERACTION,
    RESTRICTION,
    TermSignature,
    Vocabulary,
)
from physc.dsl import ast
from physc.dsl.fixes import Use, fit_help, fresh_name, latest, moving_help
from physc.dsl.fmt import format_term
from physc.dsl.scenario import ObjectIR, ScenarioIR, TermIR
from physc.dsl.sequence import SequenceChecks
from physc.gc_pause import gc_paused
from physc.suggest import article, did_you_mean

# 'Did you mean' for an unknown object compares it with every object of the scenario. Past this
# many comparisons in one scenario only the vocabulary's spellings are offered, so that a huge
# scenario full of unknown names stays linear (a real one needs a few hundred; 20,000 cost ~1 s).
SUGGESTION_COMPARISONS = 20_000


@attrs.frozen
class CheckResult:
    scenarios: tuple[ScenarioIR, ...]
    diagnostics: tuple[Diagnostic, ...]


def check_file(file: ast.File, path: str = "", domain_loader: Callable = load_domain) -> CheckResult:
    with gc_paused():
        return _check_file(file, path, domain_loader)


def _check_file(file: ast.File, path: str, domain_loader: Callable) -> CheckResult:
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
                    notes=(Label(first.name.span, "first defined here"),),
                )
            )
        domain_name = scenario.domain.text if scenario.domain else DEFAULT_DOMAIN
        try:
            domain = domain_loader(domain_name)
        except DomainError as error:
            span = scenario.domain.span if scenario.domain else scenario.name.span
            diagnostics.append(Diagnostic(error.code, error.message, span, help=error.help))
            continue
        checker = _ScenarioChecker(scenario, domain_name, domain.vocabulary, path)
        result = checker.run()
        diagnostics.extend(checker.diagnostics)
        if result is not None and first is scenario:
            scenarios.append(result)
    return CheckResult(tuple(scenarios), tuple(diagnostics))


@attrs.define
class _Object:
    name: str
    term: str
    concrete: tuple[str, ...]
    static: bool
    declared: bool
    span: Span
    used: bool = False


@attrs.define
class _Resolved:
    """A term whose arguments all resolved: ready for the causal checks."""

    node: ast.Term
    signature: TermSignature
    objects: tuple[str, ...]
    object_spans: tuple[Span, ...]
    directions: tuple[str, ...]
    direction_span: Span | None


@attrs.frozen
class _Names:
    """The object names of a scenario, declared or used, known or not (for `in`)."""

    objects: dict
    unknown: set

    def __contains__(self, name: str) -> bool:
        return name in self.objects or name in self.unknown


class _ScenarioChecker(SequenceChecks):
    """Checks one scenario: its objects and terms here, its sequence in `SequenceChecks`."""

    def __init__(self, scenario: ast.Scenario, domain: str, vocabulary: Vocabulary, path: str):
        self.scenario = scenario
        self.domain = domain
        self.vocabulary = vocabulary
        self.path = path
        self.diagnostics: list[Diagnostic] = []
        self.objects: dict[str, _Object] = {}
        self.unknown: set[str] = set()
        self.uses: dict[str, list[Use]] = {}  # every (term, parameter) an object appears as
        # E0203 for a parameter's object term: (diagnostic index, object, term asked for); the help
        # is written once every use of the object is known (fixes.fit_help).
        self.misfits: list[tuple[int, _Object, str]] = []
        # E0203 for a static object where one that moves is needed: (diagnostic index, position in
        # the sequence or None, parameter, object); the help names an object in motion there.
        self.immobile: list[tuple] = []
        self.position: int | None = None  # of the interaction being resolved
        self.helps: dict[int, str] = {}
        self.fresh_names: dict[str, str] = {}
        self.comparisons = 0

    def error(self, code, message, span, help=None, notes=()):
        self.diagnostics.append(Diagnostic(code, message, span, help=help, notes=tuple(notes)))

    # ---- objects -----------------------------------------------------------
    def declare(self, declaration: ast.Declaration) -> None:
        name = declaration.name
        vocabulary = self.vocabulary
        # Until the declaration proves good, later uses of the name stay silent.
        self.unknown.add(name.text)
        if name.text in self.objects:
            self.error(
                "E0304",
                f"the object '{name.text}' is declared twice",
                name.span,
                help="remove one of the declarations",
                notes=[Label(self.objects[name.text].span, "first declared here")],
            )
            return
        if name.text in vocabulary.directions:
            self.error("E0305", f"'{name.text}' is a direction and cannot name an object", name.span)
            return
        term = vocabulary.object_term(declaration.term.text)
        if term is None:
            self.error(
                "E0302",
                f"unknown object term '{declaration.term.text}'",
                declaration.term.span,
                help=did_you_mean(declaration.term.text, vocabulary.spellings)
                or "object terms: " + ", ".join(t.name for t in vocabulary.object_terms),
            )
            return
        concrete = term.concrete
        if declaration.concrete:
            chosen = []
            for item in declaration.concrete:
                if item.text in term.concrete:
                    chosen.append(item.text)
                    continue
                known = vocabulary.concrete(item.text) is not None
                self.error(
                    "E0303",
                    f"'{term.name}' cannot be '{item.text}'"
                    if known
                    else f"unknown concrete object '{item.text}'",
                    item.span,
                    help=(did_you_mean(item.text, term.concrete) if not known else None)
                    or f"'{term.name}' may be: {' | '.join(term.concrete)}",
                )
            if len(chosen) < len(declaration.concrete):
                return
            concrete = tuple(c for c in term.concrete if c in chosen)
        self.objects[name.text] = _Object(
            name.text, term.name, concrete, vocabulary.is_static(concrete), True, name.span
        )
        self.unknown.discard(name.text)

    def resolve_object(self, name: ast.Name) -> _Object | None:
        found = self.objects.get(name.text)
        if found is not None:
            found.used = True
            return found
        if name.text in self.unknown:  # already reported
            return None
        term = self.vocabulary.term_of_name(name.text)
        if term is None:
            self.unknown.add(name.text)
            self.comparisons += len(self.objects)
            pool = [*self.vocabulary.spellings]
            if self.comparisons <= SUGGESTION_COMPARISONS:
                pool += self.objects
            suggestion = did_you_mean(name.text, pool)
            how = f"declare it in `objects {{ {name.text}: <term> }}`"
            self.error(
                "E0301",
                f"unknown object '{name.text}': its type cannot be inferred from its name",
                name.span,
                help=f"{suggestion[:-1]}, or {how}" if suggestion else how,
            )
            return None
        found = _Object(
            name.text, term.name, term.concrete, self.vocabulary.is_static(term.concrete), False, name.span, True
        )
        self.objects[name.text] = found
        return found

    def is_object_word(self, text: str) -> bool:
        return text in self.objects or self.vocabulary.term_of_name(text) is not None

    # ---- terms -------------------------------------------------------------
    def resolve_term(self, term: ast.Term, kind: str) -> _Resolved | None:
        vocabulary = self.vocabulary
        signature = vocabulary.term(term.name.text)
        if signature is None:
            names = [t.name for t in vocabulary.terms if t.kind == kind]
            self.error(
                "E0201",
                f"unknown {kind} term '{term.name.text}'",
                term.name.span,
                help=did_you_mean(term.name.text, names) or f"{kind} terms: {', '.join(names)}",
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
                f"'{signature.name}' takes {expected} arguments, but {given} "
                f"{'was' if given == 1 else 'were'} given",
                term.span,
                help=f"write {signature.usage()}",
            )
            return None
        ok = True
        objects, spans, directions, direction_span = [], [], (), None
        for parameter, argument in zip(signature.parameters, term.arguments):
            if parameter.kind == DIRECTION:
                resolved = self.resolve_directions(signature, parameter, argument)
                ok = ok and resolved is not None
                directions, direction_span = resolved or (), argument.span
                continue
            name = argument.alternatives[0]
            if len(argument.alternatives) > 1:
                self.error(
                    "E0207",
                    f"the argument '{parameter.name}' of '{signature.name}' is an object "
                    "and cannot have alternatives",
                    argument.span,
                    help="alternatives (a | b) are for directions; name one object",
                )
                ok = False
                continue
            if name.text in vocabulary.directions and name.text not in self.objects:
                self.error(
                    "E0204",
                    f"'{signature.name}' expects an object as '{parameter.name}', "
                    f"but '{name.text}' is a direction",
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
            spans.append(name.span)
        if len(term.arguments) < total:
            parameter = signature.direction_parameter
            if parameter is not None and parameter.default is not None:
                directions = parameter.default
        if not ok:
            return None
        return _Resolved(term, signature, tuple(objects), tuple(spans), tuple(directions), direction_span)

    def check_fit(self, signature, parameter, found: _Object, name: ast.Name) -> bool:
        vocabulary = self.vocabulary
        self.uses.setdefault(found.name, []).append((signature, parameter))
        if parameter.dynamic and found.static:
            self.immobile.append((len(self.diagnostics), self.position, parameter, found.name))
            self.error(
                "E0203",
                f"'{signature.name}' expects a dynamic object as '{parameter.name}', "
                f"but '{found.name}' is {article(found.term)} {found.term}, which never moves",
                name.span,
            )
            return False
        if parameter.fits and not vocabulary.fits(found.concrete, parameter.fits):
            fits = vocabulary.object_term(parameter.fits)
            self.misfits.append((len(self.diagnostics), found, parameter.fits))
            self.error(
                "E0203",
                f"'{signature.name}' expects {fits.noun or fits.name}, "
                f"but '{found.name}' is {article(found.term)} {found.term}",
                name.span,
            )
            return False
        return True

    def explain_immobile(self, item, movers: dict[str, None]) -> None:
        """The help of an E0203 for a static object where a moving one is needed: an object in
        motion at that point of the sequence that fits (`movers`, in the order they started)."""
        index, _, parameter, name = item
        vocabulary = self.vocabulary

        def fits(other: str) -> bool:
            found = self.objects[other]
            return other != name and not found.static and (not parameter.fits or vocabulary.fits(found.concrete, parameter.fits))

        def calm(other: str) -> bool:
            return fits(other) and not vocabulary.fits(self.objects[other].concrete, vocabulary.goal)

        mover = latest(movers, calm) or latest(movers, fits)
        self.helps[index] = moving_help(vocabulary, parameter, mover, self.fresh)

    def fresh(self, base: str) -> str:
        """A name for a new object that no object of the scenario has (remembered per base)."""
        if base not in self.fresh_names:
            self.fresh_names[base] = fresh_name(base, _Names(self.objects, self.unknown))
        return self.fresh_names[base]

    def explain(self) -> None:
        """Write the help texts that needed the whole scenario: E0203 for an object term (every use
        of the object must be known) and for a static object outside the sequence."""
        if not self.misfits and not self.immobile:
            return
        written: dict[tuple[str, str], str] = {}
        for index, found, fits in self.misfits:
            key = (found.name, fits)
            if key not in written:
                declared = found.term if found.declared else None
                term = self.vocabulary.object_term(fits)
                written[key] = fit_help(self.vocabulary, found.name, declared, term, self.uses[found.name], self.fresh)
            self.helps[index] = written[key]
        players = {o.name: None for o in self.objects.values() if self.vocabulary.fits(o.concrete, self.vocabulary.player)}
        for item in self.immobile:
            if item[0] not in self.helps:
                self.explain_immobile(item, players)
        for index, help_text in self.helps.items():
            self.diagnostics[index] = attrs.evolve(self.diagnostics[index], help=help_text)

    def resolve_directions(self, signature, parameter, argument) -> tuple[str, ...] | None:
        vocabulary = self.vocabulary
        chosen: list[str] = []
        ok = True
        for name in argument.alternatives:
            if name.text not in vocabulary.directions:
                if self.is_object_word(name.text):
                    self.error(
                        "E0205",
                        f"'{signature.name}' expects a direction as '{parameter.name}', "
                        f"but '{name.text}' is an object",
                        name.span,
                        help=f"write {signature.usage()}",
                    )
                else:
                    self.error(
                        "E0206",
                        f"unknown direction '{name.text}'",
                        name.span,
                        help=did_you_mean(name.text, parameter.directions)
                        or f"'{signature.name}' allows: {', '.join(parameter.directions)}",
                    )
                ok = False
                continue
            if name.text not in parameter.directions:
                self.error(
                    "E0206",
                    f"'{signature.name}' does not allow the direction '{name.text}'",
                    name.span,
                    help=f"'{signature.name}' allows: {', '.join(parameter.directions)}",
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
        interactions = []
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
        if any(d.is_error for d in self.diagnostics):
            return None
        return ScenarioIR(
            name=self.scenario.name.text,
            title=self.scenario.title.value if self.scenario.title else None,
            domain=self.domain,
            objects=tuple(
                ObjectIR(o.name, o.term, o.concrete, o.static, o.declared, o.span)
                for o in self.objects.values()
                if o.used
            ),
            interactions=tuple(
                self._term_ir(r, narrowed[i]) for i, r in enumerate(interactions)
            ),
            restrictions=tuple(self._term_ir(r, r.directions) for r in restrictions),
            path=self.path,
        )

    @staticmethod
    def _term_ir(resolved: _Resolved, directions: tuple[str, ...]) -> TermIR:
        return TermIR(
            name=resolved.signature.name,
            objects=resolved.objects,
            directions=directions,
            written=resolved.directions,
            text=format_term(resolved.node),
            span=resolved.node.span,
        )
