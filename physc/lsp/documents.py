"""The open documents: their text as the editor has it, and the analysis of their latest version.

The server keeps the text itself, applying the editor's changes with its own positions, so that
the text it checks and the positions it reports agree on what a line is. An analysis is `physc
check`'s: `physc.dsl.frontend.analyze_text`, the same parse and the same checks, so the editor
shows exactly the diagnostics that `physc check` prints (a leading byte-order mark, which `physc
check` drops, is read as a blank, so that offsets stay those of the editor's text). The front end
keeps state while it parses, so analyses run one at a time (a lock). Each document keeps only the
analysis of its latest version, so memory does not grow with the number of edits.
"""

from __future__ import annotations

import threading
from collections.abc import Iterable

import attrs
from lsprotocol import types

from physc.diagnostics import Diagnostic, Severity, SourceText, Span
from physc.domains.words import INSTALLED
from physc.dsl.frontend import Analysis, analyze_text
from physc.dsl.parser import MAX_SOURCE_BYTES
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
            types.DiagnosticRelatedInformation(
                location=types.Location(uri=self.uri, range=self.range(n.span)), message=n.message
            )
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
        return [
            d for d in self.analysis.diagnostics if d.span is not None and d.span.start <= end and start <= d.span.end
        ]


@attrs.define
class Document:
    """An open document as the editor has it."""

    version: int | None
    text: str
    positions: Positions | None = None  # of `text`, made when first asked for


def analyze_document(uri: str, text: str) -> Analysis:
    """`physc check`'s analysis of an editor's text."""
    if len(text) > MAX_SOURCE_BYTES or len(text.encode("utf-8", "surrogatepass")) > MAX_SOURCE_BYTES:
        too_big = Diagnostic(
            "E0001", f"cannot read the input: it is larger than {MAX_SOURCE_BYTES // 2**20} MiB, the most physc reads"
        )
        return Analysis(uri, SourceText(uri, ""), None, (), (too_big,), ())
    if text.startswith("\ufeff"):
        text = " " + text[1:]
    return analyze_text(uri, text, INSTALLED)


class Documents:
    """The open documents, and the latest analysed version of each."""

    def __init__(self, encoding: str = types.PositionEncodingKind.Utf16):
        self.encoding = encoding
        self._open: dict[str, Document] = {}
        self._latest: dict[str, Snapshot] = {}
        self._analysing = threading.Lock()

    # ---- the editor's text -------------------------------------------------------------------
    def open(self, uri: str, version: int | None, text: str) -> None:
        self._open[uri] = Document(version, text)

    def change(self, uri: str, version: int | None, changes: Iterable[types.TextDocumentContentChangeEvent]) -> None:
        """Apply the editor's changes (whole texts, or ranges and their new text), in order."""
        document = self._open.get(uri)
        if document is None:
            return
        text = document.text
        for change in changes:
            if isinstance(change, types.TextDocumentContentChangePartial):
                positions = Positions(text, self.encoding)
                start, end = positions.offset(change.range.start), positions.offset(change.range.end)
                text = text[:start] + change.text + text[max(start, end) :]
            else:
                text = change.text
        self._open[uri] = Document(version, text)

    def close(self, uri: str) -> None:
        """Forget a document (a check under way finishes, but its result is not kept)."""
        self._open.pop(uri, None)
        self._latest.pop(uri, None)

    def current(self, uri: str) -> Document | None:
        return self._open.get(uri)

    def positions(self, uri: str) -> Positions | None:
        """The positions of the document's current text."""
        document = self._open.get(uri)
        if document is None:
            return None
        if document.positions is None:
            document.positions = Positions(document.text, self.encoding)
        return document.positions

    def opened(self, uri: str) -> tuple[Document, Positions] | None:
        """The open document and the positions of its current text; None if it is not open."""
        document, positions = self.current(uri), self.positions(uri)
        return None if document is None or positions is None else (document, positions)

    # ---- analyses ----------------------------------------------------------------------------
    def snapshot(self, uri: str, version: int | None, text: str) -> Snapshot:
        """The analysis of this version of the document (made now, unless it was already)."""
        with self._analysing:
            known = self._latest.get(uri)
            if known is not None and known.version == version and known.text == text:
                return known
            analysis = analyze_document(uri, text)
            document = self._open.get(uri)
            made = (
                document.positions if document is not None and document.text is text else None
            )  # completion's, if any
            snapshot = Snapshot(uri, version, text, analysis, made or Positions(text, self.encoding))
            if document is not None and document.version == version:  # still open, still this version
                self._latest[uri] = snapshot
            return snapshot

    def latest(self, uri: str) -> Snapshot | None:
        """The analysis of the document's current text, if it was made; else None."""
        snapshot, document = self._latest.get(uri), self._open.get(uri)
        if (
            snapshot is None
            or document is None
            or (snapshot.version, snapshot.text) != (document.version, document.text)
        ):
            return None
        return snapshot
