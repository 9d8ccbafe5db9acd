"""The README of a dataset, written from a jinja2 template: its scenarios, counts and command."""

from __future__ import annotations

import collections
from importlib import resources
from pathlib import Path

import jinja2

from physc import __version__
from physc.dataset.worker import FALLBACK, NO_TASK
from physc.domains import load_domain

_SIZES = ((1_000, "n<1K"), (10_000, "1K<n<10K"), (100_000, "10K<n<100K"), (1_000_000, "100K<n<1M"))


def _size_category(tasks: int) -> str:
    """Hugging Face's size category of a dataset of `tasks` rows."""
    return next((name for most, name in _SIZES if tasks < most), "1M<n<10M")


def render(folder: Path, jobs: list, rows: list[dict], command: str) -> str:
    """The README for the dataset in `folder`: `jobs` (each carrying its scenario as written) and
    their `rows`, in order."""
    by_scenario: dict[str, list] = collections.defaultdict(list)
    for job, row in zip(jobs, rows, strict=True):  # a row per job, in order (build)
        by_scenario[job.scenario].append((job, row))
    scenarios = [_scenario(name, pairs) for name, pairs in by_scenario.items()]
    made = [r for r in rows if r["outcome"] != NO_TASK]
    domains = sorted({job.domain for job in jobs})
    suffixes = {load_domain(d).files.level_suffix for d in domains}
    suffix = suffixes.pop() if len(suffixes) == 1 else "<suffix>"
    template = jinja2.Environment(keep_trailing_newline=True, undefined=jinja2.StrictUndefined).from_string(
        resources.files("physc.dataset").joinpath("templates/README.md.j2").read_text(encoding="utf-8")
    )
    return template.render(
        name=folder.resolve().name,
        total=len(rows),
        generated=len(made),
        fallbacks=sum(r["outcome"] == FALLBACK for r in rows),
        missing=len(rows) - len(made),
        scenarios=scenarios,
        backends=", ".join(
            sorted({j.backend for j in jobs} | {j.settings.verify_backend for j in jobs if j.settings.verify_backend})
        ),
        worlds=_worlds(jobs),
        validated=all(j.settings.validate for j in jobs),
        accidental=all(j.accidental for j in jobs),
        pictures=any(r.get("picture") for r in rows),
        level_suffix="level.json" if suffix == "json" else suffix,
        domains=domains,
        level_formats=[{"domain": d, "format": load_domain(d).files.level_format} for d in domains],
        size_category=_size_category(len(rows)),
        command=command,
        version=__version__,
        code=", ".join(sorted({j.code for j in jobs})),
        config=config_name(rows),
    )


def config_name(rows: list[dict]) -> str:
    """The card's one configuration, named after what the dataset holds (its rows, times left
    out, so the same command names it alike). Hugging Face keys its cache by the folder's name
    and the configuration: under a shared name, a second dataset in a folder of the same name
    loaded as the first one ("default" did that)."""
    import hashlib
    import json

    from physc.dataset.manifest import complete

    held = [{k: v for k, v in complete(row).items() if k not in TIMES} for row in rows]  # as the manifest holds them
    return "physc-" + hashlib.sha256(json.dumps(held, sort_keys=True).encode()).hexdigest()[:16]


TIMES = ("generation_seconds", "seconds")  # what differs between runs of one command


def _scenario(name: str, pairs: list) -> dict:
    job, _ = pairs[0]
    rows = [row for _, row in pairs]
    made = [r for r in rows if r["outcome"] != NO_TASK]
    robustness = collections.Counter(f"{r['robustness_passed']}/{r['robustness_run']}" for r in made)
    reasons = collections.Counter(r["reason"] for r in rows if r["outcome"] == NO_TASK)
    plays = [r["accidental"] for r in made if r.get("accidental") is not None]
    return {
        "name": name,
        "title": rows[0].get("title"),
        "domain": job.domain,
        "interactions": rows[0]["interactions"],
        "total": len(rows),
        "generated": len(made),
        "fallbacks": sum(r["outcome"] == FALLBACK for r in rows),
        "missing": len(rows) - len(made),
        "accidental": f"{sum(plays) / len(plays):.3f} (mean of {len(plays)})" if plays else "none measured",
        "source": job.source,  # as written, in block form
        "first_seed": min(j.seed for j, _ in pairs),
        "last_seed": max(j.seed for j, _ in pairs),
        "robustness": ", ".join(f"{k} × {v}" for k, v in sorted(robustness.items(), key=lambda kv: (-kv[1], kv[0])))
        or "none generated",
        "reasons": "; ".join(f"{v} × {k}" for k, v in sorted(reasons.items(), key=lambda kv: (-kv[1], kv[0]))),
    }


def _worlds(jobs) -> str:
    """The worlds the tasks were made in, in words: "the world 'phyq'" or "the worlds 'phyq', 'rolling'"."""
    names = sorted({j.world for j in jobs if j.world})
    if not names:
        return "the domain's world"
    return ("the world " if len(names) == 1 else "the worlds ") + ", ".join(f"'{n}'" for n in names)
