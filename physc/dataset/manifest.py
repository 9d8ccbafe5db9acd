"""The manifest of a dataset: one row per task, as JSON Lines while the run goes and at the end
in task order, and as Parquet.

`manifest.jsonl` is appended a row as each task finishes (flushed), after the task's files were
written whole, so a killed run loses no finished task and a torn last line stands for a task to
make again. At the end both files are written whole in the order of the jobs, so they do not
depend on the order in which tasks finished. In Parquet every field is a typed column: the
objects (the solution, the times of each stage, the settings) are structs and the interactions
lists, as in JSON Lines, so `datasets`, DuckDB and polars read the same fields either way (an
object whose fields change type from row to row, which a plugin's solution might, is JSON text).
"""

from __future__ import annotations

import json
from pathlib import Path

from physc.files import read_json_lines, write_atomic

JSONL = "manifest.jsonl"
PARQUET = "manifest.parquet"

# The columns, in order, with their Arrow types ("struct": an object, its fields' types read from
# the rows; "terms": a list of interactions in .phys syntax; "seeds": a list of seeds (the earlier
# tasks a task learned from: physc.dataset.waves); "settings" and "seconds": structs
# of fixed fields, so that datasets made with other settings, or whose tasks passed other
# stages, have the same schema and combine).
COLUMNS = [
    ("file", "string"),
    ("scenario", "string"),
    ("seed", "int64"),
    ("domain", "string"),
    ("world", "string"),
    ("backend", "string"),
    ("title", "string"),
    ("interactions", "int32"),
    ("sequence", "string"),
    ("sequence_terms", "terms"),
    ("outcome", "string"),
    ("reason", "string"),
    ("level", "string"),
    ("task", "string"),
    ("picture", "string"),
    ("examples", "string"),
    ("solution", "struct"),
    ("trace", "string"),
    ("trace_terms", "terms"),
    ("robustness_passed", "int32"),
    ("robustness_run", "int32"),
    ("validated", "bool_"),
    ("layouts_tried", "int32"),
    ("simulations", "int64"),
    ("accidental", "float64"),
    ("agent_plays", "int32"),
    ("auccess", "float64"),
    ("learned_from", "seeds"),
    ("generation_seconds", "float64"),
    ("seconds", "seconds"),
    ("settings", "settings"),
]
# A job's settings (physc.driver.job.Job.recorded), each field typed whether or not a run set it
# (its `learned_from` is the row's column of that name).
SETTINGS = (
    ("acceptance", "bool_"),
    ("accidental", "bool_"),
    ("backend", "string"),
    ("clause_budget", "int64"),
    ("code", "string"),
    ("layouts", "int64"),
    ("min_robustness", "int64"),
    ("physc", "string"),
    ("picture", "bool_"),
    ("scenario", "string"),
    ("time_budget", "float64"),
    ("validate", "bool_"),
    ("verify_backend", "string"),
    ("world", "string"),
)
# The seconds of the generation's stages (physc.driver.layout_loop; a stage a task did not pass: null).
SECONDS = (
    ("accept", "float64"),
    ("distract", "float64"),
    ("layout", "float64"),
    ("satisfy", "float64"),
    ("total", "float64"),
    ("validate", "float64"),
)


NAMES = {name for name, _ in COLUMNS}
FIXED = {"settings": SETTINGS, "seconds": SECONDS}


def _struct(fields):
    import pyarrow as pa

    return pa.struct([(name, getattr(pa, kind)()) for name, kind in fields])


def key(row: dict) -> tuple[str, int]:
    """A task's key in its dataset: scenario names are unique there (physc generate sees to it)."""
    return (row["scenario"], row["seed"])


def read(folder: Path) -> dict:
    """The rows already written, by task (the last row of a task wins; a torn line is skipped)."""
    rows = {}
    for row in read_json_lines(folder / JSONL):
        try:
            rows[key(row)] = row
        except (KeyError, TypeError):  # not a row of ours
            continue
    return rows


def _sorted(value):
    """A JSON value with every object's keys in sorted order."""
    if isinstance(value, dict):
        return {k: _sorted(value[k]) for k in sorted(value)}
    if isinstance(value, list):
        return [_sorted(v) for v in value]
    return value


def terms(text: str | None) -> list[str] | None:
    """The interactions of a sequence written `a > b > c` (no term contains '>')."""
    return None if text is None else [term.strip() for term in text.split(">") if term.strip()]


def complete(row: dict) -> dict:
    """The row with every column of COLUMNS (null where the run has none) and, after them, any
    field of its own: JSON Lines and Parquet have the same columns."""
    return {name: row.get(name) for name, _ in COLUMNS} | {k: v for k, v in row.items() if k not in NAMES}


def line(row: dict) -> str:
    return json.dumps(complete(row), sort_keys=True, ensure_ascii=False) + "\n"


def write_jsonl(folder: Path, rows: list[dict]) -> None:
    write_atomic(folder / JSONL, "".join(line(row) for row in rows))


def write_parquet(folder: Path, rows: list[dict]) -> None:
    """The rows as a Parquet table with the columns of COLUMNS (written whole)."""
    import io

    import pyarrow as pa
    import pyarrow.parquet as pq

    arrays = []
    for name, kind in COLUMNS:
        values = [row.get(name) for row in rows]
        if kind in FIXED:
            fields = FIXED[kind]
            arrays.append(
                pa.array([None if v is None else {f: v.get(f) for f, _ in fields} for v in values], _struct(fields))
            )
        elif kind == "struct":  # the fields' order sorted, so the type depends on the rows alone
            try:
                arrays.append(pa.array([_sorted(v) for v in values]))
            except (
                pa.ArrowInvalid,
                pa.ArrowTypeError,
            ):  # a field whose type differs between rows (a plugin's): JSON text
                arrays.append(
                    pa.array(
                        [None if v is None else json.dumps(v, sort_keys=True, ensure_ascii=False) for v in values],
                        pa.string(),
                    )
                )
        else:
            lists = {"terms": pa.list_(pa.string()), "seeds": pa.list_(pa.int64())}
            arrays.append(pa.array(values, type=lists[kind] if kind in lists else getattr(pa, kind)()))
    table = pa.Table.from_arrays(arrays, names=[name for name, _ in COLUMNS])
    buffer = io.BytesIO()
    pq.write_table(table, buffer)
    write_atomic(folder / PARQUET, buffer.getvalue())
