"""Parsing `.phys` text into the AST, with diagnostics instead of exceptions.

The file is cut into chunks at every `scenario` keyword (outside strings and
comments: chunks.py) and each chunk is parsed on its own with lark's LALR parser and an
inline transformer (tree_builder.py: no tree is built, no recursion: 10,000 nested brackets
are fine). A syntax error therefore costs one scenario, not the rest of the file, and
all scenarios' semantic errors are still reported in the same run; syntax_errors.py says
what a syntax error is. Reading a file (its size, its encoding) is here too.
"""

from __future__ import annotations

import functools
from importlib import resources

import attrs
from lark import Lark
from lark.exceptions import UnexpectedInput, VisitError

from physc.diagnostics import Diagnostic, SourceText
from physc.dsl import ast
from physc.dsl.chunks import cut_chunks
from physc.dsl.lexer import FastLexer
from physc.dsl.syntax_errors import KEYWORDS, TOKEN_NAMES, syntax_diagnostic
from physc.dsl.tree_builder import Builder, SyntaxProblem
from physc.files import read_input
from physc.gc_pause import gc_paused

# The parser's public names; the words of its messages (TOKEN_NAMES, KEYWORDS) live in syntax_errors.
__all__ = [
    "KEYWORDS",
    "MAX_SOURCE_BYTES",
    "TOKEN_NAMES",
    "ParseResult",
    "ReadResult",
    "parse_source",
    "parse_text",
    "read_source",
]


@attrs.frozen
class ParseResult:
    source: SourceText
    file: ast.File
    diagnostics: tuple[Diagnostic, ...]


@functools.cache
def _lark() -> tuple[Lark, Builder]:
    grammar = resources.files("physc.dsl").joinpath("phys.lark").read_text(encoding="utf-8")
    builder = Builder()
    parser = Lark(grammar, parser="lalr", lexer=FastLexer, transformer=builder, maybe_placeholders=False)
    return parser, builder


def parse_source(source: SourceText) -> ParseResult:
    """Parse a whole file; every syntax error is a diagnostic, never an exception."""
    with gc_paused():
        return _parse_source(source)


def _parse_source(source: SourceText) -> ParseResult:
    parser, builder = _lark()
    diagnostics: list[Diagnostic] = []
    scenarios: list[ast.Scenario] = []
    chunks, comments, any_scenario = cut_chunks(source)
    builder.source = source
    builder.line_starts = source.line_starts
    for index, chunk in enumerate(chunks):
        builder.offset = chunk.start
        builder.problems = []
        try:
            scenario = parser.parse(chunk.text)
            assert isinstance(scenario, ast.Scenario)  # what the transformer makes of a chunk
            scenarios.append(scenario)
        except UnexpectedInput as error:
            followed = index + 1 < len(chunks)
            diagnostics.append(syntax_diagnostic(error, chunk, parser, followed))
            continue
        except VisitError as error:
            if not isinstance(error.orig_exc, SyntaxProblem):
                raise
            diagnostics.append(error.orig_exc.diagnostic)
            continue
        except SyntaxProblem as problem:
            diagnostics.append(problem.diagnostic)
            continue
        finally:
            diagnostics.extend(builder.problems)
    if not any_scenario and not diagnostics:
        diagnostics.append(
            Diagnostic(
                "E0003",
                "this file holds no scenario",
                source.span(0, 0),
                help="write a scenario, e.g. `scenario SF = {[hit(bird)(pig)(any)] > [destroy(bird)(pig)]}, {}`",
            )
        )
    return ParseResult(source, ast.File(tuple(scenarios), tuple(comments)), tuple(diagnostics))


def parse_text(text: str, path: str = "<input>") -> ParseResult:
    return parse_source(SourceText(path, text))


@attrs.frozen
class ReadResult:
    source: SourceText | None
    diagnostics: tuple[Diagnostic, ...] = ()


MAX_SOURCE_BYTES = 64 * 1024 * 1024  # a .phys file at most (the front end takes 5 MB in ~10 s)


def read_source(path: str) -> ReadResult:
    """Read a file as UTF-8 (a leading byte-order mark is dropped); '-' is standard input.
    At most MAX_SOURCE_BYTES are read: a larger input (or /dev/zero) is refused, not held."""
    data, problem = read_input(path, limit=MAX_SOURCE_BYTES + 1)
    if data is None:
        assert problem is not None  # read_input says why it read nothing
        return ReadResult(None, (Diagnostic("E0001", problem),))
    if len(data) > MAX_SOURCE_BYTES:
        return ReadResult(
            None,
            (
                Diagnostic(
                    "E0001",
                    f"cannot read the input: it is larger than {MAX_SOURCE_BYTES // 2**20} MiB, the most physc reads",
                ),
            ),
        )
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError as error:
        good = data[: error.start].decode("utf-8")
        source = SourceText(path, good + "\ufffd" + data[error.end :].decode("utf-8", "replace"))
        return ReadResult(
            source,
            (
                Diagnostic(
                    "E0002",
                    f"the input is not valid UTF-8: byte 0x{data[error.start]:02x} at offset {error.start}",
                    source.span(len(good), len(good) + 1),
                    help="save the file as UTF-8",
                ),
            ),
        )
    if text.startswith("\ufeff"):
        text = text[1:]
    return ReadResult(SourceText(path, text))
