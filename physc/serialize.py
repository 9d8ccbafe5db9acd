"""Deterministic JSON dumps of IR values (`physc compile --emit …`)."""

from __future__ import annotations

import enum
import json
from typing import Any, TypeAlias, cast

import attrs

from physc.diagnostics import Span

# Plain data, as JSON holds it: what every IR value dumps to and a task file reads back from.
Data: TypeAlias = None | bool | int | float | str | list["Data"] | dict[str, "Data"]


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
        data: dict[str, Data] = {"node": type(value).__name__}
        for field in attrs.fields(type(value)):
            if not field.metadata.get("dump", True):
                continue
            if field.metadata.get("omit_default") and getattr(value, field.name) == field.default:
                # a field a later version added: left out where unused, so earlier files dump the same
                continue
            data[field.name] = to_data(getattr(value, field.name))
        data.update(_extra_fields(value))
        return data
    if isinstance(value, enum.Enum):
        return value.value
    if isinstance(value, (list, tuple)):
        return [to_data(v) for v in value]
    if isinstance(value, (set, frozenset)):
        # a set holds scalars (names, numbers), which sort by value
        members: list[Any] = [to_data(v) for v in value]
        return sorted(members)
    if isinstance(value, dict):
        return {str(k): to_data(v) for k, v in value.items()}
    # the rest are JSON's scalars (None, bools, numbers, strings), dumped as they are
    return cast("Data", value)


def _extra_fields(value: object) -> dict[str, Data]:
    """The fields an IR value adds to its dump beyond its attrs fields (`__extra_dump__`, a
    dict; e.g. the exact size of a DNF in `--emit qsr`); none if it has no such method."""
    extra = getattr(value, "__extra_dump__", None)
    if extra is None:
        return {}
    fields = to_data(extra())
    assert isinstance(fields, dict), "__extra_dump__ returns a dict"
    return fields


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
        node = data["node"]
        cls = classes.get(node) if isinstance(node, str) else None
        if cls is None:
            raise ValueError(f"a '{data['node']}' is not something this file may hold")
        known = {field.name for field in attrs.fields(cls)}
        unknown = sorted(set(data) - known - {"node"})
        if unknown:
            raise ValueError(
                f"a '{data['node']}' has no field {', '.join(repr(k) for k in unknown)}"
                " (a file written by another version of its domain?)"
            )
        return cls(**{k: from_data(v, classes) for k, v in data.items() if k != "node"})
    if isinstance(data, list):
        return tuple(from_data(v, classes) for v in data)
    return data
