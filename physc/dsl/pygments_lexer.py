"""A Pygments lexer for `.phys` files (`pygmentize -l phys FILE`).

Registered under the `pygments.lexers` entry point. Term, object and direction
words come from the built-in angrybirds domain's vocabulary, so highlighting
follows the domain.
"""

from __future__ import annotations

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

from physc.domains.angrybirds.vocabulary import VOCABULARY

_INTERACTIONS = tuple(t.name for t in VOCABULARY.terms if t.kind == "interaction")
_RESTRICTIONS = tuple(t.name for t in VOCABULARY.terms if t.kind == "restriction")
_OBJECT_TERMS = "|".join(s for t in VOCABULARY.object_terms for s in t.spellings)
_CONCRETE = tuple(c.name for c in VOCABULARY.concrete_objects)
_DIRECTIONS = VOCABULARY.directions


class PhysLexer(RegexLexer):
    name = "phys"
    aliases = ["phys", "physc"]
    filenames = ["*.phys"]
    mimetypes = ["text/x-phys"]
    url = "https://pypi.org/project/physc/"

    tokens = {
        "root": [
            (r"\s+", Whitespace),
            (r"(#|//).*?$", Comment.Single),
            (r'"', String.Double, "string"),
            (r"\b(scenario)(\s+)([A-Za-z_]\w*)", bygroups(Keyword.Declaration, Whitespace, Name.Class)),
            (r"\b(domain)(\s+)([A-Za-z_]\w*)", bygroups(Keyword, Whitespace, Name.Namespace)),
            (words(("objects", "interactions", "restrictions", "domain"), suffix=r"\b"), Keyword),
            (words(("and", "or"), suffix=r"\b"), Operator.Word),
            (words(_INTERACTIONS, prefix=r"\b", suffix=r"\b"), Name.Function),
            (words(_RESTRICTIONS, prefix=r"\b", suffix=r"\b"), Name.Function.Magic),
            (words(_DIRECTIONS, prefix=r"\b", suffix=r"\b"), Name.Constant),
            (words(_CONCRETE, prefix=r"\b", suffix=r"\b"), Name.Builtin.Pseudo),
            (rf"\b(?:{_OBJECT_TERMS})[0-9]*\b", Name.Builtin),
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
