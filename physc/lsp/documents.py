"""The analyses of open documents, one per document version.

An analysis is `physc check`'s: `physc.dsl.frontend.analyze_text`, the same parse and the same
checks, so the editor shows exactly the diagnostics that `physc check` prints. The front end keeps
state while it parses, so analyses run one at a time (a lock); each document keeps only the
analysis of its latest version, so memory does not grow with the number of edits.
"""

from __future__ import annotations

import threading

import attrs
from lsprotocol import types

from physc.diagnostics import Diagnostic, Severity, SourceText, Span
from physc.dsl.frontend import Analysis, analyze_text
from physc.lsp.positions import Positions

_SEVERITY = {Severity.ERROR: types.DiagnosticSeverity.Error, Severity.WARNING: types.DiagnosticSeverity.Warning}


@attrs.frozen
class Snapshot:
    """A document version, its analysis, and the positions of its text."""

    uri: str
    version: int | None
    text: str
    analysis: Analysis
    positions: Positions

    def range(self, span: Span | None) -> types.Range:
        if span is None:
            return types.Range(start=types.Position(line=0, character=0), end=types.Position(line=0, character=0))
        return self.positions.range(span)

    def lsp_diagnostic(self, diagnostic: Diagnostic) -> types.Diagnostic:
        message = diagnostic.message + (f"\nhelp: {diagnostic.help}" if diagnostic.help else "")
        related = [
            types.DiagnosticRelatedInformation(location=types.Location(uri=self.uri, range=self.range(n.span)), message=n.message)
            for n in diagnostic.notes
        ]
        return types.Diagnostic(
            range=self.range(diagnostic.span),
            message=message,
            severity=_SEVERITY[diagnostic.severity],
            code=diagnostic.code,
            source="physc",
            related_information=related or None,
        )

    def lsp_diagnostics(self) -> list[types.Diagnostic]:
        return [self.lsp_diagnostic(d) for d in self.analysis.diagnostics]

    def diagnostics_at(self, start: int, end: int) -> list[Diagnostic]:
        """The diagnostics whose span meets the offsets [start, end]."""
        return [d for d in self.analysis.diagnostics if d.span is not None and d.span.start <= end and start <= d.span.end]


class Documents:
    """The latest analysed version of each open document."""

    def __init__(self, encoding: str = types.PositionEncodingKind.Utf16):
        self.encoding = encoding
        self._latest: dict[str, Snapshot] = {}
        self._lock = threading.Lock()
        self._positions: dict[str, Positions] = {}  # of the text last asked about, by document

    def snapshot(self, uri: str, version: int | None, text: str) -> Snapshot:
        """The analysis of this version of the document (made now, unless it was already)."""
        with self._lock:
            known = self._latest.get(uri)
            if known is not None and known.version == version and known.text == text:
                return known
            analysis = analyze_text(uri, text)
            snapshot = Snapshot(uri, version, text, analysis, Positions(analysis.source, self.encoding))
            self._latest[uri] = snapshot
            return snapshot

    def latest(self, uri: str) -> Snapshot | None:
        """The latest analysis made of the document, whatever its version."""
        return self._latest.get(uri)

    def positions(self, uri: str, text: str) -> Positions:
        """The positions of a text of the document, without analysing it (for completion)."""
        for known in (self._latest.get(uri), self._positions.get(uri)):
            found = known.positions if isinstance(known, Snapshot) else known
            if found is not None and found.source.text is text:
                return found
        made = Positions(SourceText(uri, text), self.encoding)
        self._positions[uri] = made
        return made

    def forget(self, uri: str) -> None:
        with self._lock:
            self._latest.pop(uri, None)
            self._positions.pop(uri, None)
