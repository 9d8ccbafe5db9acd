"""Where in a scenario a place of the text is, read from the text alone.

Completion is asked for in the middle of typing, when the file rarely parses, so the place is found
by a tolerant walk over the tokens of the scenario around the cursor (lexed with the grammar's own
terminals): which section it is in, which term and which argument of it, which declaration. The
walk also collects the scenario's domain and object names. It reads one scenario, never the whole
file, so it costs the same in a file of 10 lines and of 100,000.
"""

from __future__ import annotations

import functools
import re

import attrs

from physc.domains import DEFAULT_DOMAIN
from physc.dsl.lexer import FastLexer

# The roles of a name at a place: what a name written there would be.
TOP = "top"  # before or between scenarios: `scenario`
SCENARIO_NAME = "scenario-name"
BODY = "body"  # inside a block-form scenario, outside its sections: section keywords
DOMAIN = "domain"
DECLARATION = "declaration"  # the name of a new object
OBJECT_TERM = "object-term"  # after `name:`
CONCRETE = "concrete"  # after `name: term =` or `|`
MATERIAL = "material"  # after `name: term(` or `|` inside it (language version 2)
TERM = "term"  # an interaction or a restriction
ARGUMENT = "argument"
OTHER = "other"

_SECTIONS = {"OBJECTS": "objects", "INTERACTIONS": "interactions", "RESTRICTIONS": "restrictions"}
_ALTERNATIVE = {"PIPE", "VEE", "OR"}
_SEPARATOR = {"GT", "COMMA", "AMP", "WEDGE", "AND"}
_SCENARIO_WORD = re.compile(r"\bscenario\b")
# A string (closed or not) or a comment on a line: no name is written inside one.
_QUOTED = re.compile(r'"(?:[^"\\\n]|\\.)*"?|#[^\n]*|//[^\n]*')


@attrs.frozen
class Token:
    kind: str
    text: str
    start: int
    end: int


@attrs.define
class Place:
    """The role of a name at an offset, and what the walk learnt of the scenario around it."""

    role: str = TOP
    section: str | None = None  # objects | interactions | restrictions
    term: str | None = None  # ARGUMENT: the term whose argument it is
    argument: int = 0  # ARGUMENT: its index
    object_term: str | None = None  # CONCRETE: the declaration's object term
    word: Token | None = None  # the name at the offset (what completion replaces, hover explains)
    domain: str = DEFAULT_DOMAIN
    declared: dict[str, str] = attrs.field(factory=dict)  # object name -> its declared term
    narrowed: dict[str, list[str]] = attrs.field(factory=dict)  # object name -> its declared concrete objects
    arguments: dict[str, None] = attrs.field(factory=dict)  # names written as arguments, in order
    sections: set[str] = attrs.field(factory=set)


@functools.cache
def _lexer() -> FastLexer:
    from physc.dsl.parser import _lark

    return FastLexer(_lark()[0].lexer_conf)


def tokens(text: str, start: int, end: int):
    """The tokens of text[start:end], comments and blanks left out; a character no token starts
    with is skipped (the text is being typed)."""
    lexer = _lexer()
    match, keywords, ignore = lexer.scanner.match, lexer.keywords, lexer.ignore
    position = start
    while position < end:
        found = match(text, position, end)
        if found is None:
            position += 1
            continue
        kind, stop = found.lastgroup, found.end()
        assert kind is not None  # the scanner is an alternation of named groups
        if kind not in ignore and kind != "COMMENT":
            value = found.group()
            yield Token(keywords.get(value, "NAME") if kind == "NAME" else kind, value, position, stop)
        position = stop


def _scenario_start(text: str, offset: int) -> int | None:
    """Where the scenario around `offset` starts: the last `scenario` keyword before it (a word in
    a comment or a string does not count), found line by line backwards; None before the first."""
    line_end = offset
    while True:
        line_start = text.rfind("\n", 0, line_end) + 1
        if _SCENARIO_WORD.search(text, line_start, line_end + 8):
            keywords = [
                t.start
                for t in tokens(text, line_start, min(len(text), max(line_end, offset)))
                if t.kind == "SCENARIO" and t.start < offset
            ]
            if keywords:
                return keywords[-1]
        if line_start == 0:
            return None
        line_end = line_start - 1


class _Walk:
    """The state machine over one scenario's tokens."""

    def __init__(self):
        self.place = Place(role=SCENARIO_NAME)
        self.form: str | None = None
        self.depth = 0
        self.paper_section = 0
        self.after_group = False  # a `)` closed an argument group: `(` continues the term
        self.declaring: str | None = None  # the object a declaration is about
        self.pending: str | None = None  # a section keyword waiting for its `{`

    def expect(self, role: str, **fields) -> None:
        place = self.place
        place.role, place.term, place.argument, place.object_term = role, None, 0, None
        for name, value in fields.items():
            setattr(place, name, value)

    def step(self, token: Token) -> None:
        place, kind = self.place, token.kind
        if self.after_group:
            self.after_group = False
            if kind == "LPAR":
                self.expect(ARGUMENT, term=place.term, argument=place.argument + 1)
                return
            self.expect(TERM)
        if kind == "NAME":
            self.name(token)
        elif kind in _SECTIONS and self.depth == 1:
            self.pending = _SECTIONS[kind]
            self.expect(OTHER)
        elif kind == "DOMAIN" and self.depth == 1:
            place.sections.add("domain")
            self.expect(DOMAIN)
        elif kind == "EQUALS" and self.depth == 0:
            self.form = "paper"
            self.expect(OTHER)
        elif kind == "LBRACE":
            self.open_brace()
        elif kind == "RBRACE":
            self.depth = max(self.depth - 1, 0)
            place.section = None
            ended = self.depth == 0 and (self.form == "block" or self.paper_section >= 2)
            self.expect(TOP if ended else BODY if self.form == "block" and self.depth == 1 else OTHER)
        elif kind == "LPAR" and place.section == "objects" and place.role == DECLARATION and place.object_term:
            self.expect(MATERIAL, object_term=place.object_term)
        elif kind in _ALTERNATIVE and place.role == MATERIAL:
            self.expect(MATERIAL, object_term=place.object_term)
        elif kind == "RPAR" and place.role == MATERIAL:
            self.expect(DECLARATION, object_term=place.object_term)
        elif kind == "LPAR" and place.role == OTHER and place.term:
            self.expect(ARGUMENT, term=place.term)
        elif kind == "RPAR" and place.role == ARGUMENT:
            self.after_group = True
            self.expect(OTHER, term=place.term, argument=place.argument)
        elif kind == "COMMA" and place.role == ARGUMENT:
            self.expect(ARGUMENT, term=place.term, argument=place.argument + 1)
        elif kind in _ALTERNATIVE and place.role == ARGUMENT:
            self.expect(ARGUMENT, term=place.term, argument=place.argument)
        elif kind in _ALTERNATIVE and place.section == "objects":
            self.expect(CONCRETE, object_term=place.object_term)
        elif kind == "COLON" and place.section == "objects":
            self.expect(OBJECT_TERM)
        elif kind == "EQUALS" and place.section == "objects":
            self.expect(CONCRETE, object_term=place.declared.get(self.declaring or ""))
        elif kind in _SEPARATOR or kind in ("LSQB", "RSQB"):
            self.expect(DECLARATION if place.section == "objects" else TERM if place.section else OTHER)
        else:
            self.expect(OTHER)

    def open_brace(self) -> None:
        place = self.place
        if self.depth == 0 and self.form is None:
            self.form = "block"
        self.depth += 1
        if self.form == "block" and self.depth == 1:
            self.expect(BODY)
        elif self.form == "block" and self.depth == 2 and self.pending:
            place.section, self.pending = self.pending, None
        elif self.form == "paper" and self.depth == 1:
            place.section = ("interactions", "restrictions")[min(self.paper_section, 1)]
            self.paper_section += 1
        if place.section:
            place.sections.add(place.section)
            self.expect(DECLARATION if place.section == "objects" else TERM)
        elif self.depth > 1:
            self.expect(OTHER)

    def name(self, token: Token) -> None:
        place, role = self.place, self.place.role
        if role == DOMAIN:
            place.domain = token.text
            self.expect(BODY)
        elif role == SCENARIO_NAME:
            self.expect(OTHER)
        elif role == MATERIAL:
            self.expect(MATERIAL, object_term=place.object_term)
        elif role == CONCRETE:
            if self.declaring:
                place.narrowed.setdefault(self.declaring, []).append(token.text)
            self.expect(DECLARATION, object_term=place.object_term)
        elif role == DECLARATION or (role == OTHER and place.section == "objects"):
            self.declaring = token.text
            self.expect(OTHER)
        elif role == OBJECT_TERM:
            if self.declaring:
                place.declared.setdefault(self.declaring, token.text)
            self.expect(DECLARATION, object_term=token.text)
        elif role == ARGUMENT:
            place.arguments.setdefault(token.text, None)
            self.expect(ARGUMENT, term=place.term, argument=place.argument)
        elif role == TERM or (role == OTHER and place.section in ("interactions", "restrictions")):
            self.expect(OTHER, term=token.text)
        else:
            self.expect(OTHER)


def locate(text: str, offset: int) -> Place:
    """The place of `offset` in `text`: the role of a name there, and its scenario's names."""
    offset = min(max(offset, 0), len(text))
    if _quoted(text, offset):
        return Place(role=OTHER)
    start = _scenario_start(text, offset)
    if start is None:
        return Place(role=TOP, word=_word_at(text, offset))
    walk = _Walk()
    at: Place | None = None
    word = None
    for token in tokens(text, start + len("scenario"), len(text)):
        if token.kind == "SCENARIO":
            break
        if at is None and token.start >= offset:
            at = attrs.evolve(walk.place)
        elif at is None and token.kind == "NAME" and token.start < offset <= token.end:
            at, word = attrs.evolve(walk.place), token
        walk.step(token)
    if at is None:  # the cursor is after the scenario's last token
        at = attrs.evolve(walk.place)
        if walk.after_group:
            at.role = TERM
    final = walk.place
    at.word, at.domain, at.sections = word, final.domain, final.sections
    at.declared, at.narrowed, at.arguments = final.declared, final.narrowed, final.arguments
    return at


def _quoted(text: str, offset: int) -> bool:
    """Whether `offset` is inside a string or a comment (read on its line)."""
    line_start = text.rfind("\n", 0, offset) + 1
    line_end = text.find("\n", offset)
    for found in _QUOTED.finditer(text, line_start, len(text) if line_end < 0 else line_end):
        word = found.group()
        closed = word[0] == '"' and len(word) > 1 and word.endswith('"')  # a comment or an open string runs on
        if found.start() < offset and (offset < found.end() or not closed):
            return True
    return False


def _word_at(text: str, offset: int) -> Token | None:
    start = offset
    while start > 0 and (text[start - 1].isalnum() or text[start - 1] == "_"):
        start -= 1
    return Token("NAME", text[start:offset], start, offset) if start < offset else None
