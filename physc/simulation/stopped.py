"""Why a simulated chain stopped where it did, in words a scenario's author can act on.

When no layout gives a task, the message names the first interaction the best simulation
never realised. This says what the simulation shows about it: how fast the actor still
moved, how near it came to its target, how much damage it dealt. For example: "rBlock3
moved at most 0.21 units/s after `hit(rBlock2, rBlock3, left)`, too slow to roll on
surface3"; for a strike that did not destroy its target, also whose mass set the damage and
the speed that would have (the domain's damage records say). It reads only the scenario and
the trace, so any domain's traces will do.
"""

from __future__ import annotations

import numpy as np

from physc.simulation.fidelity import Declared, Fidelity
from physc.simulation.trace import Trace
from physc.simulation.where import Where

STRIKE = 0.2  # s before a hit that count for how fast it struck


def why_stopped(scenario: Declared, trace: Trace, fidelity: Fidelity) -> str:
    """What the trace shows about the first declared interaction it does not realise ("" when
    it realises them all, or shows nothing useful)."""
    k = fidelity.matched
    if k >= len(scenario.interactions):
        return ""
    declared = scenario.interactions[k]
    since = fidelity.times[-1] if fidelity.times else 0.0
    after = f" after `{scenario.interactions[k - 1].text}`" if k else ""
    actor = declared.objects[0]
    if actor not in trace.names:
        return f"{actor} was gone{after}"
    if np.isnan(trace.states[:, trace.index(actor), 0]).all():
        return _never_came(trace, actor, after)
    rows = trace.states[int(since / trace.dt) :, trace.index(actor), :]
    rows = rows[~np.isnan(rows[:, 0])]
    if not len(rows):
        return f"{actor} was gone{after}"
    speed = float(np.hypot(rows[:, 3], rows[:, 4]).max())
    if declared.name == "destroy":  # how fast it struck: from just before the hit
        target = declared.objects[1]
        struck = trace.states[max(int((since - STRIKE) / trace.dt), 0) :, trace.index(actor), 3:5]
        speed = float(np.nanmax(np.hypot(struck[:, 0], struck[:, 1]))) if len(struck) else speed
        by = Where(trace).bodies(actor)  # the actor and its parts (a blue bird's split)
        dealt = [d for d in trace.damage if d.target == target and d.by in by and d.time >= since and d.amount > 0]
        if dealt:
            left = min(d.life for d in dealt)
            return (
                f"{actor} struck {target} at up to {speed:.2f} units/s{after}, "
                f"dealing {sum(d.amount for d in dealt):.2f} damage: "
                f"not enough to destroy it ({left:.2f} of its life left{_needed(dealt[0])})"
            )
        return f"{actor} moved at up to {speed:.2f} units/s{after} but dealt {declared.objects[1]} no damage"
    if declared.name in ("roll", "slide"):
        surface = declared.objects[1] if len(declared.objects) > 1 else "its surface"
        if speed < 1.0:
            return f"{actor} moved at most {speed:.2f} units/s{after}, too slow to {declared.name} on {surface}"
        return f"{actor} moved at up to {speed:.2f} units/s{after} but did not {declared.name} on {surface} as declared"
    if declared.name == "fall":
        drop = float(rows[0, 1] - rows[:, 1].min())
        if drop < 0.2:
            return f"{actor} did not fall{after} (it moved at most {speed:.2f} units/s)"
        return f"{actor} fell {drop:.2f} units{after} but did not land on {declared.objects[1]}"
    if len(declared.objects) > 1 and declared.objects[1] in trace.names:
        target = declared.objects[1]
        other = trace.states[int(since / trace.dt) :, trace.index(target), :2][: len(rows)]
        gaps = np.hypot(*(rows[: len(other), :2] - other).T)
        gaps = gaps[~np.isnan(gaps)]
        if len(gaps):
            return (
                f"{actor} came no nearer than {float(gaps.min()):.2f} units (centre to centre) to {target}{after}, "
                f"moving at up to {speed:.2f} units/s"
            )
    return f"{actor} moved at up to {speed:.2f} units/s{after}"


def _never_came(trace: Trace, actor: str, after: str) -> str:
    """Why `actor`, a body that joins a run after its start (a later action's: Science Birds'
    next bird), never came into it: the goal was met first, or the run ended before."""
    gone = {d.name: d for d in trace.destructions}
    if trace.solved and trace.goal and all(g in gone for g in trace.goal):
        last = max((gone[g] for g in trace.goal), key=lambda d: d.time)
        by = f" by {last.by}" if last.by else ""
        return (
            f"{actor} never came into the run{after}: "
            f"the goal was met first ({last.name} destroyed at {last.time:.2f} s{by})"
        )
    return f"{actor} never came into the run{after}: it ended at {trace.duration:.2f} s before {actor} was due"


def _needed(record) -> str:
    """What the strike `record` lacked, where the domain's damage rule says: whose mass set the
    damage, and the contact speed that would have destroyed the target with it."""
    if record.needed is None:
        return ""
    whose = "its own" if record.attacker == record.target else f"{record.attacker}'s"
    return f"; with {whose} mass setting the damage, a strike of {record.needed:.2f} units/s would have destroyed it"
