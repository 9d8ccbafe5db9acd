"""Offsets in a document ↔ LSP positions.

physc's spans are offsets in code points; an LSP position is a line and a column counted in the
position encoding that client and server agreed on (UTF-16 code units unless the client offers
UTF-8 or UTF-32). Lines end at `\\n` (a `\\r\\n` ending keeps its `\\r` on the line, as physc's
spans do). A position past the end of a line or of the document is clamped, never an error: a
client may ask about a place that an edit has just removed.
"""

from __future__ import annotations

import bisect

from lsprotocol import types

from physc.diagnostics import SourceText, Span

# Code units per encoding; "surrogatepass" because a JSON string may carry a lone surrogate.
_UNITS = {
    types.PositionEncodingKind.Utf8: lambda text: len(text.encode("utf-8", "surrogatepass")),
    types.PositionEncodingKind.Utf16: lambda text: len(text.encode("utf-16-le", "surrogatepass")) // 2,
    types.PositionEncodingKind.Utf32: len,
}


class Positions:
    """Converts between offsets of `source` and positions in `encoding`."""

    def __init__(self, source: SourceText, encoding: str = types.PositionEncodingKind.Utf16):
        self.source = source
        self.units = _UNITS.get(encoding, _UNITS[types.PositionEncodingKind.Utf16])
        self.utf32 = self.units is len

    def position(self, offset: int) -> types.Position:
        starts = self.source.line_starts
        offset = min(max(offset, 0), len(self.source.text))
        line = bisect.bisect_right(starts, offset) - 1
        before = self.source.text[starts[line] : offset]
        column = len(before) if self.utf32 or before.isascii() else self.units(before)
        return types.Position(line=line, character=column)

    def range(self, span: Span) -> types.Range:
        return types.Range(start=self.position(span.start), end=self.position(span.end))

    def offset(self, position: types.Position) -> int:
        """The offset of a position, clamped to the document (a column past a line's end is the
        end of the line, a line past the last one the end of the document)."""
        source = self.source
        if position.line < 0:
            return 0
        if position.line >= source.line_count:
            return len(source.text)
        start, end = source.line_bounds(position.line + 1)
        line = source.text[start:end]
        wanted = max(position.character, 0)
        if self.utf32 or line.isascii():
            return start + min(wanted, len(line))
        used = 0
        for index, char in enumerate(line):
            if used >= wanted:
                return start + index
            used += self.units(char)
        return end
