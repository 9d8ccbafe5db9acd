"""Science Birds' actions (`AngryBirds.actions`): the birds' shots. The paper's candidate shots,
each later bird's aimed where the shots before left the level, the noise of a replay (objects
jittered, the release angle), the release angle turned in steps, and a task file's record of
the shots with what Phy-Q's agents send for them (shots.py, agent_action.py)."""

from __future__ import annotations

import random

from physc.domains.actions import Actions
from physc.domains.angrybirds.vocabulary import VOCABULARY

NUDGE_STEP = (
    0.05  # degrees of release angle a step along the `nudged` line (the raising of margins moves the action so)
)
TIME_STEP = 0.005  # seconds of a tap or a wait a step along theirs (Phy-Q's agents send a tap in whole ms)


class ScienceBirdsActions(Actions):
    """The birds' shots in the bound domain's world."""

    def starts(self, scenario) -> tuple[int, ...]:
        """The interactions at which a later bird's shot starts (shots.py)."""
        from physc.domains.angrybirds.shots import shot_starts

        return shot_starts(scenario, VOCABULARY.player)

    def resumes(self, action) -> bool:
        """The game's run goes on from a snapshot for one untapped shot (`play` passes it on)."""
        from physc.domains.angrybirds.shots import simple

        return simple(action)

    def candidates(self, level, scenario, start: int = 0, before=None, after=None) -> list:
        """The paper's candidate shots: at the points of interest of what the bird's shot starts
        by hitting (the first bird's, or with `before`, the next bird's at interaction `start`,
        where the play of `before`, `after`, left it; tapped at a few points of its flight where
        the scenario taps it: shots.py)."""
        from physc.domains.angrybirds.shots import candidates, where_left

        left = level if after is None else where_left(level, after)
        return candidates(self.domain, left, scenario, start, before, after)

    def noisy(self, level, action, rng: random.Random):
        """The noise of every noisy replay (the search's, `physc verify`'s, the evaluation's):
        blocks and pigs jittered, then the release angle (noise.py)."""
        from physc.domains.angrybirds import shot_moves
        from physc.domains.angrybirds.noise import ANGLE_SIGMA, jitter

        noisy = jitter(level, rng)
        return noisy, shot_moves.noisy(action, self.domain.world, rng, ANGLE_SIGMA)

    def nudged(self, action, step: int, line: int | None = None):
        """One of `lines` moved `step` steps: a shot turned by NUDGE_STEP degrees a step, a tap
        or a wait moved by TIME_STEP seconds (None: the last shot turned)."""
        from physc.domains.angrybirds import shot_moves

        return shot_moves.nudged(action, self.domain.world, step, NUDGE_STEP, line, TIME_STEP)

    def lines(self, action) -> tuple[str, ...]:
        """Each shot's release angle, and its tap and its wait where it has them (shot_moves.py)."""
        from physc.domains.angrybirds import shot_moves

        return tuple(text for text, _, _ in shot_moves.lines(action))

    def solution(self, label: str, action):
        """Version 1's Solution for one untapped red shot, else a ShotsSolution (shots.py)."""
        from physc.domains.angrybirds import shots

        return shots.solution(label, action, self.domain.world)

    def contrasted(self, level, action, counterpart: str, contrast: str):
        """The shot at the counterpart aimed at the same point of the contrast (shots.py)."""
        from physc.domains.angrybirds import shots

        return shots.contrasted(self.domain, level, action, counterpart, contrast)

    def sweep(self, level, scenario, before=None, after=None, at: str | None = None) -> list:
        """The next bird's candidate shots at `at`, then every release angle Phy-Q's agents can
        send, half a degree apart (sweeps.py)."""
        from physc.domains.angrybirds import sweeps

        return sweeps.sweep(self.domain, level, scenario, before, after, at)

    def timing(self, action, actor: str) -> float | None:
        from physc.domains.angrybirds import sweeps

        return sweeps.timing(action, actor)

    def retimed(self, action, actor: str, wait: float | None):
        from physc.domains.angrybirds import sweeps

        return sweeps.retimed(action, actor, wait, self.domain.world.rules.earliest_wait)

    def played_as(self, level, solution):
        """The solution with the shots Phy-Q's agents send for it: for each, the whole-pixel drag
        from the slingshot whose launch is nearest its release angle (agent_action.py), that
        launch's angle, and its tap in milliseconds."""
        from physc.domains.angrybirds import shots

        return shots.played_as(level, solution)

    def agent_variants(self, level, solution) -> list[tuple[str, object]]:
        """The actions Phy-Q's agents may send beside each recorded one: the planner's release,
        the 8 pixels around the drag, a tap 20 ms early or late (shots.py)."""
        from physc.domains.angrybirds import shots

        return shots.agent_variants(level, solution)

    def sent_action(self, solution):
        from physc.domains.angrybirds import shots

        return shots.sent_action(solution)

    def action_of(self, solution):
        from physc.domains.angrybirds import shots

        return shots.action_of(solution)

    def sent_text(self, solution) -> str | None:
        """Each shot as Phy-Q's agents send it, which `physc verify` replays too."""
        from physc.domains.angrybirds.shots import each_shot

        sent = [(s.agent_action, s.agent_angle) for s in each_shot(solution)]
        if any(action is None for action, _ in sent):
            return None
        steps = ", ".join(f"env.step({list(action)}), launched at {angle:g}°" for action, angle in sent)
        return f"as Phy-Q's agents send it (replayed too): {steps}"

    def sent_record(self, solution):
        """Each shot's `[dx, dy, tap in ms]`, as Phy-Q's agents send it (one shot: the list itself)."""
        from physc.domains.angrybirds.shots import each_shot

        sent = [s.agent_action for s in each_shot(solution)]
        if any(action is None for action in sent):
            return None
        return list(sent[0]) if len(sent) == 1 else [list(a) for a in sent]
