"""Diagnostics: source spans, messages with stable codes, and their rendering.

Every stage of physc reports problems as `Diagnostic` values; nothing user-facing
is raised as a Python exception. A diagnostic is rendered as in the language
specification (section 6)::

    examples/broken.phys:7:14: error[E0203]: 'roll' expects a rollable object, ...
        7 |         > roll(fBlock, surface, right)
          |                ^^^^^^
      help: declare it as `fBlock: rollableBlock` or use an rBlock
"""

from __future__ import annotations

import bisect
import enum
import re
from typing import Iterable

import attrs

from physc import error_codes


class Span:
    """A region of source text: 0-based offsets [start, end).

    Lines and columns (1-based; `end_column` is the column just after the
    span) are looked up in the source's line index when asked for, so making
    a span costs almost nothing. Spans compare by their offsets.
    """

    __slots__ = ("start", "end", "_line_starts")

    def __init__(self, start: int, end: int, line_starts: list[int]):
        self.start = start
        self.end = end
        self._line_starts = line_starts

    def _position(self, offset: int) -> tuple[int, int]:
        index = bisect.bisect_right(self._line_starts, offset) - 1
        return index + 1, offset - self._line_starts[index] + 1

    @property
    def line(self) -> int:
        return self._position(self.start)[0]

    @property
    def column(self) -> int:
        return self._position(self.start)[1]

    @property
    def end_line(self) -> int:
        return self._position(self.end)[0]

    @property
    def end_column(self) -> int:
        return self._position(self.end)[1]

    def join(self, other: Span) -> Span:
        """The smallest span covering both."""
        return Span(min(self.start, other.start), max(self.end, other.end), self._line_starts)

    def last(self, width: int = 1) -> Span:
        """The last `width` characters of the span."""
        return Span(max(self.end - width, self.start), self.end, self._line_starts)

    def __eq__(self, other) -> bool:
        return isinstance(other, Span) and (self.start, self.end) == (other.start, other.end)

    def __hash__(self) -> int:
        return hash((self.start, self.end))

    def __repr__(self) -> str:
        return f"Span({self.start}, {self.end}, {self.line}:{self.column})"

    def __str__(self) -> str:
        return f"{self.line}:{self.column}"


class Severity(enum.Enum):
    ERROR = "error"
    WARNING = "warning"


@attrs.frozen
class Label:
    """A secondary location that explains a diagnostic ("declared here")."""

    span: Span
    message: str


@attrs.frozen
class Diagnostic:
    code: str
    message: str
    span: Span | None = None
    help: str | None = None
    notes: tuple[Label, ...] = ()

    @property
    def severity(self) -> Severity:
        return Severity(error_codes.lookup(self.code).severity)

    @property
    def is_error(self) -> bool:
        return self.severity is Severity.ERROR


class SourceText:
    """The text of one input, with its line index."""

    def __init__(self, path: str, text: str):
        self.path = path
        self.text = text
        self._line_starts = [0] + [m.end() for m in re.finditer("\n", text)]

    @property
    def line_count(self) -> int:
        return len(self._line_starts)

    @property
    def line_starts(self) -> list[int]:
        """The offset at which each line starts (shared with the spans made from it)."""
        return self._line_starts

    def offset(self, line: int, column: int) -> int:
        """The 0-based offset of a 1-based line and column."""
        return self._line_starts[line - 1] + max(column - 1, 0)

    def line_text(self, line: int) -> str:
        start = self._line_starts[line - 1]
        end = self.text.find("\n", start)
        return self.text[start:] if end < 0 else self.text[start:end]

    def span(self, start: int, end: int) -> Span:
        return Span(start, end, self._line_starts)


_ANSI = {
    Severity.ERROR: "\033[1;31m",
    Severity.WARNING: "\033[1;33m",
    "bold": "\033[1m",
    "help": "\033[1;36m",
    "note": "\033[1;34m",
    "reset": "\033[0m",
}


def _paint(text: str, style, color: bool) -> str:
    return f"{_ANSI[style]}{text}{_ANSI['reset']}" if color else text


def _snippet(source: SourceText, span: Span, style, color: bool) -> list[str]:
    """The source line of a span with a caret line under the span."""
    if span.line > source.line_count:
        return []
    text = source.line_text(span.line)
    start = max(span.column - 1, 0)
    stop = span.end_column - 1 if span.end_line == span.line else len(text)
    width = max(stop - start, 1)
    # Keep tabs so the caret lines up with the displayed source.
    prefix = "".join("\t" if ch == "\t" else " " for ch in text[:start])
    return [
        f"{span.line:>5} | {text}",
        f"      | {prefix}{_paint('^' * width, style, color)}",
    ]


def render(diagnostic: Diagnostic, source: SourceText | None, path: str, color: bool = False) -> str:
    """Render one diagnostic as text, with source lines when the source is known."""
    severity = diagnostic.severity
    where = f"{path}:{diagnostic.span}" if diagnostic.span else path
    head = _paint(f"{severity.value}[{diagnostic.code}]", severity, color)
    lines = [f"{_paint(where + ':', 'bold', color)} {head}: {diagnostic.message}"]
    if source is not None and diagnostic.span is not None:
        lines += _snippet(source, diagnostic.span, severity, color)
    for note in diagnostic.notes:
        lines.append(f"  {_paint('note', 'note', color)}: {note.message} ({path}:{note.span})")
        if source is not None:
            lines += _snippet(source, note.span, "note", color)
    if diagnostic.help:
        lines.append(f"  {_paint('help', 'help', color)}: {diagnostic.help}")
    return "\n".join(lines)


def to_json(diagnostic: Diagnostic, path: str) -> dict:
    """The machine-readable form (`--format json`), stable across versions."""

    def where(span: Span | None) -> dict:
        if span is None:
            return {"line": None, "column": None, "end_line": None, "end_column": None}
        return {
            "line": span.line,
            "column": span.column,
            "end_line": span.end_line,
            "end_column": span.end_column,
        }

    return {
        "file": path,
        **where(diagnostic.span),
        "severity": diagnostic.severity.value,
        "code": diagnostic.code,
        "message": diagnostic.message,
        "help": diagnostic.help,
        "notes": [{"message": n.message, **where(n.span)} for n in diagnostic.notes],
    }


def sort_key(diagnostic: Diagnostic) -> tuple:
    span = diagnostic.span
    return (span.start if span else -1, diagnostic.code)


def exit_status(diagnostics: Iterable[Diagnostic]) -> int:
    """The process exit status that a set of diagnostics calls for (spec section 7)."""
    status = 0
    for diagnostic in diagnostics:
        if diagnostic.is_error:
            status = max(status, error_codes.lookup(diagnostic.code).exit_status)
    return status
