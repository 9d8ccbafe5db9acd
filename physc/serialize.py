"""Deterministic JSON dumps of IR values (`physc compile --emit …`)."""

from __future__ import annotations

import enum
import json
from typing import Any

import attrs

from physc.diagnostics import Span


def to_data(value: Any) -> Any:
    """Plain data (dicts, lists, strings, numbers) for an IR value.

    attrs instances become objects whose first key `node` names their class;
    spans become "line:column-end_line:end_column" strings; frozensets are
    sorted, so the same value always dumps to the same bytes.
    """
    if isinstance(value, Span):
        return f"{value.line}:{value.column}-{value.end_line}:{value.end_column}"
    if attrs.has(type(value)):
        data = {"node": type(value).__name__}
        for field in attrs.fields(type(value)):
            if field.metadata.get("dump", True):
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


def dumps(value: Any) -> str:
    return json.dumps(to_data(value), indent=2, ensure_ascii=False) + "\n"
