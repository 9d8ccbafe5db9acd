"""Playing a Science Birds level: its scene and the game's rules as the run loop's hooks.

The game turns a level into a backend-neutral scene (catalogue shapes, materials, the first
bird at the slingshot, flying), and after every physics step of physc's run loop
(physc.simulation.run) applies the rules of Science Birds to the contacts the engine reports:
damage from the attacker's mass and the relative velocity, destruction at life <= 0, removal of
objects leaving the level and of birds that have come to rest, the next bird and a bird's
power, success when every pig is destroyed. The loop records the trace and
physc.simulation.recognise reads it; the game adds what it kept (`completed`) and names what a
bird's parts did as the bird's (`read`).

`Game` is built in layers, one job each: the setup and the birds' launches (game_launch.py),
the scene (game_scene.py), damage and blasts (game_damage.py), removals (game_removals.py), and
here the run itself: its hooks on contacts, when it is finished, resuming, and the trace.
"""

from __future__ import annotations

import attrs

from physc.domains.angrybirds.flight import FIRST
from physc.domains.angrybirds.game_removals import GameRemovals, stop_moving
from physc.domains.angrybirds.game_scene import GROUND
from physc.domains.angrybirds.launch import Shot
from physc.simulation.scene import play_scene, playout
from physc.simulation.trace import ContactRecord, Playout, Trace

__all__ = ["BIRD", "GROUND", "Game"]

BIRD = FIRST  # the first bird's name


class Game(GameRemovals):
    """A Science Birds level played in one world (its bodies, launch, rules and recognition)
    with one physics engine: the game's rules as the hooks of the generic run loop
    (physc.simulation.run)."""

    def simulate(
        self,
        shot: Shot | None = None,
        seconds: float = 10.0,
        stop_at_rest: bool = True,
        invulnerable: float | None = None,
        settle_after_solved: float | None = None,
        resume=None,
        record: bool = True,
    ) -> Trace | Playout:
        """Run the level for `seconds` (each shot's), with a shot at t = 0 or none (`scene` says
        what the rest asks); `resume`: a snapshot to go on from (physc.simulation.snapshot).
        Without `record`, an outcome playout (physc.simulation.scene.playout)."""
        scene = self.scene(shot, stop_at_rest, invulnerable, settle_after_solved)
        if not record:
            if resume is not None:
                raise ValueError("an outcome playout starts from the beginning (no snapshot)")
            return playout(scene, self.backend, self, seconds)
        return play_scene(scene, self.backend, self, seconds, self.world.recogniser, recognise=False, resume=resume)

    def play(
        self, shot: Shot | None = None, seconds: float = 10.0, restrictions=(), redirects=None, resume=None, **options
    ) -> Trace:
        """`simulate`, with the interactions recognised and the restrictions checked (`redirects`:
        the declared bounces, see physc.simulation.restrictions)."""
        scene = self.scene(shot, **options)
        return play_scene(
            scene, self.backend, self, seconds, self.world.recogniser, restrictions, redirects, resume=resume
        )

    def solved(self, recording) -> bool:
        """Science Birds' goal: every pig destroyed (a level without pigs is never solved)."""
        destroyed = {d.name for d in recording.destructions}
        return bool(self._pigs) and set(self._pigs) <= destroyed

    def on_contact(self, engine, contact: ContactRecord, damage: list, time: float) -> None:
        # A dying body struck again: OnCollisionEnter2D → DealDamage → Die, so it stops again.
        for name in self._dying.intersection((contact.a, contact.b)):
            stop_moving(engine, name)
        self.flights.on_contact(contact.a, contact.b, time)
        if time > self._invulnerable:
            self._damage(engine, contact, damage, time)

    def resume(self, engine, snapshot) -> None:
        """The game's state as the events before `snapshot` leave it: every life less its
        damage, whether the bird has struck, when it is next checked, when the last pig went."""
        for record in snapshot.damage:
            self.life[record.target] = record.life
        self._depends = list(snapshot.depends)
        self.spent = {name for name, life in self.life.items() if life <= 0} - {d.name for d in snapshot.destructions}
        struck = next((c.time for c in snapshot.contacts if BIRD in (c.a, c.b)), None)
        flights = self.flights
        if struck is not None and BIRD in flights.flying:  # (a snapshot is of a one-shot play: actions.resumes)
            flights.strike(BIRD, struck)
            while flights.flying[BIRD] <= snapshot.time + 1e-9 and flights.flying[BIRD] < self.rules.bird_lifetime:
                flights.checked(BIRD)  # the checks it passed before the cut
        gone = {d.name: d.time for d in snapshot.destructions}
        if self._pigs and set(self._pigs) <= set(gone):
            self._solved_at = max(gone[p] for p in self._pigs)
        if self._stop_at_rest:
            self._resting_since = _resting_since(snapshot, self.world.rest_speed)

    def finished(self, values: list, alive: set, time: float) -> bool:
        """With `settle_after_solved`, that long after the last pig is destroyed, once nothing
        is falling; with `stop_at_rest`, 0.3 s after everything came to rest (the bird gone)."""
        if self._settle_after_solved is not None and self._pigs:
            if self._solved_at is None and not any(p in alive for p in self._pigs):
                self._solved_at = time
            if (
                self._solved_at is not None
                and time - self._solved_at >= self._settle_after_solved
                and not self._falling(values, self._dynamic)
            ):
                return True
        if self._stop_at_rest:
            still = self.world.rest_speed
            # A shot to come waits for the level to be static, birds and all (ABGameWorld.IsLevelStable:
            # a bird at rest, not yet removed, is still); the run ends once the last bird is gone too.
            waiting = self.flights.waiting()
            if (not waiting and not alive.isdisjoint(self.flights.flying)) or any(
                abs(vx) + abs(vy) + abs(w) > still for _, _, _, vx, vy, w in values
            ):
                self._resting_since = None
            elif self._resting_since is None:
                self._resting_since = time
            elif time - self._resting_since >= 0.3:
                if not waiting:
                    return True
                self.flights.resting()  # the next shot comes now
                self._resting_since = None
        return False

    def _falling(self, values: list, dynamic: tuple[str, ...]) -> bool:
        """Whether a block, pig or TNT (not the bird) is coming down fast."""
        fast = self.world.falling_speed
        return any(v[4] < -fast for v, name in zip(values, dynamic, strict=False) if self.kinds.get(name) != "bird")

    def completed(self, trace: Trace) -> Trace:
        """The trace with the damage another reading of the open points would have dealt, the
        birds that came in and the parts of each split bird."""
        return attrs.evolve(
            trace, depends=tuple(self._depends), outlines=dict(self.outlines), parts=dict(self.flights.parent)
        )

    def read(self, interactions: tuple) -> tuple:
        """What a blue bird's other birds and a white bird's egg did, their bird's; each tap that
        fired a power, `tap(bird)` (flight.py)."""
        flights = self.flights
        return flights.read(interactions) if flights.tapped or flights.parent else interactions


def _resting_since(snapshot, still: float) -> float | None:
    """When everything came to rest before `snapshot`'s cut, and stayed so (the bird gone):
    what `Game.finished` would hold at the cut; None when something still moves there."""
    import numpy as np

    rows = snapshot.states  # (steps, bodies, 6): x, y, angle, vx, vy, w; NaN once a body is gone
    speeds = np.nan_to_num(np.abs(rows[:, :, 3:6]).sum(axis=2), nan=0.0)
    moving = (speeds > still).any(axis=1)
    if BIRD in snapshot.names:
        moving |= ~np.isnan(rows[:, snapshot.names.index(BIRD), 0])
    if moving[-1]:
        return None
    last = np.flatnonzero(moving)
    first_still = int(last[-1]) + 1 if len(last) else 0
    return (first_still + 1) * snapshot.dt  # the time `finished` saw at that step
