"""The language server's features, driven over stdio by an LSP client (a real `physc lsp`)."""

from __future__ import annotations

import json
import re
from pathlib import Path

from conftest import EXAMPLES, run_physc
from lsp_client import client, diagnostics, document, edit, open_document, position  # noqa: F401 (client: a fixture)
from lsprotocol import types

from physc.dsl.fmt import format_file
from physc.dsl.parser import parse_text

URI = "file:///work/scenario.phys"
BROKEN = """scenario SF {
    interactions {
        hit(bird, pig, any)
        > destory(bird, pig)
    }
}
"""
DECLARED = (EXAMPLES / "objects.phys").read_text()  # declares rBlock and pig, in a comment-rich block form


def applied(text: str, edits) -> str:
    """`text` with LSP text edits applied (lines end at \n, \r\n or \r; columns in UTF-16 units
    of these ASCII lines)."""
    lines = re.findall(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+\Z", text)
    starts = [0]
    for line in lines:
        starts.append(starts[-1] + len(line))

    def offset(p: types.Position) -> int:
        return len(text) if p.line >= len(lines) else starts[p.line] + p.character

    for e in sorted(edits, key=lambda e: offset(e.range.start), reverse=True):
        text = text[: offset(e.range.start)] + e.new_text + text[offset(e.range.end) :]
    return text


def where(text: str, fragment: str, after: int = 0) -> types.Position:
    """The position `after` characters into the first `fragment` of `text`."""
    offset = text.index(fragment) + after
    line = text.count("\n", 0, offset)
    return position(line, offset - (text.rfind("\n", 0, offset) + 1))


async def test_diagnostics_at_the_right_range_then_cleared_by_an_edit(client):
    open_document(client, URI, BROKEN)
    found = await diagnostics(client, URI, 1)
    assert [(d.code, d.severity, d.source) for d in found] == [("E0201", types.DiagnosticSeverity.Error, "physc")]
    assert found[0].range == types.Range(start=position(3, 10), end=position(3, 17))  # physc check's 4:11, `destory`
    assert "did you mean 'destroy'?" in found[0].message
    edit(client, URI, 2, (3, 10), (3, 17), "destroy")
    assert list(await diagnostics(client, URI, 2)) == []


async def test_diagnostics_are_those_of_physc_check(client, tmp_path):
    """Every broken example (but the one that is not UTF-8, which no editor sends), and one with a
    byte-order mark: the codes, places and messages that `physc check --format json` prints."""
    paths = [p for p in sorted((EXAMPLES / "errors").glob("*.phys")) if not p.name.startswith("E0002")]
    for path in paths + [EXAMPLES / "objects.phys"]:
        text = path.read_text(encoding="utf-8")
        if path.name == "objects.phys":
            text = "\ufeff" + text.replace("cannotFall(rBlock)", "cannotFal(rBlock)")
            path = tmp_path / "bom.phys"
            path.write_text(text, encoding="utf-8")
        uri = f"file:///work/{path.name}"
        open_document(client, uri, text)
        found = await diagnostics(client, uri, 1)
        expected = json.loads(run_physc("check", "--format", "json", path).stdout)
        assert [d.code for d in found] == [d["code"] for d in expected], path.name
        for sent, printed in zip(found, expected):
            line, column = sent.range.start.line + 1, sent.range.start.character + 1
            if text.startswith("\ufeff") and line == 1:
                column -= 1  # physc check drops the mark; the editor's text keeps it
            assert (line, column) == (printed["line"], printed["column"]), path.name
            assert sent.message.split("\nhelp: ")[0] == printed["message"]


async def test_completion_after_hit_offers_what_fits(client):
    text = DECLARED.replace("hit(bird, rBlock, left)", "hit(bird, ")
    open_document(client, URI, text)
    at = where(text, "hit(bird, ", len("hit(bird, "))
    result = await client.text_document_completion_async(types.CompletionParams(text_document=document(URI), position=at))
    labels = [item.label for item in result.items]
    assert labels[:2] == ["rBlock", "pig"]  # the scenario's objects first
    assert "fBlock" in labels and "left" not in labels and "hit" not in labels
    at = where(text, "roll(rBlock, surface, right)", len("roll(rBlock, surface, "))
    result = await client.text_document_completion_async(types.CompletionParams(text_document=document(URI), position=at))
    assert [item.label for item in result.items] == ["left", "right"]


async def test_completion_of_terms_and_declarations(client):
    text = "scenario S {\n    objects {\n        r: \n    }\n    interactions {\n        \n    }\n}\n"
    open_document(client, URI, text)
    terms = await client.text_document_completion_async(types.CompletionParams(text_document=document(URI), position=position(5, 8)))
    assert {"hit", "roll", "destroy"} <= {i.label for i in terms.items}
    assert "cannotHit" not in {i.label for i in terms.items}
    snippet = next(i for i in terms.items if i.label == "hit")
    assert snippet.insert_text_format == types.InsertTextFormat.Snippet and snippet.insert_text.startswith("hit(${1:")
    kinds = await client.text_document_completion_async(types.CompletionParams(text_document=document(URI), position=position(2, 11)))
    assert {"rollableBlock", "pig", "surface"} <= {i.label for i in kinds.items}


async def test_hover_on_a_term_an_object_and_a_diagnostic(client):
    open_document(client, URI, DECLARED)
    term = await client.text_document_hover_async(types.HoverParams(text_document=document(URI), position=where(DECLARED, "> roll(", 3)))
    assert "roll(a, b, d ⊆ {left, right})" in term.contents.value and "rolls on" in term.contents.value
    obj = await client.text_document_hover_async(types.HoverParams(text_document=document(URI), position=where(DECLARED, "hit(bird, rBlock", 11)))
    assert "rollableBlock" in obj.contents.value and "circle" in obj.contents.value
    open_document(client, "file:///work/broken.phys", BROKEN)
    await diagnostics(client, "file:///work/broken.phys", 1)
    explained = await client.text_document_hover_async(types.HoverParams(text_document=document("file:///work/broken.phys"), position=position(3, 12)))
    assert "error[E0201]" in explained.contents.value
    assert "## E0201: a term that the domain does not define" in explained.contents.value  # docs/errors.md


async def test_formatting_gives_physc_fmt_output(client):
    messy = "scenario SF = {[hit(bird)(pig)(any)] > [destroy(bird)(pig)]}, {}\n# a comment\nscenario R {interactions {hit(bird, rBlock, left) > hit(rBlock, pig, left)\n > destroy(rBlock, pig)}}\n"
    open_document(client, URI, messy)
    result = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document(URI), options=types.FormattingOptions(tab_size=4, insert_spaces=True))
    )
    parsed = parse_text(messy)
    assert applied(messy, result) == format_file(parsed.file, parsed.source)
    open_document(client, "file:///work/tidy.phys", format_file(parsed.file, parsed.source))
    tidy = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document("file:///work/tidy.phys"), options=types.FormattingOptions(tab_size=4, insert_spaces=True))
    )
    assert list(tidy) == []


async def test_line_breaks_as_the_protocol_counts_them(client):
    """A U+2028 in a comment is no line break for LSP (nor for Python's splitlines in pygls): an
    incremental edit and the formatting edits land on the right lines; a lone \r is one."""
    text = "# a note\u2028still the note\nscenario SF {\n    interactions {\n        hit(bird, pig, any)\n        > destory(bird, pig)\n    }\n}\n"
    open_document(client, URI, text)
    assert [d.range.start.line for d in await diagnostics(client, URI, 1)] == [4]
    edit(client, URI, 2, (4, 10), (4, 17), "destroy")
    assert list(await diagnostics(client, URI, 2)) == []
    fixed = text.replace("destory", "destroy").split("\n", 1)[1]  # (a comment would run on past a lone \r)
    messy = fixed.replace("    interactions", "  interactions").replace("\n", "\r")
    open_document(client, "file:///work/cr.phys", messy)
    assert list(await diagnostics(client, "file:///work/cr.phys", 1)) == []
    result = await client.text_document_formatting_async(
        types.DocumentFormattingParams(text_document=document("file:///work/cr.phys"), options=types.FormattingOptions(tab_size=4, insert_spaces=True))
    )
    parsed = parse_text(fixed)
    assert applied(messy, result) == format_file(parsed.file, parsed.source)


async def test_no_completion_in_comments_and_strings(client):
    text = 'scenario S "a title" {\n    interactions {\n        # a comment \n    }\n}\n'
    open_document(client, URI, text)
    for at in (where(text, "# a comment ", 12), where(text, '"a title', 3)):
        result = await client.text_document_completion_async(types.CompletionParams(text_document=document(URI), position=at))
        assert result is None or list(result.items) == []


async def test_definition_references_and_symbols(client):
    open_document(client, URI, DECLARED)
    use = where(DECLARED, "> hit(rBlock", 7)
    found = await client.text_document_definition_async(types.DefinitionParams(text_document=document(URI), position=use))
    assert found.range.start == where(DECLARED, "rBlock: rollableBlock")
    refs = await client.text_document_references_async(
        types.ReferenceParams(text_document=document(URI), position=use, context=types.ReferenceContext(include_declaration=True))
    )
    lines = [n for n, line in enumerate(DECLARED.splitlines()) if "rBlock" in line and not line.lstrip().startswith("#")]
    assert [r.range.start.line for r in refs] == lines  # the declaration and every use
    without = await client.text_document_references_async(
        types.ReferenceParams(text_document=document(URI), position=use, context=types.ReferenceContext(include_declaration=False))
    )
    assert len(without) == len(lines) - 1
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(text_document=document(URI)))
    assert [s.name for s in symbols] == ["RF"]
    assert [c.name for c in symbols[0].children][:2] == ["rBlock", "pig"]


async def test_quick_fix_applies_the_suggestion(client):
    open_document(client, URI, BROKEN)
    found = await diagnostics(client, URI, 1)
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(text_document=document(URI), range=found[0].range, context=types.CodeActionContext(diagnostics=found))
    )
    assert [a.title for a in actions] == ["change 'destory' to 'destroy'"]
    assert actions[0].kind == types.CodeActionKind.QuickFix and actions[0].is_preferred
    fixed = applied(BROKEN, actions[0].edit.changes[URI])
    edit(client, URI, 2, (0, 0), (99, 0), fixed)
    assert list(await diagnostics(client, URI, 2)) == []


def _decoded(data: list[int], text: str, legend) -> list[tuple[str, str]]:
    """(word, token type) of LSP's relative encoding."""
    lines, out, line, column = text.splitlines(), [], 0, 0
    for k in range(0, len(data), 5):
        d_line, d_start, length, kind, _ = data[k : k + 5]
        line += d_line
        column = column + d_start if d_line == 0 else d_start
        out.append((lines[line][column : column + length], legend.token_types[kind]))
    return out


async def test_semantic_tokens_colour_every_installed_domains_words(client):
    """Words of a plugin's vocabulary (PHYRE's touch, greenObject, blueBall) are coloured too."""
    legend = client.capabilities.semantic_tokens_provider.legend
    phyre = (Path(__file__).resolve().parents[2] / "plugins" / "physc-phyre" / "examples" / "phyre" / "task00000.phys").read_text()
    open_document(client, URI, phyre)
    found = await client.text_document_semantic_tokens_full_async(types.SemanticTokensParams(text_document=document(URI)))
    words = _decoded(found.data, phyre, legend)
    assert ("phyre", "namespace") in words and ("greenObject", "type") in words and ("blueBall", "class") in words
    assert ("touch", "function") in words and ("roll", "function") in words and ("above", "enumMember") in words
    assert ("green", "variable") in words
    open_document(client, "file:///work/objects.phys", DECLARED)
    found = await client.text_document_semantic_tokens_full_async(types.SemanticTokensParams(text_document=document("file:///work/objects.phys")))
    words = _decoded(found.data, DECLARED, legend)
    assert ("rollableBlock", "type") in words and ("hit", "function") in words and ("cannotHit", "function") in words
