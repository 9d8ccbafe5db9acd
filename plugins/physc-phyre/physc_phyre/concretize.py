"""Concrete objects and sizes for a layout graph, drawn from the seeded generator.

Sizes follow PHYRE's templates: balls of scale 0.06–0.12 (radius int(scale·128) + 0.5
px), bars 35–70 px, jars 40–60 px tall, standing sticks 45–70 px wide. A ledge that
carries an object is at least three of its widths long, so the object can rest in its
left, middle or right third; a surface something rolls or slides on is long enough to
gather speed; a purple bar the green object must stay on is long; a ramp declines 15–30° towards the motion on it (a
surface for a bounce tilts 20–40° either way). The floor and a purple floor lie across the scene's bottom; a purple
wall stands the scene's height against the edge its toucher heads for; a purple pad lies on the
floor, placed against that edge (the search may move it along the floor to where the green
object comes down, as PHYRE's lies anywhere on it); a green stick and a post stand upright; a jar holding a ball
is 45–70 px tall; an upside-down jar is turned 180°.
See-saws, teeters, cradles and purple ramps are furniture (furniture.py); the support of an
object under `cradled(a)` is a cradle, of one under `pegged(a)` a row of pegs, as long as the
black bar it stands for would be.
"""

from __future__ import annotations

import math
import random

from physc.compiler.concrete_layout import Body
from physc.compiler.geometry import Geometry
from physc.compiler.layout_graph import ON_LOCATION
from physc_phyre import furniture
from physc_phyre.level import HELD, KINDS
from physc_phyre.world import BAR_HEIGHT, SCENE, WALL, extent

PATH_LENGTH = (50.0, 90.0)
LEDGE_LENGTH = (30.0, 70.0)
BAR_LENGTH = (35.0, 70.0)
RAMP_LENGTH = (70.0, 120.0)
TARGET_LENGTH = (
    80.0,
    150.0,
)  # a purple bar the green object comes to rest on: a ball that lands rolling must stay on it
# A purple pad lying on the floor (PHYRE's 00007: 0.2 of the scene; 00019: 0.1-0.2).
PAD_LENGTH = (26.0, 51.0)
# Bars standing upright: a green or gray stick (PHYRE's templates 00003, 00009, 00017: 0.2-0.5
# of the scene) and a black post.
UPRIGHT = {"greenStick": (51.0, 128.0), "grayStick": (51.0, 128.0), "verticalBar": (30.0, 80.0)}
# A jar holding a ball: PHYRE's 00018 and 00022 use jars of scale 0.15-0.3 (38-77 px tall).
HOLDING_HEIGHT = (45.0, 70.0)
SUPPORTS = {"cradled": "cradle", "pegged": "pegRow"}  # restriction on an object → its support


def _across(geometry: Geometry) -> float:
    """How wide a turned body stands (an upright stick: its thickness)."""
    angle = math.radians(geometry.rotation)
    return abs(geometry.width * math.cos(angle)) + abs(geometry.height * math.sin(angle))


def _heading_to(scenario, name: str) -> str | None:
    """The way (left or right) the object that touches `name` last rolls or slides before it."""
    for k, term in enumerate(scenario.interactions):
        if term.name == "touch" and term.objects[1] == name:
            moves = [
                t for t in scenario.interactions[:k] if t.name in ("roll", "slide") and t.objects[0] == term.objects[0]
            ]
            return moves[-1].directions[0] if moves else None
    return None


def _size(shape: str, rng: random.Random) -> float:
    if shape == "ball":
        return int(rng.uniform(0.06, 0.12) * 128) + 0.5
    if shape == "bar":
        return round(rng.uniform(*BAR_LENGTH), 1)
    if shape == "jar":
        return round(rng.uniform(40.0, 60.0), 1)
    return round(rng.uniform(45.0, 70.0), 1)


def _chosen(graph, scenario, carried: dict[str, list[str]], rng: random.Random) -> dict[str, str]:
    """The concrete object of every node, drawn from `rng`; a bar that carries a cradled or
    pegged object becomes that support."""
    # The agent's ball is the action's, never an object of the scene (it is rollable and
    # fallable only so that the red ball may roll and fall).
    chosen = {
        node.name: rng.choice([c for c in node.concrete if c in KINDS or c in furniture.KINDS or c == "floor"])
        for node in graph.nodes
    }
    # `cradled(a)`, `pegged(a)`: the support the layout gave a is a cradle, a row of pegs (furniture.py).
    under = {t.objects[0]: SUPPORTS[t.name] for t in scenario.restrictions if t.name in SUPPORTS}
    for support, loads in carried.items():
        kinds = [under[a] for a in loads if a in under]
        if kinds and chosen.get(support) == "blackBar":
            chosen[support] = kinds[0]
    return chosen


def _ledge(node, concrete: str, bodies: dict[str, Body], carried: dict[str, list[str]], path: bool, rng) -> Body:
    """A static bar or row of pegs, long enough for what it carries (`bodies` placed so far)
    and, on a path (`path`: something rolls or slides on it), for the motion."""
    name = node.name
    # A load rests in the ledge's left, middle or right third: three of its widths; a
    # piece of furniture, as wide as a ledge, only needs its centre over an outer third.
    loads = [
        (_across(bodies[o].geometry), bodies[o].concrete in furniture.KINDS)
        for o in carried.get(name, ())
        if o in bodies
    ]
    low, high = (
        PATH_LENGTH
        if path
        else LEDGE_LENGTH
        if name in carried
        else TARGET_LENGTH
        if concrete == "purpleBar"
        else BAR_LENGTH
    )
    low = max([low] + [(1.5 if wide else 3) * across + 6.0 for across, wide in loads])
    length = round(rng.uniform(low, max(high, low + 30.0)), 1)
    geometry = furniture.peg_row(length) if concrete == "pegRow" else Geometry(length, BAR_HEIGHT)
    return Body(name, node.role, concrete, geometry)


def concretize(graph, scenario, rng: random.Random, incline) -> dict[str, Body]:
    """The concrete object and shape of every node, drawn from `rng`; ramps at the angles of
    the world's incline rule (physc.worlds.Incline)."""
    headings = {t.objects[1]: t.directions[0] for t in scenario.interactions if t.name in ("roll", "slide")}
    carried: dict[str, list[str]] = {}
    for edge in graph.edges:
        if edge.term == ON_LOCATION:
            carried.setdefault(edge.b, []).append(edge.a)
    chosen = _chosen(graph, scenario, carried, rng)
    bodies: dict[str, Body] = {}
    # Objects first: a ledge's length depends on what it carries.
    for node in sorted(graph.nodes, key=lambda n: n.static):
        name, concrete = node.name, chosen[node.name]
        if concrete == "floor":
            bodies[name] = Body(
                name, node.role, concrete, Geometry(SCENE + 2 * WALL, WALL), fixed=(SCENE / 2, -WALL / 2)
            )
        elif concrete in furniture.KINDS and concrete != "pegRow":
            bodies[name] = Body(
                name, node.role, concrete, furniture.geometry(concrete, rng, _heading_to(scenario, name))
            )
        elif concrete == "purpleWall":  # upright against the edge its toucher heads for
            side = _heading_to(scenario, name) or rng.choice(("left", "right"))
            x = BAR_HEIGHT / 2 if side == "left" else SCENE - BAR_HEIGHT / 2
            bodies[name] = Body(name, node.role, concrete, Geometry(SCENE, BAR_HEIGHT, 90.0), fixed=(x, SCENE / 2))
        elif concrete == "purplePad":  # on the floor against the edge its toucher heads for
            side = _heading_to(scenario, name) or rng.choice(("left", "right"))
            length = round(rng.uniform(*PAD_LENGTH), 1)
            x = length / 2 if side == "left" else SCENE - length / 2
            bodies[name] = Body(name, node.role, concrete, Geometry(length, BAR_HEIGHT), fixed=(x, BAR_HEIGHT / 2))
        elif concrete in UPRIGHT:
            length = round(rng.uniform(*UPRIGHT[concrete]), 1)
            bodies[name] = Body(name, node.role, concrete, Geometry(length, BAR_HEIGHT, 90.0))
        elif concrete == "purpleFloor":
            bodies[name] = Body(
                name, node.role, concrete, Geometry(SCENE, BAR_HEIGHT), fixed=(SCENE / 2, BAR_HEIGHT / 2)
            )
        elif concrete == "ramp":
            length = round(rng.uniform(*RAMP_LENGTH), 1)
            if name in headings:
                angle = rng.uniform(*incline.descending) * (-1 if headings[name] == "right" else 1)
            else:
                angle = rng.uniform(*incline.other) * rng.choice((-1, 1))
            bodies[name] = Body(name, node.role, concrete, Geometry(length, BAR_HEIGHT, round(angle, 2)))
        elif concrete in ("blackBar", "purpleBar", "pegRow") and node.static:
            bodies[name] = _ledge(node, concrete, bodies, carried, name in headings, rng)
        else:
            shape = KINDS[concrete][0]
            size = round(rng.uniform(*HOLDING_HEIGHT), 1) if concrete in HELD else _size(shape, rng)
            width, height, _ = extent(shape, size)
            turned = 180.0 if concrete == "upsideDownJar" else 0.0
            bodies[name] = Body(name, node.role, concrete, Geometry(round(width, 3), round(height, 3), turned))
    return {node.name: bodies[node.name] for node in graph.nodes}
