"""A domain's vocabulary as the front end reads it, and the vocabularies it is handed, by name.

The front end loads no domain (the domains import it, not the other way round): a domain writes its
`Vocabulary` of the classes below (physc.domains.vocabulary hands them to plugins, with the paper's
terms), and the layers above build a `Vocabularies` from the installed domains and hand it to the
checks. The kinds are the words a vocabulary marks its terms and parameters with.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable

import attrs

# The kinds of a term (the section it is written in) and of a parameter, as a vocabulary marks them.
OBJECT = "object"
DIRECTION = "direction"
INTERACTION = "interaction"
RESTRICTION = "restriction"


@attrs.frozen
class ConcreteObject:
    """A game object that an object term may become (`circle`, `flatPlatform`), and the
    materials it may be made of (none: a body with no material, a pig or a platform)."""

    name: str
    static: bool = False
    description: str = ""
    materials: tuple[str, ...] = ()


@attrs.frozen
class ObjectTerm:
    """A term of the object grammar, e.g. `rollableBlock` (abbreviation `rBlock`)."""

    name: str
    concrete: tuple[str, ...]
    abbreviation: str | None = None
    noun: str = ""  # how a message names it: "a rollable object"
    # Other object terms whose parameters it fits too, without being one of their concretes
    # (angrybirds: the level's ground fits where a surface does, but a surface is never drawn as it).
    fits_as: tuple[str, ...] = ()
    # Concrete objects a declaration may pin besides those it becomes when left open (language
    # version 2: the game's other bodies): a version-1 scenario, which pins none of them, is
    # laid out from `concrete` alone, as before.
    pinnable: tuple[str, ...] = ()

    @property
    def allowed(self) -> tuple[str, ...]:
        """Every concrete object a declaration of this term may pin."""
        return self.concrete + self.pinnable

    @property
    def spellings(self) -> tuple[str, ...]:
        return (self.name,) if self.abbreviation is None else (self.name, self.abbreviation)


@attrs.frozen
class Parameter:
    """One parameter of a term.

    An object parameter may require its object to fit an object term (`fits`:
    every concrete object the argument may become is one the term allows) and/or
    to be dynamic. A direction parameter lists its allowed directions; with a
    `default` it is optional. At most one direction parameter per term.
    """

    name: str
    kind: str  # OBJECT | DIRECTION
    fits: str | None = None
    dynamic: bool = False
    directions: tuple[str, ...] = ()
    default: tuple[str, ...] | None = None
    acts: bool = False  # the object acts: it must already be in motion
    moves: bool = False  # the interaction sets the object in motion
    destroys: bool = False  # the interaction destroys the object (it takes part in nothing after)
    completes: bool = False  # the interaction meets the domain's goal for the object (E0404)
    redirects: bool = False  # the interaction changes the object's course (a bounce)


@attrs.frozen
class TermSignature:
    name: str
    kind: str  # INTERACTION | RESTRICTION
    parameters: tuple[Parameter, ...]
    description: str = ""
    requires: str | None = None  # an earlier interaction with the same objects is required
    # or, instead, an earlier interaction of this name by the first object alone (destroy after explode)
    enabled_by: str | None = None
    narrows: str | None = None  # restriction: narrows the directions of this interaction
    forbids: str | None = None  # restriction: forbids this interaction of its first object
    # restriction: its first object rests on its second, which sets it in motion when it moves or
    # goes (a structure)
    carries: bool = False

    @property
    def required_count(self) -> int:
        return sum(1 for p in self.parameters if p.default is None)

    @property
    def direction_parameter(self) -> Parameter | None:
        return next((p for p in self.parameters if p.kind == DIRECTION), None)

    @property
    def object_parameters(self) -> tuple[Parameter, ...]:
        return tuple(p for p in self.parameters if p.kind == OBJECT)

    def usage(self) -> str:
        parts = []
        for p in self.parameters:
            text = p.name if p.kind == OBJECT else f"{p.name} ⊆ {{{', '.join(p.directions)}}}"
            parts.append(f"[{text}]" if p.default is not None else text)
        return f"{self.name}({', '.join(parts)})"


@attrs.frozen(slots=False, eq=False)
class Vocabulary:
    object_terms: tuple[ObjectTerm, ...]
    concrete_objects: tuple[ConcreteObject, ...]
    terms: tuple[TermSignature, ...]
    direction_aliases: dict[str, tuple[str, ...]] = attrs.field(factory=dict)
    player: str = ""  # object term of what the player sets in motion
    # how many objects of the player's term compile places (None: any); check warns beyond (W0302)
    players: int | None = None
    goal: str = ""  # object term of the goal objects: each must meet the goal (an interaction `completes` it)
    goal_unmet: str = "never meets the goal"  # what E0404 says of a goal object no interaction completes
    goal_rule: str = ""  # when a task is solved, for messages ("a task is solved when every pig is destroyed")
    # Derived in __attrs_post_init__: every direction word, aliases included.
    directions: tuple[str, ...] = attrs.field(init=False, default=())

    def __attrs_post_init__(self):
        words: dict[str, None] = {}
        for term in self.terms:
            for parameter in term.parameters:
                words.update(dict.fromkeys(parameter.directions))
        words.update(dict.fromkeys(self.direction_aliases))
        object.__setattr__(self, "directions", tuple(words))

    # The look-ups below are derived from the fields once, on first use (kept in the instance's
    # __dict__, which a frozen attrs class without slots allows; they are not attrs fields).
    @functools.cached_property
    def _by_spelling(self) -> dict[str, ObjectTerm]:
        return {s: t for t in self.object_terms for s in t.spellings}

    @functools.cached_property
    def _terms(self) -> dict[str, TermSignature]:
        return {t.name: t for t in self.terms}

    @functools.cached_property
    def _concrete(self) -> dict[str, ConcreteObject]:
        return {c.name: c for c in self.concrete_objects}

    @functools.cached_property
    def _typed_name(self) -> re.Pattern[str]:
        """An undeclared object's name: an object term's spelling and an optional number."""
        pattern = "|".join(sorted(map(re.escape, self._by_spelling), key=len, reverse=True))
        return re.compile(rf"({pattern})[0-9]*")

    def object_term(self, spelling: str) -> ObjectTerm | None:
        """The object term with this name or abbreviation."""
        return self._by_spelling.get(spelling)

    def object_term_named(self, spelling: str) -> ObjectTerm:
        """The object term that the vocabulary itself names (a parameter's `fits`, its `player` or
        `goal`): a KeyError if it has none, a fault of the vocabulary."""
        return self._by_spelling[spelling]

    def term_of_name(self, name: str) -> ObjectTerm | None:
        """The object term an undeclared object name implies (`rBlock2` → rollableBlock)."""
        match = self._typed_name.fullmatch(name)
        return self._by_spelling[match.group(1)] if match else None

    def term(self, name: str) -> TermSignature | None:
        return self._terms.get(name)

    def concrete(self, name: str) -> ConcreteObject | None:
        return self._concrete.get(name)

    def expand(self, direction: str) -> tuple[str, ...]:
        return self.direction_aliases.get(direction, (direction,))

    @property
    def spellings(self) -> tuple[str, ...]:
        return tuple(self._by_spelling)

    def materials(self, concrete: tuple[str, ...] | None = None, every: bool = True) -> tuple[str, ...]:
        """The materials every one of `concrete` may be made of (with `every` False: any of
        them; `concrete` None: every concrete object), in the vocabulary's order."""
        names = tuple(self._concrete) if concrete is None else concrete
        found = [set(self._concrete[c].materials) for c in names if c in self._concrete]
        chosen = (set.intersection if every else set.union)(*found) if found else set()
        order = [m for c in self.concrete_objects for m in c.materials]
        return tuple(dict.fromkeys(m for m in order if m in chosen))

    def is_static(self, concrete: tuple[str, ...]) -> bool:
        return all(self._concrete[c].static for c in concrete)

    def fits(self, concrete: tuple[str, ...], term_name: str) -> bool:
        term = self.object_term_named(term_name)
        allowed = term.allowed + tuple(c for t in self.object_terms if term.name in t.fits_as for c in t.concrete)
        return all(c in allowed for c in concrete)


class VocabularyError(Exception):
    """Why a domain has no vocabulary, said as the diagnostic on the scenario's domain: its `code`
    (E0701: not installed, E0702: its plugin fails to load), and the installed names that the
    asked-for one may be a misspelling of (`suggestions`, its quick fixes)."""

    def __init__(self, code: str, message: str, help: str | None = None, suggestions: tuple[str, ...] = ()):
        super().__init__(message)
        self.code = code
        self.message = message
        self.help = help
        self.suggestions = suggestions


@attrs.frozen
class Vocabularies:
    """The vocabularies that the checks are handed: `lookup(name)` gives a domain's vocabulary or
    raises VocabularyError; `default` is the domain of a scenario that names none."""

    lookup: Callable[[str], Vocabulary]
    default: str
