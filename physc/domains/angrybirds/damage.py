"""Science Birds' damage for one contact, under each reading of what the game's files leave open.

`ABGameObject.OnCollisionEnter2D`, which Unity calls on each object with life after the
step: the attacker is the object itself unless the other body has a Rigidbody2D whose
velocity projects further onto `collision.relativeVelocity` (`projectCollision >
projectThis`); the damage is `|v_rel| · m_attacker · 11.22 · 0.5 − defence`, at least 0.
`ABBlock` overrides it for a bird: `|v_rel| · m_bird · multiplier · 11.22 − defence`. The
ground has no Rigidbody2D (the object attacks itself); a platform has a kinematic one, still,
whose mass is one of the open points.

Three points of that rule are not in the game's files (`ScienceBirdsWorld.open_points`): the
sign of `relativeVelocity`, the kinematic platform's mass and which body attacks in a near
tie. `Strike.amounts` deals the damage under every combination of them, so a run records
where its reading decided something (physc.simulation.trace.DependenceRecord) and the least
damage any reading would have dealt (a destroy's margin under the worst reading).
"""

from __future__ import annotations

import itertools
import math

import attrs

from physc.domains.angrybirds.rules import Rules

BIRD_KIND = "bird"


@attrs.frozen
class Party:
    """One body of a contact as the rule reads it: its kind, mass and velocity after the step."""

    name: str
    kind: str
    mass: float
    velocity: tuple[float, float]


@attrs.frozen
class Strike:
    """One contact as the object `this` hears of it: the other body, the speed of the contact
    and its relative velocity (this body's less the other's, before the step), its defence."""

    this: Party
    other: Party
    speed: float
    relative: tuple[float, float]
    defence: float
    material: str

    def attacker(
        self, rules: Rules, relative_velocity: str, platform_mass: float, near_tie: str
    ) -> tuple[str, float, bool]:
        """(the attacker's name, its mass, whether ABBlock's bird override applies) under one reading."""
        this, other = self.this, self.other
        if other.kind == "ground":  # no Rigidbody2D: the object attacks itself
            return this.name, this.mass, False
        if other.kind == BIRD_KIND and this.kind == "block":
            return other.name, other.mass, True
        mass = platform_mass if other.kind == "platform" else other.mass
        if rules.attacker == "contact":  # physc's earlier model: one attacker per contact, before the step
            return (this.name, this.mass, False) if other.kind == "platform" else self._contact_attacker(mass)
        sign = 1.0 if relative_velocity == "this-minus-other" else -1.0
        rx, ry = sign * self.relative[0], sign * self.relative[1]
        norm = math.hypot(rx, ry)
        if norm == 0.0:
            return this.name, this.mass, False
        project_this = (this.velocity[0] * rx + this.velocity[1] * ry) / norm
        project_other = (other.velocity[0] * rx + other.velocity[1] * ry) / norm
        lead = project_other - project_this
        others = lead > rules.tie_band or (abs(lead) <= rules.tie_band and near_tie == "other")
        return (other.name, mass, False) if others else (this.name, this.mass, False)

    def _contact_attacker(self, other_mass: float) -> tuple[str, float, bool]:
        """The earlier model's attacker: the body whose own velocity carries the contact."""
        this, other = self.this, self.other
        rv = self.relative
        push_this = this.velocity[0] * rv[0] + this.velocity[1] * rv[1]
        push_other = -(other.velocity[0] * rv[0] + other.velocity[1] * rv[1])
        return (this.name, this.mass, False) if push_this >= push_other else (other.name, other_mass, False)

    def per_speed(self, rules: Rules, mass: float, override: bool) -> float:
        """The damage a unit of contact speed deals, before the defence."""
        if override:
            return mass * rules.bird_multiplier.get(self.material, 1.0) * rules.damage_factor
        return mass * rules.damage_factor * rules.block_damage_share

    def dealt(self, rules: Rules, **reading) -> tuple[float, str, float]:
        """(damage, attacker, damage per unit of speed) under one reading (the rules' own
        values for what `reading` leaves out)."""
        values = {key: reading.get(key, getattr(rules, key)) for key in READ}
        name, mass, override = self.attacker(rules, **values)
        per_speed = self.per_speed(rules, mass, override)
        return max(self.speed * per_speed - self.defence, 0.0), name, per_speed

    def most(self, rules: Rules, platform_masses) -> float:
        """An upper bound of the damage under any reading (a contact below it can be skipped)."""
        masses = [self.this.mass, self.other.mass] + ([max(platform_masses)] if self.other.kind == "platform" else [])
        factor = rules.damage_factor * max(rules.block_damage_share, max(rules.bird_multiplier.values(), default=1.0))
        return self.speed * max(masses) * factor - self.defence


READ = ("relative_velocity", "platform_mass", "near_tie")  # the rules' fields the open points set


def readings(points) -> tuple[tuple[str, ...], list[tuple]]:
    """(the rules' fields the open points `points` set, every combination of their values)."""
    fields = tuple(
        p.setting.split(".", 1)[1]
        for p in points
        if p.setting.startswith("rules.") and p.setting.split(".", 1)[1] in READ
    )
    values = [p.readings for p in points if p.setting.startswith("rules.") and p.setting.split(".", 1)[1] in READ]
    return fields, list(itertools.product(*values))


def decisive(fields: tuple[str, ...], amounts: dict[tuple, float]) -> tuple[int, ...]:
    """The indices of the fields whose reading changes the damage: two combinations that
    differ in that field alone deal different damage."""
    out = []
    for i in range(len(fields)):
        for combo, amount in amounts.items():
            differs = [
                other
                for other in amounts
                if other[:i] == combo[:i] and other[i + 1 :] == combo[i + 1 :] and other[i] != combo[i]
            ]
            if any(abs(amounts[other] - amount) > 1e-12 for other in differs):
                out.append(i)
                break
    return tuple(out)
