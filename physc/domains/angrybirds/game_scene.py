"""The scene a Science Birds level becomes: the second layer of `Game` (game.py). Each level
object as a backend-neutral body (its catalogue shape or the game's collider, its material's
density, friction and bounciness, its life and defence), the ground, the first bird at the
slingshot, and the run's state that the rules' hooks read."""

from __future__ import annotations

import math

from physc.backends import BodySpec, Circle, Polygon, colliders
from physc.domains.angrybirds import prefabs
from physc.domains.angrybirds.catalogue import BY_PREFAB, PHYQ_CIRCLES, extent
from physc.domains.angrybirds.game_launch import GameLaunch
from physc.domains.angrybirds.launch import Shot, shots_of
from physc.domains.angrybirds.level import LevelObject
from physc.simulation.scene import Scene, built
from physc.simulation.trace import DependenceRecord

GROUND = "ground"


class GameScene(GameLaunch):
    """The level as physics, and a run's state set for it (module docstring)."""

    def _material(self, obj: LevelObject) -> str:
        """The material the game gives a block: its own, or wood for one the world does not know."""
        material = obj.material
        return material if material is not None and material in self.model.materials else "wood"

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
                angle=angle,
                angular_damping=model.angular_drag,
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
            angle=angle,
            angular_damping=model.angular_drag,
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
        # Where another reading of the open points would have dealt other damage.
        self._depends: list[DependenceRecord] = []
        self.life: dict[str, float] = {}
        self.defence: dict[str, float] = {}
        self.material: dict[str, str] = {}
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
            first = flights.launch_due(0.0)
            assert first is not None  # a fresh run's first shot is due at once
            spec, velocity = self._launched(first)
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
