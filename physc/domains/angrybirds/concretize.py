"""Choosing concrete game objects, materials and shapes for a layout graph.

Every choice is drawn from the seeded generator handed in, so the same seed gives
the same level. Concrete objects are drawn with physics-aware preferences, and
materials adjusted so that momentum passes down a chain (preferences.py).
Platforms get lengths by role: a surface that something rolls or slides on is
long enough to gain speed on; a support is short. An inclined
surface that something rolls or slides on declines towards the motion, any other inclined
surface (for a bounce) tilts either way, at the angles of the world's incline rule
(physc.worlds.Incline).
"""

from __future__ import annotations

import random

import attrs

from physc.compiler.concrete_layout import Body
from physc.compiler.geometry import Geometry
from physc.compiler.layout_graph import ON_LOCATION, LayoutGraph
from physc.domains.angrybirds.catalogue import PLATFORM_THICKNESS, shape
from physc.domains.angrybirds.preferences import choose_concrete, light_chain_materials
from physc.dsl.scenario import ScenarioIR

PATH_SURFACE_LENGTH = (1.5, 3.0)  # short: a rolling circle loses speed to angular drag
SUPPORT_LENGTH = (1.2, 2.5)
PLATFORM_LENGTH = (1.0, 3.0)
INCLINED_LENGTH = (2.0, 4.0)


def _length(rng: random.Random, bounds: tuple[float, float]) -> float:
    return round(rng.uniform(*bounds), 2)


def concretize(graph: LayoutGraph, scenario: ScenarioIR, rng: random.Random, world) -> dict[str, Body]:
    """The concrete object, material and shape of every node, drawn from `rng`, in `world`
    (its frame, launch and incline rule)."""
    frame = world.frame
    headings = {}
    for term in scenario.interactions:
        if term.name in ("roll", "slide"):
            headings.setdefault(term.objects[1], term.directions[0])
    carried: dict[str, list[str]] = {}
    for edge in graph.edges:
        if edge.term == ON_LOCATION:
            carried.setdefault(edge.b, []).append(edge.a)
    concrete = choose_concrete(scenario, graph, rng)
    declared = {
        o.name: o.materials for o in scenario.objects if o.materials
    }  # version 2: the materials a scenario names
    bodies = {}
    # Objects first: a platform's length depends on what it carries.
    for node in sorted(graph.nodes, key=lambda n: shape(concrete[n.name]).kind == "platform"):
        name = node.name
        chosen = concrete[name]
        if chosen == "ground":
            width = frame.right - frame.left
            bodies[name] = Body(name, node.role, chosen, Geometry(width, 1.0), fixed=(0.0, frame.ground_top - 0.5))
            continue
        catalogue = shape(chosen)
        if catalogue.kind != "platform":
            material = rng.choice(declared.get(name) or catalogue.materials) if catalogue.materials else None
            fixed = world.launch.bird_rest if catalogue.kind == "bird" else None
            bodies[name] = Body(name, node.role, chosen, Geometry(catalogue.width, catalogue.height), material, fixed)
            continue
        if chosen == "inclinedPlatform":
            incline = world.incline
            ramp = name in graph.ramps and incline.ramp is not None
            length = _length(rng, incline.ramp_length if ramp and incline.ramp_length else INCLINED_LENGTH)
            if name in headings:
                span = incline.ramp if ramp and incline.ramp is not None else incline.descending
                angle = rng.uniform(*span) * (-1 if headings[name] == "right" else 1)
            else:
                angle = rng.uniform(*world.incline.other) * rng.choice((-1, 1))
            bodies[name] = Body(name, node.role, chosen, Geometry(length, PLATFORM_THICKNESS, round(angle, 2)))
            continue
        low, high = PATH_SURFACE_LENGTH if name in headings else SUPPORT_LENGTH if name in carried else PLATFORM_LENGTH
        # An object resting in a third of its support, clear of the next platform,
        # needs the support at least three of its widths (and a little) long.
        widest = max((bodies[o].geometry.width for o in carried.get(name, ())), default=0.0)
        low = max(low, 3 * widest + 0.4)
        high = max(high, low + 1.0)
        bodies[name] = Body(name, node.role, chosen, Geometry(_length(rng, (low, high)), PLATFORM_THICKNESS))
    materials = {name: body.material for name, body in bodies.items()}
    drawn = dict(materials)
    light_chain_materials(scenario, materials)
    for name, allowed in declared.items():  # a preference never overrides what the scenario says
        if name in materials and materials[name] not in allowed:
            materials[name] = drawn[name]
    bodies = {name: attrs.evolve(body, material=materials[name]) for name, body in bodies.items()}
    return {node.name: bodies[node.name] for node in graph.nodes}
