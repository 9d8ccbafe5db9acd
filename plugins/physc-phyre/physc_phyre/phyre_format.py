"""Tasks in PHYRE's own format: task ids, and `TaskCollection`s in binary Thrift, compressed.

PHYRE loads its tasks from `tasks.bin.lzma` (ids beginning `00`; `tasksNN.bin.lzma` for the
others): one `TaskCollection` (src/if/task.thrift), its tasks sorted by id, serialized with
Thrift's binary protocol and written with Python's `lzma.open(path, "w")` defaults
(docs/phyre-sources.md, section 2). physc writes the same: its task structure (task_file.py)
is PHYRE's, field for field, so a task goes into Thrift as it is, through our own IDL of
PHYRE's structures (phyre.thrift, read by thriftpy2). A task id is `TTTTT:VVV`: the template
(a scenario) and the instance (a seed), as PHYRE's task scripts number them.
"""

from __future__ import annotations

import lzma
import re
from pathlib import Path

import thriftpy2
from thriftpy2.protocol import TBinaryProtocolFactory
from thriftpy2.thrift import TType
from thriftpy2.utils import deserialize, serialize

IDL = thriftpy2.load(str(Path(__file__).with_name("phyre.thrift")), module_name="phyre_thrift")
PROTOCOL = TBinaryProtocolFactory()
TASK_ID = re.compile(r"^(\d{5}):(\d{3})$")
INSTANCES = 1000  # PHYRE's instance ids have three digits
# physc's templates are numbered from here: a range PHYRE's own never use (its ball tier
# 00000-00024, two-ball tier 00100-00124, virtual tools 01000-01011), in a file of its own
# (tasks50.bin.lzma), so that physc's tasks and PHYRE's load side by side from one folder.
FIRST_TEMPLATE = 50_000
TEMPLATES = 1000  # templates FIRST_TEMPLATE .. FIRST_TEMPLATE + 999 share that file


def task_id(template: int, instance: int) -> str:
    """PHYRE's id of instance `instance` of template `template`: "00012:004"."""
    if not 0 <= template < 100_000 or not 0 <= instance < INSTANCES:
        raise ValueError(
            f"a PHYRE task id needs a template below 100000 and an instance below {INSTANCES}, not {template} and "
            f"{instance}"
        )
    return f"{template:05d}:{instance:03d}"


def collection_file(task: str) -> str:
    """The file of PHYRE's task folder that holds the task `task` (loader.py's task_id_to_pickle)."""
    prefix = task[:2]
    return "tasks.bin.lzma" if prefix == "00" else f"tasks{prefix}.bin.lzma"


def _to_thrift(cls, data: dict):
    """`data` (a task, or a part of one, as task_file.py writes it) as an object of the IDL class `cls`."""
    values = {}
    for spec in cls.thrift_spec.values():
        kind, name = spec[0], spec[1]
        if name in data and data[name] is not None:
            values[name] = _value(kind, spec[2] if len(spec) > 3 else None, data[name])
    return cls(**values)


def _value(kind, argument, value):
    if kind == TType.STRUCT:
        return _to_thrift(argument, value)
    if kind == TType.LIST:
        inner, cls = argument if isinstance(argument, tuple) else (argument, None)
        return [_value(inner, cls, item) for item in value]
    if kind == TType.DOUBLE:
        return float(value)
    return value


def _to_data(obj) -> dict:
    """An IDL object as task_file.py's structure (the fields that are set)."""
    out = {}
    for spec in obj.thrift_spec.values():
        name = spec[1]
        value = getattr(obj, name)
        if value is not None:
            out[name] = _plain(value)
    return out


def _plain(value):
    if isinstance(value, list):
        return [_plain(v) for v in value]
    if hasattr(value, "thrift_spec"):
        return _to_data(value)
    return value


def task_bytes(task: dict) -> bytes:
    """One task (task_file.py's structure; its `physc` part is not PHYRE's and is left out) in
    Thrift's binary protocol."""
    return serialize(_to_thrift(IDL.Task, task), PROTOCOL)


def collection_bytes(tasks: list[dict]) -> bytes:
    """A TaskCollection of `tasks` (each with its `taskId`), sorted by id, binary Thrift,
    compressed as PHYRE's task files are."""
    ids = [t.get("taskId") for t in tasks]
    if any(not isinstance(i, str) or not TASK_ID.match(i) for i in ids) or len(set(ids)) != len(ids):
        raise ValueError("every task of a collection needs its own PHYRE task id (TTTTT:VVV)")
    collection = IDL.TaskCollection(tasks=[_to_thrift(IDL.Task, t) for t in sorted(tasks, key=lambda t: t["taskId"])])
    return lzma.compress(serialize(collection, PROTOCOL))


def read_collection(data: bytes) -> list[dict]:
    """The tasks of a compressed TaskCollection, as task_file.py's structure."""
    collection = deserialize(IDL.TaskCollection(), lzma.decompress(data), PROTOCOL)
    return [_to_data(task) for task in collection.tasks or ()]
