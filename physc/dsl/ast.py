"""The abstract syntax tree of `.phys` files.

Nodes are frozen attrs classes. Every node carries a source `span` that does not
take part in equality, so the block form and the paper form of one scenario give
equal trees, and a formatted file parses to a tree equal to the original.
The tree is purely syntactic: which terms and objects exist is the domain's
business (see `physc.dsl.check`).
"""

from __future__ import annotations

import attrs

from physc.diagnostics import Span

_span = attrs.field(eq=False, default=None, repr=False)


def located(span: Span | None) -> Span:
    """The span of a node of a parsed tree, which the parser always gives one (only a tree built by
    hand, to compare or format, has none): what the checks read where a message points at it."""
    assert span is not None, "a node without a span: only a parsed tree is checked"
    return span


@attrs.frozen
class Name:
    """An identifier: an object, term, direction, domain or concrete-object name."""

    text: str
    span: Span | None = _span


@attrs.frozen
class Text:
    """A string literal, unescaped."""

    value: str
    span: Span | None = _span


@attrs.frozen
class Argument:
    """One argument of a term: a name, or a set of alternatives `left | above`."""

    alternatives: tuple[Name, ...]
    span: Span | None = _span


@attrs.frozen
class Term:
    """`hit(bird, pig, left)`; the paper's curried form gives the same node."""

    name: Name
    arguments: tuple[Argument, ...]
    span: Span | None = _span
    # With its brackets, `[hit(bird)(pig)(left)]`, when written in them (where a fix inserts a term).
    outer: Span | None = attrs.field(eq=False, default=None, repr=False, metadata={"dump": False})


@attrs.frozen
class Declaration:
    """`rBlock: rollableBlock = circle | circleSmall` in an `objects` section; in version 2
    also the materials it may be made of, `fBlock: fallableBlock(stone | ice) = rectFat`."""

    name: Name
    term: Name
    concrete: tuple[Name, ...] = ()
    span: Span | None = _span
    materials: tuple[Name, ...] = attrs.field(default=(), metadata={"omit_default": True})


@attrs.frozen
class Scenario:
    name: Name
    title: Text | None = None
    domain: Name | None = None
    objects: tuple[Declaration, ...] = ()
    interactions: tuple[Term, ...] = ()
    restrictions: tuple[Term, ...] = ()
    span: Span | None = _span
    form: str = attrs.field(eq=False, default="block")  # "block" | "paper"
    # Block form only: (section, keyword span, closing-brace span), for the formatter.
    sections: tuple[tuple[str, Span, Span], ...] = attrs.field(
        eq=False, default=(), repr=False, metadata={"dump": False}
    )


@attrs.frozen
class Comment:
    """A comment, kept for the formatter; not part of the tree proper."""

    text: str
    span: Span


@attrs.frozen
class File:
    scenarios: tuple[Scenario, ...]
    comments: tuple[Comment, ...] = attrs.field(eq=False, default=(), metadata={"dump": False})
