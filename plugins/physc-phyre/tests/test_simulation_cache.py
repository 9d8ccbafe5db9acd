"""PHYRE's simulation cache of a generated dataset (`python -m physc_phyre.cache`): PHYRE's
actions, PHYRE's file (keys, dtypes, shapes, compression), the domain's statuses, the same
bytes on any number of workers, and clear refusals of bad input."""

from __future__ import annotations

import contextlib
import io
import json
import math
import subprocess
import sys

import joblib
import numpy as np
import pyarrow.parquet as pq
import pytest
from physc_phyre import DOMAIN, simulation_cache
from physc_phyre.actions import from_unit, placeable
from physc_phyre.cache import main
from test_phyre_plugin import EXAMPLES, physc

from physc.simulation.ending import Ending

ACTIONS = 20


def cache(*args) -> tuple[int, str]:
    err = io.StringIO()
    with contextlib.redirect_stderr(err):
        try:
            status = main([str(a) for a in args])
        except SystemExit as exit_:  # argparse's refusals
            status = exit_.code
    return status, err.getvalue()


@pytest.fixture(scope="module")
def dataset(tmp_path_factory):
    """A dataset with a task of each tier, and its cache of ACTIONS actions."""
    out = tmp_path_factory.mktemp("cached")
    status, _, err = physc(
        "generate",
        EXAMPLES / "01_ledge.phys",
        EXAMPLES / "07_two_balls.phys",
        "--tasks",
        "1",
        "--no-acceptance",
        "--out",
        out,
        "-q",
    )
    assert status == 0, err
    status, err = cache(out, "--actions", ACTIONS, "-q")
    assert status == 0, err
    return out


def path(dataset, tier: str, actions: int = ACTIONS):
    return dataset / "phyre" / "cache" / "offline_simulation" / str(actions) / tier / "simulation_cache.gz"


def phyres_pool(balls: int, count: int) -> np.ndarray:
    """save_action_space.py's actions, written out here: seed 42, `uniform(size=3·balls)` until
    the mapper places every ball inside the scene (two balls r1 + r2 + 1 px apart), float32."""
    rng, out = np.random.RandomState(seed=42), []
    while len(out) < count:
        a = rng.uniform(size=3 * balls)
        balls_ = [(a[i] * 255, a[i + 1] * 255, 2 + a[i + 2] * 30) for i in range(0, 3 * balls, 3)]
        inside = all(r <= x <= 256 - r and r <= y <= 256 - r for x, y, r in balls_)
        if len(balls_) == 2:
            (x1, y1, r1), (x2, y2, r2) = balls_
            inside = inside and math.hypot(x1 - x2, y1 - y2) >= r1 + r2 + 1
        if inside:
            out.append(a)
    return np.array(out, "float32")


def test_the_actions_are_phyres_pool_of_seed_42():
    ball = simulation_cache.pool("ball", 5)
    assert ball.dtype == np.float32 and ball.shape == (5, 3)
    assert np.array_equal(ball, phyres_pool(1, 5))
    # the first draw (0.375, 0.951, 0.732) puts a ball of r 24 at y 242: outside, drawn again
    assert ball[0].tolist() == pytest.approx([0.5986585, 0.1560186, 0.1559945], abs=1e-7)
    two = simulation_cache.pool("two_balls", 5)
    assert two.shape == (5, 6) and np.array_equal(two, phyres_pool(2, 5))
    assert np.array_equal(simulation_cache.pool("ball", 3), ball[:3])  # a smaller cache is a prefix


def test_the_file_is_phyres(dataset, tmp_path):
    ids = pq.read_table(dataset / "phyre" / "tasks.parquet", columns=["task_id", "tier"]).to_pylist()
    for tier, balls in (("ball", 1), ("two_balls", 2)):
        data = path(dataset, tier).read_bytes()
        assert data[:4] == b"\x1f\x8b\x08\x00" and data[4:8] == b"\0\0\0\0"  # gzip, no time stamp
        loaded = joblib.load(path(dataset, tier))
        assert list(loaded) == ["statuses_per_task", "actions"]
        assert loaded["actions"].dtype == np.float32 and loaded["actions"].shape == (ACTIONS, 3 * balls)
        assert np.array_equal(loaded["actions"], phyres_pool(balls, ACTIONS))
        statuses = loaded["statuses_per_task"]
        assert list(statuses) == [r["task_id"] for r in ids if simulation_cache.TIERS[r["tier"]] == tier]
        for array in statuses.values():
            assert array.dtype == np.int8 and array.shape == (ACTIONS,) and set(array.tolist()) <= {-1, 0, 1}
        # the bytes PHYRE's compress_partial_simuations.py writes: joblib.dump to a .gz name
        joblib.dump(loaded, tmp_path / "phyre.gz")
        assert (tmp_path / "phyre.gz").read_bytes() == data


def test_the_statuses_are_the_domains(dataset):
    from physc.serialize import from_data

    rows = pq.read_table(dataset / "phyre" / "tasks.parquet", columns=["task_id", "task", "tier"]).to_pylist()
    classes = {c.__name__: c for c in DOMAIN.files.level_classes}
    for row in rows:
        loaded = joblib.load(path(dataset, simulation_cache.TIERS[row["tier"]]))
        level = from_data(json.loads((dataset / row["task"]).read_text())["level"], classes)
        statuses = loaded["statuses_per_task"][row["task_id"]]
        for i in range(0, ACTIONS, 4):
            action = from_unit(loaded["actions"][i])
            if action is None or not all(
                placeable(level, ball) for ball in action.balls
            ):  # PHYRE's mapper, then occlusion
                expected = 0
            else:
                expected = 1 if DOMAIN.play(level, action, ending=Ending.OUTCOME).solved else -1
            assert statuses[i] == expected, (row["task_id"], i)


def test_two_balls_that_rounding_brings_closer_are_valid_as_in_phyre(dataset):
    """PHYRE's mapper tests r1 + r2 + 1 px before rounding to pixels, and its simulator then
    checks each ball against the scene's bodies only: action 630 of the two-ball pool rounds to
    balls 37.5 px apart, under r1 + r2 + 1 = 38, and is still simulated."""
    domain, level = simulation_cache.task_level(str(dataset / "TwoDrops" / "0.json"))
    action = simulation_cache.pool("two_balls", 631)[630]
    placed = from_unit(action)
    first, second = placed.balls
    assert math.hypot(first.x - second.x, first.y - second.y) < first.radius + second.radius + 1
    assert all(placeable(level, ball) for ball in placed.balls)
    expected = 1 if domain.play(level, placed, ending=Ending.OUTCOME).solved else -1
    assert simulation_cache.status(domain, level, action) == expected


def test_the_bytes_do_not_depend_on_the_workers(dataset, tmp_path):
    first = {tier: path(dataset, tier).read_bytes() for tier in ("ball", "two_balls")}
    status, err = cache(dataset, "--actions", ACTIONS, "--jobs", 2, "-q")
    assert status == 0, err
    assert {tier: path(dataset, tier).read_bytes() for tier in first} == first


@pytest.mark.parametrize(
    "args, message",
    [
        (["--actions", "0"], "from 1 to 100000"),
        (["--actions", "many"], "from 1 to 100000"),
        (["--actions", "100001"], "from 1 to 100000"),
        (["--jobs", "0"], "--jobs"),
    ],
)
def test_bad_options_exit_2(dataset, args, message):
    status, err = cache(dataset, *args)
    assert status == 2 and message in err


def test_a_folder_that_is_not_a_dataset_exits_2(tmp_path):
    status, err = cache(tmp_path / "absent", "-q")
    assert status == 2 and "no dataset folder" in err
    status, err = cache(tmp_path, "-q")
    assert status == 2 and "has no phyre/tasks.parquet" in err


def test_a_damaged_task_file_exits_2_with_no_traceback(dataset, tmp_path):
    import shutil

    copy = tmp_path / "copy"
    shutil.copytree(dataset, copy, ignore=shutil.ignore_patterns("cache"))
    task = next(p for p in sorted(copy.glob("Ledge/*.json")) if not p.name.endswith((".level.json", ".examples.json")))
    task.write_text("{not json")
    run = subprocess.run(
        [sys.executable, "-m", "physc_phyre.cache", str(copy), "--actions", "5"],
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 2, run.stderr
    assert "cannot read the task file" in run.stderr and "Traceback" not in run.stderr
    assert not (copy / "phyre" / "cache").exists()
