"""The tree-to-AST transformer of the parser: lark calls it as it reduces (an inline transformer),
so the AST is built without a parse tree and without recursion.

Syntax that the grammar accepts but the language does not (two restrictions on one line without a
separator, an unknown escape in a string) is raised as `SyntaxProblem`, which costs the scenario;
problems that do not stop the scenario (a section given twice) are collected in `problems`.
"""

from __future__ import annotations

import re

import attrs
from lark import Transformer

from physc.diagnostics import Diagnostic, Label, SourceText, Span
from physc.dsl import ast
from physc.dsl.lexer import OffsetToken

_ESCAPE = re.compile(r"\\(.)")


class SyntaxProblem(Exception):
    """Raised inside the transformer for syntax the grammar accepts but the language does not."""

    def __init__(self, diagnostic: Diagnostic):
        super().__init__(diagnostic.message)
        self.diagnostic = diagnostic


class Builder(Transformer):
    """Builds AST nodes while lark reduces (an inline transformer)."""

    # Set by the parser: for the whole file, and for the chunk being parsed (its offset in the file).
    source: SourceText
    line_starts: list[int]
    offset: int
    problems: list[Diagnostic]  # of the chunk, that do not stop it from giving a scenario

    def _span(self, first: OffsetToken, last: OffsetToken | None = None) -> Span:
        last = first if last is None else last
        return Span(first.start_pos + self.offset, last.end_pos + self.offset, self.line_starts)

    def _name(self, token: OffsetToken) -> ast.Name:
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
                arguments.append(_argument(names))
                names = []
        if names:
            arguments.append(_argument(names))
        return arguments, children[-1]

    def call(self, children):
        name = self._name(children[0])
        arguments = [a for group, _ in children[1:] for a in group]
        closing = children[-1][1]
        return ast.Term(name, tuple(arguments), self._span(children[0], closing))

    def bracketed(self, children):
        return attrs.evolve(children[1], outer=self._span(children[0], children[2]))

    def sequence(self, children):
        return [c for c in children if isinstance(c, ast.Term)]

    def conjunction(self, children):
        terms = []
        separated = True
        for child in children:
            if isinstance(child, ast.Term):
                if not separated and ast.located(terms[-1].span).end_line == ast.located(child.span).line:
                    raise SyntaxProblem(
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
                raise SyntaxProblem(
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


def _argument(names: list[ast.Name]) -> ast.Argument:
    """An argument from the names of its alternatives (made by `Builder._name`, with spans)."""
    first, last = names[0].span, names[-1].span
    assert first is not None and last is not None  # every name the builder makes has a span
    return ast.Argument(tuple(names), first.join(last))
