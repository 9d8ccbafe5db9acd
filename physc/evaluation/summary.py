"""The evaluation's numbers: the records of `physc eval` summarised per scenario and per
interaction count (Mean ± SD of each metric, what generation cost, why seeds gave no task),
beside the paper's table. The report (physc.evaluation.report) lays them out."""

from __future__ import annotations

import re
import statistics
from collections.abc import Iterable

import numpy as np

from physc.evaluation.measure import NOISY_REPLAYS

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
# With a random agent (a simulated domain's evaluation): PHYRE's AUCCESS of its attempts.
AGENT_METRICS = (("auccess", "Random agent's AUCCESS (100 attempts)", None),)
# With a domain's acceptance rule (PHYRE's): its flags for every task kept, from random actions.
ACCEPTANCE_METRICS = (
    ("good_stable", "GOOD_STABLE (random actions solve it stably, shown above the threshold)", None),
    ("trivial", "TRIVIAL (stable solutions ≥ 10 % of random attempts)", None),
    ("solution_stable", "Intended solution stable (its neighbours solve it too)", None),
    ("solve_rate", "Solutions per valid random action (PHYRE's pool, those simulated)", None),
)


def mean_sd(values: Iterable[float]) -> tuple[float, float] | None:
    """The mean and the (population) standard deviation of the values; None for none."""
    values = [float(v) for v in values]
    if not values:
        return None
    return statistics.mean(values), statistics.pstdev(values) if len(values) > 1 else 0.0


def measured(record: dict, metric: str) -> bool:
    """Whether the record has a figure for the metric: accidental solvability needs at least
    one play of the agent (records written before it was None for no play say 0.0)."""
    return metric != "accidental" or record.get("agent_plays") != 0


def summarise(records: list[dict]) -> dict:
    """The records' figures per scenario and per interaction count (`stats`: tasks made, each
    metric's Mean ± SD, costs, margins, why none), and what the report shows beside them."""

    def group(key: str) -> dict[object, list[dict]]:
        out: dict[object, list[dict]] = {}
        for r in records:
            out.setdefault(r[key], []).append(r)
        return out

    def stats(rows: list[dict]) -> dict[str, object]:
        made = [r for r in rows if r.get("generated")]
        # Fallbacks (--min-robustness): tasks whose solution passed fewer than all the
        # generator's noisy replays.
        fallbacks = sum(1 for r in made if r.get("robustness") and r["robustness"][0] < r["robustness"][1])
        out: dict[str, object] = {"tasks": len(rows), "generated": len(made), "fallbacks": fallbacks}
        for metric, _, _ in METRICS + AGENT_METRICS + ACCEPTANCE_METRICS + VERIFY_METRICS:
            out[metric] = mean_sd([r[metric] for r in made if r.get(metric) is not None and measured(r, metric)])
        out["no_agent_play"] = sum(1 for r in made if not measured(r, "accidental"))
        out |= effort(made)
        out["funnel"] = funnelled(rows)
        out["diversity"] = diversity(made)
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


def diversity(made: list[dict]) -> float | None:
    """How far apart a dataset's tasks lay out the same objects: for each scenario, the mean over
    its pairs of tasks of the mean distance (layout units) between each object's places as
    proposed (the record's `placed`, the objects both tasks have); the mean over the scenarios
    with two tasks or more. None: no scenario has two."""
    by_scenario: dict[str, list[dict]] = {}
    for r in made:
        if r.get("placed"):
            by_scenario.setdefault(r["scenario"], []).append(r["placed"])
    means = []
    for placements in by_scenario.values():
        pairs = []
        for i, a in enumerate(placements):
            for b in placements[i + 1 :]:
                shared = sorted(set(a) & set(b))
                if shared:
                    pairs.append(statistics.mean(float(np.hypot(*np.subtract(a[n], b[n]))) for n in shared))
        if pairs:
            means.append(statistics.mean(pairs))
    return statistics.mean(means) if means else None


def funnelled(rows: list[dict]) -> dict | None:
    """Where the placed layouts of `rows` went (their records' `funnel`, tasks made or not,
    physc.search.funnel): how many were placed, and the share that never realised the chain,
    realised it and were lost (to noise, a reading, a later check), and gave the task."""
    funnels = [r["funnel"] for r in rows if r.get("funnel")]
    placed = sum(f["placed"] for f in funnels)
    if not placed:
        return None
    chain = sum(f["chain_realised"] for f in funnels)
    lost: dict[str, int] = {}
    for f in funnels:
        for why, n in f["lost"].items():
            lost[why] = lost.get(why, 0) + n
    return {
        "placed": placed,
        "never": (placed - chain) / placed,
        "lost": {why: n / placed for why, n in sorted(lost.items())},
        "kept": sum(f["kept"] for f in funnels) / placed,
        "stage_simulations": sum(s["simulations"] for f in funnels for s in f["stages"]),
        "after_simulations": sum(f["simulations_after_chain"] for f in funnels),
    }


def why_none(reason: str) -> str:
    """A record's reason for no task, short: the budget or constraint that ended it, and how far
    the best simulation got."""
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
