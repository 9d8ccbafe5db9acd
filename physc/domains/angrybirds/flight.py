"""The birds of one play: the shots in turn, each bird's checks, and the powers a tap sets off.

A level's birds are shot in the order of its <Bird> list (ABGameWorld.AddBird). The first
flies at once; each next one is shot once the level has come to rest with no bird in flight
(Phy-Q's agents shoot in the framework's safe mode, which waits until the level is static),
or `Shot.wait` seconds after the game put it on the slingshot: when the bird before it first
struck something, or used its power (ABGameWorld.KillBird, called from ABBird's first
collision, the blue and white birds' taps and the black bird's blast). A bird is checked as
ABBird.cs checks it: 3 s after its first collision and every second after, it goes once
slower than 0.001 units/s, and it never lives more than 20 s (`Rules`). A tap fires the
bird's power (birds.py) at most once, while the bird is past the slingshot and, but for the
black bird, has struck nothing (HUD.cs).

What a power brings into the level (a blue bird's two other birds, a white bird's egg) is
listed among the run's bodies from the start and enters then (`RunRules.enter`).
"""

from __future__ import annotations

import math

from physc.backends import BodySpec, Circle, Polygon
from physc.domains.angrybirds.birds import POWERS, Bird, Blast, bird
from physc.domains.angrybirds.launch import Shot
from physc.simulation.recognise import ORDER
from physc.simulation.trace import Interaction

FIRST = "bird"  # the first bird's name in a trace, as before version 2
GROUP = "birds"  # the game's Birds layer: birds (and the white bird's egg) never collide with one another
EGG = "egg"  # the egg's kind


def extra(name: str, power: str) -> tuple[str, ...]:
    """The bodies a power brings in, named after the bird: the blue bird's other two, the egg."""
    if power == "split":
        return tuple(f"{name}~{i}" for i in range(1, len(POWERS.split_angles)))
    return (f"{name}~egg",) if power == "egg" else ()


class Flights:
    """The birds of one play (module docstring), driven by the Game's run hooks."""

    def __init__(self, shots: tuple[Shot, ...], prefabs: tuple[str, ...], rules, model, rest_x: float):
        self.rules, self.model, self.rest_x = rules, model, rest_x
        self.shots = shots
        self.birds: list[Bird] = [bird(prefabs[k] if k < len(prefabs) else "BirdRed") for k in range(len(shots))]
        self.names = [shot.bird for shot in shots]
        self.extras: dict[str, tuple[str, ...]] = {
            name: extra(name, b.power) if shots[k].tap is not None else ()
            for k, (name, b) in enumerate(zip(self.names, self.birds, strict=False))
        }
        self.parent = {clone: name for name, clones in self.extras.items() for clone in clones}
        self.next = 0  # the shot to come
        self.due_at: float | None = 0.0  # when it is shot (None: once the level rests)
        self.flying: dict[str, float] = {}  # a bird in play → when it is next checked
        self.struck: set[str] = set()
        self.launched: dict[str, float] = {}
        self.tapped: list[tuple[float, str]] = []  # (time, bird) of each tap that fired its power
        self.tried: set[str] = set()  # birds whose tap came (HUD.cs checks once: a tap too early is lost)
        self.fuses: dict[str, float] = {}  # black bird → when it blasts
        self.blasted: set[str] = set()  # bodies that blast and go this step (a black bird, an egg)
        self.ready_at: float | None = None  # when the game put the next bird on the slingshot (KillBird)

    @property
    def bodies(self) -> list[str]:
        """Every bird's name and what its power brings in, in the order shot."""
        return [n for name in self.names for n in (name, *self.extras[name])]

    @property
    def several(self) -> bool:
        return len(self.bodies) > 1

    def kind(self, name: str) -> str:
        return EGG if name.endswith("~egg") else "bird"

    def of(self, name: str) -> Bird:
        """The bird of a body (a blue bird's other birds are blue birds)."""
        return self.birds[self.names.index(self.parent.get(name, name))]

    # ---- the shots -----------------------------------------------------------------
    def waiting(self) -> bool:
        """Whether a shot is still to come."""
        return self.next < len(self.shots)

    def resting(self) -> None:
        """The level has come to rest with no bird in flight: the next shot comes now, unless
        its `wait` has it sooner."""
        if self.waiting() and self.due_at is None:
            self.due_at = -math.inf

    def launch_due(self, time: float) -> int | None:
        """The shot to launch now, if one is due."""
        if not self.waiting() or self.due_at is None or time < self.due_at - 1e-9:
            return None
        k = self.next
        self.next += 1
        self.due_at, self.ready_at = None, None
        self.launched[self.names[k]] = time
        self.flying[self.names[k]] = time + self.rules.bird_lifetime
        return k

    def body(self, name: str, origin: tuple[float, float]) -> BodySpec:
        """The body of a bird (the red bird: as the world's model has it)."""
        b, model = self.of(name), self.model
        red = b.prefab == "BirdRed"
        mass, friction, bounciness = (
            (model.bird_mass, model.bird_friction, model.bird_bounciness) if red else (b.mass, b.friction, b.bounciness)
        )
        return BodySpec(
            name,
            Circle(b.radius),
            *origin,
            mass=mass,
            friction=friction,
            bounciness=bounciness,
            angular_damping=model.bird_angular_drag,
            continuous=True,
            group=GROUP if self.several else "",
        )

    def left(self, name: str, time: float) -> None:
        """A bird left the level (the game's KillBird, if not yet)."""
        self.flying.pop(name, None)
        self.killed(name, time)

    def killed(self, name: str, time: float) -> None:
        """ABGameWorld.KillBird: the next bird comes onto the slingshot; a timed shot (`wait`) is
        due that long after, and never before the game can release it (`Rules.earliest_wait`)."""
        if name not in self.names or self.names.index(name) != self.next - 1 or self.ready_at is not None:
            return
        self.ready_at = time
        wait = self.shots[self.next].wait if self.waiting() else None
        if wait is not None:
            self.due_at = time + max(wait, self.rules.earliest_wait)

    # ---- contacts and checks ---------------------------------------------------------------
    def on_contact(self, a: str, b: str, time: float) -> None:
        for name in (a, b):
            if name in self.flying and name not in self.struck:
                self.strike(name, time)
            elif self.kind(name) == EGG and name in self.launched:
                self.blasted.add(name)  # ABEgg.OnCollisionEnter2D: it blasts at once

    def strike(self, name: str, time: float) -> None:
        """A bird's first collision (ABBird.OnCollisionEnter2D): the next bird comes (KillBird; the
        black bird's fuse starts instead), and the bird is checked 3 s later and every 1 s after."""
        self.struck.add(name)
        if self.of(name).power != "blast":
            self.killed(self.parent.get(name, name), time)
        self.flying[name] = min(time + self.rules.bird_still_after, self.launched_at(name) + self.rules.bird_lifetime)
        if self.of(name).power == "blast" and name not in self.fuses:
            self.fuses[name] = time + POWERS.black_fuse

    def launched_at(self, name: str) -> float:
        """When the bird (of a blue bird's copies: the blue bird) was shot."""
        return self.launched.get(self.parent.get(name, name) if self.kind(name) != EGG else name, 0.0)

    def check_due(self, name: str, time: float) -> bool:
        return name in self.flying and time >= self.flying[name] - 1e-9

    def done(self, name: str, vx: float, vy: float, time: float) -> bool:
        """At a check: whether the bird goes, too old or nearly still."""
        rules = self.rules
        return (
            time >= self.launched_at(name) + rules.bird_lifetime - 1e-9 or math.hypot(vx, vy) < rules.bird_still_speed
        )

    def checked(self, name: str) -> None:
        """A check the bird passed: the next one a second later (never past its lifetime)."""
        self.flying[name] = min(
            self.flying[name] + self.rules.bird_still_every, self.launched_at(name) + self.rules.bird_lifetime
        )

    # ---- powers ----------------------------------------------------------------------------
    def taps_due(self, time: float) -> list[str]:
        """The birds whose tap comes now (each at most once)."""
        out = []
        for name in list(self.flying):
            k = self.names.index(name) if name in self.names else None
            tap = self.shots[k].tap if k is not None else None
            if tap is None or name in self.tried:
                continue
            if time >= self.launched[name] + tap - 1e-9:
                out.append(name)
        return out

    def fire(self, engine, name: str, time: float) -> list[tuple[BodySpec, tuple[float, float]]]:
        """The tap on `name` now: the bodies its power brings in, each with its velocity (a
        black bird's blast is set for `blasts_due`)."""
        self.tried.add(name)
        b = self.of(name)
        x, y, _, vx, vy, w = engine.state(name)
        if x + 2 * b.radius <= self.rest_x + POWERS.past_slingshot or (name in self.struck and b.power != "blast"):
            return []  # HUD.cs: not past the slingshot, or struck already: the power is lost
        self.tapped.append((time, name))
        if b.power in ("split", "egg"):
            self.killed(name, time)
        speed = math.hypot(vx, vy)
        if b.power == "boost" and speed > 0:
            push = POWERS.boost / engine.mass(name)
            engine.set_velocity(name, vx + push * vx / speed, vy + push * vy / speed, w)
        elif b.power == "split":
            heading = math.atan2(vy, vx)
            angles = [heading + math.radians(a) for a in POWERS.split_angles]
            # The bird itself flies on as the middle of the fan (a copy of it, in the game, in
            # the same place at the same speed); the other two come in.
            engine.set_velocity(name, speed * math.cos(angles[1]), speed * math.sin(angles[1]), w)
            specs = []
            for clone, angle in zip(self.extras[name], (angles[0], *angles[2:]), strict=False):
                specs.append((self.body(clone, (x, y)), (speed * math.cos(angle), speed * math.sin(angle))))
                self.flying[clone] = self.launched[name] + self.rules.bird_lifetime
            return specs
        elif b.power == "egg":
            engine.set_velocity(name, vx, vy + POWERS.egg_push_up / engine.mass(name), w)
            egg = self.extras[name][0]
            self.launched[egg] = time
            self.parent[egg] = name
            spec = BodySpec(
                egg,
                Polygon(POWERS.egg_outline),
                x,
                y,
                density=POWERS.egg_density,
                friction=POWERS.egg_friction,
                gravity_scale=POWERS.egg_gravity_scale,
                group=GROUP,
            )
            return [(spec, (0.0, -POWERS.egg_drop / POWERS.egg_stored_mass))]
        elif b.power == "blast":
            self.fuses[name] = time
        return []

    def arm(self, time: float) -> bool:
        """Whether a body blasts (and goes) now: a black bird whose tap or fuse has come (it
        joins `blasted`), an egg that struck."""
        for name, at in self.fuses.items():
            if time >= at - 1e-9:
                self.blasted.add(name)
        return bool(self.blasted)

    def blast(self, name: str) -> Blast | None:
        """The blast `name` sets off as it goes, if it blasts."""
        if name not in self.blasted:
            return None
        self.blasted.discard(name)
        self.fuses.pop(name, None)
        return POWERS.egg_blast if self.kind(name) == EGG else POWERS.black_blast

    def read(self, interactions: tuple[Interaction, ...]) -> tuple[Interaction, ...]:
        """The recognised interactions as the scenario names them: what a blue bird's other
        birds and a white bird's egg did, their bird's; each tap that fired a power, `tap(bird)`."""
        named = [
            Interaction(i.name, tuple(self.parent.get(o, o) for o in i.objects), i.direction, i.time)
            for i in interactions
        ]
        named += [Interaction("tap", (name,), None, time) for time, name in self.tapped]
        ordered = sorted(named, key=lambda i: (round(i.time, 6), ORDER.get(i.name, -1)))
        out = []
        for interaction in ordered:  # a hit by two of a blue bird's three at once is one
            if interaction.name != "tap" and any(
                (o.name, o.objects, o.direction) == (interaction.name, interaction.objects, interaction.direction)
                for o in out
            ):
                continue
            out.append(interaction)
        return tuple(out)
