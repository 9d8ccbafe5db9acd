"""Where a stage's variant may go on from the parent's play instead of replaying the prefix
(physc.simulation.snapshot; docs/generation.md, "A stage's variants go on from a snapshot")."""

from __future__ import annotations

from physc.search import placing
from physc.search.chain_stages import prefix
from physc.simulation.snapshot import Snapshot


def snapshot(problem, scene, parent, stage, source) -> Snapshot | None:
    """Where the stage's `scene` may go on from `source`, the parent's play of the same action
    (physc.simulation.snapshot): cut `snapshot_lead` before a body of the prefix first comes
    near a new object. None (a run from the start) when snapshots are off, the scene differs
    from the parent's by more than the stage's new objects, or the cut would save less than
    `snapshot_least`."""
    settings = problem.settings
    if (
        not (settings.snapshots and problem.domain.actions.resumes(source.action))
        or parent.stage < 0
        or stage.start in problem.action_starts
    ):
        return None
    before = prefix(parent.layout, problem.entry, problem.plan[parent.stage].start).objects
    new = [o for o in scene.objects if o.name in stage.new]
    if not new or set(before) != {o for o in scene.objects if o.name not in stage.new}:
        return None
    trace = source.trace
    met = placing.approach(
        trace, new, {o.name: (o.width, o.height) for o in scene.objects}, problem.scale, settings.clear
    )
    step = Snapshot.latest_cut(
        trace, (trace.steps - 1 if met is None else met) - int(round(settings.snapshot_lead / trace.dt))
    )
    if step * trace.dt < settings.snapshot_least or step >= trace.steps:
        return None
    return Snapshot.of(trace, step)
