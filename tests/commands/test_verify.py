"""Cross-engine verification from the command line: `physc verify`, `--backend` and
`--verify-backend` of compile and eval."""

from __future__ import annotations

import json

import pytest
from conftest import EXAMPLES, run_physc

PAPER = EXAMPLES / "paper" / "all.paper.phys"


@pytest.fixture(scope="module")
def task(tmp_path_factory):
    """A task of SF (a bird destroys a pig), its level and task files."""
    folder = tmp_path_factory.mktemp("sf")
    level, task = folder / "sf.xml", folder / "sf.json"
    run = run_physc("compile", PAPER, "-s", "SF", "--seed", "1", "-q", "-o", level, "--task", task)
    assert run.status == 0, run.stderr
    return level, task


@pytest.mark.parametrize("backend", ["box2d", "pymunk", "bullet"])
def test_a_tasks_solution_passes_in_either_engine(task, backend):
    level, task_file = task
    run = run_physc("verify", level, "--task", task_file, "--backend", backend)
    assert run.status == 0, run.stdout + run.stderr
    assert f"passes in {backend}: solved, sequence realised, 6 of 6 noisy replays" in run.stdout
    assert "hit(bird, pig, left) > destroy(bird, pig)" in run.stdout
    data = json.loads(run_physc("verify", level, "--task", task_file, "--backend", backend, "--replays", "2", "--json").stdout)
    assert data["passes"] and data["solved"] and data["realised"] and (data["noisy_passed"], data["noisy_run"]) == (2, 2)
    # Every reading of the game that can change a replay was played (the pig's destroying strike
    # depends on relativeVelocity's sign), and none failed.
    assert data["readings"] >= 2 and data["failed_readings"] == []


def test_a_solution_that_misses_fails_with_the_reason_and_exit_1(task, tmp_path):
    level, task_file = task
    data = json.loads(task_file.read_text())
    data["solution"]["target"] = [data["solution"]["target"][0] + 6.0, data["solution"]["target"][1]]
    data["solution"]["release_angle"] += 8.0
    wrong = tmp_path / "wrong.json"
    wrong.write_text(json.dumps(data))
    run = run_physc("verify", level, "--task", wrong, "--backend", "bullet", "--replays", "0")
    assert run.status == 1
    assert "fails in bullet: not solved" in run.stdout and "why: the solution does not solve the level" in run.stdout


def test_bad_verify_input_is_a_usage_error(task, tmp_path):
    level, task_file = task
    other = EXAMPLES.parent / "tests" / "data" / "sciencebirds" / "phyq-templates" / "2_2_1_1.xml"
    run = run_physc("verify", other, "--task", task_file)
    assert run.status == 2 and "is not the level of" in run.stderr
    (tmp_path / "not.json").write_text("[1, 2")
    assert "is not a task file (JSON)" in run_physc("verify", level, "--task", tmp_path / "not.json").stderr
    (tmp_path / "other.json").write_text('{"node": "Level"}')
    assert "is not a task file" in run_physc("verify", level, "--task", tmp_path / "other.json").stderr
    assert run_physc("verify", level, "--task", tmp_path / "absent.json").status == 2
    data = json.loads(task_file.read_text())
    data["level"]["objects"][0]["node"] = "Pipeline"
    (tmp_path / "odd.json").write_text(json.dumps(data))
    run = run_physc("verify", level, "--task", tmp_path / "odd.json")
    assert run.status == 2 and "cannot be read" in run.stderr
    run = run_physc("verify", level, "--task", task_file, "--backend", "bulet")
    assert run.status == 2 and "did you mean 'bullet'" in run.stderr
    assert run_physc("verify", level, "--task", task_file, "--replays", "-1").status == 2


def test_unknown_backends_are_refused_before_any_work():
    for command in (["compile", PAPER, "-s", "SF"], ["eval", PAPER, "-s", "SF", "--out", "never"]):
        for option in ("--backend", "--verify-backend"):
            run = run_physc(*command, option, "pybulet")
            assert run.status == 2 and "did you mean 'bullet'" in run.stderr, (command, option)


def test_compile_keeps_a_task_only_if_it_also_passes_in_the_verify_backend(tmp_path):
    level, task_file = tmp_path / "sf.xml", tmp_path / "sf.json"
    run = run_physc("compile", PAPER, "-s", "SF", "--seed", "2", "-q", "--verify-backend", "bullet", "-o", level, "--task", task_file)
    assert run.status == 0, run.stderr
    assert run_physc("verify", level, "--task", task_file, "--backend", "bullet").status == 0


def test_compile_generates_in_the_backend_it_is_given(tmp_path):
    level, task_file = tmp_path / "sf.xml", tmp_path / "sf.json"
    run = run_physc("compile", PAPER, "-s", "SF", "--seed", "0", "-q", "--backend", "bullet", "-o", level, "--task", task_file)
    assert run.status == 0, run.stderr
    assert run_physc("verify", level, "--task", task_file, "--backend", "bullet").status == 0


def test_eval_records_and_reports_the_verify_backend(tmp_path):
    run = run_physc("eval", PAPER, "-s", "SF", "--tasks", "1", "--verify-backend", "bullet", "--out", tmp_path, "-q")
    assert run.status == 0, run.stderr
    (record,) = [json.loads(line) for line in (tmp_path / "records.jsonl").read_text().splitlines()]
    assert record["verify_backend"] == "bullet" and record["settings"]["verify_backend"] == "bullet"
    assert record["verified_solved"] is True and record["verified_realised"] is True and record["verified_noisy"] > 0.5
    report = (tmp_path / "results.md").read_text()
    assert "| Solved in bullet (exact replay) | 1.00 ± 0.00 |" in report
    assert "| Sequence realised in bullet (exact replay) | 1.00 ± 0.00 |" in report
    assert (tmp_path / "results.csv").read_text().splitlines()[0].endswith("verify_backend,verified_solved,verified_realised,verified_noisy")


BAD_TASKS = {
    "a coordinate that is not a number": lambda d: d["level"]["objects"][0].__setitem__("x", "abc"),
    "a target that is not a point": lambda d: d["solution"].__setitem__("target", "ab"),
    "an infinite target": lambda d: d["solution"].__setitem__("target", [float("inf"), 0.0]),
    "a release angle that is not a number": lambda d: d["solution"].__setitem__("release_angle", "x"),
    "a level that is a number": lambda d: d.__setitem__("level", 5),
    "objects that are a number": lambda d: d["level"].__setitem__("objects", 5),
    "an unknown trajectory": lambda d: d["solution"].__setitem__("trajectory", "sideways"),
    "a target out of reach": lambda d: d["solution"].__setitem__("target", [500.0, 300.0]),
}


@pytest.mark.parametrize("damage", BAD_TASKS, ids=list(BAD_TASKS))
def test_a_damaged_task_file_is_a_usage_error_not_a_crash(task, tmp_path, damage):
    level, task_file = task
    data = json.loads(task_file.read_text())
    BAD_TASKS[damage](data)
    damaged = tmp_path / "damaged.json"
    damaged.write_text(json.dumps(data))
    run = run_physc("verify", level, "--task", damaged, "--replays", "0")
    assert run.status == 2 and "internal error" not in run.stderr and str(damaged) in run.stderr


def test_deep_json_and_a_level_saved_with_crlf_and_a_bom(task, tmp_path):
    level, task_file = task
    deep = tmp_path / "deep.json"
    deep.write_text("[" * 100_000 + "]" * 100_000)
    run = run_physc("verify", level, "--task", deep)
    assert run.status == 2 and "nested too deeply" in run.stderr
    crlf = tmp_path / "crlf.xml"
    crlf.write_bytes(b"\xef\xbb\xbf" + level.read_bytes().replace(b"\n", b"\r\n"))
    assert run_physc("verify", crlf, "--task", task_file, "--replays", "0").status == 0


def test_the_verify_backend_must_be_another_engine():
    run = run_physc("compile", PAPER, "-s", "SF", "--verify-backend", "box2d")
    assert run.status == 2 and "already simulates" in run.stderr


def test_verify_plays_what_agents_may_send_beside_the_solution_and_names_what_fails(task, tmp_path):
    """Phy-Q's agents' other actions (the planner's release, the 8 pixels around the drag) are
    played too; a recorded drag moved 120 pixels up (a shot 30° down; its recorded angles kept)
    leaves the planner's release holding and its 8 pixels failing: exit 1, each named."""
    level, task_file = task
    data = json.loads(run_physc("verify", level, "--task", task_file, "--replays", "0", "--json").stdout)
    assert data["passes"] and data["agent_variants"] == 9 and data["failed_variants"] == []
    moved = json.loads(task_file.read_text())
    moved["solution"]["agent_action"][1] += 120
    wrong = tmp_path / "moved.json"
    wrong.write_text(json.dumps(moved))
    run = run_physc("verify", level, "--task", wrong, "--replays", "0")
    assert run.status == 1 and "8 of the 9 actions agents may send beside it fail" in run.stdout
    assert run.stdout.count("  fails as an agent may send it: pixel (") == 8 and "why: as an agent may send it, it fails" in run.stdout
    data = json.loads(run_physc("verify", level, "--task", wrong, "--replays", "0", "--json").stdout)
    assert not data["passes"] and len(data["failed_variants"]) == 8 and data["solved"] and data["realised"]
