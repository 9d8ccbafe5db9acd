"""What a syntax error is said as: lark's UnexpectedInput in a chunk of the file turned into a
diagnostic that names the tokens as a reader knows them (E0101-E0104), with help for the usual slips.
"""

from __future__ import annotations

from lark import Lark, Token
from lark.exceptions import UnexpectedCharacters, UnexpectedInput, UnexpectedToken

from physc.diagnostics import Diagnostic
from physc.dsl.chunks import Chunk
from physc.dsl.lexer import FastLexer

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


def _unclosed(chunk: Chunk, parser: Lark) -> Token | None:
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


def syntax_diagnostic(error: UnexpectedInput, chunk: Chunk, parser: Lark, followed: bool) -> Diagnostic:
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
            start, stop = opener.start_pos, opener.end_pos
            assert start is not None and stop is not None  # FastLexer gives every token its offsets
            return Diagnostic(
                "E0103",
                f"the scenario ends {where}, but this {_describe(opener.type)} is not closed",
                chunk.span(start, stop),
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
