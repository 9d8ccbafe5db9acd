"""Hover: what a name at a place means, and what a diagnostic there is about.

A term shows its signature and description; an object its type and the concrete objects it may be;
an object term, concrete object, direction or domain what the vocabulary says of it; a diagnostic
its message, help and the section of docs/errors.md about its code.
"""

from __future__ import annotations

from collections.abc import Sequence

from physc import error_codes
from physc.diagnostics import Diagnostic
from physc.domains import load_domain
from physc.domains.vocabulary import DIRECTION, Vocabulary
from physc.lsp import context
from physc.lsp.context import Place
from physc.lsp.vocabularies import object_concrete, vocabulary_of


def hover_text(place: Place, diagnostics: Sequence[Diagnostic]) -> str | None:
    """Markdown for a hover at a place, given the diagnostics whose span holds it."""
    parts = [_diagnostic(d) for d in diagnostics]
    word = _word(place)
    if word:
        parts.append(word)
    return "\n\n---\n\n".join(parts) or None


def _diagnostic(diagnostic: Diagnostic) -> str:
    text = f"**{diagnostic.severity.value}[{diagnostic.code}]**: {diagnostic.message}"
    if diagnostic.help:
        text += f"\n\nhelp: {diagnostic.help}"
    explained = error_codes.explanation(diagnostic.code)
    return text + (f"\n\n{explained}" if explained else "")


def _word(place: Place) -> str | None:
    if place.word is None:
        return None
    name, role = place.word.text, place.role
    if role == context.DOMAIN:
        try:
            domain = load_domain(name)
        except Exception:  # not installed, or broken: the diagnostics say so
            return None
        return f"**domain** `{name}`: {domain.description}"
    vocabulary = vocabulary_of(place.domain)
    if vocabulary is None:
        return None
    if role == context.TERM or (role == context.OTHER and place.section in ("interactions", "restrictions")):
        signature = vocabulary.term(name)
        if signature is None:
            return None
        text = f"```phys\n{signature.usage()}\n```\n\n{signature.kind}"
        return text + (f": {signature.description}" if signature.description else "")
    if role == context.ARGUMENT:
        signature = vocabulary.term(place.term or "")
        if signature and place.argument < len(signature.parameters):
            parameter = signature.parameters[place.argument]
            if parameter.kind == DIRECTION:
                return _direction(vocabulary, name, signature.name)
        return _object(vocabulary, place, name)
    if role in (context.DECLARATION, context.OTHER) and place.section == "objects":
        return _object(vocabulary, place, name)
    if role == context.OBJECT_TERM:
        term = vocabulary.object_term(name)
        if term is None:
            return None
        text = f"**object term** `{term.name}`" + (f" ({term.noun})" if term.noun else "")
        return text + f"\n\nconcrete objects: {' | '.join(term.concrete)}"
    if role == context.CONCRETE:
        concrete = vocabulary.concrete(name)
        if concrete is None:
            return None
        text = f"**concrete object** `{name}`, {'static' if concrete.static else 'dynamic'}"
        return text + (f": {concrete.description}" if concrete.description else "")
    return None


def _object(vocabulary: Vocabulary, place: Place, name: str) -> str | None:
    term, concrete = object_concrete(vocabulary, place, name)
    if term is None:
        return None
    how = "declared" if name in place.declared else "its type inferred from its name"
    text = f"**object** `{name}`: {term} ({how})"
    if concrete:
        moving = "static" if vocabulary.is_static(concrete) else "dynamic"
        text += f"\n\nmay be: {' | '.join(concrete)} ({moving})"
    return text


def _direction(vocabulary: Vocabulary, name: str, term: str) -> str:
    expanded = vocabulary.expand(name)
    if expanded != (name,):
        return f"**direction** `{name}` of `{term}`: any of {', '.join(expanded)}"
    return f"**direction** `{name}` of `{term}`"
