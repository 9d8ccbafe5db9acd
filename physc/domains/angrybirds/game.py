"""Playing a Science Birds level: its scene and the game's rules as the run loop's hooks.

The game turns a level into a backend-neutral scene (catalogue shapes, materials, the first
bird at the slingshot, flying), and after every physics step of physc's run loop
(physc.simulation.run) applies the rules of Science Birds to the contacts the engine reports:
damage from the attacker's mass and the relative velocity, destruction at life <= 0, removal of
objects leaving the level and of birds that have come to rest, the next bird and a bird's
power, success when every pig is destroyed. The loop records the trace and
physc.simulation.recognise reads it; the game adds what it kept (`completed`) and names what a
bird's parts did as the bird's (`read`).
"""

from __future__ import annotations

import math

import attrs

from physc.backends import Backend, BodySpec, Circle, Polygon, colliders
from physc.domains.angrybirds import prefabs
from physc.domains.angrybirds.catalogue import (
    BY_PREFAB,
    PHYQ_CIRCLES,
    extent,
)
from physc.domains.angrybirds.damage import Party, Strike, decisive, readings
from physc.domains.angrybirds.flight import FIRST, Flights
from physc.domains.angrybirds.launch import Shot, shots_of
from physc.domains.angrybirds.level import Level, LevelObject
from physc.domains.angrybirds.worlds import ScienceBirdsWorld
from physc.simulation.run import RunRules
from physc.simulation.scene import Scene, built, play_scene, playout
from physc.simulation.trace import ContactRecord, DamageRecord, DependenceRecord, Playout, Trace

BIRD = FIRST  # the first bird's name
GROUND = "ground"


class Game(RunRules):
    """A Science Birds level played in one world (its bodies, launch, rules and recognition)
    with one physics engine: the game's rules as the hooks of the generic run loop
    (physc.simulation.run)."""

    def __init__(self, level: Level, world: ScienceBirdsWorld, backend: Backend):
        self.level = level
        self.world = world
        self.backend = backend
        self.rules = world.rules
        self.model = world.bodies
        # The game's open points that its damage rule reads (damage.py): the rules' fields, every
        # combination of their readings, their settings' paths, the platform masses read.
        points = [p for p in world.open_points() if p.setting.startswith("rules.")]
        self._fields, self._combos = readings(points)
        self._settings = tuple(f"rules.{f}" for f in self._fields)
        self._platform_masses = next(
            (p.readings for p in points if p.setting == "rules.platform_mass"), (self.rules.platform_mass,)
        )
        self.flights = self._flights(())  # the birds of a run (`scene` makes them)

    def _material(self, obj: LevelObject) -> str:
        return obj.material if obj.material in self.model.materials else "wood"

    # ---- building the world ---------------------------------------------------------
    def _spec(self, obj: LevelObject) -> tuple[BodySpec, str, float, float]:
        """The body of a level object, its kind, life and defence."""
        catalogue = BY_PREFAB[obj.type]
        rules, model = self.rules, self.model
        angle = math.radians(obj.rotation or 0.0)
        if catalogue.kind == "platform":
            w, h = (size / 2 for size in extent(obj))
            outline = Polygon(((-w, -h), (w, -h), (w, h), (-w, h)))
            spec = BodySpec(obj.name, outline, obj.x, obj.y, angle, static=True, friction=model.platform_friction)
            return spec, "platform", math.inf, 0.0
        game = model.colliders == "game" and obj.type in prefabs.prefabs()
        if game:
            outline = prefabs.body_shape(obj.type, model.circle_colliders)
        elif catalogue.round and model.colliders == "phyq" and catalogue.name in PHYQ_CIRCLES:
            outline = Polygon(catalogue.phyq_circle_points())
        elif catalogue.round:
            outline = Circle(catalogue.width / 2)
        else:
            outline = Polygon(catalogue.outline_points())
        common = dict(angle=angle, angular_damping=model.angular_drag)
        if catalogue.kind == "pig":
            mass = prefabs.body_mass(obj.type, model.pig_density, model.circle_colliders) if game else None
            spec = BodySpec(
                obj.name,
                outline,
                obj.x,
                obj.y,
                mass=mass,
                density=model.pig_density,
                friction=model.pig_friction,
                bounciness=model.pig_bounciness,
                continuous=True,
                **common,
            )
            return spec, "pig", float(catalogue.life[""]), rules.pig_defence
        if catalogue.kind == "tnt":
            spec = BodySpec(
                obj.name,
                outline,
                obj.x,
                obj.y,
                angle,
                density=model.tnt_density,
                friction=model.tnt_friction,
                gravity_scale=model.tnt_gravity_scale,
                angular_damping=model.tnt_angular_drag,
            )
            return spec, "tnt", float(catalogue.life[""]), 0.0
        material = model.materials[self._material(obj)]
        mass = prefabs.body_mass(obj.type, material.density, model.circle_colliders) if game else None
        spec = BodySpec(
            obj.name,
            outline,
            obj.x,
            obj.y,
            mass=mass,
            density=material.density,
            friction=material.friction,
            bounciness=material.bounciness,
            **common,
        )
        return spec, "block", float(catalogue.life[material.name]), material.defence

    def scene(
        self,
        shot: Shot | None = None,
        stop_at_rest: bool = True,
        invulnerable: float | None = None,
        settle_after_solved: float | None = None,
    ) -> Scene:
        """The level as physics (physc.simulation.scene), the first bird of `shot` at the slingshot,
        flying as the shot sends it; the game, the run's rules, set for one run of it (a scene
        a run; the game's state is this run's until the next `scene`).

        Damage counts from the shot on (the player shoots after the level's first 2 s of
        invulnerability); with no shot, the first 2 s are invulnerable, as when the level loads.
        With `stop_at_rest` the run ends once everything has come to rest (and the bird is gone or
        still); with `settle_after_solved`, that many seconds after the last pig is destroyed, once
        nothing is falling (a fall that began while the sequence ran is recognised where it lands)."""
        ground_top = self.world.frame.ground_top
        ground = BodySpec(
            GROUND,
            Polygon(((-40, -0.5), (40, -0.5), (40, 0.5), (-40, 0.5))),
            0.0,
            ground_top - 0.5,
            static=True,
            friction=self.model.ground_friction,
        )
        bodies = [ground]
        self.kinds = {GROUND: "ground"}
        self._depends: list[
            DependenceRecord
        ] = []  # where another reading of the open points would have dealt other damage
        self.life, self.defence, self.material = {}, {}, {}
        self.colliders: dict[str, int] = {}  # how many colliders each body has (a blast reaches each)
        self._objects = {obj.name: obj for obj in self.level.objects}
        self._dying: set[str] = set()  # bodies that left the level but stay in the world a while (`lingers`)
        self.spent: set[str] = set()  # bodies whose life is used up (destroyed at the end of the step)
        for obj in self.level.objects:
            spec, kind, life, defence = self._spec(obj)
            bodies.append(spec)
            self.kinds[obj.name] = kind
            self.colliders[obj.name] = len(set(colliders(spec.shape)))
            self.life[obj.name] = life
            self.defence[obj.name] = defence
            self.material[obj.name] = self._material(obj) if kind == "block" else ""
        shots = shots_of(shot)
        self.flights = flights = self._flights(shots)
        self.arrivals = flights.several or any(s.tap is not None for s in shots)
        for name in flights.bodies:
            self.kinds[name] = flights.kind(name)
        dynamic = tuple(flights.bodies + [o.name for o in self.level.objects if self.kinds[o.name] != "platform"])
        self._row = {name: i for i, name in enumerate(dynamic)}
        velocities = {}
        if shots:
            spec, velocity = self._launched(flights.launch_due(0.0))
            bodies.append(spec)
            velocities[spec.name] = (*velocity, 0.0)
        self.outlines = {body.name: body.outline for body in bodies}
        # This run's settings and state, read by the hooks below.
        self._invulnerable = (
            invulnerable if invulnerable is not None else 0.0 if shots else self.rules.invulnerable_seconds
        )
        self._dynamic = dynamic
        self._pigs = tuple(n for n in dynamic if self.kinds[n] == "pig")
        self._settle_after_solved, self._solved_at = settle_after_solved, None
        self._stop_at_rest, self._resting_since = stop_at_rest, None
        return Scene(
            tuple(bodies),
            dict(self.kinds),
            self.world.gravity,
            self.world.engine,
            self.radii(),
            velocities,
            self._pigs,
            rows=dynamic,
            turns=max(len(shots), 1),
        )

    def build(self):
        """The level with no shot as a world of the game's backend, for a run stepped by hand."""
        return built(self.scene(), self.backend)

    def launch(self, engine, shot: Shot) -> None:
        """Put the bird of `shot` alone into `engine` (built by `build`) at the slingshot, flying as
        `shot` sends it, damage counting from now (an engine world stepped by hand; in a run,
        `scene` places the first bird and `enter` brings in the others)."""
        self._invulnerable = 0.0
        self.flights = self._flights((shot,))
        self._launch(engine, self.flights.launch_due(0.0))
        self.kinds[shot.bird] = "bird"

    def _flights(self, shots) -> Flights:
        """The birds of a run of `shots`, the level's <Bird> list giving each its kind."""
        return Flights(tuple(shots), self.level.birds, self.rules, self.model, self.world.launch.bird_rest[0])

    def _launched(self, k: int) -> tuple[BodySpec, tuple[float, float]]:
        """The `k`th bird at the slingshot (from where the game starts it: its own collider's
        offset) and its velocity as its shot sends it."""
        flights = self.flights
        shot, name = flights.shots[k], flights.names[k]
        (x, y), velocity = shot.start(self.world)
        bird, red = flights.of(name), self.world.launch.collider_offset
        origin = (x + bird.offset[0] - red[0], y + bird.offset[1] - red[1]) if bird.prefab != "BirdRed" else (x, y)
        return flights.body(name, origin), velocity

    def _launch(self, engine, k: int) -> str:
        """Put the `k`th bird into `engine`, flying; its name."""
        spec, velocity = self._launched(k)
        self._enter(engine, spec, velocity)
        return spec.name

    def _enter(self, engine, spec: BodySpec, velocity: tuple[float, float]) -> None:
        engine.add(spec)
        self.outlines[spec.name] = spec.outline
        engine.set_velocity(spec.name, *velocity)

    # ---- playing ----------------------------------------------------------------------
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

    def solved(self, recorded) -> bool:
        """Science Birds' goal: every pig destroyed (a level without pigs is never solved)."""
        destroyed = {d.name for d in recorded.destructions}
        return bool(self._pigs) and set(self._pigs) <= destroyed

    # ---- the run's hooks (physc.simulation.run.RunRules) ------------------------------
    def on_contact(self, engine, contact: ContactRecord, damage: list, time: float) -> None:
        for name in self._dying.intersection(
            (contact.a, contact.b)
        ):  # OnCollisionEnter2D → DealDamage → Die: it stops again
            _stop(engine, name)
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

    def on_removed(self, engine, name: str, cause: str, alive: set, damage: list, time: float) -> None:
        if self.kinds[name] == "tnt" and cause == "damage":
            self._explode(engine, name, alive, damage, time)
        elif self.kinds[name] in ("bird", "egg"):
            blast = self.flights.blast(name)
            if blast is not None:  # a black bird's or an egg's blast (ABTNT.Explode)
                self._blast(engine, name, blast.radius, blast.power, blast.damage, alive, damage, time)
            self.flights.left(name, time)

    def enter(self, engine, values: list, alive: set, damage: list, time: float) -> tuple[str, ...]:
        """What comes into the level now: a power's bodies at a tap (flight.py), the next bird."""
        flights, new = self.flights, []
        for name in flights.taps_due(time):
            if name in alive:
                for spec, velocity in flights.fire(engine, name, time):
                    self._enter(engine, spec, velocity)
                    new.append(spec.name)
        k = flights.launch_due(time)
        if k is not None:
            new.append(self._launch(engine, k))
        return tuple(new)

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

    def play(
        self, shot: Shot | None = None, seconds: float = 10.0, restrictions=(), redirects=None, resume=None, **options
    ) -> Trace:
        """`simulate`, with the interactions recognised and the restrictions checked (`redirects`:
        the declared bounces, see physc.simulation.restrictions)."""
        scene = self.scene(shot, **options)
        return play_scene(
            scene, self.backend, self, seconds, self.world.recogniser, restrictions, redirects, resume=resume
        )

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

    def _falling(self, values: list, dynamic: tuple[str, ...]) -> bool:
        """Whether a block, pig or TNT (not the bird) is coming down fast."""
        fast = self.world.falling_speed
        return any(v[4] < -fast for v, name in zip(values, dynamic) if self.kinds.get(name) != "bird")

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
        _stop(engine, name)
        self._dying.add(name)
        return stay

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

    def _wound(self, target: str, amount: float) -> None:
        self.life[target] -= amount
        if self.life[target] <= 0:
            self.spent.add(target)

    def radii(self) -> dict[str, float]:
        """The rolling radius of every body that can roll: circles, pigs, the birds."""
        flights = self.flights
        out = {n: flights.of(n).radius for n in flights.bodies if flights.kind(n) == "bird"}
        for obj in self.level.objects:
            catalogue = BY_PREFAB[obj.type]
            if catalogue.round or catalogue.kind == "pig":
                circle = (
                    prefabs.circle_radius(obj.type, self.model.circle_colliders)
                    if obj.type in prefabs.prefabs()
                    else None
                )
                out[obj.name] = circle or min(catalogue.width, catalogue.height) / 2
        return out

    # ---- rules ----------------------------------------------------------------------------
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
                amounts = {combo: strike.dealt(rules, **dict(zip(self._fields, combo)))[0] for combo in self._combos}
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


def _stop(engine, name: str) -> None:
    """ABGameObject.Die's `_rigidBody.velocity = Vector2.zero`: the body's motion stopped, its spin kept."""
    engine.set_velocity(name, 0.0, 0.0, engine.state(name)[5])


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
