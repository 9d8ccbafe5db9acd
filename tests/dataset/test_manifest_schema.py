"""One manifest schema whatever the settings: two datasets made with different settings, or whose
tasks passed different stages, concatenate in Arrow; JSON Lines and Parquet have the same
columns (issue 55)."""

from __future__ import annotations

import json

import pyarrow as pa
import pyarrow.parquet as pq

from physc.dataset import manifest


def row(seed: int, verify_backend, accept: bool) -> dict:
    settings = {
        "acceptance": True, "accidental": False, "backend": "box2d", "code": "c", "layouts": 160, "min_robustness": None,
        "physc": "0.1.0", "picture": False, "scenario": "f", "time_budget": 120.0, "validate": True, "verify_backend": verify_backend, "world": "",
    }
    seconds = {"layout": 0.1, "satisfy": 1.0, "distract": 0.0, "validate": 0.2, "total": 1.3} | ({"accept": 2.0} if accept else {})
    return {"file": "f.phys", "scenario": "F", "seed": seed, "domain": "angrybirds", "settings": settings, "seconds": seconds, "generation_seconds": 1.3}


def test_datasets_made_with_different_settings_concatenate(tmp_path):
    for name, verify, accept in (("a", None, False), ("b", "pymunk", True)):
        (tmp_path / name).mkdir()
        manifest.write_parquet(tmp_path / name, [row(0, verify, accept), row(1, verify, accept)])
    a, b = (pq.read_table(tmp_path / name / manifest.PARQUET) for name in "ab")
    assert a.schema == b.schema
    both = pa.concat_tables([a, b])
    assert both.column("settings").type.field("verify_backend").type == pa.string()
    assert [s["verify_backend"] for s in both.column("settings").to_pylist()] == [None, None, "pymunk", "pymunk"]
    assert [s["accept"] for s in both.column("seconds").to_pylist()] == [None, None, 2.0, 2.0]


def test_json_lines_and_parquet_have_the_same_columns(tmp_path):
    rows = [row(0, None, False)]
    manifest.write_jsonl(tmp_path, rows)
    manifest.write_parquet(tmp_path, rows)
    (line,) = (tmp_path / manifest.JSONL).read_text().splitlines()
    assert set(json.loads(line)) == set(pq.read_table(tmp_path / manifest.PARQUET).column_names) == {name for name, _ in manifest.COLUMNS}
