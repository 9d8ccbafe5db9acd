"""physc's PHYRE files read and simulated by PHYRE's own code: its loader
(`phyre.loader.load_compiled_task_dict`, with PHYRE's task folder pointed at the dataset) and its
`ActionSimulator`, and tools/phyre_simulator/replay.py, which uses both.

PHYRE is not a dependency (its wheels stop at Python 3.9): these tests are skipped unless
`phyre` can be imported, e.g. from a build of PHYRE's sources
(`PYTHONPATH=BUILD/python pytest ...`, see tools/phyre_simulator/README.md)."""

from __future__ import annotations

import importlib.util
import json
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest
from test_phyre_plugin import EXAMPLES, physc

REPLAY = Path(__file__).resolve().parents[3] / "tools" / "phyre_simulator" / "replay.py"
TIERS = {"BALL": "ball", "TWO_BALLS": "two_balls"}


@pytest.fixture(scope="module")
def phyre():
    return pytest.importorskip(
        "phyre", reason="PHYRE is not importable (build it from its sources: tools/phyre_simulator/README.md)"
    )


@pytest.fixture(scope="module")
def dataset(phyre, tmp_path_factory):
    out = tmp_path_factory.mktemp("dataset")
    status, _, err = physc(
        "generate",
        EXAMPLES / "01_ledge.phys",
        EXAMPLES / "07_two_balls.phys",
        "--tasks",
        "2",
        "--no-acceptance",
        "--out",
        out,
        "-q",
    )
    assert status == 0, err
    return out


@pytest.fixture
def loaded(phyre, dataset, monkeypatch):
    """PHYRE's loader with its task folder pointed at the dataset's phyre/."""
    import phyre.loader
    import phyre.settings

    monkeypatch.setattr(phyre.settings, "TASK_DIR", dataset / "phyre")
    return phyre.loader


def rows(dataset) -> list[dict]:
    return pq.read_table(dataset / "phyre" / "tasks.parquet").to_pylist()


def replay_main():
    spec = importlib.util.spec_from_file_location("phyre_replay", REPLAY)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.main


def test_phyres_loader_finds_physcs_tasks_by_id_in_their_file(loaded, dataset):
    ids = [row["task_id"] for row in rows(dataset)]
    assert loaded.task_id_to_pickle(ids[0]) == "tasks50.bin.lzma"
    tasks = loaded.load_compiled_task_dict(ids)
    assert sorted(tasks) == sorted(ids)
    # Without ids PHYRE reads every *.bin.lzma of its folder: the same tasks.
    assert sorted(loaded.load_compiled_task_dict()) == sorted(ids)


def test_phyres_tasks_are_physcs_with_their_tier_and_without_solutions(loaded, dataset):
    for row in rows(dataset):
        task = loaded.load_compiled_task_dict([row["task_id"]])[row["task_id"]]
        level = json.loads((dataset / row["level"]).read_text())
        assert task.tier == row["tier"]
        assert task.solutions is None
        assert len(task.scene.bodies) == len(level["scene"]["bodies"])
        assert (task.bodyId1, task.bodyId2) == (level["bodyId1"], level["bodyId2"])
        assert task.scene.bodies[-1].position.x == pytest.approx(level["scene"]["bodies"][-1]["position"]["x"])


def test_phyres_simulator_solves_each_task_with_its_intended_action(phyre, loaded, dataset):
    for tier in TIERS:
        mine = [row for row in rows(dataset) if row["tier"] == tier]
        assert mine, f"the dataset has no {tier} task"
        tasks = loaded.load_compiled_task_dict([row["task_id"] for row in mine])
        simulator = phyre.ActionSimulator([tasks[row["task_id"]] for row in mine], TIERS[tier])
        for index, row in enumerate(mine):
            status = simulator.simulate_action(index, np.array(row["action"]), need_images=False).status
            assert status.is_solved(), (row["task_id"], status)


def test_replay_reports_every_task_and_writes_its_files(dataset, tmp_path, capsys):
    assert replay_main()([str(dataset), "--out", str(tmp_path)]) == 0
    report = json.loads((tmp_path / "replay.json").read_text())
    assert report["summary"]["all"]["tasks"] == len(rows(dataset))
    assert report["summary"]["all"]["solved"] == len(rows(dataset))
    assert (tmp_path / "replay.csv").read_text().count("\n") == len(rows(dataset)) + 1
    assert "solved (plain)" in (tmp_path / "replay.md").read_text()
    assert "replay: wrote" in capsys.readouterr().out


def test_replay_of_a_folder_that_is_no_dataset_is_a_clear_error(tmp_path, capsys):
    assert replay_main()([str(tmp_path / "missing")]) == 2
    assert replay_main()([str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "no such folder" in err and "Traceback" not in err
