"""Parsing `.phys` text into the AST, with diagnostics instead of exceptions.

The file is cut into chunks at every `scenario` keyword (outside strings and
comments) and each chunk is parsed on its own with lark's LALR parser and an
inline transformer (no tree is built, no recursion: 10,000 nested brackets are
fine). A syntax error therefore costs one scenario, not the rest of the file, and
all scenarios' semantic errors are still reported in the same run.
"""

from __future__ import annotations

import functools
import re
from importlib import resources

import attrs
from lark import Lark, Token, Transformer
from lark.exceptions import (
    UnexpectedCharacters,
    UnexpectedInput,
    UnexpectedToken,
    VisitError,
)

from physc.diagnostics import Diagnostic, Label, SourceText, Span
from physc.dsl import ast
from physc.dsl.lexer import FastLexer
from physc.files import read_input
from physc.gc_pause import gc_paused

# What a terminal is called in a message.
TOKEN_NAMES = {
    "SCENARIO": "'scenario'",
    "DOMAIN": "'domain'",
    "OBJECTS": "'objects'",
    "INTERACTIONS": "'interactions'",
    "RESTRICTIONS": "'restrictions'",
    "AND": "'and'",
    "OR": "'or'",
    "NAME": "a name",
    "STRING": "a string",
    "LBRACE": "'{'",
    "RBRACE": "'}'",
    "LPAR": "'('",
    "RPAR": "')'",
    "LSQB": "'['",
    "RSQB": "']'",
    "COMMA": "','",
    "COLON": "':'",
    "EQUALS": "'='",
    "GT": "'>'",
    "PIPE": "'|'",
    "VEE": "'∨'",
    "AMP": "'&'",
    "WEDGE": "'∧'",
    "$END": "the end of the scenario",
}
KEYWORDS = {"SCENARIO", "DOMAIN", "OBJECTS", "INTERACTIONS", "RESTRICTIONS", "AND", "OR"}
# Alternative spellings are listed once in messages, by their first spelling.
_SYNONYMS = [("PIPE", {"VEE", "OR"}), ("COMMA", {"AMP", "WEDGE", "AND"})]
_ORDER = list(TOKEN_NAMES)
_OPENERS = {"LBRACE": "RBRACE", "LPAR": "RPAR", "LSQB": "RSQB"}
_CHARACTER_HELP = {
    ";": "separate arguments with ',' and interactions with '>'",
    "'": 'strings are written in double quotes: "like this"',
    "→": "interactions are separated by '>'",
    "⋀": "write '∧' (U+2227), '&' or 'and'",
    "⋁": "write '∨' (U+2228), '|' or 'or'",
    "\u00a0": "a no-break space: replace it with an ordinary space",
}

# Finds the `scenario` keywords that start chunks, skipping strings and comments.
_CHUNK_SCAN = re.compile(r'"(?:[^"\\\n]|\\.)*"?|#[^\n]*|//[^\n]*|\bscenario\b')
_ESCAPE = re.compile(r"\\(.)")


@attrs.frozen
class ParseResult:
    source: SourceText
    file: ast.File
    diagnostics: tuple[Diagnostic, ...]


@functools.cache
def _lark() -> tuple[Lark, _Builder]:
    grammar = resources.files("physc.dsl").joinpath("phys.lark").read_text(encoding="utf-8")
    builder = _Builder()
    parser = Lark(grammar, parser="lalr", lexer=FastLexer, transformer=builder, maybe_placeholders=False)
    return parser, builder


class _SyntaxProblem(Exception):
    """Raised inside the transformer for syntax the grammar accepts but the language does not."""

    def __init__(self, diagnostic: Diagnostic):
        super().__init__(diagnostic.message)
        self.diagnostic = diagnostic


class _Builder(Transformer):
    """Builds AST nodes while lark reduces (an inline transformer)."""

    source: SourceText
    line_starts: list[int]
    offset: int

    def _span(self, first: Token, last: Token | None = None) -> Span:
        last = first if last is None else last
        return Span(first.start_pos + self.offset, last.end_pos + self.offset, self.line_starts)

    def _name(self, token: Token) -> ast.Name:
        offset = self.offset
        return ast.Name(str(token), Span(token.start_pos + offset, token.end_pos + offset, self.line_starts))

    # ---- terms -------------------------------------------------------------
    def group(self, children):
        """[LPAR, NAME, sep, NAME, …, RPAR] → ([Argument, …], RPAR)."""
        arguments = []
        names = []
        for token in children[1:-1]:
            if token.type == "NAME":
                names.append(self._name(token))
            elif token.type == "COMMA":
                arguments.append(ast.Argument(tuple(names), names[0].span.join(names[-1].span)))
                names = []
        if names:
            arguments.append(ast.Argument(tuple(names), names[0].span.join(names[-1].span)))
        return arguments, children[-1]

    def call(self, children):
        name = self._name(children[0])
        arguments = [a for group, _ in children[1:] for a in group]
        closing = children[-1][1]
        return ast.Term(name, tuple(arguments), name.span.join(self._span(closing)))

    def bracketed(self, children):
        return attrs.evolve(children[1], outer=self._span(children[0], children[2]))

    def sequence(self, children):
        return [c for c in children if isinstance(c, ast.Term)]

    def conjunction(self, children):
        terms = []
        separated = True
        for child in children:
            if isinstance(child, ast.Term):
                if not separated and terms[-1].span.end_line == child.span.line:
                    raise _SyntaxProblem(
                        Diagnostic(
                            "E0106",
                            "two restrictions on one line need a separator between them",
                            child.span,
                            help="put each restriction on a line of its own, or separate them with ',' or 'and'",
                        )
                    )
                terms.append(child)
                separated = False
            else:
                separated = True
        return terms

    # ---- sections ----------------------------------------------------------
    def declaration(self, children):
        materials, closing = next((c for c in children if isinstance(c, tuple)), ((), None))
        tokens = [c for c in children if not isinstance(c, tuple)]
        names = [self._name(t) for t in tokens if t.type == "NAME"]
        end = tokens[-1] if tokens[-1].type != "COMMA" else tokens[-2]
        if len(names) == 2 and closing is not None:
            end = closing  # `name: term(materials)`: it ends at the closing parenthesis
        return ast.Declaration(names[0], names[1], tuple(names[2:]), self._span(children[0], end), materials)

    def materials(self, children):
        """(the materials, the closing parenthesis) of a declaration (version 2)."""
        return tuple(self._name(t) for t in children if t.type == "NAME"), children[-1]

    # A section is (kind, value, keyword span, closing span).
    def domain_section(self, children):
        name = self._name(children[1])
        return ("domain", name, self._span(children[0]), name.span)

    def objects_section(self, children):
        return ("objects", tuple(children[2:-1]), self._span(children[0]), self._span(children[-1]))

    def interactions_section(self, children):
        return ("interactions", tuple(children[2]), self._span(children[0]), self._span(children[-1]))

    def restrictions_section(self, children):
        terms = children[2] if len(children) == 4 else []
        return ("restrictions", tuple(terms), self._span(children[0]), self._span(children[-1]))

    def block_body(self, children):
        return children[1:-1], children[-1]

    def paper_body(self, children):
        sequence = children[1]
        conjunction = children[5] if len(children) == 7 else []
        return sequence, conjunction, children[-1]

    def title(self, children):
        token = children[0]
        raw = str(token)[1:-1]
        for match in _ESCAPE.finditer(raw):
            if match.group(1) not in '"\\':
                start = token.start_pos + self.offset + 1 + match.start()
                raise _SyntaxProblem(
                    Diagnostic(
                        "E0105",
                        f"unknown escape sequence '\\{match.group(1)}' in a string",
                        self.source.span(start, start + 2),
                        help='only \\" and \\\\ may be escaped in a string',
                    )
                )
        return ast.Text(_ESCAPE.sub(r"\1", raw), self._span(token))

    # ---- scenarios ---------------------------------------------------------
    def _head(self, children):
        name = self._name(children[1])
        title = children[2] if isinstance(children[2], ast.Text) else None
        return name, title

    def block_scenario(self, children):
        name, title = self._head(children)
        sections, closing = children[-1]
        found: dict[str, tuple] = {}
        kept = []
        for kind, value, span, closing_span in sections:
            if kind in found:
                self.problems.append(
                    Diagnostic(
                        "E0602",
                        f"the '{kind}' section is given twice in scenario '{name.text}'",
                        span,
                        help=f"merge the two '{kind}' sections into one",
                        notes=(Label(found[kind][1], f"first '{kind}' section"),),
                    )
                )
                continue
            found[kind] = (value, span)
            kept.append((kind, span, closing_span))
        if "interactions" not in found:
            self.problems.append(
                Diagnostic(
                    "E0603",
                    f"scenario '{name.text}' has no interactions section",
                    name.span,
                    help="add `interactions { hit(bird, pig, any) > destroy(bird, pig) }` or similar",
                )
            )

        def value(kind, default):
            return found[kind][0] if kind in found else default

        return ast.Scenario(
            name=name,
            title=title,
            domain=value("domain", None),
            objects=value("objects", ()),
            interactions=value("interactions", ()),
            restrictions=value("restrictions", ()),
            span=self._span(children[0], closing),
            form="block",
            sections=tuple(kept),
        )

    def paper_scenario(self, children):
        name, title = self._head(children)
        sequence, conjunction, closing = children[-1]
        return ast.Scenario(
            name=name,
            title=title,
            interactions=tuple(sequence),
            restrictions=tuple(conjunction),
            span=self._span(children[0], closing),
            form="paper",
        )

    def start(self, children):
        return children[0]


def _describe(token_type: str) -> str:
    return TOKEN_NAMES.get(token_type, token_type)


def _expected(expected: set[str]) -> str:
    names = set(expected)
    for main, others in _SYNONYMS:
        if main in names:
            names -= others
    ordered = sorted(names, key=lambda t: _ORDER.index(t) if t in _ORDER else len(_ORDER))
    words = [_describe(t) for t in ordered]
    if len(words) == 1:
        return words[0]
    return ", ".join(words[:-1]) + " or " + words[-1]


def _found(token: Token) -> str:
    if token.type == "NAME":
        return f"the name '{token}'"
    if token.type in KEYWORDS:
        return f"the keyword '{token}'"
    if token.type == "STRING":
        return "a string"
    return _describe(token.type)


class _Chunk:
    def __init__(self, source: SourceText, start: int, end: int):
        self.source = source
        self.start = start
        self.end = end
        self.text = source.text[start:end]

    def span(self, start: int, end: int) -> Span:
        return self.source.span(start + self.start, end + self.start)


def _unclosed(chunk: _Chunk, parser: Lark) -> Token | None:
    """The innermost bracket that is still open at the end of a chunk."""
    stack: list[Token] = []
    try:
        for token in FastLexer(parser.lexer_conf).lex(chunk.text):
            if token.type in _OPENERS:
                stack.append(token)
            elif stack and token.type == _OPENERS[stack[-1].type]:
                stack.pop()
    except UnexpectedInput:
        pass
    return stack[-1] if stack else None


def _syntax_diagnostic(error: UnexpectedInput, chunk: _Chunk, parser: Lark, followed: bool) -> Diagnostic:
    if isinstance(error, UnexpectedCharacters):
        position = error.pos_in_stream
        char = chunk.text[position]
        if char == '"':
            line_end = chunk.text.find("\n", position)
            line_end = len(chunk.text) if line_end < 0 else line_end
            return Diagnostic(
                "E0104",
                "this string is not closed on its line",
                chunk.span(position, line_end),
                help='close it with " (write \\" for a quote inside a string)',
            )
        code_point = f" (U+{ord(char):04X})" if not char.isascii() or not char.isprintable() else ""
        shown = char if char.isprintable() else repr(char)[1:-1]
        return Diagnostic(
            "E0101",
            f"unexpected character '{shown}'{code_point}",
            chunk.span(position, position + 1),
            help=_CHARACTER_HELP.get(char),
        )
    assert isinstance(error, UnexpectedToken)
    token = error.token
    if token.type == "$END":
        opener = _unclosed(chunk, parser)
        where = "before the next scenario" if followed else "at the end of the file"
        if opener is not None:
            closer = _describe(_OPENERS[opener.type])
            return Diagnostic(
                "E0103",
                f"the scenario ends {where}, but this {_describe(opener.type)} is not closed",
                chunk.span(opener.start_pos, opener.end_pos),
                help=f"add the missing {closer}; expected {_expected(error.expected)}",
            )
        end = len(chunk.text.rstrip())
        return Diagnostic(
            "E0103",
            f"the scenario ends {where}, but {_expected(error.expected)} was expected",
            chunk.span(end, end),
        )
    help_text = None
    if token.type in KEYWORDS and "NAME" in error.expected:
        help_text = f"'{token}' is a keyword of the language and cannot be used as a name"
    elif token.type == "NAME" and "GT" in error.expected:
        help_text = "interactions are separated by '>'"
    return Diagnostic(
        "E0102",
        f"expected {_expected(error.expected)}, found {_found(token)}",
        chunk.span(token.start_pos, token.end_pos),
        help=help_text,
    )


def _chunks(source: SourceText) -> tuple[list[_Chunk], list[ast.Comment], bool]:
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
    chunks = [_Chunk(source, bounds[i], bounds[i + 1]) for i in range(len(starts))]
    head_end = starts[0] if starts else len(source.text)
    head = _CHUNK_SCAN.sub(lambda m: "" if m.group()[0] in "#/" else m.group(), source.text[:head_end])
    if head.strip():
        chunks.insert(0, _Chunk(source, 0, head_end))
    return chunks, comments, bool(starts)


def parse_source(source: SourceText) -> ParseResult:
    """Parse a whole file; every syntax error is a diagnostic, never an exception."""
    with gc_paused():
        return _parse_source(source)


def _parse_source(source: SourceText) -> ParseResult:
    parser, builder = _lark()
    diagnostics: list[Diagnostic] = []
    scenarios: list[ast.Scenario] = []
    chunks, comments, any_scenario = _chunks(source)
    builder.source = source
    builder.line_starts = source.line_starts
    for index, chunk in enumerate(chunks):
        builder.offset = chunk.start
        builder.problems = []
        try:
            scenarios.append(parser.parse(chunk.text))
        except UnexpectedInput as error:
            followed = index + 1 < len(chunks)
            diagnostics.append(_syntax_diagnostic(error, chunk, parser, followed))
            continue
        except VisitError as error:
            if not isinstance(error.orig_exc, _SyntaxProblem):
                raise
            diagnostics.append(error.orig_exc.diagnostic)
            continue
        except _SyntaxProblem as problem:
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
