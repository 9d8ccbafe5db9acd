"""PHYRE's own formats: task ids, TaskCollections in binary Thrift, observations, features,
folds, and the `phyre/` folder of a generated dataset."""

from __future__ import annotations

import hashlib
import json
import lzma
import math
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest
from physc_phyre import folds, observation, phyre_format
from test_phyre_plugin import EXAMPLES, physc

PHYRE_IDS = (Path(__file__).parent / "data" / "phyre_ball_task_ids.txt").read_text().split()


@pytest.fixture(scope="module")
def dataset(tmp_path_factory):
    out = tmp_path_factory.mktemp("dataset")
    status, _, err = physc(
        "generate",
        EXAMPLES / "01_ledge.phys",
        EXAMPLES / "02_jar.phys",
        "--tasks",
        "3",
        "--no-acceptance",
        "--out",
        out,
        "-q",
    )
    assert status == 0, err
    return out


def task_of(dataset, scenario="Ledge", seed=0) -> dict:
    return json.loads((dataset / scenario / f"{seed}.level.json").read_text())


def test_task_ids_and_their_files_are_phyres():
    assert phyre_format.task_id(12, 4) == "00012:004"
    assert phyre_format.collection_file("00012:004") == "tasks.bin.lzma"
    assert phyre_format.collection_file("01003:000") == "tasks01.bin.lzma"
    with pytest.raises(ValueError, match="instance below 1000"):
        phyre_format.task_id(0, 1000)


def test_a_task_written_as_a_task_collection_and_read_back_is_the_same_task(dataset):
    task = task_of(dataset)
    task.pop("physc")
    task["taskId"] = "00000:000"
    data = phyre_format.collection_bytes([task])
    assert data[:6] == b"\xfd7zXZ\x00"  # an XZ stream, as lzma.open(path, "w") writes
    raw = lzma.decompress(data)
    # TaskCollection field 1, a list of structs; Task field 1, the id; field 2, the scene; the
    # scene's field 1, a list of bodies; the first body's position x = 128.0 (the bottom wall)
    assert raw[:3] == b"\x0f\x00\x01" and raw[3] == 12
    assert raw[8:24] == b"\x0b\x00\x01\x00\x00\x00\x0900000:000"
    assert raw[24:27] == b"\x0c\x00\x02"
    assert phyre_format.read_collection(data) == [task]
    with pytest.raises(ValueError, match="its own PHYRE task id"):
        phyre_format.collection_bytes([task, task])


def test_the_picture_fills_the_pixels_whose_centres_lie_inside_with_row_0_at_the_bottom():
    ball = {"position": {"x": 100.3, "y": 20.7}, "angle": 0.0, "color": 2, "shapes": [{"circle": {"radius": 10.0}}]}
    half = {"x": 20.0, "y": 2.56}
    bar = {
        "position": {"x": 50.0, "y": 200.0},
        "angle": math.pi / 2,
        "color": 6,
        "shapes": [
            {
                "polygon": {
                    "vertices": [
                        {"x": -half["x"], "y": -half["y"]},
                        {"x": half["x"], "y": -half["y"]},
                        {"x": half["x"], "y": half["y"]},
                        {"x": -half["x"], "y": half["y"]},
                    ]
                }
            }
        ],
    }
    task = {"scene": {"width": 256, "height": 256, "bodies": [ball, bar]}}
    image = observation.raster(task, (30.0, 30.0, 5.0))
    assert image.shape == (256, 256) and image.dtype == np.uint8
    inside = {(x, y) for x in range(256) for y in range(256) if (x + 0.5 - 100.3) ** 2 + (y + 0.5 - 20.7) ** 2 <= 100}
    assert {(x, y) for y, x in zip(*np.nonzero(image == 2), strict=True)} == inside
    assert image[20, 100] == 2 and image[255 - 20, 100] == 0  # y up: row 20 is 20 px above the bottom
    # the bar turned upright: 5.12 px wide, 40 px tall, about (50, 200)
    rows, columns = np.nonzero(image == 6)
    assert (rows.min(), rows.max() + 1, columns.min(), columns.max() + 1) == (
        180,
        220,
        47,
        53,
    )  # columns lrint(47.44) .. lrint(52.56)
    assert image[30, 30] == 1  # the agent's ball, red, drawn last


def test_features_are_phyres_fourteen_numbers_with_the_agents_ball_last(dataset):
    task = task_of(dataset, "Jar")
    rows = observation.features(task, (64.0, 128.0, 8.0))
    shaped = [b for b in task["scene"]["bodies"] if b["shapeType"]]
    assert rows.shape == (len(shaped) + 1, 14) and rows.dtype == np.float32
    assert rows[-1].tolist() == pytest.approx([0.25, 0.5, 0.0, 16 / 256, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0])
    for row, body in zip(rows, shaped, strict=False):
        assert row[3] == pytest.approx(body["diameter"] / 256)
        assert (
            row[4 + body["shapeType"] - 1] == 1
            and row[8 + body["color"] - 1] == 1
            and row.sum() == pytest.approx(row[:4].sum() + 2)
        )
        if body["shapeType"] == 3:  # a jar: at its centre of mass, above the middle of its base
            assert row[1] * 256 > body["position"]["y"] + 1


def test_folds_split_phyres_own_tasks_as_phyre_does():
    """PHYRE's 2,500 ball-tier task ids split as PHYRE's get_fold splits them (the templates of
    dev and test per seed; fingerprints of the within-template lists; docs/phyre-sources.md 4.7)."""

    def templates(ids):
        return sorted({t[:5] for t in ids})

    train, dev, test = folds.fold("cross_template", PHYRE_IDS, 0)
    assert (len(train), len(dev), len(test)) == (1600, 400, 500)
    assert templates(dev) == ["00000", "00008", "00011", "00018"]
    assert templates(test) == ["00003", "00004", "00014", "00015", "00019"]
    assert templates(folds.fold("cross_template", PHYRE_IDS, 9)[2]) == ["00002", "00007", "00012", "00019", "00021"]
    fingerprint = lambda ids: hashlib.md5(" ".join(ids).encode()).hexdigest()[:12]  # noqa: E731
    assert [fingerprint(part) for part in folds.fold("within_template", PHYRE_IDS, 0)] == [
        "751581e5e8e6",
        "25df5a7b2a57",
        "d3bb9497eb44",
    ]
    with pytest.raises(ValueError, match="no evaluation setup"):
        folds.fold("ball_cross", PHYRE_IDS, 0)


def test_a_generated_dataset_holds_phyres_benchmark(dataset, tmp_path):
    phyre = dataset / "phyre"
    assert sorted(p.name for p in phyre.glob("*.bin.lzma")) == ["tasks50.bin.lzma"]  # not PHYRE's own tasks.bin.lzma
    tasks = phyre_format.read_collection((phyre / "tasks50.bin.lzma").read_bytes())
    ids = [t["taskId"] for t in tasks]
    assert ids == [
        "50000:000",
        "50000:001",
        "50000:002",
        "50001:000",
        "50001:001",
        "50001:002",
    ]  # Ledge, then Jar; seeds in order
    assert all(phyre_format.collection_file(t) == "tasks50.bin.lzma" for t in ids)
    first = task_of(dataset)
    first.pop("physc")
    assert first.pop("solutions")  # physc's task file has the intended ball; PHYRE's tasks never do
    assert tasks[0] == {**first, "taskId": "50000:000"}
    assert not [t for t in tasks if "solutions" in t]
    observations = np.load(phyre / "observations.npy")
    assert observations.shape == (6, 256, 256) and observations.dtype == np.uint8
    assert np.array_equal(observations[0], observation.raster(first))
    table = pq.read_table(phyre / "tasks.parquet").to_pylist()
    assert [r["task_id"] for r in table] == ids and [r["seed"] for r in table] == [0, 1, 2, 0, 1, 2]
    assert table[0]["action"] == pytest.approx(task_of(dataset)["physc"]["actions"][0])
    assert len(table[0]["features"][0]) == 14
    fold_file = json.loads((phyre / "folds.json").read_text())
    assert list(fold_file) == ["ball_cross_template", "ball_within_template"]  # PHYRE's setup names, the tiers present
    assert set(fold_file["ball_within_template"]) == {str(s) for s in range(10)}
    # the same command again, in another folder: the same bytes
    assert (
        physc(
            "generate",
            EXAMPLES / "01_ledge.phys",
            EXAMPLES / "02_jar.phys",
            "--tasks",
            "3",
            "--no-acceptance",
            "--out",
            tmp_path,
            "-q",
        )[0]
        == 0
    )
    for path in phyre.iterdir():
        assert (tmp_path / "phyre" / path.name).read_bytes() == path.read_bytes(), path.name


ANSWERS: dict[str, list[float]] = {}
FITTED: list[list[str]] = []


def oracle(seen):
    """An agent that knows the intended actions (read by the test from tasks.parquet)."""
    yield (2.0, 0.5, 0.5)  # invalid: not counted
    yield ANSWERS[seen.task_id]


class Learner:
    def fit(self, observations):
        FITTED.append(sorted(o.task_id for o in observations))

    def __call__(self, seen):
        assert "solutions" not in seen.task and seen.image.shape == (256, 256)
        return iter([ANSWERS[seen.task_id]])


def failing(seen):
    raise ZeroDivisionError("no idea")


def test_an_agent_is_scored_by_phyres_auccess_on_the_folds(dataset, tmp_path, monkeypatch):
    """The intended action, given in PHYRE's [0, 1]³, solves every task at the first valid
    attempt (AUCCESS 1); an agent with `fit` sees the fold's train and dev tasks first."""
    monkeypatch.syspath_prepend(str(Path(__file__).parent))
    ANSWERS.update({r["task_id"]: r["action"] for r in pq.read_table(dataset / "phyre" / "tasks.parquet").to_pylist()})
    status, _, err = physc(
        "eval",
        "--agent",
        "test_phyre_format:oracle",
        dataset,
        "--setup",
        "ball_within_template",
        "--folds",
        "2",
        "--out",
        tmp_path / "o",
        "-q",
    )
    assert status == 0, err
    scored = json.loads((tmp_path / "o" / "agent.json").read_text())
    assert (
        scored["auccess"] == 1.0
        and scored["folds"]["0"]["tasks"] == 2
        and set(scored["folds"]["1"]["templates"]) == {"50000", "50001"}
    )
    FITTED.clear()
    assert (
        physc(
            "eval",
            "--agent",
            "test_phyre_format:Learner",
            dataset,
            "--setup",
            "ball_within_template",
            "--folds",
            "1",
            "--out",
            tmp_path / "l",
            "-q",
        )[0]
        == 1
    )
    # a class is not an agent until made: the class itself, called, returns an instance, not actions
    learner = "test_phyre_format:LEARNER"
    globals()["LEARNER"] = Learner()
    status, _, err = physc(
        "eval",
        "--agent",
        learner,
        dataset,
        "--setup",
        "ball_within_template",
        "--folds",
        "1",
        "--out",
        tmp_path / "l",
        "-q",
    )
    assert status == 0, err
    train, dev, test = folds.fold("within_template", [t for t in ANSWERS], 0)
    assert FITTED[-1] == sorted(train + dev)


def test_a_random_agent_scores_as_physcs_own_evaluation_counts(dataset, tmp_path):
    status, _, err = physc(
        "eval",
        "--agent",
        "physc_phyre.agents:random_agent",
        dataset,
        "--setup",
        "ball_within_template",
        "--folds",
        "1",
        "--out",
        tmp_path,
        "-q",
    )
    assert status == 0, err
    scored = json.loads((tmp_path / "agent.json").read_text())
    assert 0.0 <= scored["auccess"] <= 1.0 and scored["split"] == "test"


@pytest.mark.parametrize(
    "agent, message",
    [
        ("no_such_module_here:agent", "cannot import the agent's module"),
        ("test_phyre_format:missing", "has no 'missing'"),
        ("test_phyre_format:failing", "the agent raised ZeroDivisionError on task"),
        ("justaname", "MODULE:NAME"),
    ],
)
def test_a_broken_agent_is_the_agents_error_not_physcs(dataset, tmp_path, monkeypatch, agent, message):
    monkeypatch.syspath_prepend(str(Path(__file__).parent))
    status, _, err = physc(
        "eval", "--agent", agent, dataset, "--folds", "1", "--setup", "ball_within_template", "--out", tmp_path, "-q"
    )
    assert status == 1 and message in err and "Traceback" not in err


def test_a_setup_the_dataset_has_no_folds_for_is_a_clear_error(dataset, tmp_path):
    status, _, err = physc(
        "eval",
        "--agent",
        "physc_phyre.agents:random_agent",
        dataset,
        "--setup",
        "two_balls_cross_template",
        "--out",
        tmp_path,
        "-q",
    )
    assert (
        status == 2
        and "no evaluation setup 'two_balls_cross_template'" in err
        and "ball_cross_template, ball_within_template" in err
    )
    assert "Traceback" not in err


def test_a_dataset_without_its_benchmark_files_is_a_clear_error(dataset, tmp_path):
    broken = tmp_path / "broken"
    broken.mkdir()
    (broken / "manifest.jsonl").write_text((dataset / "manifest.jsonl").read_text())
    status, _, err = physc("eval", "--agent", "physc_phyre.agents:random_agent", broken, "--out", tmp_path / "out")
    assert status == 2 and "cannot read the dataset" in err and "Traceback" not in err
    status, _, err = physc(
        "eval", "--agent", "physc_phyre.agents:random_agent", tmp_path / "nowhere", "--out", tmp_path / "out"
    )
    assert status == 2 and "one dataset folder" in err
    other = tmp_path / "angrybirds"
    other.mkdir()
    (other / "manifest.jsonl").write_text(
        json.dumps({"file": "f", "scenario": "S", "seed": 0, "domain": "angrybirds", "level": "S/0.xml"}) + "\n"
    )
    status, _, err = physc("eval", "--agent", "physc_phyre.agents:random_agent", other, "--out", tmp_path / "out")
    assert status == 2 and "scores no agent" in err


def test_a_template_with_more_tasks_than_phyres_ids_allow_keeps_its_tasks_and_says_why(tmp_path, monkeypatch):
    monkeypatch.setattr(phyre_format, "INSTANCES", 1)  # PHYRE's ids allow 1,000 instances a template
    status, _, err = physc(
        "generate", EXAMPLES / "01_ledge.phys", "--tasks", "2", "--no-acceptance", "--out", tmp_path, "-q"
    )
    assert status == 2 and "not the domain's own benchmark files" in err and "instance ids have three digits" in err
    assert (tmp_path / "README.md").is_file() and (tmp_path / "manifest.parquet").is_file()
