"""PHYRE's evaluation of its tasks (`Phyre.evaluation`): PHYRE's acceptance of a task, decided on
PHYRE's own pool of random actions (acceptance.py, pool.py), its random agent with AUCCESS as the
accidental solvability, any agent scored on a generated benchmark (agents.py), and what the
measurements mean."""

from __future__ import annotations

import random

import attrs

from physc.domains.evaluation import Evaluation
from physc_phyre.acceptance import Acceptance, verdict
from physc_phyre.level import PhyreLevel

# PHYRE's SOLVABILITY_THRESHOLD_PROBS (docs/phyre-sources.md, section 5), by PHYRE's action tier.
THRESHOLDS = {"ball": 1e-5, "two_balls": 1e-6}
# A level's tier (task.thrift's `tier`) → the action tier that judges it.
ACTION_TIERS = {"BALL": "ball", "TWO_BALLS": "two_balls"}
BALLS = {"ball": 1, "two_balls": 2}  # red balls an action of the tier places
# PHYRE decides a two-ball task's ball tier first and draws until it is decided: with no
# stable one-ball solution, BAD_STABLE needs about 150,000 valid attempts (P[X = 0] < 0.05 at
# twice 1e-5), with one about 237,000; physc allows 30 chunks (300,000 attempts) before it
# gives the task up.
BALL_CHUNKS_FOR_TWO_BALLS = 30


class PhyreEvaluation(Evaluation):
    """PHYRE's evaluation, for the bound domain."""

    measures = (
        "stability = PHYRE's acceptance of a scene: left alone for 1,000 steps (16.7 s), it does not solve itself (its "
        "objects may move at the start, as in PHYRE's templates); intended "
        "solvability = the recorded action solves the task (exactly; and the share of 10 replays with the ball moved "
        "σ 0.5 px, PHYRE's half-pixel test of a stable solution); sequence fidelity = the replay realises the declared "
        "sequence; accidental solvability = the share of 100 valid attempts of PHYRE's random agent (uniform actions, "
        "occluding ones dropped) that solve the task; AUCCESS = PHYRE's area under the success curve of those attempts."
    )

    ball_rule = Acceptance(threshold=THRESHOLDS["ball"], tier="ball")
    """PHYRE's acceptance of a ball-tier task, decided as PHYRE's eval_task_complexity.py
    decides it on PHYRE's own pool of random actions (acceptance.py): done
    after ≥ 10,000 valid attempts and ≥ 3 stable solutions, kept when GOOD_STABLE (a stable
    solve rate shown above 1e-5) and not TRIVIAL; and, physc's own addition, its intended
    solution stable under half-pixel moves."""

    def rule(self, level: PhyreLevel) -> Acceptance:
        """The rule of the level's tier: two balls with threshold 1e-6, and the task must not
        be GOOD_STABLE with one ball (PHYRE's two-ball templates all `reject_ball_solvable`);
        TRIVIAL allowed where the scenario says `mayBeTrivial()`, as some of PHYRE's
        templates do."""
        rule = attrs.evolve(self.ball_rule, excluded=()) if level.may_be_trivial else self.ball_rule
        if level.tier == "BALL":
            return rule
        tier = ACTION_TIERS[level.tier]
        ball = attrs.evolve(self.ball_rule, max_chunks=BALL_CHUNKS_FOR_TWO_BALLS)
        return attrs.evolve(rule, threshold=THRESHOLDS[tier], tier=tier, unsolvable_in=(ball,))

    @staticmethod
    def action_pool(level: PhyreLevel, tier: str, chunk: int, size: int) -> list:
        """The first `size` actions of chunk `chunk` of PHYRE's acceptance pool of `tier` (pool.py)."""
        from physc_phyre.pool import acceptance_chunk

        return acceptance_chunk(BALLS[tier], chunk, size)[1]

    def score_agent(self, folder, agent, setup: str, folds, split: str) -> dict:
        """PHYRE's AUCCESS of `agent` on the folds of a generated benchmark (agents.py)."""
        from physc_phyre.agents import score

        return score(self.domain, folder, agent, setup, folds, split)

    def acceptance(self, level: PhyreLevel, action, solves):
        """PHYRE's verdict on the task (acceptance.py), by the rule of its tier."""
        actions = self.domain.actions
        return verdict(self.rule(level), level, action, solves, self.action_pool, actions.valid, actions.neighbours)

    def accidental(self, level: PhyreLevel, scenario, solution, rng: random.Random) -> dict:
        """PHYRE's random agent (agents.py): up to 100 valid actions drawn from `rng`, each
        played; the fraction that solve the level, and the task's AUCCESS."""
        from physc_phyre.agents import random_attempts

        return random_attempts(self.domain, level, rng)
