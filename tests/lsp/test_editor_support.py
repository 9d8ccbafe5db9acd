"""Editor support: the TextMate grammar and the Pygments lexer follow the vocabulary."""

from __future__ import annotations

import json
import re
import subprocess
import sys

import pytest
from conftest import EXAMPLES, ROOT
from pygments.lexers import get_lexer_by_name, get_lexer_for_filename
from pygments.token import Error, Name

from physc.domains.angrybirds.vocabulary import VOCABULARY

GRAMMAR = json.loads((ROOT / "grammar" / "syntaxes" / "phys.tmLanguage.json").read_text(encoding="utf-8"))


def word_list(entry: str) -> list[str]:
    match = GRAMMAR["repository"][entry]["match"]
    return re.search(r"\(\?:([^)]*)\)", match).group(1).split("|")


def test_textmate_term_lists_equal_the_vocabulary():
    assert word_list("interaction-terms") == [t.name for t in VOCABULARY.terms if t.kind == "interaction"]
    assert word_list("restriction-terms") == [t.name for t in VOCABULARY.terms if t.kind == "restriction"]
    assert word_list("object-terms") == [s for t in VOCABULARY.object_terms for s in t.spellings]
    assert word_list("concrete-objects") == [c.name for c in VOCABULARY.concrete_objects]
    assert word_list("directions") == list(VOCABULARY.directions)
    assert word_list("materials") == list(dict.fromkeys(m for c in VOCABULARY.concrete_objects for m in c.materials))


def test_textmate_keywords_are_the_language_keywords():
    grammar_text = json.dumps(GRAMMAR)
    for keyword in ("scenario", "domain", "objects", "interactions", "restrictions", "and", "or"):
        assert keyword in grammar_text


def test_vscode_manifest_points_at_the_grammar():
    manifest = json.loads((ROOT / "grammar" / "package.json").read_text())
    (grammar,) = manifest["contributes"]["grammars"]
    assert (ROOT / "grammar" / grammar["path"]).exists()
    assert grammar["scopeName"] == GRAMMAR["scopeName"] == "source.phys"
    assert manifest["contributes"]["languages"][0]["extensions"] == [".phys"]


def test_pygments_finds_the_lexer_through_its_entry_point():
    assert type(get_lexer_by_name("phys")).__name__ == "PhysLexer"
    assert type(get_lexer_for_filename("x.phys")).__name__ == "PhysLexer"


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("**/*.phys")), ids=lambda p: p.name)
def test_pygments_lexes_every_example_without_errors(path):
    text = path.read_bytes().decode("utf-8", "replace")
    tokens = list(get_lexer_by_name("phys").get_tokens(text))
    assert "".join(value for _, value in tokens).rstrip("\n") == text.rstrip("\n")
    assert not [value for kind, value in tokens if kind in Error]


def test_pygments_token_kinds():
    tokens = dict(
        (value, kind)
        for kind, value in get_lexer_by_name("phys").get_tokens("hit(rBlock2, circle, left) > cannotFall(x)")
    )
    assert tokens["hit"] is Name.Function
    assert tokens["rBlock2"] is Name.Builtin
    assert tokens["circle"] is Name.Builtin.Pseudo
    assert tokens["left"] is Name.Constant
    assert tokens["cannotFall"] is Name.Function.Magic
    assert tokens["x"] is Name.Variable


def test_pygmentize_command():
    # The pygmentize of this interpreter's environment, where physc registered its lexer (the
    # first one on PATH may belong to another Python).
    run = subprocess.run(
        [sys.executable, "-m", "pygments", "-l", "phys", "-f", "html", str(EXAMPLES / "paper" / "08_RF.phys")],
        capture_output=True,
        text=True,
    )
    assert run.returncode == 0 and 'class="nf">roll<' in run.stdout


def test_pygments_knows_every_installed_domains_words():
    text = (ROOT / "plugins" / "physc-phyre" / "examples" / "phyre" / "task00000.phys").read_text()
    tokens = dict((value, kind) for kind, value in get_lexer_by_name("phys").get_tokens(text))
    assert tokens["touch"] is Name.Function and tokens["greenObject"] is Name.Builtin and tokens["blueBall"] is Name.Builtin.Pseudo


def test_pygments_guesses_phys_from_the_text():
    from pygments.lexers import guess_lexer

    for path in (EXAMPLES / "paper" / "05_F.phys", ROOT / "plugins" / "physc-phyre" / "examples" / "phyre" / "task00002.phys"):
        assert type(guess_lexer(path.read_text())).__name__ == "PhysLexer", path
    assert type(guess_lexer("hit(bird, pig, any) > destroy(bird, pig)\n")).__name__ == "PhysLexer"
    assert type(guess_lexer("def f(x):\n    return x > 1\n")).__name__ != "PhysLexer"


def test_the_extension_carries_physcs_license():
    assert (ROOT / "grammar" / "LICENSE").read_text() == (ROOT / "LICENSE").read_text()


def test_the_lexers_guess_is_linear_on_long_calls():
    """analyse_text runs on any text a Pygments user guesses: a call with many arguments over
    many lines must not make its patterns backtrack (it did, exponentially, before)."""
    from physc.lsp.pygments_lexer import PhysLexer

    call = "result = compute(" + ",\n   ".join(f"arg{i}" for i in range(40)) + "\n"
    assert PhysLexer.analyse_text(call) == 0.0
    assert PhysLexer.analyse_text("\n" * 40_000 + "x") == 0.0
