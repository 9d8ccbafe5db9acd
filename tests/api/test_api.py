"""physc's Python API (issue 55, point 1): the functions the command line's work is made of,
with what they raise for bad input."""

from __future__ import annotations

import subprocess
import sys

import pytest
from conftest import EXAMPLES, GOLDEN, run_physc

import physc

F = EXAMPLES / "paper" / "05_F.phys"
SF = EXAMPLES / "paper" / "01_SF.phys"


@pytest.fixture(scope="module")
def task():
    return physc.compile(F, seed=1)


def test_every_exported_name_resolves_and_import_is_cheap():
    for name in physc.__all__:
        assert getattr(physc, name) is not None, name
    assert set(physc.__all__) <= set(dir(physc))
    fresh = subprocess.run(
        [sys.executable, "-c", "import physc, sys; print('gymnasium' in sys.modules, 'physc.api' in sys.modules, 'numpy' in sys.modules)"],
        capture_output=True, text=True, check=True,
    )
    assert fresh.stdout.split() == ["False", "False", "False"]
    import pkgutil

    submodules = {m.name for m in pkgutil.iter_modules(physc.__path__)}
    assert not submodules & set(physc.__all__), "an exported name that a submodule shadows once imported"
    with pytest.raises(AttributeError, match="no attribute 'compiel'"):
        physc.compiel  # noqa: B018


def test_compile_gives_the_task_the_command_line_writes(task, tmp_path):
    assert task.scenario == "F" and task.world == "phyq" and task.backend == "box2d"
    events = task.trace.split(" > ")
    declared = ["fall(fBlock, pig)", "hit(fBlock, pig, above)", "destroy(fBlock, pig)"]
    assert [events.index(term) for term in declared] == sorted(events.index(term) for term in declared)  # in order
    assert task.seconds["total"] > 0
    assert run_physc("compile", F, "--seed", "1", "-q", "-o", tmp_path / "cli.xml", "--task", tmp_path / "cli.json").status == 0
    physc.save_level(task, tmp_path / "api.xml")
    assert (tmp_path / "api.xml").read_bytes() == (tmp_path / "cli.xml").read_bytes()
    assert physc.level_text(task) == (tmp_path / "cli.xml").read_text()
    assert physc.load_task(tmp_path / "cli.json").level == task.level


def test_a_scenario_as_text_and_by_name(task):
    text = F.read_text()
    again = physc.compile(text, "F", seed=1)
    assert again.level == task.level and again.solution == task.solution
    assert physc.scenarios(EXAMPLES / "paper" / "all.paper.phys")[:2] == ["SF", "SFTB"]


def test_task_files_round_trip(task, tmp_path):
    physc.save_task(task, tmp_path / "t.json")
    assert physc.load_task(tmp_path / "t.json") == task
    assert physc.load_task(GOLDEN / "task" / "05_F.json").scenario == "F"


@pytest.mark.parametrize(
    ("source", "error", "message"),
    [
        ("scenario X { interactions { hit(bird, pig, left) > destory(bird, pig) } }", physc.ScenarioError, "did you mean 'destroy'"),
        ("no-such-file.phys", physc.ScenarioError, "no such scenario file"),
        (EXAMPLES / "paper" / "all.paper.phys", physc.ScenarioError, "name one"),
    ],
)
def test_bad_scenarios_raise_what_the_command_line_reports(source, error, message):
    with pytest.raises(error, match=message):
        physc.compile(source)


def test_a_scenario_with_no_task_raises_no_task():
    infeasible = sorted((EXAMPLES / "infeasible").glob("*.phys"))[0]
    with pytest.raises(physc.NoTask) as raised:
        physc.compile(infeasible, time_budget=10)
    assert raised.value.diagnostic.code.startswith("E08")
    assert isinstance(raised.value, physc.PhyscError)


def test_bad_files_raise_file_error(tmp_path):
    (tmp_path / "x.json").write_text("{}")
    with pytest.raises(physc.FileError, match="not a task file"):
        physc.load_task(tmp_path / "x.json")
    (tmp_path / "x.xml").write_text("<Level><GameObjects><Block/></GameObjects>")
    with pytest.raises(physc.FileError, match="x.xml"):
        physc.read_level(tmp_path / "x.xml")
    with pytest.raises(physc.FileError, match="not a dataset"):
        physc.load_dataset(tmp_path)


def test_render_draws_tasks_and_levels(task):
    assert physc.render(task).startswith(b"\x89PNG")
    assert physc.render(task, physc.Shot(angle=70), fmt="svg").lstrip().startswith(b"<?xml")
    level = physc.read_level(physc.level_text(task).encode())
    assert physc.render(level).startswith(b"\x89PNG")


def test_simulate_and_verify(task):
    assert physc.simulate(task, task.solution).solved
    assert physc.simulate(task, physc.Shot(target=task.solution.target, trajectory=task.solution.trajectory)).solved
    assert not physc.simulate(task, None).solved
    noisy = [physc.simulate(task, task.solution, noise=seed).duration for seed in (1, 1, 2)]
    assert noisy[0] == noisy[1]
    level = physc.read_level(physc.level_text(task).encode())
    assert physc.simulate(level, physc.Shot(angle=task.solution.release_angle)).solved
    result = physc.verify(task, replays=2)
    assert result.passes(2) and result.backend == "box2d"
    assert physc.verify(task, backend="pymunk", replays=0).backend == "pymunk"


def test_datasets_generate_and_load(tmp_path):
    dataset = physc.generate(SF, tmp_path / "ds", tasks=1, seed=1)
    assert [row["outcome"] for row in dataset] == ["ok"]
    loaded = physc.load_dataset(tmp_path / "ds")
    assert len(loaded) == 1 and [t.seed for t in loaded.tasks()] == [1]
    assert (tmp_path / "ds" / "manifest.parquet").is_file()
    on_dask = physc.generate(SF, tmp_path / "dask", tasks=1, seed=1, dask_workers=1)
    assert (tmp_path / "dask" / on_dask.rows[0]["task"]).read_bytes() == (tmp_path / "ds" / dataset.rows[0]["task"]).read_bytes()


def test_one_dataset_cannot_hold_two_scenarios_of_one_name(tmp_path):
    copy = tmp_path / "again.phys"
    copy.write_text(F.read_text())
    with pytest.raises(physc.ScenarioError, match="two files have a scenario named 'F'"):
        physc.generate([F, copy], tmp_path / "ds")


def test_the_stub_states_every_export():
    """physc/__init__.pyi gives type checkers and editors the names __init__.py imports lazily."""
    import ast
    from pathlib import Path

    stub = ast.parse((Path(physc.__file__).with_name("__init__.pyi")).read_text())
    stated = {alias.asname or alias.name for node in stub.body if isinstance(node, ast.ImportFrom) for alias in node.names}
    assert stated | {"__version__"} == set(physc.__all__)
