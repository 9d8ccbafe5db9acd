"""Whether a benchmark keeps a task, by how its fixed pool of random actions fares in it:
PHYRE's acceptance, decided as PHYRE's evaluation decides it, on PHYRE's own actions, with
far fewer simulations.

PHYRE (src/python/phyre/eval_task_complexity.py; docs/phyre-sources.md, section 5)
simulates a fixed pool of random actions on a task, in chunks of 10,000, and counts each
as invalid (it occludes a body), not solved, solved unstably, or solved stably (each
neighbour, the ball moved half a pixel, solves too or is invalid). After each chunk it
computes its flags from the counts (`flags`) and stops once the task is done: at least
10,000 valid attempts, GOOD or BAD, GOOD_STABLE or BAD_STABLE, and at least 3 solutions
(stable solutions) where GOOD (GOOD_STABLE) holds. The task is kept when its flags then
hold GOOD_STABLE and not TRIVIAL (a template's `required_flags` and `excluded_flags`: a few
of PHYRE's allow TRIVIAL); a two-ball task also needs the ball tier's flags, done first, not
to hold GOOD_STABLE (`Acceptance.unsolvable_in`: PHYRE's
`reject_ball_solvable`).

The same verdict, sooner: which actions are valid is geometry, known without simulating,
so each chunk's attempts and valid attempts are known before any simulation. Only the
solved and stable counts are unknown, and each flag is monotone in one of them. physc
simulates the pool's actions in order and bounds the counts at the end of the chunk that
could be PHYRE's last; it stops as soon as every count within the bounds gives the same
answer (`_settled`). A verdict reached so is PHYRE's verdict on that pool, given the
engine's outcome of each action.

Giving up: physc never keeps a task PHYRE would not, but it may reject one before PHYRE's
rule decides: after `max_chunks` chunks (PHYRE draws until its rule decides, up to
150,000 actions for a task with rare solutions), or when the stable share of the first
`screen` attempts is above `trivial` beyond doubt (`give_up`: the exact interval at that
level lies above it). The record says which.

The PHYRE-like domain states its rule per level (evaluation.py, `PhyreEvaluation.rule`), its
pool as PHYRE's (pool.py) and the neighbourhood of an action as its actions' `neighbours`; physc's
search asks for the verdict through the domain's evaluation (physc.domains.evaluation).
"""

from __future__ import annotations

import functools
from collections.abc import Callable

import attrs


@attrs.frozen
class Acceptance:
    """A benchmark's rule for keeping a task (module docstring). The defaults are PHYRE's."""

    threshold: float
    """GOOD: the solve rate of random actions must be shown above this (PHYRE: 1e-5 ball, 1e-6 two balls)."""
    tier: str = "ball"
    """The tier whose pool of actions judges the task (the domain's name for it)."""
    p_value: float = 0.05
    """The level of PHYRE's one-sided binomial tests (P_VALUE)."""
    trivial: float = 0.1
    """TRIVIAL: stable solutions at this share of all attempts, invalid ones included, or more."""
    min_valid: int = 10_000
    """Valid attempts before the rule may decide (MIN_VALID_ATTEMPTS)."""
    min_solutions: int = 3
    """Solutions (stable ones) the rule needs before deciding GOOD (GOOD_STABLE) (MIN_SOLUTIONS)."""
    chunk: int = 10_000
    """Attempts a chunk (ACTION_POOL_SIZE: the rule decides only at a chunk's end)."""
    max_chunks: int = 4
    """physc gives the task up, rejected, if the rule has not decided after this many chunks."""
    screen: int = 1_000
    """The first attempts, whose solutions are all judged, for the TRIVIAL give-up."""
    give_up: float = 1e-4
    """The chance left that a task given up as TRIVIAL from its first attempts is not."""
    unsolvable_in: tuple[Acceptance, ...] = ()
    """Rules of other tiers under which the task must not be GOOD_STABLE (decided first)."""
    required: tuple[str, ...] = ("GOOD_STABLE",)
    """The flags a kept task holds when decided (PHYRE's `required_flags` of a template)."""
    excluded: tuple[str, ...] = ("TRIVIAL",)
    """The flags it must not hold (`excluded_flags`: most of PHYRE's templates exclude TRIVIAL)."""


@attrs.frozen
class Counts:
    """What a chunk's end sees: attempts and valid ones (known), solved and stable (bounds)."""

    attempts: int
    valid: int
    solved: tuple[int, int]
    stable: tuple[int, int]


@attrs.frozen
class TierResult:
    """One tier's evaluation: its answer (kept, or GOOD_STABLE for an `unsolvable_in` tier),
    the counts where it was decided, the flags certain there, and why it was given up."""

    tier: str
    answer: bool
    chunks: int
    counts: Counts
    flags: tuple[str, ...]
    simulated: int  # random actions simulated (neighbours not counted)
    solved_simulated: int  # of those, the solutions
    given_up: str | None = None

    def record(self) -> dict:
        c = self.counts
        return {
            "tier": self.tier,
            "chunks": self.chunks,
            "attempts": c.attempts,
            "valid": c.valid,
            "solved": list(c.solved),
            "stable": list(c.stable),
            "flags": list(self.flags),
            "simulated": self.simulated,
            "given_up": self.given_up,
            "solve_rate": round(self.solved_simulated / max(self.simulated, 1), 6),
        }


# Why a task is not kept, in PHYRE's terms: the phrases a search gives its layout up with.
REASONS = {
    "unstable": "the solution's neighbours do not all solve it",
    "solvable": "an easier tier's random actions solve it (GOOD_STABLE there)",
    "undecided": "an easier tier's random actions did not show it unsolvable within the chunks allowed",
    "trivial": "random actions solve it too often (TRIVIAL)",
    "not_good": "random actions do not solve it (not GOOD_STABLE)",
}


@attrs.frozen
class Verdict:
    """The rule's verdict on a task: its own tier's evaluation, those of the tiers it must not
    be solvable in, and whether the intended solution is stable."""

    solution_stable: bool
    main: TierResult | None  # None: the intended solution was not stable, nothing else judged
    excluded: tuple[TierResult, ...] = ()
    simulations: int = 0  # every play, neighbours included

    @property
    def accepted(self) -> bool:
        return (
            self.solution_stable
            and self.main is not None
            and self.main.answer
            and not any(t.answer or t.given_up for t in self.excluded)
        )

    @property
    def flags(self) -> list[str]:
        return list(self.main.flags) if self.main is not None else []

    @property
    def trivial(self) -> bool:
        return "TRIVIAL" in self.flags

    @property
    def reason(self) -> str:
        """Why the task is not kept, in the words the search's ledger records it under ('' when
        it is kept): REASONS' unstable, solvable, undecided (an easier tier's rule did not
        decide within its chunks), trivial or not_good."""
        if self.accepted:
            return ""
        return REASONS[self.why]

    @property
    def why(self) -> str:
        """The key of `reason` in REASONS ('' when the task is kept)."""
        if self.accepted:
            return ""
        if not self.solution_stable:
            return "unstable"
        if any(t.answer for t in self.excluded):
            return "solvable"
        if any(t.given_up for t in self.excluded):
            return "undecided"
        return "trivial" if self.trivial else "not_good"

    def record(self) -> dict:
        """The figures a task file and `physc eval` keep."""
        main = self.main.record() if self.main is not None else {}
        return {
            "accepted": self.accepted,
            "flags": self.flags,
            "solution_stable": self.solution_stable,
            "simulations": self.simulations,
            **main,
            "unsolvable_in": [t.record() for t in self.excluded],
        }


def flags(rule: Acceptance, attempts: int, valid: int, solved: int, stable: int) -> frozenset[str]:
    """PHYRE's `compute_flags` on counts: GOOD/BAD and GOOD_STABLE/BAD_STABLE by one-sided
    binomial tests against the threshold (twice it for BAD), IMPOSSIBLE with no solution,
    TRIVIAL at a stable share of `trivial` of all attempts or more."""
    out = set()
    for suffix, count in (("", solved), ("_STABLE", stable)):
        if _greater(count, valid, rule.threshold) < rule.p_value:
            out.add("GOOD" + suffix)
        if _less(count, valid, 2 * rule.threshold) < rule.p_value:
            out.add("BAD" + suffix)
    if not solved:
        out.add("IMPOSSIBLE")
    if stable / max(attempts, 1) >= rule.trivial:
        out.add("TRIVIAL")
    return frozenset(out)


@functools.lru_cache(maxsize=4096)
def _greater(k: int, n: int, p: float) -> float:
    """P[X ≥ k], X ~ Binomial(n, p): scipy's `binom_test(k, n, p, alternative='greater')`,
    which PHYRE calls, as the binomial's upper tail."""
    from scipy.special import bdtrc

    return 1.0 if k <= 0 else float(bdtrc(k - 1, n, p))


@functools.lru_cache(maxsize=4096)
def _less(k: int, n: int, p: float) -> float:
    """P[X ≤ k] (`alternative='less'`)."""
    from scipy.special import bdtr

    return float(bdtr(k, n, p))


def done(rule: Acceptance, valid: int, solved: int, stable: int, held: frozenset[str]) -> bool:
    """PHYRE's `_update_done_stats`: whether the rule decides at these counts."""
    if valid < rule.min_valid or not {"GOOD", "BAD"} & held or not {"GOOD_STABLE", "BAD_STABLE"} & held:
        return False
    return not ("GOOD" in held and solved < rule.min_solutions) and not (
        "GOOD_STABLE" in held and stable < rule.min_solutions
    )


def answer(rule: Acceptance, held: frozenset[str], main: bool) -> bool:
    """A decided tier's answer: kept (the required flags held, the excluded ones not), or for
    a tier the task must not be solvable in, whether it is (GOOD_STABLE)."""
    if not main:
        return "GOOD_STABLE" in held
    return set(rule.required) <= held and not set(rule.excluded) & held


def outcome(rule: Acceptance, counts: tuple[int, int, int, int], main: bool) -> bool | None:
    """The answer if the rule decides at these counts (attempts, valid, solved, stable), else None."""
    attempts, valid, solved, stable = counts
    held = flags(rule, attempts, valid, solved, stable)
    return answer(rule, held, main) if done(rule, valid, solved, stable, held) else None


def _points(lo: int, hi: int, tests) -> list[int]:
    """The counts in [lo, hi] at which any of the monotone `tests` changes, with the ends:
    between two neighbouring points every test keeps its value."""
    points = {lo, hi}
    for test in tests:
        first = test(lo)
        if test(hi) == first:
            continue
        a, b = lo, hi  # test(a) == first != test(b)
        while b - a > 1:
            m = (a + b) // 2
            a, b = (m, b) if test(m) == first else (a, m)
        points.update((a, b))
    return sorted(points)


def _settled(rule: Acceptance, counts: Counts, main: bool) -> tuple[bool, set]:
    """Whether every solved and stable count within `counts`' bounds (stable never beyond what
    the solved count allows) gives the same outcome; and the outcomes found."""
    n, t = counts.valid, counts.attempts
    (s_lo, s_hi), (st_lo, st_hi) = counts.solved, counts.stable
    solved_tests = (
        lambda k: _greater(k, n, rule.threshold) < rule.p_value,
        lambda k: _less(k, n, 2 * rule.threshold) < rule.p_value,
        lambda k: k >= rule.min_solutions,
        lambda k: k > 0,
    )
    stable_tests = solved_tests[:3] + (lambda k: k / max(t, 1) >= rule.trivial,)
    seen = set()
    for s in _points(s_lo, s_hi, solved_tests):
        top = st_hi - (s_hi - s)  # the unknown stable ones are among the unknown solutions
        for st in _points(st_lo, max(st_lo, top), stable_tests):
            seen.add(outcome(rule, (t, n, s, st), main))
            if len(seen) > 1:
                return False, seen
    return True, seen


def _trivial_beyond_doubt(stable: int, attempts: int, rule: Acceptance) -> bool:
    """Whether the exact (Clopper-Pearson) lower bound of the stable share, at `give_up`,
    lies at `trivial` or above."""
    from scipy.special import betaincinv

    return stable > 0 and float(betaincinv(stable, attempts - stable + 1, rule.give_up)) >= rule.trivial


def stable_solution(action, neighbours, valid: Callable, solves: Callable) -> bool:
    """Whether every neighbour of a solving `action` solves too, or is not a valid action."""
    return all(not valid(n) or solves(n) for n in neighbours(action))


def evaluate(
    rule: Acceptance, pool: Callable, valid: Callable, solves: Callable, neighbours: Callable, main: bool = True
) -> TierResult:
    """PHYRE's evaluation of a task in `rule`'s tier, settled early (module docstring):
    `pool(chunk)` the chunk's actions, `valid(a)`, `solves(a)` (a simulation),
    `neighbours(a)`. `main`: the answer is whether the task is kept; otherwise whether it is
    GOOD_STABLE."""
    chunks = attempts = 0
    pending: list[tuple[int, object]] = []  # the valid actions in pool order, each with its attempt's number (from 1)
    solved = stable = simulated = 0  # simulated: pending[:simulated] are done
    unjudged: list = []

    def bounds() -> Counts:
        left = len(pending) - simulated  # valid actions not simulated yet
        return Counts(attempts, len(pending), (solved, solved + left), (stable, stable + len(unjudged) + left))

    def result(answer_: bool, given_up: str | None = None) -> TierResult:
        counts = bounds()
        certain = [
            name
            for name in ("GOOD_STABLE", "GOOD", "BAD_STABLE", "BAD", "IMPOSSIBLE", "TRIVIAL")
            if all(
                name in flags(rule, counts.attempts, counts.valid, s, st) for s in counts.solved for st in counts.stable
            )
        ]
        return TierResult(rule.tier, answer_, chunks, counts, tuple(certain), simulated, solved, given_up)

    screens = main and "TRIVIAL" in rule.excluded  # the TRIVIAL give-up, on the first `screen` attempts
    while True:
        if chunks == rule.max_chunks:
            return result(False, f"undecided after {rule.max_chunks} chunks of {rule.chunk} attempts")
        for action in pool(chunks):
            attempts += 1
            if valid(action):
                pending.append((attempts, action))
        chunks += 1
        wait = 0  # simulations before the bounds are tried again: they settle only near the end
        while True:
            counts = bounds()
            if wait <= 0:
                settled, seen = _settled(rule, counts, main)
                if settled:
                    break
                wait = (counts.solved[1] - counts.solved[0]) // 100
            wait -= 1
            if simulated < len(pending):  # simulate the next valid action
                screened, action = pending[simulated]  # attempts up to this one
                simulated += 1
                screening = screens and screened <= rule.screen
                if solves(action):
                    solved += 1
                    if screening or stable < rule.min_solutions:
                        stable += stable_solution(action, neighbours, valid, solves)
                    else:
                        unjudged.append(action)
                if screening and _trivial_beyond_doubt(stable, screened, rule):
                    return result(False, f"TRIVIAL beyond doubt in the first {screened} attempts")
            else:  # every action simulated: judge the solutions left
                stable += stable_solution(unjudged.pop(), neighbours, valid, solves)
        (decided,) = seen
        if decided is not None:
            return result(decided)


def judge(
    rule: Acceptance, solution, pool: Callable, valid: Callable, solves: Callable, neighbours: Callable
) -> Verdict:
    """The verdict on a task whose intended action is `solution`: `pool(rule, chunk)` the
    chunk of `rule`'s tier and size, the rest as `evaluate` takes them. The tiers the task must not
    be solvable in are judged first, as PHYRE does, and a task solvable there is not judged
    in its own."""
    plays = [0]

    def counted(action) -> bool:
        plays[0] += 1
        return solves(action)

    if not (valid(solution) and stable_solution(solution, neighbours, valid, counted)):
        return Verdict(False, None, simulations=plays[0])
    excluded = []
    for other in rule.unsolvable_in:
        excluded.append(evaluate(other, lambda chunk, r=other: pool(r, chunk), valid, counted, neighbours, main=False))
        if excluded[-1].answer or excluded[-1].given_up:  # solvable there, or not shown unsolvable: not kept
            return Verdict(True, None, tuple(excluded), plays[0])
    main = evaluate(rule, lambda chunk: pool(rule, chunk), valid, counted, neighbours)
    return Verdict(True, main, tuple(excluded), plays[0])


def verdict(
    rule: Acceptance, level, action, solves: Callable, pool: Callable, valid: Callable, neighbours: Callable
) -> Verdict:
    """`rule`'s verdict on a finished level whose intended action is `action`: `solves(candidate)`
    plays one action (within the search's budget), `pool(level, tier, chunk, size)` the pool's
    chunks, `valid(level, action)` and `neighbours(action)` as the domain's actions say."""
    return judge(
        rule,
        action,
        lambda r, chunk: pool(level, r.tier, chunk, r.chunk),
        lambda a: valid(level, a),
        solves,
        neighbours,
    )
