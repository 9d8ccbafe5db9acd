"""The Scenario IR: a checked scenario with typed objects and narrowed directions.

This is what the static checks (`physc.dsl.check`) produce and what the compiler
passes consume (`physc compile --emit scenario`).
"""

from __future__ import annotations

import attrs

from physc.diagnostics import Span


@attrs.frozen
class ObjectIR:
    """An object instance of the scenario (every use of one name is one object)."""

    name: str
    term: str  # the object term, e.g. "rollableBlock"
    concrete: tuple[str, ...]  # the concrete objects it may become
    static: bool
    declared: bool  # declared in `objects { }` (else typed by its spelling)
    span: Span | None = attrs.field(eq=False, default=None)
    # The materials it may be made of, as declared (language version 2); none: any its concrete
    # objects may be made of. Left out of dumps while none, as version 1 has none.
    materials: tuple[str, ...] = attrs.field(default=(), metadata={"omit_default": True})


@attrs.frozen
class TermIR:
    """An interaction or restriction with resolved objects and directions.

    `directions` is the set the generator may realise: aliases (`any`) expanded,
    defaults filled in and, for interactions, narrowed by the restrictions.
    `written` is the set as written (aliases expanded), before narrowing.
    """

    name: str
    objects: tuple[str, ...]
    directions: tuple[str, ...] = ()
    written: tuple[str, ...] = ()
    text: str = ""  # the term as written, in canonical form: "hit(bird, pig, left | above)"
    span: Span | None = attrs.field(eq=False, default=None)


@attrs.frozen
class ScenarioIR:
    name: str
    title: str | None
    domain: str
    objects: tuple[ObjectIR, ...]
    interactions: tuple[TermIR, ...]
    restrictions: tuple[TermIR, ...]
    path: str = attrs.field(eq=False, default="")

    def object(self, name: str) -> ObjectIR:
        return next(o for o in self.objects if o.name == name)
