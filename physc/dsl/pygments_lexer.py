"""A Pygments lexer for `.phys` files (`pygmentize -l phys FILE`).

Registered under the `pygments.lexers` entry point. Term, object and direction words come
from the vocabularies of every installed domain (the built-in angrybirds and plugins such as
the PHYRE-like one), so highlighting follows the domains a user has.
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


def _vocabularies() -> list:
    """The vocabulary of each installed domain that loads (a broken plugin is skipped: the
    lexer must still highlight)."""
    from physc.domains import installed_domains, load_domain

    found = []
    for name in sorted(installed_domains()):
        try:
            found.append(load_domain(name).vocabulary)
        except Exception:
            continue
    return found


_VOCABULARIES = _vocabularies()
_INTERACTIONS = tuple(sorted({t.name for v in _VOCABULARIES for t in v.terms if t.kind == "interaction"}))
_RESTRICTIONS = tuple(sorted({t.name for v in _VOCABULARIES for t in v.terms if t.kind == "restriction"}))
_OBJECT_TERMS = "|".join(sorted({re.escape(s) for v in _VOCABULARIES for t in v.object_terms for s in t.spellings}, key=lambda s: (-len(s), s)))
_CONCRETE = tuple(sorted({c.name for v in _VOCABULARIES for c in v.concrete_objects}))
_DIRECTIONS = tuple(sorted({d for v in _VOCABULARIES for d in v.directions}))
# What a .phys file has and other languages rarely do: a scenario block, or the paper's
# `hit(…) > destroy(…)` sequence form.
# Unambiguous patterns (each space belongs to one part), so a failing search is linear: every
# Pygments user's guess_lexer runs them on any text.
_SCENARIO = re.compile(r"^[ \t]*scenario[ \t]+[A-Za-z_]\w*[ \t]*(\"[^\"\n]*\"[ \t]*)?\{", re.MULTILINE)
_SEQUENCE = re.compile(r"\b[a-z]\w*\(\s*\w+(?:\s*[,|]\s*\w+)*\s*\)\s*>\s*[a-z]\w*\(")


class PhysLexer(RegexLexer):
    name = "phys"
    aliases = ["phys", "physc"]
    filenames = ["*.phys"]
    mimetypes = ["text/x-phys"]
    url = "https://pypi.org/project/physc/"

    def analyse_text(text):
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
