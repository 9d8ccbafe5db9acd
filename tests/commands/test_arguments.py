"""Numeric options are checked where they are parsed: a careless value is a usage error
(exit 2, one clear line), never an internal error, a hang or a silently accepted budget."""

from __future__ import annotations

import pytest
from conftest import EXAMPLES, run_physc

from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.level_xml import emit_level

SCENARIO = EXAMPLES / "paper" / "04_R.phys"


@pytest.fixture(scope="module")
def level(tmp_path_factory):
    path = tmp_path_factory.mktemp("level") / "one_pig.xml"
    pig = LevelObject("Pig", "BasicSmall", 2.0, -3.26, name="pig1")
    path.write_text(emit_level(Level(objects=(pig,))), encoding="utf-8")
    return path


PLAY_OPTIONS = [
    ("--seconds", "-1"),
    ("--seconds", "0"),
    ("--seconds", "nan"),
    ("--seconds", "inf"),
    ("--seconds", "1e9"),
    ("--seconds", "ten"),
    ("--shot=nan,0.59", None),
    ("--shot=1e999,0", None),
    ("--shot=5000,0", None),
    ("--shot=1,2,sideways", None),
    ("--shot=1", None),
    ("--angle", "nan"),
    ("--angle", "91"),
    ("--angle", "-inf"),
]


@pytest.mark.parametrize("command", ["simulate", "trace", "render"])
@pytest.mark.parametrize("option, value", PLAY_OPTIONS)
def test_play_options(command, option, value, level, tmp_path):
    extra = ["-o", str(tmp_path / "p.png")] if command == "render" else []
    run = run_physc(command, level, option, *([value] if value is not None else []), *extra)
    assert run.status == 2, run.stderr
    assert "error: argument" in run.stderr and "Traceback" not in run.stderr
    assert not (tmp_path / "p.png").exists()


@pytest.mark.parametrize(
    "option, value",
    [
        ("--time-budget", "0"),
        ("--time-budget", "-1"),
        ("--time-budget", "nan"),
        ("--layouts", "0"),
        ("--layouts", "-5"),
        ("--layouts", "1.5"),
        ("--min-robustness", "0"),
        ("--min-robustness", "9"),
        ("--seed", "-1"),
        ("--seed", str(2**63)),
        ("--clause-budget", "0"),
    ],
)
def test_compile_options(option, value, tmp_path):
    out = tmp_path / "r.xml"
    run = run_physc("compile", SCENARIO, option, value, "-o", out, "-q")
    assert run.status == 2, run.stderr
    assert "--" in run.stderr and "Traceback" not in run.stderr
    assert not out.exists()


@pytest.mark.parametrize(
    "option, value",
    [("--tasks", "0"), ("--jobs", "0"), ("--jobs", "-2"), ("--seed", "-3"), ("--time-budget", "inf"), ("--min-robustness", "7")],
)
def test_eval_options(option, value, tmp_path):
    run = run_physc("eval", SCENARIO, "--out", tmp_path / "out", option, value, "-q")
    assert run.status == 2, run.stderr
    assert not (tmp_path / "out").exists()


def test_eval_seeds_stay_in_range(tmp_path):
    run = run_physc("eval", SCENARIO, "--out", tmp_path / "out", "--seed", str(2**63 - 2), "--tasks", "3", "-q")
    assert run.status == 2 and "largest seed" in run.stderr


def test_a_valid_limit_is_accepted(level):
    run = run_physc("simulate", level, "--seconds", "0.5", "--shot=2,-3.26")
    assert run.status == 0, run.stderr


def test_a_value_with_control_characters_is_echoed_escaped(level):
    run = run_physc("simulate", level, "--seconds", "\x1b[31m1")
    assert run.status == 2 and "\x1b" not in run.stderr and "'\\x1b[31m1' is not a number" in run.stderr
    run = run_physc("compile", SCENARIO, "--layouts", "\x00")
    assert run.status == 2 and "\x00" not in run.stderr
