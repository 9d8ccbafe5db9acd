"""The checks of a scenario's objects (spec section 5, items 1-2): declarations, names whose type
is inferred, and whether an object fits the parameter it is given to.

A part of the scenario checker (physc/dsl/check.py) on its state (check_state.ScenarioState); the
sequence's checks (`SequenceChecks`) build on it. The help texts that need every use of an object
(E0203's declaration, E0301's renames) are written by `explain` once the whole scenario is resolved.
"""

from __future__ import annotations

import attrs

from physc.diagnostics import Label, Span
from physc.dsl import ast
from physc.dsl.check_state import Immobile, KnownObject, ScenarioState
from physc.dsl.fixes import Advice, fit_help, fresh_name, latest, moving_help, replacements, suggestion
from physc.dsl.vocabularies import ObjectTerm, Parameter, TermSignature
from physc.suggest import article, asking, closest

# 'Did you mean' for an unknown object compares it with every object of the scenario. Past this
# many comparisons in one scenario only the vocabulary's spellings are offered, so that a huge
# scenario full of unknown names stays linear (a real one needs a few hundred; 20,000 cost ~1 s).
SUGGESTION_COMPARISONS = 20_000


@attrs.frozen
class _Names:
    """The object names of a scenario, declared or used, known or not (for `in`)."""

    objects: dict[str, KnownObject]
    unknown: set[str]

    def __contains__(self, name: str) -> bool:
        return name in self.objects or name in self.unknown


class ObjectChecks(ScenarioState):
    """Declarations and object arguments: a part of the scenario checker, on its state."""

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
            asked, fixes = suggestion(declaration.term, vocabulary.spellings)
            self.error(
                "E0302",
                f"unknown object term '{declaration.term.text}'",
                declaration.term.span,
                help=asked or "object terms: " + ", ".join(t.name for t in vocabulary.object_terms),
                fixes=fixes,
            )
            return
        concrete = term.concrete
        if declaration.concrete:
            chosen = []
            allowed = term.allowed
            for item in declaration.concrete:
                if item.text in allowed:
                    chosen.append(item.text)
                    continue
                known = vocabulary.concrete(item.text) is not None
                asked, fixes = suggestion(item, allowed) if not known else (None, replacements(item, allowed))
                self.error(
                    "E0303",
                    f"'{term.name}' cannot be '{item.text}'" if known else f"unknown concrete object '{item.text}'",
                    item.span,
                    help=asked or f"'{term.name}' may be: {' | '.join(allowed)}",
                    fixes=fixes,
                )
            if len(chosen) < len(declaration.concrete):
                return
            concrete = tuple(c for c in allowed if c in chosen)
        materials = self.declared_materials(declaration, term, concrete)
        if materials is None:
            return
        self.objects[name.text] = KnownObject(
            name.text,
            term.name,
            concrete,
            vocabulary.is_static(concrete),
            True,
            ast.located(name.span),
            declaration=declaration.span,
            materials=materials,
        )
        self.unknown.discard(name.text)

    def declared_materials(
        self, declaration: ast.Declaration, term: ObjectTerm, concrete: tuple[str, ...]
    ) -> tuple[str, ...] | None:
        """The materials a declaration names (version 2), in the vocabulary's order; None after
        E0306 for one that every concrete object it may become cannot be made of."""
        if not declaration.materials:
            return ()
        possible = self.vocabulary.materials(concrete)
        good = True
        for item in declaration.materials:
            if item.text in possible:
                continue
            good = False
            if not possible:
                self.error(
                    "E0306",
                    f"'{declaration.name.text}' ({' | '.join(concrete)}) is made of no material",
                    item.span,
                    help="only blocks have a material: remove the parenthesis",
                )
                continue
            asked, fixes = suggestion(item, possible)
            self.error(
                "E0306",
                f"'{declaration.name.text}' cannot be made of '{item.text}'",
                item.span,
                help=asked or f"its materials: {' | '.join(possible)}",
                fixes=fixes,
            )
        if not good:
            return None
        named = {m.text for m in declaration.materials}
        return tuple(m for m in possible if m in named)

    def resolve_object(self, name: ast.Name) -> KnownObject | None:
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
            found = closest(name.text, pool)
            asked = asking(found)
            how = f"declare it in `objects {{ {name.text}: <term> }}`"
            if found:
                self.misspelt[name.text] = (len(self.diagnostics), name, found)
            self.error(
                "E0301",
                f"unknown object '{name.text}': its type cannot be inferred from its name",
                name.span,
                help=f"{asked[:-1]}, or {how}" if asked else how,
            )
            return None
        found = KnownObject(
            name.text,
            term.name,
            term.concrete,
            self.vocabulary.is_static(term.concrete),
            False,
            ast.located(name.span),
            True,
        )
        self.objects[name.text] = found
        return found

    def is_object_word(self, text: str) -> bool:
        return text in self.objects or self.vocabulary.term_of_name(text) is not None

    def check_fit(self, signature: TermSignature, parameter: Parameter, found: KnownObject, name: ast.Name) -> bool:
        vocabulary = self.vocabulary
        self.uses.setdefault(found.name, []).append((signature, parameter))
        if parameter.dynamic and found.static:
            self.immobile.append(Immobile(len(self.diagnostics), self.position, parameter, found.name))
            self.error(
                "E0203",
                f"'{signature.name}' expects a dynamic object as '{parameter.name}', "
                f"but '{found.name}' is {article(found.term)} {found.term}, which never moves",
                name.span,
            )
            return False
        if parameter.fits and not vocabulary.fits(found.concrete, parameter.fits):
            fits = vocabulary.object_term_named(parameter.fits)
            self.misfits.append((len(self.diagnostics), found, parameter.fits))
            self.error(
                "E0203",
                f"'{signature.name}' expects {fits.noun or fits.name}, "
                f"but '{found.name}' is {article(found.term)} {found.term}",
                name.span,
            )
            return False
        return True

    def explain_immobile(self, item: Immobile, movers: dict[str, None]) -> None:
        """The help of an E0203 for a static object where a moving one is needed: an object in
        motion at that point of the sequence that fits (`movers`, in the order they started)."""
        index, parameter, name = item.diagnostic, item.parameter, item.name
        vocabulary = self.vocabulary

        def fits(other: str) -> bool:
            found = self.objects[other]
            return (
                other != name
                and not found.static
                and (not parameter.fits or vocabulary.fits(found.concrete, parameter.fits))
            )

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
        """Write the help texts and fixes that needed the whole scenario: E0203 for an object term
        (every use of the object must be known), for a static object outside the sequence, and the
        renames of E0301 (every use of the unknown name)."""
        uses: dict[str, list[Span]] = {}
        if self.misspelt:
            for term in self.scenario.interactions + self.scenario.restrictions:
                for argument in term.arguments:
                    for other in argument.alternatives:
                        if other.text in self.misspelt and other.span != self.misspelt[other.text][1].span:
                            uses.setdefault(other.text, []).append(ast.located(other.span))
        for name, (index, first, found) in self.misspelt.items():
            fixes = replacements(first, found, tuple(uses.get(name, ())))
            self.diagnostics[index] = attrs.evolve(self.diagnostics[index], fixes=fixes)
        if not self.misfits and not self.immobile:
            return
        written: dict[tuple[str, str], Advice] = {}
        declarations: dict[int, Span | None] = {}
        for index, found, fits in self.misfits:
            key = (found.name, fits)
            if key not in written:
                declared = found.term if found.declared else None
                term = self.vocabulary.object_term_named(fits)
                written[key] = fit_help(self.vocabulary, found.name, declared, term, self.uses[found.name], self.fresh)
            self.helps[index] = written[key]
            declarations[index] = found.declaration
        players = {
            o.name: None for o in self.objects.values() if self.vocabulary.fits(o.concrete, self.vocabulary.player)
        }
        for item in self.immobile:
            if item.diagnostic not in self.helps:
                self.explain_immobile(item, players)
        for index, advice in self.helps.items():
            diagnostic = self.diagnostics[index]
            fixes = self.fixes(advice, diagnostic.span, declaration=declarations.get(index))
            self.diagnostics[index] = attrs.evolve(diagnostic, help=advice.text, fixes=fixes)
