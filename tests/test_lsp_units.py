"""The language server's parts in-process: positions, the cursor's place, completion, hover, and
the quick fixes that the static checks attach (every one removes its diagnostic)."""

from __future__ import annotations

import json
import sys

import pytest
from hypothesis import given
from hypothesis import strategies as st
from lsprotocol import types

from conftest import EXAMPLES, run_physc
from physc.diagnostics import SourceText
from physc.dsl.frontend import analyze_text
from physc.lsp import context
from physc.lsp.completion import complete
from physc.lsp.hover import hover_text
from physc.lsp.positions import Positions
from strategies import PHYS_PIECES, mutate_text
from test_fuzz import PHYS_CORPUS, fuzz, randoms

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
    positions = Positions(SourceText("x", text))
    assert positions.position(text.index("b")) == types.Position(line=0, character=3)  # 😀 is two units
    assert positions.offset(types.Position(line=0, character=3)) == text.index("b")
    assert positions.offset(types.Position(line=1, character=2)) == text.index("\r")
    assert positions.offset(types.Position(line=0, character=99)) == text.index("\n")  # past the line's end
    assert positions.offset(types.Position(line=99, character=0)) == len(text)  # past the document's
    utf8 = Positions(SourceText("x", text), types.PositionEncodingKind.Utf8)
    assert utf8.position(text.index("b")) == types.Position(line=0, character=5)
    lone = Positions(SourceText("x", "\ud800x"))
    assert lone.position(1) == types.Position(line=0, character=1)  # a lone surrogate is one unit


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
    assert labels("scenario S { restrictions { § } }") == ["cannotHit", "cannotFall"]
    assert labels("scenario S { objects { p: pig = § } }") == ["pigSmall", "pigMedium"]
    assert labels("scenario S { domain nowhere\n interactions { hit(§ } }") == []  # unknown domain: nothing
    assert labels("scenario S { interactions { nothing(§ } }") == []
    assert labels("scenario S { interactions { hit(a, b, c, d, § } }") == []


def test_completion_in_the_phyre_domain():
    found = labels("scenario S { domain phyre\n interactions { § } }")
    assert "touch" in found and "destroy" not in found


def test_hover_explains_a_diagnostic_with_docs_errors_md():
    text = "scenario SF {\n    interactions {\n        hit(bird, pig, any)\n        > destory(bird, pig)\n    }\n}\n"
    analysis = analyze_text("x.phys", text)
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


@pytest.mark.parametrize("path", BROKEN, ids=[p.stem for p in BROKEN])
def test_every_quick_fix_removes_its_diagnostic(path):
    text = path.read_bytes().decode("utf-8", "replace")
    for diagnostic in analyze_text(path.name, text).diagnostics:
        for fix in diagnostic.fixes:
            after = analyze_text(path.name, applied(text, fix)).diagnostics
            assert (diagnostic.code, diagnostic.message) not in {(d.code, d.message) for d in after}, fix.title


def test_quick_fixes_where_a_help_proposes_a_change():
    """The codes whose broken example has a fix; a misspelt object is renamed at every use."""
    fixed = {p.stem[:5] for p in BROKEN if any(d.fixes for d in analyze_text(p.name, p.read_bytes().decode("utf-8", "replace")).diagnostics)}
    assert {"E0201", "E0203", "E0301", "E0302", "E0303", "E0206", "E0401", "E0402", "E0403", "E0404", "E0701"} <= fixed
    text = (EXAMPLES / "errors" / "E0301_unknown_object.phys").read_text()
    (diagnostic,) = analyze_text("x", text).diagnostics
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
    assert "pip install 'physc[lsp]'" in run.stderr and "Traceback" not in run.stderr


# ---- fuzzing: no input and no offset makes the editor features fail ------------------------------
@fuzz(300)
@given(randoms, st.sampled_from(PHYS_CORPUS))
def test_mutated_files_at_random_places(rng, text):
    text = mutate_text(rng, text, PHYS_PIECES, PHYS_CORPUS)
    analysis = analyze_text("fuzz.phys", text)
    for _ in range(3):
        offset = rng.randint(0, len(text))
        found = context.locate(text, offset)
        complete(found, snippets=True)
        hover_text(context.locate(text, min(offset + 1, len(text))), analysis.diagnostics[:2])
        positions = Positions(analysis.source) if analysis.source else None
        if positions is not None:
            assert positions.offset(positions.position(offset)) == offset
