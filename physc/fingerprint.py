"""Fingerprints: what a generated task depends on, so that a resumed run can tell a result made
by the same scenario and the same code from one made before an edit (`physc eval`, `physc
generate`)."""

from __future__ import annotations

import functools
import hashlib
import importlib.util
import json
from pathlib import Path
from typing import TYPE_CHECKING

import attrs

from physc.backends import installed_backends
from physc.domains import installed_domains

if TYPE_CHECKING:
    from attrs import AttrsInstance


def scenario_fingerprint(scenario: AttrsInstance) -> str:
    """A hash of what a scenario says: the fields its equality compares (not where it is
    written: spans, the file's path, layout and comments do not count)."""
    data = attrs.asdict(scenario, filter=lambda attribute, _: bool(attribute.eq))
    return hashlib.sha256(json.dumps(data, sort_keys=True).encode()).hexdigest()[:16]


def source_fingerprint(where: Path) -> str:
    """A hash of the Python source at `where`, a module's file or a package's folder:
    every .py file's path (relative to the folder) and content. Anything else (docs,
    caches, data) does not count."""
    files, folder = ([where], where.parent) if where.is_file() else (sorted(where.rglob("*.py")), where)
    digest = hashlib.sha256()
    for path in files:
        digest.update(path.relative_to(folder).as_posix().encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


@functools.cache
def code_fingerprint(domain: str, backends: tuple[str, ...] = ()) -> str:
    """A hash of the code a task of `domain` depends on: physc's own source and, for a
    domain or a backend (of `backends`) that a third-party package brings, that package's.
    Records made by other code are made again, so a run resumed after an edit to the
    generator never mixes old tasks with new ones."""
    packages = {"physc"}
    entry_points = [installed_domains().get(domain)] + [installed_backends().get(name) for name in backends]
    for entry_point in entry_points:
        if entry_point is not None:
            packages.add(entry_point.module.split(".")[0])
    parts = []
    for package in sorted(packages):
        spec = importlib.util.find_spec(package)
        if spec is None:
            continue
        where = list(spec.submodule_search_locations or []) or (
            [spec.origin] if spec.has_location and spec.origin is not None else []
        )
        parts += [f"{package}:{source_fingerprint(Path(place))}" for place in where]
    return hashlib.sha256("\n".join(parts).encode()).hexdigest()[:16]
