"""Whether a benchmark keeps a task, by how random actions fare in it (PHYRE's acceptance).

PHYRE keeps a task of its ball tier only if random actions solve it *stably* at a rate
shown to be above 1e-5 (GOOD_STABLE: a one-sided binomial test, p < 0.05) and not
trivially (TRIVIAL: stable solutions are 10 % or more of all attempts, invalid ones
included); a solution is stable when each of its neighbours (PHYRE: the ball moved half a
pixel in the 8 directions) also solves the task or is invalid. PHYRE decides on 10,000
valid random actions or more (src/python/phyre/eval_task_complexity.py; docs/phyre-
sources.md, section 5). A generator cannot spend 10,000 simulations on every task, so
physc draws them one at a time and stops as soon as both answers are known with
`confidence`: GOOD_STABLE as soon as PHYRE's own binomial test passes on the attempts made
so far; TRIVIAL or not as soon as the exact (Clopper-Pearson) interval of the stable share
lies on one side of `trivial`. What cannot be settled within `attempts` valid draws is
decided as PHYRE would on those draws. A task is accepted when it is GOOD_STABLE, not
TRIVIAL, and its intended solution is stable.

A domain states its rule as `acceptance` (an `Acceptance`; None: every task is kept; or per
level, `acceptance_of`) and its
neighbourhood of an action as `neighbours` (physc.domains.simulated.SimulatedDomain).
"""

from __future__ import annotations

from collections.abc import Callable

import attrs


DRAWS_PER_ATTEMPT = 100  # draws per valid action at most (a scene random actions can hardly be placed in ends the draws)


@attrs.frozen
class Acceptance:
    """A benchmark's rule for keeping a task (module docstring)."""

    threshold: float
    """GOOD_STABLE: the stable-solve rate of random actions must be shown to exceed this (PHYRE's ball tier: 1e-5)."""
    p_value: float = 0.05
    """The level of the one-sided binomial test (PHYRE's P_VALUE)."""
    trivial: float = 0.1
    """TRIVIAL: stable solutions at this share of all attempts or more."""
    attempts: int = 10_000
    """Valid random actions drawn at most (PHYRE's MIN_VALID_ATTEMPTS)."""
    confidence: float = 0.99
    """How sure the early decision on TRIVIAL must be (the exact interval's level)."""


@attrs.frozen
class Verdict:
    """What the random actions showed: the counts, PHYRE's flags, and whether the intended
    solution is stable."""

    attempts: int  # random actions drawn (invalid ones included, as PHYRE counts them)
    valid: int
    solved: int
    stable: int  # of the solved, those judged stable (every neighbour solves too, or is invalid): a lower bound once the task is known not TRIVIAL
    good_stable: bool
    trivial: bool
    solution_stable: bool

    @property
    def accepted(self) -> bool:
        return self.good_stable and not self.trivial and self.solution_stable

    @property
    def flags(self) -> list[str]:
        """PHYRE's names of the flags that hold."""
        return [name for name, holds in (("GOOD_STABLE", self.good_stable), ("TRIVIAL", self.trivial)) if holds]

    def record(self) -> dict:
        """The figures a task file and `physc eval` keep."""
        return {
            "accepted": self.accepted, "flags": self.flags, "solution_stable": self.solution_stable, "attempts": self.attempts,
            "valid": self.valid, "solved": self.solved, "stable": self.stable, "stable_rate": round(self.stable / max(self.attempts, 1), 6),
        }


def good(stable: int, valid: int, rule: Acceptance) -> bool:
    """PHYRE's GOOD_STABLE test: P[X ≥ stable] < p_value for X ~ Binomial(valid, threshold)
    (the p-value of scipy's one-sided `binom_test`, which PHYRE calls, as the binomial's upper
    tail: `bdtrc(k - 1, n, p)`)."""
    from scipy.special import bdtrc

    return stable > 0 and bool(bdtrc(stable - 1, valid, rule.threshold) < rule.p_value)


def trivial_known(stable: int, attempts: int, rule: Acceptance) -> bool | None:
    """Whether the stable share is known to be at least `trivial` (True) or below it (False)
    with `confidence`; None while the interval straddles it. The interval is the exact
    (Clopper-Pearson) one, from the inverse of the incomplete beta function: scipy's
    `binomtest(...).proportion_ci(method="exact")` gives the same bounds at a thousand times
    the cost, which was half of a PHYRE-like task's acceptance."""
    from scipy.special import betaincinv

    tail = (1 - rule.confidence) / 2
    low = 0.0 if stable == 0 else float(betaincinv(stable, attempts - stable + 1, tail))
    high = 1.0 if stable == attempts else float(betaincinv(stable + 1, attempts - stable, 1 - tail))
    if low >= rule.trivial:  # (a share of none: the interval is [0, …])
        return True
    if high < rule.trivial:
        return False
    return None


def stable_solution(action, neighbours, valid: Callable, solves: Callable) -> bool:
    """Whether every neighbour of a solving `action` solves too, or is not a valid action."""
    return all(not valid(n) or solves(n) for n in neighbours(action))


def judge(rule: Acceptance, solution, draw: Callable, valid: Callable, solves: Callable, neighbours: Callable) -> Verdict:
    """The verdict on a task: `solution` its intended action, `draw()` a random action,
    `valid(a)` whether it may be taken, `solves(a)` whether it solves the task (a
    simulation), `neighbours(a)` the actions its stability is judged by.

    A random solution's stability (its neighbours' simulations) is judged only while it can
    change an answer: until the first stable one makes the task GOOD_STABLE, and while the
    share of *solutions* (an upper bound of the stable share) does not already show that the
    task is not TRIVIAL. A solution left unjudged is judged if that changes."""
    solution_stable = valid(solution) and stable_solution(solution, neighbours, valid, solves)
    if not solution_stable:  # rejected whatever random actions show
        return Verdict(0, 0, 0, 0, False, False, False)
    attempts = valid_count = solved = stable = 0
    unjudged: list = []  # random solutions whose stability was not needed yet
    is_good, is_trivial = False, None
    check_every = 1

    def judged(action) -> None:
        nonlocal stable, is_good
        if stable_solution(action, neighbours, valid, solves):
            stable += 1
            is_good = is_good or good(stable, valid_count, rule)

    while valid_count < rule.attempts and attempts < rule.attempts * DRAWS_PER_ATTEMPT:
        action = draw()
        attempts += 1
        if not valid(action):
            continue
        valid_count += 1
        if solves(action):
            solved += 1
            unjudged.append(action)
            if not is_good:
                judged(unjudged.pop())
        if attempts % check_every and not (unjudged and is_good and is_trivial is None):
            continue
        check_every = max(1, attempts // 20)  # the interval, now and then: it costs more than a draw
        if trivial_known(solved, attempts, rule) is False:  # not even the solutions reach the share
            is_trivial = False
        else:
            while unjudged:
                judged(unjudged.pop())
            is_trivial = trivial_known(stable, attempts, rule)
        if is_trivial or (is_trivial is False and is_good):
            break
    while unjudged and is_trivial is None:
        judged(unjudged.pop())
    if is_trivial is None:  # undecided within the draws: PHYRE's rule on them
        is_trivial = stable / max(attempts, 1) >= rule.trivial
    is_good = is_good or good(stable, valid_count, rule)
    return Verdict(attempts, valid_count, solved, stable, is_good, bool(is_trivial), solution_stable)


def verdict(domain, level, label: str, action, evaluator) -> Verdict | None:
    """`domain`'s verdict on a finished level whose intended action is `action` (labelled
    `label`); None when the domain has no rule. Random actions come from a generator named
    after the label, so a seed gives the same verdict in any process; every play is counted
    by the search's `evaluator`."""
    import random

    rule = domain.acceptance_of(level) if hasattr(domain, "acceptance_of") else getattr(domain, "acceptance", None)
    if rule is None:
        return None
    rng = random.Random(f"acceptance/{label}")

    def solves(candidate) -> bool:
        return evaluator.run(lambda: domain.play(level, candidate, recognise=False)).solved

    return judge(rule, action, lambda: domain.random_action(level, rng), lambda a: domain.valid(level, a), solves, domain.neighbours)
