"""physc generate: datasets on local processes and on a real Dask LocalCluster; resuming after a
killed client, a killed worker, a full disk; the executors' errors."""

from __future__ import annotations

import errno
import hashlib
import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import psutil
import pytest
from conftest import EXAMPLES, run_physc

SF = EXAMPLES / "paper" / "01_SF.phys"
F = EXAMPLES / "paper" / "03_SFLB.phys"  # the second scenario: quick, and written as JSON (its obstacle)
TIMES = ("generation_seconds", "seconds")


def dataset(folder: Path) -> tuple[dict, list[dict]]:
    """A dataset's files (hashes; the README's line naming the folder left out) and its manifest
    rows without their times."""
    files = {}
    for path in sorted(folder.rglob("*")):
        if path.is_file() and path.name not in ("manifest.jsonl", "manifest.parquet"):
            data = path.read_bytes()
            if path.name == "README.md":
                data = b"\n".join(line for line in data.split(b"\n") if b"--out" not in line and not line.startswith(b"# "))
            files[str(path.relative_to(folder))] = hashlib.sha256(data).hexdigest()
    rows = [json.loads(line) for line in (folder / "manifest.jsonl").read_text().splitlines()]
    for row in rows:
        for name in TIMES:
            row.pop(name)
    return files, rows


def generate(*args) -> subprocess.Popen:
    """`physc generate` as a process of its own session (so that it and its workers can be killed)."""
    return subprocess.Popen(
        [sys.executable, "-m", "physc", "generate", *map(str, args), "-q"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True,
    )


def rows_written(folder: Path) -> int:
    path = folder / "manifest.jsonl"
    return len(path.read_text().splitlines()) if path.exists() else 0


def wait_for_rows(folder: Path, count: int, process: subprocess.Popen, seconds: float = 120) -> None:
    end = time.monotonic() + seconds
    while rows_written(folder) < count:
        assert process.poll() is None, process.communicate()
        assert time.monotonic() < end, "no progress"
        time.sleep(0.05)


@pytest.fixture(scope="module")
def reference(tmp_path_factory):
    """SF and SFLB, 4 tasks each, made one after another in this process."""
    folder = tmp_path_factory.mktemp("reference") / "dataset"
    run = run_physc("generate", SF, F, "--tasks", "4", "--out", folder, "-q")
    assert run.status == 0, run.stderr
    return folder


def test_a_dataset_is_complete_and_loads_in_pandas(reference):
    files, rows = dataset(reference)
    assert [(r["scenario"], r["seed"], r["outcome"]) for r in rows] == [("SF", s, "ok") for s in range(4)] + [("SFLB", s, "ok") for s in range(4)]
    assert {f"SF/{s}.xml" for s in range(4)} | {f"SFLB/{s}.json" for s in range(4)} | {"README.md"} <= set(files)
    tasks = pd.read_parquet(reference / "manifest.parquet")
    assert list(tasks["seed"]) == [0, 1, 2, 3] * 2 and set(tasks["outcome"]) == {"ok"}
    assert tasks["robustness_passed"].min() >= 4 and tasks["generation_seconds"].gt(0).all()
    assert tasks["solution"][0]["node"] == "Solution" and tasks["settings"][0]["backend"] == "box2d"  # structs, as in JSON Lines
    assert list(tasks["sequence_terms"][0]) == ["hit(bird, pig, any)", "destroy(bird, pig)"] and list(tasks["trace_terms"][0]) == rows[0]["trace"].split(" > ")
    assert tasks["file"][0] == "SF/scenario.phys" and (reference / "SF" / "scenario.phys").read_text().startswith("scenario SF")
    task = json.loads((reference / "SFLB" / "2.json").read_text())
    assert task["seed"] == 2 and task["trace"] == rows[6]["trace"] and "seconds" not in task
    readme = (reference / "README.md").read_text()
    assert "8 tasks of 2 scenarios: 8 generated" in readme and "| SFLB (Single Force Left Blocked) | angrybirds | 2 | 4 | 4 | 0 | 0 |" in readme
    assert "physc generate" in readme and "pd.read_parquet" in readme and "@inproceedings" in readme


def test_a_dataset_loads_in_hugging_face_datasets_as_it_is(reference, monkeypatch):
    """The README is a dataset card: its YAML names the manifest, so the folder loads as it is."""
    datasets = pytest.importorskip("datasets")
    monkeypatch.setenv("HF_HUB_OFFLINE", "1")
    monkeypatch.setenv("HF_DATASETS_OFFLINE", "1")
    monkeypatch.setenv("HF_DATASETS_CACHE", str(reference.parent / "hf-cache"))
    tasks = datasets.load_dataset(str(reference), split="test")
    assert tasks.num_rows == 8 and tasks[0]["scenario"] == "SF" and tasks[0]["solution"]["node"] == "Solution"
    assert tasks[4]["sequence_terms"][0].startswith("hit(bird")
    card = (reference / "README.md").read_text().split("---\n")[1]
    assert "license: mit" in card and "path: manifest.parquet" in card


def test_two_datasets_in_folders_of_one_name_each_load_as_themselves(reference, tmp_path, monkeypatch):
    """Hugging Face keys its cache by the folder's name and the card's configuration: the card
    names its configuration after what the dataset holds, so a second `ds` is not the first."""
    datasets = pytest.importorskip("datasets")
    from physc.dataset import manifest, readme

    monkeypatch.setenv("HF_HUB_OFFLINE", "1")
    monkeypatch.setenv("HF_DATASETS_OFFLINE", "1")
    monkeypatch.setenv("HF_DATASETS_CACHE", str(tmp_path / "hf-cache"))
    rows = [json.loads(line) for line in (reference / "manifest.jsonl").read_text().splitlines()]
    first, second = tmp_path / "a" / "ds", tmp_path / "b" / "ds"
    shutil.copytree(reference, first)
    shutil.copytree(reference, second)
    manifest.write_parquet(second, rows[:2])  # a smaller dataset in a folder of the same name
    card = (second / "README.md").read_text()
    (second / "README.md").write_text(card.replace(readme.config_name(rows), readme.config_name(rows[:2])))
    assert readme.config_name(rows) in card
    assert datasets.load_dataset(str(first), split="test").num_rows == 8
    assert datasets.load_dataset(str(second), split="test").num_rows == 2


def test_the_readme_shows_no_absolute_path(tmp_path, monkeypatch):
    from physc.commands.running import command_arguments, reproducing_command

    monkeypatch.setattr(sys, "argv", ["physc", "--color", "never", "generate", "/home/me/x.phys", "--out", "/home/me/data/set", "--jobs", "2"])
    assert reproducing_command("generate", command_arguments("generate", [])) == "physc generate x.phys --out set"
    monkeypatch.setattr(sys, "argv", ["physc", "generate", "a.phys", "--out=/srv/d/", "--format", "json"])
    assert reproducing_command("generate", command_arguments("generate", [])) == "physc generate a.phys --out=d"


def test_local_processes_and_a_dask_cluster_make_the_same_dataset(reference, tmp_path):
    run = run_physc("generate", SF, F, "--tasks", "4", "--out", tmp_path / "dataset", "--jobs", "2", "-q")
    assert run.status == 0, run.stderr
    assert dataset(tmp_path / "dataset") == dataset(reference)
    run = run_physc("generate", SF, F, "--tasks", "4", "--out", tmp_path / "dask" / "dataset", "--dask-workers", "2", "-q")
    assert run.status == 0, run.stderr
    assert dataset(tmp_path / "dask" / "dataset") == dataset(reference)


def test_a_killed_client_resumes(reference, tmp_path):
    folder = tmp_path / "dataset"
    process = generate(SF, F, "--tasks", "4", "--out", folder, "--dask-workers", "2")
    wait_for_rows(folder, 2, process)
    os.killpg(process.pid, signal.SIGKILL)  # the client and the cluster it started
    process.wait()
    assert rows_written(folder) < 8
    run = run_physc("generate", SF, F, "--tasks", "4", "--out", folder)
    assert run.status == 0, run.stderr
    assert "resuming:" in run.stderr
    assert dataset(folder) == dataset(reference)


def test_a_killed_worker_loses_no_task_and_duplicates_none(reference, tmp_path):
    folder = tmp_path / "dataset"
    process = generate(SF, F, "--tasks", "4", "--out", folder, "--dask-workers", "2")
    wait_for_rows(folder, 1, process)
    workers = [p for p in psutil.Process(process.pid).children() if "resource_tracker" not in " ".join(p.cmdline())]
    assert workers, "no worker process"
    workers[0].kill()  # by its PID, in the middle of the run
    out, err = process.communicate(timeout=300)
    assert process.returncode == 0, err.decode()
    assert dataset(folder) == dataset(reference)
    keys = [(r["scenario"], r["seed"]) for r in map(json.loads, (folder / "manifest.jsonl").read_text().splitlines())]
    assert len(keys) == len(set(keys)) == 8


def test_a_torn_manifest_and_a_lost_file_are_made_again(reference, tmp_path):
    folder = tmp_path / "dataset"
    assert run_physc("generate", SF, "--tasks", "3", "--out", folder, "-q").status == 0
    lines = (folder / "manifest.jsonl").read_text().splitlines()
    (folder / "manifest.jsonl").write_text(lines[0] + "\n" + lines[1] + "\n" + lines[2][:50])  # killed while writing
    (folder / "SF" / "1.xml").unlink()
    run = run_physc("generate", SF, "--tasks", "3", "--out", folder)
    assert run.status == 0 and "resuming: 1 of 3 tasks already done" in run.stderr
    files, rows = dataset(folder)
    assert [r["seed"] for r in rows] == [0, 1, 2] and "SF/1.xml" in files


def test_a_full_disk_stops_with_a_clear_error_and_keeps_what_was_done(tmp_path, monkeypatch):
    from physc.dataset import build
    from physc.files import OutputError, write_atomic

    written = []

    def filling(path, data):
        if len(written) == 7:  # the scenario's copy, three files for each of two tasks (level, task, examples), then the third task's first file
            raise OutputError(path, OSError(errno.ENOSPC, os.strerror(errno.ENOSPC)))
        written.append(path)
        write_atomic(path, data)

    monkeypatch.setattr(build, "write_atomic", filling)
    folder = tmp_path / "dataset"
    run = run_physc("generate", SF, "--tasks", "4", "--out", folder, "-q")
    assert run.status == 2 and "Traceback" not in run.stderr
    assert "No space left on device" in run.stderr and "the 2 tasks finished so far are kept" in run.stderr
    assert rows_written(folder) == 2 and not (folder / "manifest.parquet").exists()
    monkeypatch.undo()
    run = run_physc("generate", SF, "--tasks", "4", "--out", folder)
    assert run.status == 0 and "resuming: 2 of 4 tasks already done" in run.stderr


def test_an_unreachable_scheduler_is_a_usage_error_within_seconds(tmp_path):
    started = time.monotonic()
    run = run_physc("generate", SF, "--tasks", "1", "--out", tmp_path / "d", "--scheduler", "tcp://127.0.0.1:9")
    assert run.status == 2 and "cannot reach the Dask scheduler at tcp://127.0.0.1:9" in run.stderr
    assert time.monotonic() - started < 15 and "Traceback" not in run.stderr
    assert not (tmp_path / "d").exists() or not any((tmp_path / "d").iterdir())


def test_an_unwritable_folder_is_a_usage_error(tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("")
    run = run_physc("generate", SF, "--tasks", "1", "--out", blocker / "dataset")
    assert run.status == 2 and "cannot write" in run.stderr and "Traceback" not in run.stderr


def test_without_dask_a_clear_message(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "distributed", None)
    run = run_physc("generate", SF, "--tasks", "1", "--out", tmp_path, "--dask-workers", "2")
    assert run.status == 2 and "pip install -e '.[dask]'" in run.stderr


def test_one_executor_at_a_time_and_unique_scenario_names(tmp_path):
    run = run_physc("generate", SF, "--out", tmp_path, "--jobs", "2", "--dask-workers", "2")
    assert run.status == 2 and "not allowed with argument" in run.stderr
    run = run_physc("generate", SF, EXAMPLES / "paper" / "all.paper.phys", "--tasks", "1", "--out", tmp_path)
    assert run.status == 2 and "two files have a scenario named 'SF'" in run.stderr


def test_eval_on_a_dask_cluster_gives_the_same_records(tmp_path):
    def records(folder):
        found = [json.loads(line) for line in (folder / "records.jsonl").read_text().splitlines()]
        return sorted(json.dumps({k: v for k, v in r.items() if k != "generation_seconds"}, sort_keys=True) for r in found)

    assert run_physc("eval", SF, "--tasks", "2", "--out", tmp_path / "one", "-q").status == 0
    assert run_physc("eval", SF, "--tasks", "2", "--dask-workers", "2", "--out", tmp_path / "dask", "-q").status == 0
    assert records(tmp_path / "dask") == records(tmp_path / "one")


def _dies_once(marker: str) -> str:
    """A job whose first run kills its process (a worker lost to the out-of-memory killer)."""
    if not os.path.exists(marker):
        Path(marker).write_text("died")
        os.kill(os.getpid(), signal.SIGKILL)
    return marker


def test_local_processes_run_again_the_jobs_of_a_broken_pool(tmp_path):
    from physc.execution.local import LocalProcesses

    markers = [str(tmp_path / f"job{n}") for n in range(4)]
    kept = []
    LocalProcesses(2).map(_dies_once, markers, kept.append)
    assert sorted(kept) == sorted(markers)


def _always_dies(number: int) -> int:
    if number == 2:
        os.kill(os.getpid(), signal.SIGKILL)
    return number


def test_a_job_that_always_kills_its_worker_stops_the_run_clearly():
    from physc.execution import ExecutorError
    from physc.execution.local import RUNS, LocalProcesses

    kept = []
    with pytest.raises(ExecutorError, match=f"died {RUNS} times while running the job 2"):
        LocalProcesses(2).map(_always_dies, range(5), kept.append)
    assert 2 not in kept


@pytest.fixture(scope="module")
def cluster():
    """A Dask cluster that `physc generate --scheduler` connects to by its address."""
    import logging

    from distributed import LocalCluster

    with LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=logging.ERROR) as running:
        yield running


def test_an_existing_cluster_by_its_address(reference, cluster, tmp_path):
    run = run_physc("generate", SF, "--tasks", "2", "--out", tmp_path / "dataset", "--scheduler", cluster.scheduler_address, "-q")
    assert run.status == 0, run.stderr
    _, rows = dataset(tmp_path / "dataset")
    assert rows == dataset(reference)[1][:2]


def test_workers_with_other_physc_code_are_refused(cluster, tmp_path, monkeypatch):
    from physc import fingerprint

    monkeypatch.setattr(fingerprint, "code_fingerprint", lambda domain, backends=(): "other code")  # here, not in the workers
    run = run_physc("generate", SF, "--tasks", "1", "--out", tmp_path, "--scheduler", cluster.scheduler_address)
    assert run.status == 2 and "run other physc code than this machine" in run.stderr


@pytest.fixture
def separate_cluster(tmp_path):
    """A scheduler and a worker started by hand, as on a cluster: `dask scheduler` and `dask
    worker` processes, the worker in a folder of its own. Yields (address, start_worker)."""
    import json as json_
    import shutil
    import subprocess
    import time

    dask = shutil.which("dask")
    if dask is None:
        pytest.skip("the dask command is not installed")
    info = tmp_path / "scheduler.json"
    started = [subprocess.Popen([dask, "scheduler", "--scheduler-file", str(info), "--port", "0", "--dashboard-address", ":0"], stderr=subprocess.DEVNULL)]
    for _ in range(300):
        if info.exists() and info.read_text().strip():
            break
        time.sleep(0.1)
    address = json_.loads(info.read_text())["address"]

    def start_worker(folder: Path) -> None:
        folder.mkdir(parents=True, exist_ok=True)
        started.append(subprocess.Popen([dask, "worker", address, "--nthreads", "1", "--no-dashboard"], cwd=folder, stderr=subprocess.DEVNULL))

    yield address, start_worker
    for process in reversed(started):
        process.terminate()
        process.wait(timeout=30)


def test_a_worker_in_another_folder_makes_the_scenario_it_was_sent(reference, separate_cluster, tmp_path, monkeypatch):
    """Jobs carry the scenario's text: a worker started elsewhere, where the relative path is
    missing or names another file, makes the client's scenario."""
    address, start_worker = separate_cluster
    elsewhere = tmp_path / "worker"
    (elsewhere / "paper").mkdir(parents=True)
    (elsewhere / "paper" / "01_SF.phys").write_text((EXAMPLES / "paper" / "02_SFTB.phys").read_text().replace("SFTB", "SF"))
    start_worker(elsewhere)
    monkeypatch.chdir(EXAMPLES)
    run = run_physc("generate", "paper/01_SF.phys", "--tasks", "2", "--out", tmp_path / "dataset", "--scheduler", address, "-q")
    assert run.status == 0, run.stderr
    _, rows = dataset(tmp_path / "dataset")
    made = [{k: v for k, v in row.items() if k != "file"} for row in rows]
    assert made == [{k: v for k, v in row.items() if k != "file"} for row in dataset(reference)[1][:2]]


def test_a_scheduler_without_workers_is_said_and_given_up(separate_cluster, tmp_path, monkeypatch):
    from physc.execution import dask as dask_executor

    address, _ = separate_cluster
    monkeypatch.setattr(dask_executor, "WORKER_WAIT", 2.0)
    run = run_physc("generate", SF, "--tasks", "1", "--out", tmp_path / "d", "--scheduler", address)
    assert "has no workers; waiting up to 2 s" in run.stderr
    assert run.status == 2 and "none joined in 2 s" in run.stderr and "dask worker" in run.stderr


def test_a_cluster_started_here_serves_its_dashboard():
    """physc[dask] brings bokeh, so --dask-workers' cluster has a real dashboard, named in the first progress line."""
    pytest.importorskip("bokeh")
    from physc.execution.dask import DaskCluster

    with DaskCluster(workers=1) as cluster:
        assert "dashboard http://127.0.0.1:" in cluster.describe()


def test_the_readme_command_is_physcs_own_command_line(monkeypatch):
    from physc.commands.running import command_arguments

    monkeypatch.setattr(sys, "argv", ["pytest", "-q", "tests/x.py", "-k", "generate"])  # physc run in another program
    assert command_arguments("generate", ["a.phys"]) == ["a.phys"]
    monkeypatch.setattr(sys, "argv", ["physc", "--traceback", "--color=never", "generate", "b.phys"])
    assert command_arguments("generate", []) == ["b.phys"]


def test_an_object_whose_fields_change_type_is_json_text_in_parquet(tmp_path):
    """A plugin's solution may hold a field that is a number in one task and a word in
    another: the Parquet manifest still writes (that column as JSON text)."""
    from physc.dataset import manifest

    rows = [{"scenario": "S", "seed": 0, "solution": {"at": 1.5}}, {"scenario": "S", "seed": 1, "solution": {"at": "top"}}]
    manifest.write_parquet(tmp_path, rows)
    table = pd.read_parquet(tmp_path / "manifest.parquet")
    assert [json.loads(v) for v in table["solution"]] == [{"at": 1.5}, {"at": "top"}]
