"""The vocabulary a domain brings to the `.phys` language.

The grammar knows no domain words. A domain declares:

* its **object terms** (`rollableBlock`, abbreviation `rBlock`, …) and the
  **concrete objects** each may become (`circle`, `circleSmall`, …), some of
  them static (platforms);
* its **term signatures**: interaction and restriction terms with typed
  parameters and the causal role of each parameter (acts, is set in motion, is
  destroyed), so the static checks of the language stay domain-agnostic;
* its **directions**, with aliases such as `any`;
* which object term the player sets in motion (the shot) and which objects are
  goals, with how the goal is met (angrybirds: every pig must be destroyed; a PHYRE-like
  domain: the green object must touch the target): an interaction with a `completes`
  parameter meets it for that parameter's object.
"""

from __future__ import annotations

import re

import attrs

# The kinds of a term and of a parameter are the front end's words (the domains import it).
from physc.dsl.vocabularies import DIRECTION, INTERACTION, OBJECT, RESTRICTION


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
    enabled_by: str | None = None  # or, instead, an earlier interaction of this name by the first object alone (destroy after explode)
    narrows: str | None = None  # restriction: narrows the directions of this interaction
    forbids: str | None = None  # restriction: forbids this interaction of its first object
    carries: bool = False  # restriction: its first object rests on its second, which sets it in motion when it moves or goes (a structure)

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
    players: int | None = None  # how many objects of the player's term compile places (None: any); check warns beyond (W0302)
    goal: str = ""  # object term of the goal objects: each must meet the goal (an interaction `completes` it)
    goal_unmet: str = "never meets the goal"  # what E0404 says of a goal object no interaction completes
    goal_rule: str = ""  # when a task is solved, for messages ("a task is solved when every pig is destroyed")
    # Derived in __attrs_post_init__: every direction word, aliases included.
    directions: tuple[str, ...] = attrs.field(init=False, default=())

    def __attrs_post_init__(self):
        by_spelling = {s: t for t in self.object_terms for s in t.spellings}
        object.__setattr__(self, "_by_spelling", by_spelling)
        object.__setattr__(self, "_terms", {t.name: t for t in self.terms})
        object.__setattr__(self, "_concrete", {c.name: c for c in self.concrete_objects})
        pattern = "|".join(sorted(map(re.escape, by_spelling), key=len, reverse=True))
        object.__setattr__(self, "_typed_name", re.compile(rf"({pattern})[0-9]*"))
        words: dict[str, None] = {}
        for term in self.terms:
            for parameter in term.parameters:
                words.update(dict.fromkeys(parameter.directions))
        words.update(dict.fromkeys(self.direction_aliases))
        object.__setattr__(self, "directions", tuple(words))

    def object_term(self, spelling: str) -> ObjectTerm | None:
        """The object term with this name or abbreviation."""
        return self._by_spelling.get(spelling)

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
        term = self._by_spelling[term_name]
        allowed = term.allowed + tuple(c for t in self.object_terms if term.name in t.fits_as for c in t.concrete)
        return all(c in allowed for c in concrete)


SIDES = ("left", "right", "above", "below")


def paper_terms(rollable: str, slidable: str, surface: str) -> tuple[dict[str, TermSignature], tuple[TermSignature, ...]]:
    """The paper's interaction terms (hit, roll, fall, slide, bounce, by name) and its
    restrictions (cannotHit, cannotFall), with the object terms a domain calls rollable,
    slidable and a surface. Recognition (physc.simulation.recognise) and the layout rules
    (physc.compiler.layout_rules) read these terms; a domain adds its goal term."""

    def actor(fits=None):
        return Parameter("a", OBJECT, fits=fits, dynamic=True, acts=True)

    hit_directions = SIDES + ("any",)
    along = ("left", "right")
    interactions = (
        TermSignature("hit", INTERACTION, (actor(), Parameter("b", OBJECT, moves=True), Parameter("d", DIRECTION, directions=hit_directions)), "a collides with b from direction d of b"),
        TermSignature("roll", INTERACTION, (actor(rollable), Parameter("b", OBJECT, fits=surface), Parameter("d", DIRECTION, directions=along)), "a rolls on b towards d"),
        TermSignature(
            "fall", INTERACTION,
            (actor(), Parameter("b", OBJECT), Parameter("d", DIRECTION, directions=("above", "left", "right"), default=("above",))),
            "a falls towards b (a starts far from b in direction d of b)",
        ),
        TermSignature("slide", INTERACTION, (actor(slidable), Parameter("b", OBJECT, fits=surface), Parameter("d", DIRECTION, directions=along)), "a slides on b towards d"),
        TermSignature(
            "bounce", INTERACTION,
            (Parameter("a", OBJECT, dynamic=True, acts=True, redirects=True), Parameter("b", OBJECT, fits=surface), Parameter("d", DIRECTION, directions=SIDES)),
            "a bounces off b towards d (where a goes after the bounce)",
        ),
    )
    restrictions = (
        TermSignature(
            "cannotHit", RESTRICTION,
            (Parameter("a", OBJECT, dynamic=True), Parameter("b", OBJECT), Parameter("d", DIRECTION, directions=hit_directions)),
            "during the solution, a must not collide with b from d", narrows="hit",
        ),
        TermSignature("cannotFall", RESTRICTION, (Parameter("a", OBJECT, dynamic=True),), "during the solution, a must not fall", forbids="fall"),
    )
    return {t.name: t for t in interactions}, restrictions


def structure_terms() -> tuple[TermSignature, TermSignature]:
    """Language version 2's restrictions on a level's make-up, which the layout rules read
    (physc.compiler.layout_rules) and the search checks (physc.generation.contrasts):
    `contrast(a, b)` (a domain that has it writes `SimulatedDomain.contrasted`) and `on(a, b)`."""
    contrast = TermSignature(
        "contrast",
        RESTRICTION,
        (Parameter("a", OBJECT, dynamic=True), Parameter("b", OBJECT, dynamic=True)),
        "a rests as b does, but the action that sets b going, aimed at a instead, does not solve the task (version 2: "
        "the heavier circle, the block on the taller pillar)",
    )
    on = TermSignature(
        "on",
        RESTRICTION,
        (Parameter("a", OBJECT, dynamic=True), Parameter("b", OBJECT, dynamic=True)),
        "a rests on b in the level: a structure of several bodies, whose weak point is what the chain knocks out (version 2)",
        carries=True,
    )
    return contrast, on
