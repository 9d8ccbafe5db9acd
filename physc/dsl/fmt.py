"""`physc fmt`: print scenarios in the canonical block form, keeping comments.

The canonical form: sections in the order domain, objects, interactions,
restrictions (empty ones left out); four spaces of indentation; terms in call
style without brackets; the first interaction on its own line and every further
one on a line starting with `>`; one restriction per line; one blank line
between sections and between scenarios.

Comments are anchored to the syntax they sit next to in the source: a comment
on the line where a node ends stays at the end of that node's line; any other
comment goes on its own lines before the next node. Formatting is idempotent.
"""

from __future__ import annotations

from collections.abc import Iterable

import attrs

from physc.diagnostics import SourceText, Span
from physc.dsl import ast

INDENT = "    "
SECTION_ORDER = ("domain", "objects", "interactions", "restrictions")


def quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def format_argument(argument: ast.Argument) -> str:
    return " | ".join(name.text for name in argument.alternatives)


def format_term(term: ast.Term) -> str:
    return f"{term.name.text}({', '.join(format_argument(a) for a in term.arguments)})"


def format_declaration(declaration: ast.Declaration) -> str:
    text = f"{declaration.name.text}: {declaration.term.text}"
    if declaration.materials:
        text += "(" + " | ".join(name.text for name in declaration.materials) + ")"
    if declaration.concrete:
        text += " = " + " | ".join(name.text for name in declaration.concrete)
    return text


@attrs.define
class _Line:
    depth: int
    text: str
    anchor: Span | None = None  # the source node this line stands for
    leading: list[ast.Comment] = attrs.field(factory=list)
    trailing: list[ast.Comment] = attrs.field(factory=list)
    blank_before: bool = False


def _closing_brace(span: Span | None) -> Span | None:
    return None if span is None else span.last()


def _scenario_lines(scenario: ast.Scenario) -> list[_Line]:
    spans = {kind: (keyword, closing) for kind, keyword, closing in scenario.sections}
    head = f"scenario {scenario.name.text}"
    if scenario.title is not None:
        head += " " + quote(scenario.title.value)
    lines = [_Line(0, head + " {", scenario.name.span)]
    if scenario.domain is not None:
        keyword = spans["domain"][0] if "domain" in spans else scenario.domain.span
        lines.append(_Line(1, f"domain {scenario.domain.text}", keyword))
    blocks = {
        "objects": [(format_declaration(d), d.span) for d in scenario.objects],
        "interactions": [(("> " if i else "") + format_term(t), t.span) for i, t in enumerate(scenario.interactions)],
        "restrictions": [(format_term(t), t.span) for t in scenario.restrictions],
    }
    for kind in SECTION_ORDER[1:]:
        if not blocks[kind]:
            continue
        keyword, closing = spans.get(kind, (None, None))
        lines.append(_Line(1, f"{kind} {{", keyword, blank_before=len(lines) > 1))
        lines += [_Line(2, text, span) for text, span in blocks[kind]]
        lines.append(_Line(1, "}", closing))
    lines.append(_Line(0, "}", _closing_brace(scenario.span)))
    return lines


def _attach(lines: list[_Line], comments: Iterable[ast.Comment]) -> list[ast.Comment]:
    """Attach each comment to a line (trailing or leading); return those after the last node."""
    anchored = sorted(((line.anchor, line) for line in lines if line.anchor is not None), key=lambda a: a[0].start)
    ends_on: dict[int, tuple[Span, _Line]] = {}
    for anchor, line in anchored:  # the last node that ends on a source line owns its end-of-line comment
        ends_on[anchor.end_line] = (anchor, line)
    tail: list[ast.Comment] = []
    cursor = 0
    for comment in sorted(comments, key=lambda c: c.span.start):
        owner = ends_on.get(comment.span.line)
        if owner is not None and owner[0].end <= comment.span.start:
            owner[1].trailing.append(comment)
            continue
        while cursor < len(anchored) and anchored[cursor][0].start < comment.span.start:
            cursor += 1
        (anchored[cursor][1].leading if cursor < len(anchored) else tail).append(comment)
    return tail


def _gap(source: SourceText | None, after_line: int, before_line: int) -> bool:
    """Whether the source has a blank line strictly between two lines."""
    if source is None:
        return False
    return any(not source.line_text(n).strip() for n in range(after_line + 1, min(before_line, source.line_count + 1)))


def _render_comments(
    out: list[str],
    comments: list[ast.Comment],
    indent: str,
    source: SourceText | None,
    next_line: int | None,
    keep_gaps: bool,
) -> None:
    for index, comment in enumerate(comments):
        out.append(indent + comment.text)
        following = comments[index + 1].span.line if index + 1 < len(comments) else next_line
        if keep_gaps and following is not None and _gap(source, comment.span.line, following):
            out.append("")


def format_file(file: ast.File, source: SourceText | None = None) -> str:
    """The canonical text of a parsed file (comments kept when `file.comments` has them)."""
    scenario_lines = [_scenario_lines(s) for s in file.scenarios]
    tail = _attach([line for lines in scenario_lines for line in lines], file.comments)
    out: list[str] = []
    for lines in scenario_lines:
        if out:
            out.append("")
        for line in lines:
            indent = INDENT * line.depth
            if line.blank_before:
                out.append("")
            if line.leading:
                # Comments before a closing brace are inside the block it closes.
                inner = INDENT * (line.depth + 1) if line.text == "}" else indent
                top = line.depth == 0 and line.text != "}"
                assert line.anchor is not None  # comments are attached to the lines of source nodes only
                _render_comments(out, line.leading, inner, source, line.anchor.line, keep_gaps=top)
            text = indent + line.text
            if line.trailing:
                text += "  " + " ".join(c.text for c in line.trailing)
            out.append(text)
    if tail:
        last = file.scenarios[-1].span.end_line if file.scenarios and file.scenarios[-1].span else None
        if out and (last is None or source is None or _gap(source, last, tail[0].span.line)):
            out.append("")
        _render_comments(out, tail, "", source, None, keep_gaps=True)
    while out and out[-1] == "":
        out.pop()
    return "\n".join(out) + "\n" if out else ""
