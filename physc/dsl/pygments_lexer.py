"""The rules of the Pygments lexer for `.phys` files, made for the vocabularies it is handed.

`phys_lexer` knows the language's keywords and forms; term, object and direction words come from
the vocabularies its caller hands it. `physc.lsp.pygments_lexer` makes the lexer that installing physc
registers (`pygmentize -l phys FILE`), with every installed domain's words: the front end loads
no domain.
"""

from __future__ import annotations

import re

from pygments.lexer import RegexLexer, bygroups, words
from pygments.token import (
    Comment,
    Keyword,
    Name,
    Operator,
    Punctuation,
    String,
    Text,
    Whitespace,
)

from physc.dsl.vocabularies import INTERACTION, RESTRICTION

# What a .phys file has and other languages rarely do: a scenario block, or the paper's
# `hit(…) > destroy(…)` sequence form.
# Unambiguous patterns (each space belongs to one part), so a failing search is linear: every
# Pygments user's guess_lexer runs them on any text.
_SCENARIO = re.compile(r"^[ \t]*scenario[ \t]+[A-Za-z_]\w*[ \t]*(\"[^\"\n]*\"[ \t]*)?\{", re.MULTILINE)
_SEQUENCE = re.compile(r"\b[a-z]\w*\(\s*\w+(?:\s*[,|]\s*\w+)*\s*\)\s*>\s*[a-z]\w*\(")


def phys_lexer(vocabularies) -> type[RegexLexer]:
    """The lexer class `PhysLexer` that highlights the words of `vocabularies` (each a
    `physc.domains.vocabulary.Vocabulary`)."""
    vocabularies = list(vocabularies)
    interactions = tuple(sorted({t.name for v in vocabularies for t in v.terms if t.kind == INTERACTION}))
    restrictions = tuple(sorted({t.name for v in vocabularies for t in v.terms if t.kind == RESTRICTION}))
    object_terms = "|".join(
        sorted(
            {re.escape(s) for v in vocabularies for t in v.object_terms for s in t.spellings},
            key=lambda s: (-len(s), s),
        )
    )
    concrete = tuple(sorted({c.name for v in vocabularies for c in v.concrete_objects}))
    directions = tuple(sorted({d for v in vocabularies for d in v.directions}))

    class PhysLexer(RegexLexer):
        name = "phys"
        aliases = ["phys", "physc"]
        filenames = ["*.phys"]
        mimetypes = ["text/x-phys"]

        @staticmethod
        def analyse_text(text: str) -> float:
            """How sure it is that `text` is a .phys file (Pygments' guess_lexer asks every lexer)."""
            if _SCENARIO.search(text):
                return 0.9 if ("interactions" in text or "restrictions" in text) else 0.6
            if _SEQUENCE.search(text):
                return 0.5
            return 0.0

        tokens = {
            "root": [
                (r"\s+", Whitespace),
                (r"(#|//).*?$", Comment.Single),
                (r'"', String.Double, "string"),
                (r"\b(scenario)(\s+)([A-Za-z_]\w*)", bygroups(Keyword.Declaration, Whitespace, Name.Class)),
                (r"\b(domain)(\s+)([A-Za-z_]\w*)", bygroups(Keyword, Whitespace, Name.Namespace)),
                (words(("objects", "interactions", "restrictions", "domain"), suffix=r"\b"), Keyword),
                (words(("and", "or"), suffix=r"\b"), Operator.Word),
                (words(interactions, prefix=r"\b", suffix=r"\b"), Name.Function),
                (words(restrictions, prefix=r"\b", suffix=r"\b"), Name.Function.Magic),
                (words(directions, prefix=r"\b", suffix=r"\b"), Name.Constant),
                (words(concrete, prefix=r"\b", suffix=r"\b"), Name.Builtin.Pseudo),
                (rf"\b(?:{object_terms})[0-9]*\b", Name.Builtin),
                (r"[A-Za-z_]\w*", Name.Variable),
                (r"[>|∨&∧=]", Operator),
                (r"[{}()\[\],:]", Punctuation),
                (r".", Text),
            ],
            "string": [
                (r'\\["\\]', String.Escape),
                (r'"', String.Double, "#pop"),
                (r"\n", Text, "#pop"),
                (r'[^"\\\n]+', String.Double),
                (r"\\.", String.Double),
            ],
        }

    return PhysLexer
