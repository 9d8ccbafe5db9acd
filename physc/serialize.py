"""Deterministic JSON dumps of IR values (`physc compile --emit …`)."""

from __future__ import annotations

import enum
import json
from typing import Union

import attrs

from physc.diagnostics import Span

# Plain data, as JSON holds it: what every IR value dumps to and a task file reads back from.
Data = Union[None, bool, int, float, str, list["Data"], dict[str, "Data"]]


def to_data(value: object) -> Data:
    """Plain data (dicts, lists, strings, numbers) for an IR value.

    attrs instances become objects whose first key `node` names their class (a field marked
    `omit_default` is left out while it holds its default);
    spans become "line:column-end_line:end_column" strings; frozensets are
    sorted, so the same value always dumps to the same bytes.
    """
    if isinstance(value, Span):
        return f"{value.line}:{value.column}-{value.end_line}:{value.end_column}"
    if attrs.has(type(value)):
        data = {"node": type(value).__name__}
        for field in attrs.fields(type(value)):
            if not field.metadata.get("dump", True):
                continue
            if field.metadata.get("omit_default") and getattr(value, field.name) == field.default:
                continue  # a field a later version added: left out where unused, so earlier files dump the same
            data[field.name] = to_data(getattr(value, field.name))
        extra = getattr(value, "__extra_dump__", None)
        if extra is not None:
            data.update(to_data(extra()))
        return data
    if isinstance(value, enum.Enum):
        return value.value
    if isinstance(value, (list, tuple)):
        return [to_data(v) for v in value]
    if isinstance(value, (set, frozenset)):
        return sorted(to_data(v) for v in value)
    if isinstance(value, dict):
        return {str(k): to_data(v) for k, v in value.items()}
    return value


def dumps(value: object) -> str:
    return json.dumps(to_data(value), indent=2, ensure_ascii=False) + "\n"


def from_data(data: Data, classes: dict[str, type]) -> object:
    """The IR value that `to_data` made `data` from, for the attrs classes in `classes` (by
    name, as `node` names them): objects of another node, and fields the class does not have
    (a file written by another version of its domain), are refused (ValueError), rather than
    read as something else; lists become tuples. Reads back what a task file holds (its
    level, its solution)."""
    if isinstance(data, dict):
        if "node" not in data:
            return {k: from_data(v, classes) for k, v in data.items()}
        cls = classes.get(data["node"])
        if cls is None:
            raise ValueError(f"a '{data['node']}' is not something this file may hold")
        known = {field.name for field in attrs.fields(cls)}
        unknown = sorted(set(data) - known - {"node"})
        if unknown:
            raise ValueError(
                f"a '{data['node']}' has no field {', '.join(repr(k) for k in unknown)} (a file written by another version of its domain?)"
            )
        return cls(**{k: from_data(v, classes) for k, v in data.items() if k != "node"})
    if isinstance(data, list):
        return tuple(from_data(v, classes) for v in data)
    return data
