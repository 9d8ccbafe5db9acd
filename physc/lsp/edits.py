"""Edits that the server proposes: quick fixes from diagnostics and document formatting.

Quick fixes are the `fixes` that the static checks attach to their diagnostics (the "did you mean"
of a help, as edits); formatting is `physc fmt`'s output, sent as the smallest line edits that turn
the document into it, so that the cursor and the rest of the text stay where they were.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Callable, Sequence

from lsprotocol import types

from physc.diagnostics import Diagnostic, SourceText
from physc.dsl import ast
from physc.dsl.fmt import format_file

ToRange = Callable[..., types.Range]
_LINES = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+\Z")


def quick_fixes(
    uri: str, found: Sequence[tuple[Diagnostic, types.Diagnostic]], to_range: ToRange
) -> list[types.CodeAction]:
    """A code action per fix of each diagnostic (ours paired with what the client was sent)."""
    actions = []
    for diagnostic, sent in found:
        for number, fix in enumerate(diagnostic.fixes):
            edits = [types.TextEdit(range=to_range(e.span), new_text=e.text) for e in fix.edits]
            actions.append(
                types.CodeAction(
                    title=fix.title,
                    kind=types.CodeActionKind.QuickFix,
                    diagnostics=[sent],
                    is_preferred=number == 0 and len(diagnostic.fixes) == 1,
                    edit=types.WorkspaceEdit(changes={uri: edits}),
                )
            )
    return actions


def lines(text: str) -> list[str]:
    """The lines of `text` with their breaks, as LSP counts lines (`\n`, `\r\n`, `\r`)."""
    return _LINES.findall(text)


def formatting(file: ast.File, source: SourceText, text: str) -> list[types.TextEdit]:
    """The line edits that make the document's `text` `physc fmt`'s output (none when it is)."""
    formatted = format_file(file, source)
    if formatted == text:
        return []
    old, new = lines(text), lines(formatted)
    edits = []
    matcher = difflib.SequenceMatcher(None, old, new, autojunk=False)
    for tag, i1, i2, j1, j2 in reversed(matcher.get_opcodes()):
        if tag == "equal":
            continue
        start = types.Position(line=i1, character=0)
        end = types.Position(line=i2, character=0)
        edits.append(types.TextEdit(range=types.Range(start=start, end=end), new_text="".join(new[j1:j2])))
    return edits
