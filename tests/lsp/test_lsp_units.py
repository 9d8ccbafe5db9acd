"""The language server's parts in-process: positions, the cursor's place, completion, hover, and
the quick fixes that the static checks attach (every one removes its diagnostic)."""

from __future__ import annotations

import json
import sys

import pytest
from conftest import EXAMPLES, run_physc
from hypothesis import given
from hypothesis import strategies as st
from lsprotocol import types
from strategies import PHYS_CORPUS, PHYS_PIECES, fuzz, mutate_text, randoms

from physc.domains.words import INSTALLED
from physc.dsl.frontend import analyze_text
from physc.lsp import context
from physc.lsp.completion import complete
from physc.lsp.hover import hover_text
from physc.lsp.positions import Positions

OBJECTS = (EXAMPLES / "objects.phys").read_text()


def place(text: str, marker: str = "§") -> context.Place:
    """The place of `marker` in `text` (the marker removed)."""
    offset = text.index(marker)
    return context.locate(text.replace(marker, "", 1), offset)


def labels(text: str) -> list[str]:
    return [item.label for item in complete(place(text), snippets=False)]


# ---- positions ---------------------------------------------------------------------------------
def test_positions_count_utf16_units_and_clamp():
    text = "a😀b\ncé\r\nend"
    positions = Positions(text)
    assert positions.position(text.index("b")) == types.Position(line=0, character=3)  # 😀 is two units
    assert positions.offset(types.Position(line=0, character=3)) == text.index("b")
    assert positions.offset(types.Position(line=1, character=2)) == text.index("\r")
    assert positions.offset(types.Position(line=0, character=99)) == text.index("\n")  # past the line's end
    assert positions.offset(types.Position(line=99, character=0)) == len(text)  # past the document's
    utf8 = Positions(text, types.PositionEncodingKind.Utf8)
    assert utf8.position(text.index("b")) == types.Position(line=0, character=5)
    lone = Positions("\ud800x")
    assert lone.position(1) == types.Position(line=0, character=1)  # a lone surrogate is one unit


def test_lines_end_as_the_protocol_says():
    """At \n, \r\n and \r; not at the other breaks that Python's splitlines knows."""
    text = "a\rb\r\nc\u2028d\x0ce\nf"
    positions = Positions(text)
    assert [positions.position(text.index(c)).line for c in "abcdef"] == [0, 1, 2, 2, 2, 3]
    assert positions.offset(types.Position(line=2, character=2)) == text.index("d")


# ---- the place of the cursor --------------------------------------------------------------------
def test_place_in_block_and_paper_forms():
    found = place("scenario S { interactions { hit(bird, §) } }")
    assert (found.role, found.term, found.argument, found.section) == (context.ARGUMENT, "hit", 1, "interactions")
    found = place("scenario S = {[hit(bird)(pig)(§)]}, {}")
    assert (found.role, found.term, found.argument) == (context.ARGUMENT, "hit", 2)
    assert place("scenario S = {[hit(bird)(pig)(any)]}, {§}").section == "restrictions"
    assert place("scenario S { objects { r: § } }").role == context.OBJECT_TERM
    found = place("scenario S { objects { r: rollableBlock = circle | § } }")
    assert (found.role, found.object_term) == (context.CONCRETE, "rollableBlock")
    assert place("scenario S { domain § }").role == context.DOMAIN
    assert place("scenario S { § }").role == context.BODY
    assert place("# scenario in a comment\n§").role == context.TOP
    found = place('scenario S "scenario" {\n  domain phyre\n  interactions { § }\n}\nscenario T { }')
    assert (found.role, found.domain) == (context.TERM, "phyre")


def test_place_collects_the_scenarios_names():
    found = place(OBJECTS.replace("> hit(rBlock, fBlock", "> hit(rB§lock, fBlock"))
    assert found.declared == {"rBlock": "rollableBlock", "pig": "pig"}
    assert found.narrowed == {"rBlock": ["circle"], "pig": ["pigMedium", "pigSmall"]}
    assert {"bird", "rBlock", "surface", "fBlock", "pig"} <= set(found.arguments)  # directions too: completion filters
    assert found.word.text == "rBlock"


# ---- completion and hover -----------------------------------------------------------------------
def test_completion_offers_what_fits_the_parameter():
    assert labels("scenario S { interactions { roll(rBlock, surface, § } }") == ["left", "right"]
    after_hit = labels("scenario S { interactions { hit(§ } }")
    assert "bird" in after_hit and "surface" not in after_hit  # the actor moves; a surface never does
    rolling = labels("scenario S { interactions { hit(bird, fBlock, left) > roll(§ } }")
    assert "rBlock" in rolling and "fBlock" not in rolling  # roll's object is rollable
    assert labels("scenario S { restrictions { § } }") == ["cannotHit", "cannotFall", "contrast", "on", "nonGreedy", "blocks", "timed"]
    assert labels("scenario S { objects { p: pig = § } }") == ["pigSmall", "pigMedium", "pigBig"]  # pigBig: pinned only (version 2)
    assert labels("scenario S { domain nowhere\n interactions { hit(§ } }") == []  # unknown domain: nothing
    assert labels("scenario S { interactions { nothing(§ } }") == []
    assert labels("scenario S { interactions { hit(a, b, c, d, § } }") == []


def test_completion_of_version_2_declarations():
    assert labels("scenario S { objects { f: fallableBlock(§ } }") == ["wood", "stone", "ice"]
    assert labels("scenario S { objects { f: fallableBlock(stone | § } }") == ["wood", "stone", "ice"]
    pinned = labels("scenario S { objects { f: fallableBlock(stone) = § } }")
    assert "rectFat" in pinned and "circle" in pinned and "pigBig" not in pinned
    exploding = labels("scenario S { interactions { hit(bird, tnt, left) > explode(§ } }")
    assert "tnt" in exploding and "pig" not in exploding  # explode's object is a TNT box
    assert "explode" in labels("scenario S { interactions { § } }")


def test_completion_in_the_phyre_domain():
    found = labels("scenario S { domain phyre\n interactions { § } }")
    assert "touch" in found and "destroy" not in found


def test_every_code_has_its_explanation_shipped():
    """physc/errors.md (a link to docs/errors.md, shipped as package data) explains every code."""
    from physc import error_codes

    assert [code for code in error_codes.CODES if not error_codes.explanation(code)] == []


def test_hover_explains_a_diagnostic_with_docs_errors_md():
    text = "scenario SF {\n    interactions {\n        hit(bird, pig, any)\n        > destory(bird, pig)\n    }\n}\n"
    analysis = analyze_text("x.phys", text, INSTALLED)
    offset = text.index("destory") + 2
    shown = hover_text(context.locate(text, offset + 1), [d for d in analysis.diagnostics if d.span.start <= offset <= d.span.end])
    assert shown.startswith("**error[E0201]**: unknown interaction term 'destory'")
    assert "help: did you mean 'destroy'?" in shown
    assert "## E0201: a term that the domain does not define" in shown


# ---- quick fixes --------------------------------------------------------------------------------
def applied(text: str, fix) -> str:
    for edit in sorted(fix.edits, key=lambda e: e.span.start, reverse=True):
        text = text[: edit.span.start] + edit.text + text[edit.span.end :]
    return text


BROKEN = sorted((EXAMPLES / "errors").glob("*.phys"))


# The paper form, and terms in brackets, where a fix that inserts a term must write it in brackets.
BRACKETED = [
    "scenario X = {[hit(bird)(pig)(left)]}, {}",
    "scenario X = {[roll(rBlock)(surface)(left)] > [hit(rBlock)(pig)(left)] > [destroy(rBlock)(pig)]}, {}",
    "scenario X = {[hit(bird)(pig)(left)] > [destroy(bird)(pig)] > [destroy(fBlock)(pig)]}, {}",
    "scenario X = {[hit(bird)(pig)(left)] > [hit(fBlock)(pig)(left)] > [destroy(fBlock)(pig)]}, {}",
    "scenario X { interactions { [hit(bird, pig, left)] } }",
    "scenario X { interactions { hit(bird, rBlok, left) > roll(rBlok, surface, left, x) > destroy(rBlok, pig) } }",
]
FIXABLE = [p.read_bytes().decode("utf-8", "replace") for p in BROKEN] + BRACKETED


@pytest.mark.parametrize("text", FIXABLE, ids=[p.stem for p in BROKEN] + [f"bracketed{n}" for n in range(len(BRACKETED))])
def test_every_quick_fix_removes_its_diagnostic(text):
    """A fix takes its diagnostic away and never breaks the syntax (a syntax error would hide every
    other diagnostic)."""
    before = analyze_text("x.phys", text, INSTALLED)
    for diagnostic in before.diagnostics:
        for fix in diagnostic.fixes:
            after = analyze_text("x.phys", applied(text, fix), INSTALLED)
            assert [d.code for d in after.syntax] == [d.code for d in before.syntax], fix.title
            assert (diagnostic.code, diagnostic.message) not in {(d.code, d.message) for d in after.diagnostics}, fix.title


def test_inserted_terms_follow_their_neighbours_brackets():
    (diagnostic,) = analyze_text("x", BRACKETED[0], INSTALLED).diagnostics
    assert applied(BRACKETED[0], diagnostic.fixes[0]) == "scenario X = {[hit(bird)(pig)(left)] > [destroy(bird, pig)]}, {}"
    (diagnostic,) = analyze_text("x", BRACKETED[1], INSTALLED).diagnostics
    assert applied(BRACKETED[1], diagnostic.fixes[0]).startswith("scenario X = {[hit(bird, rBlock, left)] > [roll(")
    text = BRACKETED[5]
    renamed = applied(text, analyze_text("x", text, INSTALLED).diagnostics[0].fixes[0])  # every use, the broken term's too
    assert "rBlok" not in renamed


def test_quick_fixes_where_a_help_proposes_a_change():
    """The codes whose broken example has a fix; a misspelt object is renamed at every use."""
    fixed = {p.stem[:5] for p in BROKEN if any(d.fixes for d in analyze_text(p.name, p.read_bytes().decode("utf-8", "replace"), INSTALLED).diagnostics)}
    assert {"E0201", "E0203", "E0301", "E0302", "E0303", "E0206", "E0401", "E0402", "E0403", "E0404", "E0701"} <= fixed
    text = (EXAMPLES / "errors" / "E0301_unknown_object.phys").read_text()
    (diagnostic,) = analyze_text("x", text, INSTALLED).diagnostics
    assert "rBlok" not in applied(text, diagnostic.fixes[0]) and len(diagnostic.fixes[0].edits) == 3


def test_check_json_lists_the_fixes():
    run = run_physc("check", "--format", "json", EXAMPLES / "errors" / "E0201_unknown_term.phys")
    (found,) = json.loads(run.stdout)
    assert found["fixes"] == [
        {"title": "change 'destory' to 'destroy'", "edits": [{"text": "destroy", "line": 5, "column": 11, "end_line": 5, "end_column": 18}]}
    ]


# ---- the command ----------------------------------------------------------------------------------
def test_lsp_without_pygls_is_a_usage_error(monkeypatch):
    monkeypatch.setitem(sys.modules, "pygls.lsp.server", None)
    monkeypatch.delitem(sys.modules, "physc.lsp.server", raising=False)
    run = run_physc("lsp")
    assert run.status == 2
    assert "pip install -e '.[lsp]'" in run.stderr and "Traceback" not in run.stderr


# ---- fuzzing: no input and no offset makes the editor features fail ------------------------------
@fuzz(300)
@given(randoms, st.sampled_from(PHYS_CORPUS))
def test_mutated_files_at_random_places(rng, text):
    text = mutate_text(rng, text, PHYS_PIECES, PHYS_CORPUS)
    analysis = analyze_text("fuzz.phys", text, INSTALLED)
    for _ in range(3):
        offset = rng.randint(0, len(text))
        found = context.locate(text, offset)
        complete(found, snippets=True)
        hover_text(context.locate(text, min(offset + 1, len(text))), analysis.diagnostics[:2])
        positions = Positions(text)
        if text[offset - 1 : offset + 1] != "\r\n":  # not between the two characters of one line break
            assert positions.offset(positions.position(offset)) == offset
