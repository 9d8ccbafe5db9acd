"""A real `physc lsp` process and an LSP client talking to it over stdio (pytest-lsp), and the
helpers that drive it: open and edit documents, wait for their diagnostics."""

from __future__ import annotations

import asyncio
import sys

import pytest_lsp
from lsprotocol import types
from pytest_lsp import ClientServerConfig, LanguageClient, client_capabilities

SERVER = [sys.executable, "-m", "physc", "lsp", "--stdio"]  # as VS Code starts it


@pytest_lsp.fixture(config=ClientServerConfig(server_command=SERVER))
async def client(lsp_client: LanguageClient):
    record_publications(lsp_client)
    initialized = await lsp_client.initialize_session(types.InitializeParams(capabilities=client_capabilities("visual-studio-code")))
    lsp_client.capabilities = initialized.capabilities  # what the server said it does
    yield
    await lsp_client.shutdown_session()


def record_publications(client: LanguageClient) -> None:
    """Keep every publishDiagnostics in `client.published` (pytest-lsp keeps only the last list
    per document, without its version)."""
    client.published = []
    features = client.protocol.fm.features
    default = features[types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS]

    def record(params: types.PublishDiagnosticsParams):
        client.published.append(params)
        return default(params)

    features[types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS] = record


TIMEOUT = 60.0


def open_document(client, uri: str, text: str, version: int = 1) -> None:
    client.text_document_did_open(
        types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri=uri, language_id="phys", version=version, text=text))
    )


def replace_all(client, uri: str, text: str, version: int) -> None:
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
            content_changes=[types.TextDocumentContentChangeWholeDocument(text=text)],
        )
    )


def edit(client, uri: str, version: int, start: tuple[int, int], end: tuple[int, int], text: str) -> None:
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
            content_changes=[
                types.TextDocumentContentChangePartial(
                    range=types.Range(start=types.Position(line=start[0], character=start[1]), end=types.Position(line=end[0], character=end[1])),
                    text=text,
                )
            ],
        )
    )


async def diagnostics(client, uri: str, version: int, timeout: float = TIMEOUT) -> list[types.Diagnostic]:
    """The diagnostics published for this version of the document (waiting for them)."""

    async def wait():
        while True:
            for params in reversed(client.published):
                if params.uri == uri and params.version == version:
                    return params.diagnostics
            await asyncio.sleep(0.01)

    return await asyncio.wait_for(wait(), timeout)


def position(line: int, character: int) -> types.Position:
    return types.Position(line=line, character=character)


def document(uri: str) -> types.TextDocumentIdentifier:
    return types.TextDocumentIdentifier(uri=uri)
