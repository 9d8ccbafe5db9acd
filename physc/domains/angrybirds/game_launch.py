"""The game's setup in one world and the launch of its birds: the first layer of `Game`
(game.py). A run's flights (flight.py), each bird put at the slingshot flying as its shot sends
it, and what comes into the level during a run (a power's bodies at a tap, the next bird)."""

from __future__ import annotations

from physc.backends import Backend, BodySpec
from physc.domains.angrybirds.damage import readings
from physc.domains.angrybirds.flight import Flights
from physc.domains.angrybirds.launch import Shot
from physc.domains.angrybirds.level import Level
from physc.domains.angrybirds.worlds import ScienceBirdsWorld
from physc.simulation.run import RunRules


class GameLaunch(RunRules):
    """A Science Birds level in one world and engine, and its birds' launches (module docstring);
    the run's state that `scene` sets (game_scene.py) is declared here where the launch reads it."""

    kinds: dict[str, str]  # each body's kind ("ground", "platform", "block", "pig", "tnt", "bird", "egg")
    outlines: dict  # each body's outline, the birds that came in included
    _invulnerable: float  # until when (s) no damage counts

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

    def launch(self, engine, shot: Shot) -> None:
        """Put the bird of `shot` alone into `engine` (built by `build`) at the slingshot, flying as
        `shot` sends it, damage counting from now (an engine world stepped by hand; in a run,
        `scene` places the first bird and `enter` brings in the others)."""
        self._invulnerable = 0.0
        self.flights = self._flights((shot,))
        first = self.flights.launch_due(0.0)
        assert first is not None  # a fresh run's first shot is due at once
        self._launch(engine, first)
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
