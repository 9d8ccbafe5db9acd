"""A `.phys` file cut into chunks at every `scenario` keyword (outside strings and comments), each
parsed on its own: a syntax error costs one scenario, not the rest of the file. The comments are
collected on the way, for the formatter.
"""

from __future__ import annotations

import re

from physc.diagnostics import SourceText, Span
from physc.dsl import ast

# Finds the `scenario` keywords that start chunks, skipping strings and comments.
_CHUNK_SCAN = re.compile(r'"(?:[^"\\\n]|\\.)*"?|#[^\n]*|//[^\n]*|\bscenario\b')


class Chunk:
    """The text of one scenario (or of what precedes the first), at its offset in the file."""

    def __init__(self, source: SourceText, start: int, end: int):
        self.source = source
        self.start = start
        self.end = end
        self.text = source.text[start:end]

    def span(self, start: int, end: int) -> Span:
        return self.source.span(start + self.start, end + self.start)


def cut_chunks(source: SourceText) -> tuple[list[Chunk], list[ast.Comment], bool]:
    """Cut the text at `scenario` keywords; also collect comments. Returns
    (chunks, comments, whether text other than comments precedes the first keyword)."""
    starts = []
    comments = []
    for match in _CHUNK_SCAN.finditer(source.text):
        text = match.group()
        if text == "scenario":
            starts.append(match.start())
        elif text[0] in "#/":
            comments.append(ast.Comment(text.rstrip("\r"), source.span(match.start(), match.end())))
    bounds = starts + [len(source.text)]
    chunks = [Chunk(source, bounds[i], bounds[i + 1]) for i in range(len(starts))]
    head_end = starts[0] if starts else len(source.text)
    head = _CHUNK_SCAN.sub(lambda m: "" if m.group()[0] in "#/" else m.group(), source.text[:head_end])
    if head.strip():
        chunks.insert(0, Chunk(source, 0, head_end))
    return chunks, comments, bool(starts)
