"""One simulated play of a level, and where an object's outline lies.

Every part of the satisfier makes and reads `Attempt`s: its search in satisfy.py, the
repairs (placing.py, repairs.py, impetus.py), the obstruction and the shortcut guard
(obstruct.py) and the robustness checks (robustness.py); so the record, the time a play
may last (SECONDS) and the outline arithmetic they all share live here, apart from all of
them, which lets each of those import it without importing the others.
"""

from __future__ import annotations

import attrs

from physc.compiler.qsr_evaluate import five_points
from physc.domains.angrybirds.catalogue import extent
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import LevelObject
from physc.simulation.fidelity import Fidelity
from physc.simulation.trace import Trace

SECONDS = 9.0  # simulated time per attempt at most


@attrs.frozen
class Attempt:
    label: str
    shot: Shot
    trace: Trace
    fidelity: Fidelity


def _span(obj: LevelObject) -> tuple[float, float]:
    """The leftmost and rightmost x of an object's outline box."""
    xs = [p.real for k, p in five_points(obj.x, obj.y, *extent(obj), obj.rotation or 0.0).items() if k != "c"]
    return min(xs), max(xs)


def _along(obj: LevelObject, sign: float) -> tuple[float, float]:
    """The near and the far end of an object's outline box along a heading (`sign` +1
    to the right, -1 to the left), as coordinates that grow along it."""
    near, far = sorted(sign * x for x in _span(obj))
    return near, far
