"""The manifest of a dataset: one row per task, as JSON Lines while the run goes and at the end
in task order, and as Parquet.

`manifest.jsonl` is appended a row as each task finishes (flushed), after the task's files were
written whole, so a killed run loses no finished task and a torn last line stands for a task to
make again. At the end both files are written whole in the order of the jobs, so they do not
depend on the order in which tasks finished. In Parquet the fields that are objects (the solution,
the times of each stage, the settings) are JSON text; every other field is a typed column.
"""

from __future__ import annotations

import json
from pathlib import Path

from physc.files import read_json_lines, write_atomic

JSONL = "manifest.jsonl"
PARQUET = "manifest.parquet"

# The columns, in order, with their Arrow types ("json": an object written as JSON text).
COLUMNS = [
    ("file", "string"), ("scenario", "string"), ("seed", "int64"), ("domain", "string"), ("title", "string"),
    ("interactions", "int32"), ("sequence", "string"), ("outcome", "string"), ("reason", "string"),
    ("level", "string"), ("task", "string"), ("picture", "string"), ("solution", "json"), ("trace", "string"),
    ("robustness_passed", "int32"), ("robustness_run", "int32"), ("validated", "bool_"), ("layouts_tried", "int32"),
    ("simulations", "int64"), ("accidental", "float64"), ("agent_plays", "int32"), ("auccess", "float64"),
    ("generation_seconds", "float64"), ("seconds", "json"), ("settings", "json"),
]


def key(row: dict) -> tuple[str, str, int]:
    return (row["file"], row["scenario"], row["seed"])


def read(folder: Path) -> dict:
    """The rows already written, by task (the last row of a task wins; a torn line is skipped)."""
    rows = {}
    for row in read_json_lines(folder / JSONL):
        try:
            rows[key(row)] = row
        except (KeyError, TypeError):  # not a row of ours
            continue
    return rows


def line(row: dict) -> str:
    return json.dumps(row, sort_keys=True, ensure_ascii=False) + "\n"


def write_jsonl(folder: Path, rows: list[dict]) -> None:
    write_atomic(folder / JSONL, "".join(line(row) for row in rows))


def write_parquet(folder: Path, rows: list[dict]) -> None:
    """The rows as a Parquet table with the columns of COLUMNS (written whole)."""
    import io

    import pyarrow as pa
    import pyarrow.parquet as pq

    arrays, fields = [], []
    for name, kind in COLUMNS:
        values = [row.get(name) for row in rows]
        if kind == "json":
            values = [None if v is None else json.dumps(v, sort_keys=True, ensure_ascii=False) for v in values]
            kind = "string"
        fields.append(pa.field(name, getattr(pa, kind)()))
        arrays.append(pa.array(values, type=fields[-1].type))
    table = pa.Table.from_arrays(arrays, schema=pa.schema(fields))
    buffer = io.BytesIO()
    pq.write_table(table, buffer)
    write_atomic(folder / PARQUET, buffer.getvalue())
