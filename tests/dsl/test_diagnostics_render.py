"""Rendered diagnostics are safe to print: control characters escaped, long lines cut around the caret."""

from __future__ import annotations

import json
import re
import unicodedata

from hypothesis import given, settings
from hypothesis import strategies as st

from physc.diagnostics import MAX_COLUMNS, Diagnostic, Label, SourceText, render, safe

# What a terminal would act on: C0 controls but tab and newline, DEL, C1 controls, bidi controls.
TERMINAL_CONTROLS = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


def rendered(text: str, start: int, end: int, path: str = "x.phys", **fields) -> list[str]:
    source = SourceText(path, text)
    diagnostic = Diagnostic(fields.pop("code", "E0201"), fields.pop("message", "a message"), source.span(start, end), **fields)
    return render(diagnostic, source, path).split("\n")


def caret_column(lines: list[str]) -> int:
    return lines[2].index("^")


def test_escape_sequences_in_the_source_are_shown_escaped_and_the_caret_stays_aligned():
    text = "scenario X { interactions { \x1b[31mhit(bird, pig, any) } }"
    start = text.index("hit")
    lines = rendered(text, start, start + 3)
    assert "\x1b" not in "\n".join(lines)
    assert lines[1] == "    1 | scenario X { interactions { \\x1b[31mhit(bird, pig, any) } }"
    assert caret_column(lines) == lines[1].index("hit") and lines[2].endswith("^^^")
    escape = text.index("\x1b")
    lines = rendered(text, escape, escape + 1)
    assert caret_column(lines) == lines[1].index("\\x1b") and lines[2].endswith("^" * len("\\x1b"))


def test_every_kind_of_terminal_control_is_escaped():
    for char, shown in [("\x07", "\\x07"), ("\x7f", "\\x7f"), ("\x9b", "\\x9b"), ("\u202e", "\\u202e"), ("\u2028", "\\u2028"), ("\r", "\\x0d")]:
        text = f"hit(bird,{char} pig)"
        lines = rendered(text, text.index("pig"), text.index("pig") + 3)
        assert shown in lines[1] and not TERMINAL_CONTROLS.search("\n".join(lines)), char
        assert caret_column(lines) == lines[1].index("pig")


def test_tabs_and_wide_characters_keep_the_caret_aligned():
    lines = rendered("\thit(\tbird)", 6, 10)
    assert lines[1] == "    1 | \thit(\tbird)"
    assert lines[2] == "      | \t    \t^^^^"
    lines = rendered("猪猪 hit", 3, 6)  # two double-width characters and a space: five columns
    assert lines[2] == "      |      ^^^"


def test_a_crlf_line_ending_is_not_shown():
    lines = rendered("hit(bird)\r\nnext", 0, 3)
    assert lines[1] == "    1 | hit(bird)"


def test_paths_messages_help_and_notes_are_escaped():
    source = SourceText("a\x1b]0;title\x07.phys", "hit(bird)\n")
    diagnostic = Diagnostic(
        "E0201",
        "unknown type '\x1b[2J'\nsecond line",
        source.span(0, 3),
        help="try \u202eevil",
        notes=(Label(source.span(4, 8), "note \x9b"),),
    )
    text = render(diagnostic, source, source.path)
    assert not TERMINAL_CONTROLS.search(text)
    assert text.startswith("a\\x1b]0;title\\x07.phys:1:1: error[E0201]: unknown type '\\x1b[2J'\nsecond line")
    assert "help: try \\u202eevil" in text and "note \\x9b (a\\x1b]0;title\\x07.phys:1:5)" in text


def test_a_long_line_is_cut_around_the_caret():
    text = "hit(bird, pig, any) > " * 5000 + "hti(bird, pig)" + " > hit(bird, pig, any)" * 5000
    start = text.index("hti")
    lines = rendered(text, start, start + 3)
    assert len("\n".join(lines)) < 600
    shown = lines[1][len("    1 | ") :]
    assert shown.startswith("…") and shown.endswith("…") and len(shown) <= MAX_COLUMNS
    assert caret_column(lines) == lines[1].index("hti") and lines[2].endswith("^^^")


def test_a_cut_line_shows_more_on_the_side_that_has_more():
    text = "x" * 5000 + "END"
    lines = rendered(text, 5000, 5003)
    assert lines[1].endswith("xxxEND") and lines[1][8] == "…" and len(lines[1]) - 8 == MAX_COLUMNS - 1
    lines = rendered(text, 0, 1)
    assert lines[1].startswith("    1 | xxx") and lines[1].endswith("…") and caret_column(lines) == 8


def test_a_long_caret_is_cut_with_its_line():
    text = "a" * 10 + "b" * 10_000
    lines = rendered(text, 10, 10_010)
    assert len(lines[2]) < 2 * MAX_COLUMNS and lines[1].endswith("…")


def test_a_long_name_in_a_message_is_cut_in_its_middle():
    name = "n" * 100_000
    lines = rendered(name, 0, len(name), message=f"unknown object '{name}'", help=f"declare {name}")
    assert sum(map(len, lines)) < 1000 and "…" in lines[0] and "…" in lines[-1]


def test_json_keeps_the_exact_text(tmp_path, physc):
    path = tmp_path / "e\x1bvil.phys"
    path.write_text("scenario X { interactions { hit(bird, pig, any) > destroy(bird, \x1b[31mpig) } }", encoding="utf-8")
    run = physc("check", "--format", "json", path)
    (found,) = json.loads(run.stdout)
    assert found["file"] == str(path) and found["message"] == "unexpected character '\\x1b' (U+001B)"
    text = physc("check", "--color", "never", path).stderr
    assert "\x1b" not in text and "e\\x1bvil.phys" in text


def test_safe_keeps_newlines_only_when_asked():
    assert safe("a\nb\x1b") == "a\\x0ab\\x1b"
    assert safe("a\nb\x1b", newlines=True) == "a\nb\\x1b"


def _blank(shown: str) -> str:
    """What the caret line holds under `shown`: tabs kept, every other character as many spaces as
    the columns it takes (none for a combining mark, two for a wide one)."""
    out = []
    for char in shown:
        if char == "\t":
            out.append(char)
        elif not unicodedata.combining(char):
            out.append("  " if unicodedata.east_asian_width(char) in "WF" else " ")
    return "".join(out)


plain_text = st.text(st.characters(blacklist_characters="\n§"), max_size=300)


@settings(max_examples=300, deadline=None, derandomize=True, database=None)
@given(plain_text, plain_text, plain_text)
def test_any_line_renders_safely_and_aligned(before, middle, after):
    line = before + "§" + middle + after
    lines = rendered(line, len(before), len(before) + 1 + len(middle))
    assert not TERMINAL_CONTROLS.search("\n".join(lines))
    shown = lines[1][8:]
    assert len(shown) <= 4 * MAX_COLUMNS  # escaped characters count for more
    # The caret starts under the marked character, however many columns those before it take.
    assert lines[2][8:] == _blank(shown[: shown.index("§")]) + lines[2][8:].lstrip(" \t")
    assert lines[2][8:].lstrip(" \t").startswith("^")
