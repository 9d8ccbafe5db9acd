"""Diagnostics: source spans, messages with stable codes, and their rendering.

Every stage of physc reports problems as `Diagnostic` values; nothing user-facing
is raised as a Python exception. A diagnostic is rendered as in the language
specification (section 6)::

    examples/broken.phys:7:14: error[E0203]: 'roll' expects a rollable object, ...
        7 |         > roll(fBlock, surface, right)
          |                ^^^^^^
      help: declare it as `fBlock: rollableBlock` or use an rBlock

Rendered text is safe to print: characters that a terminal would act on rather than show
(control characters, bidirectional overrides) are shown escaped, `\x1b` or `\u202e`, and a long
source line is shown as a window of at most `MAX_COLUMNS` columns around the caret, cut with `…`.
`to_json` keeps the exact text.
"""

from __future__ import annotations

import bisect
import enum
import re
import unicodedata
from collections.abc import Iterable

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

    def first(self, width: int = 1) -> Span:
        """The first `width` characters of the span (0: the empty span where it starts)."""
        return Span(self.start, min(self.start + width, self.end), self._line_starts)

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
class Edit:
    """Replace the text of `span` with `text` (an empty span inserts)."""

    span: Span
    text: str


@attrs.frozen
class Fix:
    """A change that a diagnostic's help proposes, ready to apply: what editors offer as a quick
    fix. `title` says what it does ("replace 'hti' with 'hit'")."""

    title: str
    edits: tuple[Edit, ...]

    @classmethod
    def replace(cls, span: Span, text: str, title: str | None = None) -> Fix:
        return cls(title or f"replace with '{text}'", (Edit(span, text),))


@attrs.frozen
class Diagnostic:
    code: str
    message: str
    span: Span | None = None
    help: str | None = None
    notes: tuple[Label, ...] = ()
    fixes: tuple[Fix, ...] = ()  # the help's proposals as edits, best first

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

    def line_bounds(self, line: int) -> tuple[int, int]:
        """The offsets where a line starts and ends (its newline excluded)."""
        start = self._line_starts[line - 1]
        end = self._line_starts[line] - 1 if line < len(self._line_starts) else len(self.text)
        return start, end

    def line_text(self, line: int) -> str:
        start, end = self.line_bounds(line)
        return self.text[start:end]

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


# ---- safe text --------------------------------------------------------------------------
# What a terminal acts on instead of showing: C0 and C1 control characters, DEL, the bidirectional
# controls ("Trojan source") and the line and paragraph separators. A tab is kept (it is shown as
# it is in the source line and in the caret line, so the caret stays aligned).
_FORMATTING = "\x7f-\x9f\u061c\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069"
_UNSAFE = re.compile(f"[\x00-\x08\x0a-\x1f{_FORMATTING}]")
_UNSAFE_IN_MESSAGES = re.compile(f"[\x00-\x08\x0b-\x1f{_FORMATTING}]")  # newlines kept
MAX_COLUMNS = 120  # the widest source excerpt shown, `…` marks included
_CONTEXT = 40  # columns shown before the caret when a line is cut
_LONG_WORD = re.compile(r"\S{121,}")


def escaped(char: str) -> str:
    """How an unsafe character is shown: `\x1b`, `\u202e`."""
    code = ord(char)
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def safe(text: str, newlines: bool = False) -> str:
    """`text` with its unsafe characters escaped (`newlines`: keep line breaks), for a terminal."""
    pattern = _UNSAFE_IN_MESSAGES if newlines else _UNSAFE
    return pattern.sub(lambda m: escaped(m.group()), text)


def _message(text: str) -> str:
    """A message or help for the terminal: escaped, and a word of user text longer than a line (a
    100 KB name) cut in its middle."""
    text = _LONG_WORD.sub(lambda m: m.group()[:60] + "…" + m.group()[-59:], text)
    return safe(text, newlines=True)


def _shown(char: str) -> tuple[str, int]:
    """A source character as shown, and the columns it takes."""
    if char == "\t":
        return char, 1
    if _UNSAFE.match(char):
        text = escaped(char)
        return text, len(text)
    if unicodedata.combining(char):
        return char, 0
    return char, 2 if unicodedata.east_asian_width(char) in "WF" else 1


def _plain(text: str) -> bool:
    """Whether every character of `text` takes one column and is shown as it is (tabs aside)."""
    return text.isascii() and not _UNSAFE.search(text)


def _width(text: str) -> int:
    return len(text) if _plain(text) else sum(_shown(c)[1] for c in text)


def _walk(text: str, position: int, limit: int, budget: int, step: int) -> tuple[int, int]:
    """From `position` towards `limit` (step +1 or -1), as far as `budget` columns go; returns the
    position reached and the columns used. At most 4 × budget characters are looked at."""
    reach = min(limit, position + budget) if step > 0 else max(limit, position - budget)
    if _plain(text[min(position, reach) : max(position, reach)]):
        return reach, abs(reach - position)
    used = 0
    looked = 0
    while position != limit and looked < 4 * budget:
        width = _shown(text[position if step > 0 else position - 1])[1]
        if used + width > budget:
            break
        used += width
        position += step
        looked += 1
    return position, used


def _snippet(source: SourceText, span: Span, style, color: bool) -> list[str]:
    """The source line of a span with a caret line under the span, cut to a window around the caret."""
    if span.line > source.line_count:
        return []
    text = source.text
    line_start, line_end = source.line_bounds(span.line)
    if line_end > line_start and text[line_end - 1] == "\r":  # a CRLF line ending
        line_end -= 1
    start = min(max(span.start, line_start), line_end)
    stop = min(span.end, line_end) if span.end_line == span.line else line_end
    stop = max(stop, start)
    low, high = line_start, line_end
    if line_end - line_start > MAX_COLUMNS or _width(text[low:high]) > MAX_COLUMNS:
        budget = MAX_COLUMNS - 2  # room for the two marks
        low, left = _walk(text, start, line_start, _CONTEXT, -1)
        high, right = _walk(text, start, line_end, budget - left, +1)
        if high == line_end:  # room left after the end of the line: show more before the caret
            low, _ = _walk(text, low, line_start, budget - left - right, -1)
    window = text[low:high]
    if _plain(window):
        shown = window
        caret_prefix = re.sub("[^\t]", " ", text[low:start])
        caret_width = min(stop, high) - start
    else:
        shown = "".join(_shown(c)[0] for c in window)
        caret_prefix = "".join("\t" if c == "\t" else " " * _shown(c)[1] for c in text[low:start])
        caret_width = _width(text[start : min(stop, high)])
    before = "…" if low > line_start else ""
    after = "…" if high < line_end else ""
    prefix = (" " if before else "") + caret_prefix
    return [
        f"{span.line:>5} | {before}{shown}{after}",
        f"      | {prefix}{_paint('^' * max(caret_width, 1), style, color)}",
    ]


def render(diagnostic: Diagnostic, source: SourceText | None, path: str, color: bool = False) -> str:
    """Render one diagnostic as text, with source lines when the source is known."""
    severity = diagnostic.severity
    path = safe(path)
    where = f"{path}:{diagnostic.span}" if diagnostic.span else path
    head = _paint(f"{severity.value}[{diagnostic.code}]", severity, color)
    lines = [f"{_paint(where + ':', 'bold', color)} {head}: {_message(diagnostic.message)}"]
    if source is not None and diagnostic.span is not None:
        lines += _snippet(source, diagnostic.span, severity, color)
    for note in diagnostic.notes:
        lines.append(f"  {_paint('note', 'note', color)}: {_message(note.message)} ({path}:{note.span})")
        if source is not None:
            lines += _snippet(source, note.span, "note", color)
    if diagnostic.help:
        lines.append(f"  {_paint('help', 'help', color)}: {_message(diagnostic.help)}")
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
        "fixes": [
            {"title": f.title, "edits": [{"text": e.text, **where(e.span)} for e in f.edits]} for f in diagnostic.fixes
        ],
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
