"""The scene IR: a world ready to run, backend-neutral, and the generic way to play it.

A domain that judges one action by simulation says what its level is as physics: the
bodies (physc.backends.BodySpec), the kind of each (what its recogniser calls surfaces,
background, thrown), the rolling radius of the round ones, the velocities the action
gives, and which bodies the goal is about. `play_scene` builds that in the backend it is handed
(the domain's: physc.domains.base.Domain.at), runs the generic loop (physc.simulation.run) with the
domain's rules, and judges the trace: interactions recognised, restrictions checked.
Every play of a simulated domain goes through here (physc.domains.simulated: the domain's
`simulation` gives the scene and its rules; Angry Birds' game makes both).
"""

from __future__ import annotations

import attrs

from physc.backends import Backend, BodySpec, EngineWorld
from physc.backends.settings import EngineSettings
from physc.simulation.recognise import Recogniser
from physc.simulation.restrictions import violations
from physc.simulation.run import RunRules, run, run_to_outcome
from physc.simulation.trace import Playout, Trace


@attrs.frozen
class Scene:
    bodies: tuple[BodySpec, ...]
    kinds: dict = attrs.field(eq=False)  # name → kind (the recogniser's surfaces, background, thrown)
    gravity: float  # downwards, in the domain's units
    engine: EngineSettings  # the target world's engine settings (its step, iterations, thresholds)
    radii: dict = attrs.field(factory=dict, eq=False)  # name → rolling radius of a round body
    velocities: dict = attrs.field(factory=dict, eq=False)  # name → (vx, vy, ω) at the start
    goal: tuple[str, ...] = ()  # the bodies the goal is about (Trace.goal)
    # The dynamic bodies' rows in the trace, where they are not the scene's moving bodies in order:
    # a scene whose rules bring bodies in later (RunRules.arrivals) lists them here too.
    rows: tuple[str, ...] = ()
    turns: int = 1  # the player's turns in the run, one after another (Science Birds: shots): `seconds` each

    @property
    def dt(self) -> float:
        """The seconds of one step."""
        return self.engine.dt

    @property
    def dynamic(self) -> tuple[str, ...]:
        """The bodies that move, in the trace's order (its state columns): `rows`, or the
        scene's moving bodies in order."""
        return self.rows or tuple(b.name for b in self.bodies if not b.static)


def built(scene: Scene, backend: Backend) -> EngineWorld:
    """`scene` as an engine world of `backend`, the action's velocities given."""
    engine = backend.create_world(scene.gravity, scene.engine)
    for body in scene.bodies:
        engine.add(body)
    for name, velocity in scene.velocities.items():
        engine.set_velocity(name, *velocity)
    return engine


def playout(scene: Scene, backend: Backend, rules: RunRules, seconds: float, to_end: bool = True) -> Playout:
    """`scene` played to its outcome under `rules` (physc.simulation.run.run_to_outcome): what
    `play_scene` would say of the goal, the damage and the destructions, and where the bodies end
    (without `to_end`: where they are once the outcome is settled). `seconds`: each turn's."""
    dynamic = scene.dynamic
    recorded = run_to_outcome(built(scene, backend), dynamic, rules, seconds * scene.turns, scene.dt, to_end)
    return Playout(
        scene.dt,
        dynamic,
        recorded.states[-1],
        recorded.steps,
        recorded.damage,
        recorded.destructions,
        scene.goal,
        rules.solved(recorded),
        rules.goal_met(recorded),
    )


def play_scene(
    scene: Scene,
    backend: Backend,
    rules: RunRules,
    seconds: float,
    recogniser: Recogniser,
    restrictions=(),
    redirects=None,
    recognise: bool = True,
    resume=None,
) -> Trace:
    """`scene` run for `seconds` at most (each turn's) under `rules`, in `backend` (from the
    snapshot `resume`, if given), the trace completed by the rules; with `recognise`, the
    interactions recognised, as the rules read them, and the restrictions (`redirects`: the
    declared bounces, see physc.simulation.restrictions) checked."""
    dynamic = scene.dynamic
    recorded = run(built(scene, backend), dynamic, rules, seconds * scene.turns, scene.dt, resume)
    trace = rules.completed(
        Trace(
            scene.dt,
            dynamic,
            dict(scene.kinds),
            recorded.states,
            recorded.contacts,
            recorded.separations,
            recorded.damage,
            recorded.destructions,
            scene.goal,
            rules.solved(recorded),
            goal_met=rules.goal_met(recorded),
            outlines={body.name: body.outline for body in scene.bodies},
            radii=dict(scene.radii),
        )
    )
    if not recognise:
        return trace
    interactions = rules.read(recogniser.recognise(trace, scene.radii))
    return attrs.evolve(trace, interactions=interactions, violations=violations(interactions, restrictions, redirects))
