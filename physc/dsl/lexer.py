"""A fast lexer for lark, built from the terminals of `phys.lark`.

lark's own basic lexer counts lines and columns for every token. physc does
not need that: spans are computed from offsets, and only when a position is
shown. This lexer matches one alternation of the grammar's terminals per token
and yields lark Tokens carrying offsets; it is plugged into lark as a custom
lexer, so the grammar file stays the single definition of the tokens.

Keywords: a string terminal that the NAME pattern also matches (`scenario`,
`and`, …) is found by looking the matched NAME up, exactly as lark does.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from typing import Protocol

from lark.common import LexerConf
from lark.exceptions import UnexpectedCharacters
from lark.lexer import Lexer, PatternStr, Token

_new_token = Token._future_new


class OffsetToken(Protocol):
    """A token as FastLexer makes it: its offsets are always set (lark's Token types them optional)."""

    type: str
    start_pos: int
    end_pos: int


class FastLexer(Lexer):
    __future_interface__ = 0  # lark calls lex(self, text), not the base class's lex(lexer_state, parser_state)

    def __init__(self, lexer_conf: LexerConf):
        terminals = lexer_conf.terminals
        self.ignore = frozenset(lexer_conf.ignore)
        name_terminal = next(t for t in terminals if t.name == "NAME")
        name_pattern = re.compile(name_terminal.pattern.to_regexp())
        self.keywords: dict[str, str] = {}
        strings, patterns = [], []
        for terminal in terminals:
            pattern = terminal.pattern
            if isinstance(pattern, PatternStr) and name_pattern.fullmatch(pattern.value):
                self.keywords[pattern.value] = terminal.name
            elif isinstance(pattern, PatternStr):
                strings.append(terminal)
            else:
                patterns.append(terminal)
        # Longer strings first, so that a string is never cut short by its prefix.
        strings.sort(key=lambda t: -len(t.pattern.value))
        patterns.sort(key=lambda t: -t.priority)
        alternation = "|".join(f"(?P<{t.name}>{t.pattern.to_regexp()})" for t in strings + patterns)
        self.scanner = re.compile(alternation)
        self.terminal_names = frozenset(t.name for t in terminals) - self.ignore

    def lex(self, text: str) -> Iterator[Token]:  # pyright: ignore[reportIncompatibleMethodOverride]  # interface 0
        match = self.scanner.match
        ignore, keywords = self.ignore, self.keywords
        position, end = 0, len(text)
        while position < end:
            found = match(text, position)
            if found is None:
                raise UnexpectedCharacters(text, position, None, None, allowed=self.terminal_names)
            kind = found.lastgroup
            stop = found.end()
            if kind not in ignore:
                value = found.group()
                if kind == "NAME":
                    kind = keywords.get(value, "NAME")
                yield _new_token(kind, value, position, end_pos=stop)
            position = stop
