"""A benchmark's acceptance of a task by its pool of random actions (physc_phyre.acceptance):
PHYRE's flags and stopping rule, the same verdict as PHYRE's full evaluation with fewer
simulations, and the give-ups."""

from __future__ import annotations

import math
import random

import pytest
from physc_phyre.acceptance import Acceptance, done, evaluate, flags, judge, outcome

# PHYRE's rule at a tenth of its pool, so that a test simulates thousands of actions, not
# tens of thousands: the thresholds are scaled so that the same binomial tests decide.
SMALL = Acceptance(threshold=1e-4, min_valid=1000, chunk=1000, screen=100)
INTENDED = -1.0  # the task's intended solution: it solves, and so do its neighbours


class World:
    """Actions are numbers in [0, 1) from a pool of seeded chunks; those below `solved` solve
    the task, and those below `stable` also keep solving a neighbour's distance away (a + 2;
    an unstable one has a neighbour that fails); those from `valid` to 1 are invalid."""

    def __init__(self, solved: float, stable: float | None = None, valid: float = 1.0, seed: int = 0, size: int = 1000):
        self.solved, self.stable, self.valid_below = solved, solved if stable is None else stable, valid
        self.seed, self.size = seed, size
        self.plays = 0

    def pool(self, chunk: int) -> list[float]:
        rng = random.Random(f"{self.seed}/{chunk}")
        return [rng.random() for _ in range(self.size)]

    def valid(self, a: float) -> bool:
        return a < self.valid_below or a >= 2 or a == INTENDED  # neighbours are valid

    def solves(self, a: float) -> bool:
        self.plays += 1
        return a == INTENDED or 0 <= a < self.solved or (a >= 2 and a - 2 < self.stable)

    def neighbours(self, a: float) -> list[float]:
        if a == INTENDED:
            return [INTENDED] * 8
        return [a + 2] * 8 if a < self.stable else [a + 2, 5.0]

    def evaluate(self, rule=SMALL, main=True):
        return evaluate(rule, self.pool, self.valid, self.solves, self.neighbours, main)


def phyres(rule: Acceptance, world: World, main: bool = True) -> tuple[bool, int | None, int]:
    """PHYRE's evaluation as eval_task_complexity.py runs it: every action of each chunk
    simulated and every solution judged, the flags computed at each chunk's end, until done.
    (answer, chunks, plays)."""
    attempts = valid = solved = stable = 0
    for chunk in range(rule.max_chunks):
        for a in world.pool(chunk):
            attempts += 1
            if not world.valid(a):
                continue
            valid += 1
            if world.solves(a):
                solved += 1
                stable += all(not world.valid(n) or world.solves(n) for n in world.neighbours(a))
        decided = outcome(rule, (attempts, valid, solved, stable), main)
        if decided is not None:
            return decided, chunk + 1, world.plays
    return False, None, world.plays


def test_phyres_flags_on_a_task_of_its_own():
    """PHYRE's 00000:000 in the ball tier (data/evaluations/00000.lzma): 20,000 attempts, 2,176
    invalid, 164 unstable and 3 stable solutions: GOOD and GOOD_STABLE, done."""
    rule = Acceptance(threshold=1e-5)
    held = flags(rule, 20_000, 17_824, 167, 3)
    assert held == {"GOOD", "GOOD_STABLE"}
    assert done(rule, 17_824, 167, 3, held)
    assert not done(rule, 9_999, 167, 3, held)  # fewer than 10,000 valid attempts
    assert not done(rule, 17_824, 167, 2, flags(rule, 20_000, 17_824, 167, 2))  # GOOD_STABLE, but 2 stable solutions
    assert flags(rule, 20_000, 17_824, 0, 0) == {"IMPOSSIBLE"}  # neither GOOD nor BAD: PHYRE draws on
    assert "TRIVIAL" in flags(rule, 20_000, 17_824, 2_500, 2_000)  # a tenth of all attempts, invalid ones included


@pytest.mark.parametrize(
    ("solved", "stable", "valid", "seed"),
    [
        (0.02, 0.02, 1.0, 0),
        (0.02, 0.01, 0.85, 1),
        (0.005, 0.004, 0.9, 2),
        (0.09, 0.09, 0.95, 3),
        (0.12, 0.1, 1.0, 4),
        (0.2, 0.05, 0.9, 5),
        (0.0, 0.0, 1.0, 6),
        (0.003, 0.001, 0.8, 7),
        (0.1, 0.1, 1.0, 8),
        (0.3, 0.3, 0.7, 9),
    ],
)
def test_the_early_verdict_is_phyres(solved, stable, valid, seed):
    """Whatever the rates, the verdict stopped early equals PHYRE's on every action, at the
    same chunk; never more plays."""
    rule = Acceptance(threshold=1e-4, min_valid=1000, chunk=1000, screen=0)  # (no give-up: the verdict must be PHYRE's)
    expected, chunks, full_plays = phyres(rule, World(solved, stable, valid, seed))
    world = World(solved, stable, valid, seed)
    result = world.evaluate(rule)
    assert result.answer == expected
    if chunks is not None:
        assert result.chunks == chunks and result.given_up is None
    assert world.plays <= full_plays


def test_a_rarely_solved_task_is_kept_with_fewer_plays_than_phyres():
    """Stability is judged only where it can change the verdict: here 3 stable solutions
    and the bound on TRIVIAL, against PHYRE's 8 neighbours for every solution. (Showing that
    a task is not TRIVIAL still takes most of its actions: any of them might be a stable
    solution.)"""
    world, reference = World(0.03, 0.03, 0.9), World(0.03, 0.03, 0.9)
    result = world.evaluate()
    expected, _, full_plays = phyres(SMALL, reference)
    assert result.answer and expected
    assert (
        result.counts.stable[0] >= SMALL.min_solutions
        and "GOOD_STABLE" in result.flags
        and "TRIVIAL" not in result.flags
    )
    assert world.plays < 0.75 * full_plays
    assert (
        result.counts.attempts == 2000 and result.counts.valid < 2000
    )  # two chunks: the first holds < 1,000 valid ones


def test_a_task_stably_solved_by_half_its_actions_is_given_up_as_trivial_at_once():
    world = World(0.5)
    result = world.evaluate()
    assert not result.answer and result.given_up.startswith("TRIVIAL beyond doubt")
    assert world.plays < 200


def test_a_task_never_solved_is_given_up_after_the_chunks_physc_allows():
    """PHYRE would draw until BAD (about 150,000 attempts at its threshold); physc stops."""
    result = World(0.0).evaluate(Acceptance(threshold=1e-4, min_valid=1000, chunk=1000, max_chunks=2))
    assert not result.answer and result.given_up == "undecided after 2 chunks of 1000 attempts" and result.chunks == 2
    assert result.counts.solved[0] == 0


def judged_in_two_tiers(ball: World, two_balls: World, ball_chunks: int = 20):
    """A two-ball task's verdict: actions are (tier, number), each tier's its own world. With
    no one-ball solution, BAD_STABLE needs 15,000 valid attempts at this threshold."""
    worlds = {"ball": ball, "two_balls": two_balls}
    ball_rule = Acceptance(threshold=1e-4, min_valid=1000, chunk=1000, screen=100, max_chunks=ball_chunks)
    rule = Acceptance(
        threshold=1e-5, tier="two_balls", min_valid=1000, chunk=1000, screen=100, unsolvable_in=(ball_rule,)
    )
    return judge(
        rule,
        INTENDED,
        lambda r, chunk: [(r.tier, u) for u in worlds[r.tier].pool(chunk)],
        lambda a: a == INTENDED or worlds[a[0]].valid(a[1]),
        lambda a: a == INTENDED or worlds[a[0]].solves(a[1]),
        lambda a: [INTENDED] * 8 if a == INTENDED else [(a[0], n) for n in worlds[a[0]].neighbours(a[1])],
    )


def test_a_task_solvable_in_an_easier_tier_is_rejected_before_its_own_is_judged():
    """PHYRE's `reject_ball_solvable`: a two-ball task one ball solves (GOOD_STABLE) is dropped."""
    two_balls = World(0.02, seed=1)
    verdict = judged_in_two_tiers(World(0.02), two_balls)
    assert not verdict.accepted and verdict.why == "solvable" and verdict.main is None
    assert verdict.record()["unsolvable_in"][0]["tier"] == "ball" and two_balls.plays == 0
    kept = judged_in_two_tiers(World(0.0), World(0.02, seed=1))  # one ball never solves it: BAD_STABLE
    assert kept.accepted and not kept.excluded[0].answer and kept.main.tier == "two_balls"
    assert kept.excluded[0].chunks == 15 and "BAD_STABLE" in kept.excluded[0].flags
    # Not shown unsolvable with one ball within the chunks allowed: not kept (PHYRE would draw on)
    undecided = judged_in_two_tiers(World(0.0), World(0.02, seed=1), ball_chunks=4)
    assert not undecided.accepted and undecided.why == "undecided" and undecided.main is None


def test_an_unstable_intended_solution_is_rejected_without_drawing():
    world = World(0.02, stable=0.005)
    verdict = judge(SMALL, 0.01, lambda r, chunk: world.pool(chunk), world.valid, world.solves, world.neighbours)
    assert not verdict.accepted and verdict.why == "unstable" and verdict.simulations == 1  # its first neighbour fails


def test_the_record_holds_the_counts_and_their_bounds():
    world = World(0.03, 0.03, 0.9)
    verdict = judge(SMALL, INTENDED, lambda r, chunk: world.pool(chunk), world.valid, world.solves, world.neighbours)
    record = verdict.record()
    assert record["accepted"] and record["tier"] == "ball" and record["chunks"] == 2 and record["attempts"] == 2000
    lo, hi = record["stable"]
    assert SMALL.min_solutions <= lo <= hi < 0.1 * record["attempts"]
    assert record["simulations"] == world.plays and 0.02 < record["solve_rate"] < 0.05


def test_a_template_that_allows_trivial_tasks_keeps_one_after_a_few_plays():
    """PHYRE's templates 00000, 00003, 00005, 00011 and 00024 require GOOD_STABLE and exclude
    nothing: a task half the actions solve is kept, as soon as 3 stable solutions are known."""
    rule = Acceptance(threshold=1e-4, min_valid=1000, chunk=1000, screen=100, excluded=())
    world = World(0.5)
    result = world.evaluate(rule)
    assert result.answer and result.given_up is None and "GOOD_STABLE" in result.flags
    expected, chunks, full_plays = phyres(rule, World(0.5))
    assert expected and result.chunks == chunks
    assert world.plays < 50 < full_plays


def test_auccess_weights_early_solutions_as_phyre_does():
    from physc_phyre.agents import auccess

    assert auccess(1) == pytest.approx(1.0)
    assert auccess(None) == 0.0 and auccess(101) == 0.0
    assert auccess(100) == pytest.approx((math.log(101) - math.log(100)) / math.log(101))
    assert auccess(10) == pytest.approx((math.log(101) - math.log(10)) / math.log(101))
