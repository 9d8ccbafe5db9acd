"""The evaluation report: tables as the paper lays them out, plots, pictures.

Writes into the output folder: results.md (tables, Mean ± SD, the paper's numbers
beside ours), results.json, results.csv (one row per task), a PNG plot per metric
against the interaction count with the paper's values as a reference series, and
a picture of one generated task per interaction count.
"""

from __future__ import annotations

import csv
import io
import json
import statistics
from pathlib import Path

import matplotlib
import numpy as np

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from physc.domains.base import provides, solution_classes  # noqa: E402
from physc.evaluation.measure import NOISY_REPLAYS  # noqa: E402
from physc.files import write_atomic  # noqa: E402

# The paper's table "The results of the intended solvability, accidental
# solvability, and generation time evaluations (Mean±SD)", and its 100 % stability.
PAPER = {
    "intended": {2: (1.00, 0.00), 4: (0.91, 0.11), 6: (0.87, 0.10), 8: (0.82, 0.07)},
    "accidental": {2: (0.12, 0.05), 4: (0.08, 0.03), 6: (0.07, 0.01), 8: (0.03, 0.01)},
    "seconds": {2: (1.83, 0.10), 4: (2.37, 0.27), 6: (3.16, 0.86), 8: (4.68, 1.03)},
    "stable": {2: (1.00, 0.00), 4: (1.00, 0.00), 6: (1.00, 0.00), 8: (1.00, 0.00)},
}
METRICS = (
    ("intended_noisy", "Intended solvability (10 noisy replays)", "intended"),
    ("intended_exact", "Intended solvability (exact replay)", "intended"),
    ("fidelity_noisy", "Sequence fidelity (noisy replays)", None),
    ("accidental", "Accidental solvability", "accidental"),
    ("stable", "Physical stability", "stable"),
    ("generation_seconds", "Generation time (seconds)", "seconds"),
)
# With --verify-backend: the solution replayed in the second engine ("{backend}" is its name).
VERIFY_METRICS = (
    ("verified_solved", "Solved in {backend} (exact replay)", None),
    ("verified_realised", "Sequence realised in {backend} (exact replay)", None),
    ("verified_noisy", "Sequence realised in {backend} (" + str(NOISY_REPLAYS) + " noisy replays)", None),
)
NAMES = {
    2: "Two",
    3: "Three",
    4: "Four",
    5: "Five",
    6: "Six",
    7: "Seven",
    8: "Eight",
}  # interaction counts as the table heads them
# With a random agent (a simulated domain's evaluation): PHYRE's AUCCESS of its attempts.
AGENT_METRICS = (("auccess", "Random agent's AUCCESS (100 attempts)", None),)
# With a domain's acceptance rule (PHYRE's): its flags for every task kept, from random actions.
ACCEPTANCE_METRICS = (
    ("good_stable", "GOOD_STABLE (random actions solve it stably, shown above the threshold)", None),
    ("trivial", "TRIVIAL (stable solutions ≥ 10 % of random attempts)", None),
    ("solution_stable", "Intended solution stable (its neighbours solve it too)", None),
    ("solve_rate", "Solutions per valid random action (PHYRE's pool, those simulated)", None),
)
CSV_COLUMNS = (
    "file",
    "scenario",
    "interactions",
    "seed",
    "generated",
    "generation_seconds",
    "stable",
    "largest_shift",
    "intended_exact",
    "intended_noisy",
    "fidelity_exact",
    "fidelity_noisy",
    "accidental",
    "agent_plays",
    "trace",
    "reason",
    "min_robustness",
    "robustness",
    "layouts_tried",
    "simulations",
    "structure",
)
VERIFY_COLUMNS = ("verify_backend", "verified_solved", "verified_realised", "verified_noisy")  # with --verify-backend


def mean_sd(values) -> tuple[float, float] | None:
    values = [float(v) for v in values]
    if not values:
        return None
    return statistics.mean(values), statistics.pstdev(values) if len(values) > 1 else 0.0


def measured(record: dict, metric: str) -> bool:
    """Whether the record has a figure for the metric: accidental solvability needs at least
    one play of the agent (records written before it was None for no play say 0.0)."""
    return metric != "accidental" or record.get("agent_plays") != 0


def fmt(pair) -> str:
    return "–" if pair is None else f"{pair[0]:.2f} ± {pair[1]:.2f}"


def summarise(records: list[dict]) -> dict:
    def group(key):
        out: dict = {}
        for r in records:
            out.setdefault(r[key], []).append(r)
        return out

    def stats(rows):
        made = [r for r in rows if r.get("generated")]
        # Fallbacks (--min-robustness): tasks whose solution passed fewer than all the
        # generator's noisy replays.
        fallbacks = sum(1 for r in made if r.get("robustness") and r["robustness"][0] < r["robustness"][1])
        out = {"tasks": len(rows), "generated": len(made), "fallbacks": fallbacks}
        for metric, _, _ in METRICS + AGENT_METRICS + ACCEPTANCE_METRICS + VERIFY_METRICS:
            out[metric] = mean_sd([r[metric] for r in made if r.get(metric) is not None and measured(r, metric)])
        out["no_agent_play"] = sum(1 for r in made if not measured(r, "accidental"))
        out |= effort(made)
        seconds = sorted(r["generation_seconds"] for r in made if r.get("generation_seconds") is not None)
        sims = sorted(r["simulations"] for r in made if r.get("simulations") is not None)
        out["median_seconds"] = float(np.median(seconds)) if seconds else None
        out["median_simulations"] = float(np.median(sims)) if sims else None
        shares = [(r["weakest_share"], r["weakest_link"]) for r in made if r.get("weakest_share") is not None]
        out["weakest"] = min(shares) if shares else None
        out["raised"] = sum(1 for r in made if r.get("raised"))
        reasons: dict[str, int] = {}
        for r in rows:
            if not r.get("generated") and r.get("reason"):
                short = why_none(r["reason"])
                reasons[short] = reasons.get(short, 0) + 1
        out["why_none"] = sorted(reasons.items(), key=lambda item: -item[1])
        return out

    scenarios = {
        name: stats(rows) | {"interactions": rows[0]["interactions"]} for name, rows in group("scenario").items()
    }
    counts = {count: stats(rows) for count, rows in sorted(group("interactions").items())}
    verified = sorted({r["verify_backend"] for r in records if r.get("verify_backend")})
    domains = sorted({r.get("domain", "angrybirds") for r in records})  # records without one are angrybirds'
    agent = any(r.get("auccess") is not None for r in records)
    judged = any(r.get("good_stable") is not None for r in records)
    return {
        "scenarios": scenarios,
        "interactions": counts,
        "paper": PAPER,
        "verify_backend": ", ".join(verified) or None,
        "domains": domains,
        "auccess": agent,
        "acceptance": judged,
    }


def metrics(summary: dict) -> tuple:
    """The report's metrics: the paper's (compared with the paper's table only for its own
    domain), the random agent's AUCCESS and the verify backend's when the records have them."""
    own = (
        METRICS
        if summary.get("domains", ["angrybirds"]) == ["angrybirds"]
        else tuple((m, title, None) for m, title, _ in METRICS)
    )
    out = (
        own
        + (AGENT_METRICS if summary.get("auccess") else ())
        + (ACCEPTANCE_METRICS if summary.get("acceptance") else ())
    )
    backend = summary.get("verify_backend")
    if backend:
        out += tuple((metric, title.format(backend=backend), paper) for metric, title, paper in VERIFY_METRICS)
    return out


def effort(made: list[dict]) -> dict:
    """What the generated tasks cost (records that carry it): layouts and simulations per task,
    and the share of the simulations spent on layouts given up, per reason (the task's `given_up`)."""
    rows = [r for r in made if "given_up" in r]
    total = sum(r["simulations"] for r in rows)
    shares: dict[str, float] = {}
    for r in rows:
        for why, counts in r["given_up"].items():
            shares[why] = shares.get(why, 0.0) + (counts["simulations"] / total if total else 0.0)
    return {
        "layouts_tried": mean_sd([r["layouts_tried"] for r in rows]),
        "simulations": mean_sd([r["simulations"] for r in rows]),
        "given_up": dict(sorted(shares.items(), key=lambda item: -item[1])),
    }


def _effort_lines(summary: dict, counts: list, names: dict) -> list[str]:
    """The report's table of what generation cost, when the records carry it."""
    rows = summary["interactions"]
    if not any(rows[c]["layouts_tried"] for c in counts):
        return []
    reasons = list(dict.fromkeys(why for c in counts for why in rows[c]["given_up"]))
    lines = ["", "## What generation cost (generated tasks)", ""]
    lines.append("| | " + " | ".join(names.get(c, str(c)) for c in counts) + " |")
    lines.append("|---|" + "---|" * len(counts))
    lines.append("| Layouts tried per task | " + " | ".join(fmt(rows[c]["layouts_tried"]) for c in counts) + " |")
    lines.append("| Simulations per task | " + " | ".join(_whole(rows[c]["simulations"]) for c in counts) + " |")
    for why in reasons:
        cells = [f"{100 * rows[c]['given_up'].get(why, 0.0):.1f} %" for c in counts]
        lines.append(f"| Simulations on layouts given up: {why} | " + " | ".join(cells) + " |")
    return lines


def _scenario_effort(summary: dict) -> list[str]:
    """Per scenario: what a task cost (median seconds and simulations), the weakest margin of
    its tasks (the least share over the noisy replays each solution passed, and its link), and
    why the seeds that gave none gave none."""
    rows = summary["scenarios"]
    if not any(row.get("median_seconds") is not None or row.get("why_none") for row in rows.values()):
        return []
    lines = ["", "## Per scenario: cost, margins, and why no task", ""]
    lines.append(
        "| scenario | generated | median s a task | median simulations a task | weakest margin (share, link) | margins raised | why no task (seeds) |"
    )
    lines.append("|---|---|---|---|---|---|---|")
    for name, row in rows.items():
        seconds = "–" if row.get("median_seconds") is None else f"{row['median_seconds']:.1f}"
        sims = "–" if row.get("median_simulations") is None else f"{row['median_simulations']:,.0f}"
        weakest = "–" if row.get("weakest") is None else f"{row['weakest'][0]:+.2f} `{row['weakest'][1]}`"
        raised = f"{row.get('raised', 0)}"
        why = "; ".join(f"{text} ({n})" for text, n in row.get("why_none", [])) or "–"
        lines.append(f"| {name} | {_generated(row)} | {seconds} | {sims} | {weakest} | {raised} | {why} |")
    return lines


def why_none(reason: str) -> str:
    """A record's reason for no task, short: the budget or constraint that ended it, and how far
    the best simulation got."""
    import re

    head = reason.split(";")[0]
    if "time budget" in head:
        head = "time ran out"
    elif "within the budget" in head:
        head = "layouts ran out"
    elif "in none did the simulated solution" in head:
        head = "every layout tried"
    best = re.search(r"realised (\d+) of the (\d+) interactions", reason)
    fragile = "the solution was too fragile" in reason or "fails physc verify" in reason
    return (
        head
        + (f", best {best.group(1)} of {best.group(2)}" if best else "")
        + (", fragile" if fragile and best and best.group(1) == best.group(2) else "")
    )


def _whole(pair) -> str:
    return "–" if pair is None else f"{pair[0]:,.0f} ± {pair[1]:,.0f}"


def _generated(row: dict) -> str:
    text = f"{row['generated']}/{row['tasks']}"
    fallbacks = row.get("fallbacks", 0)
    return text + (f" ({fallbacks} fallback{'s' if fallbacks != 1 else ''})" if fallbacks else "")


def markdown(summary: dict, command: str, seconds: float) -> str:
    counts = sorted(summary["interactions"])
    names = NAMES
    lines = [
        "# Evaluation results",
        "",
        f"Command: `{command}`  ",
        f"Wall time of this invocation: {seconds:.0f} s (a resumed run counts only the tasks it ran)",
        "",
    ]
    lines += ["## Per interaction count (physc; the paper in brackets)", ""]
    lines.append("| Evaluation metric | " + " | ".join(names.get(c, str(c)) for c in counts) + " |")
    lines.append("|---|" + "---|" * len(counts))
    for metric, title, paper_key in metrics(summary):
        cells = []
        for c in counts:
            ours = fmt(summary["interactions"][c][metric])
            paper = PAPER.get(paper_key, {}).get(c) if paper_key else None
            cells.append(f"{ours} ({fmt(paper)})" if paper else ours)
        lines.append(f"| {title} | " + " | ".join(cells) + " |")
    lines.append("| Tasks generated | " + " | ".join(_generated(summary["interactions"][c]) for c in counts) + " |")
    unplayed = [summary["interactions"][c].get("no_agent_play", 0) for c in counts]
    if any(unplayed):
        lines.append(
            "| Tasks where the agent found no play (no accidental solvability) | "
            + " | ".join(map(str, unplayed))
            + " |"
        )
    lines += _effort_lines(summary, counts, names)
    lines += ["", "## Per scenario", ""]
    header = ["scenario", "interactions", "generated"] + [title for _, title, _ in metrics(summary)]
    lines.append("| " + " | ".join(header) + " |")
    lines.append("|" + "---|" * len(header))
    for name, row in summary["scenarios"].items():
        cells = [name, str(row["interactions"]), _generated(row)] + [fmt(row[m]) for m, _, _ in metrics(summary)]
        lines.append("| " + " | ".join(cells) + " |")
    lines += _scenario_effort(summary)
    lines += [""] + _definitions(summary.get("domains", ["angrybirds"]))
    if summary.get("verify_backend"):
        lines += [
            f"With --verify-backend, a task was kept only if its solution also passed in {summary['verify_backend']}, and",
            f'the rows "in {summary["verify_backend"]}" replay it there afresh: exactly, and {NOISY_REPLAYS} times with the same noise.',
        ]
    return "\n".join(lines) + "\n"


def _definitions(domains: list[str]) -> list[str]:
    """What the metrics mean for the records' domains: each domain's own `measures` text
    (angrybirds': the paper's definitions), wrapped; named by its domain where several are."""
    import textwrap

    from physc.domains import load_domain

    lines = []
    for name in domains:
        measures = load_domain(name).evaluation.measures
        if measures:
            lead = "Definitions: " if len(domains) == 1 else f"Definitions ({name}): "
            lines += textwrap.wrap(lead + measures, width=DEFINITIONS_WIDTH, break_on_hyphens=False)
    lines.append(
        "Metrics are over the generated tasks; generation ran with the final validation skipped, as in the paper."
    )
    return lines


DEFINITIONS_WIDTH = 104  # characters a line of the definitions holds (the report's other notes run as long)


def plot(summary: dict, metric: str, title: str, paper_key: str | None) -> bytes:
    counts = sorted(summary["interactions"])
    figure, axes = plt.subplots(figsize=(5, 3.4), dpi=100)
    ours = [(c, summary["interactions"][c][metric]) for c in counts if summary["interactions"][c][metric]]
    if ours:
        axes.errorbar(
            [c for c, _ in ours],
            [v[0] for _, v in ours],
            yerr=[v[1] for _, v in ours],
            marker="o",
            capsize=3,
            label="physc",
        )
    if paper_key:
        paper = PAPER[paper_key]
        axes.errorbar(
            list(paper),
            [v[0] for v in paper.values()],
            yerr=[v[1] for v in paper.values()],
            marker="s",
            capsize=3,
            linestyle="--",
            label="paper",
        )
    axes.set_xticks([2, 4, 6, 8])
    axes.set_xlabel("interactions in the scenario")
    axes.set_title(title, fontsize=10)
    if ours or paper_key:  # nothing drawn (no task had a figure): no legend to show
        axes.legend(fontsize=8)
    figure.tight_layout()
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", metadata={"Software": None})
    plt.close(figure)
    return buffer.getvalue()


def write(records: list[dict], folder: Path, command: str, seconds: float) -> dict:
    summary = summarise(records)
    write_atomic(folder / "results.md", markdown(summary, command, seconds))
    write_atomic(
        folder / "results.json",
        json.dumps({"command": command, "seconds": round(seconds, 1), **summary}, indent=2, default=str) + "\n",
    )
    out = io.StringIO()
    columns = (
        CSV_COLUMNS
        + (("auccess",) if summary.get("auccess") else ())
        + (VERIFY_COLUMNS if summary.get("verify_backend") else ())
    )
    columns += tuple(metric for metric, _, _ in ACCEPTANCE_METRICS) if summary.get("acceptance") else ()
    writer = csv.DictWriter(out, fieldnames=columns, extrasaction="ignore")
    writer.writeheader()
    for record in sorted(records, key=lambda r: (r["scenario"], r["seed"])):
        passed = record.get("robustness")
        writer.writerow(record | {"robustness": f"{passed[0]}/{passed[1]}" if passed else ""})
    write_atomic(folder / "results.csv", out.getvalue())
    for metric, title, paper_key in metrics(summary):
        write_atomic(folder / f"plot_{metric}.png", plot(summary, metric, title, paper_key))
    _pictures(records, folder)
    return summary


def _pictures(records: list[dict], folder: Path) -> None:
    """One picture of a generated task per interaction count: the domain's `picture` of the
    task the record holds (records without a domain are angrybirds', as before domains
    were recorded)."""
    from physc.compiler.task import Task
    from physc.domains import load_domain
    from physc.serialize import from_data

    seen = set()
    for record in sorted(records, key=lambda r: (r["interactions"], r["scenario"], r["seed"])):
        if not record.get("generated") or record["interactions"] in seen:
            continue
        seen.add(record["interactions"])
        domain = load_domain(record.get("domain", "angrybirds"))
        if not domain.files.level_classes or not provides(domain, "picture"):
            continue
        level = from_data(record["level"], {cls.__name__: cls for cls in domain.files.level_classes})
        solution = from_data(record["solution"], solution_classes(domain))
        task = Task(
            record["scenario"],
            domain.name,
            record["seed"],
            "",
            level,
            solution,
            record["trace"],
            None,
            tuple(record["robustness"]),
            (),
            (),
            (),
            record.get("layouts_tried", 0),
            0,
            record.get("simulations", 0),
            {},
            {},
        )
        write_atomic(folder / f"task_{record['scenario']}_{record['seed']}.png", domain.files.picture(task))
