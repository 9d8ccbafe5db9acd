"""Science Birds' evaluation (`AngryBirds.evaluation`): the paper's heuristic agent measures how
often a task is solved by accident (agent.py). No acceptance rule: every task the search finds is
kept."""

from __future__ import annotations

from physc.domains.evaluation import Evaluation


class ScienceBirdsEvaluation(Evaluation):
    """Science Birds' evaluation, in the bound domain's world."""

    def accidental(self, level, scenario, solution, rng) -> dict:
        """The paper's heuristic agent (agent.py): it shoots at everything but the first target."""
        from physc.domains.angrybirds.agent import accidental

        first = self.domain.reach_targets(scenario)
        fraction, plays = accidental(self.domain, level, first[0] if first else None)
        return {"accidental": None if fraction is None else round(fraction, 5), "agent_plays": plays}
