"""A benchmark's acceptance of a task by random actions (physc.generation.acceptance): PHYRE's
GOOD_STABLE and TRIVIAL, decided early when the answer is known, and the stability of a
solution by its neighbours."""

from __future__ import annotations

import random

import pytest

from physc.generation.acceptance import Acceptance, good, judge, trivial_known

PHYRE = Acceptance(threshold=1e-5, attempts=1000)
INTENDED = -1.0  # the task's intended solution: it solves, and so do its neighbours


class World:
    """Actions are numbers in [0, 1); those below `solved` solve the task, and those below
    `stable` also keep solving a neighbour's distance away (a + 2; an unstable one has a
    neighbour that fails); those from `valid` to 1 are invalid."""

    def __init__(self, solved: float, stable: float | None = None, valid: float = 1.0, seed: int = 0):
        self.solved, self.stable, self.valid_below = solved, solved if stable is None else stable, valid
        self.rng = random.Random(seed)
        self.plays = 0

    def draw(self) -> float:
        return self.rng.random()

    def valid(self, a: float) -> bool:
        return a < self.valid_below or a >= 2 or a == INTENDED  # neighbours are valid

    def solves(self, a: float) -> bool:
        self.plays += 1
        return a == INTENDED or 0 <= a < self.solved or (a >= 2 and a - 2 < self.stable)  # a neighbour of a stable solution is a + 2

    def neighbours(self, a: float) -> list[float]:
        if a == INTENDED:
            return [INTENDED] * 8
        return [a + 2] * 8 if a < self.stable else [a + 2, 5.0]

    def judge(self, rule=PHYRE, solution=None):
        solution = INTENDED if solution is None else solution
        return judge(rule, solution, self.draw, self.valid, self.solves, self.neighbours)


def test_phyres_binomial_test():
    """One stable solution in 10,000 does not show a rate above 1e-5 (P = 0.095); two do
    (0.005); one in 1,000 does (0.01)."""
    rule = Acceptance(threshold=1e-5)
    assert not good(1, 10_000, rule) and good(2, 10_000, rule) and good(1, 1000, rule) and not good(0, 10, rule)


def test_the_trivial_share_is_known_once_its_interval_lies_on_one_side():
    assert trivial_known(60, 100, PHYRE) is True
    assert trivial_known(0, 100, PHYRE) is False
    assert trivial_known(10, 100, PHYRE) is None


def test_a_task_random_actions_never_solve_is_not_good_after_every_draw():
    world = World(solved=0.0)
    verdict = world.judge()
    assert (verdict.valid, verdict.solved, verdict.good_stable, verdict.trivial) == (1000, 0, False, False)
    assert not verdict.accepted and verdict.flags == []


def test_a_task_half_the_random_actions_solve_is_trivial_early():
    verdict = World(solved=0.5).judge()
    assert verdict.trivial and verdict.good_stable and not verdict.accepted
    assert verdict.attempts < 100  # known long before the draws run out
    assert verdict.flags == ["GOOD_STABLE", "TRIVIAL"]


def test_a_task_rarely_solved_stably_is_accepted_early_and_judges_few_solutions():
    world = World(solved=0.02)
    verdict = world.judge()
    assert verdict.good_stable and not verdict.trivial and verdict.solution_stable and verdict.accepted
    assert verdict.attempts < 400
    # the first solution's neighbours are played (GOOD_STABLE needs one); the share of solutions
    # shows it is not TRIVIAL, so the others' are not
    assert world.plays < verdict.valid + 9 * 2 + 8


def test_invalid_actions_count_as_attempts_for_trivial_but_not_for_good():
    """PHYRE's TRIVIAL share is over all attempts, invalid ones included: 12 % of the valid
    actions solve, but only 6 % of all."""
    verdict = World(solved=0.06, valid=0.5).judge()
    assert verdict.attempts > 1.8 * verdict.valid
    assert not verdict.trivial and verdict.accepted


def test_unstable_solutions_are_neither_good_nor_trivial():
    """Every random solution has a neighbour that fails: none is stable, so the task is not
    GOOD_STABLE, however often it is solved."""
    verdict = World(solved=0.3, stable=0.0).judge()
    assert verdict.solved > 0 and verdict.stable == 0 and not verdict.good_stable and verdict.solution_stable


def test_an_intended_solution_that_is_not_stable_or_not_valid_ends_the_judging_at_once():
    world = World(solved=0.3, stable=0.0)
    verdict = world.judge(solution=0.1)
    assert not verdict.solution_stable and verdict.attempts == 0 and not verdict.accepted
    assert not World(solved=0.3, valid=0.5).judge(solution=0.7).solution_stable  # an invalid action


def test_a_solution_with_a_failing_neighbour_is_not_accepted():
    world = World(solved=0.02, stable=0.01)
    assert world.judge(solution=0.015).solution_stable is False
    assert world.judge(solution=0.005).solution_stable is True


def test_the_verdict_is_the_same_for_the_same_draws():
    assert World(0.05, seed=3).judge() == World(0.05, seed=3).judge()


@pytest.mark.parametrize("share", [0.08, 0.12])
def test_undecided_within_the_draws_falls_back_on_phyres_rule(share):
    rule = Acceptance(threshold=1e-5, attempts=60)
    verdict = World(share, seed=1).judge(rule)
    assert verdict.valid == 60
    assert verdict.trivial == (verdict.stable / verdict.attempts >= 0.1)


def test_the_tests_closed_forms_agree_with_scipys_binomtest():
    """`good` is scipy's one-sided binomial test (PHYRE's binom_test) and `trivial_known` reads
    scipy's exact interval, computed in closed form."""
    from scipy.stats import binomtest

    rule = Acceptance(threshold=1e-5)
    for n in (1, 7, 40, 333, 1000):
        for k in sorted({0, 1, 2, 3, n // 10, n // 3, n - 1, n}):
            if not 0 <= k <= n:
                continue
            expected = k > 0 and binomtest(k, n, rule.threshold, alternative="greater").pvalue < rule.p_value
            assert good(k, n, rule) == expected, (k, n)
            interval = binomtest(k, n).proportion_ci(confidence_level=rule.confidence, method="exact")
            known = True if interval.low >= rule.trivial else False if interval.high < rule.trivial else None
            assert trivial_known(k, n, rule) == known, (k, n)
