"""Several shots and taps (language version 2): the candidate shots of each bird, and their record.

A scenario's birds are shot in the order its sequence first names them; the interaction
that first names a later bird starts its shot, which the search chooses once the chain has
got there (physc.search.chain: a stage that starts a shot extends each parent's action by
the new bird's candidates). A bird's candidates are the paper's (actions.py) at the first
object it hits; a bird the scenario taps (`tap(bird)`) is tapped at a few points of its
flight towards that object (`TAP_SHARES` of the way, in whole milliseconds, as Phy-Q's agents
send a tap time). A later shot is taken once the level rests, as Phy-Q's agents wait; where
the sequence has an object the shots before set going act after this shot starts (Phy-Q's
adequate timing), the shot is timed instead, tried at waits after the game brought the bird
onto the slingshot that span the time the play before still moves (`waits`).

A task whose solution is one untapped shot of the red bird keeps version 1's record
(`Solution`); any other is a `ShotsSolution`, one `BirdShot` per bird.
"""

from __future__ import annotations

import math

import attrs

from physc.domains.angrybirds.launch import Shot, Shots, shots_of

TAP_SHARES = (0.45, 0.6, 0.75, 0.9)  # of the way to the target, where a candidate taps
WAITS = 4  # the waits a timed shot is tried at, spread over the time the play before still moves
WAIT_SPAN = (
    3.0  # seconds they spread over after the earliest where no play says (as the waits before the game's earliest did)
)


@attrs.frozen
class Solution:
    """The intended solution of one untapped shot of the red bird (version 1's record): a
    full-stretch shot."""

    aimed_at: str  # the point of interest, e.g. "rBlock.left, low"
    target: tuple[float, float]
    trajectory: str  # "low" | "high"
    release_angle: float  # degrees
    # The shot as Phy-Q's agent framework sends it, `env.step([dx, dy, tap_time])` (whole
    # pixels from the slingshot's reference point), and the release angle the game launches
    # that at (physc.domains.angrybirds.agent_action); None in task files from before them.
    agent_action: tuple[int, int, int] | None = None
    agent_angle: float | None = None

    def __attrs_post_init__(self):
        """A task file's shot holds finite numbers and a trajectory (ValueError if not)."""
        numbers = (
            (*self.target, self.release_angle) if isinstance(self.target, tuple) and len(self.target) == 2 else None
        )
        if numbers is None or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in numbers
        ):
            raise ValueError("the solution's target and release angle must be finite numbers")
        if self.trajectory not in ("low", "high"):
            raise ValueError(f"the solution's trajectory is 'low' or 'high', not {self.trajectory!r}")


@attrs.frozen
class BirdShot:
    """One bird's shot in a task's solution: what it was aimed at, its release angle, its tap
    (seconds after the launch; None: none), and the action Phy-Q's agents send for it,
    `[dx, dy, tap in ms]` (agent_action.py), with the angle the game launches that at."""

    bird: str
    aimed_at: str
    target: tuple[float, float]
    trajectory: str
    release_angle: float
    tap: float | None = None
    wait: float | None = None
    agent_action: tuple[int, int, int] | None = None
    agent_angle: float | None = None

    def __attrs_post_init__(self):
        """A task file's shot holds finite numbers where a shot has them (ValueError if not)."""
        numbers = (
            [*self.target, self.release_angle] if isinstance(self.target, tuple) and len(self.target) == 2 else None
        )
        numbers = numbers and numbers + [v for v in (self.tap, self.wait) if v is not None]
        if not numbers or not all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in numbers
        ):
            raise ValueError("a shot's target, release angle, tap and wait must be finite numbers")
        if self.trajectory not in ("low", "high"):
            raise ValueError(f"a shot's trajectory is 'low' or 'high', not {self.trajectory!r}")


@attrs.frozen
class ShotsSolution:
    """A solution of several shots, or of a tapped or non-red bird's (language version 2)."""

    aimed_at: str
    shots: tuple[BirdShot, ...]


def birds(scenario, player: str) -> list[str]:
    """The scenario's birds in the order shot: as its sequence first names them (a bird it
    never names comes last, in the order declared)."""
    declared = [o.name for o in scenario.objects if o.term == player]
    first = {}
    for k, term in enumerate(scenario.interactions):
        for name in term.objects:
            if name in declared:
                first.setdefault(name, k)
    return sorted(declared, key=lambda name: (first.get(name, len(scenario.interactions)), declared.index(name)))


def shot_starts(scenario, player: str) -> tuple[int, ...]:
    """The interactions at which a later bird's shot starts (where the sequence first names it)."""
    named = birds(scenario, player)[1:]
    out = []
    for k, term in enumerate(scenario.interactions):
        if any(
            name in named and not any(name in t.objects for t in scenario.interactions[:k]) for name in term.objects
        ):
            out.append(k)
    return tuple(sorted(set(out)))


def first_hit(scenario, name: str, start: int):
    """What `name`'s shot is aimed at: the object of the hit its shot starts with (after its
    taps), if it starts with one."""
    term = next((t for t in scenario.interactions[start:] if t.name != "tap"), None)
    return term.objects[1] if term is not None and term.name == "hit" and term.objects[0] == name else None


def timed(scenario, start: int, player_names) -> bool:
    """Whether a shot starting at interaction `start` must be taken while something the shots
    before set going still moves: an object that acted before `start` acts again after it."""
    before = {t.objects[0] for t in scenario.interactions[:start] if t.objects} - set(player_names)
    return any(t.objects and t.objects[0] in before for t in scenario.interactions[start:])


def declared_timed(scenario, name: str) -> bool:
    """Whether a restriction `timed(name)` says the bird's shot is timed (language version 2)."""
    return any(t.name == "timed" and t.objects[0] == name for t in scenario.restrictions)


def tapped(scenario, name: str) -> bool:
    return any(t.name == "tap" and t.objects[0] == name for t in scenario.interactions)


def candidates(domain, level, scenario, start: int = 0, before=None, after=None) -> list[tuple[str, object]]:
    """The labelled actions that shoot the bird whose shot starts at interaction `start` (after
    `before`, the shots so far: then labelled by the bird, the search joins the labels; `after`:
    their play, which a timed shot's waits are drawn from)."""
    order = birds(scenario, domain.vocabulary.player)
    k = len(shots_of(before))
    if k >= len(order):
        return []
    name = order[k]
    target = first_hit(scenario, name, start)
    if target is None:
        return []
    out = []
    for label, shot in domain.search.actions_at(level, target):
        shot = attrs.evolve(shot, bird=name)
        variants = tap_variants(label, shot, domain.world) if tapped(scenario, name) else [(label, shot)]
        if before is not None and (timed(scenario, start, order) or declared_timed(scenario, name)):
            variants = [
                (f"{text}, after {wait:g} s", attrs.evolve(v, wait=wait))
                for text, v in variants
                for wait in waits(domain.world, v, shots_of(before)[-1].bird, after)
            ]
        for text, variant in variants:
            if before is None:
                out.append((text, variant))
            else:
                out.append((f"{name}: {text}", Shots((*shots_of(before), variant))))
    return out


def waits(world, shot: Shot, before: str, after) -> tuple[float, ...]:
    """The waits a timed `shot` is tried at: WAITS of them, spread over the time the play of
    the shots before (`after`) still moves once `before`, the bird before, first struck
    something (its turn began then), from the earliest the game releases a shot
    (`Rules.earliest_wait`) to the latest whose bird reaches its target's x before that play
    comes to rest; only the earliest where the play rests sooner. Without the play (or a strike
    in it), over WAIT_SPAN from the earliest."""
    earliest = world.rules.earliest_wait
    turn = None if after is None else next((c.time for c in after.contacts if before in (c.a, c.b)), None)
    span = WAIT_SPAN
    if after is not None and turn is not None:
        (x, _), (vx, _) = shot.start(world)
        flight = (shot.target[0] - x) / vx if shot.target is not None and vx > 0 else 0.0
        span = after.duration - turn - flight - earliest
    if span <= 0:
        return (round(earliest, 2),)
    return tuple(round(earliest + span * k / (WAITS - 1), 2) for k in range(WAITS))


def where_left(level, trace):
    """`level` as a play left it (its trace's last step): each object where it ended, turned as
    it ended; an object gone by then left out. A later bird is aimed at its target there, as an
    agent sees the level before its next shot."""
    from physc.domains.playing import states_at

    states = states_at(trace, trace.steps - 1)
    objects = []
    for obj in level.objects:
        state = states.get(obj.name, ())
        if state is None:
            continue
        objects.append(
            obj
            if not state
            else attrs.evolve(
                obj, x=round(state[0], 5), y=round(state[1], 5), rotation=round(math.degrees(state[2]), 3)
            )
        )
    return attrs.evolve(level, objects=tuple(objects))


def tap_variants(label: str, shot: Shot, world) -> list[tuple[str, Shot]]:
    """`shot` tapped at each of TAP_SHARES of the way to its target, labelled so."""
    return [(f"{label}, tap {share:.0%}", attrs.evolve(shot, tap=tap_time(shot, world, share))) for share in TAP_SHARES]


def tap_time(shot: Shot, world, share: float) -> float:
    """When the bird of `shot` is `share` of the way (in x) to its target, in whole milliseconds."""
    (x, _), (vx, _) = shot.start(world)
    assert shot.target is not None, "a candidate shot is aimed at a point"
    return round(max(share * (shot.target[0] - x) / vx, 0.001), 3) if vx > 0 else 0.001


def as_action(shots) -> Shot | Shots:
    """Shots as one action: a single shot as itself (as the search's candidates give it), more
    as `Shots`."""
    shots = tuple(shots)
    return shots[0] if len(shots) == 1 else Shots(shots)


def simple(action) -> bool:
    """Whether an action is version 1's: one untapped shot of the bird named `bird`."""
    return isinstance(action, Shot) and action.tap is None and action.bird == "bird"


def solution(label: str, action, world):
    """The task's record of `action` (module docstring)."""
    if simple(action):
        if action.target is None:  # as Solution's own check says of a shot without a target
            raise ValueError("the solution's target and release angle must be finite numbers")
        return Solution(label, action.target, action.trajectory, round(action.release_angle(world), 5))
    labels = label.split("; ")
    parts = []
    for k, shot in enumerate(shots_of(action)):
        aimed = labels[k].split(": ", 1)[-1] if k < len(labels) else label
        if shot.target is None:  # as BirdShot's own check says of a shot without a target
            raise ValueError("a shot's target, release angle, tap and wait must be finite numbers")
        parts.append(
            BirdShot(
                shot.bird, aimed, shot.target, shot.trajectory, round(shot.release_angle(world), 5), shot.tap, shot.wait
            )
        )
    return ShotsSolution(label, tuple(parts))


def each_shot(solution) -> tuple:
    """The shot records of a task's solution: its BirdShots, or version 1's Solution alone."""
    return solution.shots if isinstance(solution, ShotsSolution) else (solution,)


def action_of(solution, noise=None):
    """The action a recorded solution takes: at its targets, or (`noise`: (rng, σ)) at its
    release angles jittered."""
    if isinstance(solution, ShotsSolution):
        shots = []
        for s in solution.shots:
            if noise is None:
                shots.append(Shot(target=s.target, trajectory=s.trajectory, tap=s.tap, bird=s.bird, wait=s.wait))
            else:
                shots.append(
                    Shot(angle=s.release_angle + noise[0].gauss(0.0, noise[1]), tap=s.tap, bird=s.bird, wait=s.wait)
                )
        return as_action(shots)
    if noise is None:
        return Shot(target=tuple(solution.target), trajectory=solution.trajectory)
    return Shot(angle=solution.release_angle + noise[0].gauss(0.0, noise[1]))


def played_as(level, solution):
    """Each shot with the action Phy-Q's agents send for it (agent_action.py; the tap in ms)."""
    from physc.domains.angrybirds.agent_action import agent_action

    def sent(angle: float, tap: float | None):
        action, launched = agent_action(angle, level.slingshot, level.camera.y, level.camera.max_width)
        return (action[0], action[1], 0 if tap is None else int(round(tap * 1000))), round(launched, 5)

    if isinstance(solution, ShotsSolution):
        shots = []
        for s in solution.shots:
            action, angle = sent(s.release_angle, s.tap)
            shots.append(attrs.evolve(s, agent_action=action, agent_angle=angle))
        return attrs.evolve(solution, shots=tuple(shots))
    action, angle = sent(solution.release_angle, None)
    return attrs.evolve(solution, agent_action=action, agent_angle=angle)


def sent_action(solution):
    """The action as Phy-Q's agents send it, at the angles the game launches theirs."""
    if isinstance(solution, ShotsSolution):
        if any(s.agent_angle is None for s in solution.shots):
            return None
        return as_action(Shot(angle=s.agent_angle, tap=s.tap, bird=s.bird, wait=s.wait) for s in solution.shots)
    return None if solution.agent_angle is None else Shot(angle=solution.agent_angle)


TAP_OFF = 20  # ms: a tap a step early or late (HUD.cs times it in whole frames; a fixed step is 0.02 s)
TAP_LEAST = 1  # ms: the earliest tap (the game taps only at a tap time above 0)


def agent_variants(level, solution) -> list[tuple[str, object]]:
    """(label, action) for each action Phy-Q's agents may send for `solution` beside the one
    `played_as` recorded: for each shot in turn, the others as sent, the trajectory planner's
    release for its angle, each of the 8 pixels around its drag, and, for a tapped shot, its tap
    TAP_OFF ms early and late (agent_action.py). None for a record without agent actions."""
    from physc.domains.angrybirds import agent_action as aa

    records, base = each_shot(solution), sent_action(solution)
    if base is None or any(s.agent_action is None for s in records):
        return []
    sent = shots_of(base)
    view = (level.slingshot, level.camera.y, level.camera.max_width)
    out = []
    for k, (record, shot) in enumerate(zip(records, sent, strict=True)):
        action = list(record.agent_action)
        named = f"shot {k + 1} ({shot.bird}): " if len(sent) > 1 else ""
        pixels = [("the planner's release", aa.planner_release(record.release_angle, *view)[:2] + action[2:])]
        pixels += [(f"pixel ({p[0] - action[0]:+d}, {p[1] - action[1]:+d})", p) for p in aa.neighbours(action)]
        for label, pixel in pixels:
            angle, stretch = aa.launch_angle(pixel, *view)
            if stretch < 1.0:
                raise ValueError(f"env.step({pixel}) is not a full-stretch shot")
            played = attrs.evolve(shot, angle=round(angle, 5))
            out.append((f"{named}{label}: env.step({pixel}), launched at {angle:.3f}°", _with(sent, k, played)))
        if shot.tap is not None:
            for sign, word in ((-1, "early"), (1, "late")):
                tap = max(action[2] + sign * TAP_OFF, TAP_LEAST)
                pixel = [*action[:2], tap]
                played = attrs.evolve(shot, tap=tap / 1000)
                out.append((f"{named}the tap {TAP_OFF} ms {word}: env.step({pixel})", _with(sent, k, played)))
    return out


def _with(shots, k: int, shot) -> Shot | Shots:
    """`shots` as one action, its k-th shot replaced by `shot`."""
    return as_action((*shots[:k], shot, *shots[k + 1 :]))


def level_birds(layout, scenario, player: str, prefab_of) -> tuple[str, ...]:
    """The level's <Bird> list: each bird's prefab, in the order shot."""
    names = {o.name: o for o in layout.objects}
    order = birds(scenario, player) if scenario is not None else [o.name for o in layout.objects if o.role == "player"]
    return tuple(prefab_of(names[n].concrete) for n in order if n in names) or ("BirdRed",)


CONTRAST_REACH = 1.5  # units: a shot whose aim lies this near the counterpart's centre is the one aimed at it


def contrasted(domain, level, action, counterpart: str, contrast: str):
    """The shot aimed at `counterpart` (its aim nearest the counterpart's centre, within
    CONTRAST_REACH: a raised shot is named by a point of its flight near, not on, the body)
    aimed at the same point of `contrast` instead (its offset from the centre scaled by the two
    bodies' sizes), on the same trajectory if it reaches there, else on the other; the other
    shots unchanged. None when no shot is aimed near the counterpart, or the point is out of reach."""
    from physc.domains.angrybirds.catalogue import extent

    objects = {o.name: o for o in level.objects}
    if counterpart not in objects or contrast not in objects:
        return None
    a, b = objects[counterpart], objects[contrast]
    (aw, ah), (bw, bh) = extent(a), extent(b)
    shots = list(shots_of(action))
    near = [(math.hypot(s.target[0] - a.x, s.target[1] - a.y), k) for k, s in enumerate(shots) if s.target is not None]
    near = [(d, k) for d, k in near if d <= CONTRAST_REACH]
    if not near:
        return None
    k = min(near)[1]
    shot = shots[k]
    assert shot.target is not None  # `near` holds only shots aimed at a point
    point = (round(b.x + (shot.target[0] - a.x) * bw / aw, 5), round(b.y + (shot.target[1] - a.y) * bh / ah, 5))
    other = "high" if shot.trajectory == "low" else "low"
    for trajectory in (shot.trajectory, other):
        if domain.world.launch.aim(*point, trajectory, domain.world.gravity) is not None:
            shots[k] = attrs.evolve(shot, target=point, trajectory=trajectory, angle=None)
            return as_action(shots)
    return None
