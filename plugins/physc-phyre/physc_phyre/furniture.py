"""Scene furniture: PHYRE's objects that are several bodies or lie at an angle of their own,
and the placements the layout cannot say (one object inside or under a jar).

PHYRE's templates build scenes from balls, bars and jars, but many of them join a few into one
working part (docs/phyre-sources.md, section 7):

* a see-saw: a dynamic bar balanced on a static fulcrum ball under its middle (00004's blue
  beam; `seesaw`, `blueSeesaw`);
* a teeter: a dynamic bar lying level on two static fulcrum balls, under its middle and under
  one end, so that it holds until a weight comes onto its free half (00021; `teeter`);
* a cradle: two short static bars tilted ±5° meeting in a shallow V, which holds a ball until
  it is struck sideways (00015; `cradle`);
* a purple bar that is a slope (00010's and 00011's tilted targets; `purpleRamp`);
* a peg row: small static black balls in a level row, close enough for a ball to rest and
  roll on them (00012's and 00013's "stars"; `pegRow`, the support of an object under
  `pegged(a)`);
* a jar over an object, or an object in a jar (00018's cover jar over the green ball, 00005's
  green ball in a jar; the restriction `inside(a, jar)`).

Each is one object of the scenario, so the layout places it as one box. Its main body bears the
object's name (what the scenario's terms and the goal talk about); the other parts are named
after it (`NAME_fulcrum`, `NAME_end`, `NAME_right`) and are static scenery. They are all balls and
bars, so PHYRE's task files, pictures and features need nothing new.
"""

from __future__ import annotations

import math
import random

import attrs

from physc.compiler.geometry import Geometry
from physc_phyre.world import BAR_HEIGHT, extent, jar_thickness

FULCRUM = 12.5  # px, a see-saw's fulcrum ball (PHYRE's 00004: scale 0.1)
SEESAW_LENGTH = (77.0, 115.0)  # px, 00004's beam: 0.3-0.45 of the scene
TEETER_FULCRUM = 6.5  # px, 00021's two fulcrum balls (scale 0.05)
TEETER_LENGTH = (45.0, 77.0)  # px, 00021's teeter: 0.15-0.3 of the scene (a ball crosses it)
CRADLE_TILT = 5.0  # degrees, 00015's two bars
CRADLE_BAR = (13.0, 26.0)  # px, each bar: 0.05-0.1 of the scene
PURPLE_RAMP_LENGTH = (80.0, 150.0)  # px
PURPLE_RAMP_TILT = (10.0, 30.0)  # degrees, rising towards the way its toucher comes (00011: 15-30)
PEG = 5.5  # px, a peg's radius (00012's stars: scale 0.04)
PEG_SPACING = 18.0  # px between pegs' centres at most: a ball of radius 7.5 or more rests on them
PEG_ROW_LENGTH = (50.0, 90.0)  # px, when concretize does not say
COVER_FIT = 0.21  # a covered ball's radius is this share of its cover jar's height (00018: 6.5 / 30.7)

# concrete object → (colour of the main body, whether it moves)
KINDS = {
    "seesaw": ("gray", True),
    "blueSeesaw": ("blue", True),
    "teeter": ("gray", True),
    "cradle": ("black", False),
    "purpleRamp": ("purple", False),
    "pegRow": ("black", False),
}
SUFFIXES = ("_fulcrum", "_end", "_right", "_peg")  # the parts other than the main body


def geometry(concrete: str, rng: random.Random, heading: str | None = None) -> Geometry:
    """The outline box of a piece of furniture, its sizes drawn from `rng`; a purple ramp rises
    towards `heading` (the way its toucher comes; None: either way)."""
    if concrete in ("seesaw", "blueSeesaw"):
        return Geometry(round(rng.uniform(*SEESAW_LENGTH), 1), 2 * FULCRUM + BAR_HEIGHT)
    if concrete == "teeter":
        return Geometry(round(rng.uniform(*TEETER_LENGTH), 1), 2 * TEETER_FULCRUM + BAR_HEIGHT)
    if concrete == "cradle":
        a = math.radians(CRADLE_TILT)
        bar = round(rng.uniform(*CRADLE_BAR), 1)
        return Geometry(
            round(2 * bar * math.cos(a) + BAR_HEIGHT * math.sin(a), 3),
            round(bar * math.sin(a) + BAR_HEIGHT * math.cos(a), 3),
        )
    if concrete == "purpleRamp":
        tilt = rng.uniform(*PURPLE_RAMP_TILT)
        sign = {"right": 1, "left": -1}.get(heading or "") or rng.choice((-1, 1))
        return Geometry(round(rng.uniform(*PURPLE_RAMP_LENGTH), 1), BAR_HEIGHT, round(sign * tilt, 2))
    if concrete == "pegRow":
        return peg_row(round(rng.uniform(*PEG_ROW_LENGTH), 1))
    raise ValueError(f"no furniture '{concrete}'")


def peg_row(length: float) -> Geometry:
    """The outline box of a row of pegs about `length` long."""
    return Geometry(max(length, 2 * PEG + PEG_SPACING), 2 * PEG)


def bodies(placed, body_class) -> list:
    """The bodies (`body_class`: level.SceneBody) of a placed piece of furniture, the main one
    first, from its outline box (centre placed.x, placed.y; placed.width × placed.height)."""
    name, (color, _) = placed.name, KINDS[placed.concrete]
    cx, bottom = placed.x, placed.y - placed.height / 2
    if placed.concrete in ("seesaw", "blueSeesaw", "teeter"):
        r = FULCRUM if placed.concrete != "teeter" else TEETER_FULCRUM
        length = placed.width
        beam = body_class(
            name, "bar", round(cx, 3), round(bottom + 2 * r + BAR_HEIGHT / 2, 3), 0.0, length, color, True
        )
        out = [beam, body_class(name + "_fulcrum", "ball", round(cx, 3), round(bottom + r, 3), 0.0, r, "black", False)]
        if (
            placed.concrete == "teeter"
        ):  # a second fulcrum under its right end: it holds until its left half is weighed down
            out.append(
                body_class(
                    name + "_end", "ball", round(cx + length / 2 - r, 3), round(bottom + r, 3), 0.0, r, "black", False
                )
            )
        return out
    if placed.concrete == "cradle":
        a = math.radians(CRADLE_TILT)
        bar = (placed.width - BAR_HEIGHT * math.sin(a)) / (2 * math.cos(a))
        y = bottom + placed.height / 2
        dx = bar / 2 * math.cos(a)
        return [
            body_class(name, "bar", round(cx - dx, 3), round(y, 3), round(-a, 6), round(bar, 3), color, False),
            body_class(
                name + "_right", "bar", round(cx + dx, 3), round(y, 3), round(a, 6), round(bar, 3), color, False
            ),
        ]
    if placed.concrete == "purpleRamp":
        return [
            body_class(
                name,
                "bar",
                round(cx, 3),
                round(placed.y, 3),
                round(math.radians(placed.rotation), 6),
                placed.width,
                color,
                False,
            )
        ]
    if placed.concrete == "pegRow":  # evenly spread over the box, the outermost at its ends
        gaps = math.ceil((placed.width - 2 * PEG) / PEG_SPACING - 1e-9)
        step = (placed.width - 2 * PEG) / gaps
        left, y = cx - placed.width / 2 + PEG, round(bottom + PEG, 3)
        names = [name] + [f"{name}_peg{k}" for k in range(1, gaps + 1)]
        return [
            body_class(n, "ball", round(left + k * step, 3), y, 0.0, PEG, color, False) for k, n in enumerate(names)
        ]
    raise ValueError(f"no furniture '{placed.concrete}'")


def cover_height(radius: float) -> float:
    """The height of an upside-down jar that covers a ball of `radius` with room to spare."""
    return round(radius / COVER_FIT, 1)


def inside(bodies: list, pairs, held) -> list:
    """`bodies` with each (object, jar) of `pairs` (the scenario's `inside(a, jar)`) put
    together: an upside-down jar is moved over the object where it lies, resized to cover it;
    an upright jar is moved to a ball that the layout put on a support of its own (where its
    path starts), its base where the ball rests; any other object is moved into an upright
    jar, onto its base (`held`: level.held, for a ball). The support the layout gave the one
    moved (`support_NAME`) goes with it."""
    out = list(bodies)
    for name, jar_name in pairs:
        index = {b.name: k for k, b in enumerate(out)}
        if name not in index or jar_name not in index:
            continue
        thing, jar = out[index[name]], out[index[jar_name]]
        if jar.shape != "jar":
            continue
        if abs(math.cos(jar.angle) + 1) < 1e-6:  # upside down: it comes to the object
            if thing.shape == "ball":
                height = max(jar.size, cover_height(thing.size))
                bottom = thing.y - thing.size
            else:  # a bar: its outline's bottom
                height, bottom = jar.size, thing.y - BAR_HEIGHT / 2
            # Turned 180°, the jar's origin (its base's middle) lies `below` above its box's middle.
            below = extent("jar", height)[2]
            out[index[jar_name]] = attrs.evolve(jar, x=thing.x, y=round(bottom + height / 2 + below, 3), size=height)
            moved = jar_name
        else:  # upright: the object goes in
            moved = name
            if thing.shape == "ball" and f"support_{name}" in index:
                # The layout placed the ball on a support of its own (where its path starts):
                # the jar comes to it first, its base where the ball rests.
                base = thing.y - thing.size + jar_thickness(jar.size) / 2
                jar = out[index[jar_name]] = attrs.evolve(jar, x=round(thing.x, 3), y=round(base, 3))
                moved = jar_name
            if thing.shape == "ball":
                _, ball = held(name, jar.x, jar.y, jar.angle, jar.size, thing.color, jar.color)
                out[index[name]] = attrs.evolve(thing, x=ball.x, y=ball.y, size=min(thing.size, ball.size))
            else:  # a stick stands on the base, whose top lies `t / 2` above the jar's origin
                half_t = jar.size / 2 - extent("jar", jar.size)[2]
                out[index[name]] = attrs.evolve(thing, x=jar.x, y=round(jar.y + half_t + thing.size / 2, 3))
        out = [b for b in out if b.name != f"support_{moved}"]
    return out
