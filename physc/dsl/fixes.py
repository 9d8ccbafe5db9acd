"""The fixes that the static checks' help texts propose, worked out so that they keep the scenario valid.

A help text that says "declare it as `pig: surface`" is worse than none when the pig must stay a pig
for a later `destroy`. So the fix for an object that does not fit a parameter looks at every use of
the object in the scenario: a declaration is proposed only if one concrete object satisfies all of
them; otherwise the help proposes a separate object, named so that it clashes with no name of the
scenario. Like the checks, nothing here knows a domain word: it reads term signatures and the
vocabulary's object terms.
"""

from __future__ import annotations

from collections.abc import Callable, Container, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING

import attrs

from physc.diagnostics import Edit, Fix, Span
from physc.dsl.ast import Name, Term, located
from physc.dsl.vocabularies import INTERACTION, ObjectTerm, Parameter, TermSignature, Vocabulary
from physc.suggest import article, asking, closest

if TYPE_CHECKING:  # the checks' state imports this module: only its types are read here
    from physc.dsl.check_state import KnownObject, Resolved

Use = tuple[TermSignature, Parameter]


@attrs.frozen
class Advice:
    """A help text and the code it proposes, which the checks turn into quick fixes (`Fix`)."""

    text: str
    declaration: str | None = None  # write this declaration of the object instead of its own
    other: str | None = None  # name this object at the use instead
    before: str | None = None  # insert this term before the one the error is about
    after: tuple[str, ...] = ()  # add these terms after the last interaction

    def fixes(
        self, span: Span | None, term: Term | None, declaration: Span | None, last: Term | None
    ) -> tuple[Fix, ...]:
        """The edits proposed for an error at `span` about the term `term`, of an object declared
        at `declaration`, in a scenario whose last interaction is `last`. An inserted term is
        written in brackets where its neighbour is (`[hit(bird, pig, any)] > [destroy(…)]`)."""
        fixes = []
        if self.declaration and declaration is not None:
            fixes.append(Fix.replace(declaration, self.declaration, f"declare it as `{self.declaration}`"))
        if self.other and span is not None:
            fixes.append(Fix.replace(span, self.other, f"use `{self.other}` here"))
        if self.before and term is not None:
            written = _beside(term, self.before)
            fixes.append(
                Fix(
                    f"insert `{self.before}` before it",
                    (Edit(located(term.outer or term.span).first(0), f"{written} > "),),
                )
            )
        if self.after and last is not None:
            added = "".join(f" > {_beside(last, t)}" for t in self.after)
            fixes.append(
                Fix(
                    f"add `> {' > '.join(self.after)}` at the end",
                    (Edit(located(last.outer or last.span).last(0), added),),
                )
            )
        return tuple(fixes)


def _beside(neighbour: Term, text: str) -> str:
    """A term's text as written next to `neighbour`: in brackets if it is."""
    return f"[{text}]" if neighbour.outer is not None else text


def replacements(name: Name, found: Iterable[str], uses: tuple[Span, ...] = ()) -> tuple[Fix, ...]:
    """Quick fixes that replace a misspelt name (an ast.Name, and its other `uses`) with each name found."""
    spans = (located(name.span), *uses)
    return tuple(Fix(f"change '{name.text}' to '{other}'", tuple(Edit(s, other) for s in spans)) for other in found)


def suggestion(name: Name, candidates: Iterable[str]) -> tuple[str | None, tuple[Fix, ...]]:
    """ "did you mean …?" for a misspelt name (an ast.Name), and its quick fixes."""
    found = closest(name.text, candidates)
    return asking(found), replacements(name, found)


Fresh = Callable[[str], str]  # a name for a new object, from a base such as `surface`


def fresh_name(base: str, taken: Container[str]) -> str:
    """`base`, or `base2`, `base3`, … : the first that no object of the scenario is called."""
    if base not in taken:
        return base
    number = 2
    while f"{base}{number}" in taken:
        number += 1
    return f"{base}{number}"


def noun(term: ObjectTerm) -> str:
    """How a help text names an object of the term: its noun ("a surface"), else "a <name>"."""
    return term.noun or f"{article(term.name)} {term.name}"


def _admits(vocabulary: Vocabulary, parameter: Parameter, concrete: str) -> bool:
    if parameter.fits and concrete not in vocabulary.object_term_named(parameter.fits).concrete:
        return False
    return not (parameter.dynamic and vocabulary.is_static((concrete,)))


def allowed_concrete(vocabulary: Vocabulary, uses: Sequence[Use]) -> tuple[str, ...]:
    """The concrete objects that satisfy every use at once (in the vocabulary's order)."""
    return tuple(c.name for c in vocabulary.concrete_objects if all(_admits(vocabulary, p, c.name) for _, p in uses))


def _declaration(vocabulary: Vocabulary, name: str, allowed: tuple[str, ...], fits: ObjectTerm) -> str:
    """`name: term`, with a term whose concrete objects all lie in `allowed` (the one the failed
    parameter asks for first, then the largest), else the asked-for term narrowed to `allowed`."""
    candidates = [t for t in vocabulary.object_terms if set(t.concrete) <= set(allowed)]
    if fits in candidates:
        return f"{name}: {fits.name}"
    if candidates:
        best = max(candidates, key=lambda t: len(t.concrete))
        return f"{name}: {best.name}"
    return f"{name}: {fits.name} = {' | '.join(c for c in fits.concrete if c in allowed)}"


def _separate(vocabulary: Vocabulary, name: str, fits: ObjectTerm, uses: Sequence[Use], fresh: Fresh) -> Advice:
    """Help for an object that no declaration can make fit all its uses: name another object here."""
    other = fresh(fits.abbreviation or fits.name)
    why = ""
    for signature, parameter in uses:
        if not any(_admits(vocabulary, parameter, c) for c in fits.concrete):
            needs = noun(vocabulary.object_term_named(parameter.fits)) if parameter.fits else "an object that moves"
            why = f": '{signature.name}' needs it as {needs}"
            break
    return Advice(
        f"use a separate object here, e.g. `{other}` ({noun(fits)}); '{name}' cannot also be {noun(fits)}{why}",
        other=other,
    )


def fit_help(
    vocabulary: Vocabulary, name: str, declared_term: str | None, fits: ObjectTerm, uses: Sequence[Use], fresh: Fresh
) -> Advice:
    """Help for an object `name` that does not fit a parameter asking for `fits`.

    `declared_term` is the term of its declaration (None when its name typed it), `uses` every
    (term, parameter) it appears as in the scenario; `fresh(base)` names a new object (fresh_name).
    """
    allowed = allowed_concrete(vocabulary, uses)
    if declared_term is not None:
        declared = vocabulary.object_term_named(declared_term)
        narrowed = [c for c in declared.concrete if c in allowed]
        if narrowed:
            declaration = f"{name}: {declared.name} = {' | '.join(narrowed)}"
        elif allowed:
            declaration = _declaration(vocabulary, name, allowed, fits)
        else:
            return _separate(vocabulary, name, fits, uses, fresh)
        return Advice(f"declare it as `{declaration}`", declaration=declaration)
    if allowed:
        other = fresh(fits.abbreviation or fits.name)
        declaration = _declaration(vocabulary, name, allowed, fits)
        return Advice(f"declare it as `{declaration}` or use {article(other)} {other}", other=other)
    return _separate(vocabulary, name, fits, uses, fresh)


def latest(movers: dict[str, None], accept: Callable[[str], bool], limit: int = 64) -> str | None:
    """The object set in motion last (`movers` in the order they started) that `accept`s, among the
    last `limit` of them: a bound that keeps the help texts of a huge scenario linear."""
    for count, name in enumerate(reversed(movers)):
        if count == limit:
            break
        if accept(name):
            return name
    return None


def moving_help(vocabulary: Vocabulary, parameter: Parameter, mover: str | None, fresh: Fresh) -> Advice:
    """Help for a static object where an object that moves is needed: `mover` (in motion there,
    fitting the parameter), else a new object of the term the parameter asks for, else the player's."""
    if mover is not None:
        other = mover
    elif parameter.fits:
        fits = vocabulary.object_term_named(parameter.fits)
        other = fresh(fits.abbreviation or fits.name)
    else:
        other = vocabulary.player
    return Advice(f"use an object that moves here, e.g. `{other}`", other=other)


def _mover(vocabulary: Vocabulary) -> TermSignature | None:
    """The interaction by which one object sets another in motion (angrybirds: hit)."""
    for signature in vocabulary.terms:
        parameters = signature.object_parameters
        if signature.kind == INTERACTION and len(parameters) == 2 and parameters[0].acts and parameters[1].moves:
            return signature
    return None


def _completer(vocabulary: Vocabulary) -> tuple[TermSignature, int] | None:
    """The interaction that meets the goal for one of its two objects, and that object's
    position (angrybirds: destroy, 1; a PHYRE-like domain: touch, 0)."""
    for signature in vocabulary.terms:
        parameters = signature.object_parameters
        if signature.kind == INTERACTION and len(parameters) == 2:
            for position, parameter in enumerate(parameters):
                if parameter.completes:
                    return signature, position
    return None


def call(
    vocabulary: Vocabulary, signature: TermSignature, objects: Sequence[str], every_direction: bool = False
) -> str:
    """A term as written: `hit(bird, rBlock, left)`; with `every_direction`, the alias that
    allows them all where the parameter has one (`any`)."""
    arguments = list(objects)
    parameter = signature.direction_parameter
    if parameter is not None and parameter.directions:
        alias = next((d for d in parameter.directions if d in vocabulary.direction_aliases), None)
        arguments.append(alias if every_direction and alias else parameter.directions[0])
    return f"{signature.name}({', '.join(arguments)})"


def start_help(vocabulary: Vocabulary, obj: str) -> Advice:
    """Help for a sequence that starts with another object than the player's (E0401)."""
    player = vocabulary.player
    mover = _mover(vocabulary)
    if mover is None:
        return Advice(f"start the sequence with the {player}")
    example = call(vocabulary, mover, (player, obj))
    return Advice(f"start the sequence with the {player}, e.g. {example}", before=example)


def motion_help(vocabulary: Vocabulary, obj: str, actor: str | None) -> Advice:
    """Help for an object that acts before anything set it in motion (E0402): an earlier
    interaction in which `actor`, an object already in motion, sets it in motion."""
    mover = _mover(vocabulary)
    if mover is None or actor is None:
        return Advice("add an earlier interaction that sets it in motion")
    example = call(vocabulary, mover, (actor, obj))
    return Advice(f"add an earlier interaction that sets it in motion, e.g. `{example}`", before=example)


def goal_help(
    vocabulary: Vocabulary,
    goal: str,
    last: Resolved | None,
    actor: str | None,
    objects: Mapping[str, KnownObject] | None = None,
) -> Advice:
    """Help for a goal object that no interaction completes (E0404): interactions to add at the
    end of the sequence.

    `last` is the last interaction of the sequence (a resolved term), `actor` an object in motion at
    its end that may collide with the goal (None: the player's object), `objects` the scenario's
    objects by name (for a goal met with another object that must fit a term: the first declared
    one that does).
    """
    found, mover = _completer(vocabulary), _mover(vocabulary)
    if found is None:
        return Advice(f"add an interaction that meets the goal for '{goal}'")
    completer, position = found
    if position == 0:  # the goal object acts on another (touch(green, target))
        other = completer.object_parameters[1]
        term = vocabulary.object_term(other.fits) if other.fits else None
        partner = next(
            (
                o.name
                for o in (objects or {}).values()
                if o.name != goal and term and vocabulary.fits(o.concrete, term.name)
            ),
            None,
        )
        partner = partner or (term.abbreviation or term.name if term else actor or vocabulary.player)
        added = [call(vocabulary, completer, (goal, partner))]
    elif last is not None and last.signature.name == completer.requires and last.objects[1:2] == (goal,):
        added = [call(vocabulary, completer, (last.objects[0], goal))]
    else:
        actor = actor or vocabulary.player
        added = [call(vocabulary, completer, (actor, goal))]
        if mover is not None and completer.requires == mover.name:
            added.insert(0, call(vocabulary, mover, (actor, goal), every_direction=True))
    return Advice(f"add `> {' > '.join(added)}` at the end of the interactions", after=tuple(added))
