"""Parsing: the two scenario forms, the paper's own table (golden AST dumps: test_golden_stages.py)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import EXAMPLES

from physc.dsl import ast
from physc.dsl.parser import parse_text

BLOCK_FILES = sorted((EXAMPLES / "paper").glob("[0-9][0-9]_*.phys"))


def parse_file(path):
    result = parse_text(path.read_text(encoding="utf-8"), str(path))
    assert result.diagnostics == ()
    return result.file


def test_sixteen_paper_scenarios_in_block_form():
    assert len(BLOCK_FILES) == 16
    for number, path in enumerate(BLOCK_FILES, 1):
        (scenario,) = parse_file(path).scenarios
        assert path.name == f"{number:02d}_{scenario.name.text}.phys"
        assert scenario.form == "block"


def test_paper_form_equals_block_form():
    paper = parse_file(EXAMPLES / "paper" / "all.paper.phys").scenarios
    block = tuple(parse_file(p).scenarios[0] for p in BLOCK_FILES)
    assert [s.form for s in paper] == ["paper"] * 16
    assert paper == block
    for p, b in zip(paper, block):  # equal modulo positions, not by accident
        assert p.interactions[0].span != b.interactions[0].span


def _interaction_counts():
    return [len(s.interactions) for s in parse_file(EXAMPLES / "paper" / "all.paper.phys").scenarios]


def test_interaction_counts_match_the_paper_grouping():
    # The paper: scenarios 1-3 have two interactions, 4-7 four, 8-12 six, 13-16 eight.
    assert _interaction_counts() == [2] * 3 + [4] * 4 + [6] * 5 + [8] * 4


def _paper_table_rows() -> list[tuple[str, str]]:
    """The scenario definitions exactly as the paper's LaTeX table prints them."""
    # The table as the paper's LaTeX source has it (tests/data/paper: copied, with a header).
    tex = (Path(__file__).parents[1] / "data" / "paper" / "scenario_table.tex").read_text(encoding="utf-8")
    table = tex[tex.index("Name & Scenario Definition") :]
    rows = []
    for chunk in table.split(r"\midrule")[1:]:
        text = re.sub(r"\\textit\{([^}]*)\}", r"\1", chunk)
        for latex, plain in [(r"$>$", ">"), (r"$\vee$", "∨"), (r"$\wedge$", "∧"), (r"\{", "{"), (r"\}", "}")]:
            text = text.replace(latex, plain)
        text = text.replace("\\\\", " ").replace("&", " ")
        match = re.match(r"\s*(\d+)\.\s+(\w+)\s+(.*)", text, re.S)
        rows.append((match.group(2), " ".join(match.group(3).split())))
    return rows


def test_examples_match_the_paper_table_term_by_term():
    rows = _paper_table_rows()
    ours = parse_file(EXAMPLES / "paper" / "all.paper.phys").scenarios
    assert [name for name, _ in rows] == [s.name.text for s in ours]
    for (name, definition), scenario in zip(rows, ours):
        (theirs,) = parse_file_text(f"scenario {name} = {definition}").scenarios
        assert theirs.interactions == scenario.interactions, name
        assert theirs.restrictions == scenario.restrictions, name


def parse_file_text(text):
    result = parse_text(text)
    assert result.diagnostics == (), result.diagnostics
    return result.file


def test_spans_point_at_the_source():
    text = "scenario SF {\n    interactions { hit(bird, pig, any) > destroy(bird, pig) }\n}\n"
    (scenario,) = parse_file_text(text).scenarios
    hit = scenario.interactions[0]
    assert (hit.span.line, hit.span.column, hit.span.end_column) == (2, 20, 39)
    assert text[hit.span.start : hit.span.end] == "hit(bird, pig, any)"
    pig = hit.arguments[1].alternatives[0]
    assert text[pig.span.start : pig.span.end] == "pig"
    assert scenario.span.start == 0 and scenario.span.end == len(text) - 1


def test_curried_call_and_bracketed_forms_are_equal():
    forms = ["hit(bird, pig, left | above)", "hit(bird)(pig)(left ∨ above)", "[[hit(bird)(pig, left or above)]]"]
    terms = [parse_file_text(f"scenario X {{ interactions {{ {f} }} }}").scenarios[0].interactions for f in forms]
    assert terms[0] == terms[1] == terms[2]


@pytest.mark.parametrize("separator", [",", " and ", " & ", " ∧ ", "\n"])
def test_restriction_separators(separator):
    text = f"scenario X {{ interactions {{ hit(bird, pig, any) }} restrictions {{ a(x){separator}b(y) }} }}"
    (scenario,) = parse_file_text(text).scenarios
    assert [t.name.text for t in scenario.restrictions] == ["a", "b"]


def test_sections_in_any_order_and_empty_restrictions_equal_absent():
    a = parse_file_text("scenario X { restrictions { } interactions { h(b) } domain d }").scenarios[0]
    b = parse_file_text("scenario X { domain d interactions { h(b) } }").scenarios[0]
    c = parse_file_text("scenario X = {h(b)}, {}").scenarios[0]
    assert a == b
    assert c == ast.Scenario(name=ast.Name("X"), interactions=b.interactions)


def test_title_escapes():
    (scenario,) = parse_file_text(r'scenario X "a \"b\" \\ c" = {h(b)}, {}').scenarios
    assert scenario.title.value == 'a "b" \\ c'


def test_a_syntax_error_costs_one_scenario_only():
    text = (
        "scenario A = {hit(bird)(pig)(any) > destroy(bird)(pig)}, {}\n"
        "scenario B { interactions { hit(bird pig) } }\n"
        "scenario C = {hit(bird)(pig)(any) > destroy(bird)(pig)}, {}\n"
        "scenario D { interactions { hit(bird, pig, any) }\n"
        "scenario E = {hit(bird)(pig)(any) > destroy(bird)(pig)}, {}\n"
    )
    result = parse_text(text)
    assert [s.name.text for s in result.file.scenarios] == ["A", "C", "E"]
    assert [(d.code, d.span.line) for d in result.diagnostics] == [("E0102", 2), ("E0103", 4)]
