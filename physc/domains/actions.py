"""A simulated domain's actions: the player's candidate actions, their noise, the line the search
moves one along, and their record in a task file; a part of the domain (physc.domains.part),
`domain.actions`, which the search, the replays and the agents ask. A domain writes a subclass
of `Actions` with what differs and names it `actions = part(MyActions)`."""

from __future__ import annotations

import random
from collections.abc import Sequence

from physc.domains.errors import MissingCapability
from physc.domains.part import Part


class Actions(Part):
    """The player's actions in one domain (module docstring); `self.domain` is the domain bound
    to its world and engine."""

    def candidates(self, level, scenario, start: int = 0, before=None, after=None) -> Sequence[tuple[str, object]]:
        """(label, action) for every candidate action, in the order they are tried (the paper's
        points of interest of the first target). A domain whose player acts several times
        (`starts`) gives, with `start`, `before` and `after`, the candidates of the action that
        starts at interaction `start`, each extending `before`, aimed at the level as the play
        of `before` left it (`after`, its trace). A capability (`actions`), declared."""
        raise MissingCapability(self.domain.name, ("actions",), "generating a task")

    def starts(self, scenario) -> tuple[int, ...]:
        """The interactions at which a later action of the player starts (Angry Birds: a later
        bird's shot); the search chooses it there, extending each action that got that far. The
        default: one action, ()."""
        return ()

    resumable: bool = True
    """Whether the domain's `play` goes on from a snapshot (its `resume`): the generic play does;
    a domain whose own play does not pass `resume` on to the run loop sets False (then the
    search replays every prefix from the start)."""

    def resumes(self, action) -> bool:
        """Whether a play of `action` may go on from a snapshot (`resumable`, for this action)."""
        return self.resumable

    def noisy(self, level, action, rng: random.Random):
        """(level, action) as one noisy replay draws them from `rng`: the domain's noise model,
        the one of the search's robustness replays, `physc verify`'s and the evaluation's. The
        default has none: noisy replays are exact replays."""
        return level, action

    def nudged(self, action, step: int, line: int | None = None) -> object | None:
        """`action` moved `step` whole steps along a line (one of the coordinates the search moves
        to raise a weak chain's margins, physc.search.coordinates); `line`: which of its `lines`
        (None: the one the search moves when it moves one, the last action's). None: no such
        line, or no such action there (the default: no line). A domain with one line may leave
        `line` out of its override: the search passes it only where `lines` names several."""
        return None

    def lines(self, action) -> tuple[str, ...]:
        """The lines `nudged` moves `action` along, named (the search raises a chain of several
        actions along each of them, so that a later action's weak link may be raised by moving an
        earlier one: Science Birds, each shot's release angle, tap and wait). The default: one,
        "the action", where `nudged` has a line."""
        return ("the action",) if self.nudged(action, 1) is not None else ()

    def contrasted(self, level, action, counterpart: str, contrast: str) -> object | None:
        """`action` aimed at `contrast` as it is aimed at `counterpart` (language version 2's
        `contrast(a, b)`, physc.search.contrasts); None: the domain cannot say (the default),
        or the action is not aimed at the counterpart."""
        return None

    def sweep(self, level, scenario, before=None, after=None, at: str | None = None) -> Sequence[tuple[str, object]]:
        """(label, action) for every action the player could send next, as a property's check
        plays them (language version 2's `nonGreedy`, `blocks`: physc.search.properties): the
        next action after `before` (None: the first), the level as the play of `before` left
        it (`after`, its trace), swept over the action's range at the domain's resolution, with
        the candidates aimed at `at` first. The default: none (the domain cannot check them)."""
        return ()

    def timing(self, action, actor: str) -> float | None:
        """When `actor`'s part of `action` is taken, in seconds after the part before it (version
        2's `timed(a)`); None: it is not timed (the default)."""
        return None

    def retimed(self, action, actor: str, wait: float | None) -> object | None:
        """`action` with `actor`'s part taken `wait` seconds after the part before it (None: once
        the level rests), or at the time the world takes it instead where it cannot take it
        then (`timing` of the result says which); None: the domain cannot retime it (the default)."""
        return None

    def valid(self, level, action) -> bool:
        """Whether `action` may be taken in `level` (PHYRE: the ball occludes nothing)."""
        return True

    def random_action(self, level, rng: random.Random) -> object | None:
        """An action for `level` drawn as the evaluation's random agent draws one (None: the
        domain has no random agent; it declares `random_action` when it has one)."""
        return None

    def neighbours(self, action) -> list:
        """The actions a solution's stability is judged by (PHYRE: the ball moved half a pixel in
        the 8 directions); the default: none, so every solution counts as stable."""
        return []

    def solution(self, label: str, action):
        """The task's record of the action found (an attrs value; the default: the action)."""
        return action

    def action_of(self, solution):
        """The action a task's recorded solution takes (the inverse of `solution`)."""
        return solution

    def played_as(self, level, solution):
        """`solution` with what the target world's players send to make it, if that is not the
        action itself (angrybirds: the drag Phy-Q's agent framework sends); the default: as it is."""
        return solution

    def agent_variants(self, level, solution) -> list[tuple[str, object]]:
        """(label, action) for each action the target world's agents may send for `solution`
        beside the one `played_as` recorded: each must solve the task too, in every reading (the
        search's precision step, physc.search.precision, and `physc verify`). Angrybirds: for
        each shot, the 8 pixels around its drag, Phy-Q's trajectory planner's release, a tap
        20 ms early or late. The default: none. (Not `neighbours`, which a benchmark's
        acceptance rule asks of any action it judges, PHYRE's stability.)"""
        return []

    def sent_text(self, solution) -> str | None:
        """What the target world's players send for `solution`, in words, for `physc verify` to
        print beside its verdict (angrybirds: Phy-Q's `env.step([dx, dy, tap])` and the angle the
        game launches it at); None: they send the solution's own action (the default)."""
        return None

    def sent_record(self, solution) -> object | None:
        """The same as plain data for `physc verify --format json` (`sent`); None: as recorded."""
        return None

    def sent_action(self, solution) -> object | None:
        """The action `played_as` recorded, as the world plays it (`physc verify` replays it beside
        the solution); None: the solution's own action is what players send (default)."""
        return None
