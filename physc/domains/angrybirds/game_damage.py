"""The damage a Science Birds run deals: the third layer of `Game` (game.py). The damage rule
(damage.py) on both bodies of a contact, in the world's reading of the game's open points (and
where another reading would deal other damage), and the blasts of TNT, a black bird and an egg."""

from __future__ import annotations

import math

from physc.domains.angrybirds.damage import Party, Strike, decisive
from physc.domains.angrybirds.game_scene import GameScene
from physc.simulation.trace import ContactRecord, DamageRecord, DependenceRecord


class GameDamage(GameScene):
    """The game's damage and blasts (module docstring)."""

    def _damage(self, engine, contact: ContactRecord, out: list, time: float) -> None:
        """The damage rule (damage.py) on both bodies of `contact`, in this world's reading; where
        another reading of the game's open points would deal other damage, a DependenceRecord."""
        rules = self.rules
        speed = contact.speed
        if speed <= 0:
            return
        for target in (contact.a, contact.b):
            if (
                target not in self.life
                or self.life[target] <= 0
                or target in self._dying
                or self.kinds.get(target) == "platform"
            ):
                continue  # a platform has no ABGameObject: nothing of it is damaged
            other = contact.b if target == contact.a else contact.a
            rv = (
                contact.relative_velocity
                if target == contact.a
                else (-contact.relative_velocity[0], -contact.relative_velocity[1])
            )
            strike = Strike(
                self._party(engine, target),
                self._party(engine, other),
                speed,
                rv,
                self.defence[target],
                self.material.get(target, ""),
            )
            amount, attacker, per_speed = strike.dealt(rules)
            least = most = None
            if self._fields and strike.most(rules, self._platform_masses) > 0:
                amounts = {
                    combo: strike.dealt(rules, **dict(zip(self._fields, combo, strict=True)))[0]
                    for combo in self._combos
                }
                least, most = min(amounts.values()), max(amounts.values())
                points = decisive(self._fields, amounts)
                if points:
                    self._depends.append(DependenceRecord(time, target, tuple(self._settings[i] for i in points)))
            if amount <= 0 and not most:
                continue
            # The strike that would have destroyed it: its life and defence over the damage a unit of speed deals.
            needed = (self.life[target] + self.defence[target]) / per_speed if per_speed > 0 else None
            if amount > 0:
                self._wound(target, amount)
            out.append(DamageRecord(time, target, amount, self.life[target], other, attacker, needed, least, most))

    def _party(self, engine, name: str) -> Party:
        """`name` as the damage rule reads it: kind, mass and velocity after the step (a
        platform or the ground: still, and massless here; the rule reads a platform's mass)."""
        kind = self.kinds.get(name, "")
        if kind in ("platform", "ground"):
            return Party(name, kind, 0.0, (0.0, 0.0))
        _, _, _, vx, vy, _ = engine.state(name)
        return Party(name, kind, engine.mass(name), (vx, vy))

    def _wound(self, target: str, amount: float) -> None:
        self.life[target] -= amount
        if self.life[target] <= 0:
            self.spent.add(target)

    @staticmethod
    def _last_attacker(damage: list, name: str) -> str | None:
        return next((d.by for d in reversed(damage) if d.target == name and d.amount > 0), None)

    def _explode(self, engine, name: str, alive: set, damage: list, time: float) -> None:
        """A TNT box's blast (TNT.prefab's numbers, `Rules`)."""
        rules = self.rules
        self._blast(engine, name, rules.tnt_radius, rules.tnt_impulse, rules.tnt_damage, alive, damage, time)

    def _blast(
        self, engine, name: str, radius: float, power: float, amount: float, alive: set, damage: list, time: float
    ) -> None:
        """ABTNT.Explode where `name` is: every body within `radius` but birds takes damage and
        an impulse away from it, both falling off linearly with the distance."""
        cx, cy = engine.state(name)[:2]
        for other in sorted(alive):
            if other == name or self.kinds.get(other) == "bird":
                continue
            x, y, _, vx, vy, w = engine.state(other)
            distance = math.hypot(x - cx, y - cy)
            share = max(1.0 - distance / radius, 0.0)
            if share <= 0.0 or distance == 0:
                continue
            # Physics2D.OverlapCircleAll lists colliders: a body with several takes the blast from each.
            hits = self.colliders.get(other, 1)
            push = hits * power * share / max(engine.mass(other), 1e-6)
            engine.set_velocity(other, vx + push * (x - cx) / distance, vy + push * (y - cy) / distance, w)
            if other in self.life:
                dealt = hits * amount * share
                self._wound(other, dealt)
                damage.append(DamageRecord(time, other, dealt, self.life[other], name))
