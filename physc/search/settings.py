"""The search's settings in one place: budgets, beams and the noise streams.

Every number that bounds the one generation search (physc.search.search) is a field
of `SearchSettings`, with its default here and nowhere else; a domain that needs other
values sets its own `search.settings` (physc.domains.search_hooks; PHYRE-like: the same; angrybirds: the same). The
measurements that chose them are in docs/generation.md.
"""

from __future__ import annotations

import attrs

NOISE_STREAMS = (
    "robustness",
    "confirmation",
)  # the replays a solution is chosen for, and the fresh ones that confirm it

# Why a layout is given up (`Outcome.given_up`), in the order of the search's steps.
NO_ACTION = "no candidate action"
NOT_REALISED = "the sequence was not realised"
FRAGILE = "the solution was too fragile"
NOT_OBSTRUCTED = "a forbidden hit could not be blocked"
OBSTRUCTED_FRAGILE = "the obstacles made the solution fragile"
CONTRAST_SOLVES = "a contrast solved the task as its counterpart does"
CONTRAST_UNAIMED = "a contrast's counterpart is not what the player acts on"
PROPERTY_BROKEN = "an action the player could send breaks a declared property"
PROPERTY_UNCHECKED = "the domain cannot play the actions a declared property is checked against"
IMPRECISE = "an action the agents may send beside the solution's does not solve it"  # physc.search.precision
UNSTABLE = "the level did not stand"
NOT_VALIDATED = "validation failed"
INVALID_ACTION = "the solution is not a valid action in the finished level"
NOT_ACCEPTED = "the benchmark's acceptance rule did not keep it"  # where its verdict gives no words (Verdict.reason)


@attrs.frozen
class SearchSettings:
    """What bounds the search of one placed layout."""

    variants: int = 60
    """Variants of stages simulated per layout at most (the budget of the stage search)."""
    variants_per_stage: int = 12
    """Variants tried per stage and parent at most, before the search backtracks."""
    beam: int = 3
    """Actions that realise a stage, kept for the next."""
    screen: int = 4
    """Candidate actions a changed first stage is tried with before the rest."""
    places: int = 6
    """Places offered along the path of each of the beam's first two actions."""
    bodies: int = 3
    """Bodies (kind, material, size) offered for a new object at each place."""
    step: float = 0.3
    """Layout units of travel between the places a target is offered along a path."""
    gap: float = 0.02
    """Layout units between a placed target and the actor that is to meet it."""
    clear: float = 0.05
    """Layout units a placed target keeps from where the prefix's bodies pass before the hit."""
    moving: float = 0.25
    """Trace units per second: an actor slower than this is offered no targets further on."""
    settle: float = 0.3
    """Seconds after a roll, slide or fall is recognised before its path is read for the next target."""
    snapshots: bool = True
    """Whether a stage's variants go on from a snapshot of the parent's play (confirmed by a
    full run when they pass; physc.simulation.snapshot) instead of replaying the prefix."""
    snapshot_lead: float = 0.25
    """Seconds before a body of the prefix first comes within `clear` of a new object that
    the snapshot is cut."""
    snapshot_least: float = 0.5
    """Seconds of the prefix a snapshot must save (less: the variant is run in full)."""
    proposals: int = 6
    """Local changes offered per stage and changed layout (physc.search.proposals)."""
    repair_depth: int = 3
    """Local changes on top of one another."""
    candidates: int = 3
    """Working actions put through the noisy replays at most, per layout."""
    stage_replays: int = 3
    """Noisy replays of a stage's scene that judge a variant's strength (physc.search.chain)."""
    weak_kept: int = 3
    """Weak variants of a stage (a noisy replay lost a link) met before the strongest of them is
    built on, when no strong one came first (physc.search.chain)."""
    raise_stages: int = 4
    """Stages per layout whose failed or weak links the search raises (physc.search.chain)."""
    raise_stage_evaluations: int = 24
    """Candidates a stage's raising judges at most, each played once and in `stage_replays`
    noisy replays."""
    raise_candidates: int = 1
    """Working actions per layout whose margins the strengthening raises (the first ones)."""
    raise_evaluations: int = 36
    """Candidates (layouts and actions) the strengthening simulates at most per action, each
    played once and in the domain's noisy replays."""
    raise_enough: float = 0.25
    """The least margin (as a share of each link's scale, physc.simulation.margins) that every
    link must keep in every noisy replay for the strengthening to stop before its budget."""
    raise_population: int = 6
    """Candidates per generation of CMA-ES."""
    raise_sigma: float = 0.1
    """CMA-ES's first step raising a whole chain's margins, as a share of each coordinate's
    reach: a realised chain is a narrow region, and a step of a tenth (angrybirds: 0.15 units,
    0.3° of release angle) keeps most candidates in it."""
    raise_stage_sigma: float = 0.35
    """CMA-ES's first step raising a stage, whose link may not happen at all yet: wider."""
    raise_reach: float = 15.0
    """How far the strengthening may move an object or a surface's end either way, in the
    layout's clearances (angrybirds: 0.4 units; PHYRE-like: 8 pixels)."""
    raise_turn: float = 5.0
    """Degrees the strengthening may turn an inclined surface either way."""
    raise_steps: int = 60
    """Steps along each of the domain's `actions.lines` the strengthening may move the action
    either way (angrybirds: 3° of a shot's release angle, 0.3 s of its tap or wait)."""
    obstacles: int = 6
    """Obstacles tried per forbidden hit."""
    shortcuts: int = 3
    """Shortcuts (solving actions at other objects) blocked at most."""
    distractors: int = 3
    """Distractors added at most."""
    accidental: float = 0.05
    """The share of the evaluation's agent's plays that may solve a task by accident
    (physc.search.accidents; the paper's measure, which issue 74 asks to keep at 0.05 or less)."""
    accident_guards: int = 4
    """Plays that solve by accident that the search tries to block, at most."""


SETTINGS = SearchSettings()
