"""What leaves a Science Birds level during a run: the fourth layer of `Game` (game.py). A
body whose life is spent, one outside the level, a bird at rest or too old, a dying body that
lingers (ABGameObject.Die), and what a removal sets off (a TNT box's or a bird's blast)."""

from __future__ import annotations

from physc.domains.angrybirds import prefabs
from physc.domains.angrybirds.game_damage import GameDamage


class GameRemovals(GameDamage):
    """The game's removals (module docstring)."""

    def on_removed(self, engine, name: str, cause: str, alive: set, damage: list, time: float) -> None:
        if self.kinds[name] == "tnt" and cause == "damage":
            self._explode(engine, name, alive, damage, time)
        elif self.kinds[name] in ("bird", "egg"):
            blast = self.flights.blast(name)
            if blast is not None:  # a black bird's or an egg's blast (ABTNT.Explode)
                self._blast(engine, name, blast.radius, blast.power, blast.damage, alive, damage, time)
            self.flights.left(name, time)

    def removals_due(self, values: list, alive: set, time: float) -> bool:
        """Whether anything may leave the level this step (what does is `gone`'s to say):
        a body whose life is spent, one outside the level, the bird at rest or too old.
        `values`: the state of each body, NaN for the bodies already gone (no test holds for NaN)."""
        if self.spent and not self.spent.isdisjoint(alive):
            return True
        left, right = self.world.frame.left, self.world.frame.right
        for v in values:  # `_outside`, inlined: this runs every step, and a call per body nearly triples its cost
            if v[0] < left or v[0] > right:
                return True
        flights = self.flights
        if flights.blasted or flights.fuses and flights.arm(time):
            return True
        for name in flights.flying:
            if name in alive and flights.check_due(name, time):
                _, _, _, vx, vy, _ = values[self._row[name]]
                if flights.done(name, vx, vy, time):
                    return True
                flights.checked(name)
        return False

    def gone(self, name: str, state: tuple, time: float, damage: list) -> tuple | None:
        """Why `name` (its state: x, y, angle, vx, vy, ω) leaves the level now (the kind of
        destruction and by whom), if it does."""
        x, _, _, vx, vy, _ = state
        if name in self.spent:
            return ("damage", self._last_attacker(damage, name))
        if self._outside(x):
            return ("out of world", None)
        flights = self.flights
        if name in flights.blasted or (flights.check_due(name, time) and flights.done(name, vx, vy, time)):
            return ("removed", None)
        return None

    def _outside(self, x: float) -> bool:
        """Whether `x` lies beyond the level's left or right edge (never for NaN: a body
        already gone)."""
        return x < self.world.frame.left or x > self.world.frame.right

    def lingers(self, engine, name: str, cause: str) -> float:
        """ABGameObject.Die (`Rules.dying_lingers`): a dying pig or block stops, loses its
        first collider and stays for its prefab's `lifetime`; one left with no collider, or
        whose backend cannot take a collider out, goes at once."""
        obj = self._objects.get(name)
        if not self.rules.dying_lingers or obj is None or self.kinds.get(name) not in ("pig", "block"):
            return 0.0
        stay = prefabs.lifetime(obj.type) if obj.type in prefabs.prefabs() else 0.0
        if stay <= 0:
            return 0.0
        if prefabs.first_collider_enabled(obj.type, self.model.circle_colliders):
            if self.colliders.get(name, 1) == 1 or not hasattr(engine, "disable_collider"):
                return 0.0  # nothing left to collide with (or no way to take the collider out)
            engine.disable_collider(name, 0)
        stop_moving(engine, name)
        self._dying.add(name)
        return stay


def stop_moving(engine, name: str) -> None:
    """ABGameObject.Die's `_rigidBody.velocity = Vector2.zero`: the body's motion stopped, its spin kept."""
    engine.set_velocity(name, 0.0, 0.0, engine.state(name)[5])
