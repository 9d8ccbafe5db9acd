"""Malformed input of every kind gives diagnostics, never a traceback."""

from __future__ import annotations

import io
import os

from hypothesis import given, settings
from hypothesis import strategies as st

from physc.domains.words import INSTALLED
from physc.dsl.check import check_file
from physc.dsl.parser import parse_text


def test_empty_file(tmp_path, physc):
    path = tmp_path / "empty.phys"
    path.write_text("")
    run = physc("check", path)
    assert run.status == 1 and "error[E0003]" in run.stderr


def test_non_utf8(tmp_path, physc):
    path = tmp_path / "latin1.phys"
    path.write_bytes(b"scenario X = {hit(bird)(pig)(any)}, {} # caf\xe9\n")
    run = physc("check", path)
    assert run.status == 1 and f"{path}:1:45: error[E0002]" in run.stderr


def test_random_bytes(tmp_path, physc):
    path = tmp_path / "noise.phys"
    path.write_bytes(bytes(range(256)) * 4)
    run = physc("check", path)
    assert run.status == 1 and "error[E0002]" in run.stderr and "Traceback" not in run.stderr


def test_directory(tmp_path, physc):
    run = physc("check", tmp_path)
    assert run.status == 2 and "error[E0001]" in run.stderr and "directory" in run.stderr


def test_missing_file(tmp_path, physc):
    run = physc("check", tmp_path / "nope.phys")
    assert run.status == 2 and "no such file" in run.stderr


def test_unreadable_file(tmp_path, physc):
    path = tmp_path / "secret.phys"
    path.write_text("scenario X = {h(b)}, {}")
    path.chmod(0)
    if os.access(path, os.R_OK):  # root reads anything
        return
    run = physc("check", path)
    assert run.status == 2 and "error[E0001]" in run.stderr


def test_unclosed_braces(physc, tmp_path):
    path = tmp_path / "open.phys"
    path.write_text("scenario X {\n  interactions {\n    hit(bird, pig, any) > destroy(bird, pig)\n")
    run = physc("check", path)
    assert run.status == 1 and f"{path}:2:16: error[E0103]" in run.stderr


def test_ten_thousand_nested_brackets(physc, tmp_path):
    path = tmp_path / "deep.phys"
    deep = "[" * 10_000 + "hit(bird, pig, any)" + "]" * 10_000
    path.write_text(f"scenario X {{ interactions {{ {deep} > destroy(bird, pig) }} }}")
    run = physc("check", path)
    assert run.status == 0, run.stderr
    unbalanced = tmp_path / "deeper.phys"
    unbalanced.write_text("scenario X { interactions { " + "[" * 10_000 + "hit(bird, pig, any) } }")
    run = physc("check", unbalanced)
    assert run.status == 1 and "error[E0102]" in run.stderr


def test_ten_thousand_open_parentheses(physc, tmp_path):
    path = tmp_path / "parens.phys"
    path.write_text("scenario X { interactions { hit" + "(" * 10_000 + " } }")
    run = physc("check", path)
    assert run.status == 1 and "Traceback" not in run.stderr


def test_standard_input(physc, monkeypatch):
    stdin = io.TextIOWrapper(io.BytesIO(b"scenario X = {hit(bird)(pig)(any) > destroy(bird)(pig)}, {}\n"))
    monkeypatch.setattr("sys.stdin", stdin)
    assert physc("check", "-").status == 0


@settings(max_examples=300, deadline=None)
@given(st.text(max_size=200))
def test_random_text_never_raises(text):
    result = parse_text(text)
    check_file(result.file, vocabularies=INSTALLED)


PIECES = ["scenario", "X", "{", "}", "(", ")", "[", "]", ",", ">", "|", "∨", "∧", "=", ":", "and", "or",
          "interactions", "restrictions", "objects", "domain", "hit", "bird", "pig", "left", "any", '"t"',
          "destroy", "cannotHit", "# c\n", "\n", "rBlock1", "roll", "surface", "fall", "cannotFall"]


@settings(max_examples=500, deadline=None)
@given(st.lists(st.sampled_from(PIECES), max_size=40))
def test_random_token_soup_never_raises(pieces):
    result = parse_text(" ".join(pieces))
    checked = check_file(result.file, vocabularies=INSTALLED)
    for diagnostic in result.diagnostics + checked.diagnostics:
        assert diagnostic.span is not None and diagnostic.code


def test_a_restriction_repeated_thousands_of_times_is_said_once(tmp_path, physc):
    """Repeats are harmless, and cost nothing: the checked scenario holds each restriction once,
    so a task is as quick to make as without them."""
    from physc.dsl.frontend import analyze

    repeated = "\n".join(["        cannotHit(bird, pig, above)"] * 5000)
    path = tmp_path / "repeats.phys"
    path.write_text(
        'scenario SF "Single Force" {\n    interactions {\n        hit(bird, pig, any)\n        > destroy(bird, pig)\n    }\n'
        f"    restrictions {{\n{repeated}\n    }}\n}}\n"
    )
    (scenario,) = analyze(str(path), INSTALLED).scenarios
    assert [r.text for r in scenario.restrictions] == ["cannotHit(bird, pig, above)"]
    run = physc("compile", path, "--time-budget", "60", "-o", tmp_path / "sf.xml", "-q")
    assert run.status == 0, run.stderr
