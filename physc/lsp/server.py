"""`physc lsp`: the language server for `.phys` files (pygls, over stdio).

Diagnostics are `physc check`'s, published after every change: the check runs on a worker thread,
so completion and hover are answered while a long file is being checked, and edits that arrive
during a check are coalesced into one check of the latest version. Diagnostics of a version that
is no longer the latest, or of a document that was closed meanwhile, are never published.
Every feature handler is guarded: an unexpected error in one answers that request with nothing and
is logged, and the server goes on.
"""

from __future__ import annotations

import asyncio
import functools
import logging
import sys
from concurrent.futures import ThreadPoolExecutor
from typing import TYPE_CHECKING

from lsprotocol import types
from pygls.lsp.server import LanguageServer

from physc import __version__
from physc.lsp import completion, context, edits, hover, navigation, semantic
from physc.lsp.documents import Documents, Snapshot

if TYPE_CHECKING:
    from physc.dsl import ast

log = logging.getLogger("physc.lsp")
# How long the checking thread may hold the interpreter before the thread that answers requests
# gets a turn (Python's default is 5 ms): short, so that completion asked during a long check is
# answered in a few turns rather than after many 5 ms slices.
SWITCH_INTERVAL = 0.0005
TRIGGERS = ["(", ",", ":", "=", "|", ">", " "]


class PhyscServer(LanguageServer):
    """The server: pygls plus the open documents, their analyses and the checks under way."""

    def __init__(self):
        super().__init__("physc", __version__, text_document_sync_kind=types.TextDocumentSyncKind.Incremental)
        self.documents = Documents()
        self.checker = ThreadPoolExecutor(max_workers=1, thread_name_prefix="physc-check")
        self.checking: dict[str, asyncio.Future[None]] = {}
        self.stale: set[str] = set()  # changed while being checked

    # ---- checks ------------------------------------------------------------------------------
    def schedule_check(self, uri: str) -> None:
        if uri in self.checking:
            self.stale.add(uri)
            return
        self.checking[uri] = asyncio.ensure_future(self._check(uri))

    async def _check(self, uri: str) -> None:
        loop = asyncio.get_running_loop()
        try:
            while True:
                self.stale.discard(uri)
                document = self.documents.current(uri)
                if document is None:
                    return
                snapshot = await loop.run_in_executor(
                    self.checker, self.documents.snapshot, uri, document.version, document.text
                )
                if uri in self.stale:
                    continue
                if self.documents.latest(uri) is not snapshot:  # closed meanwhile
                    return
                self.text_document_publish_diagnostics(
                    types.PublishDiagnosticsParams(
                        uri=uri, version=snapshot.version, diagnostics=snapshot.lsp_diagnostics()
                    )
                )
                return
        except Exception:  # a bug in physc: keep serving; the log says what happened
            log.exception("checking %s failed", uri)
        finally:
            self.checking.pop(uri, None)

    async def current(self, uri: str) -> Snapshot | None:
        """The analysis of the document as it is now (made on the worker, after the checks
        queued there, unless it was already made)."""
        document = self.documents.current(uri)
        if document is None:
            return None
        latest = self.documents.latest(uri)
        if latest is not None:
            return latest
        loop = asyncio.get_running_loop()
        return await loop.run_in_executor(self.checker, self.documents.snapshot, uri, document.version, document.text)

    async def parsed(self, uri: str) -> tuple[Snapshot, ast.File] | None:
        """`current` and its syntax tree, when the document's text gave one (what navigation reads)."""
        snapshot = await self.current(uri)
        file = None if snapshot is None else snapshot.analysis.file
        return None if snapshot is None or file is None else (snapshot, file)

    def close(self, uri: str) -> None:
        self.documents.close(uri)
        self.stale.discard(uri)
        self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri=uri, diagnostics=[]))

    def snippets(self) -> bool:
        """Whether the client takes completions written as snippets."""
        try:
            document = self.client_capabilities.text_document
        except AttributeError:  # asked before the client said what it can do
            return False
        abilities = document.completion if document is not None else None
        item = abilities.completion_item if abilities is not None else None
        return bool(item is not None and item.snippet_support)


def guarded(handler):
    """A feature handler that answers None, and logs, instead of failing on a bug."""

    @functools.wraps(handler)
    async def run(ls, params):
        try:
            return await handler(ls, params)
        except Exception:
            log.exception("%s failed", handler.__name__)
            return None

    return run


def build() -> PhyscServer:
    """The server with its features: the documents' life, then help while editing, then navigation."""
    server = PhyscServer()
    _follow_documents(server)
    _help_editing(server)
    _navigate(server)
    return server


def _follow_documents(server: PhyscServer) -> None:
    """The features that keep the server's copy of each document as the editor has it, and check it."""

    @server.feature(types.INITIALIZE)
    def initialize(ls: PhyscServer, params: types.InitializeParams) -> None:
        ls.documents.encoding = ls.workspace.position_encoding or types.PositionEncodingKind.Utf16

    @server.feature(types.TEXT_DOCUMENT_DID_OPEN)
    def did_open(ls: PhyscServer, params: types.DidOpenTextDocumentParams) -> None:
        item = params.text_document
        ls.documents.open(item.uri, item.version, item.text)
        ls.schedule_check(item.uri)

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: PhyscServer, params: types.DidChangeTextDocumentParams) -> None:
        uri = params.text_document.uri
        ls.documents.change(uri, params.text_document.version, params.content_changes)
        ls.schedule_check(uri)

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: PhyscServer, params: types.DidCloseTextDocumentParams) -> None:
        ls.close(params.text_document.uri)


def _help_editing(server: PhyscServer) -> None:
    """The features that help while typing: completion, hover, formatting and quick fixes."""

    @server.feature(types.TEXT_DOCUMENT_COMPLETION, types.CompletionOptions(trigger_characters=TRIGGERS))
    @guarded
    async def complete(ls: PhyscServer, params: types.CompletionParams):
        place = _place(ls, params.text_document.uri, params.position)
        return (
            None
            if place is None
            else types.CompletionList(is_incomplete=False, items=completion.complete(place, ls.snippets()))
        )

    @server.feature(types.TEXT_DOCUMENT_HOVER)
    @guarded
    async def on_hover(ls: PhyscServer, params: types.HoverParams):
        opened = ls.documents.opened(params.text_document.uri)
        if opened is None:
            return None
        document, positions = opened
        text, offset = document.text, positions.offset(params.position)
        inside = offset < len(text) and (text[offset].isalnum() or text[offset] == "_")
        place = context.locate(text, offset + 1 if inside else offset)
        # The diagnostics of the current text when its check is done; a hover does not wait for one.
        snapshot = ls.documents.latest(params.text_document.uri)
        found = hover.hover_text(place, snapshot.diagnostics_at(offset, offset) if snapshot else [])
        if found is None:
            return None
        word = place.word
        where = types.Range(start=positions.position(word.start), end=positions.position(word.end)) if word else None
        return types.Hover(contents=types.MarkupContent(kind=types.MarkupKind.Markdown, value=found), range=where)

    @server.feature(types.TEXT_DOCUMENT_FORMATTING)
    @guarded
    async def formatting(ls: PhyscServer, params: types.DocumentFormattingParams):
        snapshot = await ls.current(params.text_document.uri)
        if snapshot is None:
            return None
        analysis = snapshot.analysis
        if analysis.file is None or analysis.source is None or any(d.is_error for d in analysis.syntax):
            return None  # physc fmt formats only what parses
        return edits.formatting(analysis.file, analysis.source, snapshot.text)

    @server.feature(
        types.TEXT_DOCUMENT_CODE_ACTION, types.CodeActionOptions(code_action_kinds=[types.CodeActionKind.QuickFix])
    )
    @guarded
    async def code_actions(ls: PhyscServer, params: types.CodeActionParams):
        snapshot = await ls.current(params.text_document.uri)
        if snapshot is None:
            return None
        positions = snapshot.positions
        start, end = (positions.offset(p) for p in (params.range.start, params.range.end))
        found = [(d, snapshot.lsp_diagnostic(d)) for d in snapshot.diagnostics_at(start, end) if d.fixes]
        return edits.quick_fixes(params.text_document.uri, found, snapshot.range)


def _navigate(server: PhyscServer) -> None:
    """The features that read the syntax tree: definition, references, symbols, semantic tokens."""

    @server.feature(types.TEXT_DOCUMENT_DEFINITION)
    @guarded
    async def definition(ls: PhyscServer, params: types.DefinitionParams):
        parsed = await ls.parsed(params.text_document.uri)
        if parsed is None:
            return None
        snapshot, file = parsed
        span = navigation.definition(file, snapshot.positions.offset(params.position))
        return None if span is None else types.Location(uri=params.text_document.uri, range=snapshot.range(span))

    @server.feature(types.TEXT_DOCUMENT_REFERENCES)
    @guarded
    async def references(ls: PhyscServer, params: types.ReferenceParams):
        parsed = await ls.parsed(params.text_document.uri)
        if parsed is None:
            return None
        snapshot, file = parsed
        offset = snapshot.positions.offset(params.position)
        spans = navigation.references(file, offset, params.context.include_declaration)
        return [types.Location(uri=params.text_document.uri, range=snapshot.range(s)) for s in spans]

    @server.feature(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL)
    @guarded
    async def document_symbols(ls: PhyscServer, params: types.DocumentSymbolParams):
        parsed = await ls.parsed(params.text_document.uri)
        if parsed is None:
            return None
        snapshot, file = parsed
        return navigation.symbols(file, snapshot.range)

    @server.feature(types.TEXT_DOCUMENT_SEMANTIC_TOKENS_FULL, semantic.LEGEND)
    @guarded
    async def semantic_tokens(ls: PhyscServer, params: types.SemanticTokensParams):
        parsed = await ls.parsed(params.text_document.uri)
        if parsed is None:
            return None
        snapshot, file = parsed
        return semantic.tokens(file, snapshot.positions)


def _place(ls: PhyscServer, uri: str, position: types.Position) -> context.Place | None:
    """The place of a position in the document as it is now (read from its text: no analysis)."""
    opened = ls.documents.opened(uri)
    if opened is None:
        return None
    document, positions = opened
    return context.locate(document.text, positions.offset(position))


class _OneLine(logging.Formatter):
    """Log lines for the editor's output panel: an error's type and message, not its traceback
    (`physc lsp --log-file` keeps the tracebacks)."""

    def format(self, record: logging.LogRecord) -> str:
        text = f"physc lsp: {record.levelname.lower()}: {record.getMessage()}"
        if record.exc_info and record.exc_info[1] is not None:
            error = record.exc_info[1]
            text += f": {type(error).__name__}: {error}"
        return text


def serve(log_file: str | None = None) -> None:
    """Serve over stdin and stdout until the client exits. Warnings and errors go to stderr as one
    line each; with `log_file`, everything down to info, with tracebacks, goes there too."""
    stderr = logging.StreamHandler()
    stderr.setLevel(logging.WARNING)
    stderr.setFormatter(_OneLine())
    handlers: list[logging.Handler] = [stderr]
    if log_file:
        to_file = logging.FileHandler(log_file, encoding="utf-8")
        to_file.setFormatter(logging.Formatter("%(asctime)s %(name)s %(levelname)s %(message)s"))
        handlers.append(to_file)
    logging.basicConfig(level=logging.INFO if log_file else logging.WARNING, handlers=handlers, force=True)
    sys.setswitchinterval(SWITCH_INTERVAL)
    build().start_io()
