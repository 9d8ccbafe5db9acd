"""The command line's shared flags: one spelling of JSON output (`--format json`) in every
command that reports something, `--color` and `--traceback` before or after the command,
and the exit statuses in every command's help."""

from __future__ import annotations

import json
import shutil
import subprocess

import pytest
from conftest import EXAMPLES, SCIENCEBIRDS, run_physc

from physc.cli import build_parser

SF = EXAMPLES / "paper" / "01_SF.phys"
ONE_PIG = SCIENCEBIRDS / "phyq-templates" / "1_1_1_1.xml"
BROKEN = EXAMPLES / "errors" / "E0203_type_mismatch.phys"


def _commands():
    parser = build_parser()
    action = next(a for a in parser._actions if a.dest == "command")
    return action.choices


def test_every_help_ends_with_every_exit_status():
    helps = {"physc": build_parser().format_help()} | {name: sub.format_help() for name, sub in _commands().items()}
    for name, text in helps.items():
        flat = " ".join(text.split())
        for status in ("0 ok", "1 input errors", "2 usage", "3 no task", "70 internal error", "130 interrupted"):
            assert status in flat, (name, status)


def test_every_reporting_command_spells_json_one_way():
    for name, sub in _commands().items():
        flags = {option for action in sub._actions for option in action.option_strings if action.help != "==SUPPRESS=="}
        if name in ("lsp", "completion"):  # the language server protocol; a shell script
            continue
        assert "--format" in flags, name
        assert "--json" not in flags, name  # kept hidden, for old scripts


@pytest.mark.parametrize("where", ["before", "after"])
def test_color_before_or_after_the_command(where):
    args = ["--color", "always", "check", BROKEN] if where == "before" else ["check", "--color", "always", BROKEN]
    assert "\x1b[" in run_physc(*args).stderr
    args = ["--color", "never", "check", BROKEN] if where == "before" else ["check", "--color", "never", BROKEN]
    assert "\x1b[" not in run_physc(*args).stderr


def test_json_outputs_parse(tmp_path):
    outputs = {
        "check": run_physc("check", SF, "--format", "json"),
        "fmt": run_physc("fmt", SF, "--format", "json"),
        "simulate": run_physc("simulate", ONE_PIG, "--shot", "0,-3.27", "--format", "json"),
        "trace": run_physc("trace", ONE_PIG, "--shot", "0,-3.27", "--format", "json"),
        "render": run_physc("render", ONE_PIG, "-o", tmp_path / "level.svg", "--format", "json"),
        "domains": run_physc("domains", "--format", "json"),
        "backends": run_physc("backends", "--format", "json"),
        "old spelling": run_physc("trace", ONE_PIG, "--shot", "0,-3.27", "--json"),
    }
    data = {}
    for name, run in outputs.items():
        assert run.status == 0, (name, run.stderr)
        data[name] = json.loads(run.stdout)
    assert data["fmt"][0]["file"] == str(SF) and data["fmt"][0]["canonical"] in (True, False) and "formatted" in data["fmt"][0]
    assert data["simulate"]["solved"] is True and data["trace"] == data["old spelling"]
    assert data["render"]["picture"] == str(tmp_path / "level.svg") and data["render"]["format"] == "svg"


def test_generate_and_eval_report_json(tmp_path):
    run = run_physc("generate", SF, "--tasks", "1", "--out", tmp_path / "data", "--format", "json", "--no-validate")
    report = json.loads(run.stdout)
    assert run.status == 0 and report["generated"] == report["tasks"] == 1 and report["rows"][0]["scenario"] == "SF"
    run = run_physc("eval", SF, "--tasks", "1", "--out", tmp_path / "eval", "--format", "json")
    report = json.loads(run.stdout)
    assert run.status == 0 and report["report"].endswith("results.md") and "interactions" in report


@pytest.mark.skipif(shutil.which("bash") is None, reason="needs bash")
def test_bash_completes_commands_and_flags(tmp_path):
    script = tmp_path / "physc.bash"
    run = run_physc("completion", "bash")
    assert run.status == 0
    script.write_text(run.stdout)

    def complete(*words: str) -> list[str]:
        line = f'source {script}; COMP_WORDS=({" ".join(words)}); COMP_CWORD={len(words) - 1}; _shtab_physc; echo "${{COMPREPLY[@]}}"'
        return subprocess.run(["bash", "-c", line], capture_output=True, text=True, check=True).stdout.split()

    assert complete("physc", "com") == ["compile", "completion"]
    assert "--format" in complete("physc", "check", "--fo")
    assert "--time-budget" in complete("physc", "generate", "--time")


def test_completion_for_every_shell_shtab_knows():
    for shell in ("zsh", "tcsh", "fish", "powershell"):
        run = run_physc("completion", shell)
        assert run.status == 0 and "compile" in run.stdout, shell
