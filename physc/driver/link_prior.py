"""A world's prior for the proposal model: where each kind of link happens in that world, measured
by simulation and shipped with the domain as data, saying what it was made from.

A prior file (`<world>.json` in the package a domain names as its `search.priors`) holds
examples, (kind, features, realised), that the search's own compiles gave over a set of
scenarios (benchmarks/link_prior.py makes it), and its provenance: the world, the scenarios,
seeds and seconds, the physc version, the date, and the *recognition fingerprint* of the world it
was measured in (`recognition`: the world's settings as they read, the recogniser's code and the
features' code). A prior whose fingerprint is not the world's now was measured with another
reading of the words: the search does not use it, and the task file says so; the test suite
fails on a shipped one, so it is made again whenever recognition changes.
"""

from __future__ import annotations

import hashlib
import importlib.resources
import json
from pathlib import Path

import attrs

from physc.fingerprint import source_fingerprint
from physc.search import link_features
from physc.search.link_model import Example

SIMULATION = Path(__file__).resolve().parent.parent / "simulation"  # the recogniser's code, physc.simulation
CAP = 600  # examples kept of each kind (the first, in the files' order): the file stays small


def recognition(domain) -> str:
    """The fingerprint of what decides whether a link happened in `domain`'s world: its settings
    (engine, bodies, recogniser), the recogniser's code and the features' code."""
    parts = [repr(domain.world), source_fingerprint(SIMULATION), source_fingerprint(Path(link_features.__file__))]
    return hashlib.sha256("\n".join(parts).encode()).hexdigest()[:16]


@attrs.frozen
class Prior:
    """A world's examples by kind, and where they came from."""

    world: str
    fingerprint: str  # recognition's, when it was measured
    provenance: dict  # scenarios, seeds, seconds, physc version, date, the command
    examples: dict[str, list[Example]]

    @property
    def count(self) -> int:
        return sum(len(rows) for rows in self.examples.values())

    def record(self, current: bool) -> dict:
        """What a task file says of the prior its search used (or did not: `current` False)."""
        return {"world": self.world, "fingerprint": self.fingerprint, "examples": self.count, "used": current} | {
            key: self.provenance[key] for key in ("made", "physc") if key in self.provenance
        }


def path_of(domain) -> Path | None:
    """Where `domain`'s world's prior file is, if its domain ships one."""
    package = getattr(domain.search, "priors", None)
    if package is None:
        return None
    where = Path(str(importlib.resources.files(package))) / f"{domain.world.name}.json"
    return where if where.is_file() else None


def load(domain) -> Prior | None:
    """`domain`'s world's prior, if its domain ships one."""
    where = path_of(domain)
    if where is None:
        return None
    data = json.loads(where.read_text(encoding="utf-8"))
    examples = {
        kind: [(tuple(values), bool(realised)) for values, realised in rows] for kind, rows in data["examples"].items()
    }
    return Prior(data["world"], data["fingerprint"], data["provenance"], examples)


def write(where: Path, domain, rows: list[tuple[str, tuple[float, ...], bool]], provenance: dict) -> Prior:
    """A prior of `rows` (kind, features, realised) measured in `domain`'s world, written to
    `where` whole (a temporary file renamed)."""
    examples: dict[str, list[Example]] = {}
    for kind, values, realised in rows:
        kept = examples.setdefault(kind, [])
        if len(kept) < CAP:
            kept.append((tuple(round(v, 4) for v in values), realised))
    prior = Prior(domain.world.name, recognition(domain), provenance, dict(sorted(examples.items())))
    data = {
        "world": prior.world,
        "fingerprint": prior.fingerprint,
        "features": list(link_features.NAMES),
        "provenance": provenance,
        "examples": {kind: [[list(v), r] for v, r in rows] for kind, rows in prior.examples.items()},
    }
    partial = where.with_suffix(".partial")
    partial.write_text(json.dumps(data, separators=(",", ":")) + "\n", encoding="utf-8")
    partial.replace(where)
    return prior
