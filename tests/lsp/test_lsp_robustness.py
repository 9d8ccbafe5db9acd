"""Bad input never takes the language server down: garbage on the wire, random documents, a 5 MB
document, an unknown domain, a document closed while it is being checked, positions past the end."""

from __future__ import annotations

import asyncio
import json
import os
import random
import subprocess

from conftest import EXAMPLES
from lsp_client import SERVER, client, diagnostics, document, open_document, position  # noqa: F401 (client: a fixture)
from lsprotocol import types

SCENARIO = (EXAMPLES / "objects.phys").read_text()
FAR = position(10**6, 10**6)


async def ask_everything(client, uri: str, at: types.Position) -> None:
    """Every request the server answers, at one position: each must be answered (maybe with nothing)."""
    text = document(uri)
    await client.text_document_completion_async(types.CompletionParams(text_document=text, position=at))
    await client.text_document_hover_async(types.HoverParams(text_document=text, position=at))
    await client.text_document_definition_async(types.DefinitionParams(text_document=text, position=at))
    await client.text_document_references_async(
        types.ReferenceParams(text_document=text, position=at, context=types.ReferenceContext(include_declaration=True))
    )
    await client.text_document_code_action_async(
        types.CodeActionParams(text_document=text, range=types.Range(start=at, end=at), context=types.CodeActionContext(diagnostics=[]))
    )
    await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=text))
    await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=text, options=types.FormattingOptions(tab_size=4, insert_spaces=True))
    )


async def test_positions_past_the_end_are_answered(client):
    uri = "file:///work/far.phys"
    open_document(client, uri, SCENARIO)
    await diagnostics(client, uri, 1)
    for at in (FAR, position(3, 10**6), position(0, 10**6), position(10**6, 0)):
        await ask_everything(client, uri, at)
    await ask_everything(client, "file:///work/never-opened.phys", position(0, 0))


async def test_random_documents(client):
    """Random text (control characters, astral and lone surrogate code points, scenario fragments)."""
    chosen = random.Random(7)
    alphabet = "scenario{}()[],:=|>&# \n\t\"\\ab_01\x00\x1b\u202e\u00e9\U0001f600\ud800→∧∨"
    pieces = ["scenario ", "hit(", "bird", ", ", "pig", ")", " > ", "{", "}", "objects {", "r: ", "domain ", "\n"]
    for number in range(12):
        parts = [chosen.choice(pieces) if chosen.random() < 0.5 else chosen.choice(alphabet) for _ in range(chosen.randint(0, 400))]
        text = "".join(parts)
        uri = f"file:///work/random{number}.phys"
        open_document(client, uri, text)
        await diagnostics(client, uri, 1)
        lines = text.split("\n")
        line = chosen.randrange(len(lines))
        await ask_everything(client, uri, position(line, chosen.randint(0, len(lines[line]) + 2)))


async def test_a_5_mb_document(client):
    """Checked on the worker: completion and hover are answered meanwhile, then its diagnostics come."""
    block = SCENARIO.replace("scenario RF", "scenario RF{n}")
    copies = 5 * 2**20 // len(block) + 1
    text = "".join(block.replace("{n}", str(n)) for n in range(copies))
    assert len(text) >= 5 * 2**20
    uri = "file:///work/big.phys"
    open_document(client, uri, text)
    small = "file:///work/small.phys"
    open_document(client, small, SCENARIO)
    at = position(text.count("\n") - 5, 12)
    started = asyncio.get_running_loop().time()
    result = await asyncio.wait_for(client.text_document_completion_async(types.CompletionParams(text_document=document(uri), position=at)), 30)
    assert result is not None
    hovered = await client.text_document_hover_async(types.HoverParams(text_document=document(uri), position=position(3, 12)))  # `angrybirds`
    assert hovered is not None
    assert asyncio.get_running_loop().time() - started < 5  # neither waited for the check
    found = await diagnostics(client, uri, 1, timeout=300)
    assert list(found) == []


async def test_an_unknown_domain(client):
    uri = "file:///work/domain.phys"
    text = SCENARIO.replace("domain angrybirds", "domain angrybird")
    open_document(client, uri, text)
    found = await diagnostics(client, uri, 1)
    assert [d.code for d in found] == ["E0701"]
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(text_document=document(uri), range=found[0].range, context=types.CodeActionContext(diagnostics=found))
    )
    assert [a.title for a in actions] == ["change 'angrybird' to 'angrybirds'"]
    inside = text.index("hit(bird, ") + len("hit(bird, ")
    line = text.count("\n", 0, inside)
    result = await client.text_document_completion_async(
        types.CompletionParams(text_document=document(uri), position=position(line, inside - text.rfind("\n", 0, inside) - 1))
    )
    assert list(result.items) == []
    await ask_everything(client, uri, position(line, 12))


async def test_a_document_closed_while_being_checked(client):
    uri = "file:///work/closing.phys"
    text = SCENARIO * 3000  # about a second of checking
    open_document(client, uri, text)
    client.text_document_did_close(types.DidCloseTextDocumentParams(text_document=document(uri)))
    await ask_everything(client, "file:///work/other.phys", position(0, 0))
    open_document(client, "file:///work/after.phys", SCENARIO)
    await diagnostics(client, "file:///work/after.phys", 1, timeout=120)  # the worker is past the closed one
    ours = [p for p in client.published if p.uri == uri]
    assert ours and list(ours[-1].diagnostics) == []  # cleared on close, nothing published after


def test_garbage_on_the_wire():
    """Bytes that are no LSP message, a body that is no JSON, then a real request: it is answered,
    and stderr shows no traceback."""

    def frame(message: dict) -> bytes:
        body = json.dumps(message).encode()
        return b"Content-Length: %d\r\n\r\n" % len(body) + body

    garbage = random.Random(3).randbytes(4096)
    request = frame({"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}})
    stop = frame({"jsonrpc": "2.0", "id": 2, "method": "shutdown"}) + frame({"jsonrpc": "2.0", "method": "exit"})
    run = subprocess.run(
        SERVER, input=garbage + b"\r\n\r\n" + b"Content-Length: 10\r\n\r\n{not json}" + request + stop, capture_output=True, timeout=60,
        env={**os.environ, "PYTHONUNBUFFERED": "1"},
    )
    assert b'"id": 1' in run.stdout and b'"capabilities"' in run.stdout
    assert b"Traceback" not in run.stderr
    assert run.returncode == 0, run.stderr[-2000:]
