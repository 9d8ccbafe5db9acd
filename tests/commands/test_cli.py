"""The command line: commands, --emit stages, exit statuses, files written whole."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys

import pytest
from conftest import EXAMPLES

from physc import __version__

SF = EXAMPLES / "paper" / "01_SF.phys"
ALL = EXAMPLES / "paper" / "all.paper.phys"


@pytest.mark.parametrize("flag", ["--version", "-V"])
def test_version(physc, flag):
    run = physc(flag)
    assert run.status == 0 and run.stdout.strip() == f"physc {__version__}"


def test_no_command_is_a_usage_error(physc):
    assert physc().status == 2


def test_unknown_option_is_a_usage_error(physc):
    run = physc("check", "--bogus", SF)
    assert run.status == 2 and "unrecognized arguments" in run.stderr


def test_check_ok_and_summary(physc):
    run = physc("check", *sorted((EXAMPLES / "paper").glob("*.phys")))
    assert run.status == 0
    assert run.stderr.strip() == "0 errors, 0 warnings in 17 files"


def test_check_json(physc):
    run = physc("check", "--format", "json", EXAMPLES / "errors" / "E0203_type_mismatch.phys")
    (diagnostic,) = json.loads(run.stdout)
    assert run.status == 1
    assert diagnostic["code"] == "E0203" and diagnostic["severity"] == "error"
    assert (diagnostic["line"], diagnostic["column"], diagnostic["end_column"]) == (6, 16, 22)
    assert diagnostic["help"] == "declare it as `fBlock: rollableBlock` or use an rBlock"


def test_check_exit_status_is_the_worst(physc, tmp_path):
    broken = EXAMPLES / "errors" / "E0201_unknown_term.phys"
    assert physc("check", SF, broken).status == 1
    assert physc("check", SF, broken, tmp_path / "missing.phys").status == 2
    assert physc("check", EXAMPLES / "errors" / "W0301_unused_declaration.phys").status == 0


def test_diagnostic_text_matches_the_specification(physc):
    run = physc("check", "--color", "never", EXAMPLES / "errors" / "E0203_type_mismatch.phys")
    path = EXAMPLES / "errors" / "E0203_type_mismatch.phys"
    assert run.stderr.splitlines()[:4] == [
        f"{path}:6:16: error[E0203]: 'roll' expects a rollable object, but 'fBlock' is a fallableBlock",
        "    6 |         > roll(fBlock, surface, right)",
        "      |                ^^^^^^",
        "  help: declare it as `fBlock: rollableBlock` or use an rBlock",
    ]


def test_color_always_paints(physc):
    run = physc("check", "--color", "always", EXAMPLES / "errors" / "E0203_type_mismatch.phys")
    assert "\033[1;31merror[E0203]" in run.stderr


@pytest.mark.parametrize("where", ["before", "after"])
def test_no_color_before_or_after_the_command(physc, where):
    """`--no-color` is `--color never`, at the top level or the command's, even over an
    earlier --color always."""
    bad = EXAMPLES / "errors" / "E0203_type_mismatch.phys"
    args = ("--color", "always", "--no-color", "check", bad) if where == "before" else ("check", "--color", "always", "--no-color", bad)
    run = physc(*args)
    assert run.status == 1 and "error[E0203]" in run.stderr and "\033[" not in run.stderr


def test_a_negative_shot_is_a_value_not_an_option(physc):
    """Most solutions aim left of the sling: `--shot -3.5,-0.8,high` as typed, no `=` needed."""
    from conftest import TEMPLATES

    run = physc("simulate", TEMPLATES[0], "--shot", "-3.5,-0.8,high", "--seconds", "1")
    assert run.status == 0, run.stderr
    assert "shot (-3.5, -0.8), high" in run.stdout


@pytest.mark.parametrize("stage", ["ast", "scenario"])
def test_compile_emit(physc, stage):
    run = physc("compile", SF, "--emit", stage)
    assert run.status == 0, run.stderr
    data = json.loads(run.stdout)
    assert data["node"] == ("Scenario" if stage == "ast" else "ScenarioIR")
    assert physc("compile", SF, "--emit", stage).stdout == run.stdout  # deterministic


def test_compile_emit_scenario_content(physc):
    data = json.loads(physc("compile", ALL, "-s", "SFTB", "--emit", "scenario").stdout)
    assert data["name"] == "SFTB"
    assert data["interactions"][0]["directions"] == ["left", "right", "below"]
    assert [o["name"] for o in data["objects"]] == ["bird", "pig"]
    assert data["interactions"][0]["span"] == "8:46-8:65"


def test_compile_several_scenarios(physc):
    data = json.loads(physc("compile", ALL, "-s", "R", "-s", "RRR", "--emit", "scenario").stdout)
    assert [d["name"] for d in data] == ["R", "RRR"]
    assert len(json.loads(physc("compile", ALL, "--emit", "ast").stdout)) == 16


def test_compile_unknown_scenario(physc):
    run = physc("compile", ALL, "-s", "RFF", "--emit", "ast")
    assert run.status == 2 and "did you mean 'RF'" in run.stderr and "Traceback" not in run.stderr


def test_compile_unknown_stage(physc):
    run = physc("compile", SF, "--emit", "senario")
    assert run.status == 2 and "did you mean 'scenario'" in run.stderr


def test_every_stage_is_available(physc):
    from physc.driver.stages import STAGES

    assert all(s.run is not None for s in STAGES)


def test_compile_input_errors_exit_1(physc):
    run = physc("compile", EXAMPLES / "errors" / "E0203_type_mismatch.phys", "--emit", "scenario")
    assert run.status == 1 and run.stdout == ""


def test_compile_ignores_errors_of_other_scenarios(physc, tmp_path):
    path = tmp_path / "two.phys"
    path.write_text(
        "scenario GOOD = {[hit(bird)(pig)(any)] > [destroy(bird)(pig)]}, {}\n"
        "scenario BAD = {[hit(bird)(pig)(any)] > [destory(bird)(pig)]}, {}\n"
    )
    assert physc("compile", path, "-s", "GOOD", "--emit", "scenario").status == 0
    assert physc("compile", path, "-s", "BAD", "--emit", "scenario").status == 1


def test_compile_output_file(physc, tmp_path):
    out = tmp_path / "sf.json"
    assert physc("compile", SF, "--emit", "scenario", "-o", out).status == 0
    assert json.loads(out.read_text())["name"] == "SF"
    assert [p.name for p in tmp_path.iterdir()] == ["sf.json"]  # no temporary left behind


def test_fmt_check_and_write(physc, tmp_path):
    path = tmp_path / "x.phys"
    path.write_text("scenario X = {[hit(bird)(pig)(any)] > [destroy(bird)(pig)]}, {} # c\n")
    run = physc("fmt", "--check", path)
    assert run.status == 1 and f"would reformat {path}" in run.stderr
    assert physc("fmt", "--write", path).status == 0
    assert physc("fmt", "--check", path).status == 0
    assert path.read_text().startswith("scenario X {\n")
    assert physc("fmt", path).stdout == path.read_text()


def test_fmt_refuses_broken_files_and_writes_nothing(physc, tmp_path):
    path = tmp_path / "x.phys"
    original = "scenario X { interactions { hit(bird pig) } }\n"
    path.write_text(original)
    run = physc("fmt", "--write", path)
    assert run.status == 1 and "E0102" in run.stderr
    assert path.read_text() == original


def test_fmt_write_and_check_exclusive(physc):
    assert physc("fmt", "--write", "--check", SF).status == 2


def test_domains(physc):
    run = physc("domains")
    assert run.status == 0
    assert run.stdout.startswith("angrybirds: ")
    assert "rollableBlock (rBlock)" in run.stdout and "cannotFall(a)" in run.stdout
    data = json.loads(physc("domains", "--format", "json").stdout)
    assert data[0]["name"] == "angrybirds"
    run = physc("domains", "angrybird")
    assert run.status == 2 and "did you mean 'angrybirds'" in run.stderr


def test_internal_errors_are_reported_not_dumped(physc, monkeypatch):
    def broken(*args, **kwargs):
        raise RuntimeError("boom")

    monkeypatch.setattr("physc.dsl.frontend.check_file", broken)
    run = physc("check", SF)
    assert run.status == 70
    assert "internal error: RuntimeError: boom" in run.stderr and "Traceback" not in run.stderr
    for where in (["check", "--traceback", SF], ["--traceback", "check", SF]):  # after the command or before it
        run = physc(*where)
        assert run.status == 70 and "Traceback" in run.stderr and "RuntimeError: boom" in run.stderr


@pytest.mark.skipif(shutil.which("physc") is None, reason="the physc console script is not installed")
def test_console_script():
    run = subprocess.run(["physc", "check", "-q", str(SF)], capture_output=True, text=True)
    assert run.returncode == 0 and run.stderr == ""
    run = subprocess.run([sys.executable, "-m", "physc", "--version"], capture_output=True, text=True)
    assert run.stdout.strip() == f"physc {__version__}"


def test_unwritable_outputs_are_usage_errors(physc, tmp_path):
    missing = tmp_path / "no" / "such" / "folder" / "sf.xml"
    run = physc("compile", SF, "-o", missing, "-q")
    assert run.status == 2 and f"cannot write {missing}" in run.stderr and "internal error" not in run.stderr
    blocker = tmp_path / "file"
    blocker.write_text("")
    run = physc("eval", SF, "--tasks", "1", "--out", blocker / "inside", "-q")
    assert run.status == 2 and "cannot write" in run.stderr
