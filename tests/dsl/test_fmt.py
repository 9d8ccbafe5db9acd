"""The formatter: canonical, idempotent, faithful to the tree, keeps comments."""

from __future__ import annotations

from conftest import EXAMPLES
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from strategies import files, written

from physc.dsl.fmt import format_file
from physc.dsl.parser import parse_text


def fmt(text: str) -> str:
    result = parse_text(text)
    assert result.diagnostics == (), (text, result.diagnostics)
    return format_file(result.file, result.source)


@settings(max_examples=100, deadline=None)
@given(files)
def test_parse_of_fmt_is_the_tree(file):
    text = format_file(file)
    result = parse_text(text)
    assert result.diagnostics == ()
    assert result.file == file
    assert fmt(text) == text


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data())
def test_fmt_is_idempotent_and_keeps_comments(data):
    file = data.draw(files)
    source = data.draw(written(file))
    parsed = parse_text(source)
    assert parsed.diagnostics == (), source
    assert parsed.file == file
    once = fmt(source)
    assert fmt(once) == once
    again = parse_text(once)
    assert again.file == file
    # Comments travel with the syntax they annotate, so reordered sections may
    # reorder them; none may be lost or duplicated.
    assert sorted(c.text for c in again.file.comments) == sorted(c.text for c in parsed.file.comments)


def test_examples_are_canonical():
    for path in sorted((EXAMPLES / "paper").glob("[0-9]*.phys")) + [EXAMPLES / "objects.phys"]:
        text = path.read_text(encoding="utf-8")
        assert fmt(text) == text, path.name


def test_paper_form_becomes_block_form():
    out = fmt('scenario SFTB "Top" = {[hit(bird)(pig)(any)] > [destroy(bird)(pig)]}, {[cannotHit(bird)(pig)(above)]}\n')
    assert out == (
        'scenario SFTB "Top" {\n'
        "    interactions {\n"
        "        hit(bird, pig, any)\n"
        "        > destroy(bird, pig)\n"
        "    }\n"
        "\n"
        "    restrictions {\n"
        "        cannotHit(bird, pig, above)\n"
        "    }\n"
        "}\n"
    )


def test_comment_placement():
    source = (
        "# header\n"
        "\n"
        "scenario X { # after brace\n"
        "  restrictions { cannotHit(bird, pig, above) }\n"
        "  interactions {\n"
        "    # before hit\n"
        "    hit(bird, pig, any) >  // after hit\n"
        "    destroy(bird, pig)\n"
        "    # before closing\n"
        "  }\n"
        "} # after scenario\n"
        "# tail\n"
    )
    assert fmt(source) == (
        "# header\n"
        "\n"
        "scenario X {  # after brace\n"
        "    interactions {\n"
        "        # before hit\n"
        "        hit(bird, pig, any)  // after hit\n"
        "        > destroy(bird, pig)\n"
        "        # before closing\n"
        "    }\n"
        "\n"
        "    restrictions {\n"
        "        cannotHit(bird, pig, above)\n"
        "    }\n"
        "}  # after scenario\n"
        "# tail\n"
    )
