"""Semantic tokens: every word of a `.phys` file coloured by what it is in its scenario's domain.

The TextMate grammar knows the language's keywords and Angry Birds' words; a domain installed as
a plugin (the PHYRE-like one's `touch`, `greenObject`, `blueJar`) is known only here, from the
vocabulary `physc check` loads. Words the domain does not know get no token (their diagnostic
says why).
"""

from __future__ import annotations

from lsprotocol import types

from physc.domains import DEFAULT_DOMAIN
from physc.dsl import ast
from physc.lsp.positions import Positions
from physc.lsp.vocabularies import vocabulary_of

# The legend: what each kind of word is, in LSP's standard token types and modifiers.
TOKEN_TYPES = ("namespace", "type", "class", "function", "variable", "enumMember")
TOKEN_MODIFIERS = ("declaration", "defaultLibrary")
LEGEND = types.SemanticTokensLegend(token_types=list(TOKEN_TYPES), token_modifiers=list(TOKEN_MODIFIERS))
_DECLARATION, _LIBRARY = 1, 2  # modifier bits


def tokens(file: ast.File, positions: Positions) -> types.SemanticTokens:
    """The file's tokens, in document order, encoded as LSP asks (relative positions)."""
    found: list[tuple[int, int, str, int]] = []  # (start, end, type, modifiers)
    for scenario in file.scenarios:
        found += _scenario(scenario)
    data, line, column = [], 0, 0
    for start, end, kind, modifiers in sorted(found):
        first, last = positions.position(start), positions.position(end)
        if first.line != last.line:  # a token never spans lines
            continue
        data += [
            first.line - line,
            first.character - (column if first.line == line else 0),
            last.character - first.character,
            TOKEN_TYPES.index(kind),
            modifiers,
        ]
        line, column = first.line, first.character
    return types.SemanticTokens(data=data)


def _scenario(scenario: ast.Scenario) -> list[tuple[int, int, str, int]]:
    vocabulary = vocabulary_of(scenario.domain.text if scenario.domain else DEFAULT_DOMAIN)
    if vocabulary is None:
        return []
    out = []

    def add(name: ast.Name | None, kind: str, modifiers: int = 0) -> None:
        if name is not None and name.span is not None:
            out.append((name.span.start, name.span.end, kind, modifiers))

    add(scenario.domain, "namespace")
    for declaration in scenario.objects:
        add(declaration.name, "variable", _DECLARATION)
        if vocabulary.object_term(declaration.term.text):
            add(declaration.term, "type", _LIBRARY)
        for concrete in declaration.concrete:
            if vocabulary.concrete(concrete.text):
                add(concrete, "class", _LIBRARY)
    for term in scenario.interactions + scenario.restrictions:
        signature = vocabulary.term(term.name.text)
        if signature is None:
            continue
        add(term.name, "function", _LIBRARY)
        for argument in term.arguments:
            for name in argument.alternatives:
                if name.text in vocabulary.directions:
                    add(name, "enumMember", _LIBRARY)
                else:
                    add(name, "variable")
    return out
