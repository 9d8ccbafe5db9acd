"""The language server's latency and memory, measured as an editor sees them (docs/performance.md).

    python benchmarks/lsp.py [--edits 200] [--big-edits 40] [--completions 200] [--memory-edits 1000]

Starts `physc lsp` as a subprocess and drives it over stdio with pygls's client:
- diagnostics after an edit: the time from sending a didChange (an incremental edit of one line,
  alternately making and mending an error) to receiving the publishDiagnostics of that version,
  for a 200-line and a 5,000-line file, one edit at a time;
- completion: the round trip of a completion request inside `hit(`, in the 200-line file and the
  5,000-line file;
- memory: the server's resident set size after the first edit and after `--memory-edits` edits.
Prints p50, p95 and max in milliseconds, and the memory in MiB. The targets (issue 34): diagnostics
p95 <= 50 ms (200 lines) and <= 500 ms (5,000 lines), completion p95 <= 30 ms, memory within 20 %.
"""

from __future__ import annotations

import argparse
import asyncio
import platform
import statistics
import sys
import time
from pathlib import Path

from lsprotocol import types
from pygls.lsp.client import LanguageClient

SCENARIO = (Path(__file__).resolve().parents[1] / "examples" / "beyond" / "01_RRRR.phys").read_text()
BODY = "\n".join(line for line in SCENARIO.splitlines() if not line.startswith("#")) + "\n"


def document(lines: int) -> str:
    """A file of about `lines` lines: the RRRR scenario (10 interactions) under distinct names."""
    parts, count = [], 0
    while count < lines:
        part = BODY.replace("scenario RRRR", f"scenario RRRR{len(parts)}")
        parts.append(part)
        count += part.count("\n")
    return "".join(parts)


class Client(LanguageClient):
    def __init__(self):
        super().__init__("physc-benchmark", "1")
        self.published: dict[tuple[str, int | None], asyncio.Future] = {}

        @self.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def published(params: types.PublishDiagnosticsParams):
            future = self.published.get((params.uri, params.version))
            if future is not None and not future.done():
                future.set_result(params.diagnostics)

    def expect(self, uri: str, version: int) -> asyncio.Future:
        future = asyncio.get_running_loop().create_future()
        self.published[(uri, version)] = future
        return future


def rss_mib(pid: int) -> float:
    for line in Path(f"/proc/{pid}/status").read_text().splitlines():
        if line.startswith("VmRSS:"):
            return int(line.split()[1]) / 1024
    return float("nan")


def summary(name: str, seconds: list[float]) -> str:
    ms = sorted(s * 1000 for s in seconds)
    p95 = ms[min(len(ms) - 1, round(0.95 * (len(ms) - 1)))]
    return f"{name:<42} n={len(ms):<5} p50 {statistics.median(ms):7.1f} ms   p95 {p95:7.1f} ms   max {ms[-1]:7.1f} ms"


async def edits(client: Client, uri: str, text: str, count: int, version: int, first: int = 0) -> tuple[list[float], int]:
    """`count` edits of the line `> hit(rBlock1, rBlock2, left)` near the middle of the text: the
    term becomes `hitt` (an unknown term, E0201) and back, each timed to its diagnostics."""
    line = text.count("\n", 0, text.index("> hit(rBlock1", len(text) // 2))
    column = text.splitlines()[line].index("hit") + 3
    times = []
    for number in range(first, first + count):
        version += 1
        broken = number % 2 == 0
        end = column if broken else column + 1
        change = types.TextDocumentContentChangePartial(
            range=types.Range(start=types.Position(line=line, character=column), end=types.Position(line=line, character=end)),
            text="t" if broken else "",
        )
        waiting = client.expect(uri, version)
        started = time.perf_counter()
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version), content_changes=[change])
        )
        found = await asyncio.wait_for(waiting, 60)
        times.append(time.perf_counter() - started)
        assert bool(found) == broken, (number, found)
    return times, version


async def completions(client: Client, uri: str, text: str, count: int) -> list[float]:
    offset = text.index("> hit(rBlock2", len(text) // 2) + len("> hit(")
    line = text.count("\n", 0, offset)
    at = types.Position(line=line, character=offset - text.rfind("\n", 0, offset) - 1)
    times = []
    for _ in range(count):
        started = time.perf_counter()
        result = await client.text_document_completion_async(types.CompletionParams(text_document=types.TextDocumentIdentifier(uri=uri), position=at))
        times.append(time.perf_counter() - started)
        assert result.items
    return times


async def completions_while_checking(client: Client, uri: str, text: str, count: int, version: int) -> list[float]:
    """Completion asked right after an edit, while the server checks the edited text."""
    offset = text.index("> hit(rBlock2", len(text) // 2) + len("> hit(")
    line = text.count("\n", 0, offset)
    at = types.Position(line=line, character=offset - text.rfind("\n", 0, offset) - 1)
    edited = text.count("\n", 0, text.index("> hit(rBlock1", len(text) // 2))
    times = []
    for number in range(count):
        version += 1
        inserting = number % 2 == 0  # a space before the line's indentation, then taken away again
        end = types.Position(line=edited, character=0 if inserting else 1)
        change = types.TextDocumentContentChangePartial(
            range=types.Range(start=types.Position(line=edited, character=0), end=end), text=" " if inserting else ""
        )
        waiting = client.expect(uri, version)
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version), content_changes=[change])
        )
        started = time.perf_counter()
        result = await client.text_document_completion_async(types.CompletionParams(text_document=types.TextDocumentIdentifier(uri=uri), position=at))
        times.append(time.perf_counter() - started)
        assert result.items
        await asyncio.wait_for(waiting, 60)
    return times


async def run(args) -> None:
    client = Client()
    await client.start_io(sys.executable, "-m", "physc", "lsp")
    pid = client._server.pid
    await client.initialize_async(types.InitializeParams(capabilities=types.ClientCapabilities()))
    client.initialized(types.InitializedParams())
    print(f"python {platform.python_version()}, {platform.machine()}")
    for lines, count in ((200, args.edits), (5000, args.big_edits)):
        text = document(lines)
        uri = f"file:///bench/{lines}.phys"
        waiting = client.expect(uri, 1)
        client.text_document_did_open(types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri=uri, language_id="phys", version=1, text=text)))
        await asyncio.wait_for(waiting, 60)
        times, _ = await edits(client, uri, text, count, 1)
        print(summary(f"diagnostics after an edit, {text.count(chr(10))} lines", times))
        print(summary(f"completion in hit(, {text.count(chr(10))} lines", await completions(client, uri, text, args.completions)))
        during = await completions_while_checking(client, uri, text, args.big_edits, 1 + count)
        print(summary(f"completion during a check, {text.count(chr(10))} lines", during))
        client.text_document_did_close(types.DidCloseTextDocumentParams(text_document=types.TextDocumentIdentifier(uri=uri)))

    text = document(200)
    uri = "file:///bench/memory.phys"
    waiting = client.expect(uri, 1)
    client.text_document_did_open(types.DidOpenTextDocumentParams(text_document=types.TextDocumentItem(uri=uri, language_id="phys", version=1, text=text)))
    await asyncio.wait_for(waiting, 60)
    _, version = await edits(client, uri, text, 1, 1)
    first = rss_mib(pid)
    await edits(client, uri, text, args.memory_edits - 1, version, first=1)
    last = rss_mib(pid)
    print(f"memory: {first:.1f} MiB after the first edit, {last:.1f} MiB after {args.memory_edits} ({100 * (last / first - 1):+.1f} %)")
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--edits", type=int, default=200)
    parser.add_argument("--big-edits", type=int, default=40)
    parser.add_argument("--completions", type=int, default=200)
    parser.add_argument("--memory-edits", type=int, default=1000)
    asyncio.run(run(parser.parse_args()))


if __name__ == "__main__":
    main()
