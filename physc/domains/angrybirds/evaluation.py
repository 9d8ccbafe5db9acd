"""Science Birds' evaluation (`AngryBirds.evaluation`): the paper's heuristic agent measures how
often a task is solved by accident (agent.py). No acceptance rule: every task the search finds is
kept."""

from __future__ import annotations

from physc.domains.evaluation import Evaluation


class ScienceBirdsEvaluation(Evaluation):
    """Science Birds' evaluation, in the bound domain's world."""

    measures = (
        "stability = no object moves more than 0.05 in 10 s without action and nothing is destroyed; intended "
        "solvability = the recorded solution solves the task (exactly; and the share of 10 replays with release-angle "
        "noise σ 0.1° and block/pig position noise σ 0.005); sequence fidelity = the replay realises the declared "
        "sequence without breaking a restriction; accidental solvability = the paper's AS: the share of the heuristic "
        "agent's plays (every dynamic object but the solution's target, at its points of interest, both trajectories) "
        "that solve the task. A fallback (`--min-robustness`) is a task whose solution passed fewer than all of the "
        "generator's 6 noisy replays."
    )

    def agent_plays(self, level, scenario) -> list:
        """The paper's heuristic agent's plays (agent.py): at everything but the first target."""
        from physc.domains.angrybirds.agent import plays

        first = self.domain.reach_targets(scenario)
        return plays(self.domain, level, first[0] if first else None)

    def accidental(self, level, scenario, solution, rng) -> dict:
        """The paper's heuristic agent (agent.py): it shoots at everything but the first target."""
        from physc.domains.angrybirds.agent import accidental

        first = self.domain.reach_targets(scenario)
        fraction, plays = accidental(self.domain, level, first[0] if first else None)
        return {"accidental": None if fraction is None else round(fraction, 5), "agent_plays": plays}
