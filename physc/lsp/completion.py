"""Completion: what may be written at a place, from the domain's vocabulary and the scenario.

After `hit(` only what fits there is offered: the objects of the scenario and the object names
whose type the domain infers (`rBlock`, `pig`) that fit the parameter, or the parameter's
directions. Terms come with a snippet of their parameters when the client takes snippets.
"""

from __future__ import annotations

from lsprotocol import types

from physc.domains import installed_domains
from physc.domains.vocabulary import DIRECTION, INTERACTION, RESTRICTION, Parameter, TermSignature, Vocabulary
from physc.lsp import context
from physc.lsp.context import Place
from physc.lsp.vocabularies import object_concrete, vocabulary_of

Kind = types.CompletionItemKind
_SECTION_SNIPPETS = {
    "domain": "domain ${1:angrybirds}",
    "objects": "objects {\n\t$0\n}",
    "interactions": "interactions {\n\t$0\n}",
    "restrictions": "restrictions {\n\t$0\n}",
}
_SCENARIO_SNIPPET = "scenario ${1:Name} {\n\tinteractions {\n\t\t$0\n\t}\n}"


def complete(place: Place, snippets: bool) -> list[types.CompletionItem]:
    """The completion items for a place."""
    role = place.role
    if role == context.TOP:
        return [_keyword("scenario", _SCENARIO_SNIPPET if snippets else None)]
    if role == context.BODY:
        missing = [s for s in _SECTION_SNIPPETS if s not in place.sections]
        return [_keyword(s, _SECTION_SNIPPETS[s] if snippets else None) for s in missing]
    if role == context.DOMAIN:
        return [types.CompletionItem(label=name, kind=Kind.Module, detail="domain") for name in installed_domains()]
    vocabulary = vocabulary_of(place.domain)
    if vocabulary is None:
        return []
    if role == context.OBJECT_TERM:
        return [
            types.CompletionItem(
                label=t.name, kind=Kind.Class, detail=" | ".join(t.concrete), documentation=t.noun or None
            )
            for t in vocabulary.object_terms
        ]
    if role in (context.CONCRETE, context.MATERIAL):
        term = vocabulary.object_term(place.object_term or "")
        names = term.allowed if term else tuple(c.name for c in vocabulary.concrete_objects)
        if role == context.CONCRETE:
            return [_concrete(vocabulary, name) for name in names]
        return [
            types.CompletionItem(label=m, kind=Kind.EnumMember, detail="material")
            for m in vocabulary.materials(names, every=False)
        ]
    if role == context.TERM and place.section in ("interactions", "restrictions"):
        kind = INTERACTION if place.section == "interactions" else RESTRICTION
        return [_term(t, snippets) for t in vocabulary.terms if t.kind == kind]
    if role == context.ARGUMENT:
        signature = vocabulary.term(place.term or "")
        if signature is None or place.argument >= len(signature.parameters):
            return []
        return _arguments(vocabulary, place, signature.parameters[place.argument])
    return []


def _keyword(word: str, snippet: str | None) -> types.CompletionItem:
    if snippet is None:
        return types.CompletionItem(label=word, kind=Kind.Keyword)
    return types.CompletionItem(
        label=word, kind=Kind.Keyword, insert_text=snippet, insert_text_format=types.InsertTextFormat.Snippet
    )


def _concrete(vocabulary: Vocabulary, name: str) -> types.CompletionItem:
    concrete = vocabulary.concrete(name)
    assert concrete is not None  # a term's concrete objects are the vocabulary's
    detail = "static" if concrete.static else "dynamic"
    return types.CompletionItem(
        label=name, kind=Kind.EnumMember, detail=detail, documentation=concrete.description or None
    )


def _term(signature: TermSignature, snippets: bool) -> types.CompletionItem:
    item = types.CompletionItem(
        label=signature.name,
        kind=Kind.Function if signature.kind == INTERACTION else Kind.Interface,
        detail=signature.usage(),
        documentation=signature.description or None,
    )
    if snippets:
        slots = []
        for number, parameter in enumerate(signature.parameters, 1):
            if parameter.kind == DIRECTION and parameter.directions:
                slots.append(f"${{{number}|{','.join(parameter.directions)}|}}")
            else:
                slots.append(f"${{{number}:{parameter.name}}}")
        item.insert_text = f"{signature.name}({', '.join(slots)})"
        item.insert_text_format = types.InsertTextFormat.Snippet
    return item


def _arguments(vocabulary: Vocabulary, place: Place, parameter: Parameter) -> list[types.CompletionItem]:
    if parameter.kind == DIRECTION:
        items = []
        for direction in parameter.directions:
            expanded = vocabulary.expand(direction)
            detail = "any of " + ", ".join(expanded) if expanded != (direction,) else "direction"
            items.append(types.CompletionItem(label=direction, kind=Kind.EnumMember, detail=detail))
        return items

    def fits(concrete: tuple[str, ...] | None) -> bool:
        if not concrete:
            return False
        if parameter.fits and not vocabulary.fits(concrete, parameter.fits):
            return False
        return not (parameter.dynamic and vocabulary.is_static(concrete))

    items, seen = [], set()
    names = list(place.declared) + [n for n in place.arguments if n not in vocabulary.directions]
    for name in names:  # the scenario's objects first
        if name in seen or (place.word is not None and name == place.word.text):
            continue
        seen.add(name)
        term, concrete = object_concrete(vocabulary, place, name)
        if fits(concrete):
            items.append(
                types.CompletionItem(label=name, kind=Kind.Variable, detail=term, sort_text=f"0{len(items):04d}")
            )
    for term in vocabulary.object_terms:  # then the names whose type the domain infers
        name = term.abbreviation or term.name
        if name not in seen and fits(term.concrete):
            seen.add(name)
            items.append(
                types.CompletionItem(
                    label=name, kind=Kind.Class, detail=f"a new {term.name}", sort_text=f"1{len(items):04d}"
                )
            )
    return items
