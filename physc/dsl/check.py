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
from physc.dsl.fmt import format_term
from physc.dsl.scenario import ObjectIR, ScenarioIR, TermIR
from physc.gc_pause import gc_paused
from physc.suggest import did_you_mean


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


class _ScenarioChecker:
    def __init__(self, scenario: ast.Scenario, domain: str, vocabulary: Vocabulary, path: str):
        self.scenario = scenario
        self.domain = domain
        self.vocabulary = vocabulary
        self.path = path
        self.diagnostics: list[Diagnostic] = []
        self.objects: dict[str, _Object] = {}
        self.unknown: set[str] = set()

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
            suggestion = did_you_mean(name.text, [*self.vocabulary.spellings, *self.objects])
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
        if parameter.dynamic and found.static:
            self.error(
                "E0203",
                f"'{signature.name}' expects a dynamic object as '{parameter.name}', "
                f"but '{found.name}' is a {found.term}, which never moves",
                name.span,
            )
            return False
        if parameter.fits and not vocabulary.fits(found.concrete, parameter.fits):
            fits = vocabulary.object_term(parameter.fits)
            use = fits.abbreviation or fits.name
            self.error(
                "E0203",
                f"'{signature.name}' expects {fits.noun or fits.name}, but '{found.name}' is a {found.term}",
                name.span,
                help=f"declare it as `{found.name}: {fits.name}` or use an {use}"
                if not found.declared
                else f"declare it with a concrete object that {fits.name} allows: "
                + " | ".join(fits.concrete),
            )
            return False
        return True

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

    # ---- causality, goals, restrictions -------------------------------------
    def check_causality(self, interactions: list[_Resolved | None]) -> None:
        vocabulary = self.vocabulary
        players = {o.name for o in self.objects.values() if vocabulary.fits(o.concrete, vocabulary.player)}
        in_motion = set(players)
        destroyed: dict[str, Span] = {}
        seen: set[tuple[str, tuple[str, ...]]] = set()
        # Once an interaction fails to resolve, what it would have set in motion,
        # hit or destroyed is unknown: later causal errors would be guesses.
        complete = True
        for index, resolved in enumerate(interactions):
            if resolved is None:
                complete = False
                continue
            signature = resolved.signature
            for obj, span in zip(resolved.objects, resolved.object_spans):
                if obj in destroyed:
                    self.error(
                        "E0405",
                        f"'{obj}' takes part in '{signature.name}' after it was destroyed",
                        span,
                        notes=[Label(destroyed[obj], f"'{obj}' is destroyed here")],
                    )
            for parameter, obj, span in zip(signature.object_parameters, resolved.objects, resolved.object_spans):
                if not parameter.acts:
                    continue
                if obj not in in_motion:
                    in_motion.add(obj)  # report each object once
                else:
                    continue
                if index == 0 and obj not in players:
                    self.error(
                        "E0401",
                        f"the first interaction must be performed by the {vocabulary.player} "
                        f"(the player's only action), but here '{obj}' acts",
                        span,
                        help=f"start the sequence with the {vocabulary.player}, "
                        f"e.g. hit({vocabulary.player}, {obj}, left)",
                    )
                elif complete:
                    self.error(
                        "E0402",
                        f"'{obj}' acts in '{signature.name}' before anything set it in motion",
                        span,
                        help=f"add an earlier interaction that sets it in motion, e.g. hit(x, {obj}, left)",
                    )
            if complete and signature.requires and (signature.requires, resolved.objects) not in seen:
                pair = ", ".join(resolved.objects)
                self.error(
                    "E0403",
                    f"'{signature.name}({pair})' needs an earlier '{signature.requires}({pair}, …)'",
                    resolved.node.span,
                    help=f"add `{signature.requires}({pair}, any)` before it",
                )
            for parameter, obj, span in zip(signature.object_parameters, resolved.objects, resolved.object_spans):
                if parameter.moves:
                    in_motion.add(obj)
                if parameter.destroys:
                    destroyed.setdefault(obj, resolved.node.span)
            seen.add((signature.name, resolved.objects[:2]))
        goal = vocabulary.goal
        for obj in self.objects.values() if complete else ():
            if obj.name in self.unknown or not vocabulary.fits(obj.concrete, goal) or obj.name in destroyed:
                continue
            if not obj.used:
                continue
            self.error(
                "E0404",
                f"the {goal} '{obj.name}' is never destroyed (a task is solved when every {goal} is destroyed)",
                obj.span,
                help=f"add `> destroy(x, {obj.name})` after an interaction that hits it",
            )

    def apply_restrictions(self, interactions, restrictions) -> dict[int, tuple[str, ...]]:
        """Narrow interaction directions; report restrictions that contradict the sequence."""
        narrowed = {i: r.directions for i, r in enumerate(interactions) if r is not None}
        # A restriction on how a reaches b constrains a's direct approach: the
        # interactions a performs before anything redirects it (e.g. a bounce).
        redirected: set[str] = set()
        direct: dict[int, bool] = {}
        for index, interaction in enumerate(interactions):
            if interaction is None:
                continue
            direct[index] = interaction.objects[0] not in redirected
            for parameter, obj in zip(interaction.signature.object_parameters, interaction.objects):
                if parameter.redirects:
                    redirected.add(obj)
        for restriction in restrictions:
            if restriction is None:
                continue
            signature = restriction.signature
            for index, interaction in enumerate(interactions):
                if interaction is None:
                    continue
                name = interaction.signature.name
                same_pair = interaction.objects[:2] == restriction.objects[:2]
                if signature.narrows == name and same_pair and direct[index]:
                    left = tuple(d for d in narrowed[index] if d not in restriction.directions)
                    if not left:
                        self.error(
                            "E0501",
                            f"'{restriction.node.name.text}' forbids every direction "
                            f"that this '{name}' allows ({', '.join(narrowed[index])})",
                            interaction.direction_span or interaction.node.span,
                            help="allow more directions in the interaction or fewer in the restriction",
                            notes=[Label(restriction.node.span, "the restriction")],
                        )
                    narrowed[index] = left
                elif signature.forbids == name and interaction.objects[:1] == restriction.objects[:1]:
                    self.error(
                        "E0502",
                        f"'{restriction.node.name.text}({restriction.objects[0]})' forbids this '{name}'",
                        interaction.node.span,
                        help="remove the restriction or the interaction",
                        notes=[Label(restriction.node.span, "the restriction")],
                    )
        return narrowed

    # ---- the whole scenario ------------------------------------------------
    def run(self) -> ScenarioIR | None:
        for declaration in self.scenario.objects:
            self.declare(declaration)
        interactions = [self.resolve_term(t, INTERACTION) for t in self.scenario.interactions]
        restrictions = [self.resolve_term(t, RESTRICTION) for t in self.scenario.restrictions]
        if self.scenario.interactions:
            self.check_causality(interactions)
        narrowed = self.apply_restrictions(interactions, restrictions)
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
