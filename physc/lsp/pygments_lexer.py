"""The Pygments lexer that installing physc registers (`pygmentize -l phys FILE`).

Named by the `pygments.lexers` entry point, so Pygments loads it and no caller can hand it
anything: it takes the words of every installed domain that loads (the built-in angrybirds and
plugins such as the PHYRE-like one), so highlighting follows the domains a user has.
"""

from __future__ import annotations

from physc.domains.words import loadable_vocabularies
from physc.dsl.pygments_lexer import phys_lexer

PhysLexer = phys_lexer(loadable_vocabularies())
