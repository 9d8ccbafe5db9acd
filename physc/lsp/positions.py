"""Offsets in a document ↔ LSP positions.

physc's spans are offsets in code points; an LSP position is a line and a column counted in the
position encoding that client and server agreed on (UTF-16 code units unless the client offers
UTF-8 or UTF-32). Lines end at `\\n`, `\\r\\n` or `\\r`, as the protocol says (not at the other
breaks that Python's `splitlines` knows, such as U+2028). A position past the end of a line or of
the document is clamped, never an error: a client may ask about a place that an edit has just
removed.
"""

from __future__ import annotations

import bisect
import re
from collections.abc import Callable

from lsprotocol import types

from physc.diagnostics import Span

# Code units per encoding; "surrogatepass" because a JSON string may carry a lone surrogate.
_UNITS: dict[str, Callable[[str], int]] = {
    types.PositionEncodingKind.Utf8: lambda text: len(text.encode("utf-8", "surrogatepass")),
    types.PositionEncodingKind.Utf16: lambda text: len(text.encode("utf-16-le", "surrogatepass")) // 2,
    types.PositionEncodingKind.Utf32: len,
}
_LINE_END = re.compile(r"\r\n|\r|\n")


class Positions:
    """Converts between offsets of `text` and positions in `encoding`."""

    def __init__(self, text: str, encoding: str = types.PositionEncodingKind.Utf16):
        self.text = text
        self.units = _UNITS.get(encoding, _UNITS[types.PositionEncodingKind.Utf16])
        self.utf32 = self.units is len
        self.starts = [0]  # the offset where each line starts
        self.ends: list[int] = []  # the offset where each line's text ends (its line break excluded)
        for found in _LINE_END.finditer(text):
            self.ends.append(found.start())
            self.starts.append(found.end())
        self.ends.append(len(text))

    def position(self, offset: int) -> types.Position:
        offset = min(max(offset, 0), len(self.text))
        line = bisect.bisect_right(self.starts, offset) - 1
        before = self.text[self.starts[line] : min(offset, self.ends[line])]
        column = len(before) if self.utf32 or before.isascii() else self.units(before)
        return types.Position(line=line, character=column)

    def range(self, span: Span) -> types.Range:
        return types.Range(start=self.position(span.start), end=self.position(span.end))

    def offset(self, position: types.Position) -> int:
        """The offset of a position, clamped to the document (a column past a line's end is the
        end of the line, a line past the last one the end of the document)."""
        if position.line < 0:
            return 0
        if position.line >= len(self.starts):
            return len(self.text)
        start, end = self.starts[position.line], self.ends[position.line]
        line = self.text[start:end]
        wanted = max(position.character, 0)
        if self.utf32 or line.isascii():
            return start + min(wanted, len(line))
        used = 0
        for index, char in enumerate(line):
            if used >= wanted:
                return start + index
            used += self.units(char)
        return end

    def line_start(self, line: int) -> int:
        """The offset where a line starts (the end of the document past the last line)."""
        return self.starts[line] if 0 <= line < len(self.starts) else len(self.text)
