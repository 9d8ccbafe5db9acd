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
from pathlib import Path

import matplotlib
import matplotlib.pyplot as plt

from physc.domains.base import provides, solution_classes
from physc.evaluation.measure import NOISY_REPLAYS
from physc.evaluation.summary import ACCEPTANCE_METRICS, PAPER, metrics, summarise
from physc.files import write_atomic

matplotlib.use("Agg")  # the plots are drawn off-screen; pyplot resolves its backend lazily, so Agg it is

NAMES = {
    2: "Two",
    3: "Three",
    4: "Four",
    5: "Five",
    6: "Six",
    7: "Seven",
    8: "Eight",
}  # interaction counts as the table heads them
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


def fmt(pair) -> str:
    return "–" if pair is None else f"{pair[0]:.2f} ± {pair[1]:.2f}"


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


def _funnel_lines(summary: dict, counts: list, names: dict) -> list[str]:
    """Where the placed layouts went (every task, made or not; physc.search.funnel), per
    interaction count and per scenario."""
    rows = summary["interactions"]
    if not any(rows[c].get("funnel") for c in counts):
        return []
    lines = ["", "## Where the placed layouts went (every task, made or not)", ""]
    lines.append("| | " + " | ".join(names.get(c, str(c)) for c in counts) + " |")
    lines.append("|---|" + "---|" * len(counts))
    funnels = [rows[c].get("funnel") for c in counts]
    lines.append("| Placed layouts | " + " | ".join("–" if f is None else f"{f['placed']:,}" for f in funnels) + " |")
    lines.append("| Never realised the chain | " + " | ".join(_share(f, "never") for f in funnels) + " |")
    for why in sorted({w for f in funnels if f for w in f["lost"]}):
        cells = ["–" if f is None else f"{100 * f['lost'].get(why, 0.0):.1f} %" for f in funnels]
        lines.append(f"| Realised the chain, lost to {why} | " + " | ".join(cells) + " |")
    lines.append("| Gave the task | " + " | ".join(_share(f, "kept") for f in funnels) + " |")
    spread = [rows[c].get("diversity") for c in counts]
    lines.append(
        "| Diversity (mean distance between the same objects' places across a scenario's tasks) | "
        + " | ".join("–" if d is None else f"{d:.2f}" for d in spread)
        + " |"
    )
    lines += [
        "",
        "| scenario | placed layouts | never realised the chain | lost to noise | gave the task | diversity |",
    ]
    lines.append("|---|---|---|---|---|---|")
    for name, row in summary["scenarios"].items():
        f = row.get("funnel")
        if f is not None:
            noise = f"{100 * f['lost'].get('noise', 0.0):.1f} %"
            d = row.get("diversity")
            cells = [f"{f['placed']:,}", _share(f, "never"), noise, _share(f, "kept"), "–" if d is None else f"{d:.2f}"]
            lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return lines


def _share(funnel: dict | None, key: str) -> str:
    return "–" if funnel is None else f"{100 * funnel[key]:.1f} %"


def _scenario_effort(summary: dict) -> list[str]:
    """Per scenario: what a task cost (median seconds and simulations), the weakest margin of
    its tasks (the least share over the noisy replays each solution passed, and its link), and
    why the seeds that gave none gave none."""
    rows = summary["scenarios"]
    if not any(row.get("median_seconds") is not None or row.get("why_none") for row in rows.values()):
        return []
    lines = ["", "## Per scenario: cost, margins, and why no task", ""]
    lines.append(
        "| scenario | generated | median s a task | median simulations a task | weakest margin (share, link) "
        "| margins raised | why no task (seeds) |"
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
    lines += _funnel_lines(summary, counts, names)
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
            "With --verify-backend, a task was kept only if its solution also passed in "
            f"{summary['verify_backend']}, and",
            f'the rows "in {summary["verify_backend"]}" replay it there afresh: exactly, and {NOISY_REPLAYS} times'
            " with the same noise.",
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
